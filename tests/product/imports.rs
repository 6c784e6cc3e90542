//! The import graph file by file: which source file names an item of which other, read from the
//! `use` trees and the `crate::`/`super::`/`self::` paths, a name re-exported by a `mod.rs`
//! followed to the file that defines it.
//!
//! Two rules stand on it: no files import each other in a loop (a module's own `mod.rs` naming
//! its children does not count: a parent is made of its children), and in the GLSL engine and in
//! `src/app` no file imports from a module above it (a child never reaches back up into its
//! parent's `mod.rs`; the parent only declares and re-exports).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::architecture::rust_files;
use crate::support::repo;

/// A module's path inside its crate: `["app", "views", "pixels"]` for `app/views/pixels/mod.rs`.
type ModPath = Vec<String>;

/// One crate's files and what each of them names.
struct Graph {
    /// Each module path with its file.
    files: BTreeMap<ModPath, PathBuf>,
    /// For each file, the names it re-exports (`pub use a::b as c;` → `c` ↦ `[a, b]`; a glob
    /// `pub use a::*;` → `*` ↦ `[a, *]`).
    reexports: BTreeMap<ModPath, BTreeMap<String, Vec<String>>>,
    /// For each file, the files whose items it names.
    edges: BTreeMap<ModPath, BTreeSet<ModPath>>,
}

/// A file's text with its comments and its `#[cfg(test)] mod … { … }` blocks taken out: a
/// comment may name a module it does not use, and a test module's `super` is the file itself.
fn code_without_tests(text: &str) -> String {
    let code: String = text
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let mut out = String::new();
    let mut rest = code.as_str();
    while let Some(at) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..at]);
        let after = &rest[at + "#[cfg(test)]".len()..];
        let trimmed = after.trim_start();
        if !trimmed.starts_with("mod ") {
            rest = after;
            continue;
        }
        let Some(open) = trimmed.find('{') else {
            rest = "";
            break;
        };
        let mut depth = 0usize;
        let mut end = trimmed.len();
        for (i, c) in trimmed[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + i + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        rest = &trimmed[end..];
    }
    out.push_str(rest);
    out
}

/// The paths a `use` tree names, each with the name it is known by:
/// `a::{b, c::{d, self}, f as g}` → `a::b` (b), `a::c::d` (d), `a::c` (c), `a::f` (g).
fn expand_use(tree: &str) -> Vec<(String, String)> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let (path, alias) = match tree.split_once(" as ") {
            Some((path, alias)) => (path.trim(), alias.trim()),
            None => (tree, tree.rsplit("::").next().unwrap_or("")),
        };
        return if path.is_empty() {
            Vec::new()
        } else {
            vec![(path.to_owned(), alias.to_owned())]
        };
    };
    let prefix = &tree[..open];
    let mut parts = Vec::new();
    let mut depth = 0usize;
    let mut current = String::new();
    for c in tree[open + 1..].chars() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => break,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(std::mem::take(&mut current));
                continue;
            }
            _ => {}
        }
        current.push(c);
    }
    parts.push(current);
    let whole = prefix.trim_end_matches("::");
    parts
        .iter()
        .flat_map(|p| expand_use(p))
        .map(|(p, alias)| {
            if p == "self" {
                let named = whole.rsplit("::").next().unwrap_or("");
                let alias = if alias == "self" { named } else { &alias };
                (whole.to_owned(), alias.to_owned())
            } else {
                (format!("{prefix}{p}"), alias)
            }
        })
        .collect()
}

/// The `use` statements of a text, each tree expanded into its paths (as segments) with the
/// name each is known by; `public` keeps only `pub use` (re-exports).
fn uses(code: &str, public: bool) -> Vec<(String, Vec<String>)> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before = &rest[..at];
        let after = &rest[at + 4..];
        let Some(end) = after.find(';') else { break };
        let word_start = !before.ends_with(|c: char| c.is_alphanumeric() || c == '_');
        let line_start = before.rfind(['\n', ';', '{', '}']).map_or(0, |i| i + 1);
        let head = before[line_start..].trim();
        let is_pub = head.starts_with("pub");
        let is_statement = head.is_empty() || is_pub || head.starts_with("#[");
        if word_start && is_statement && (!public || is_pub) {
            let tree = after[..end]
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ");
            for (full, alias) in expand_use(&tree) {
                let segments = full.split("::").map(|s| s.trim().to_owned()).collect();
                out.push((alias, segments));
            }
        }
        rest = &after[end..];
    }
    out
}

