//! The lesson editor's panel, docked at the window's right: the steps listed (those changed
//! since the last save marked), moved, copied and deleted; the file's row, undo, redo and save (`file_actions.rs`); the
//! current step's words and what is on screen recorded (`words.rs`, `screen.rs`), a new lesson
//! (`new.rs`), the file (`file.rs`).

use egui::RichText;

use super::file::Edited;
use super::new::{Made, NewLesson};
use crate::app::command::LessonCommand;

use crate::app::layout::Room;
use crate::app::session::{Command, Session};
use crate::lesson::SceneSpec;
use crate::lesson::param::{self, Animation, Easing, Repeat, Value};
use crate::vocabulary::{Lang, Text};

/// The editor's state.
#[derive(Default)]
pub struct Editor {
    /// Whether the panel is shown.
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
    /// Sliders dragged while the panel was open: the new step's animations.
    pub(super) drags: Vec<Animation>,
    /// The steps changed since the last save, and the draft's revision they were read at.
    pub(super) marks: Option<(u64, Vec<bool>)>,
    /// What the last action said.
    pub(super) said: Option<Result<String, String>>,
    /// The last refusal of the buttons under "what is on screen" (add or update a step): while
    /// it is what the editor last said, it is said there, beside them, and scrolled to once
    /// (`true` until it is).
    pub(super) refused_on_screen: Option<(String, bool)>,
    /// The "New lesson" part.
    pub new: NewLesson,
    /// A lesson just made, for the app to open (and then [`Self::adopt`]).
    pub made: Option<Made>,
    /// Why the last new lesson was not made.
    pub(super) new_error: Option<String>,
}

impl Editor {
    /// Follows what the session has open: a lesson other than the one edited is taken up (its
    /// file read, its recovery copy looked for; the panel opens to offer one). `file` is the
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
        match Edited::open(&session.source, file, None, &session.given, session.lang) {
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
    pub fn adopt(
        &mut self,
        source: &str,
        file: Option<&std::path::Path>,
        text: String,
        given: &crate::lesson::Given,
        lang: Lang,
    ) {
        self.words_for = None;
        self.marks = None;
        match Edited::open(source, file, Some(text), given, lang) {
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
            if !matches!(
                end,
                Value::Number(_) | Value::Vec2(_) | Value::Vec3(_) | Value::Vec4(_)
            ) {
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

    /// The editor, when open, docked at the window's right edge (the view beside it frames
    /// its subject in what is left, as it does beside the inspector and the code); the
    /// commands it gives the session. `root` is the frame's root: the panel is shown before
    /// the view's; with other panels at the right (`room`), it starts narrower.
    pub fn ui(&mut self, root: &mut egui::Ui, session: &Session, room: Room) -> Vec<Command> {
        let mut out = Vec::new();
        if let Some(doc) = &mut self.doc {
            doc.keep_recovery();
        }
        if !self.open {
            return out;
        }
        let lang = session.lang;
        self.shortcuts(root.ctx(), session, &mut out);
        let title = match &self.doc {
            Some(d) => format!(
                "{} — {}{}",
                lang.t("window-lesson-editor"),
                d.draft.name(),
                if d.draft.is_dirty() { " ●" } else { "" }
            ),
            None => lang.t("window-lesson-editor").to_owned(),
        };
        // A quarter of the window, up to 480 points (less beside another panel, 320 beside a
        // lab): the words' boxes and the steps' list fit, and the view keeps the rest.
        let window = root.ctx().content_rect().width();
        let (id, wide) = match room {
            Room::Alone => ("lesson-editor", (window * 0.25).clamp(340.0, 480.0)),
            Room::Beside => ("lesson-editor-beside", (window * 0.22).clamp(320.0, 420.0)),
            Room::Crowded => ("lesson-editor-crowded", 320.0),
        };
        let mut open = true;
        egui::Panel::right(id)
            .default_size(wide)
            .min_size(300.0)
            .resizable(true)
            .show(root, |ui| {
                // A tool for the teacher, not for the room: at the chrome's size in classroom
                // mode too, as the code is.
                crate::app::style::chrome_style(ui);
                ui.horizontal(|ui| {
                    // The close button first, at the right; the title wraps in what it leaves.
                    ui.with_layout(egui::Layout::right_to_left(egui::Align::Min), |ui| {
                        let close = ui
                            .button("×")
                            .on_hover_text(lang.t("window-close-the-editor-r"));
                        if close.clicked() {
                            open = false;
                        }
                        ui.with_layout(egui::Layout::left_to_right(egui::Align::Min), |ui| {
                            ui.add(egui::Label::new(RichText::new(title).strong()).wrap());
                        });
                    });
                });
                ui.separator();
                egui::ScrollArea::vertical()
                    .id_salt("lesson-editor-scroll")
                    .show(ui, |ui| self.contents(ui, session, lang, &mut out));
            });
        crate::app::layout::name_divider(root, id, lang.t("window-lesson-editor"), lang);
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
            // What the last action said, at the top where it is seen (a refusal of the
            // buttons under the screen's part beside them instead).
            let below = |m: &Result<String, String>| matches!((m, &self.refused_on_screen), (Err(e), Some((r, _))) if e == r);
            if let Some(m) = self.said.as_ref().filter(|m| !below(m)) {
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
                ui.label(
                    RichText::new(lang.t("window-a-built-in-lesson-is"))
                        .color(ui.visuals().warn_fg_color),
                );
            } else {
                self.steps(ui, session, lang, out);
                ui.separator();
                self.step_words(ui, session, lang, out);
                ui.separator();
                self.on_screen(ui, session, lang, out);
            }
        } else {
            ui.label(lang.t("window-open-a-lesson-to-edit"));
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
        ui.label(RichText::new(lang.t("window-steps")).strong())
            .on_hover_text(lang.t("window-changed-since-the-last-save"));
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
                RichText::new(
                    lang.t_with("window-steps-deleted", &[("count", &doc.draft.deleted())]),
                )
                .weak(),
            );
        }
        let mut moved = None;
        let mut result = None;
        ui.horizontal_wrapped(|ui| {
            ui.label(lang.t_with("window-step-label", &[("step", &(current + 1))]));
            if ui
                .add_enabled(current > 0, egui::Button::new(lang.t("window-earlier")))
                .clicked()
            {
                result = Some(doc.draft.move_step(current, current - 1));
                moved = Some(current - 1);
            }
            if ui
                .add_enabled(current + 1 < n, egui::Button::new(lang.t("window-later")))
                .clicked()
            {
                result = Some(doc.draft.move_step(current, current + 1));
                moved = Some(current + 1);
            }
            if ui.button(lang.t("window-duplicate")).clicked() {
                result = Some(doc.draft.duplicate(current));
                moved = Some(current + 1);
            }
            if ui
                .add_enabled(n > 1, egui::Button::new(lang.t("window-delete")))
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
pub(super) fn said(ui: &mut egui::Ui, message: &Result<String, String>) -> egui::Response {
    match message {
        Ok(m) => ui.label(RichText::new(m).color(egui::Color32::LIGHT_GREEN)),
        Err(e) => ui.label(
            RichText::new(e)
                .color(ui.visuals().error_fg_color)
                .monospace(),
        ),
    }
}
