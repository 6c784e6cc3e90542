//! Export of a lesson: `index.html`, one self-contained handout (every image embedded) in one
//! language, whose pictures are what the app shows for each step ([`super::picture`]); an
//! animated step gets a filmstrip for print and an animated GIF for screens. On request:
//! `--slides` (one 1920×1080 PNG per step, [`super::slides`]) and `--data` (each step's buffers
//! as PNG and `capture.json` in `step-NN/`, each texture's mip levels once in `textures/`).

use std::path::PathBuf;

use anyhow::{Context, Result};
use image::RgbaImage;
use pipeline::capture::FrameCapture;
use rayon::prelude::*;

use super::filmstrip;
use super::handout::{self, Animated, Frame, StepPage};
use super::palette::Palette;
use super::picture::{Rendered, step_picture};
use super::{ExportFile, ExportOptions, png_rgba, write_files};
use crate::lesson::param::Value;
use crate::lesson::{Lesson, SceneSpec};
use crate::vocabulary::Lang;

/// What to export of a lesson.
#[derive(Clone, Debug)]
pub struct LessonExport {
    /// The folder (created if missing).
    pub out: PathBuf,
    /// One step (0-based), or all.
    pub step: Option<usize>,
    /// A viewport size overriding the lesson's.
    pub size: Option<(u32, u32)>,
    /// The handout's language.
    pub lang: Lang,
    /// At most this many records per table in each `capture.json` (with `data`).
    pub max_records: usize,
    /// A teacher's key: every answer printed under its question.
    pub answers: bool,
    /// One 1920×1080 PNG per step in `slides/`.
    pub slides: bool,
    /// Each step's buffers and `capture.json` in `step-NN/`, the textures in `textures/`.
    pub data: bool,
    /// With `data`: the window pixel `(x, y)` (y up) whose full record each step's
    /// `capture.json` holds, in place of the step's own inspected pixel.
    pub pixel: Option<(u32, u32)>,
    /// Stops the export between two files.
    pub cancel: super::Cancel,
}

/// The moments of an animated step drawn for its GIF (screens), from its start to its end;
/// every other one makes the filmstrip (paper), 5 frames.
const GIF_FRAMES: usize = 9;

/// The folder name of step `k` (0-based): `step-01`, `step-02`…
fn step_dir(k: usize) -> String {
    format!("step-{:02}", k + 1)
}

/// What a lesson's export wrote, and what it warns of.
#[derive(Debug, Default)]
pub struct Exported {
    /// Every path written.
    pub written: Vec<PathBuf>,
    /// A step's frame drawn with something a reader should know, `step 3: …`: triangles
    /// dropped for a `gl_Position` that is not finite, pixels whose colour was not.
    pub warnings: Vec<String>,
}

/// Exports `lesson`; returns every path written and each step's warnings. `progress` is told
/// how many parts of how many are done and which was done last.
///
/// # Errors
/// A step out of range, a render or an encoding that fails, a folder that cannot be written.
pub fn export_lesson(
    lesson: &Lesson,
    opts: &LessonExport,
    progress: &mut (dyn FnMut(usize, usize, &str) + Send),
) -> Result<Exported> {
    let (steps, built) = build_steps(lesson, opts, progress)?;
    let mut written = Vec::new();
    let mut warnings = Vec::new();
    let mut pages = Vec::new();
    let mut textures_written = false;
    for b in built {
        let (page, folders, warned) = b?;
        warnings.extend(warned);
        for (folder, files) in folders {
            if folder == "textures" && std::mem::replace(&mut textures_written, true) {
                continue;
            }
            written.extend(write_files(
                &opts.out.join(folder),
                &files,
                &mut |_, _, _| {},
                (&opts.cancel, opts.lang),
            )?);
        }
        pages.push(page);
    }
    progress(steps, steps + 1, "index.html");
    let html = handout::html(lesson, &pages, opts.lang, opts.answers);
    let target = opts.out.join("index.html");
    super::create_folder(&opts.out, opts.lang)?;
    super::write_atomically(&target, html.as_bytes(), opts.lang)?;
    written.push(target);
    Ok(Exported { written, warnings })
}

