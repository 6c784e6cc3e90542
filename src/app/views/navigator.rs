//! The pipeline navigator: the stages in order as a clickable strip.

use egui::{RichText, Ui};

use crate::app::session::{Command, Session};
use crate::vocabulary::Stage;

/// Draws the strip; returns the stage clicked, if any.
pub fn ui(ui: &mut Ui, session: &Session) -> Option<Command> {
    let lang = session.lang;
    let mut cmd = None;
    ui.horizontal_wrapped(|ui| {
        for (i, stage) in Stage::ALL.into_iter().enumerate() {
            if i > 0 {
                ui.label(RichText::new("→").weak());
            }
            let selected = session.selection.stage == stage;
            let text = RichText::new(stage.name(lang))
                .size(ui.style().text_styles[&egui::TextStyle::Button].size * 1.15);
            let r = ui
                .selectable_label(selected, if selected { text.strong() } else { text })
                .on_hover_text(stage.explanation(lang));
            if r.clicked() {
                cmd = Some(Command::SelectStage(stage));
            }
        }
    });
    cmd
}
