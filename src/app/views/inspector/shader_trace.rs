//! The shader debugger in the pixel inspector: each fragment the student's fragment shader ran
//! for at the inspected pixel, the inputs it received (interpolated), then its run statement by
//! statement with every value written, and the colour it wrote or its `discard`.

use egui::{RichText, Ui};
use pipeline::capture::{FragmentTrace, FrameCapture};
use pipeline::shader::TraceLine;

use crate::app::session::Session;

use crate::vocabulary::{Lang, num};

/// The fragment shader's runs at the inspected pixel, when the frame ran one.
pub(super) fn ui(ui: &mut Ui, capture: &FrameCapture, lang: Lang) {
    let Some(record) = &capture.shaders else {
        return;
    };
    ui.label(RichText::new(lang.t("shader-trace-your-fragment-shader-at-this")).strong());
    if record.pixel.is_empty() {
        ui.label(lang.t("shader-trace-it-did-not-run-here"));
    }
    for (k, f) in record.pixel.iter().enumerate() {
        fragment(ui, k, f, lang);
    }
    if record.not_finite > 0 {
        ui.colored_label(
            ui.visuals().warn_fg_color,
            format!(
                "{} {}",
                record.not_finite,
                lang.t("shader-trace-pixels-of-this-frame-came")
            ),
        );
    }
}

fn fragment(ui: &mut Ui, k: usize, f: &FragmentTrace, lang: Lang) {
    let title = format!(
        "{} {} · {} {} · {} {}",
        lang.t("shader-trace-fragment"),
        k + 1,
        lang.t("shader-trace-triangle"),
        f.primitive,
        f.samples,
        lang.t("shader-trace-sample-s"),
    );
    egui::CollapsingHeader::new(title)
        .id_salt(("shader fragment", k))
        .default_open(true)
        .show(ui, |ui| {
            ui.label(
                RichText::new(lang.t("shader-trace-received-interpolated-across-the-triangle"))
                    .italics(),
            );
            values(ui, &f.inputs);
            ui.label(RichText::new(lang.t("shader-trace-ran-statement-by-statement")).italics());
            run(ui, &f.trace, lang);
            match f.output {
                Some(c) => {
                    ui.monospace(format!(
                        "→ vec4({}, {}, {}, {})",
                        num(c[0]),
                        num(c[1]),
                        num(c[2]),
                        num(c[3])
                    ));
                }
                None => {
                    ui.label(lang.t("shader-trace-discarded-what-lies-behind-shows"));
                }
            }
        });
}

/// Whether a traced value holds NaN or an infinity (as the trace writes them: `NaN`, `inf`).
fn not_finite(text: &str) -> bool {
    text.split(|c: char| !(c.is_alphanumeric() || c == '-'))
        .any(|w| matches!(w, "NaN" | "inf" | "-inf"))
}

/// The selected vertex's run through its object's vertex shader, when the object has one: its
/// attributes, each statement, its outputs (`gl_Position` the clip position of the table).
pub(super) fn vertex(ui: &mut Ui, session: &Session, capture: &FrameCapture, row: usize) {
    let lang = session.lang;
    let traced = match pipeline::trace_vertex(&session.spec.scene, capture, row) {
        Ok(Some(t)) => t,
        Ok(None) => return,
        Err(e) => {
            ui.colored_label(ui.visuals().error_fg_color, e.to_string());
            return;
        }
    };
    egui::CollapsingHeader::new(
        RichText::new(format!(
            "{} {} ({})",
            lang.t("shader-trace-your-vertex-shader-at-vertex"),
            traced.row,
            traced.object
        ))
        .strong(),
    )
    .id_salt("vertex shader run")
    .default_open(true)
    .show(ui, |ui| {
        egui::ScrollArea::vertical()
            .id_salt("vertex shader run scroll")
            .max_height(ui.available_height() * 0.45)
            .show(ui, |ui| {
                ui.label(RichText::new(lang.t("shader-trace-received-its-attributes")).italics());
                values(ui, &traced.inputs);
                ui.label(
                    RichText::new(lang.t("shader-trace-ran-statement-by-statement")).italics(),
                );
                run(ui, &traced.trace, lang);
                ui.label(RichText::new(lang.t("shader-trace-wrote")).italics());
                values(ui, &traced.outputs);
            });
    });
    ui.separator();
}

/// Names and values, one a row. A long value (a `Light` struct, a matrix) wraps within the
/// panel instead of widening it past the window.
fn values(ui: &mut Ui, rows: &[(String, String)]) {
    for (name, value) in rows {
        ui.horizontal_wrapped(|ui| {
            ui.monospace(name);
            ui.add(egui::Label::new(RichText::new(value).monospace()).wrap());
        });
    }
}

/// The flag after a statement whose value stopped being a number (every glyph in the embedded
/// fonts: `⚠` is in none of them and drew as a box).
const NOT_FINITE_MARK: &str = "◀ NaN/∞";

/// A run, statement by statement, a value that is NaN or infinite flagged; long lines wrap.
fn run(ui: &mut Ui, trace: &[TraceLine], lang: Lang) {
    for line in trace {
        ui.horizontal_wrapped(|ui| {
            ui.monospace(format!("{} {:>3}", lang.t("shader-trace-line"), line.line));
            let words = crate::vocabulary::trace::words(line, lang);
            let text = if not_finite(&words) {
                // The statement where a value stopped being a number.
                RichText::new(format!("{words}   {NOT_FINITE_MARK}"))
                    .monospace()
                    .color(ui.visuals().error_fg_color)
            } else {
                RichText::new(words).monospace()
            };
            ui.add(egui::Label::new(text).wrap());
        });
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_nan_flag_has_glyphs() {
        let drawable = |c| crate::export::text::covers(c);
        assert!(super::NOT_FINITE_MARK.chars().all(drawable));
        // The flag it replaced drew as a box: the check can fail.
        assert!(!drawable('⚠'));
    }
}
