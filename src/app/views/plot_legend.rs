//! A plot's legend as the app's own checkboxes above it: egui_plot's entries are as high as
//! their text (17 points), under the 24 a mouse needs (WCAG 2.2, 2.5.8) and the 44 a finger
//! does; these are the style's checkboxes, as big as every other control
//! ([`crate::app::style::target_size`]).

use egui::{Color32, RichText, Ui};

/// One checkbox per entry — a swatch in its curve's colour, then its name in the text's —
/// in a row that wraps; returns which entries are shown. What was hidden is kept per `id`.
pub fn legend(ui: &mut Ui, id: &str, entries: &[(&str, Color32)]) -> Vec<bool> {
    let key = egui::Id::unique(("plot-legend", id));
    let mut hidden: std::collections::BTreeSet<String> =
        ui.data(|d| d.get_temp(key)).unwrap_or_default();
    ui.horizontal_wrapped(|ui| {
        for (name, color) in entries {
            let mut shown = !hidden.contains(*name);
            let swatch = RichText::new("■").color(*color);
            if ui.checkbox(&mut shown, (swatch, *name)).changed() {
                if shown {
                    hidden.remove(*name);
                } else {
                    hidden.insert((*name).to_owned());
                }
            }
        }
    });
    let shown = entries.iter().map(|(n, _)| !hidden.contains(*n)).collect();
    ui.data_mut(|d| d.insert_temp(key, hidden));
    shown
}
