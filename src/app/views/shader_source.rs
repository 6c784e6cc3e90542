//! The shader panel's source: line numbers (a line with a message marked), the text highlighted
//! as C-like code, each message written in red at the end of its line.

use egui::{RichText, Ui};

/// The source with line numbers (a line with a message marked), highlighted as C-like code,
/// each message written in red at the end of its line; `tab` names the tab, which keeps its own
/// scroll position. Returns whether it was edited.
pub(super) fn code(
    ui: &mut Ui,
    (source, tab): (&mut String, &str),
    errors: &[(usize, &str)],
) -> bool {
    let mut changed = false;
    egui::ScrollArea::both()
        .id_salt("shader source")
        .show(ui, |ui| {
            ui.horizontal_top(|ui| {
                let lines = source.lines().count().max(1) + usize::from(source.ends_with('\n'));
                let gutter: String = (1..=lines)
                    .map(|n| {
                        if errors.iter().any(|(line, _)| *line == n) {
                            format!("!{n:>3}\n")
                        } else {
                            format!("{n:>4}\n")
                        }
                    })
                    .collect();
                ui.add(
                    egui::Label::new(
                        RichText::new(gutter.trim_end())
                            .monospace()
                            .color(ui.visuals().weak_text_color()),
                    )
                    .selectable(false),
                );
                let theme = egui_extras::syntax_highlighting::CodeTheme::from_style(ui.style());
                // No wrapping: a source line is one line, as its number says.
                let mut layouter = |ui: &Ui, text: &dyn egui::TextBuffer, _wrap_width: f32| {
                    let mut job = egui_extras::syntax_highlighting::highlight(
                        ui.ctx(),
                        ui.style(),
                        &theme,
                        text.as_str(),
                        "c",
                    );
                    job.wrap.max_width = f32::INFINITY;
                    ui.fonts_mut(|f| f.layout_job(job))
                };
                // A fixed id: the messages above come and go as one types, and an id counted
                // from the widgets before it would change with them, taking the focus away.
                let out = egui::TextEdit::multiline(source)
                    .id_salt(("shader source", tab))
                    .code_editor()
                    .desired_rows(lines.max(24))
                    .desired_width(640.0)
                    .lock_focus(true)
                    .layouter(&mut layouter)
                    .show(ui);
                changed = out.response.changed();
                // Without wrapping, row k of the laid-out text is source line k + 1.
                let font = egui::TextStyle::Monospace.resolve(ui.style());
                let color = ui.visuals().error_fg_color;
                for (line, message) in errors {
                    if let Some(row) = line.checked_sub(1).and_then(|k| out.galley.rows.get(k)) {
                        let rect = row.rect().translate(out.galley_pos.to_vec2());
                        ui.painter().text(
                            egui::pos2(rect.max.x + 24.0, rect.center().y),
                            egui::Align2::LEFT_CENTER,
                            format!("◀ {message}"),
                            font.clone(),
                            color,
                        );
                    }
                }
            });
        });
    changed
}
