//! The Pixel tab: the inspected pixel, its colour derived step by step (every line a formula of
//! the course with the capture's numbers), and every fragment that reached it with its edge
//! functions and depth test.

use egui::{Color32, RichText, Ui};
use pipeline::capture::{Fate, FragmentRecord, FrameCapture, PixelExplanation, PixelRecord};

use crate::app::session::Session;
use crate::app::views::typeset::{self, Style};
use crate::vocabulary::{Lang, num, remark, section_name};

/// Draws the tab.
pub fn ui(ui: &mut Ui, session: &Session, capture: &FrameCapture, record: Option<&PixelRecord>) {
    let lang = session.lang;
    let style = Style::body(ui);
    let Some(record) = record else {
        typeset::paragraph(ui, lang.t("pixel-click-a-pixel-in-a"), &style);
        return;
    };
    let (x, y) = (record.x, record.y);
    let s = capture.settings.samples.count();
    ui.heading(format!("{} ({x}, {y})", lang.t("pixel-pixel")));
    if let Some(e) = &record.explanation {
        ui.label(
            RichText::new(format!(
                "{} · {} {}",
                session.spec.label(&e.object, lang),
                lang.t("pixel-triangle"),
                e.primitive
            ))
            .strong(),
        );
    }
    typeset::paragraph(
        ui,
        &format!(
            "{}: {}/{s} · {}: z_w = {} · {}: ({}, {}, {})",
            lang.t("pixel-coverage"),
            record.coverage,
            lang.t("pixel-depth-mean-of-samples"),
            num(record.depth),
            lang.t("pixel-colour"),
            num(record.color[0]),
            num(record.color[1]),
            num(record.color[2])
        ),
        &style,
    );
    swatch(ui, record.color);
    if capture.shaders.is_some() {
        // The colour is the student's shader's: its run comes first; the derivation below
        // still tells how the fragment got here, and what pipelens' own shading would give.
        super::shader_trace::ui(ui, capture, lang);
        ui.separator();
        ui.label(RichText::new(lang.t("pixel-how-the-fragment-got-here")).italics());
    }
    match &record.explanation {
        Some(e) => explanation(ui, e, lang),
        None => {
            ui.label(lang.t("pixel-no-fragment-owns-this-pixel"));
        }
    }
    ui.separator();
    ui.label(RichText::new(lang.t("pixel-every-fragment-that-reached-the")).strong());
    if record.fragments.is_empty() {
        ui.label(lang.t("pixel-none"));
    }
    for (k, f) in record.fragments.iter().enumerate() {
        fragment(ui, k, f, session, capture, lang);
    }
    if record.primitive.is_none() && !record.fragments.is_empty() {
        // The samples above are pipelens' own edge test's; where the student's inside test
        // decides the coverage, it is what left the pixel empty, not the depth test.
        let student_inside = session
            .spec
            .scene
            .hook(pipeline::shader::HookKind::Inside)
            .is_some();
        ui.label(if student_inside {
            lang.t("pixel-your-inside-covers-none-of")
        } else {
            lang.t("pixel-every-fragment-failed-the-depth")
        });
    }
}

fn swatch(ui: &mut Ui, c: [f32; 3]) {
    let b = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
    let (r, _) = ui.allocate_exact_size(egui::vec2(48.0, 16.0), egui::Sense::hover());
    ui.painter()
        .rect_filled(r, 2.0, Color32::from_rgb(b(c[0]), b(c[1]), b(c[2])));
}

