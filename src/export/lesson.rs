//! Export of a lesson: for every step (or one), the capture's files in `step-NN/` — every
//! buffer as PNG, the overlays, `capture.json` (with the step's highlighted pixel), the
//! compared settings' images and the profile CSV where the step shows them — and `index.html`,
//! a self-contained handout with the narration in one language, the images and the matrices.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{Context, Result};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::transform::NamedMatrix;

use super::{ExportFile, ExportOptions, encode_capture, png_rgba, profile_csv, write_files};
use crate::lesson::script::Layout;
use crate::lesson::{Lesson, SceneSpec, Step};
use crate::observer::observer_image;
use crate::vocabulary::{Comparison, Lang, Stage, num};

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
    /// At most this many records per table in each `capture.json`.
    pub max_records: usize,
    /// Stops the export between two files.
    pub cancel: super::Cancel,
}

/// What one step exported, for the handout.
struct StepFiles {
    index: usize,
    dir: String,
    main_image: String,
    compared: Vec<(String, String)>,
    capture: FrameCapture,
}

/// The folder name of step `k` (0-based): `step-01`, `step-02`…
fn step_dir(k: usize) -> String {
    format!("step-{:02}", k + 1)
}

/// Exports `lesson`; returns every path written. `progress` is told how many parts of how
/// many are done and what comes next.
///
/// # Errors
/// A step out of range, a render or an encoding that fails, a folder that cannot be written.
pub fn export_lesson(
    lesson: &Lesson,
    opts: &LessonExport,
    progress: &mut dyn FnMut(usize, usize, &str),
) -> Result<Vec<PathBuf>> {
    let n = lesson.steps.len();
    let steps: Vec<usize> = match opts.step {
        Some(k) if k < n => vec![k],
        Some(k) => anyhow::bail!(
            "--step {} is out of range: the lesson has steps 1 to {n}",
            k + 1
        ),
        None => (0..n).collect(),
    };
    let mut written = Vec::new();
    let mut done = Vec::new();
    let parts = steps.len() + 1;
    for (i, &k) in steps.iter().enumerate() {
        opts.cancel.check()?;
        progress(
            i,
            parts,
            &format!("step {}: {}", k + 1, lesson.steps[k].title.get(opts.lang)),
        );
        let (files, step_files) = step_files(lesson, k, opts)?;
        written.extend(write_files(
            &opts.out.join(&step_files.dir),
            &files,
            &mut |_, _, _| {},
            &opts.cancel,
        )?);
        done.push(step_files);
    }
    progress(steps.len(), parts, "index.html");
    let html = handout(lesson, &done, opts.lang);
    let target = opts.out.join("index.html");
    super::write_atomically(&target, html.as_bytes())?;
    written.push(target);
    Ok(written)
}

/// The scene of step `k` at the export's size.
fn spec_of(lesson: &Lesson, k: usize, opts: &LessonExport) -> Result<SceneSpec> {
    let mut spec = lesson.spec_at(k);
    if let Some((w, h)) = opts.size {
        spec.settings.width = w;
        spec.settings.height = h;
    }
    if let Some(p) = spec.settings.problems().first() {
        anyhow::bail!("{p}");
    }
    Ok(spec)
}