/// The `crate::…`, `super::…` and `self::…` paths written in code.
fn written_paths(code: &str) -> Vec<Vec<String>> {
    let bytes = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < code.len() {
        let word = ["crate::", "super::", "self::"]
            .into_iter()
            .find(|w| code[i..].starts_with(w));
        let boundary = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        if let (Some(_), true) = (word, boundary) {
            let end = code[i..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| i + e);
            let written = &code[i..end];
            if !written.ends_with("::") {
                out.push(written.split("::").map(str::to_owned).collect());
            }
            i = end;
        } else {
            i += code[i..].chars().next().map_or(1, char::len_utf8);
        }
    }
    out
}

impl Graph {
    fn of(src: &Path) -> Graph {
        let mut files = BTreeMap::new();
        for f in rust_files(src) {
            let rel = f.strip_prefix(src).expect("below src").with_extension("");
            let mut path: ModPath = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            if matches!(
                path.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                path.pop();
            }
            files.insert(path, f);
        }
        let codes: BTreeMap<ModPath, String> = files
            .iter()
            .map(|(m, f)| {
                let text = std::fs::read_to_string(f).expect("a source file");
                (m.clone(), code_without_tests(&text))
            })
            .collect();
        let reexports = codes
            .iter()
            .map(|(m, code)| (m.clone(), uses(code, true).into_iter().collect()))
            .collect();
        let mut graph = Graph {
            files,
            reexports,
            edges: BTreeMap::new(),
        };
        for (m, code) in &codes {
            let mut named: Vec<Vec<String>> = uses(code, false).into_iter().map(|u| u.1).collect();
            named.extend(written_paths(code));
            let targets = named
                .iter()
                .filter_map(|p| graph.absolute(m, p))
                .filter_map(|a| graph.resolve(&a, 0))
                .filter(|t| t != m)
                .collect();
            graph.edges.insert(m.clone(), targets);
        }
        graph
    }

    /// A path as written in module `m`, made absolute; `None` for another crate's.
    fn absolute(&self, m: &ModPath, path: &[String]) -> Option<ModPath> {
        let mut segments = path;
        let mut base = match path.first().map(String::as_str) {
            Some("crate") => {
                segments = &path[1..];
                Vec::new()
            }
            Some("self" | "super") => m.clone(),
            Some(first) => {
                let mut child = m.clone();
                child.push(first.to_owned());
                if !self.files.contains_key(&child) {
                    return None;
                }
                m.clone()
            }
            None => return None,
        };
        while let Some(s) = segments.first() {
            match s.as_str() {
                "self" => {}
                "super" => {
                    base.pop();
                }
                _ => break,
            }
            segments = &segments[1..];
        }
        base.extend(segments.iter().cloned());
        Some(base)
    }

    /// The file that defines what an absolute path names: the longest module prefix, through
    /// that module's re-exports where it re-exports the next name.
    fn resolve(&self, path: &[String], depth: usize) -> Option<ModPath> {
        let k = (0..=path.len())
            .rev()
            .find(|&k| self.files.contains_key(&path[..k]))?;
        let module = path[..k].to_vec();
        let (Some(name), true) = (path.get(k), depth < 8) else {
            return Some(module);
        };
        let reexports = &self.reexports[&module];
        if let Some(target) = reexports.get(name)
            && let Some(mut a) = self.absolute(&module, target)
        {
            a.extend(path[k + 1..].iter().cloned());
            return self.resolve(&a, depth + 1);
        }
        for target in reexports
            .iter()
            .filter(|(alias, _)| *alias == "*")
            .map(|(_, t)| t)
        {
            let Some(mut a) = self.absolute(&module, &target[..target.len() - 1]) else {
                continue;
            };
            let glob_module = a.clone();
            a.push(name.clone());
            match self.resolve(&a, depth + 1) {
                Some(found) if found != glob_module => return Some(found),
                _ => {}
            }
        }
        Some(module)
    }