/// The handout alone, as one self-contained HTML text (every image in it), written nowhere: what
/// the browser build offers as a download. `opts.out`, `slides` and `data` are not used.
///
/// # Errors
/// When a step cannot be rendered, or `opts.step` is out of range.
pub fn handout_html(lesson: &Lesson, opts: &LessonExport) -> Result<String> {
    let opts = LessonExport {
        slides: false,
        data: false,
        ..opts.clone()
    };
    let (_, built) = build_steps(lesson, &opts, &mut |_, _, _| {})?;
    let pages = built
        .into_iter()
        .map(|b| b.map(|(page, _, _)| page))
        .collect::<Result<Vec<_>>>()?;
    Ok(handout::html(lesson, &pages, opts.lang, opts.answers))
}

/// Every step asked for (`opts.step`, or all), built in parallel: how many, and each one's page
/// and files, in order. `progress` hears of each step as it is done.
fn build_steps(
    lesson: &Lesson,
    opts: &LessonExport,
    progress: &mut (dyn FnMut(usize, usize, &str) + Send),
) -> Result<(usize, Vec<Result<BuiltStep>>)> {
    let n = lesson.steps.len();
    let steps: Vec<usize> = match opts.step {
        Some(k) if k < n => vec![k],
        Some(k) => anyhow::bail!(
            "--step {} is out of range: the lesson has steps 1 to {n}",
            k + 1
        ),
        None => (0..n).collect(),
    };
    let parts = steps.len() + 1;
    // The steps are independent: each is rendered, drawn and encoded on its own thread; the
    // files are written afterwards, in order.
    let done = std::sync::atomic::AtomicUsize::new(0);
    let progress = std::sync::Mutex::new(progress);
    let built: Vec<Result<BuiltStep>> = steps
        .par_iter()
        .map(|&k| {
            opts.cancel.check()?;
            let out = build_step(lesson, k, opts)?;
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            if let Ok(mut p) = progress.lock() {
                let title = lesson.steps[k].title.get(opts.lang);
                p(n, parts, &format!("step {}: {title}", k + 1));
            }
            Ok(out)
        })
        .collect();
    Ok((steps.len(), built))
}

/// A step's page of the handout, the files it adds by folder (its slide, its data), and its
/// frame's warnings.
type BuiltStep = (StepPage, Vec<(String, Vec<ExportFile>)>, Vec<String>);

/// Step `k`'s page of the handout, and the files it adds (by folder): its slide, its data.
fn build_step(lesson: &Lesson, k: usize, opts: &LessonExport) -> Result<BuiltStep> {
    let Drawn {
        spec,
        capture,
        variants,
        picture,
        print,
    } = draw(lesson, k, opts, None)?;
    let animated = animation(lesson, k, opts)?;
    let mut folders = Vec::new();
    let legend = super::picture::legend(lesson, k, &capture, opts.lang);
    if opts.slides {
        let extras = slide_extras(lesson, k, &capture, legend.clone(), opts.lang);
        let slide = super::slides::slide(lesson, k, &picture, &extras, opts.lang);
        let file = ExportFile {
            name: format!("{}.png", step_dir(k)),
            description: format!("slide of step {}", k + 1),
            bytes: png_rgba(&slide)?,
        };
        folders.push(("slides".to_owned(), vec![file]));
    }
    if opts.data {
        let export = ExportOptions {
            out: opts.out.join(step_dir(k)),
            overlay_zoom: 0,
            max_records: opts.max_records,
            pixel: opts.pixel,
            cancel: opts.cancel.clone(),
            lang: opts.lang,
        };
        let (files, textures) =
            super::lesson_data::data_files(lesson, k, export, &capture, &variants)?;
        folders.push((step_dir(k), files));
        if !textures.is_empty() {
            folders.push(("textures".to_owned(), textures));
        }
    }
    let mut matrices = capture.matrices.clone();
    for m in &mut matrices.models {
        // `M_model(floor)` in the handout's language: `M_model(地面)`.
        if let Some(object) = m
            .name
            .strip_prefix("M_model(")
            .and_then(|r| r.strip_suffix(')'))
        {
            m.name = format!("M_model({})", spec.label(object, opts.lang));
        }
    }
    // The debugger's run at the step's own pixel (or the one asked for), where shaders ran.
    let pixel = capture.settings.capture.pixel;
    let trace = capture
        .shaders
        .as_ref()
        .filter(|_| lesson.steps[k].pixel.is_some() || opts.pixel.is_some())
        .map(|s| s.pixel.clone())
        .unwrap_or_default();
    let alt = alt_text(lesson, k, &spec, &capture, opts);
    let page = StepPage {
        alt,
        index: k,
        picture: compact_image(&print)?,
        trace: pixel.map(|p| (p, trace)).filter(|(_, t)| !t.is_empty()),
        legend,
        animated,
        subject: crate::spaces::subject(
            &capture,
            lesson.steps[k].focus.as_deref().unwrap_or_default(),
            None,
            crate::vocabulary::Space::World,
        ),
        matrices,
        stage: lesson.stage_at(k),
    };
    let warnings = capture
        .not_finite_warnings()
        .into_iter()
        .map(|w| format!("step {}: {w}", k + 1))
        .collect();
    Ok((page, folders, warnings))
}

