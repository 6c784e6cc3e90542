//! `pipelens export`: a scene's stage snapshots, or a lesson's handout, slides and data, with a
//! progress bar on a terminal and Ctrl+C stopping between two whole files.

use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context, Result};
use pipeline::capture::FrameCapture;
use pipeline::lighting::Frequency;
use pipeline::raster::Samples;
use pipeline::settings::RenderSettings;

use super::args::Size;
use crate::export::ExportOptions;
use crate::lesson::{self, SceneSpec};

/// The progress of an export: a bar on stderr when it is a terminal, nothing in a log or a
/// pipe (where the summary printed at the end says what was written).
pub(super) struct Progress(indicatif::ProgressBar);

impl Progress {
    pub(super) fn new() -> Self {
        let bar =
            indicatif::ProgressBar::with_draw_target(None, indicatif::ProgressDrawTarget::stderr());
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:30}] {pos}/{len} {wide_msg}",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        Self(bar)
    }

    pub(super) fn show(&self, done: usize, all: usize, what: &str) {
        self.0.set_length(all as u64);
        self.0.set_position(done as u64);
        self.0.set_message(what.to_owned());
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}

/// A cancel flag that Ctrl+C sets: the export then stops between two files, leaving whole
/// files and no temporary ones, and says so.
pub(super) fn cancel_on_interrupt() -> crate::export::Cancel {
    let cancel = crate::export::Cancel::default();
    let flag = cancel.clone();
    // Fails only if a handler is already set (never, in one command): then Ctrl+C just exits.
    let _ = ctrlc::set_handler(move || flag.cancel());
    cancel
}

