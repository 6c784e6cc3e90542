//! The commands panels return, applied to the session once per frame: each kind in one
//! function, every command of the kind in its match (no catch-all), so a new command is applied
//! where its kind is, or does not compile.

use std::sync::Arc;

use super::state::Session;
use crate::app::command::{
    Command, EditorCommand, LessonCommand, SceneCommand, SelectionCommand, ViewCommand,
};
use crate::app::player::LessonPlayer;
use crate::vocabulary::Comparison;

impl Session {
    /// Applies one command.
    pub fn apply(&mut self, cmd: Command) {
        match cmd {
            Command::Lesson(c) => self.apply_lesson(c),
            Command::Editor(c) => self.apply_editor(c),
            Command::Scene(c) => self.apply_scene(c),
            Command::View(c) => self.apply_view(c),
            Command::Selection(c) => self.apply_selection(c),
        }
    }

    /// The lesson being played: its steps, its animations, the typed answers.
    fn apply_lesson(&mut self, cmd: LessonCommand) {
        match cmd {
            LessonCommand::GoToStep(k) => self.enter_step(k),
            LessonCommand::NextStep => {
                let k = self.lesson.as_ref().map_or(0, |p| p.step + 1);
                self.enter_step(k);
            }
            LessonCommand::PreviousStep => {
                let k = self.lesson.as_ref().map_or(0, |p| p.step.saturating_sub(1));
                self.enter_step(k);
            }
            LessonCommand::TogglePlay => {
                if let Some(p) = &mut self.lesson {
                    if !p.playing && p.current().animate.iter().all(|a| a.finished(p.time)) {
                        p.time = 0.0;
                    }
                    p.playing = !p.playing && !p.current().animate.is_empty();
                }
            }
            LessonCommand::Tick(dt) => self.tick(dt),
            LessonCommand::ShowAnswer(b) => {
                if let Some(p) = &mut self.lesson {
                    p.show_answer = b;
                }
            }
            LessonCommand::TypeAnswer { cell, text } => {
                if let Some(p) = &mut self.lesson
                    && let Some(e) = &p.current().expect
                {
                    let at = (p.step, cell, e.shape.cells());
                    self.progress.type_cell(&p.lesson, at, text);
                    p.verdict = None;
                }
            }
            LessonCommand::CheckAnswer => {
                if let Some(p) = &mut self.lesson {
                    p.verdict = self.progress.check(&p.lesson, p.step);
                }
            }
        }
    }

    /// The lesson file, reloaded from disk or revised in the editor.
    fn apply_editor(&mut self, cmd: EditorCommand) {
        match cmd {
            EditorCommand::ReloadLesson(lesson) => {
                let step = self.lesson.as_ref().map_or(0, |p| p.step);
                self.revise(*lesson, step, true);
            }
            EditorCommand::ReviseLesson {
                lesson,
                step,
                enter,
            } => self.revise(*lesson, step, enter),
            EditorCommand::SetReloadError(e) => self.reload_error = e,
        }
    }

    /// `lesson` in place of the one playing, at its step `step`: entered (its scene, view and
    /// selection as the step sets them) or, for a change of words only, kept as it is on screen.
    /// A change of words keeps the player where it was on that step — its animations' time,
    /// playing or not, the answer shown — for the screen is what that time drew: a step
    /// recorded next counts its changes from there.
    fn revise(&mut self, lesson: crate::lesson::Lesson, step: usize, enter: bool) {
        self.reload_error = None;
        let step = step.min(lesson.steps.len().saturating_sub(1));
        let mut player = LessonPlayer::new(Arc::new(lesson), step);
        if let Some(was) = self.lesson.as_ref().filter(|p| !enter && p.step == step) {
            player.time = was.time;
            player.playing = was.playing;
            player.show_answer = was.show_answer;
            player.verdict.clone_from(&was.verdict);
        }
        self.lesson = Some(player);
        if enter {
            self.enter_step(step);
        }
    }

    /// The scene and settings drawn: a new frame is asked for when they changed.
    fn apply_scene(&mut self, cmd: SceneCommand) {
        match cmd {
            SceneCommand::SetSpec(spec) => {
                if *spec != self.spec {
                    self.spec = *spec;
                    self.request_render();
                }
            }
        }
    }

    /// How the frame is shown.
    fn apply_view(&mut self, cmd: ViewCommand) {
        let stage = self.selection.stage;
        let sel = &mut self.selection;
        match cmd {
            ViewCommand::SelectStage(s) => self.go_to(s),
            ViewCommand::NextStage => self.go_to(stage.next()),
            ViewCommand::PreviousStage => self.go_to(stage.previous()),
            ViewCommand::PlayTransition => sel.transition = 0.0,
            ViewCommand::SelectBuffer(b) => sel.buffer = b,
            ViewCommand::ToggleOverlay(o) => {
                if let Some(i) = sel.overlays.iter().position(|x| *x == o) {
                    sel.overlays.remove(i);
                } else {
                    sel.overlays.push(o);
                }
            }
            ViewCommand::ToggleSamples => sel.show_samples = !sel.show_samples,
            ViewCommand::ToggleNormals => sel.show_normals = !sel.show_normals,
            ViewCommand::ToggleObserver => sel.show_observer = !sel.show_observer,
            ViewCommand::SetDepthView(d) => sel.depth_view = d,
            ViewCommand::SetComparison(c) => {
                if sel.comparison != c {
                    sel.comparison = c;
                    // The Mach band comparison is read along a line; the others on request.
                    if sel.profile.is_none() && c == Some(Comparison::Shading) {
                        let (w, h) = (self.spec.settings.width, self.spec.settings.height);
                        sel.profile = Some(crate::lesson::script::middle_row(w, h));
                    }
                    self.request_render();
                }
            }
            ViewCommand::SetLang(l) => self.lang = l,
            ViewCommand::SetTouch(t) => self.touch = t,
            ViewCommand::SetOrbit(o) => {
                if o != self.orbit {
                    self.orbit = o;
                    self.orbit_framed = false;
                    self.request_render();
                }
            }
            ViewCommand::SetObserverAspect(a) => {
                let changed = self
                    .observer_aspect
                    .is_none_or(|old| (old / a - 1.0).abs() > 0.05);
                if changed {
                    self.observer_aspect = Some(a);
                    if self.orbit_framed {
                        // The step's framing was for the old shape (the lesson image's on
                        // the first frame): a tall panel would show the subject small.
                        self.orbit = self.observer_framing(&self.spec, &self.animation_poses());
                    }
                    if self.observer_shown() {
                        self.request_render();
                    }
                }
            }
            ViewCommand::SetViewPixels(p) => self.view_pixels = Some(p),
        }
    }

    /// What is picked in the picture.
    fn apply_selection(&mut self, cmd: SelectionCommand) {
        let sel = &mut self.selection;
        match cmd {
            SelectionCommand::SelectVertex(v) => sel.vertex = v,
            SelectionCommand::SelectPixel(p) => sel.pixel = p,
            SelectionCommand::SetProfile(p) => sel.profile = p,
            SelectionCommand::SetCost(on) => sel.cost = on,
            SelectionCommand::SetWatch(w) => {
                sel.watch = w;
                // A new watch (or none): why the last one was dropped no longer stands.
                self.watch_error = None;
            }
        }
    }
}