/// What step `k`'s slide shows besides its picture and words: the picture's `legend`; for a lab,
/// what the picture is, the task and the starter's TODO lines; else the debugger's run at the
/// step's pixel, or the lines of its own shaders its edit changed (the start of `main()` where
/// nothing came before).
fn slide_extras(
    lesson: &Lesson,
    k: usize,
    capture: &FrameCapture,
    legend: Vec<String>,
    lang: Lang,
) -> super::slides::Extras {
    use super::listing::{focus, starter_todos, step_edits};
    let step = &lesson.steps[k];
    let local = |source: &str| crate::vocabulary::glsl::localize(source, lang, &lesson.comments);
    let mut extras = super::slides::Extras {
        legend,
        ..Default::default()
    };
    if let Some(e) = &step.exercise {
        extras.caption = Some(super::handout_exercise::lab_target(lang).to_owned());
        extras.task = Some(format!(
            "{} {}",
            lang.t("lesson-exercise"),
            e.task.get(lang)
        ));
        extras.code = starter_todos(&e.starter)
            .into_iter()
            .find(|(.., todo)| !todo.is_empty())
            .map(|(file, source, todo)| (file, focus(&local(source), &todo, 3, 10)));
        return extras;
    }
    let run = capture
        .shaders
        .as_ref()
        .filter(|_| step.pixel.is_some())
        .and_then(|s| s.pixel.first());
    if let (Some(f), Some((x, y))) = (run, capture.settings.capture.pixel) {
        let mut rows: Vec<super::listing::Row> = f
            .trace
            .iter()
            .map(|l| {
                let words = crate::vocabulary::trace::words(l, lang);
                (
                    l.line.to_string(),
                    words,
                    matches!(l.step, pipeline::shader::Step::Branch { .. }),
                )
            })
            .collect();
        if rows.len() > 10 {
            rows.drain(9..rows.len() - 1);
        }
        let heading = format!("{} ({x}, {y})", lang.t("lesson-the-debugger-at-pixel"));
        extras.code = Some((heading, rows));
        return extras;
    }
    if let Some(code) = &step.shader {
        extras.code =
            step_edits(lesson, k, code)
                .into_iter()
                .next()
                .map(|(file, source, marked)| {
                    let source = &local(source);
                    let rows = if marked.is_empty() {
                        // `void main()` (marked) and the seven lines after it.
                        let main = source.lines().position(|l| l.starts_with("void main"));
                        main.map_or_else(Vec::new, |m| {
                            source
                                .lines()
                                .enumerate()
                                .skip(m)
                                .take(8)
                                .map(|(i, l)| ((i + 1).to_string(), l.to_owned(), i == m))
                                .collect()
                        })
                    } else {
                        focus(source, &marked, 1, 12)
                    };
                    (file, rows)
                });
    }
    extras
}

/// A step rendered and drawn: its scene, its capture, the compared settings' captures and
/// its picture.
struct Drawn {
    spec: SceneSpec,
    capture: FrameCapture,
    variants: Vec<(String, FrameCapture)>,
    /// As the app and the slides show it.
    picture: RgbaImage,
    /// For the printed page: its drawings in ink on white.
    print: RgbaImage,
}

