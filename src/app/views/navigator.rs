//! The pipeline navigator: the stages in order as a clickable strip.

use egui::{RichText, Ui};

use crate::app::command::ViewCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::Stage;

/// Draws the strip; returns the stage clicked, if any.
pub fn ui(ui: &mut Ui, session: &Session) -> Option<Command> {
    let lang = session.lang;
    let mut cmd = None;
    // The arrows between the stages only where there is room for them.
    let arrows = ui.ctx().content_rect().width() > 1600.0;
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = if arrows { 6.0 } else { 3.0 };
        for (i, stage) in Stage::ALL.into_iter().enumerate() {
            if i > 0 && arrows {
                ui.label(RichText::new("›").weak());
            }
            let selected = session.selection.stage == stage;
            let text = RichText::new(stage.name(lang));
            let r = ui
                .selectable_label(selected, if selected { text.strong() } else { text })
                .on_hover_text(stage.explanation(lang));
            if r.clicked() {
                cmd = Some(Command::View(ViewCommand::SelectStage(stage)));
            }
        }
    });
    cmd
}
