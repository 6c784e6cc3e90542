//! An exercise step in the session (no egui here): the student's shaders and inside test draw
//! the step's picture, pipelens' own stages draw the reference in the same render job, and the two frames
//! are compared pixel by pixel. A frame that matches everywhere passes the exercise, which the
//! progress remembers with the code that passed; the code the student last ran is kept too and
//! comes back when the step is entered again.

use std::sync::Arc;

use pipeline::buffers::Capture;
use pipeline::capture::FrameCapture;
use pipeline::scene::{ObjectShader, Scene};
use pipeline::settings::RenderSettings;
use pipeline::shader::HookKind;

use super::reference::Comparison;
use super::state::Session;
use crate::app::progress::SavedCode;
use crate::lab::Findings;
use crate::lesson::SceneSpec;
use crate::lesson::answer::Exercise;

impl Session {
    /// The current step's exercise, if it is one.
    #[must_use]
    pub fn current_exercise(&self) -> Option<&Exercise> {
        let p = self.lesson.as_ref()?;
        p.current().exercise.as_ref()
    }

    /// The reference the render job draws beside the student's frame: the scene without the
    /// student's code (pipelens' own stages, as its shipped GLSL where there is one), at the same settings, keeping the colour and the inspected
    /// pixel's record (its derivation is shown beside the student's trace). None for a draft.
    pub(super) fn exercise_reference(&self, spec: &SceneSpec) -> Option<(Scene, RenderSettings)> {
        self.current_exercise()?;
        if self.drafting {
            return None;
        }
        let scene = crate::lab::reference_scene(&spec.scene, &spec.settings);
        let settings = RenderSettings {
            // The buffer the student's frame is shown in, so that the reference beside it is
            // shown in it too.
            capture: Capture::showing([self.selection.buffer]).with_pixel(self.selection.pixel),
            ..spec.settings
        };
        Some((scene, settings))
    }

    /// Whether the exercise's reference does not keep the buffer now shown (it is shown in the
    /// student's buffer beside the student's frame): it is rendered again, but not for a draft,
    /// which renders no reference.
    pub(super) fn reference_stale(&self) -> bool {
        !self.drafting
            && self.exercise.reference.as_ref().is_some_and(|r| {
                !r.settings
                    .capture
                    .covers(Capture::showing([self.selection.buffer]))
            })
    }

    /// Takes a render's reference (none for a draft: the last one stays), compares the frame on
    /// screen with it, and keeps the student's code — as passed when every pixel matches. A
    /// render drawn for the step before (`this_step` false: it arrives after the step changed)
    /// is judged by nothing: its frame and reference are the other step's, and a verdict from
    /// them could pass this step's lab.
    pub(super) fn receive_reference(
        &mut self,
        reference: Option<Arc<FrameCapture>>,
        this_step: bool,
    ) {
        let Some(exercise) = self.current_exercise().cloned() else {
            self.exercise = Comparison::default();
            return;
        };
        if !this_step {
            self.exercise.findings = Findings::default();
            return;
        }
        if reference.is_some() {
            self.exercise.reference = reference;
        }
        // Found once per frame received, not at every repaint of the card.
        self.exercise.findings = match (&self.capture, &self.exercise.reference) {
            (Some(c), Some(r)) if !self.shown_draft => Findings::between(
                &self.spec.scene,
                (c, r),
                exercise.tolerance,
                crate::lab::Rules::of(&exercise),
            ),
            _ => Findings::default(),
        };
        let (Some(player), Some(code)) = (&self.lesson, self.student_code()) else {
            return;
        };
        let passed = self.exercise.passed();
        self.progress
            .keep_code(&player.lesson, player.step, code, passed);
    }

    /// The sources the scene's objects run: the student's code on an exercise step.
    fn student_code(&self) -> Option<SavedCode> {
        let objects = &self.spec.scene.objects;
        let code = SavedCode {
            shaders: objects
                .iter()
                .find_map(|o| o.code.shader.as_ref())
                .map(|sh| {
                    (
                        sh.programs.vertex.source.clone(),
                        sh.programs.fragment.source.clone(),
                    )
                }),
            hooks: HookKind::ALL
                .into_iter()
                .filter_map(|kind| Some((kind, self.spec.scene.hook(kind)?.source.clone())))
                .collect(),
        };
        (code != SavedCode::default()).then_some(code)
    }

    /// On entering an exercise step: the code the student last ran there, in place of the
    /// starter, when it still compiles.
    pub(super) fn restore_code(&mut self, spec: &mut SceneSpec) {
        self.exercise = Comparison::default();
        let Some(player) = &self.lesson else {
            return;
        };
        if player.current().exercise.is_none() {
            return;
        }
        let Some(code) = self.progress.code(&player.lesson, player.step) else {
            return;
        };
        if let Some((vertex, fragment)) = &code.shaders
            && let Ok(programs) = pipeline::shader::link(Some(vertex), Some(fragment))
        {
            spec.scene.set_shaders(&ObjectShader {
                programs: Arc::new(programs),
                time: 0.0,
            });
        }
        for (kind, source) in &code.hooks {
            if let Ok(hook) = pipeline::shader::compile_hook(*kind, source) {
                spec.scene.set_hook(&hook);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::command::LessonCommand;
    use crate::app::session::Command;

    /// Lesson 10's light casters lab, entered from the specular lab while that lab's frame is
    /// still being drawn: that frame, when it arrives, is the other lab's (its scene, its
    /// reference), and this lab is judged by nothing until its own frame comes — before, the
    /// card showed the specular lab's "Not yet: 162116 of 172800" under the light casters.
    #[test]
    fn a_frame_drawn_for_the_step_before_is_not_judged_by_this_one() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/10-blinn-phong.toml");
        let doc = crate::lesson::load_file(&path).expect("lesson 10 loads");
        let mut s = Session::with_document(doc, "test", None);
        let lab = s
            .lesson
            .as_ref()
            .and_then(|p| {
                p.lesson
                    .steps
                    .iter()
                    .position(|st| st.title.en.starts_with("Lab: the specular"))
            })
            .expect("the specular lab");
        s.apply(Command::Lesson(LessonCommand::GoToStep(lab)));
        // The job the worker would be running as the student presses →.
        let before = s
            .job()
            .run(&mut crate::app::worker::RecycledCaptures::default())
            .result
            .expect("the specular lab renders");
        s.apply(Command::Lesson(LessonCommand::GoToStep(lab + 1)));
        let own = s
            .exercise
            .reference
            .clone()
            .expect("the light casters' reference");
        let verdict = |s: &Session| s.exercise.findings.difference.as_ref().map(|d| d.passed());
        assert_eq!(
            verdict(&s),
            Some(false),
            "the light casters' own starter is not yet right"
        );
        // The late frame: shown (as `receive` shows any newer frame), not judged.
        s.capture = Some(before.capture.clone());
        s.receive_reference(before.reference.clone(), false);
        assert_eq!(
            verdict(&s),
            None,
            "the specular lab's frame judged the light casters"
        );
        let kept = s.exercise.reference.as_ref().expect("a reference");
        assert!(
            Arc::ptr_eq(kept, &own),
            "the specular lab's reference was kept as this one's"
        );
        // Its own frame is judged again.
        let now = s
            .job()
            .run(&mut crate::app::worker::RecycledCaptures::default())
            .result
            .expect("the light casters lab renders");
        s.capture = Some(now.capture);
        s.receive_reference(now.reference, true);
        assert_eq!(verdict(&s), Some(false));
    }
}
