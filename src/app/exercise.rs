//! An exercise step in the session (no egui here): the student's shaders and inside test draw
//! the step's picture, pipelens' own stages draw the reference in the same render job, and the two frames
//! are compared pixel by pixel. A frame that matches everywhere passes the exercise, which the
//! progress remembers with the code that passed; the code the student last ran is kept too and
//! comes back when the step is entered again.

use std::sync::Arc;

use pipeline::buffers::Capture;
use pipeline::capture::{Difference, FrameCapture};
use pipeline::scene::{ObjectShader, Scene};
use pipeline::settings::RenderSettings;
use pipeline::shader::{CurveDifference, HookKind};

use super::progress::SavedCode;
use super::session::Session;
use crate::lesson::SceneSpec;
use crate::lesson::answer::Exercise;

/// The reference of an exercise step and how the frame on screen compares with it.
#[derive(Clone, Debug, Default)]
pub struct Comparison {
    /// pipelens' own frame of the step's scene (kept through drafts).
    pub reference: Option<Arc<FrameCapture>>,
    /// The frame on screen against the reference (`None` while either is missing or the frame
    /// on screen is a draft).
    pub difference: Option<Difference>,
    /// The student's curve against pipelens' own, point by point, when the step's scene runs
    /// the student's de Casteljau: what decides the exercise then.
    pub curve: Option<CurveDifference>,
}

/// How far (in the curve's units) a student's curve point may be from pipelens' `b(t)` and
/// still match: far below a pixel of the lesson's view (3 units across 720 pixels), far above
/// the rounding of a correct construction in `f32`.
pub const CURVE_TOLERANCE: f32 = 1e-4;

impl Comparison {
    /// Whether the exercise passed: every curve point within the tolerance where a curve is
    /// compared, else every pixel.
    #[must_use]
    pub fn passed(&self) -> bool {
        match &self.curve {
            Some(c) => c.passed(),
            None => self.difference.as_ref().is_some_and(Difference::passed),
        }
    }
}

impl Session {
    /// The current step's exercise, if it is one.
    #[must_use]
    pub fn current_exercise(&self) -> Option<&Exercise> {
        let p = self.lesson.as_ref()?;
        p.current().exercise.as_ref()
    }

    /// The reference the render job draws beside the student's frame: the scene without shaders
    /// (pipelens' own stages), at the same settings, keeping the colour and the inspected
    /// pixel's record (its derivation is shown beside the student's trace). None for a draft.
    pub(super) fn exercise_reference(&self, spec: &SceneSpec) -> Option<(Scene, RenderSettings)> {
        self.current_exercise()?;
        if self.drafting {
            return None;
        }
        let mut scene = spec.scene.clone();
        for o in &mut scene.objects {
            o.shader = None;
            o.inside = None;
            o.depth_test = None;
            o.curve = None;
        }
        let settings = RenderSettings {
            capture: Capture::COLOR.with_pixel(self.selection.pixel),
            ..spec.settings
        };
        Some((scene, settings))
    }

    /// Takes a render's reference (none for a draft: the last one stays), compares the frame on
    /// screen with it, and keeps the student's code — as passed when every pixel matches.
    pub(super) fn receive_reference(&mut self, reference: Option<Arc<FrameCapture>>) {
        let Some(exercise) = self.current_exercise().cloned() else {
            self.exercise = Comparison::default();
            return;
        };
        if reference.is_some() {
            self.exercise.reference = reference;
        }
        self.exercise.difference = match (&self.capture, &self.exercise.reference) {
            (Some(c), Some(r)) if !self.shown_draft => c.difference(r, exercise.tolerance),
            _ => None,
        };
        self.exercise.curve = self.curve_difference();
        let (Some(player), Some(code)) = (&self.lesson, self.student_code()) else {
            return;
        };
        let passed = self.exercise.passed();
        self.progress
            .keep_code(&player.lesson, player.step, code, passed);
    }

    /// The student's de Casteljau against pipelens' curve, when an object runs one on a Bézier
    /// curve (`None` also when it stops with a run-time error, which the status line shows).
    fn curve_difference(&self) -> Option<CurveDifference> {
        self.spec.scene.objects.iter().find_map(|o| {
            let hook = o.curve.as_ref()?;
            let Some(pipeline::mesh::BuiltinMesh::Bezier { points, .. }) = o.builtin else {
                return None;
            };
            hook.curve_difference(points, CURVE_TOLERANCE).ok()
        })
    }

    /// The sources the scene's objects run: the student's code on an exercise step.
    fn student_code(&self) -> Option<SavedCode> {
        let objects = &self.spec.scene.objects;
        let code = SavedCode {
            shaders: objects.iter().find_map(|o| o.shader.as_ref()).map(|sh| {
                (
                    sh.programs.vertex.source.clone(),
                    sh.programs.fragment.source.clone(),
                )
            }),
            inside: objects
                .iter()
                .find_map(|o| o.inside.as_ref())
                .map(|i| i.source.clone()),
            depth_test: objects
                .iter()
                .find_map(|o| o.depth_test.as_ref())
                .map(|t| t.source.clone()),
            curve: objects
                .iter()
                .find_map(|o| o.curve.as_ref())
                .map(|c| c.source.clone()),
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
        for (kind, source) in [
            (HookKind::Inside, &code.inside),
            (HookKind::DepthTest, &code.depth_test),
            (HookKind::Curve, &code.curve),
        ] {
            if let Some(Ok(hook)) = source
                .as_deref()
                .map(|s| pipeline::shader::compile_hook(kind, s))
            {
                spec.scene.set_hook(&hook);
            }
        }
    }
}
