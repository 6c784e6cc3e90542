//! The debugger's breakpoints as a list under its bar: each line with a dot, on which of its
//! hits the run stops (every hit, or the n-th), and for the fragment shader a condition found
//! over the whole frame — the first fragment, reading the picture from the top, where it holds
//! after the line, inspected and shown at that line (through the variable picture's watch).

use std::collections::BTreeMap;

use egui::{RichText, Ui};
use pipeline::shader::Stage;
use pipeline::shader::probe::WatchKind;
use pipeline::shader::stepping::Breakpoint;

use super::watch_picture::WatchPanel;
use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};

/// The breakpoints of both shaders, the fragment shader's conditions, and a condition being
/// searched over the frame.
#[derive(Default)]
pub struct Breakpoints {
    /// The breakpoints, by stage.
    pub by_stage: BTreeMap<StageKey, Vec<Breakpoint>>,
    /// The fragment shader's breakpoints' conditions, by line.
    pub conditions: BTreeMap<usize, String>,
    /// A condition searched over the frame: its line and text, until its watch's frame is here.
    pub finding: Option<(usize, String)>,
    /// What the last search found nothing for, or could not read, in words.
    pub note: Option<String>,
}

/// A stage as a key of the breakpoints' map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum StageKey {
    /// The vertex shader.
    Vertex,
    /// The fragment shader.
    Fragment,
}

impl From<Stage> for StageKey {
    fn from(s: Stage) -> Self {
        match s {
            Stage::Vertex => Self::Vertex,
            Stage::Fragment => Self::Fragment,
        }
    }
}

impl Breakpoints {
    /// The breakpoints of `stage`.
    #[must_use]
    pub fn of(&self, stage: Stage) -> &[Breakpoint] {
        self.by_stage.get(&stage.into()).map_or(&[], Vec::as_slice)
    }

    /// Sets or clears the breakpoint on `line` of `stage`.
    pub fn toggle(&mut self, stage: Stage, line: usize) {
        let list = self.by_stage.entry(stage.into()).or_default();
        match list.iter().position(|b| b.line == line) {
            Some(k) => {
                list.remove(k);
            }
            None => list.push(Breakpoint::at(line)),
        }
    }
}

/// The list of `stage`'s breakpoints, each editable; the command a condition's search asks
/// for (its watch, shown in `watch`'s row too).
pub fn list(
    ui: &mut Ui,
    bps: &mut Breakpoints,
    watch: &mut WatchPanel,
    stage: Stage,
    session: &Session,
) -> Option<Command> {
    let lang = session.lang;
    let mut command = None;
    let mut removed = None;
    if let Some(note) = &bps.note {
        ui.label(RichText::new(note).color(ui.visuals().warn_fg_color));
    }
    let lines: Vec<usize> = bps.of(stage).iter().map(|b| b.line).collect();
    for line in lines {
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(format!("● {} {line}", lang.t("breakpoints-line"))).monospace());
            let Some(b) = bps
                .by_stage
                .get_mut(&stage.into())
                .and_then(|l| l.iter_mut().find(|b| b.line == line))
            else {
                return;
            };
            let mut hit = b.hit.unwrap_or(0);
            let at_hit = ui.label(lang.t("breakpoints-at-hit"));
            if ui
                .add(
                    egui::DragValue::new(&mut hit)
                        .range(0..=100_000)
                        .custom_formatter(|n, _| {
                            if n < 1.0 {
                                lang.t("breakpoints-every").to_owned()
                            } else {
                                format!("{n}")
                            }
                        }),
                )
                .labelled_by(at_hit.id)
                .on_hover_text(lang.t("breakpoints-stop-only-the-n-th"))
                .changed()
            {
                b.hit = (hit > 0).then_some(hit);
            }
            if stage == Stage::Fragment {
                let condition = bps.conditions.entry(line).or_default();
                let label = ui.label(lang.t("breakpoints-where"));
                ui.add(
                    egui::TextEdit::singleline(condition)
                        .id_salt(("breakpoint condition", line))
                        .code_editor()
                        // One line: Tab moves on to the next control, as in every field (the
                        // code editor's lock would trap the keyboard here, WCAG 2.1.2).
                        .lock_focus(false)
                        .desired_width(160.0)
                        .hint_text("diffuse <= 0.0"),
                )
                .labelled_by(label.id);
                if ui
                    .button(lang.t("breakpoints-find-in-the-frame"))
                    .on_hover_text(lang.t("breakpoints-the-first-fragment-reading-the"))
                    .clicked()
                {
                    let condition = condition.trim().to_owned();
                    let spec = pipeline::shader::probe::WatchSpec::fragment(line, &condition);
                    match session.spec.scene.watching(&spec) {
                        Ok(_) => {
                            bps.note = None;
                            watch.expression.clone_from(&condition);
                            watch.line = line;
                            bps.finding = Some((line, condition.clone()));
                            command =
                                Some(Command::Selection(SelectionCommand::SetWatch(Some(spec))));
                        }
                        Err(e) => {
                            bps.note = Some(format!(
                                "{} {e}",
                                lang.t("breakpoints-the-condition-cannot-be-read")
                            ));
                        }
                    }
                }
            }
            if ui
                .add(crate::app::style::glyph_button(ui, "×", None))
                .on_hover_text(lang.t("breakpoints-remove-this-breakpoint"))
                .clicked()
            {
                removed = Some(line);
            }
        });
    }
    if let Some(line) = removed {
        bps.toggle(stage, line);
    }
    command
}

/// Once the frame with a condition's watch is here, the first pixel where it holds: the
/// command that inspects it and the line to show in its run, or, where it holds nowhere or is
/// not a condition, why not (in [`Breakpoints::note`]).
pub fn found(bps: &mut Breakpoints, session: &Session) -> (Option<Command>, Option<usize>) {
    let Some((line, condition)) = bps.finding.clone() else {
        return (None, None);
    };
    let picture = session
        .capture
        .as_ref()
        .and_then(|c| c.shaders.as_ref())
        .and_then(|r| r.watch.as_ref())
        .filter(|w| w.line == line && w.expression == condition);
    let Some(picture) = picture else {
        return (None, None);
    };
    bps.finding = None;
    let lang = session.lang;
    match (picture.kind, picture.first_where()) {
        (Some(WatchKind::Bool), Some(first)) => (
            Some(Command::Selection(SelectionCommand::SelectPixel(Some(
                first,
            )))),
            Some(line),
        ),
        (Some(WatchKind::Bool), None) => {
            bps.note = Some(format!(
                "`{condition}` {}",
                lang.t("breakpoints-holds-at-no-fragment-of")
            ));
            (None, None)
        }
        _ => {
            bps.note = Some(format!(
                "`{condition}` {}",
                lang.t("breakpoints-is-not-a-condition-a")
            ));
            (None, None)
        }
    }
}
