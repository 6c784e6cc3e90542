//! What the editor does with its file: the row of Undo, Redo and Save and their keys
//! (the shortcut table's), the questions about a recovery copy or a file changed on disk, and
//! each revision handed to the session, which keeps playing the last good lesson when a
//! revision is broken.

use egui::{Context, RichText};

use super::new;
use super::window::Editor;
use crate::app::command::EditorCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::Lang;

impl Editor {
    /// Ctrl+S saves; Ctrl+Z undoes and Ctrl+Shift+Z or Ctrl+Y redoes, unless a text box has the
    /// keys (it undoes its own typing). The keys are the shortcut table's.
    pub(super) fn shortcuts(&mut self, ctx: &Context, session: &Session, out: &mut Vec<Command>) {
        use crate::app::shortcuts::{Action, pressed};
        if pressed(ctx, Action::Save) {
            self.save(false);
        }
        if ctx.text_edit_focused() {
            return;
        }
        if pressed(ctx, Action::Redo) {
            self.undo_redo(false, session, out);
        } else if pressed(ctx, Action::Undo) {
            self.undo_redo(true, session, out);
        }
    }

    /// The file, Undo, Redo and Save.
    pub(super) fn file_row(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        let Some(doc) = &self.doc else {
            return;
        };
        let (undo, redo, dirty, builtin) = (
            doc.draft.can_undo(),
            doc.draft.can_redo(),
            doc.draft.is_dirty(),
            doc.builtin(),
        );
        ui.horizontal_wrapped(|ui| {
            if ui
                .add_enabled(undo, egui::Button::new(lang.tr("↶ Undo", "↶ 撤销")))
                .on_hover_text("Ctrl+Z")
                .clicked()
            {
                self.undo_redo(true, session, out);
            }
            if ui
                .add_enabled(redo, egui::Button::new(lang.tr("↷ Redo", "↷ 重做")))
                .on_hover_text("Ctrl+Shift+Z, Ctrl+Y")
                .clicked()
            {
                self.undo_redo(false, session, out);
            }
            let save = if builtin {
                lang.tr("Save as a new lesson ↓", "另存为新课程 ↓")
            } else if crate::app::platform::WRITES_FILES {
                lang.tr("Save", "保存")
            } else {
                lang.tr("Save (download)", "保存（下载）")
            };
            let button = ui
                .add_enabled(dirty || builtin || !crate::app::platform::WRITES_FILES, egui::Button::new(save))
                .on_hover_text(if builtin {
                    lang.tr(
                        "A built-in lesson is not changed: make it a lesson file of your own below (New lesson, from this lesson).",
                        "内置课程不会被修改：在下面把它新建为你自己的课程文件（新建课程，从本课程开始）。",
                    )
                } else {
                    lang.tr("Ctrl+S: the file is written whole or not at all", "Ctrl+S：文件要么完整写入，要么不写")
                });
            if button.clicked() {
                if builtin {
                    self.new.from = new::From::Builtin(session.source.clone());
                    self.new.show = true;
                } else {
                    self.save(false);
                }
            }
            // A word or two, as long as each other: the row keeps its height when the first
            // change is typed (a longer note wrapped to a second line and moved everything
            // under it, the box being typed in too, down a line).
            if dirty {
                ui.label(
                    RichText::new(lang.tr("● unsaved", "● 未保存"))
                        .color(ui.visuals().warn_fg_color),
                )
                .on_hover_text(lang.tr(
                    "Unsaved changes, kept in a recovery copy beside the file until saved (Ctrl+S).",
                    "有未保存的修改，保存（Ctrl+S）之前已在文件旁保存恢复副本。",
                ));
            } else {
                ui.label(RichText::new(lang.tr("saved", "已保存")).weak());
            }
        });
    }

    pub(super) fn save(&mut self, overwrite: bool) {
        if let Some(doc) = &mut self.doc {
            if doc.builtin() {
                return;
            }
            self.said = Some(doc.save(overwrite).map(|f| format!("saved: {f}")));
        }
    }

