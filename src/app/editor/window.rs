//! The lesson editor's window: the steps listed (those changed since the last save marked),
//! moved, copied and deleted; undo and redo; save; the current step's words and what is on
//! screen recorded (`words.rs`, `screen.rs`), a new lesson (`new.rs`), the file (`file.rs`).

use egui::{Context, RichText};

use super::file::Edited;
use super::new::{self, Made, NewLesson};
use crate::app::command::{EditorCommand, LessonCommand};

use crate::app::session::{Command, Session};
use crate::lesson::SceneSpec;
use crate::lesson::param::{self, Animation, Easing, Repeat, Value};
use crate::vocabulary::{Lang, Text};

/// The editor's state.
#[derive(Default)]
pub struct Editor {
    /// Whether the window is shown.
    pub open: bool,
    /// The lesson being edited (the one open in the session, once the window was opened or a
    /// recovery copy was found).
    pub doc: Option<Edited>,
    /// The words in the boxes (the lesson's title and summary, the step's four), and the step
    /// and revision they were read at.
    pub(super) words: [Text; 6],
    pub(super) words_for: Option<(usize, u64)>,
    /// The words of a new step, typed before it is added.
    pub(super) fresh: [Text; 2],
    /// Sliders dragged while the window was open: the new step's animations.
    pub(super) drags: Vec<Animation>,
    /// The steps changed since the last save, and the draft's revision they were read at.
    pub(super) marks: Option<(u64, Vec<bool>)>,
    /// What the last action said.
    pub(super) said: Option<Result<String, String>>,
    /// The "New lesson" part.
    pub new: NewLesson,
    /// A lesson just made, for the app to open (and then [`Self::adopt`]).
    pub made: Option<Made>,
    /// Why the last new lesson was not made.
    pub(super) new_error: Option<String>,
}

impl Editor {
    /// Follows what the session has open: a lesson other than the one edited is taken up (its
    /// file read, its recovery copy looked for; the window opens to offer one). `file` is the
    /// file on disk the session was opened from, if any.
    pub fn follow(&mut self, session: &Session, file: Option<&std::path::Path>) {
        if session.lesson.is_none() {
            self.doc = None;
            return;
        }
        if self
            .doc
            .as_ref()
            .is_some_and(|d| d.source == session.source)
        {
            return;
        }
        self.words_for = None;
        self.marks = None;
        self.drags.clear();
        match Edited::open(&session.source, file, None) {
            Ok(doc) => {
                if doc.recovery.is_some() {
                    self.open = true;
                }
                self.doc = Some(doc);
            }
            Err(e) => {
                self.doc = None;
                // A lesson with no text to edit (dropped on a page) says nothing until edited.
                if file.is_some() {
                    self.said = Some(Err(e));
                }
            }
        }
    }

    /// Takes up `text` as the lesson the session now has open under the name `source` (a
    /// lesson just made, or a file dropped on the page), saved into `file` when there is one.
    pub fn adopt(&mut self, source: &str, file: Option<&std::path::Path>, text: String) {
        self.words_for = None;
        self.marks = None;
        match Edited::open(source, file, Some(text)) {
            Ok(doc) => self.doc = Some(doc),
            Err(e) => self.said = Some(Err(e)),
        }
    }

    /// A drag that ended, from the scene `from` to `to`: each number or vector it moved is an
    /// animation of the next recorded step, from where it began to where it was let go.
    pub fn dragged(&mut self, from: &SceneSpec, to: &SceneSpec) {
        if !self.open {
            return;
        }
        for (name, end) in param::differences(from, to) {
            let Some(start) = param::get(from, &name) else {
                continue;
            };
            if !matches!(end, Value::Number(_) | Value::Vec3(_)) {
                continue;
            }
            self.drags.retain(|a| a.param != name);
            self.drags.push(Animation {
                param: name,
                from: start,
                to: end,
                seconds: 4.0,
                easing: Easing::DEFAULT,
                repeat: Repeat::DEFAULT,
            });
        }
    }

