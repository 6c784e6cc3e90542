//! The handout: one HTML file with every image embedded (no file beside it is needed), in one
//! language, that reads on a screen and prints on A4 — a step never split across pages where
//! it fits, no interactive parts on paper, each step's matrices only where they changed or where
//! the step's stage uses them, and, for a teacher's key, every answer printed.

use std::fmt::Write as _;

use base64::Engine as _;
use pipeline::capture::{FragmentTrace, Matrices};
use pipeline::scene::StudentCode;
use pipeline::transform::NamedMatrix;

use super::html;
use crate::lesson::Lesson;
use crate::vocabulary::glsl::localize;
use crate::vocabulary::notation::{self, Node};
use crate::vocabulary::{Lang, Stage, num};

/// An encoded image.
pub struct Image {
    /// `image/png` or `image/jpeg`.
    pub mime: &'static str,
    /// The file's bytes.
    pub bytes: Vec<u8>,
}

impl Image {
    fn url(&self) -> String {
        data_url(self.mime, &self.bytes)
    }
}

/// One frame of a filmstrip: the picture and the animated parameters' values.
pub struct Frame {
    /// The picture.
    pub image: Image,
    /// `name = value` of each animated parameter.
    pub caption: String,
}

/// What an animated step shows: a filmstrip for paper, a looping GIF for screens.
pub struct Animated {
    /// Frames across the animation.
    pub filmstrip: Vec<Frame>,
    /// GIF bytes.
    pub gif: Vec<u8>,
}

/// What the handout shows of one step.
pub struct StepPage {
    /// The step (0-based).
    pub index: usize,
    /// Its picture.
    pub picture: Image,
    /// Its animation, if it has one.
    pub animated: Option<Animated>,
    /// The matrices of its scene.
    pub matrices: Matrices,
    /// Whether each object (each model matrix) is the step's subject (its `focus`; every
    /// object when it names none).
    pub subject: Vec<bool>,
    /// The stage it shows.
    pub stage: Stage,
    /// The debugger's run at its inspected pixel: the pixel and each fragment's run there, when
    /// shaders ran on it.
    pub trace: Option<((u32, u32), Vec<FragmentTrace>)>,
    /// The legend of the picture's drawings, printed under it.
    pub legend: Vec<String>,
}

/// A data URL of `bytes` of MIME type `mime`.
fn data_url(mime: &str, bytes: &[u8]) -> String {
    format!(
        "data:{mime};base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    )
}

/// Typeset notation ([`notation`]) as HTML, as the app lays it out: scripts as `<sub>` and
/// `<sup>`, a fraction's parts stacked over a bar, code in monospace, a narration's formula
/// highlighted.
fn typeset(nodes: &[Node]) -> String {
    let mut s = String::new();
    for n in nodes {
        match n {
            Node::Text(t) => s.push_str(&html::esc(t)),
            Node::Code(t) => {
                let _ = write!(s, "<code>{}</code>", html::esc(t));
            }
            Node::Script { base, sub, sup } => {
                s.push_str(&typeset(base));
                if let Some(x) = sub {
                    let _ = write!(s, "<sub>{}</sub>", typeset(x));
                }
                if let Some(x) = sup {
                    let _ = write!(s, "<sup>{}</sup>", typeset(x));
                }
            }
            Node::Frac { num, den } => {
                let _ = write!(
                    s,
                    "<span class=\"frac\"><span>{}</span><span>{}</span></span>",
                    typeset(num),
                    typeset(den)
                );
            }
            Node::Formula(inner) => {
                let _ = write!(s, "<strong>{}</strong>", typeset(inner));
            }
        }
    }
    s
}

/// The narration's simple markdown as HTML: paragraphs, `- ` bullets, `**formulas**`, each
/// line typeset ([`notation::parse_paragraph`]).
fn markdown(text: &str) -> String {
    let mut out = String::new();
    for paragraph in text.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
        let lines: Vec<&str> = paragraph.lines().map(str::trim).collect();
        let inline = |l: &str| typeset(&notation::parse_paragraph(l));
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
        typeset(&notation::parse(&m.name, true)),
        typeset(&notation::parse(&lang.formula(&m.formula), true))
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

/// The matrices a step shows: those its stage applies (the model matrices of the step's subject
/// on the model and world stages, the view matrix on the view stage, the projection on clip and
/// NDC, the viewport on the viewport stage) and any that changed since the previous step shown.
fn matrices_shown<'a>(
    now: &'a Matrices,
    before: Option<&Matrices>,
    stage: Stage,
    subject: &[bool],
) -> Vec<&'a NamedMatrix> {
    let changed = |a: &NamedMatrix, b: Option<&NamedMatrix>| b.is_none_or(|b| a.matrix != b.matrix);
    let mut out = Vec::new();
    for (i, m) in now.models.iter().enumerate() {
        let used =
            matches!(stage, Stage::Model | Stage::World) && subject.get(i).copied().unwrap_or(true);
        if used || before.is_some_and(|b| changed(m, b.models.get(i))) {
            out.push(m);
        }
    }
    for (m, used, prev) in [
        (&now.view, stage == Stage::View, before.map(|b| &b.view)),
        (
            &now.projection,
            matches!(stage, Stage::Clip | Stage::Ndc),
            before.map(|b| &b.projection),
        ),
        (
            &now.viewport,
            stage == Stage::Screen,
            before.map(|b| &b.viewport),
        ),
    ] {
        if used || (before.is_some() && changed(m, prev)) {
            out.push(m);
        }
    }
    out
}

