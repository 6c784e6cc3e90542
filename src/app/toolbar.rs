//! The stage's toolbar over its picture: the stage's name (its explanation on hover), the buffer
//! and overlays of the pixel stages, the depth ramp, the comparison and the observer. In a small
//! window (a phone) the name is in the bar above, and the rest is one View menu, so that the
//! picture keeps the rows a wrapped toolbar would take.

use egui::RichText;

use super::session::Command;
use super::views::pixels::PixelView;
use super::{PipelensApp, style, views};
use crate::app::command::ViewCommand;

impl PipelensApp {
    /// One row: the stage's name (its explanation on hover) and the view's controls; in a small
    /// window the controls in a View menu.
    pub(super) fn stage_toolbar(
        &mut self,
        ui: &mut egui::Ui,
        capture: &pipeline::capture::FrameCapture,
    ) {
        let sel = self.session.selection.clone();
        let lang = self.session.lang;
        if super::window_size::is_compact(ui.ctx()) {
            ui.horizontal(|ui| {
                style::chrome_style(ui);
                ui.menu_button(lang.t("toolbar-view"), |ui| {
                    self.view_controls(ui, capture);
                });
            });
            return;
        }
        ui.horizontal_wrapped(|ui| {
            style::chrome_style(ui);
            let size = ui.style().text_styles[&egui::TextStyle::Heading].size;
            ui.label(RichText::new(sel.stage.name(lang)).strong().size(size))
                .on_hover_ui(|ui| {
                    views::typeset::paragraph(
                        ui,
                        sel.stage.explanation(lang),
                        &views::typeset::Style::body(ui),
                    );
                });
            self.view_controls(ui, capture);
        });
    }

    /// The buffer and overlays (pixel stages), the depth ramp, the comparison, the observer; on
    /// a small screen the geometry view's own buttons (Front view, Reset view, normals).
    pub(super) fn view_controls(
        &mut self,
        ui: &mut egui::Ui,
        capture: &pipeline::capture::FrameCapture,
    ) {
        let sel = self.session.selection.clone();
        let lang = self.session.lang;
        let space = sel.stage.space();
        if space.is_none() {
            let c = self
                .pixel_view
                .toolbar(ui, &sel, &self.session.buffers, lang);
            self.commands.extend(c);
            if sel.buffer == pipeline::buffers::BufferKind::Depth
                && let Some(c) = PixelView::depth_controls(ui, &sel, capture, lang)
            {
                self.commands.push(c);
            }
            self.comparison_choice(ui);
        }
        // A small screen's geometry view has its buttons here, off the picture.
        if let Some(space) = space
            && super::window_size::is_compact(ui.ctx())
        {
            let c = self.geometry_view.view_buttons(ui, &self.session, space);
            self.commands.extend(c);
        }
        if space.is_some() || sel.comparison.is_none() {
            let mut obs = sel.show_observer;
            if ui
                .checkbox(&mut obs, lang.t("toolbar-observer-view"))
                .on_hover_text(lang.t("toolbar-the-scene-seen-from-outside"))
                .changed()
            {
                self.commands
                    .push(Command::View(ViewCommand::ToggleObserver));
            }
        }
    }

    /// Side by side: none, or one of the comparisons.
    fn comparison_choice(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        let current = self.session.selection.comparison;
        let mut choice = current;
        egui::ComboBox::new("comparison", lang.t("toolbar-side-by-side"))
            .selected_text(current.map_or(lang.t("toolbar-off"), |c| c.name(lang)))
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut choice, None, lang.t("toolbar-off"));
                for c in crate::vocabulary::Comparison::ALL {
                    ui.selectable_value(&mut choice, Some(c), c.name(lang));
                }
            })
            .response
            .on_hover_text(lang.t("toolbar-render-the-scene-with-different"));
        if choice != current {
            self.commands
                .push(Command::View(ViewCommand::SetComparison(choice)));
        }
    }
}
