//! The architecture ARCHITECTURE.md describes, checked: the layers of the product, the order of
//! the core's modules, the size of files.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::support::repo;

/// Every `.rs` file below `dir`.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).expect("a source folder") {
            let p = entry.expect("a folder entry").path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The text of a source file without its comments (a comment may name a module it does not use).
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).expect("a source file");
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level modules of a crate's `src` (a file `m.rs` or a folder `m/`), with their files.
fn modules(src: &Path) -> BTreeMap<String, Vec<PathBuf>> {
    let mut out = BTreeMap::new();
    for entry in std::fs::read_dir(src).expect("src") {
        let p = entry.expect("an entry").path();
        let name = p
            .file_stem()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if p.is_dir() {
            out.insert(name, rust_files(&p));
        } else if name != "lib" && name != "main" && p.extension().is_some_and(|e| e == "rs") {
            out.insert(name, vec![p]);
        }
    }
    out
}

/// Which top-level modules each one names as `crate::m`.
fn dependencies(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mods = modules(src);
    mods.iter()
        .map(|(m, files)| {
            let used = files
                .iter()
                .flat_map(|f| {
                    let text = code(f);
                    mods.keys()
                        .filter(|d| *d != m && text.contains(&format!("crate::{d}")))
                        .cloned()
                        .collect::<Vec<_>>()
                })
                .collect();
            (m.clone(), used)
        })
        .collect()
}

/// A cycle among the modules, if there is one (depth-first search).
fn cycle(deps: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        deps: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = path.iter().position(|p| p == m) {
            let mut c = path[i..].to_vec();
            c.push(m.to_owned());
            return Some(c);
        }
        if done.contains(m) {
            return None;
        }
        path.push(m.to_owned());
        for d in deps.get(m).into_iter().flatten() {
            if let Some(c) = visit(d, deps, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(m.to_owned());
        None
    }
    let mut done = BTreeSet::new();
    deps.keys()
        .find_map(|m| visit(m, deps, &mut Vec::new(), &mut done))
}

#[test]
fn the_cycle_finder_finds_a_cycle() {
    let deps: BTreeMap<String, BTreeSet<String>> = [
        ("a", vec!["b"]),
        ("b", vec!["c"]),
        ("c", vec!["a"]),
        ("d", vec![]),
    ]
    .into_iter()
    .map(|(m, ds)| (m.to_owned(), ds.into_iter().map(str::to_owned).collect()))
    .collect();
    assert_eq!(
        cycle(&deps),
        Some(vec!["a".into(), "b".into(), "c".into(), "a".into()])
    );
}

#[test]
fn the_core_s_modules_form_no_cycle() {
    let deps = dependencies(&repo().join("crates/pipeline/src"));
    assert!(deps.len() > 10, "the core's modules were found: {deps:?}");
    assert_eq!(cycle(&deps), None, "the core's modules: {deps:#?}");
}

#[test]
fn the_product_s_modules_form_no_cycle_and_only_the_top_uses_the_app() {
    let deps = dependencies(&repo().join("src"));
    assert_eq!(cycle(&deps), None, "the product's modules: {deps:#?}");
    for below in [
        "vocabulary",
        "lesson",
        "lab",
        "export",
        "observer",
        "spaces",
    ] {
        let used = &deps[below];
        assert!(
            !used.contains("app") && !used.contains("cli") && !used.contains("bench"),
            "{below} uses {used:?}: it must not import the app"
        );
    }
    assert!(
        deps["vocabulary"].is_empty(),
        "the vocabulary uses only the core"
    );
}

/// The GLSL engine is a crate of its own, below the pipeline: it knows neither the pipeline nor
/// a GUI, and its modules form no cycle.
#[test]
fn the_glsl_engine_stands_alone() {
    let deps = dependencies(&repo().join("crates/glsl/src"));
    assert!(deps.len() > 10, "the engine's modules were found: {deps:?}");
    assert_eq!(cycle(&deps), None, "the engine's modules: {deps:#?}");
    let manifest = std::fs::read_to_string(repo().join("crates/glsl/Cargo.toml"))
        .expect("the engine's manifest");
    for above in ["pipeline", "egui", "eframe", "winit", "image"] {
        assert!(
            !manifest.contains(&format!("\n{above}")),
            "the engine depends on {above}"
        );
    }
}

#[test]
fn the_core_knows_no_gui() {
    let manifest = std::fs::read_to_string(repo().join("crates/pipeline/Cargo.toml"))
        .expect("the core's manifest");
    for gui in ["egui", "eframe", "winit"] {
        assert!(!manifest.contains(gui), "the core depends on {gui}");
    }
}

#[test]
fn a_source_file_over_600_lines_says_why_at_its_top() {
    let mut long = Vec::new();
    for dir in [
        "src",
        "crates/glsl/src",
        "crates/pipeline/src",
        "tests",
        "crates/pipeline/tests",
    ] {
        for f in rust_files(&repo().join(dir)) {
            let text = std::fs::read_to_string(&f).expect("a source file");
            let head: String = text.lines().take(12).collect::<Vec<_>>().join("\n");
            if text.lines().count() > 600 && !head.contains("Longer than 600 lines:") {
                long.push(f.display().to_string());
            }
        }
    }
    assert!(
        long.is_empty(),
        "over 600 lines with no `Longer than 600 lines:` reason at the top: {long:?}"
    );
}