/// "Explain this pixel": the derivation, part by part, each line a formula, the numbers put in,
/// the value, and what it means.
fn explanation(ui: &mut Ui, e: &PixelExplanation, lang: Lang) {
    let style = Style::body(ui);
    let formula_style = Style {
        color: style.accent,
        ..style
    };
    let numbers_style = style.sized(style.size * 0.92);
    egui::CollapsingHeader::new(RichText::new(lang.t("pixel-explain-this-pixel")).strong())
        .id_salt("explain")
        .default_open(true)
        .show(ui, |ui| {
            let mut section = None;
            for line in &e.lines {
                if section != Some(line.section) {
                    section = Some(line.section);
                    ui.add_space(4.0);
                    ui.label(RichText::new(section_name(line.section, lang)).strong());
                }
                ui.indent(("line", line.formula.as_str()), |ui| {
                    typeset::paragraph(ui, &format!("**{}**", line.formula), &formula_style);
                    let mut rest = String::new();
                    if !line.numbers.is_empty() {
                        rest.push_str(&format!("= {}", line.numbers));
                    }
                    if !line.result.is_empty() {
                        rest.push_str(&format!(
                            "{}= **{}**",
                            if rest.is_empty() { "" } else { " " },
                            line.result
                        ));
                    }
                    if !rest.is_empty() {
                        typeset::paragraph(ui, &rest, &numbers_style);
                    }
                    for r in &line.remarks {
                        typeset::paragraph(
                            ui,
                            &remark(r, lang),
                            &numbers_style.sized(style.size * 0.85),
                        );
                    }
                });
            }
        });
}

/// One fragment: its triangle, its edge functions at the centre, its samples' inside and depth
/// tests, its depth and barycentrics.
fn fragment(
    ui: &mut Ui,
    k: usize,
    f: &FragmentRecord,
    session: &Session,
    capture: &FrameCapture,
    lang: Lang,
) {
    let prim = &capture.primitives[f.primitive as usize];
    let object = capture
        .objects
        .get(prim.object as usize)
        .map(|o| session.spec.label(&o.name, lang))
        .unwrap_or_default();
    let title = format!(
        "{} {} · {object} · {} {}{}",
        lang.t("pixel-fragment"),
        k + 1,
        lang.t("pixel-triangle"),
        f.primitive,
        if f.visible {
            lang.t("pixel-visible")
        } else {
            ""
        }
    );
    let style = Style::body(ui);
    egui::CollapsingHeader::new(RichText::new(title).strong())
        .id_salt(("frag", k))
        .default_open(k < 3)
        .show(ui, |ui| {
            if prim.fate == Fate::Clipped {
                ui.label(lang.t("pixel-a-piece-of-a-clipped"));
            }
            let e = &f.edges;
            typeset::paragraph(
                ui,
                &format!(
                    "**E_0, E_1, E_2** = ({}, {}, {}) · **λ** = ({}, {}, {})",
                    num(e.centre[0] as f32),
                    num(e.centre[1] as f32),
                    num(e.centre[2] as f32),
                    num(e.lambda[0] as f32),
                    num(e.lambda[1] as f32),
                    num(e.lambda[2] as f32)
                ),
                &style,
            );
            ui.horizontal_wrapped(|ui| {
                ui.label(lang.t("pixel-samples"));
                for (si, outcome) in f.samples.iter().enumerate() {
                    let (text, color) = match outcome {
                        None => ("·", Color32::GRAY),
                        Some(true) => ("√", Color32::from_rgb(90, 210, 90)),
                        Some(false) => ("×", Color32::from_rgb(235, 80, 80)),
                    };
                    let tie = e.samples.get(si).filter(|q| !q.on_edges.is_empty());
                    ui.label(
                        RichText::new(format!(
                            "{si}{text}{}",
                            if tie.is_some() { "*" } else { "" }
                        ))
                        .color(color)
                        .monospace(),
                    )
                    .on_hover_text(match (outcome, f.sample_depths[si]) {
                        (None, _) => lang.t("pixel-not-covered").to_owned(),
                        (Some(true), Some(z)) => format!(
                            "{} z = {}",
                            lang.t("pixel-covered-passed-the-depth-test"),
                            num(z)
                        ),
                        (Some(false), Some(z)) => format!(
                            "{} z = {}",
                            lang.t("pixel-covered-failed-the-depth-test"),
                            num(z)
                        ),
                        _ => String::new(),
                    });
                }
            });
            if e.samples.iter().any(|q| !q.on_edges.is_empty()) {
                ui.label(lang.t("pixel-on-an-edge-the-top"));
            }
            let b = f.bary_perspective;
            typeset::paragraph(
                ui,
                &format!(
                    "z_w = {} · **b** = ({}, {}, {})",
                    num(f.depth),
                    num(b[0]),
                    num(b[1]),
                    num(b[2])
                ),
                &style,
            );
        });
}