fn step_files(
    lesson: &Lesson,
    k: usize,
    opts: &LessonExport,
) -> Result<(Vec<ExportFile>, StepFiles)> {
    let step = &lesson.steps[k];
    let spec = spec_of(lesson, k, opts)?;
    let capture = pipeline::render(&spec.scene, &spec.settings)
        .with_context(|| format!("rendering step {}", k + 1))?;
    let dir = step_dir(k);
    let export = ExportOptions {
        out: opts.out.join(&dir),
        overlay_zoom: 0,
        max_records: opts.max_records,
        pixel: step
            .pixel
            .filter(|&(x, y)| x < capture.width() && y < capture.height()),
        cancel: opts.cancel.clone(),
    };
    let mut files = encode_capture(&capture, &export)?;
    let mut main_image = main_image(step, &capture);
    let geometry = step.stage.is_some_and(|s| s.space().is_some());
    if (step.layout == Layout::Observer || geometry)
        && let Some(img) = observer_image(&spec, &capture)
    {
        files.push(ExportFile {
                name: "observer.png".into(),
                description: "the scene from outside, with the viewing camera's frustum (near plane yellow, far plane orange)".into(),
                bytes: png_rgba(&img)?,
            });
        if geometry {
            main_image = "observer.png".to_owned();
        }
    }
    let mut compared = Vec::new();
    if let Some(c) = step.compare {
        let variants = c
            .variants(&spec.settings)
            .into_iter()
            .map(|(label, settings)| {
                pipeline::render(&spec.scene, &settings).map(|cap| (label, cap))
            })
            .collect::<Result<Vec<_>, _>>()?;
        for (label, cap) in &variants {
            let name = format!("compare_{}.png", slug(label));
            files.push(ExportFile {
                name: name.clone(),
                description: format!("the colour image with {label}"),
                bytes: png_rgba(&cap.image(BufferKind::Color))?,
            });
            compared.push((label.clone(), name));
        }
        if c == Comparison::Shading || step.profile.is_some() {
            let line = step.profile.unwrap_or_else(|| {
                let (w, h) = (capture.width() as f32, capture.height() as f32);
                [0.0, h / 2.0, w - 1.0, h / 2.0]
            });
            let named: Vec<(&str, &FrameCapture)> =
                variants.iter().map(|(l, c)| (l.as_str(), c)).collect();
            files.push(profile_csv(line, &named));
        }
    } else if let Some(line) = step.profile {
        files.push(profile_csv(line, &[("color", &capture)]));
    }
    Ok((
        files,
        StepFiles {
            index: k,
            dir,
            main_image,
            compared,
            capture,
        },
    ))
}

/// The image that shows the step: its buffer, the stage's own buffer for pixel stages, the
/// overlays for rasterization, the colour image otherwise.
fn main_image(step: &Step, capture: &FrameCapture) -> String {
    let buffers = capture.buffers();
    let kind = step
        .buffer
        .or_else(|| {
            step.stage
                .filter(|s| s.space().is_none())
                .map(|s| s.default_buffer())
        })
        .filter(|k| buffers.contains(k));
    match (kind, step.stage) {
        (Some(k), _) => format!("{}.png", k.name()),
        (None, Some(Stage::Raster)) => "overlays.png".to_owned(),
        _ => "color.png".to_owned(),
    }
}

fn slug(label: &str) -> String {
    let s: String = label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    s.trim_matches('_').replace("__", "_")
}

/// Escapes text for HTML.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The narration's simple markdown as HTML: paragraphs, `- ` bullets, `**bold**`.
fn markdown(text: &str) -> String {
    let mut out = String::new();
    for paragraph in text.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
        let lines: Vec<&str> = paragraph.lines().map(str::trim).collect();
        let inline = |l: &str| {
            esc(l)
                .split("**")
                .enumerate()
                .map(|(i, part)| {
                    if i % 2 == 1 {
                        format!("<strong>{part}</strong>")
                    } else {
                        part.to_owned()
                    }
                })
                .collect::<String>()
        };
        if lines.iter().all(|l| l.starts_with("- ")) {
            out.push_str("<ul>");
            for l in lines {
                let _ = write!(out, "<li>{}</li>", inline(&l[2..]));
            }
            out.push_str("</ul>\n");
        } else {
            let _ = writeln!(out, "<p>{}</p>", inline(&lines.join(" ")));
        }
    }
    out
}

fn matrix_html(m: &NamedMatrix, lang: Lang) -> String {
    let rows = m.matrix.transpose().to_cols_array_2d();
    let mut s = format!(
        "<figure class=\"m\"><figcaption><b>{}</b><br><i>{}</i></figcaption><table>",
        esc(&m.name),
        esc(&lang.formula(&m.formula))
    );
    for r in rows {
        s.push_str("<tr>");
        for v in r {
            let _ = write!(s, "<td>{}</td>", num(v));
        }
        s.push_str("</tr>");
    }
    s.push_str("</table></figure>");
    s
}

