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
    ui.label(
        RichText::new(lang.tr(
            "Your fragment shader at this pixel",
            "你的片元着色器在此像素",
        ))
        .strong(),
    );
    if record.pixel.is_empty() {
        ui.label(lang.tr(
            "It did not run here: no triangle of an object with shaders covers this pixel.",
            "它没有在这里运行：没有带着色器的物体的三角形覆盖此像素。",
        ));
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
                lang.tr(
                    "pixels of this frame came out NaN or infinite (drawn black).",
                    "个像素的结果为 NaN 或无穷大（画成黑色）。"
                )
            ),
        );
    }
}

fn fragment(ui: &mut Ui, k: usize, f: &FragmentTrace, lang: Lang) {
    let title = format!(
        "{} {} · {} {} · {} {}",
        lang.tr("fragment", "片元"),
        k + 1,
        lang.tr("triangle", "三角形"),
        f.primitive,
        f.samples,
        lang.tr("sample(s)", "个采样"),
    );
    egui::CollapsingHeader::new(title)
        .id_salt(("shader fragment", k))
        .default_open(true)
        .show(ui, |ui| {
            ui.label(
                RichText::new(lang.tr(
                    "received (interpolated across the triangle)",
                    "收到的输入（在三角形上插值）",
                ))
                .italics(),
            );
            values(ui, &f.inputs);
            ui.label(
                RichText::new(lang.tr("ran, statement by statement", "逐条语句的执行")).italics(),
            );
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
                    ui.label(lang.tr(
                        "→ discarded: what lies behind shows instead.",
                        "→ 被丢弃（discard）：显示其后方的表面。",
                    ));
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
            lang.tr("Your vertex shader at vertex", "你的顶点着色器在顶点"),
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
                ui.label(
                    RichText::new(lang.tr("received (its attributes)", "收到的输入（它的属性）"))
                        .italics(),
                );
                values(ui, &traced.inputs);
                ui.label(
                    RichText::new(lang.tr("ran, statement by statement", "逐条语句的执行"))
                        .italics(),
                );
                run(ui, &traced.trace, lang);
                ui.label(RichText::new(lang.tr("wrote", "输出")).italics());
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
            ui.monospace(format!("{} {:>3}", lang.tr("line", "行"), line.line));
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
