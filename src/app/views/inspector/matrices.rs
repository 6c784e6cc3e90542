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
        RichText::new(lang.t("matrices-what-this-stage-applies"))
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
            typeset::note(ui, lang.t("matrices-games101-s-m-viewport-maps"));
        }
    }
    ui.add_space(8.0);
    egui::CollapsingHeader::new(RichText::new(lang.t("matrices-other-matrices")).strong())
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
                session.lang.t("matrices-object"),
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
    typeset::note(ui, lang.t("matrices-the-same-projection-in-games101"));
    matrix(ui, &m.projection_games101, lang, "games101", open);
    typeset::note(
        ui,
        if capture.projection.is_perspective() {
            lang.t("matrices-m-ortho-m-persp-ortho")
        } else {
            lang.t("matrices-m-ortho-z-ortho-with")
        },
    );
}

/// The figures' traversal as the matrix stack sees it: push, visit with the composite, pop.
fn hierarchy(ui: &mut Ui, session: &Session, capture: &FrameCapture, lang: Lang) {
    use pipeline::hierarchy::Step;
    ui.label(RichText::new(lang.t("matrices-matrix-stack-depth-first")).strong());
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