/// The handout: every exported step with its narration, images and matrices.
fn handout(lesson: &Lesson, steps: &[StepFiles], lang: Lang) -> String {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    let mut h = String::new();
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\"><title>{}</title>\n<style>\n\
         body{{font-family:'Noto Sans SC','Noto Sans CJK SC',sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.55;color:#222}}\n\
         h1{{margin-bottom:.2em}} .summary{{color:#555}} section{{border-top:1px solid #ccc;margin-top:2em;padding-top:1em}}\n\
         img{{max-width:100%;image-rendering:pixelated;border:1px solid #aaa}} .row{{display:flex;gap:1em;flex-wrap:wrap}} .row figure{{flex:1;min-width:240px;margin:0}}\n\
         figure.m{{display:inline-block;margin:.4em 1em .4em 0;vertical-align:top}} figure.m table{{border-collapse:collapse;font-family:monospace}}\n\
         figure.m td{{padding:.1em .5em;text-align:right;border-left:1px solid #ddd}} figcaption{{font-size:.9em}} strong{{color:#8a3b00}}\n\
         details{{background:#f6f6f0;padding:.5em 1em;margin-top:1em}} .files{{font-size:.85em;color:#666}}\n\
         </style></head><body>\n",
        if lang == Lang::Zh { "zh-CN" } else { "en" },
        esc(lesson.title.get(lang))
    );
    let _ = writeln!(
        h,
        "<h1>{}</h1><p class=\"summary\">{}</p>",
        esc(lesson.title.get(lang)),
        esc(lesson.summary.get(lang))
    );
    if !lesson.prerequisites.is_empty() {
        let _ = writeln!(
            h,
            "<p class=\"summary\">{}: {}</p>",
            t("Before this lesson", "先修课"),
            esc(&lesson.prerequisites.join(", "))
        );
    }
    for s in steps {
        let step = &lesson.steps[s.index];
        let _ = write!(
            h,
            "<section id=\"{dir}\"><h2>{n}. {title}</h2>\n{body}",
            dir = s.dir,
            n = s.index + 1,
            title = esc(step.title.get(lang)),
            body = markdown(step.narration.get(lang))
        );
        if s.compared.is_empty() {
            let _ = writeln!(
                h,
                "<p><img src=\"{}/{}\" alt=\"{}\"></p>",
                s.dir,
                s.main_image,
                esc(step.title.get(lang))
            );
        } else {
            h.push_str("<div class=\"row\">");
            for (label, file) in &s.compared {
                let _ = write!(
                    h,
                    "<figure><img src=\"{}/{file}\" alt=\"{l}\"><figcaption>{l}</figcaption></figure>",
                    s.dir,
                    l = esc(label)
                );
            }
            h.push_str("</div>\n");
        }
        let m = &s.capture.matrices;
        h.push_str("<div>");
        if let Some(first) = m.models.first() {
            h.push_str(&matrix_html(first, lang));
        }
        for x in [&m.view, &m.projection, &m.viewport] {
            h.push_str(&matrix_html(x, lang));
        }
        h.push_str("</div>\n");
        if let Some(q) = &step.question {
            let _ = writeln!(
                h,
                "<details><summary><b>{}</b> {}</summary>{}</details>",
                t("Question:", "思考题："),
                esc(q.get(lang)),
                step.answer
                    .as_ref()
                    .map(|a| markdown(a.get(lang)))
                    .unwrap_or_default()
            );
        }
        let _ = writeln!(
            h,
            "<p class=\"files\">{}: <a href=\"{d}/capture.json\">capture.json</a>, <a href=\"{d}/\">{d}/</a></p></section>",
            t("Every buffer and the numbers", "全部缓冲与数据"),
            d = s.dir
        );
    }
    h.push_str("</body></html>\n");
    h
}
