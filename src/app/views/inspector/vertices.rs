//! The vertex table: every vertex through the spaces, its header fixed while the rows scroll,
//! scrolled to the vertex picked in a view, the objects by name. It shows the stage's space and
//! the one before it (what the stage's matrix does); any other space can be added.

use egui::{RichText, Ui};
use egui_extras::{Column, TableBuilder};
use pipeline::capture::FrameCapture;
use pipeline::vertex::VertexRecord;

use super::tabs::Inspector;
use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};
use crate::app::views::palette;
use crate::vocabulary::{Lang, Space, Stage, vec3, vec4};

const SPACES: [Space; 6] = [
    Space::Model,
    Space::World,
    Space::Eye,
    Space::Clip,
    Space::Ndc,
    Space::Window,
];

fn space_header(space: Space, lang: Lang) -> &'static str {
    match space {
        Space::Model => lang.t("vertices-model"),
        Space::World => lang.t("vertices-world"),
        Space::Eye => lang.t("vertices-eye"),
        Space::Clip => lang.t("vertices-clip-x-y-z-w"),
        Space::Ndc => "NDC",
        Space::Window => lang.t("vertices-window"),
    }
}

fn coordinates(v: &VertexRecord, space: Space) -> String {
    match space {
        Space::Model => vec3(v.object_pos.truncate()),
        Space::World => vec3(v.world.truncate()),
        Space::Eye => vec3(v.eye.truncate()),
        Space::Clip => vec4(v.clip),
        Space::Ndc => v.ndc.map_or_else(|| "— (w ≤ 0)".to_owned(), vec3),
        Space::Window => v.window.map_or_else(|| "—".to_owned(), vec3),
    }
}

/// The spaces shown by default: the stage's and the one before (its input).
fn default_spaces(stage: Stage) -> Vec<Space> {
    match stage.space() {
        Some(Space::Model) | None => vec![Space::Model, Space::World],
        Some(space) => {
            let k = SPACES.iter().position(|s| *s == space).unwrap_or(1);
            vec![SPACES[k - 1], space]
        }
    }
}

/// The spaces the table shows, one checkbox each (the stage's and the one before until the
/// reader picks); the choice kept in the inspector.
fn choose_spaces(ui: &mut Ui, inspector: &mut Inspector, session: &Session) -> Vec<Space> {
    let lang = session.lang;
    let mut spaces = inspector
        .spaces
        .clone()
        .unwrap_or_else(|| default_spaces(session.selection.stage));
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.t("vertices-spaces"));
        for space in SPACES {
            let mut on = spaces.contains(&space);
            if ui.checkbox(&mut on, space_header(space, lang)).changed() {
                if on {
                    spaces.push(space);
                    spaces.sort_by_key(|s| SPACES.iter().position(|x| x == s));
                } else {
                    spaces.retain(|s| *s != space);
                }
                inspector.spaces = Some(spaces.clone());
            }
        }
    });
    spaces
}

/// Draws the table; returns the vertex clicked.
pub fn ui(
    ui: &mut Ui,
    inspector: &mut Inspector,
    session: &Session,
    capture: &FrameCapture,
) -> Vec<Command> {
    let lang = session.lang;
    let mut cmds = Vec::new();
    let spaces = choose_spaces(ui, inspector, session);
    ui.label(
        RichText::new(lang.t("vertices-click-a-row-to-highlight"))
            .size(ui.style().text_styles[&egui::TextStyle::Small].size),
    );
    let selected = session.selection.vertex;
    if let Some(row) = selected {
        super::shader_trace::vertex(ui, session, capture, row as usize);
    }
    let scroll_to = selected.filter(|v| inspector.scrolled_to != Some(*v));
    inspector.scrolled_to = selected;
    let size = ui.style().text_styles[&egui::TextStyle::Monospace].size;
    let row_height = ui.text_style_height(&egui::TextStyle::Monospace) + 4.0;
    let mut table = TableBuilder::new(ui)
        .id_salt("vertex-table")
        .striped(true)
        .resizable(true)
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
        .column(Column::auto().at_least(size * 3.5))
        .column(Column::auto().at_least(size * 4.0).clip(true));
    for _ in &spaces {
        table = table.column(Column::auto().at_least(size * 10.0));
    }
    if let Some(v) = scroll_to {
        table = table.scroll_to_row(v as usize, Some(egui::Align::Center));
    }
    table
        .header(row_height + 2.0, |mut header| {
            header.col(|ui| {
                ui.strong(lang.t("vertices-vertex"));
            });
            header.col(|ui| {
                ui.strong(lang.t("vertices-object"));
            });
            for space in &spaces {
                header.col(|ui| {
                    ui.strong(space_header(*space, lang));
                });
            }
        })
        .body(|body| {
            body.rows(row_height, capture.vertices.len(), |mut row| {
                let i = row.index();
                let v = &capture.vertices[i];
                let is_selected = selected == Some(i as u32);
                row.set_selected(is_selected);
                let text = |s: String| {
                    let t = RichText::new(s).monospace();
                    if is_selected {
                        t.color(palette::SELECTED)
                    } else {
                        t
                    }
                };
                row.col(|ui| {
                    if ui
                        .selectable_label(is_selected, text(format!("v{i}")))
                        .clicked()
                    {
                        let row = (!is_selected).then_some(i as u32);
                        cmds.push(Command::Selection(SelectionCommand::SelectVertex(row)));
                    }
                });
                row.col(|ui| {
                    let name = capture.objects.get(v.object as usize).map_or_else(
                        || v.object.to_string(),
                        |o| session.spec.label(&o.name, lang),
                    );
                    ui.label(text(name));
                });
                for space in &spaces {
                    row.col(|ui| {
                        ui.label(text(coordinates(v, *space)));
                    });
                }
            });
        });
    cmds
}
