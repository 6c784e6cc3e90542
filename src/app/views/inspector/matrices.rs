//! The Matrices tab: first the matrix the stage applies (the object's model matrix or the
//! figures' matrix stack, V, P in both courses' forms, the viewport), its factors open; then the
//! others, folded.

use egui::{RichText, Ui};
use pipeline::capture::FrameCapture;

use crate::app::session::{Session, Teaching};
use crate::app::views::{matrix, typeset};
use crate::vocabulary::{Lang, part_name};

/// Draws the tab.
pub fn ui(ui: &mut Ui, session: &Session, capture: &FrameCapture) {
    let lang = session.lang;
    let teaching = session.teaching();
    let m = &capture.matrices;
    ui.label(
        RichText::new(lang.tr("What this stage applies", "本阶段使用的矩阵"))
            .strong()
            .size(ui.style().text_styles[&egui::TextStyle::Body].size * 1.05),
    );
    match teaching {
        Teaching::Model(k) if !m.models.is_empty() => {
            let k = k.min(m.models.len() - 1);
            object_caption(ui, session, capture, k);
            super::rotation::forms(ui, session, k);
            matrix(ui, &m.models[k], lang, "focused-model", true);
        }
        Teaching::Stack => hierarchy(ui, session, capture, lang),
        Teaching::View => matrix(ui, &m.view, lang, "focused-view", true),
        Teaching::Projection => projection(ui, capture, lang, true),
        _ => {
            matrix(ui, &m.viewport, lang, "focused-viewport", true);
            typeset::note(
                ui,
                lang.tr(
                    "GAMES101's M_viewport maps x and y the same way and leaves z unchanged; OpenGL (and pipelens) also maps z from [−1, 1] to z_w ∈ [0, 1]. (The notes label this matrix M_{persp→ortho} by mistake.)",
                    "GAMES101 的 M_viewport 对 x、y 的变换相同而 z 保持不变；OpenGL（以及 pipelens）还把 z 从 [−1, 1] 映射到 z_w ∈ [0, 1]。（笔记中把该矩阵误标为 M_{persp→ortho}。）",
                ),
            );
        }
    }
    ui.add_space(8.0);
    egui::CollapsingHeader::new(RichText::new(lang.tr("Other matrices", "其他矩阵")).strong())
        .id_salt("other-matrices")
        .show(ui, |ui| {
            for (i, model) in m.models.iter().enumerate() {
                if teaching != Teaching::Model(i) {
                    object_caption(ui, session, capture, i);
                    matrix(ui, model, lang, &format!("model{i}"), false);
                    ui.add_space(6.0);
                }
            }
            if teaching != Teaching::View {
                matrix(ui, &m.view, lang, "view", false);
                ui.add_space(6.0);
            }
            if teaching != Teaching::Projection {
                projection(ui, capture, lang, false);
                ui.add_space(6.0);
            }
            if !matches!(teaching, Teaching::Viewport | Teaching::Pixel) {
                matrix(ui, &m.viewport, lang, "viewport", false);
            }
            if teaching != Teaching::Stack && !capture.hierarchy.is_empty() {
                ui.add_space(6.0);
                hierarchy(ui, session, capture, lang);
            }
        });
}

/// Which object a model matrix places, by its label.
fn object_caption(ui: &mut Ui, session: &Session, capture: &FrameCapture, k: usize) {
    if let Some(o) = capture.objects.get(k) {
        ui.label(
            RichText::new(format!(
                "{}: {}",
                session.lang.tr("object", "物体"),
                session.spec.label(&o.name, session.lang)
            ))
            .strong(),
        );
    }
}

/// The projection in OpenGL's form, then GAMES101's, and how they relate.
fn projection(ui: &mut Ui, capture: &FrameCapture, lang: Lang, open: bool) {
    let m = &capture.matrices;
    matrix(ui, &m.projection, lang, "projection", open);
    ui.add_space(6.0);
    typeset::note(
        ui,
        lang.tr(
            "The same projection in GAMES101's terms (n = −near, f = −far):",
            "GAMES101 记法下的同一投影（n = −near，f = −far）：",
        ),
    );
    matrix(ui, &m.projection_games101, lang, "games101", open);
    typeset::note(
        ui,
        if capture.projection.is_perspective() {
            lang.tr(
                "M_ortho·M_{persp→ortho} = −Z·P with Z = diag(1, 1, −1, 1): the same x, y after the division; NDC z mirrored (near → +1).",
                "M_ortho·M_{persp→ortho} = −Z·P，Z = diag(1, 1, −1, 1)：除法后 x、y 相同；NDC 的 z 取反（近平面 → +1）。",
            )
        } else {
            lang.tr(
                "M_ortho = Z·Ortho with Z = diag(1, 1, −1, 1): NDC z mirrored (near → +1).",
                "M_ortho = Z·Ortho，Z = diag(1, 1, −1, 1)：NDC 的 z 取反（近平面 → +1）。",
            )
        },
    );
}

/// The figures' traversal as the matrix stack sees it: push, visit with the composite, pop.
fn hierarchy(ui: &mut Ui, session: &Session, capture: &FrameCapture, lang: Lang) {
    use pipeline::hierarchy::Step;
    ui.label(
        RichText::new(lang.tr("Matrix stack, depth-first", "矩阵栈（深度优先遍历）")).strong(),
    );
    let focus = session.selection.focus.as_deref().unwrap_or_default();
    let size = ui.style().text_styles[&egui::TextStyle::Body].size;
    for (i, step) in capture.hierarchy.iter().enumerate() {
        match step {
            Step::Push { depth } => {
                ui.label(
                    RichText::new(format!("{}push(M)  → {depth}", "  ".repeat(depth - 1)))
                        .monospace()
                        .size(size * 0.95),
                );
            }
            Step::Pop { depth } => {
                ui.label(
                    RichText::new(format!("{}M = pop() → {depth}", "  ".repeat(*depth)))
                        .monospace()
                        .size(size * 0.95),
                );
            }
            Step::Visit {
                figure,
                node,
                composite,
                ..
            } => {
                let open = focus.contains(figure) && i < 12;
                egui::CollapsingHeader::new(
                    RichText::new(format!("M({}) = M·local", part_name(node, lang))).monospace(),
                )
                .id_salt(("stack", i))
                .default_open(open)
                .show(ui, |ui| {
                    matrix(ui, composite, lang, &format!("stack{i}"), false)
                });
            }
        }
    }
}