    /// The window, when open; the commands it gives the session.
    pub fn ui(&mut self, ctx: &Context, session: &Session) -> Vec<Command> {
        let mut out = Vec::new();
        if let Some(doc) = &mut self.doc {
            doc.keep_recovery();
        }
        if !self.open {
            return out;
        }
        let lang = session.lang;
        self.shortcuts(ctx, session, &mut out);
        let mut open = self.open;
        let title = match &self.doc {
            Some(d) => format!(
                "{} — {}{}",
                lang.tr("Lesson editor", "课程编辑器"),
                d.draft.name(),
                if d.draft.is_dirty() { " ●" } else { "" }
            ),
            None => lang.tr("Lesson editor", "课程编辑器").to_owned(),
        };
        // Over the narration card, first at the top-right (the picture's subject keeps clear of
        // the card, at the bottom-left); its title bar moves it.
        let screen = ctx.content_rect();
        let most = screen.height() - 90.0;
        egui::Window::new(title)
            .id(egui::Id::unique("lesson-editor"))
            .open(&mut open)
            .order(egui::Order::Foreground)
            .pivot(egui::Align2::RIGHT_TOP)
            .default_pos(egui::pos2(screen.right() - 16.0, screen.top() + 64.0))
            .default_width(640.0)
            .max_height(most)
            .show(ctx, |ui| {
                egui::ScrollArea::vertical()
                    .id_salt("lesson-editor-scroll")
                    .max_height(most)
                    .min_scrolled_height(most)
                    .show(ui, |ui| self.contents(ui, session, lang, &mut out));
            });
        self.open = open;
        out
    }

    pub(super) fn contents(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        if self.doc.is_some() {
            self.file_row(ui, session, lang, out);
            // What the last action said, at the top where it is seen.
            if let Some(m) = &self.said {
                said(ui, m);
            }
            if self
                .doc
                .as_ref()
                .is_some_and(|d| d.recovery.is_some() || d.ask_overwrite || d.disk_changed)
            {
                self.questions(ui, session, lang, out);
            }
            if self.doc.as_ref().is_some_and(Edited::builtin) {
                // Not edited in place: edits to a lesson shipped inside the app would have no
                // file to be kept in.
                ui.label(RichText::new(lang.tr(
                    "A built-in lesson is not edited in place. Make it a lesson of your own (New lesson, from this lesson, below), then record, word and arrange its steps there.",
                    "内置课程不能直接修改。先把它新建为你自己的课程（见下方“新建课程”，从本课程开始），再在那里录制、撰写和调整步骤。",
                )).color(ui.visuals().warn_fg_color));
            } else {
                self.steps(ui, session, lang, out);
                ui.separator();
                self.step_words(ui, session, lang, out);
                ui.separator();
                self.on_screen(ui, session, lang, out);
            }
        } else {
            ui.label(lang.tr(
                "Open a lesson to edit it, or make a new one below.",
                "打开一个课程即可编辑它，或在下面新建一个。",
            ));
        }
        ui.separator();
        let current = self.doc.as_ref().map(|d| d.draft.text().to_owned());
        match self.new.ui(ui, session, lang, current.as_deref()) {
            Some(Ok(made)) => {
                self.said = Some(Ok(made.said.clone()));
                self.new_error = None;
                self.made = Some(made);
            }
            Some(Err(e)) => self.new_error = Some(e),
            None => {}
        }
        if let Some(e) = &self.new_error {
            said(ui, &Err(e.clone()));
        }
    }

