//! The command line: `pipelens [COMMAND]`.

/// `println!` that ends the program quietly when its reader has gone (`pipelens check lessons/ |
/// head`), where `println!` panics with "failed printing to stdout".
macro_rules! say {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        if let Err(e) = writeln!(std::io::stdout().lock(), $($t)*) {
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                std::process::exit(0);
            }
        }
    }};
}

mod args;
mod authoring;
mod grade;

pub use args::Size;
use args::{parse_line, parse_pixel, parse_stage};

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use pipeline::capture::FrameCapture;
use pipeline::raster::Samples;
use pipeline::settings::RenderSettings;
use pipeline::shade::Frequency;

use crate::export::ExportOptions;
use crate::lesson::{self, SceneSpec};

/// pipelens — the graphics pipeline as a glass box.
#[derive(Debug, Parser)]
#[command(name = "pipelens", version, about, long_about = None)]
pub struct Cli {
    /// What to do; with none, pipelens opens the app.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// The app: the lesson or scene file to open (the built-in tour, lessons/00-tour.toml, when
    /// omitted). The file is watched: edits are reloaded on save.
    #[arg(long = "lesson", visible_alias = "scene", value_name = "FILE")]
    pub scene: Option<PathBuf>,
    /// The app: the interface language, `en` or `zh`.
    #[arg(long, value_parser = ["en", "zh"])]
    pub lang: Option<String>,
    /// The app: the stage to open on (model, world, view, clip, ndc, viewport, rasterization,
    /// depth, shading, texturing, output).
    #[arg(long, value_parser = parse_stage)]
    pub stage: Option<crate::vocabulary::Stage>,
    /// The app: settings to compare side by side in the pixel stages.
    #[arg(long, value_parser = ["shading", "interpolation", "samples", "filtering", "minification"])]
    pub compare: Option<String>,
    /// The app: a lesson's step to open on (1-based).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub step: Option<u32>,
    /// The app: open in classroom mode (large type, high contrast, the picture first; key C).
    #[arg(long)]
    pub classroom: bool,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene with no window and write every stage's buffers as PNG, plus capture.json.
    Export {
        /// The scene or lesson file (TOML); the built-in scene when omitted. A lesson exports
        /// every step (or `--step N`) into step-NN/ folders with an index.html handout.
        scene: Option<PathBuf>,
        /// A lesson: export only step N (1-based).
        #[arg(long)]
        step: Option<usize>,
        /// A lesson: the handout's language, `en` or `zh`.
        #[arg(long, value_parser = ["en", "zh"], default_value = "en")]
        lang: String,
        /// A lesson: a teacher's key, every answer printed under its question.
        #[arg(long)]
        answers: bool,
        /// A lesson: also one 1920×1080 PNG per step in `slides/`, for a slide deck.
        #[arg(long)]
        slides: bool,
        /// A lesson: also each step's buffers as PNG and capture.json in `step-NN/`, and the
        /// textures' mip levels in `textures/`.
        #[arg(long)]
        data: bool,
        /// The folder to write into (created if missing).
        #[arg(long, short)]
        out: PathBuf,
        /// Viewport size, e.g. 1280x720 (overrides the scene's).
        #[arg(long)]
        size: Option<Size>,
        /// Samples per pixel: 1, 4, 8 or 16 (overrides the scene's).
        #[arg(long)]
        samples: Option<u32>,
        /// Magnification of overlays.png (0: at least 1280 pixels wide).
        #[arg(long, default_value_t = 0)]
        zoom: u32,
        /// At most this many vertex rows and primitive records in capture.json.
        #[arg(long, default_value_t = 200_000)]
        max_records: usize,
        /// Also write profile.csv, the intensity along the line X0,Y0,X1,Y1 (image pixels, y
        /// down); with lighting on, for flat, Gouraud and Phong shading side by side.
        #[arg(long, value_name = "X0,Y0,X1,Y1", value_parser = parse_line)]
        profile: Option<[f32; 4]>,
        /// Also write into capture.json everything about window pixel X,Y (y up, as the app's
        /// pixel inspector shows it): every fragment, its depth test, each lighting term, the
        /// texture lookup, the shaders' runs. For a lesson, with --data: in every step's
        /// capture.json, in place of the step's own pixel.
        #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
        pixel: Option<(u32, u32)>,
    },
    /// Validate scene and lesson files and print every problem with file:line:column.
    Check {
        /// The files to check; a folder stands for every `.toml` file under it. A `.vert` or
        /// `.frag` file is compiled as that stage, `inside.glsl` (and the other pipeline
        /// functions' files, as the shader panel's Save names them) as that function.
        #[arg(required = true)]
        paths: Vec<PathBuf>,
    },
    /// Write a new lesson: a commented bilingual template that uses every key a step can take
    /// and passes `check` as it is. An existing file is never overwritten.
    NewLesson {
        /// The lesson file to create, e.g. lessons/20-my-lesson.toml; its name becomes the id.
        file: PathBuf,
        /// A lab instead: a step where the student completes a shader, checked pixel by pixel
        /// against pipelens' own (`exercise = { task, starter, tolerance }`).
        #[arg(long)]
        lab: bool,
    },
    /// Grade a class's lab hand-ins with no window, exactly as the app checks a lab: each
    /// student's code drawn and compared with pipelens' own, pixel by pixel. Prints a table
    /// (student, step, passed, matching pixels, the first difference in words).
    Grade {
        /// The lesson: a lesson file, or a built-in lesson's name such as 10-blinn-phong.
        lesson: String,
        /// The hand-ins, one per student: a folder as the shader panel's Save writes it
        /// (shader.vert, shader.frag, inside.glsl, …), one source file, or the LESSON-work.toml
        /// the app's Export my work writes. What a student did not hand in stays the starter's.
        #[arg(required = true, value_name = "SUBMISSION")]
        submissions: Vec<PathBuf>,
        /// The lab step to grade (1-based; repeat for several). Every lab step when omitted.
        #[arg(long = "step", value_name = "N")]
        steps: Vec<usize>,
        /// Also write the grades as CSV (one row per student and step).
        #[arg(long, value_name = "FILE")]
        csv: Option<PathBuf>,
        /// Also write Gradescope's results.json (one hand-in: Gradescope runs one container
        /// per submission; scripts/gradescope/ holds the autograder).
        #[arg(long, value_name = "FILE")]
        gradescope: Option<PathBuf>,
        /// The feedback's language, `en` or `zh`.
        #[arg(long, default_value = "en", value_parser = ["en", "zh"])]
        lang: String,
    },
    /// Time each stage of the pipeline on standard scenes.
    Bench {
        /// One frame per case (a smoke run).
        #[arg(long)]
        quick: bool,
        /// Instead: each lesson's handout size and export time, in both languages (the lessons
        /// of `lessons/`, and the six-step teapot lesson when the data has the teapot).
        #[arg(long)]
        handouts: bool,
        /// Instead: only the rows of the student's shaders (GLSL beside the built-in path).
        #[arg(long, conflicts_with = "handouts")]
        shaders: bool,
        /// Instead: each step of a built-in lesson (its file name without `.toml`, as
        /// `00-tour`) rendered as the app renders it, on one thread and on every thread: the
        /// frame time a page reports beside it (`scripts/web-test.sh`).
        #[arg(long, value_name = "LESSON", conflicts_with_all = ["handouts", "shaders"])]
        steps: Option<String>,
        /// Instead: this many hand-ins of lesson 10's specular lab (right, wrong and broken)
        /// graded as `pipelens grade` grades them, timed (200 in ≤ 60 s on 2 threads is the
        /// target).
        #[arg(long, value_name = "N", num_args = 0..=1, default_missing_value = "200",
              conflicts_with_all = ["handouts", "shaders", "steps"])]
        grade: Option<usize>,
        /// Frames per case (the median is shown).
        #[arg(long)]
        frames: Option<usize>,
        /// Also run the llvmpipe reference renderer alternately on the bunny and Spot: the
        /// Python of its venv (see ../shared/peers/llvmpipe/README.md).
        #[arg(long, value_name = "PYTHON")]
        peer_python: Option<PathBuf>,
        /// The peer's render.py.
        #[arg(
            long,
            value_name = "SCRIPT",
            default_value = "../shared/peers/llvmpipe/render.py"
        )]
        peer_script: PathBuf,
        /// Where the bunny and Spot are.
        #[arg(long, value_name = "DIR", default_value = "../shared/data")]
        data: PathBuf,
    },
}