/// Step `k` at moment `t` of its animation (`None`: before it), rendered and drawn.
fn draw(lesson: &Lesson, k: usize, opts: &LessonExport, t: Option<f32>) -> Result<Drawn> {
    let spec = spec_of(lesson, k, opts, t)?;
    let capture =
        pipeline::render(&spec.scene, &spec.settings).map_err(|e| not_drawn(k, &e, opts.lang))?;
    let variants = variants(lesson, k, &spec, opts.lang)?;
    let rendered = Rendered {
        spec: &spec,
        capture: &capture,
        variants: &variants,
    };
    let picture = step_picture(lesson, k, &rendered, (opts.lang, Palette::Screen))?;
    // The handout's page: drawn pictures (a geometry stage, a chart) in ink on white.
    let drawn = lesson.stage_at(k).space().is_some()
        || lesson.steps[k]
            .profile_line(capture.width(), capture.height())
            .is_some();
    let print = if drawn && t.is_none() {
        step_picture(lesson, k, &rendered, (opts.lang, Palette::Print))?
    } else {
        picture.clone()
    };
    Ok(Drawn {
        spec,
        capture,
        variants,
        picture,
        print,
    })
}

/// The scene of step `k` at the export's size, at moment `t` of its animation (`None`: as the
/// step sets it, before its animation).
fn spec_of(lesson: &Lesson, k: usize, opts: &LessonExport, t: Option<f32>) -> Result<SceneSpec> {
    let mut spec = match t {
        Some(t) => lesson.spec_playing(k, t),
        None => lesson.spec_at(k),
    };
    if let Some((w, h)) = opts.size {
        spec.settings.width = w;
        spec.settings.height = h;
    }
    // An exercise is exported as what it asks for: pipelens' own frame, not the starter's.
    if lesson.steps[k].exercise.is_some() {
        spec.scene.clear_code();
    }
    // The pixel `capture.json` describes and the handout's debugger prints: the frame records
    // its fragment shaders' runs there. `--pixel`, else the step's own inspected pixel, when it
    // is inside the image.
    let (w, h) = (spec.settings.width, spec.settings.height);
    spec.settings.capture.pixel = opts
        .pixel
        .or(lesson.steps[k].pixel)
        .filter(|&(x, y)| x < w && y < h);
    if let Some(p) = spec.settings.problems().first() {
        anyhow::bail!(crate::vocabulary::run::settings_problem(p, opts.lang));
    }
    // A step that draws a variable over the frame keeps it: its picture shows it beside.
    if let Some(watch) = &lesson.steps[k].watch {
        spec.scene = spec
            .scene
            .watching(watch)
            .with_context(|| opts.lang.t_with("lesson-step-watch", &[("step", &(k + 1))]))?;
    }
    Ok(spec)
}

/// "step k: why it could not be drawn", in `lang` (the student's code that stopped, at its
/// line, or the scene's problems).
fn not_drawn(k: usize, e: &pipeline::RenderError, lang: Lang) -> anyhow::Error {
    anyhow::anyhow!(lang.t_with(
        "lesson-step-not-drawn",
        &[
            ("step", &(k + 1)),
            ("why", &crate::vocabulary::run::render_error(e, lang)),
        ],
    ))
}

/// The compared settings' captures, when step `k` compares.
fn variants(
    lesson: &Lesson,
    k: usize,
    spec: &SceneSpec,
    lang: Lang,
) -> Result<Vec<(String, FrameCapture)>> {
    let Some(c) = lesson.steps[k].compare else {
        return Ok(Vec::new());
    };
    c.variants(&spec.settings)
        .into_iter()
        .map(|(label, settings)| {
            pipeline::render(&spec.scene, &settings)
                .map(|cap| (label, cap))
                .map_err(|e| not_drawn(k, &e, lang))
        })
        .collect()
}

