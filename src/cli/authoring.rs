//! The commands for writing lessons: `check` (every problem, each mesh's size, warnings) and
//! `new-lesson` (the commented template).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};

use crate::lesson;

pub(super) fn new_lesson(file: &Path, lab: bool) -> Result<ExitCode> {
    let text = lesson::start::from_template(file, lab).map_err(anyhow::Error::msg)?;
    if let Some(dir) = file.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("cannot create the folder {}", dir.display()))?;
    }
    // `create_new`: an existing lesson is never replaced.
    let mut f = std::fs::File::options()
        .write(true)
        .create_new(true)
        .open(file)
        .with_context(|| {
            if file.exists() {
                format!("{} exists already; it was left as it is", file.display())
            } else {
                format!("cannot create {}", file.display())
            }
        })?;
    std::io::Write::write_all(&mut f, text.as_bytes())
        .with_context(|| format!("cannot write {}", file.display()))?;
    let steps = text.matches("\n[[steps]]").count();
    let what = if lab { "a lab" } else { "a lesson" };
    say!(
        "Wrote {}: {what} of {steps} step{}. Play it with `pipelens --lesson {0}`; it reloads on save.",
        file.display(),
        if steps == 1 { "" } else { "s" }
    );
    Ok(ExitCode::SUCCESS)
}

/// Each object's mesh: its triangles and where it sits (its bounding box in object
/// coordinates, after `fit`), which a lesson's author needs to place the camera.
fn print_meshes(spec: &lesson::SceneSpec) {
    let short = |x: f32| crate::vocabulary::short(x, 3);
    let v = |p: glam::Vec3| format!("[{}, {}, {}]", short(p.x), short(p.y), short(p.z));
    for o in &spec.scene.objects {
        let m = &o.mesh;
        let bounds = m.bounds().map_or_else(
            || "no vertices".to_owned(),
            |(lo, hi)| {
                let c = (lo + hi) / 2.0;
                format!("box {} to {}, centre {}", v(lo), v(hi), v(c))
            },
        );
        say!(
            "  {}: {}, {} triangles, {bounds}",
            o.name,
            m.name,
            m.triangle_count()
        );
    }
}

/// Checks every file (a folder: every `.toml` under it); exit code 1 if any has an error.
pub(super) fn check(paths: &[PathBuf]) -> ExitCode {
    let (paths, problems) = files_to_check(paths);
    for p in &problems {
        eprintln!("{p}");
    }
    let mut failed = problems.len();
    for p in &paths {
        if let Some(ok) = check_shader(p) {
            failed += usize::from(!ok);
            continue;
        }
        match lesson::load_file(p) {
            Ok(lesson::Document::Scene(s)) => {
                say!("{}: ok (scene)", p.display());
                print_meshes(&s);
            }
            Ok(lesson::Document::Lesson(l)) => {
                let n = l.steps.len();
                say!(
                    "{}: ok (lesson {}, {n} step{})",
                    p.display(),
                    l.id,
                    if n == 1 { "" } else { "s" }
                );
                print_meshes(&l.scene);
                for w in &l.warnings {
                    eprintln!("{w}");
                }
            }
            Err(d) => {
                failed += 1;
                eprintln!("{d}");
            }
        }
    }
    if failed > 0 {
        eprintln!(
            "{failed} of {} file(s) have errors",
            paths.len() + problems.len()
        );
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

/// A shader file checked as the shader panel compiles it: `.vert` and `.frag` as that stage,
/// `.glsl` as the pipeline function its name says (`inside.glsl`, `depth_test.glsl`, …), each
/// message at `file:line:column`. `None` for a file that is no shader (a lesson or a scene);
/// otherwise whether it compiled.
fn check_shader(path: &Path) -> Option<bool> {
    use pipeline::shader::{HookKind, Stage};
    enum Kind {
        Stage(Stage),
        Hook(HookKind),
    }
    let extension = path.extension()?.to_str()?;
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or_default();
    let kind = match extension {
        "vert" => Kind::Stage(Stage::Vertex),
        "frag" => Kind::Stage(Stage::Fragment),
        "glsl" => match HookKind::from_key(stem) {
            Some(k) => Kind::Hook(k),
            None => {
                let names: Vec<String> = HookKind::ALL
                    .iter()
                    .map(|k| format!("{}.glsl", k.key()))
                    .collect();
                eprintln!(
                    "{}: error: a .glsl file is checked as the pipeline function its name says: {}; a shader is a .vert or a .frag",
                    path.display(),
                    names.join(", ")
                );
                return Some(false);
            }
        },
        _ => return None,
    };
    let source = match std::fs::read_to_string(path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{}: error: cannot read it: {e}", path.display());
            return Some(false);
        }
    };
    let (what, result) = match kind {
        Kind::Stage(Stage::Vertex) => (
            "vertex shader".to_owned(),
            pipeline::shader::compile(Stage::Vertex, &source).map(drop),
        ),
        Kind::Stage(Stage::Fragment) => (
            "fragment shader".to_owned(),
            pipeline::shader::compile(Stage::Fragment, &source).map(drop),
        ),
        Kind::Hook(k) => (
            format!("`{}`", k.signature()),
            pipeline::shader::compile_hook(k, &source).map(drop),
        ),
    };
    match result {
        Ok(()) => {
            say!("{}: ok ({what})", path.display());
            Some(true)
        }
        Err(errors) => {
            for e in &errors {
                let said = crate::vocabulary::compile::complaint(
                    &e.complaint,
                    crate::vocabulary::Lang::EN,
                )
                .unwrap_or_else(|| e.message.clone());
                eprintln!("{}:{}:{}: error: {said}", path.display(), e.line, e.column);
            }
            Some(false)
        }
    }
}

/// The files `check` reads: each file named, and every `.toml` file under each folder named
/// (sorted, at any depth); a folder with none is a problem.
fn files_to_check(paths: &[PathBuf]) -> (Vec<PathBuf>, Vec<String>) {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)?
            .map(|e| e.map(|e| e.path()))
            .collect::<std::io::Result<_>>()?;
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out)?;
            } else if p.extension().is_some_and(|e| e == "toml") {
                out.push(p);
            }
        }
        Ok(())
    }
    let (mut files, mut problems) = (Vec::new(), Vec::new());
    for p in paths {
        if !p.is_dir() {
            files.push(p.clone());
            continue;
        }
        let before = files.len();
        match walk(p, &mut files) {
            Err(e) => problems.push(format!(
                "{}: error: cannot read this folder: {e}",
                p.display()
            )),
            Ok(()) if files.len() == before => problems.push(format!(
                "{}: error: this folder has no .toml file to check",
                p.display()
            )),
            Ok(()) => {}
        }
    }
    (files, problems)
}
