//! Lessons: a scene and the steps a teacher walks through, each with its narration in Chinese
//! and English, the stage and layout to show, parameter changes and animations, overlays, a
//! highlighted pixel or vertex, and a question for self-study.

mod animation;
mod student;

use std::path::Path;

use pipeline::buffers::BufferKind;
use toml::Spanned;

use super::param::{self, Animation, Value};
use super::raw::{RawLessonFile, RawStep, RawValue};
use super::validate::Checker;
use super::{Diagnostics, SceneSpec};
use crate::vocabulary::{Comparison, Lang, Stage, Text};

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
    /// The depth buffer's grey ramp `[black, white]` in window depth (`None`: the nearest and
    /// farthest depth present).
    pub depth_range: Option<[f32; 2]>,
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

/// Whether TOML text is a lesson (it has a `[lesson]` table) rather than a bare scene.
#[must_use]
pub fn is_lesson(text: &str) -> bool {
    text.parse::<toml::Table>()
        .is_ok_and(|t| t.contains_key("lesson"))
}

/// Parses and validates lesson text. `file` names it in messages; `base` resolves paths.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_lesson(text: &str, file: &str, base: &Path) -> Result<Lesson, Diagnostics> {
    let raw: RawLessonFile = super::parse_toml(text, file)?;
    let scene = super::validate::scene(&raw.scene, text, file, base);
    let mut c = Checker::new(text, file);
    let meta = raw.lesson.get_ref();
    let id = meta.id.get_ref().trim().to_owned();
    if id.is_empty() {
        c.error(meta.id.span(), "`id` must not be empty");
    }
    let mut warnings = Vec::new();
    let stem = Path::new(file).file_stem().and_then(|s| s.to_str());
    if let Some(stem) = stem.filter(|s| !id.is_empty() && *s != id) {
        warnings.push(
            super::Diagnostic::at(
                file,
                text,
                meta.id.span(),
                format!(
                    "the id \"{id}\" differs from the file's name \"{stem}\": prerequisites name \
                     lessons by id and a reader looks for the file of that name, so keep the two the same"
                ),
            )
            .warning(),
        );
    }
    let title = c.text_of("title", &meta.title);
    let summary = c.text_of("summary", &meta.summary);
    let prerequisites = meta
        .prerequisites
        .iter()
        .map(|p| p.get_ref().clone())
        .collect();
    if raw.steps.is_empty() {
        c.error(
            raw.lesson.span(),
            "the lesson has no steps: add at least one [[steps]] with a `title` and `narration`",
        );
    }
    let mut steps = Vec::new();
    if let Ok(base_spec) = &scene {
        let mut spec = base_spec.clone();
        for s in &raw.steps {
            steps.push(c.step(s, &mut spec, base));
        }
    }
    let mut found = c.found;
    let scene = match scene {
        Ok(s) => s,
        Err(Diagnostics(mut d)) => {
            d.extend(found);
            return Err(Diagnostics(d));
        }
    };
    if !found.is_empty() {
        found.sort_by_key(|d| (d.line, d.column));
        return Err(Diagnostics(found));
    }
    Ok(Lesson {
        warnings,
        comments: raw.comments.zh,
        id,
        title,
        summary,
        prerequisites,
        scene,
        steps,
    })
}

type Views = (
    Option<Stage>,
    Layout,
    Option<Comparison>,
    Option<BufferKind>,
    Option<Vec<Overlay>>,
);
type Targets = (Option<(u32, u32)>, Option<u32>, Option<[f32; 4]>);

