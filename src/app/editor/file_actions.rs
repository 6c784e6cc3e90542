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
            self.save(false, session.lang);
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
                .add_enabled(undo, egui::Button::new(lang.t("file-actions-undo")))
                .on_hover_text("Ctrl+Z")
                .clicked()
            {
                self.undo_redo(true, session, out);
            }
            if ui
                .add_enabled(redo, egui::Button::new(lang.t("file-actions-redo")))
                .on_hover_text("Ctrl+Shift+Z, Ctrl+Y")
                .clicked()
            {
                self.undo_redo(false, session, out);
            }
            let save = if builtin {
                lang.t("file-actions-save-as-a-new-lesson")
            } else if crate::app::platform::WRITES_FILES {
                lang.t("file-actions-save")
            } else {
                lang.t("file-actions-save-download")
            };
            let button = ui
                .add_enabled(
                    dirty || builtin || !crate::app::platform::WRITES_FILES,
                    egui::Button::new(save),
                )
                .on_hover_text(if builtin {
                    lang.t("file-actions-a-built-in-lesson-is")
                } else {
                    lang.t("file-actions-ctrl-s-the-file-is")
                });
            if button.clicked() {
                if builtin {
                    self.new.from = new::From::Builtin(session.source.clone());
                    self.new.show = true;
                } else {
                    self.save(false, lang);
                }
            }
            // A word or two, as long as each other: the row keeps its height when the first
            // change is typed (a longer note wrapped to a second line and moved everything
            // under it, the box being typed in too, down a line).
            if dirty {
                ui.label(
                    RichText::new(lang.t("file-actions-unsaved")).color(ui.visuals().warn_fg_color),
                )
                .on_hover_text(lang.t("file-actions-unsaved-changes-kept-in-a"));
            } else {
                ui.label(RichText::new(lang.t("file-actions-saved")).weak());
            }
        });
    }

    pub(super) fn save(&mut self, overwrite: bool, lang: Lang) {
        if let Some(doc) = &mut self.doc {
            if doc.builtin() {
                return;
            }
            self.said = Some(
                doc.save(overwrite, lang)
                    .map(|f| lang.t_with("file-actions-saved-to", &[("file", &f)])),
            );
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
                RichText::new(lang.t("file-actions-unsaved-changes-to-this-lesson")).color(warn),
            );
            ui.horizontal(|ui| {
                if ui.button(lang.t("file-actions-restore-them")).clicked() {
                    self.said = Some(doc.restore().map(|()| {
                        lang.t("file-actions-restored-save-keeps-them-undo")
                            .to_owned()
                    }));
                    changed = true;
                }
                if ui.button(lang.t("file-actions-discard-them")).clicked() {
                    doc.discard_recovery();
                }
            });
        }
        if doc.ask_overwrite || doc.disk_changed {
            ui.label(RichText::new(lang.t("file-actions-the-file-changed-on-disk")).color(warn));
            ui.horizontal(|ui| {
                if ui
                    .button(lang.t("file-actions-overwrite-it-with-my-edits"))
                    .clicked()
                {
                    self.said = Some(
                        doc.save(true, lang)
                            .map(|f| lang.t_with("file-actions-saved-to", &[("file", &f)])),
                    );
                }
                if ui
                    .button(lang.t("file-actions-load-it-from-disk-undo"))
                    .clicked()
                {
                    self.said = Some(
                        doc.load_from_disk(lang)
                            .map(|()| lang.t("file-actions-loaded-from-disk").to_owned()),
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
                    lang.t("file-actions-not-done-the-lesson-would")
                )));
            }
            Err(e) => {
                self.said = Some(Err(format!(
                    "{}\n{e}",
                    lang.t("file-actions-the-lesson-does-not-pass")
                )));
            }
        }
    }
}
