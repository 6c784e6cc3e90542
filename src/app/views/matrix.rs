//! A matrix as the views show it: its name and formula typeset, its numbers in a grid, its
//! factors below it.

use egui::{RichText, Ui};
use glam::Mat4;
use pipeline::transform::{NamedMatrix, to_rows};

use super::typeset;
use crate::vocabulary::{Lang, num};

/// A matrix with its name and formula typeset, its numbers, and its factors below it (open
/// when `open`).
pub fn matrix(ui: &mut Ui, m: &NamedMatrix, lang: Lang, id: &str, open: bool) {
    let style = typeset::Style::body(ui);
    typeset::formula(ui, &m.name, &style.sized(style.size * 1.1));
    let formula = lang.formula(&m.formula);
    if !formula.is_empty() {
        let dim = typeset::Style {
            color: ui.visuals().text_color().gamma_multiply(0.85),
            ..style
        };
        typeset::paragraph(ui, &formula, &dim.sized(style.size * 0.9));
    }
    matrix_grid(ui, &m.matrix, id);
    if !m.factors.is_empty() {
        egui::CollapsingHeader::new(lang.t("matrix-factors"))
            .id_salt(format!("{id}-factors"))
            .default_open(open)
            .show(ui, |ui| {
                for (i, f) in m.factors.iter().enumerate() {
                    matrix(ui, f, lang, &format!("{id}-{i}"), false);
                }
            });
    }
}

/// The 4×4 numbers, in monospace at the body size, right-aligned.
pub fn matrix_grid(ui: &mut Ui, m: &Mat4, id: &str) {
    let size = ui.style().text_styles[&egui::TextStyle::Body].size;
    egui::Frame::group(ui.style()).show(ui, |ui| {
        egui::Grid::new(id)
            .spacing([size * 0.7, 2.0])
            .show(ui, |ui| {
                for row in to_rows(m) {
                    for v in row {
                        ui.label(
                            RichText::new(format!("{:>9}", num(v)))
                                .monospace()
                                .size(size),
                        );
                    }
                    ui.end_row();
                }
            });
    });
}