const STYLE: &str = "\
body{font-family:'Noto Sans SC','Noto Sans CJK SC','pipelens CJK',sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.55;color:#222;line-break:strict}
h1{margin-bottom:.2em} .summary{color:#555} section{border-top:1px solid #ccc;margin-top:2em;padding-top:1em}
img{max-width:100%;border:1px solid #aaa} figure{margin:.6em 0} figcaption{font-size:.9em;color:#444}
.film{display:grid;grid-template-columns:repeat(5,1fr);gap:.4em} .film figure{margin:0} .film img{width:100%}
figure.m{display:inline-block;margin:.4em 1em .4em 0;vertical-align:top} figure.m table{border-collapse:collapse;font-family:monospace}
figure.m td{padding:.1em .5em;text-align:right;border-left:1px solid #ddd} strong{color:#8a3b00}
sub,sup{font-size:75%;line-height:0} code{font-size:92%;background:#f0f0ea;padding:0 .2em}
.frac{display:inline-flex;flex-direction:column;vertical-align:middle;text-align:center;font-size:88%;margin:0 .15em;line-height:1.15}
.frac>span:first-child{border-bottom:1px solid currentColor;padding:0 .2em}
.question{background:#f6f6f0;padding:.5em 1em;margin-top:1em} .answer{border-left:4px solid #8a3b00;padding:.2em 1em;margin:.5em 0}
pre.code{font-size:85%;background:#f0f0ea;padding:.5em;white-space:pre-wrap} table.fill{border-collapse:collapse;margin:.4em 0} table.fill td{border:1px solid #555;min-width:4.5em;height:1.8em;padding:0 .4em;text-align:right;font-family:monospace;background:#fff}
details{margin-top:.4em} .key{display:inline-block;background:#8a3b00;color:#fff;padding:.1em .6em;border-radius:.3em}
@media print{
@page{size:A4;margin:14mm}
body{max-width:none;margin:0;font-size:10.5pt}
section{margin-top:1em}
h2,p.listing{break-after:avoid}
figure,.question,.film,table.src tr{break-inside:avoid} .question{break-before:avoid}
.question.exercise{break-inside:auto} p.ui{break-after:avoid}
figure.m{margin:.3em .5em .3em 0;font-size:8pt} figure.m figcaption{max-width:42mm}
.screen{display:none}
img{max-height:100mm;width:auto}
.film img{max-height:none;width:100%}
}
";

/// For a Chinese handout, the app's own Chinese font embedded as `pipelens CJK`, cut to the
/// characters of `text` (the handout's own): a reader whose machine has no Chinese font (a bare
/// Linux, headless Chromium printing to PDF) would see boxes. A machine with Noto Sans SC uses
/// its own; the embedded one is the fallback. Lesson 11's adds about 0.15 MB (the whole font
/// would add 4 MB); an English handout has none.
fn cjk_font_face(lang: Lang, text: &str) -> String {
    match lang {
        Lang::Zh => {
            // A font that cannot be cut is embedded whole: larger, and still Chinese.
            let font = super::font::cjk_subset(text)
                .unwrap_or_else(|_| crate::vocabulary::cjk_font().to_vec());
            // For Chinese characters and punctuation only (Latin text keeps the reader's own
            // sans-serif and monospace): a listing's font list names it first, so that headless
            // Chromium does not draw the first Chinese run of a listing as boxes, as it did with
            // the font as a fallback after the monospace one.
            format!(
                "@font-face{{font-family:'pipelens CJK';src:url({}) format('opentype');unicode-range:U+2000-206F,U+2E80-9FFF,U+F900-FFEF}}\n",
                data_url("font/otf", &font)
            )
        }
        Lang::En => String::new(),
    }
}

/// The handout of the exported `pages`, in `lang`; with `answers`, every answer printed.
#[must_use]
pub fn html(lesson: &Lesson, pages: &[StepPage], lang: Lang, answers: bool) -> String {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    // The body first: the head's font is cut to the characters it holds.
    let mut h = String::new();
    let _ = writeln!(
        h,
        "<h1>{}</h1><p class=\"summary\">{}</p>",
        typeset(&notation::parse_paragraph(lesson.title.get(lang))),
        typeset(&notation::parse_paragraph(lesson.summary.get(lang)))
    );
    if answers {
        let _ = writeln!(
            h,
            "<p><span class=\"key ui\">{}</span></p>",
            t(
                "Teacher's key: every answer printed",
                "教师版：印出全部答案"
            )
        );
    }
    if !lesson.prerequisites.is_empty() {
        let _ = writeln!(
            h,
            "<p class=\"summary\"><span class=\"ui\">{}</span>: {}</p>",
            t("Before this lesson", "先修课"),
            html::esc(&lesson.prerequisites.join(", "))
        );
    }
    let mut before: Option<&Matrices> = None;
    for page in pages {
        step_html(&mut h, lesson, page, before, lang, answers);
        before = Some(&page.matrices);
    }
    h.push_str("</body></html>\n");
    let title = html::esc(lesson.title.get(lang));
    format!(
        "<!doctype html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width\"><title>{title}</title>\n<style>\n{}{STYLE}{}</style></head><body>\n{h}",
        if lang == Lang::Zh { "zh-CN" } else { "en" },
        cjk_font_face(lang, &format!("{title}{h}")),
        super::listing::STYLE
    )
}

fn step_html(
    h: &mut String,
    lesson: &Lesson,
    page: &StepPage,
    before: Option<&Matrices>,
    lang: Lang,
    answers: bool,
) {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    let step = &lesson.steps[page.index];
    let title = html::esc(step.title.get(lang));
    let _ = write!(
        h,
        "<section id=\"step-{n}\"><h2>{n}. {heading}</h2>\n{body}",
        n = page.index + 1,
        heading = typeset(&notation::parse_paragraph(step.title.get(lang))),
        body = markdown(step.narration.get(lang))
    );
    let target = if step.exercise.is_some() {
        format!("{}{}", t(" — ", "——"), lab_target(lang))
    } else {
        String::new()
    };
    let legend: String = page
        .legend
        .iter()
        .map(|l| format!("<br>{}", html::esc(l)))
        .collect();
    let _ = writeln!(
        h,
        "<figure><img src=\"{}\" alt=\"{title}\"><figcaption class=\"ui\">{}{}{target}{legend}</figcaption></figure>",
        page.picture.url(),
        t("Stage: ", "阶段："),
        page.stage.name(lang)
    );
    if let Some(a) = &page.animated {
        let _ = writeln!(
            h,
            "<figure class=\"screen\"><img src=\"{}\" alt=\"{title}\"><figcaption class=\"ui\">{}</figcaption></figure>",
            data_url("image/gif", &a.gif),
            t(
                "The animation, as the app plays it",
                "动画，与应用中播放的相同"
            )
        );
        let _ = write!(
            h,
            "<p class=\"ui\">{}</p><div class=\"film\">",
            t(
                "The animation in frames, from its start to its end:",
                "动画的分帧，从开始到结束："
            )
        );
        for f in &a.filmstrip {
            let _ = write!(
                h,
                "<figure><img src=\"{}\" alt=\"{c}\"><figcaption>{c}</figcaption></figure>",
                f.image.url(),
                c = html::esc(&f.caption)
            );
        }
        h.push_str("</div>\n");
    }
    let shown = matrices_shown(&page.matrices, before, page.stage, &page.subject);
    if !shown.is_empty() {
        h.push_str("<div>");
        for m in shown {
            h.push_str(&matrix_html(m, lang));
        }
        h.push_str("</div>\n");
    }
    if let Some(code) = &step.shader {
        h.push_str(&shaders_html(lesson, page.index, code, lang));
    }
    if let Some((pixel, fragments)) = &page.trace {
        h.push_str(&trace_html(*pixel, fragments, lang));
    }
    if let Some(e) = &step.exercise {
        h.push_str(&exercise_html(e, &lesson.comments, lang));
    }
    if let Some(q) = &step.question {
        h.push_str(&question_html(step, q, lang, answers));
    }
    h.push_str("</section>\n");
}

/// A step's question, its blanks for a typed answer, and its answer (printed in a teacher's
/// key, else folded on screen and left out of print).
fn question_html(
    step: &crate::lesson::script::Step,
    q: &crate::vocabulary::Text,
    lang: Lang,
    answers: bool,
) -> String {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    let mut h = String::new();
    let _ = write!(
        h,
        "<div class=\"question\"><b class=\"ui\">{}</b> {}",
        t("Question:", "思考题："),
        typeset(&notation::parse_paragraph(q.get(lang)))
    );
    if let Some(e) = &step.expect {
        h.push_str(&fill_in(e, answers, lang));
    }
    if let Some(a) = &step.answer {
        if answers {
            let _ = write!(
                h,
                "<div class=\"answer\"><b class=\"ui\">{}</b>{}</div>",
                t("Answer:", "答案："),
                markdown(a.get(lang))
            );
        } else {
            let _ = write!(
                h,
                "<details class=\"screen\"><summary class=\"ui\">{}</summary>{}</details>",
                t("Show the answer", "显示答案"),
                markdown(a.get(lang))
            );
        }
    }
    h.push_str("</div>\n");
    h
}

/// One file's listing under its name, its comments in `lang` (from the lesson's `comments`),
/// the `marked` lines on yellow.
fn file_listing(
    file: &str,
    source: &str,
    marked: &[usize],
    (lang, comments): (Lang, &std::collections::BTreeMap<String, String>),
) -> String {
    format!(
        "<p class=\"listing\"><code>{file}</code></p>{}",
        super::listing::html(&localize(source, lang, comments), marked)
    )
}

/// The shaders step `k` runs of its own (its `shader`), each a listing under its file name, the
/// lines it changed from the shader of the same file the step before ran on yellow.
fn shaders_html(lesson: &Lesson, k: usize, code: &StudentCode, lang: Lang) -> String {
    let files = super::listing::step_edits(lesson, k, code);
    if files.is_empty() {
        return String::new();
    }
    let mut h = format!(
        "<p class=\"listing ui\">{}</p>",
        lang.tr(
            "The shaders this step runs (on yellow: the lines changed from the step before):",
            "本步骤运行的着色器（黄底：与上一步相比改动的行）："
        )
    );
    for (file, source, marked) in files {
        h.push_str(&file_listing(
            &file,
            source,
            &marked,
            (lang, &lesson.comments),
        ));
    }
    h
}

/// What a lab's picture is: pipelens' own frame, which the student's code must draw.
pub(super) fn lab_target(lang: Lang) -> &'static str {
    lang.tr(
        "pipelens' own, what your code must draw",
        "pipelens 自带的结果：你的代码要画出的画面",
    )
}

/// The debugger at the step's pixel on paper: each fragment's inputs, its run statement by
/// statement (line and words, branches and loop iterations among them), and what it wrote.
fn trace_html((x, y): (u32, u32), fragments: &[FragmentTrace], lang: Lang) -> String {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    let mut h = String::new();
    for (k, f) in fragments.iter().enumerate() {
        let _ = write!(
            h,
            "<p class=\"listing ui\">{} ({x}, {y}) · {} {} · {} {}</p><table class=\"src\">",
            t("The debugger at pixel", "调试器：像素"),
            t("fragment", "片元"),
            k + 1,
            t("triangle", "三角形"),
            f.primitive
        );
        let row = |h: &mut String, n: &str, text: &str| {
            let _ = write!(
                h,
                "<tr><td class=\"n\">{n}</td><td class=\"l\">{}</td></tr>",
                html::esc(text)
            );
        };
        // Each input under GLSL's own word for it (no Chinese in the narrow number column:
        // headless Chromium drew it there as boxes).
        for (name, value) in &f.inputs {
            row(&mut h, "in", &format!("{name} = {value}"));
        }
        for line in &f.trace {
            row(
                &mut h,
                &line.line.to_string(),
                &crate::vocabulary::trace::words(line, lang),
            );
        }
        let out = f.output.map_or_else(
            || t("discarded", "被丢弃").to_owned(),
            |c| {
                format!(
                    "vec4({}, {}, {}, {})",
                    num(c[0]),
                    num(c[1]),
                    num(c[2]),
                    num(c[3])
                )
            },
        );
        row(&mut h, "→", &out);
        h.push_str("</table>");
    }
    h
}

/// An exercise on paper: the task, and the starter code the student completes (the stages the
/// lesson wrote; pipelens' own are not repeated), its TODO lines on yellow.
fn exercise_html(
    e: &crate::lesson::answer::Exercise,
    comments: &std::collections::BTreeMap<String, String>,
    lang: Lang,
) -> String {
    let t = |en: &'static str, zh: &'static str| lang.tr(en, zh);
    let mut h = format!(
        "<div class=\"question exercise\"><b class=\"ui\">{}</b> {}",
        t("Exercise:", "练习："),
        typeset(&notation::parse_paragraph(e.task.get(lang)))
    );
    for (file, source, todo) in super::listing::starter_todos(&e.starter) {
        h.push_str(&file_listing(&file, source, &todo, (lang, comments)));
    }
    h.push_str("</div>\n");
    h
}

/// The boxes a question's expected value is written into on paper, one per entry (a matrix
/// cell by cell), with the tolerance stated; in a teacher's key, filled with the value.
fn fill_in(e: &crate::lesson::answer::Expect, answers: bool, lang: Lang) -> String {
    let (rows, cols) = e.shape.size();
    let tolerance = e.tolerance_words(lang);
    let mut h = String::new();
    let _ = write!(
        h,
        "<div class=\"ui\">{}</div><table class=\"fill\">",
        match lang {
            Lang::En => format!("Your answer (each entry within {tolerance}):"),
            Lang::Zh => format!("你的答案（每项误差 {tolerance} 以内）："),
        }
    );
    for r in 0..rows {
        h.push_str("<tr>");
        for c in 0..cols {
            let v = e.values[r * cols + c];
            let cell = if answers {
                crate::vocabulary::short(v as f32, 4)
            } else {
                String::new()
            };
            let _ = write!(h, "<td>{cell}</td>");
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Narration, questions and the matrices' formulas are typeset as the app lays them out,
    /// not printed with their marks.
    #[test]
    fn formulas_are_typeset_not_printed_with_their_marks() {
        let html = markdown("Depth **z_ndc = (f+n)/(f−n)** feeds `depth_test`; x^2 < y.");
        let frac = "<span class=\"frac\"><span>f+n</span><span>f−n</span></span>";
        assert!(
            html.contains(&format!("<strong>z<sub>ndc</sub> = {frac}</strong>")),
            "{html}"
        );
        assert!(html.contains("<code>depth_test</code>"), "{html}");
        assert!(html.contains("x<sup>2</sup> &lt; y."), "{html}");
        for mark in ["**", "_ndc", "^2", "`"] {
            assert!(!html.contains(mark), "{mark} in {html}");
        }
        let m = NamedMatrix::new("M_persp", "M_{persp→ortho}", glam::Mat4::IDENTITY);
        let figure = matrix_html(&m, Lang::En);
        assert!(figure.contains("M<sub>persp→ortho</sub>"), "{figure}");
    }
}