/// The lesson's own checks, on the scene's checker: the steps are checked against the scene as
/// the steps before them left it.
impl Checker<'_> {
    fn value(&mut self, v: &Spanned<RawValue>) -> Option<Value> {
        Some(match v.get_ref() {
            RawValue::Bool(b) => Value::Bool(*b),
            RawValue::Number(x) if x.is_finite() && x.abs() <= 1e15 => Value::Number(*x as f32),
            RawValue::Vec3(a) if a.iter().all(|x| x.is_finite() && x.abs() <= 1e15) => {
                Value::Vec3(glam::Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32))
            }
            RawValue::Name(n) => Value::Name(n.clone()),
            _ => {
                self.error(
                    v.span(),
                    "expected finite numbers of magnitude at most 1e15",
                );
                return None;
            }
        })
    }

    fn step(&mut self, s: &Spanned<RawStep>, spec: &mut SceneSpec, base: &Path) -> Step {
        let r = s.get_ref();
        let title = self.text_of("title", &r.title);
        let narration = self.text_of("narration", &r.narration);
        let question = r.question.as_ref().map(|q| self.text_of("question", q));
        let answer = r.answer.as_ref().map(|a| self.text_of("answer", a));
        let expect = self.expect(r);
        let exercise = r.exercise.as_ref().and_then(|e| self.exercise(e, base));
        let (stage, layout, compare, buffer, overlays) = self.views(s);
        let mut set = Vec::new();
        // In the order written (a `projection.kind` before the keys of that kind).
        let mut written: Vec<_> = r.set.iter().collect();
        written.sort_by_key(|(name, _)| name.span().start);
        for (name, v) in written {
            let Some(value) = self.value(v) else { continue };
            match param::apply(spec, name.get_ref(), &value) {
                Ok(()) => set.push((name.get_ref().clone(), value)),
                Err(e) => self.error(name.span(), e),
            }
        }
        let shader = r
            .shader
            .as_ref()
            .and_then(|sh| super::validate::shaders::shader(self, sh, base));
        if let Some(code) = &shader {
            spec.scene.run_code(code);
        }
        let animate = r
            .animate
            .iter()
            .filter_map(|a| self.animation(a, spec))
            .collect();
        let (pixel, vertex, profile) = self.targets(r, spec);
        let focus = r.focus.as_ref().map(|names| self.focus(names, spec));
        let depth_range = r.depth_range.as_ref().and_then(|d| {
            let [a, b] = *d.get_ref();
            if (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) && a < b {
                Some([a as f32, b as f32])
            } else {
                self.error(
                    d.span(),
                    format!("`depth_range` = [black, white] must be window depths with 0 ≤ black < white ≤ 1, got [{a}, {b}]"),
                );
                None
            }
        });
        Step {
            title,
            narration,
            stage,
            layout,
            compare,
            buffer,
            overlays,
            set,
            animate,
            pixel,
            vertex,
            profile,
            focus,
            depth_range,
            shader,
            question,
            expect,
            answer,
            exercise,
        }
    }

    /// What a step shows: stage, layout, compared settings, buffer, overlays.
    fn views(&mut self, s: &Spanned<RawStep>) -> Views {
        let r = s.get_ref();
        let stages: Vec<(String, Stage)> = Stage::ALL
            .into_iter()
            .map(|st| (st.name(Lang::En).to_lowercase(), st))
            .collect();
        let stage_options: Vec<(&str, Stage)> =
            stages.iter().map(|(n, st)| (n.as_str(), *st)).collect();
        let stage = r
            .stage
            .as_ref()
            .and_then(|v| self.choice("stage", v, &stage_options));
        let compare_options: Vec<(&str, Comparison)> =
            Comparison::ALL.into_iter().map(|c| (c.key(), c)).collect();
        let compare = r
            .compare
            .as_ref()
            .and_then(|v| self.choice("compare", v, &compare_options));
        let layout = match &r.layout {
            Some(v) => self.choice("layout", v, &LAYOUTS).unwrap_or(Layout::Single),
            None if compare.is_some() => Layout::Compare,
            None => Layout::Single,
        };
        if let (Some(c), Some(l)) = (&r.compare, &r.layout)
            && layout != Layout::Compare
        {
            self.error(
                l.span(),
                format!(
                    "`compare = \"{}\"` shows settings side by side, which needs `layout = \"compare\"` (or no `layout`)",
                    c.get_ref()
                ),
            );
        }
        if layout == Layout::Compare && compare.is_none() {
            let span = r.layout.as_ref().map_or(s.span(), Spanned::span);
            self.error(
                span,
                "`layout = \"compare\"` needs `compare = \"shading\" | \"interpolation\" | \"samples\" | \"filtering\"`",
            );
        }
        let buffer_options: Vec<(&str, BufferKind)> =
            BufferKind::ALL.into_iter().map(|b| (b.name(), b)).collect();
        let buffer = r
            .buffer
            .as_ref()
            .and_then(|v| self.choice("buffer", v, &buffer_options));
        let overlays = r.overlays.as_ref().map(|list| {
            list.iter()
                .filter_map(|o| self.choice("overlays", o, &OVERLAYS))
                .collect()
        });
        (stage, layout, compare, buffer, overlays)
    }

    /// What a step points at: a pixel, a vertex-table row, a profile line, each inside the
    /// scene as the step leaves it.
    fn targets(&mut self, r: &RawStep, spec: &SceneSpec) -> Targets {
        let pixel = r.pixel.as_ref().and_then(|p| {
            let [x, y] = *p.get_ref();
            let (w, h) = (spec.settings.width, spec.settings.height);
            match (u32::try_from(x), u32::try_from(y)) {
                (Ok(x), Ok(y)) if x < w && y < h => Some((x, y)),
                _ => {
                    self.error(
                        p.span(),
                        format!("`pixel` must be inside the {w}×{h} viewport: 0 ≤ x < {w}, 0 ≤ y < {h} (y up), got [{x}, {y}]"),
                    );
                    None
                }
            }
        });
        let vertex = r.vertex.as_ref().and_then(|v| {
            let rows: usize = spec
                .scene
                .drawn_objects()
                .0
                .iter()
                .map(|o| o.mesh.positions.len())
                .sum();
            match usize::try_from(*v.get_ref()) {
                Ok(n) if n < rows => Some(n as u32),
                _ => {
                    self.error(
                        v.span(),
                        format!(
                            "`vertex` must be a row of the vertex table, 0 to {}, got {}",
                            rows.saturating_sub(1),
                            v.get_ref()
                        ),
                    );
                    None
                }
            }
        });
        let profile = r.profile.as_ref().and_then(|p| {
            let [a, b, c, d] = *p.get_ref();
            let (w, h) = (
                f64::from(spec.settings.width),
                f64::from(spec.settings.height),
            );
            if [a, c].iter().all(|x| (0.0..w).contains(x))
                && [b, d].iter().all(|y| (0.0..h).contains(y))
            {
                Some([a as f32, b as f32, c as f32, d as f32])
            } else {
                self.error(
                    p.span(),
                    format!(
                        "`profile` = [x0, y0, x1, y1] must lie inside the {w}×{h} image (y down)"
                    ),
                );
                None
            }
        });
        (pixel, vertex, profile)
    }

    /// The names a step frames: each an object or a figure of the scene as the step leaves it.
    fn focus(&mut self, names: &[Spanned<String>], spec: &SceneSpec) -> Vec<String> {
        let known: Vec<&str> = spec
            .scene
            .objects
            .iter()
            .map(|o| o.name.as_str())
            .chain(spec.scene.figures.iter().map(|f| f.name.as_str()))
            .collect();
        names
            .iter()
            .filter_map(|n| {
                let name = n.get_ref();
                if known.contains(&name.as_str()) {
                    return Some(name.clone());
                }
                let hint = pipeline::shader::suggest::did_you_mean(
                    name,
                    known.iter().copied(),
                    pipeline::shader::suggest::Quote::Value,
                );
                self.error(
                    n.span(),
                    format!(
                        "`focus` names objects or figures of the scene ({}), got \"{name}\"{hint}",
                        known
                            .iter()
                            .map(|k| format!("\"{k}\""))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                );
                None
            })
            .collect()
    }
}
