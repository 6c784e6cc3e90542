//! The command line: `pipelens [COMMAND]` — its arguments (`args.rs`), a command sent to where
//! it is done: exports (`export.rs`), `check` and `new-lesson` (`authoring.rs`), `grade`
//! (`grade.rs`), `bench` (`bench.rs`), or the app.

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
mod bench;
mod export;
mod grade;

pub use args::Size;
use args::{parse_lang, parse_line, parse_pixel, parse_stage, parse_watch};
pub use export::load;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};

use crate::export::ExportOptions;
use crate::lesson::{self};

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
    /// The app: the interface language, by its tag — one of the catalogs in locales/ (en,
    /// zh-Hans or zh), or the pseudo-locale en-XA.
    #[arg(long, value_parser = parse_lang)]
    pub lang: Option<crate::vocabulary::Lang>,
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
        /// A lesson: the handout's language, by its tag (en, zh-Hans or zh, any catalog in
        /// locales/).
        #[arg(long, value_parser = parse_lang, default_value = "en")]
        lang: crate::vocabulary::Lang,
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
        /// Also write watch.png and watch.csv: the fragment shader's expression EXPR just after
        /// line LINE, at every pixel (as the debugger's variable picture draws it); with
        /// EXPR@vertex:LINE the vertex shader's, interpolated over each triangle. For a
        /// lesson, with --step: the step's shaders, and only the watch's files.
        #[arg(long, value_name = "EXPR@LINE", value_parser = parse_watch)]
        watch: Option<pipeline::shader::probe::WatchSpec>,
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
    /// (student, step, passed, matching pixels, and the feedback: the verdict, where the first
    /// difference is and what was found there).
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
        /// The feedback's language, by its tag (en, zh-Hans or zh, any catalog in locales/).
        #[arg(long, default_value = "en", value_parser = parse_lang)]
        lang: crate::vocabulary::Lang,
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
        /// Instead: only the rows of the student's shaders (GLSL beside the built-in path) and
        /// of the shader debugger (a keystroke to the picture, a click to its trace, a watch,
        /// a variable's picture, on lesson 24).
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
        /// Instead: the frame at 1, 2, 4, … threads up to the cores (or `--threads`), with its
        /// speed-up and efficiency: the every-buffer and colour-only frames of the lit textured
        /// scene, the every-buffer resolve, the 1M sphere, the student's GLSL over the built-in.
        #[arg(long, conflicts_with_all = ["handouts", "shaders", "steps", "grade"])]
        scaling: bool,
        /// The thread counts `--scaling` measures, as `1,2,4` (default: 1, then doubling, up to
        /// the cores).
        #[arg(long, value_name = "N,N,…", value_delimiter = ',', requires = "scaling",
              value_parser = clap::value_parser!(u16).range(1..=1024))]
        threads: Vec<u16>,
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
            watch,
        }) => {
            if let Some(path) = scene.as_deref()
                && let lesson::Document::Lesson(l) =
                    lesson::load_file(path).map_err(|d| anyhow::anyhow!("{d}"))?
            {
                if let Some(watch) = &watch {
                    return export::export_step_watch(&l, step, &out, size, watch);
                }
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
                    lang,
                    max_records,
                    answers,
                    slides,
                    data,
                    pixel,
                    cancel: export::cancel_on_interrupt(),
                };
                return export::export_lesson(&l, &opts);
            }
            if step.is_some() {
                anyhow::bail!("--step applies to lessons; this is a scene file");
            }
            let opts = ExportOptions {
                out,
                overlay_zoom: zoom,
                max_records,
                pixel,
                cancel: export::cancel_on_interrupt(),
                lang,
            };
            export::export(
                scene.as_deref(),
                &opts,
                size,
                samples,
                (profile, watch.as_ref()),
            )?;
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
                lang,
            })?;
            Ok(ExitCode::SUCCESS)
        }
        Some(Command::NewLesson { file, lab }) => authoring::new_lesson(&file, lab),
        Some(bench @ Command::Bench { .. }) => bench::run(bench),
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
    let lang = cli.lang.unwrap_or_else(crate::app::initial_lang);
    let speaks = |l: &lesson::Lesson| l.title.others.keys().any(|t| lang.matches(t));
    if !lang.has_catalog() && !matches!(&doc, lesson::Document::Lesson(l) if speaks(l)) {
        let found: Vec<&str> = crate::vocabulary::Lang::all()
            .iter()
            .map(|l| l.tag())
            .collect();
        eprintln!(
            "pipelens: no catalog and no lesson words in \"{}\": it is shown in English (the catalogs found: {})",
            lang.tag(),
            found.join(", ")
        );
    }
    let start = crate::app::Start {
        lang,
        stage: cli.stage,
        compare: cli
            .compare
            .as_deref()
            .and_then(crate::vocabulary::Comparison::from_name),
        step: cli.step.map(|n| n as usize - 1),
        classroom: cli.classroom,
        touch: false,
    };
    crate::app::run(doc, source, cli.scene.clone(), start)?;
    Ok(ExitCode::SUCCESS)
}
