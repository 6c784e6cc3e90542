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
    matrix_grid(ui, &m.matrix, id, lang);
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

/// The 4×4 numbers, in monospace at the body size, right-aligned; a screen reader reads the
/// grid as one group named by its rows ([`said`]) before its cells.
pub fn matrix_grid(ui: &mut Ui, m: &Mat4, id: &str, lang: Lang) {
    let size = ui.style().text_styles[&egui::TextStyle::Body].size;
    let grid = egui::Frame::group(ui.style()).show(ui, |ui| {
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
    let name = said(m, lang);
    grid.response
        .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Group, true, &name));
}

/// A matrix's numbers as a screen reader says them, row by row: "the 4×4 matrix, row by row:
/// row 1: 320, 0, 0, 320; row 2: …".
#[must_use]
pub fn said(m: &Mat4, lang: Lang) -> String {
    let rows: Vec<String> = to_rows(m)
        .iter()
        .enumerate()
        .map(|(k, row)| {
            let values: Vec<String> = row
                .iter()
                .map(|&v| crate::vocabulary::short(v, 3))
                .collect();
            lang.t_with(
                "matrix-grid-row",
                &[
                    ("row", &(k + 1)),
                    ("values", &values.join(lang.t("list-separator"))),
                ],
            )
        })
        .collect();
    lang.t_with(
        "matrix-grid",
        &[("rows", &rows.join(lang.t("answer-list-separator")))],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The viewport matrix of a 640×400 window, said row by row in both languages (its rows
    /// written by hand: x_w = 320·x + 320, y_w = 200·y + 200, z_w = z/2 + 1/2).
    #[test]
    fn a_matrix_is_said_row_by_row() {
        let viewport = Mat4::from_cols_array(&[
            320.0, 0.0, 0.0, 0.0, 0.0, 200.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 320.0, 200.0, 0.5, 1.0,
        ]);
        assert_eq!(
            said(&viewport, Lang::EN),
            "the 4×4 matrix, row by row: row 1: 320, 0, 0, 320; row 2: 0, 200, 0, 200; \
             row 3: 0, 0, 0.5, 0.5; row 4: 0, 0, 0, 1"
        );
        assert_eq!(
            said(&viewport, Lang::ZH),
            "4×4 矩阵，按行：第 1 行：320、0、0、320；第 2 行：0、200、0、200；\
             第 3 行：0、0、0.5、0.5；第 4 行：0、0、0、1"
        );
    }
}
