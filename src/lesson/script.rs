//! Lessons: a scene and the steps a teacher walks through, each with its narration in Chinese
//! and English, the stage and layout to show, parameter changes and animations, overlays, a
//! highlighted pixel or vertex, and a question for self-study; the scene as each step leaves
//! it. A lesson's text is read and checked in `read.rs`.

mod animation;
mod expect_and_exercise;
mod read;

pub use read::{is_lesson, parse_lesson, parse_lesson_in};

use pipeline::buffers::BufferKind;

use super::SceneSpec;
use super::param::{self, Animation, Value};
use crate::vocabulary::{Comparison, Stage, Text};

/// How a step arranges its views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// The stage alone.
    Single,
    /// The stage beside the observer view (the camera, its frustum and the canonical cube).
    Observer,
    /// Settings side by side (`compare`).
    Compare,
}

/// The layouts' names in a lesson file.
pub const LAYOUTS: [(&str, Layout); 3] = [
    ("single", Layout::Single),
    ("observer", Layout::Observer),
    ("compare", Layout::Compare),
];

/// The overlays' names in a lesson file.
pub const OVERLAYS: [(&str, Overlay); 4] = [
    ("edges", Overlay::Edges),
    ("bounding_boxes", Overlay::BoundingBoxes),
    ("samples", Overlay::Samples),
    ("normals", Overlay::Normals),
];

/// What a step draws over the pixel views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overlay {
    /// Each triangle's edges.
    Edges,
    /// Each triangle's bounding box.
    BoundingBoxes,
    /// Sample positions (zoomed in).
    Samples,
    /// Each vertex's normal as a short line (the world view).
    Normals,
}

/// A panel a step opens (`panels = [...]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepPanel {
    /// The inspector, where a pixel's or a vertex's derivation is read.
    Inspector,
    /// The shader panel, with its source and debugger.
    Shader,
}

impl StepPanel {
    /// The names a lesson file gives them.
    pub const NAMES: [(&str, Self); 2] = [("inspector", Self::Inspector), ("shader", Self::Shader)];
}

/// One step of a lesson.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// Its title.
    pub title: Text,
    /// What the teacher says (simple markdown: paragraphs, `**bold**`, `- ` lists).
    pub narration: Text,
    /// The stage shown.
    pub stage: Option<Stage>,
    /// The arrangement.
    pub layout: Layout,
    /// The settings compared, with `layout = "compare"`.
    pub compare: Option<Comparison>,
    /// The buffer a pixel stage shows.
    pub buffer: Option<BufferKind>,
    /// The overlays (`None`: leave them as they are).
    pub overlays: Option<Vec<Overlay>>,
    /// Parameter changes, kept by the steps after this one.
    pub set: Vec<(String, Value)>,
    /// Parameters moving while the step plays.
    pub animate: Vec<Animation>,
    /// The pixel to inspect (window coordinates, y up).
    pub pixel: Option<(u32, u32)>,
    /// The vertex-table row to highlight.
    pub vertex: Option<u32>,
    /// The profile line `[x0, y0, x1, y1]` (image pixels, y down).
    pub profile: Option<[f32; 4]>,
    /// The objects and figures the geometry views frame (`None`: every object).
    pub focus: Option<Vec<String>>,
    /// The direction the observer looks from, `[yaw, pitch]` in degrees (`orbit = [25, 20]`;
    /// `None`: 60° round and 30° up, [`crate::observer::DEFAULT_DIRECTION`]). Its distance is
    /// always the one that frames the step's subject.
    pub orbit: Option<[f32; 2]>,
    /// The depth buffer's grey ramp `[black, white]` in window depth (`None`: the nearest and
    /// farthest depth present).
    pub depth_range: Option<[f32; 2]>,
    /// The shader expression drawn over the frame, with its shader and the line after which it
    /// is read (`watch = "EXPR@LINE"` for the fragment shader, `"EXPR@vertex:LINE"`; the
    /// debugger's variable picture).
    pub watch: Option<pipeline::shader::probe::WatchSpec>,
    /// The fragment shader's lines the step is about, first and last, from 1
    /// (`shader_lines = [23, 25]`): the shader panel opens on them, scrolled to and marked.
    pub shader_lines: Option<(usize, usize)>,
    /// The panels the step opens (`panels = ["inspector"]`).
    pub panels: Vec<StepPanel>,
    /// The shaders and inside test every object runs from this step on (`None`: as the steps
    /// before left them).
    pub shader: Option<pipeline::scene::StudentCode>,
    /// A question for self-study.
    pub question: Option<Text>,
    /// The value the question asks for, which the student types (`expect = …`).
    pub expect: Option<super::answer::Expect>,
    /// Code the student writes, compared with pipelens' own stage (`exercise = { … }`).
    pub exercise: Option<super::answer::Exercise>,
    /// Its answer.
    pub answer: Option<Text>,
}