/// Parses the command line, runs it, prints errors as one clear message, and returns the exit code.
#[must_use]
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("pipelens: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// Runs a parsed command line.
///
/// # Errors
/// Any failure, with its context, for `main` to print.
pub fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        None => open_app(&cli),
        Some(Command::Export {
            scene,
            out,
            size,
            samples,
            zoom,
            max_records,
            profile,
            pixel,
            step,
            lang,
            answers,
            slides,
            data,
        }) => {
            if let Some(path) = scene.as_deref()
                && let lesson::Document::Lesson(l) =
                    lesson::load_file(path).map_err(|d| anyhow::anyhow!("{d}"))?
            {
                if let Some((x, y)) = pixel
                    && !data
                {
                    anyhow::bail!(
                        "--pixel {x},{y} writes that pixel's record into each step's capture.json, which a lesson's export writes with --data: add --data"
                    );
                }
                let opts = crate::export::lesson::LessonExport {
                    out,
                    step: match step {
                        Some(0) => anyhow::bail!("--step counts from 1"),
                        s => s.map(|s| s - 1),
                    },
                    size: size.map(|s| (s.width, s.height)),
                    lang: if lang == "zh" {
                        crate::vocabulary::Lang::Zh
                    } else {
                        crate::vocabulary::Lang::En
                    },
                    max_records,
                    answers,
                    slides,
                    data,
                    pixel,
                    cancel: cancel_on_interrupt(),
                };
                return export_lesson(&l, &opts);
            }
            if step.is_some() {
                anyhow::bail!("--step applies to lessons; this is a scene file");
            }
            let opts = ExportOptions {
                out,
                overlay_zoom: zoom,
                max_records,
                pixel,
                cancel: cancel_on_interrupt(),
            };
            export(scene.as_deref(), &opts, size, samples, profile)?;
            Ok(ExitCode::SUCCESS)
        }
        Some(Command::Check { paths }) => Ok(authoring::check(&paths)),
        Some(Command::Grade {
            lesson,
            submissions,
            steps,
            csv,
            gradescope,
            lang,
        }) => {
            grade::run(&grade::GradeRequest {
                lesson,
                steps,
                submissions,
                csv,
                gradescope,
                lang: if lang == "zh" {
                    crate::vocabulary::Lang::Zh
                } else {
                    crate::vocabulary::Lang::En
                },
            })?;
            Ok(ExitCode::SUCCESS)
        }
        Some(Command::NewLesson { file, lab }) => authoring::new_lesson(&file, lab),
        Some(bench @ Command::Bench { .. }) => run_bench(bench),
    }
}

