//! What a handout's step asks of its reader: the question with the boxes to fill in (or, in a
//! teacher's key, the answer), the exercise with its file listed and what is left to do marked,
//! a lab's student code and, at its inspected pixel, the fragments' trace.

use std::fmt::Write as _;

use pipeline::capture::FragmentTrace;
use pipeline::scene::StudentCode;

use super::html::{self, markdown, typeset};
use crate::lesson::Lesson;
use crate::vocabulary::glsl::localize;
use crate::vocabulary::notation;
use crate::vocabulary::{Lang, num};

/// A step's question, its blanks for a typed answer, and its answer (printed in a teacher's
/// key, else folded on screen and left out of print).
pub(super) fn question_html(
    step: &crate::lesson::script::Step,
    q: &crate::vocabulary::Text,
    lang: Lang,
    answers: bool,
) -> String {
    let t = |id: &'static str| lang.t(id);
    let mut h = String::new();
    let _ = write!(
        h,
        "<div class=\"question\"><b class=\"ui\">{}</b> {}",
        t("handout-exercise-question"),
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
                t("handout-exercise-answer"),
                markdown(a.get(lang))
            );
        } else {
            let _ = write!(
                h,
                "<details class=\"screen\"><summary class=\"ui\">{}</summary>{}</details>",
                t("handout-exercise-show-the-answer"),
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
pub(super) fn shaders_html(lesson: &Lesson, k: usize, code: &StudentCode, lang: Lang) -> String {
    let files = super::listing::step_edits(lesson, k, code);
    if files.is_empty() {
        return String::new();
    }
    let mut h = format!(
        "<p class=\"listing ui\">{}</p>",
        lang.t("handout-exercise-the-shaders-this-step-runs")
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
    lang.t("handout-exercise-pipelens-own-what-your-code")
}

/// The debugger at the step's pixel on paper: each fragment's inputs, its run statement by
/// statement (line and words, branches and loop iterations among them), and what it wrote.
pub(super) fn trace_html((x, y): (u32, u32), fragments: &[FragmentTrace], lang: Lang) -> String {
    let t = |id: &'static str| lang.t(id);
    let mut h = String::new();
    for (k, f) in fragments.iter().enumerate() {
        let _ = write!(
            h,
            "<p class=\"listing ui\">{} ({x}, {y}) · {} {} · {} {}</p><table class=\"src\">",
            t("handout-exercise-the-debugger-at-pixel"),
            t("handout-exercise-fragment"),
            k + 1,
            t("handout-exercise-triangle"),
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
            || t("handout-exercise-discarded").to_owned(),
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
pub(super) fn exercise_html(
    e: &crate::lesson::answer::Exercise,
    comments: &std::collections::BTreeMap<String, String>,
    lang: Lang,
) -> String {
    let t = |id: &'static str| lang.t(id);
    let mut h = format!(
        "<div class=\"question exercise\"><b class=\"ui\">{}</b> {}",
        t("handout-exercise-exercise"),
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
        lang.t_with("handout-exercise-your-answer", &[("tolerance", &tolerance)])
    );
    // The entries' names over their boxes, where the step names them.
    if !e.names.is_empty() && rows == 1 {
        h.push_str("<tr>");
        for c in 0..cols {
            let name = e.entry_name((0, c)).unwrap_or_default();
            let _ = write!(h, "<th>{}</th>", html::esc(name));
        }
        h.push_str("</tr>");
    }
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
