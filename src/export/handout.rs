//! The handout: one HTML file with every image embedded (no file beside it is needed), in one
//! language, that reads on a screen and prints on A4 — a step never split across pages where
//! it fits, no interactive parts on paper, each step's matrices only where they changed or where
//! the step's stage uses them, and, for a teacher's key, every answer printed.

use std::fmt::Write as _;

use base64::Engine as _;
use pipeline::capture::{FragmentTrace, Matrices};
use pipeline::transform::NamedMatrix;

use super::html::{self, markdown, typeset};
use crate::lesson::Lesson;
use crate::vocabulary::notation;
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
    /// The picture's text alternative ([`crate::vocabulary::alt_text`]), its `alt`.
    pub alt: String,
}

/// A data URL of `bytes` of MIME type `mime`.
fn data_url(mime: &str, bytes: &[u8]) -> String {
    format!(
        "data:{mime};base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    )
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
pre.code{font-size:85%;background:#f0f0ea;padding:.5em;white-space:pre-wrap} table.fill{border-collapse:collapse;margin:.4em 0} table.fill td{border:1px solid #555;min-width:4.5em;height:1.8em;padding:0 .4em;text-align:right;font-family:monospace;background:#fff} table.fill th{font-weight:normal;font-family:monospace;padding:0 .4em;text-align:center}
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
    if lang.is_chinese() {
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
    } else {
        String::new()
    }
}

/// The handout of the exported `pages`, in `lang`; with `answers`, every answer printed.
#[must_use]
pub fn html(lesson: &Lesson, pages: &[StepPage], lang: Lang, answers: bool) -> String {
    let t = |id: &'static str| lang.t(id);
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
            t("handout-teacher-s-key-every-answer")
        );
    }
    if !lesson.prerequisites.is_empty() {
        let _ = writeln!(
            h,
            "<p class=\"summary\"><span class=\"ui\">{}</span>: {}</p>",
            t("handout-before-this-lesson"),
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
        lang.tag(),
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
    let t = |id: &'static str| lang.t(id);
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
        format!(
            "{}{}",
            t("handout-dash"),
            super::handout_exercise::lab_target(lang)
        )
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
        "<figure><img src=\"{}\" alt=\"{title} — {}\"><figcaption class=\"ui\">{}{}{target}{legend}</figcaption></figure>",
        page.picture.url(),
        html::esc(&page.alt),
        t("handout-stage"),
        page.stage.name(lang)
    );
    if let Some(a) = &page.animated {
        let _ = writeln!(
            h,
            "<figure class=\"screen\"><img src=\"{}\" alt=\"{title}\"><figcaption class=\"ui\">{}</figcaption></figure>",
            data_url("image/gif", &a.gif),
            t("handout-the-animation-as-the-app")
        );
        let _ = write!(
            h,
            "<p class=\"ui\">{}</p><div class=\"film\">",
            t("handout-the-animation-in-frames-from")
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
        h.push_str(&super::handout_exercise::shaders_html(
            lesson, page.index, code, lang,
        ));
    }
    if let Some((pixel, fragments)) = &page.trace {
        h.push_str(&super::handout_exercise::trace_html(
            *pixel, fragments, lang,
        ));
    }
    if let Some(e) = &step.exercise {
        h.push_str(&super::handout_exercise::exercise_html(
            e,
            &lesson.comments,
            lang,
        ));
    }
    if let Some(q) = &step.question {
        h.push_str(&super::handout_exercise::question_html(
            step, q, lang, answers,
        ));
    }
    h.push_str("</section>\n");
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
        let figure = matrix_html(&m, Lang::EN);
        assert!(figure.contains("M<sub>persp→ortho</sub>"), "{figure}");
    }
}
