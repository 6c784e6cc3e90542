//! The debugger's breakpoints as a list under its bar: each line with a dot, on which of its
//! hits the run stops (every hit, or the n-th), and for the fragment shader a condition found
//! over the whole frame — the first fragment, reading the picture from the top, where it holds
//! after the line, inspected and shown at that line (through the variable picture's watch).

use egui::{RichText, Ui};
use pipeline::shader::Stage;
use pipeline::shader::probe::WatchKind;

use super::debugger::Debugger;
use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};

/// The list of `stage`'s breakpoints, each editable; the command a condition's search asks
/// for (its watch).
pub fn list(
    ui: &mut Ui,
    debugger: &mut Debugger,
    stage: Stage,
    session: &Session,
) -> Option<Command> {
    let lang = session.lang;
    let mut command = None;
    let mut removed = None;
    let lines: Vec<usize> = debugger.of(stage).iter().map(|b| b.line).collect();
    for line in lines {
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(format!("● {} {line}", lang.tr("line", "行"))).monospace());
            let Some(b) = debugger
                .breakpoints
                .get_mut(&stage.into())
                .and_then(|l| l.iter_mut().find(|b| b.line == line))
            else {
                return;
            };
            let mut hit = b.hit.unwrap_or(0);
            ui.label(lang.tr("at hit", "在第"));
            if ui
                .add(
                    egui::DragValue::new(&mut hit)
                        .range(0..=100_000)
                        .custom_formatter(|n, _| {
                            if n < 1.0 {
                                lang.tr("every", "每次").to_owned()
                            } else {
                                format!("{n}")
                            }
                        }),
                )
                .on_hover_text(lang.tr(
                    "Stop only the n-th time the run reaches this line (in a loop: its n-th iteration); 0 stops at every hit.",
                    "只在运行第 n 次到达此行时停下（在循环中即第 n 次迭代）；0 表示每次都停。",
                ))
                .changed()
            {
                b.hit = (hit > 0).then_some(hit);
            }
            if stage == Stage::Fragment {
                let condition = debugger.conditions.entry(line).or_default();
                let label = ui.label(lang.tr("where", "条件"));
                ui.add(
                    egui::TextEdit::singleline(condition)
                        .id_salt(("breakpoint condition", line))
                        .code_editor()
                        .desired_width(160.0)
                        .hint_text("diffuse <= 0.0"),
                )
                .labelled_by(label.id);
                if ui
                    .button(lang.tr("Find in the frame", "在整帧中查找"))
                    .on_hover_text(lang.tr(
                        "The first fragment, reading the picture from the top, where the condition holds just after this line: it is inspected, and its run shown at this line.",
                        "从画面顶部读起，第一个在此行之后条件成立的片元：检查它，并在此行显示它的运行过程。",
                    ))
                    .clicked()
                {
                    let condition = condition.trim().to_owned();
                    match session.spec.scene.watching(line, &condition) {
                        Ok(_) => {
                            debugger.note = None;
                            debugger.watch.expression.clone_from(&condition);
                            debugger.watch.line = line;
                            debugger.finding = Some((line, condition.clone()));
                            command = Some(Command::Selection(SelectionCommand::SetWatch(Some(
                                (line, condition),
                            ))));
                        }
                        Err(e) => {
                            debugger.note = Some(format!(
                                "{} {e}",
                                lang.tr("The condition cannot be read there:", "无法在此处读取该条件：")
                            ));
                        }
                    }
                }
            }
            if ui
                .small_button("×")
                .on_hover_text(lang.tr("Remove this breakpoint", "删除此断点"))
                .clicked()
            {
                removed = Some(line);
            }
        });
    }
    if let Some(line) = removed {
        debugger.toggle(stage, line);
    }
    command
}

/// Once the frame with a condition's watch is here, the first pixel where it holds: the
/// command that inspects it (and the line to show in its run), or, where it holds nowhere or
/// is not a condition, why not.
pub fn found(debugger: &mut Debugger, session: &Session) -> Option<Command> {
    let (line, condition) = debugger.finding.clone()?;
    let picture = session
        .capture
        .as_ref()
        .and_then(|c| c.shaders.as_ref())
        .and_then(|r| r.watch.as_ref())
        .filter(|w| w.line == line && w.expression == condition)?;
    debugger.finding = None;
    let lang = session.lang;
    match (picture.kind, picture.first_where()) {
        (Some(WatchKind::Bool), Some(first)) => {
            debugger.show_line = Some(line);
            Some(Command::Selection(SelectionCommand::SelectPixel(Some(
                first,
            ))))
        }
        (Some(WatchKind::Bool), None) => {
            debugger.note = Some(format!(
                "`{condition}` {}",
                lang.tr(
                    "holds at no fragment of this frame after that line.",
                    "在此帧中没有任何片元在该行之后成立。"
                )
            ));
            None
        }
        _ => {
            debugger.note = Some(format!(
                "`{condition}` {}",
                lang.tr(
                    "is not a condition (a bool): write a comparison, such as diffuse <= 0.0.",
                    "不是条件（bool）：请写一个比较，例如 diffuse <= 0.0。"
                )
            ));
            None
        }
    }
}