pub(super) fn export_lesson(
    lesson: &lesson::Lesson,
    opts: &crate::export::lesson::LessonExport,
) -> Result<ExitCode> {
    let bar = Progress::new();
    let exported = crate::export::lesson::export_lesson(lesson, opts, &mut |done, all, what| {
        bar.show(done, all, what);
    })?;
    drop(bar);
    for w in &exported.warnings {
        eprintln!("pipelens: warning: {w}");
    }
    say!(
        "Exported {} files of lesson {} to {}; open {}",
        exported.written.len(),
        lesson.id,
        opts.out.display(),
        opts.out.join("index.html").display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Loads a scene file, or the built-in scene for `None`.
///
/// # Errors
/// The file's diagnostics, all of them.
pub fn load(scene: Option<&Path>) -> Result<SceneSpec> {
    let spec = match scene {
        Some(p) => lesson::load_scene_file(p),
        None => lesson::default_scene(),
    };
    spec.map_err(|d| anyhow::anyhow!("{d}"))
}

pub(super) fn export(
    scene: Option<&Path>,
    opts: &ExportOptions,
    size: Option<Size>,
    samples: Option<u32>,
    (profile, watch): (
        Option<[f32; 4]>,
        Option<&pipeline::shader::probe::WatchSpec>,
    ),
) -> Result<()> {
    let mut spec = load(scene)?;
    if let Some(s) = size {
        spec.settings.width = s.width;
        spec.settings.height = s.height;
    }
    if let Some(n) = samples {
        spec.settings.samples = Samples::from_count(n)
            .with_context(|| format!("--samples must be 1, 4, 8 or 16, got {n}"))?;
    }
    // The inspected pixel's fragment-shader runs are recorded as the frame is drawn.
    if opts.pixel.is_some() {
        spec.settings.capture.pixel = opts.pixel;
    }
    let scene = match watch {
        Some(w) => spec.scene.watching(w)?,
        None => spec.scene.clone(),
    };
    let capture = pipeline::render(&scene, &spec.settings)?;
    for w in capture.not_finite_warnings() {
        eprintln!("pipelens: warning: {w}");
    }
    let mut files = crate::export::encode_capture(&capture, opts)?;
    if let Some(picture) = capture.shaders.as_ref().and_then(|r| r.watch.as_ref()) {
        files.extend(crate::export::watch_files(picture)?);
        say_watch(picture);
    }
    if let Some(line) = profile {
        files.push(profile_file(&spec, &capture, line)?);
    }
    let bar = Progress::new();
    let written = crate::export::write_files(
        &opts.out,
        &files,
        &mut |done, all, name| bar.show(done, all, name),
        (&opts.cancel, opts.lang),
    )?;
    drop(bar);
    say!(
        "Exported {} files ({}×{}, {} sample(s), {} primitives) to {}:",
        written.len(),
        spec.settings.width,
        spec.settings.height,
        spec.settings.samples.count(),
        capture.primitives.len(),
        opts.out.display()
    );
    for p in &written {
        say!("  {}", p.display());
    }
    Ok(())
}

/// Step `step` (from 1) of `lesson` drawn with its shaders watching `watch`: the watch's files
/// written into `out`, whole or not at all.
///
/// # Errors
/// No step given, a step without shaders of its own, a watch that does not compile, a size the
/// renderer refuses, a file that could not be written.
pub(super) fn export_step_watch(
    lesson: &lesson::Lesson,
    step: Option<usize>,
    out: &Path,
    size: Option<Size>,
    watch: &pipeline::shader::probe::WatchSpec,
) -> Result<ExitCode> {
    let Some(k) = step.and_then(|s| s.checked_sub(1)) else {
        anyhow::bail!("--watch on a lesson reads one step's shaders: add --step N (from 1)");
    };
    if k >= lesson.steps.len() {
        anyhow::bail!(
            "--step {}: the lesson has {} steps",
            k + 1,
            lesson.steps.len()
        );
    }
    let mut spec = lesson.spec_at(k);
    if let Some(s) = size {
        spec.settings.width = s.width;
        spec.settings.height = s.height;
    }
    if let Some(p) = spec.settings.problems().first() {
        anyhow::bail!("{p}");
    }
    let scene = spec
        .scene
        .watching(watch)
        .with_context(|| format!("step {}", k + 1))?;
    let capture = pipeline::render(&scene, &spec.settings)?;
    let picture = capture
        .shaders
        .as_ref()
        .and_then(|r| r.watch.as_ref())
        .context("the frame kept no watch")?;
    let files = crate::export::watch_files(picture)?;
    let written = crate::export::write_files(
        out,
        &files,
        &mut |_, _, _| {},
        (
            &crate::export::Cancel::default(),
            crate::vocabulary::Lang::EN,
        ),
    )?;
    say_watch(picture);
    for p in &written {
        say!("  {}", p.display());
    }
    Ok(ExitCode::SUCCESS)
}

/// What a watch saw, in a line: where it ran, its type and its range.
fn say_watch(picture: &pipeline::capture::WatchPicture) {
    let what = format!("`{}` {}", picture.expression, picture.place());
    match picture.kind {
        None if picture.from_vertex => {
            say!("{what}: no triangle of the frame has all three corners through that line");
        }
        None => say!("{what}: no fragment of the frame ran that line"),
        Some(pipeline::shader::probe::WatchKind::Bool) => {
            let holds = picture
                .values
                .iter()
                .flatten()
                .filter(|v| v[0] != 0.0)
                .count();
            let first = picture
                .first_where()
                .map(|(x, y)| format!("; the first, reading from the top, at pixel {x},{y}"))
                .unwrap_or_default();
            say!(
                "{what}: holds at {holds} of the {} pixels that have it{first}",
                picture.pixels_run()
            );
        }
        Some(kind) => {
            let range = picture
                .range(0)
                .map(|(lo, hi)| format!(", first component from {lo} to {hi}"))
                .unwrap_or_default();
            say!(
                "{what}: a {} at {} pixels{range}",
                kind.glsl(),
                picture.pixels_run()
            );
        }
    }
}

/// The profile along `line`: of the capture itself when unlit; of the flat, Gouraud and Phong
/// renderings of the same scene when lit (the Mach band comparison).
fn profile_file(
    spec: &SceneSpec,
    capture: &FrameCapture,
    line: [f32; 4],
) -> Result<crate::export::ExportFile> {
    if spec.settings.shading == Frequency::Unlit {
        return Ok(crate::export::profile_csv(line, &[("color", capture)]));
    }
    let modes = [
        ("flat", Frequency::Flat),
        ("gouraud", Frequency::Gouraud),
        ("phong", Frequency::Phong),
    ];
    let captures = modes
        .iter()
        .map(|(_, f)| {
            let settings = RenderSettings {
                shading: *f,
                ..spec.settings
            };
            pipeline::render(&spec.scene, &settings)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let named: Vec<(&str, &FrameCapture)> =
        modes.iter().map(|(n, _)| *n).zip(captures.iter()).collect();
    Ok(crate::export::profile_csv(line, &named))
}