impl Step {
    /// Whether the step asks its question before its animation plays ("predict, then watch"):
    /// a step with both a question and an animation starts paused, and Space plays it.
    #[must_use]
    pub fn predicts(&self) -> bool {
        self.question.is_some() && !self.animate.is_empty()
    }

    /// The line whose intensity profile the step plots: its own `profile`, else, comparing
    /// shading frequencies (the Mach bands), the middle row of an image of `width`×`height`.
    #[must_use]
    pub fn profile_line(&self, width: u32, height: u32) -> Option<[f32; 4]> {
        self.profile.or_else(|| {
            (self.compare == Some(Comparison::Shading)).then(|| middle_row(width, height))
        })
    }
}

/// The middle row of an image of `width`×`height`, `[x0, y0, x1, y1]` in image pixels: where
/// the Mach band comparison reads its profile unless told otherwise.
#[must_use]
pub fn middle_row(width: u32, height: u32) -> [f32; 4] {
    let (w, h) = (width as f32, height as f32);
    [0.0, h / 2.0, w - 1.0, h / 2.0]
}

/// A lesson, validated.
#[derive(Clone, Debug, PartialEq)]
pub struct Lesson {
    /// Its id, such as `05-perspective`.
    pub id: String,
    /// Its title.
    pub title: Text,
    /// One or two sentences on what it teaches.
    pub summary: Text,
    /// Ids of the lessons to take first.
    pub prerequisites: Vec<String>,
    /// The scene before the first step.
    pub scene: SceneSpec,
    /// The steps, at least one.
    pub steps: Vec<Step>,
    /// What loads but is probably a mistake (an `id` that differs from the file's name).
    pub warnings: Vec<super::Diagnostic>,
    /// The Chinese of the comments of its GLSL, by their English (`[comments.zh]`).
    pub comments: std::collections::BTreeMap<String, String>,
}

impl Lesson {
    /// The stage step `k` shows: its own `stage`, else that of the last step before it that
    /// named one, else the default stage (the world).
    #[must_use]
    pub fn stage_at(&self, k: usize) -> Stage {
        self.steps
            .iter()
            .take(k + 1)
            .rev()
            .find_map(|s| s.stage)
            .unwrap_or_default()
    }

    /// The buffer step `k` shows on a pixel stage: its own `buffer`, else its stage's default.
    #[must_use]
    pub fn buffer_at(&self, k: usize) -> BufferKind {
        self.steps
            .get(k)
            .and_then(|s| s.buffer)
            .unwrap_or_else(|| self.stage_at(k).default_buffer())
    }

    /// The scene at step `k`: the lesson's scene with the `set`s of steps 0…k applied in order
    /// (each was checked when the lesson was loaded).
    #[must_use]
    pub fn spec_at(&self, k: usize) -> SceneSpec {
        let mut spec = self.scene.clone();
        for step in self.steps.iter().take(k + 1) {
            for (name, value) in &step.set {
                // Checked at load time; a failure here leaves the value as it was.
                let _ = param::apply(&mut spec, name, value);
            }
            if let Some(code) = &step.shader {
                spec.scene.run_code(code);
            }
        }
        // An exercise's starter draws its own step only.
        if let Some(e) = self.steps.get(k).and_then(|s| s.exercise.as_ref()) {
            spec.scene.run_code(&e.starter);
        }
        spec
    }

    /// The scene step `k` starts from: the one the step before it leaves (the lesson's scene
    /// before the first).
    #[must_use]
    pub fn spec_before(&self, k: usize) -> SceneSpec {
        match k.checked_sub(1) {
            Some(before) => self.spec_at(before),
            None => self.scene.clone(),
        }
    }

    /// The scene `t` seconds into step `k`: [`Self::spec_at`] with its animations applied.
    #[must_use]
    pub fn spec_playing(&self, k: usize, t: f32) -> SceneSpec {
        let mut spec = self.spec_at(k);
        if let Some(step) = self.steps.get(k) {
            for a in &step.animate {
                let _ = param::apply(&mut spec, &a.param, &a.value_at(t));
            }
        }
        // Shaders read the time into the step as `uniform float time;`.
        for shader in spec
            .scene
            .objects
            .iter_mut()
            .filter_map(|o| o.code.shader.as_mut())
        {
            shader.time = t;
        }
        spec
    }
}