    /// A recovery copy to restore, a file changed on disk.
    pub(super) fn questions(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        let Some(doc) = &mut self.doc else {
            return;
        };
        let warn = ui.visuals().warn_fg_color;
        let mut changed = false;
        if doc.recovery.is_some() {
            ui.label(
                RichText::new(lang.tr(
                    "Unsaved changes to this lesson were kept from the last time it was edited.",
                    "上次编辑这个课程时有未保存的修改，已保留。",
                ))
                .color(warn),
            );
            ui.horizontal(|ui| {
                if ui.button(lang.tr("Restore them", "恢复这些修改")).clicked() {
                    self.said = Some(doc.restore().map(|()| {
                        lang.tr(
                            "Restored: Save keeps them, Undo drops them.",
                            "已恢复：保存即保留，撤销即放弃。",
                        )
                        .to_owned()
                    }));
                    changed = true;
                }
                if ui.button(lang.tr("Discard them", "丢弃")).clicked() {
                    doc.discard_recovery();
                }
            });
        }
        if doc.ask_overwrite || doc.disk_changed {
            ui.label(
                RichText::new(lang.tr(
                    "The file changed on disk while you were editing it.",
                    "编辑期间，文件在磁盘上被修改了。",
                ))
                .color(warn),
            );
            ui.horizontal(|ui| {
                if ui
                    .button(lang.tr("Overwrite it with my edits", "用我的修改覆盖它"))
                    .clicked()
                {
                    self.said = Some(doc.save(true).map(|f| format!("saved: {f}")));
                }
                if ui
                    .button(lang.tr(
                        "Load it from disk (Undo brings my edits back)",
                        "从磁盘载入（撤销可找回我的修改）",
                    ))
                    .clicked()
                {
                    self.said = Some(
                        doc.load_from_disk()
                            .map(|()| lang.tr("Loaded from disk.", "已从磁盘载入。").to_owned()),
                    );
                    changed = true;
                }
            });
        }
        if changed {
            self.revised(session, None, false, out);
        }
    }

    pub(super) fn undo_redo(&mut self, undo: bool, session: &Session, out: &mut Vec<Command>) {
        let Some(doc) = &mut self.doc else {
            return;
        };
        let done = if undo {
            doc.draft.undo()
        } else {
            doc.draft.redo()
        };
        if done {
            self.revised(session, None, false, out);
        }
    }

    /// After a change to the draft: the session plays the lesson as it now reads, at `step`
    /// (the step it was at when `None`), entered. A change that leaves a lesson `check` rejects
    /// is taken back when `refuse` (a step recorded, moved, copied or deleted: the steps on
    /// screen and in the file stay the same steps), and the editor says why; otherwise (undo,
    /// redo, a restored copy) the last good lesson keeps playing and the editor lists what to fix.
    pub(super) fn revised(
        &mut self,
        session: &Session,
        step: Option<usize>,
        refuse: bool,
        out: &mut Vec<Command>,
    ) {
        let Some(doc) = &mut self.doc else {
            return;
        };
        self.words_for = None;
        let lang = session.lang;
        let at = step.unwrap_or_else(|| session.lesson.as_ref().map_or(0, |p| p.step));
        match doc.draft.lesson() {
            Ok(lesson) => out.push(Command::Editor(EditorCommand::ReviseLesson {
                lesson: Box::new(lesson),
                step: at,
                enter: true,
            })),
            Err(e) if refuse => {
                doc.draft.discard_last();
                self.said = Some(Err(format!(
                    "{}\n{e}",
                    lang.tr(
                        "Not done: the lesson would no longer pass the check (a step's parameters may need one before it):",
                        "未执行：这样改动后课程将无法通过检查（某一步的参数可能依赖它之前的步骤）：",
                    )
                )));
            }
            Err(e) => {
                self.said = Some(Err(format!(
                    "{}\n{e}",
                    lang.tr(
                        "The lesson does not pass the check; the last good version keeps playing until this is fixed:",
                        "课程无法通过检查；在修正之前继续播放上一个正确的版本：",
                    )
                )));
            }
        }
    }
}
