//! Running the real binary.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `pipelens` with `args` in `dir`.
pub fn pipelens(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pipelens"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the pipelens binary runs")
}

/// The repository root (where `assets/` is).
pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `../shared/data`, when this checkout has it beside it.
pub fn shared_data() -> Option<PathBuf> {
    let p = repo().join("../shared/data");
    p.is_dir().then_some(p)
}

/// Text of stdout and stderr together.
pub fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

/// Asserts that one of `found` is at `line:column` and its message contains `needle`, showing
/// them all otherwise.
pub fn assert_found(
    found: &[pipelens::lesson::Diagnostic],
    line: usize,
    column: usize,
    needle: &str,
) {
    assert!(
        found
            .iter()
            .any(|d| d.line == line && d.column == column && d.message.contains(needle)),
        "expected {line}:{column} \"{needle}\", got:\n{}",
        found
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n")
    );
}

/// Every `.toml` file in `lessons/`, sorted.
pub fn lesson_files() -> Vec<std::path::PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(repo().join("lessons"))
        .expect("lessons/ exists")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    files
}

/// Writes `text` to `path` as an editor saving it would, with the modification time `modified`
/// (some file systems keep whole seconds: a test that saves twice in a second moves the time on
/// itself so that live reload sees the change).
pub fn save_edited(path: &std::path::Path, text: &str, modified: std::time::SystemTime) {
    std::fs::write(path, text).expect("write");
    std::fs::File::options()
        .write(true)
        .open(path)
        .and_then(|f| f.set_modified(modified))
        .expect("touch");
}

/// The lesson `lessons/{id}.toml`, loaded as the app loads it.
pub fn lesson(id: &str) -> pipelens::lesson::Lesson {
    let path = repo().join(format!("lessons/{id}.toml"));
    match pipelens::lesson::load_file(&path) {
        Ok(pipelens::lesson::Document::Lesson(lesson)) => *lesson,
        Ok(_) => panic!("{} is not a lesson", path.display()),
        Err(e) => panic!("{e}"),
    }
}

/// The text of HTML: its tags left out (entities as written).
pub fn without_tags(html: &str) -> String {
    let mut text = String::with_capacity(html.len());
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => text.push(c),
            _ => {}
        }
    }
    text
}

/// The share of a capture's pixels that some triangle covers.
pub fn covered_share(capture: &pipeline::capture::FrameCapture) -> f32 {
    let ids = &capture.pixels.primitive;
    let covered = ids.iter().filter(|&&p| p != pipeline::raster::NONE).count();
    covered as f32 / ids.len().max(1) as f32
}