/// An animated step's filmstrip and GIF: the picture at evenly spaced moments of its first
/// pass (from → to), each captioned with the animated parameters' values (the first two).
fn animation(lesson: &Lesson, k: usize, opts: &LessonExport) -> Result<Option<Animated>> {
    let step = &lesson.steps[k];
    let Some(longest) = step.animate.iter().map(|a| a.seconds).reduce(f32::max) else {
        return Ok(None);
    };
    let frame_at = |t: f32| -> Result<(RgbaImage, String)> {
        opts.cancel.check()?;
        let Drawn { spec, picture, .. } = draw(lesson, k, opts, Some(t))?;
        // Two values at most, so that a frame's caption stays under its frame (a walking figure
        // animates four joints together; the narration names them).
        let mut values: Vec<String> = step
            .animate
            .iter()
            .take(2)
            .map(|a| {
                let name = crate::lesson::param::describe(&spec, &a.param, opts.lang);
                format!("{name} = {}", shown(&a.value_at(t)))
            })
            .collect();
        if step.animate.len() > 2 {
            values.push("…".to_owned());
        }
        let caption = values.join(", ");
        Ok((filmstrip::small(&picture), caption))
    };
    let mut filmstrip = Vec::new();
    let mut gif_frames = Vec::new();
    for i in 0..GIF_FRAMES {
        let (mut image, caption) = frame_at(longest * i as f32 / (GIF_FRAMES - 1) as f32)?;
        if i % 2 == 0 {
            filmstrip.push(Frame {
                image: compact_image(&image)?,
                caption: caption.clone(),
            });
        }
        filmstrip::caption_on(&mut image, &caption);
        gif_frames.push(image);
    }
    // Forth and back, as the lesson plays by default.
    let back: Vec<RgbaImage> = gif_frames[1..GIF_FRAMES - 1]
        .iter()
        .rev()
        .cloned()
        .collect();
    gif_frames.extend(back);
    let delay = (longest * 1000.0 / (GIF_FRAMES - 1) as f32).round() as u32;
    Ok(Some(Animated {
        filmstrip,
        gif: filmstrip::gif(&gif_frames, delay)?,
    }))
}

/// An image for the handout: PNG or JPEG (quality 90), whichever is smaller — JPEG for shaded
/// renders, PNG for flat colours and thin lines, where it is both smaller and exact.
fn compact_image(img: &RgbaImage) -> Result<super::handout::Image> {
    let png = png_rgba(img)?;
    let mut jpeg = Vec::new();
    let rgb = image::DynamicImage::ImageRgba8(img.clone()).to_rgb8();
    image::codecs::jpeg::JpegEncoder::new_with_quality(&mut jpeg, 90)
        .encode_image(&rgb)
        .context("encoding a JPEG")?;
    Ok(if jpeg.len() * 10 < png.len() * 7 {
        super::handout::Image {
            mime: "image/jpeg",
            bytes: jpeg,
        }
    } else {
        super::handout::Image {
            mime: "image/png",
            bytes: png,
        }
    })
}

/// A vector as a caption shows it: `(1, 0.5, 0)`.
fn components(v: &[f32]) -> String {
    let c: Vec<String> = v.iter().map(|&x| crate::vocabulary::short(x, 2)).collect();
    format!("({})", c.join(", "))
}

/// A value as a caption shows it.
fn shown(v: &Value) -> String {
    match v {
        Value::Number(x) => crate::vocabulary::short(*x, 2),
        Value::Vec2(v) => components(&v.to_array()),
        Value::Vec3(v) => components(&v.to_array()),
        Value::Vec4(v) => components(&v.to_array()),
        other => other.to_string(),
    }
}

/// Step `k`'s picture in words ([`crate::lesson::describe::picture`]), at the step's pixel or
/// the one asked for.
fn alt_text(
    lesson: &Lesson,
    k: usize,
    spec: &crate::lesson::SceneSpec,
    capture: &pipeline::capture::FrameCapture,
    opts: &LessonExport,
) -> String {
    crate::lesson::describe::picture(
        spec,
        capture,
        (lesson.stage_at(k), Some(lesson.buffer_at(k))),
        lesson.steps[k].focus.as_deref().unwrap_or_default(),
        lesson.steps[k].pixel.or(opts.pixel),
        opts.lang,
    )
}