    /// The edges that are not a module naming its own descendants.
    fn sideways(&self) -> BTreeMap<ModPath, BTreeSet<ModPath>> {
        self.edges
            .iter()
            .map(|(m, ts)| {
                let kept = ts.iter().filter(|t| !t.starts_with(m)).cloned().collect();
                (m.clone(), kept)
            })
            .collect()
    }

    /// The imports from a file to a module above it, below `under`.
    fn upward(&self, under: &str) -> Vec<String> {
        self.edges
            .iter()
            .filter(|(m, _)| m.first().is_some_and(|f| f == under) || under.is_empty())
            .flat_map(|(m, ts)| {
                ts.iter()
                    .filter(move |t| m.starts_with(t) && t.len() < m.len())
                    .map(move |t| format!("{} → {}", m.join("/"), self.file(t)))
            })
            .collect()
    }

    fn file(&self, m: &ModPath) -> String {
        self.files[m].display().to_string()
    }
}

/// Which top-level modules (a file `m.rs` or a folder `m/` of `src`) each one names, from the
/// import graph file by file.
pub(crate) fn top_level_modules(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let graph = Graph::of(src);
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (m, targets) in &graph.edges {
        let Some(from) = m.first() else { continue };
        let used = out.entry(from.clone()).or_default();
        for to in targets.iter().filter_map(|t| t.first()) {
            if to != from {
                used.insert(to.clone());
            }
        }
    }
    out
}

/// The loops among the edges (Tarjan's strongly connected components of two nodes or more).
pub(crate) fn loops<T: Ord + Clone>(edges: &BTreeMap<T, BTreeSet<T>>) -> Vec<Vec<T>> {
    struct Search<'a, T> {
        edges: &'a BTreeMap<T, BTreeSet<T>>,
        index: BTreeMap<T, usize>,
        low: BTreeMap<T, usize>,
        stack: Vec<T>,
        found: Vec<Vec<T>>,
    }
    impl<T: Ord + Clone> Search<'_, T> {
        fn visit(&mut self, v: &T) {
            let i = self.index.len();
            self.index.insert(v.clone(), i);
            self.low.insert(v.clone(), i);
            self.stack.push(v.clone());
            for w in self.edges.get(v).into_iter().flatten() {
                let low = if !self.index.contains_key(w) {
                    self.visit(w);
                    self.low[w]
                } else if self.stack.contains(w) {
                    self.index[w]
                } else {
                    continue;
                };
                let low = self.low[v].min(low);
                self.low.insert(v.clone(), low);
            }
            if self.low[v] == self.index[v] {
                let at = self
                    .stack
                    .iter()
                    .position(|s| s == v)
                    .expect("on the stack");
                let component = self.stack.split_off(at);
                if component.len() > 1 {
                    self.found.push(component);
                }
            }
        }
    }
    let mut search = Search {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in edges.keys() {
        if !search.index.contains_key(v) {
            search.visit(v);
        }
    }
    search.found
}

fn path(s: &str) -> ModPath {
    s.split('/')
        .filter(|p| !p.is_empty())
        .map(str::to_owned)
        .collect()
}

#[test]
fn a_use_tree_expands_to_its_paths() {
    let pair = |p: &str, a: &str| (p.to_owned(), a.to_owned());
    assert_eq!(
        expand_use("super::{a, b::{c, self}, d as e}"),
        [
            pair("super::a", "a"),
            pair("super::b::c", "c"),
            pair("super::b", "b"),
            pair("super::d", "e")
        ]
    );
    assert_eq!(
        uses("pub use self::x::{Y as Z, W};\nuse crate::q;", true),
        [
            ("Z".to_owned(), path("self/x/Y")),
            ("W".to_owned(), path("self/x/W"))
        ]
    );
    assert_eq!(uses("pub use self::x::Y;\nuse crate::q;", false).len(), 2);
    assert_eq!(
        written_paths("use crate::{a, b};\nlet a = crate::m::f(super::g, my_crate::h);"),
        [path("crate/m/f"), path("super/g")]
    );
    assert_eq!(
        code_without_tests(
            "fn a() {}\n#[cfg(test)]\nmod tests { use super::*; fn b() {} }\nfn c() {}"
        ),
        "fn a() {}\n\nfn c() {}"
    );
}