    /// Ctrl+S saves; Ctrl+Z undoes and Ctrl+Shift+Z or Ctrl+Y redoes, unless a text box has the
    /// keys (it undoes its own typing). The keys are the shortcut table's.
    pub(super) fn shortcuts(&mut self, ctx: &Context, session: &Session, out: &mut Vec<Command>) {
        use crate::app::shortcuts::{Action, pressed};
        if pressed(ctx, Action::Save) {
            self.save(false);
        }
        if ctx.egui_wants_keyboard_input() {
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
            let state = if dirty {
                RichText::new(lang.tr("● unsaved changes (kept in a recovery copy)", "● 有未保存的修改（已保存恢复副本）"))
                    .color(ui.visuals().warn_fg_color)
            } else {
                RichText::new(lang.tr("saved", "已保存")).weak()
            };
            ui.label(state);
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

    /// The steps, the current one selected, those changed since the last save marked; the
    /// current one moved, copied or deleted.
    pub(super) fn steps(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        let (Some(doc), Some(player)) = (&mut self.doc, &session.lesson) else {
            return;
        };
        let current = player.step;
        let n = doc.draft.len();
        ui.label(RichText::new(lang.tr("Steps", "步骤")).strong())
            .on_hover_text(lang.tr("● changed since the last save", "● 自上次保存以来有改动"));
        // Read from the file's text once a change or a save, not every frame.
        let revision = doc.draft.revision();
        if self.marks.as_ref().is_none_or(|(r, _)| *r != revision) {
            self.marks = Some((revision, doc.draft.changed_steps()));
        }
        let changed = self.marks.as_ref().map_or(&[][..], |(_, m)| m.as_slice());
        egui::ScrollArea::vertical()
            .id_salt("lesson-editor-steps")
            .max_height(180.0)
            .show(ui, |ui| {
                for (k, step) in player.lesson.steps.iter().enumerate().take(n) {
                    let mark = if changed.get(k) == Some(&true) {
                        "●"
                    } else {
                        "  "
                    };
                    let label = format!("{mark} {:>2}  {}", k + 1, step.title.get(lang));
                    if ui.selectable_label(k == current, label).clicked() && k != current {
                        out.push(Command::Lesson(LessonCommand::GoToStep(k)));
                    }
                }
            });
        if doc.draft.deleted() > 0 {
            ui.label(
                RichText::new(match lang {
                    Lang::En => format!(
                        "{} step(s) deleted since the last save",
                        doc.draft.deleted()
                    ),
                    Lang::Zh => format!("自上次保存以来删除了 {} 步", doc.draft.deleted()),
                })
                .weak(),
            );
        }
        let mut moved = None;
        let mut result = None;
        ui.horizontal_wrapped(|ui| {
            ui.label(match lang {
                Lang::En => format!("Step {}:", current + 1),
                Lang::Zh => format!("第 {} 步：", current + 1),
            });
            if ui
                .add_enabled(
                    current > 0,
                    egui::Button::new(lang.tr("▲ Earlier", "▲ 前移")),
                )
                .clicked()
            {
                result = Some(doc.draft.move_step(current, current - 1));
                moved = Some(current - 1);
            }
            if ui
                .add_enabled(
                    current + 1 < n,
                    egui::Button::new(lang.tr("▼ Later", "▼ 后移")),
                )
                .clicked()
            {
                result = Some(doc.draft.move_step(current, current + 1));
                moved = Some(current + 1);
            }
            if ui.button(lang.tr("Duplicate", "复制")).clicked() {
                result = Some(doc.draft.duplicate(current));
                moved = Some(current + 1);
            }
            if ui
                .add_enabled(n > 1, egui::Button::new(lang.tr("Delete", "删除")))
                .clicked()
            {
                result = Some(doc.draft.delete(current));
                moved = Some(current.min(n.saturating_sub(2)));
            }
        });
        match result {
            Some(Ok(())) => {
                self.said = None;
                self.revised(session, moved, true, out);
            }
            Some(Err(e)) => self.said = Some(Err(e)),
            None => {}
        }
    }
}

/// A message: done in green, refused or failed in the error colour.
fn said(ui: &mut egui::Ui, message: &Result<String, String>) {
    match message {
        Ok(m) => ui.label(RichText::new(m).color(egui::Color32::LIGHT_GREEN)),
        Err(e) => ui.label(
            RichText::new(e)
                .color(ui.visuals().error_fg_color)
                .monospace(),
        ),
    };
}
