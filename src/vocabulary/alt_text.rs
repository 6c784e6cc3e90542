//! A picture's text alternative: what a screen reader reads, and a handout's `alt`, in place of
//! the picture (issue "Every student can use it", WCAG 1.1.1). It says what the step shows —
//! the stage, the buffer, the objects drawn (the step's subject first) — and at an inspected
//! pixel the first and last lines of its derivation, the same lines as "explain this pixel".

use pipeline::buffers::BufferKind;
use pipeline::capture::PixelExplanation;

use super::{Lang, Stage, buffer_name};

/// What a picture shows, for its text alternative.
pub struct Shown<'a> {
    /// The stage on screen.
    pub stage: Stage,
    /// The buffer shown, on the stages that show one.
    pub buffer: Option<BufferKind>,
    /// The objects drawn, in the reader's language: the step's subject, then the rest.
    pub objects: (&'a [String], &'a [String]),
    /// The picture's size in pixels.
    pub size: (u32, u32),
    /// The inspected pixel's derivation, with the owning object's name in the reader's language.
    pub pixel: Option<(&'a PixelExplanation, String)>,
}

/// The text alternative of a picture showing `shown`, in `lang`: "Output stage, Colour buffer,
/// 640×400 pixels: the cube (beside: the floor). At pixel (320, 200), the cube's triangle 5:
/// clip_0 = P·V·M·p_0 = (…); … colour = (…)."
#[must_use]
pub fn alt_text(shown: &Shown, lang: Lang) -> String {
    let mut out = match shown.buffer.filter(|_| shown.stage.space().is_none()) {
        Some(b) => format!(
            "{}{}{}",
            stage_words(shown.stage, lang),
            lang.t("alt-text-comma"),
            lang.t_with("alt-text-buffer", &[("name", &buffer_name(b, lang))]),
        ),
        None => stage_words(shown.stage, lang),
    };
    let (w, h) = shown.size;
    out.push_str(&lang.t_with("alt-text-size", &[("w", &w), ("h", &h)]));
    let (subject, rest) = shown.objects;
    if subject.is_empty() && rest.is_empty() {
        out.push_str(lang.t("alt-text-nothing-drawn"));
    } else {
        let list = |names: &[String]| names.join(lang.t("alt-text-list-comma"));
        let (first, others) = if subject.is_empty() {
            (rest, &[][..])
        } else {
            (subject, rest)
        };
        out.push_str(lang.t("alt-text-colon"));
        out.push_str(&list(first));
        if !others.is_empty() {
            out.push_str(&lang.t_with("alt-text-beside", &[("others", &list(others))]));
        }
        out.push_str(lang.t("alt-text-full-stop"));
    }
    if let Some((p, object)) = &shown.pixel {
        out.push_str(&lang.t_with(
            "alt-text-at-pixel",
            &[
                ("x", &p.x),
                ("y", &p.y),
                ("object", object),
                ("triangle", &p.primitive),
            ],
        ));
        let line = |l: &pipeline::capture::Line| {
            if l.numbers.is_empty() {
                format!("{} = {}", l.formula, l.result)
            } else {
                format!("{} = {} = {}", l.formula, l.numbers, l.result)
            }
        };
        match (p.lines.first(), p.lines.last()) {
            (Some(a), Some(b)) if p.lines.len() > 1 => {
                out.push_str(&format!(
                    "{}{}{}{}",
                    lang.t("alt-text-colon"),
                    line(a),
                    lang.t("alt-text-ellipsis"),
                    line(b)
                ));
            }
            (Some(a), _) => {
                out.push_str(lang.t("alt-text-colon"));
                out.push_str(&line(a));
            }
            _ => {}
        }
        out.push_str(lang.t("alt-text-full-stop"));
    }
    out
}

/// "Output stage" / "输出阶段".
fn stage_words(stage: Stage, lang: Lang) -> String {
    lang.t_with("alt-text-stage", &[("stage", &stage.name(lang))])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A geometry stage names no buffer; a pixel stage does; the subject comes first with the
    /// rest beside it, in each language's punctuation.
    #[test]
    fn a_picture_in_words() {
        let (cube, floor) = (["cube".to_owned()], ["floor".to_owned()]);
        let shown = |stage, objects| Shown {
            stage,
            buffer: Some(BufferKind::Color),
            objects,
            size: (640, 400),
            pixel: None,
        };
        assert_eq!(
            alt_text(&shown(Stage::Output, (&cube, &floor)), Lang::EN),
            "Output stage, Colour buffer, 640×400 pixels: cube (beside: floor)."
        );
        assert_eq!(
            alt_text(&shown(Stage::World, (&[], &floor)), Lang::EN),
            "World stage, 640×400 pixels: floor."
        );
        let (cube, floor) = (["立方体".to_owned()], ["地面".to_owned()]);
        assert_eq!(
            alt_text(&shown(Stage::Output, (&cube, &floor)), Lang::ZH),
            "输出阶段，颜色缓冲，640×400 像素：立方体（另有：地面）。"
        );
        assert_eq!(
            alt_text(&shown(Stage::Depth, (&[], &[])), Lang::EN),
            "Depth stage, Colour buffer, 640×400 pixels: nothing drawn."
        );
    }
}