#[test]
fn the_loop_finder_finds_a_loop() {
    let edges: BTreeMap<ModPath, BTreeSet<ModPath>> = [
        ("a", vec!["b"]),
        ("b", vec!["c"]),
        ("c", vec!["a"]),
        ("d", vec!["a"]),
    ]
    .into_iter()
    .map(|(m, ts)| (path(m), ts.into_iter().map(path).collect()))
    .collect();
    let found = loops(&edges);
    assert_eq!(found.len(), 1);
    let mut members = found[0].clone();
    members.sort();
    assert_eq!(members, [path("a"), path("b"), path("c")]);
}

/// A crate of five files written for the test: a re-export is followed to the file that
/// defines the name, a child that names its parent's own item imports back up, and two
/// siblings that name each other's items form a loop.
#[test]
fn a_re_export_is_followed_and_an_import_back_up_is_found() {
    let dir = std::env::temp_dir().join(format!("pipelens-imports-{}", std::process::id()));
    let files = [
        ("lib.rs", "mod a;\nmod s;\nmod t;\n"),
        (
            "a/mod.rs",
            "mod b;\nmod c;\nmod d;\npub use c::Thing;\npub fn helper() {}\n",
        ),
        ("a/b.rs", "use super::Thing;\n"),
        ("a/c.rs", "pub struct Thing;\n"),
        (
            "a/d.rs",
            "use super::helper;\n#[cfg(test)]\nmod tests {\n    use super::super::b;\n}\n",
        ),
        ("s.rs", "pub struct S(crate::t::T);\n"),
        ("t.rs", "pub struct T;\nfn f(_: crate::s::S) {}\n"),
    ];
    for (name, text) in files {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().expect("a folder")).expect("the folder");
        std::fs::write(path, text).expect("the file");
    }
    let graph = Graph::of(&dir);
    let targets = |m: &str| graph.edges[&path(m)].clone();
    assert_eq!(
        targets("a/b"),
        [path("a/c")].into(),
        "through the re-export"
    );
    assert_eq!(
        targets("a/d"),
        [path("a")].into(),
        "a test module is left out"
    );
    assert_eq!(graph.upward("a").len(), 1, "{:?}", graph.upward("a"));
    assert!(graph.upward("a")[0].starts_with("a/d"));
    let found = loops(&graph.sideways());
    assert_eq!(found.len(), 1, "{found:?}");
    let mut members = found[0].clone();
    members.sort();
    assert_eq!(members, [path("s"), path("t")]);
    std::fs::remove_dir_all(&dir).expect("the test's folder removed");
}

fn assert_no_loop(src: &str) {
    let graph = Graph::of(&repo().join(src));
    assert!(graph.files.len() > 10, "{src}'s files were found");
    let sideways = graph.sideways();
    let found: Vec<Vec<String>> = loops(&sideways)
        .iter()
        .map(|l| {
            l.iter()
                .map(|m| {
                    let named: Vec<String> = sideways[m]
                        .iter()
                        .filter(|t| l.contains(t))
                        .map(|t| t.join("/"))
                        .collect();
                    format!("{} names {}", m.join("/"), named.join(", "))
                })
                .collect()
        })
        .collect();
    assert!(
        found.is_empty(),
        "files of {src} that import each other in a loop: {found:#?}"
    );
}

#[test]
fn no_files_of_the_engine_import_each_other_in_a_loop() {
    assert_no_loop("crates/glsl/src");
}

#[test]
fn no_files_of_the_core_import_each_other_in_a_loop() {
    assert_no_loop("crates/pipeline/src");
}

#[test]
fn no_files_of_the_product_import_each_other_in_a_loop() {
    assert_no_loop("src");
}

#[test]
fn no_import_runs_back_up_in_the_engine_or_the_app() {
    let engine = Graph::of(&repo().join("crates/glsl/src")).upward("");
    assert!(
        engine.is_empty(),
        "the engine's imports back up: {engine:#?}"
    );
    let app = Graph::of(&repo().join("src")).upward("app");
    assert!(app.is_empty(), "the app's imports back up: {app:#?}");
}