/// `pipelens bench` in its five forms: the stages (with llvmpipe alongside on request), the
/// handouts, the student's shaders, a lesson's steps as the app renders them, a class's lab
/// hand-ins graded.
fn run_bench(command: Command) -> Result<ExitCode> {
    match command {
        Command::Bench {
            handouts: true,
            data,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::handouts::run(Path::new("lessons"), &data, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            shaders: true,
            quick,
            frames,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::shader_rows(frames.unwrap_or(if quick { 1 } else { 5 }), &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            grade: Some(count), ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::grade::run(count, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            steps: Some(lesson),
            quick,
            frames,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            let threads = std::thread::available_parallelism().map_or(1, usize::from);
            let frames = frames.unwrap_or(if quick { 1 } else { 7 });
            crate::bench::steps::run(&format!("{lesson}.toml"), frames, threads, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            quick,
            frames,
            peer_python,
            peer_script,
            data,
            handouts: false,
            shaders: false,
            steps: None,
            grade: None,
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::run(quick, frames, &mut out)?;
            if let Some(python) = peer_python {
                let peer = crate::bench::Peer {
                    python,
                    script: peer_script,
                };
                crate::bench::run_against_peer(&peer, &data, quick, &mut out)?;
            }
            Ok(ExitCode::SUCCESS)
        }
        _ => anyhow::bail!("run_bench is called with a bench command"),
    }
}

/// The app, on the lesson or scene the command line names (the tour by default).
fn open_app(cli: &Cli) -> Result<ExitCode> {
    let doc = match cli.scene.as_deref() {
        Some(p) => lesson::load_file(p),
        None => lesson::default_lesson().map(|l| lesson::Document::Lesson(Box::new(l))),
    }
    .map_err(|d| anyhow::anyhow!("{d}"))?;
    let source = crate::app::session::source_name(cli.scene.as_ref());
    let lang = match cli.lang.as_deref() {
        Some("zh") => crate::vocabulary::Lang::Zh,
        Some(_) => crate::vocabulary::Lang::En,
        None => crate::app::initial_lang(),
    };
    let start = crate::app::Start {
        lang,
        stage: cli.stage,
        compare: cli
            .compare
            .as_deref()
            .and_then(crate::vocabulary::Comparison::from_name),
        step: cli.step.map(|n| n as usize - 1),
        classroom: cli.classroom,
    };
    crate::app::run(doc, source, cli.scene.clone(), start)?;
    Ok(ExitCode::SUCCESS)
}

/// The progress of an export: a bar on stderr when it is a terminal, nothing in a log or a
/// pipe (where the summary printed at the end says what was written).
struct Progress(indicatif::ProgressBar);

impl Progress {
    fn new() -> Self {
        let bar =
            indicatif::ProgressBar::with_draw_target(None, indicatif::ProgressDrawTarget::stderr());
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:30}] {pos}/{len} {wide_msg}",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        Self(bar)
    }

    fn show(&self, done: usize, all: usize, what: &str) {
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
fn cancel_on_interrupt() -> crate::export::Cancel {
    let cancel = crate::export::Cancel::default();
    let flag = cancel.clone();
    // Fails only if a handler is already set (never, in one command): then Ctrl+C just exits.
    let _ = ctrlc::set_handler(move || flag.cancel());
    cancel
}

fn export_lesson(
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

fn export(
    scene: Option<&Path>,
    opts: &ExportOptions,
    size: Option<Size>,
    samples: Option<u32>,
    profile: Option<[f32; 4]>,
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
    let capture = pipeline::render(&spec.scene, &spec.settings)?;
    for w in capture.not_finite_warnings() {
        eprintln!("pipelens: warning: {w}");
    }
    let mut files = crate::export::encode_capture(&capture, opts)?;
    if let Some(line) = profile {
        files.push(profile_file(&spec, &capture, line)?);
    }
    let bar = Progress::new();
    let written = crate::export::write_files(
        &opts.out,
        &files,
        &mut |done, all, name| bar.show(done, all, name),
        &opts.cancel,
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

#[cfg(test)]
mod tests {
    use super::Size;

    #[test]
    fn sizes_parse_and_reject() {
        assert_eq!(
            "640x480".parse::<Size>(),
            Ok(Size {
                width: 640,
                height: 480
            })
        );
        assert_eq!("1280×720".parse::<Size>().map(|s| s.width), Ok(1280));
        for bad in ["640", "0x10", "10x0", "100000x100000", "axb", "-5x5"] {
            assert!(bad.parse::<Size>().is_err(), "{bad} should be rejected");
        }
    }
}
