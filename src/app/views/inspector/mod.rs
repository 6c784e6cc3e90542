//! The inspector: the matrices with their formulas and factors, the vertex table through every
//! space, and the pixel inspector (every fragment that reached a pixel, its edge functions, and
//! its colour derived step by step). It opens on what the stage and the step teach.

mod matrices;
mod pixel;
mod rotation;
mod shader_trace;
mod tabs;
mod vertices;

pub use tabs::{Inspector, Tab};

use egui::Ui;
use pipeline::capture::FrameCapture;

use crate::app::session::{Command, Session};

/// Draws the inspector.
pub fn ui(
    ui: &mut Ui,
    inspector: &mut Inspector,
    session: &Session,
    capture: &FrameCapture,
) -> Vec<Command> {
    inspector.follow(session);
    let lang = session.lang;
    let mut cmds = Vec::new();
    ui.horizontal(|ui| {
        let tab = &mut inspector.tab;
        ui.selectable_value(tab, Tab::Matrices, lang.t("inspector-matrices"));
        ui.selectable_value(tab, Tab::Vertices, lang.t("inspector-vertices"));
        ui.selectable_value(tab, Tab::Pixel, lang.t("inspector-pixel"));
    });
    ui.separator();
    match inspector.tab {
        Tab::Matrices => {
            egui::ScrollArea::vertical()
                .id_salt("matrices")
                .show(ui, |ui| matrices::ui(ui, session, capture));
        }
        Tab::Vertices => cmds.extend(vertices::ui(ui, inspector, session, capture)),
        Tab::Pixel => {
            let record = inspector.record(session, capture);
            egui::ScrollArea::vertical()
                .id_salt("pixel")
                .show(ui, |ui| pixel::ui(ui, session, capture, record));
        }
    }
    cmds
}
