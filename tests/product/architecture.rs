//! The architecture ARCHITECTURE.md describes, checked: the layers of the product, the order of
//! the core's modules, the size of files.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::imports::{loops, top_level_modules};
use crate::support::repo;

/// Every `.rs` file below `dir`.
pub(crate) fn rust_files(dir: &Path) -> Vec<PathBuf> {
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

#[test]
fn the_core_s_modules_form_no_cycle() {
    let deps = top_level_modules(&repo().join("crates/pipeline/src"));
    assert!(deps.len() > 10, "the core's modules were found: {deps:?}");
    assert_eq!(
        loops(&deps),
        Vec::<Vec<String>>::new(),
        "the core's modules: {deps:#?}"
    );
}

/// The modules a table of ARCHITECTURE.md lists, in its order, from the heading that starts
/// with `heading` to the next one.
fn table_order(heading: &str) -> Vec<String> {
    let text = std::fs::read_to_string(repo().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let start = text.find(heading).expect("the table's heading");
    let section = &text[start + heading.len()..];
    let section = &section[..section.find("\n### ").unwrap_or(section.len())];
    section
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .map(|m| m.trim_end_matches(".rs").trim_end_matches('/').to_owned())
        .collect()
}

#[test]
fn each_core_module_uses_only_those_above_it_in_architecture_md() {
    let order = table_order("### The core crate");
    let deps = top_level_modules(&repo().join("crates/pipeline/src"));
    let listed: BTreeSet<&String> = order.iter().collect();
    let modules: BTreeSet<&String> = deps.keys().collect();
    assert_eq!(
        listed, modules,
        "ARCHITECTURE.md lists every core module once"
    );
    for (i, m) in order.iter().enumerate() {
        let below: Vec<&String> = deps[m].iter().filter(|d| !order[..i].contains(d)).collect();
        assert!(
            below.is_empty(),
            "`{m}` uses {below:?}, listed below it in ARCHITECTURE.md's table"
        );
    }
}

#[test]
fn the_product_s_modules_form_no_cycle_and_only_the_top_uses_the_app() {
    let deps = top_level_modules(&repo().join("src"));
    assert_eq!(
        loops(&deps),
        Vec::<Vec<String>>::new(),
        "the product's modules: {deps:#?}"
    );
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
    let deps = top_level_modules(&repo().join("crates/glsl/src"));
    assert!(deps.len() > 10, "the engine's modules were found: {deps:?}");
    assert_eq!(
        loops(&deps),
        Vec::<Vec<String>>::new(),
        "the engine's modules: {deps:#?}"
    );
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

/// Every source file names its concept in its first line, a `//!` doc comment: what it holds,
/// in the course's words, for the reader who opens it.
#[test]
fn every_source_file_names_its_concept_in_its_first_line() {
    let mut unnamed = Vec::new();
    for dir in ["src", "crates/glsl/src", "crates/pipeline/src", "web/src"] {
        for f in rust_files(&repo().join(dir)) {
            let text = std::fs::read_to_string(&f).expect("a source file");
            if !text.starts_with("//! ") {
                unnamed.push(f.display().to_string());
            }
        }
    }
    assert!(
        unnamed.is_empty(),
        "files whose first line is not a `//!` line naming what they hold: {unnamed:?}"
    );
}

/// The `.rs` file names ARCHITECTURE.md writes in backticks (`resolve.rs`, `script/read.rs`).
fn file_names_in(text: &str) -> Vec<String> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .filter(|t| {
            t.ends_with(".rs")
                && t.chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '/' | '.'))
        })
        .map(str::to_owned)
        .collect()
}

/// A file named in ARCHITECTURE.md exists: a renamed or split file leaves no stale name there.
#[test]
fn every_file_architecture_md_names_exists() {
    let text = std::fs::read_to_string(repo().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let files: Vec<String> = ["src", "crates", "web", "tests", "fuzz"]
        .iter()
        .flat_map(|d| rust_files(&repo().join(d)))
        // The build script, at the root.
        .chain([repo().join("build.rs")].into_iter().filter(|p| p.exists()))
        .map(|p| {
            p.strip_prefix(repo())
                .expect("below the repository")
                .display()
                .to_string()
        })
        .collect();
    let names = file_names_in(&text);
    assert!(names.len() > 100, "only {} file names read", names.len());
    let missing: BTreeSet<&String> = names
        .iter()
        .filter(|n| {
            !files
                .iter()
                .any(|f| f == *n || f.ends_with(&format!("/{n}")))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "ARCHITECTURE.md names files that do not exist: {missing:?}"
    );
    // The reader itself: a name in code spans only, whole.
    assert_eq!(
        file_names_in("in `a/b.rs` and (`c.rs`), not mod.rs nor `d.rs x`"),
        ["a/b.rs", "c.rs"]
    );
}
