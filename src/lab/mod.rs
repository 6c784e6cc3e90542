//! A lab's check, one way for the app and for `pipelens grade`: the student's code draws the
//! step's picture, pipelens' own stages (as their shipped GLSL where there is one) draw the
//! reference at the same settings, and the two frames are compared pixel by pixel — or, where
//! the step runs the student's de Casteljau, the curve point by point. What the comparison
//! finds ([`Findings`]) is worded by [`words`] in the interface's language.
//!
//! The app renders both frames in one job and calls [`Findings::between`] as each frame
//! arrives; [`check`] does the same with no window.

mod findings;
pub mod quantity;
pub mod samples;
pub mod submission;
pub mod words;

pub use findings::{
    CURVE_TOLERANCE, MatrixMismatch, Mismatch, first_difference, first_mismatch,
    first_wrong_vertex, wrong_matrix, wrong_shadow_matrix,
};

use pipeline::buffers::Capture;
use pipeline::capture::{Criteria, Difference, FrameCapture};
use pipeline::scene::Scene;
use pipeline::settings::RenderSettings;
use pipeline::shader::CurveDifference;

use crate::lesson::SceneSpec;
use crate::lesson::answer::{Compare, Exercise};
use crate::lesson::forbid::Shortcut;
use crate::vocabulary::Lang;

/// What a lab's check takes from its exercise besides the tolerance: the names it forbids the
/// student's code to use, the starter (whose own files are not the student's to answer for),
/// and the value it compares with one of pipelens' quantities.
#[derive(Clone, Copy, Debug)]
pub struct Rules<'a> {
    /// The forbidden names (`exercise.forbid`).
    pub forbid: &'a [String],
    /// The lab's starter.
    pub starter: &'a pipeline::scene::StudentCode,
    /// `exercise.compare`.
    pub compare: Option<&'a Compare>,
}

impl<'a> Rules<'a> {
    /// The rules of `exercise`.
    #[must_use]
    pub fn of(exercise: &'a Exercise) -> Self {
        Self {
            forbid: &exercise.forbid,
            starter: &exercise.starter,
            compare: exercise.compare.as_ref(),
        }
    }
}

/// What comparing a student's frame with pipelens' own found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Findings {
    /// The frame against the reference, pixel by pixel.
    pub difference: Option<Difference>,
    /// The student's curve against pipelens' own, point by point, when the scene runs the
    /// student's de Casteljau: what decides the lab then.
    pub curve: Option<CurveDifference>,
    /// The first row of the vertex table whose clip position is not pipelens' (a vertex
    /// shader's lab): the row, the student's clip position and pipelens'.
    pub vertex: Option<(u32, glam::Vec4, glam::Vec4)>,
    /// The matrix the student built (for that vertex, or the shadow's) that is not pipelens'.
    pub matrix: Option<MatrixMismatch>,
    /// Where the student's run at the inspected pixel first parts from pipelens' own shader's.
    pub mismatch: Option<Mismatch>,
    /// The first sample of the first wrong pixel where the student's inside or depth test
    /// answers otherwise than pipelens' rule.
    pub sample: Option<samples::SampleMismatch>,
    /// The value the lab compares with one of pipelens' quantities (`exercise.compare`), where
    /// it differs at the inspected pixel.
    pub quantity: Option<quantity::QuantityMismatch>,
    /// pipelens' own answer taken where the lab asks the student to compute it (a uniform it
    /// forbids declared, a function it forbids called): the lab is not passed, whatever the
    /// pixels say.
    pub shortcut: Option<Shortcut>,
}

impl Findings {
    /// What the student's frame `mine` (drawn from `scene`, which holds the student's code)
    /// shows against pipelens' own `reference`, each channel within `tolerance` 8-bit steps.
    /// The mismatch is found at the pixel both frames traced (their capture's pixel); a name
    /// the rules forbid in the student's code is a shortcut.
    #[must_use]
    pub fn between(
        scene: &Scene,
        (mine, reference): (&FrameCapture, &FrameCapture),
        tolerance: f32,
        rules: Rules<'_>,
    ) -> Self {
        let vertex = scene
            .has_shaders()
            .then(|| first_wrong_vertex(mine, reference))
            .flatten();
        let matrix = vertex
            .and_then(|(row, ..)| {
                let object = mine.vertices.get(row as usize)?.object as usize;
                let trace = pipeline::trace_vertex(scene, mine, row as usize).ok()??;
                wrong_matrix(&trace.trace, mine, object)
            })
            .or_else(|| fragment_matrix(mine))
            .or_else(|| wrong_shadow_matrix(scene));
        let difference = mine.difference_by(reference, criteria(scene, tolerance));
        let sample = difference
            .as_ref()
            .and_then(|d| d.first)
            .and_then(|first| samples::first_sample_mismatch(scene, reference, first));
        let quantity = rules
            .compare
            .and_then(|c| quantity::quantity_mismatch(c, (mine, reference), scene));
        // A matrix off, or the lab's quantity, says more than a value it puts off further on:
        // the runs are compared (a vertex traced again) only where neither is found. A run is
        // compared only in a shader the lab asks the student to write (its starter says TODO
        // there) or that they changed: never a line of a stage they were not to touch.
        let (vertex_changed, fragment_changed) = changed_stages(scene, rules.starter);
        let mismatch = (matrix.is_none() && quantity.is_none())
            .then(|| {
                fragment_changed
                    .then(|| first_mismatch(traced(mine), traced(reference)))
                    .flatten()
                    .map(|m| Mismatch {
                        pixel: mine.settings.capture.pixel,
                        ..m
                    })
                    .or_else(|| {
                        let first = difference.as_ref()?.first?;
                        vertex_changed.then(|| vertex_mismatch(scene, (mine, reference), first))?
                    })
            })
            .flatten();
        Self {
            difference,
            curve: curve_difference(scene),
            vertex,
            matrix,
            mismatch,
            sample,
            quantity,
            shortcut: crate::lesson::forbid::find(
                rules.forbid,
                &scene_sources(scene),
                &crate::lesson::forbid::sources(rules.starter),
            ),
        }
    }

    /// Whether the lab passed: every curve point within the tolerance where a curve is
    /// compared, else every pixel.
    #[must_use]
    pub fn passed(&self) -> bool {
        if self.shortcut.is_some() {
            return false;
        }
        match &self.curve {
            Some(c) => c.passed(),
            None => self.difference.as_ref().is_some_and(Difference::passed),
        }
    }

    /// Everything found, as the card says it: the verdict first, then what is off (the
    /// vertex, the matrix, the value at the first wrong pixel).
    #[must_use]
    pub fn sentences(&self, lang: Lang) -> Vec<String> {
        if let Some(s) = &self.shortcut {
            return vec![s.words(lang)];
        }
        if let Some(c) = &self.curve {
            return vec![words::curve_verdict(c, lang)];
        }
        let Some(d) = &self.difference else {
            return Vec::new();
        };
        let mut out = vec![words::verdict(d, lang)];
        if d.passed() {
            return out;
        }
        if let Some(s) = &self.sample {
            out.push(s.words(lang));
        }
        if let Some((row, yours, theirs)) = self.vertex {
            out.push(words::vertex_words(row, yours, theirs, lang));
        }
        if let Some(m) = &self.matrix {
            out.push(words::matrix_words(m, lang));
        }
        if let Some(q) = &self.quantity {
            out.push(q.words(lang));
        }
        if let Some(m) = &self.mismatch {
            out.push(words::mismatch_words(m, lang));
        }
        out
    }
}

/// How far two window depths of a pixel may differ and still match: far above the rounding of
/// a matrix written in another order (about 10⁻⁷), far below what a wrong projection moves
/// (`fn/(n − f)` for `2fn/(n − f)`, Direct3D's z in [0, 1]).
pub const DEPTH_TOLERANCE: f32 = 1e-5;

/// What a lab compares: the colour within `tolerance` steps, the coverage and the depth of every
/// pixel; and, where the student's code decides which samples a triangle covers or keeps (the
/// inside test, the depth test), which triangle owns each pixel.
#[must_use]
pub fn criteria(scene: &Scene, tolerance: f32) -> Criteria {
    use pipeline::shader::HookKind;
    Criteria {
        tolerance,
        depth: Some(DEPTH_TOLERANCE),
        owner: scene.hook(HookKind::Inside).is_some() || scene.hook(HookKind::DepthTest).is_some(),
    }
}

/// The student's sources in `scene`, named as the shader panel's Save names them: the first
/// object's shaders and the scene's functions.
fn scene_sources(scene: &Scene) -> Vec<(String, &str)> {
    crate::lesson::forbid::files(
        scene.objects.iter().find_map(|o| o.code.shader.as_ref()),
        |kind| scene.hook(kind),
    )
}

/// Whether the student's vertex and fragment shaders are theirs to write: the starter says
/// TODO there, or the student's code differs from the starter's (comments aside) (a stage the starter does not
/// give is the student's when they wrote one).
fn changed_stages(scene: &Scene, starter: &pipeline::scene::StudentCode) -> (bool, bool) {
    let Some(mine) = scene.objects.iter().find_map(|o| o.code.shader.as_ref()) else {
        return (false, false);
    };
    let Some(given) = &starter.shader else {
        return (true, true);
    };
    let (m, g) = (&mine.programs, &given.programs);
    // The starter's code under comments in another language is still the starter.
    let changed = |a: &str, b: &str| !pipeline::shader::lexeme::same_code(a, b);
    (
        g.vertex.source.contains("TODO") || changed(&m.vertex.source, &g.vertex.source),
        g.fragment.source.contains("TODO") || changed(&m.fragment.source, &g.fragment.source),
    )
}

/// Where the student's vertex shader first parts from pipelens' own, run on the first corner
/// of the triangle that owns pixel `first` in the student's frame: the same vertex through both
/// (the reference's shipped GLSL traced on its own scene).
fn vertex_mismatch(
    scene: &Scene,
    (mine, reference): (&FrameCapture, &FrameCapture),
    first: (u32, u32),
) -> Option<Mismatch> {
    let i = mine.grid().checked_index(first.0, first.1)?;
    let p = *mine.pixels.primitive.get(i)?;
    let row = mine.primitives.get(p as usize)?.vertices[0];
    let own = reference_scene(scene, &mine.settings);
    let yours = pipeline::trace_vertex(scene, mine, row as usize).ok()??;
    let theirs = pipeline::trace_vertex(&own, reference, row as usize).ok()??;
    let mut m = first_difference(&yours.trace, &theirs.trace)?;
    m.vertex = Some(row);
    Some(m)
}

/// A matrix the student's fragment shader built at the traced pixel (the viewport matrix, say)
/// that is not pipelens' own.
fn fragment_matrix(mine: &FrameCapture) -> Option<MatrixMismatch> {
    traced(mine).iter().find_map(|f| {
        let object = mine.primitives.get(f.primitive as usize)?.object as usize;
        wrong_matrix(&f.trace, mine, object)
    })
}

/// The shaders' runs at the frame's traced pixel (none where no shader ran).
fn traced(frame: &FrameCapture) -> &[pipeline::capture::FragmentTrace] {
    frame.shaders.as_ref().map_or(&[], |s| &s.pixel)
}

/// The student's de Casteljau against pipelens' curve, when an object runs one on a Bézier
/// curve, or the student's `bezier_patch` against pipelens' surface, when an object runs one on
/// a Bézier patch (`None` also when it stops with a run-time error).
fn curve_difference(scene: &Scene) -> Option<CurveDifference> {
    use pipeline::mesh::BuiltinMesh;
    scene.objects.iter().find_map(|o| {
        match (
            &o.builtin,
            o.code.hooks.get(pipeline::shader::HookKind::Curve),
            o.code.hooks.get(pipeline::shader::HookKind::Patch),
        ) {
            (Some(BuiltinMesh::Bezier { points, .. }), Some(hook), _) => {
                hook.curve_difference(*points, CURVE_TOLERANCE).ok()
            }
            (Some(BuiltinMesh::BezierPatch { heights, .. }), _, Some(hook)) => {
                let rows = pipeline::mesh::patch::control_points(heights);
                hook.patch_difference(&rows, CURVE_TOLERANCE).ok()
            }
            _ => None,
        }
    })
}

/// The reference a lab's frame is compared with: the scene without the student's code —
/// pipelens' own stages, as its shipped GLSL where there is one, which draws the same pixels and
/// whose run at a pixel is what the student's run is compared with value by value.
#[must_use]
pub fn reference_scene(scene: &Scene, settings: &RenderSettings) -> Scene {
    let mut own = scene.clone();
    own.clear_code();
    match own.with_builtin_shaders(settings) {
        Ok(Some(shipped)) => shipped,
        _ => own,
    }
}

/// The check of a lab with no window, as the app makes it: `spec` (the step's scene with the
/// student's code in place) drawn and compared with pipelens' own, each channel within
/// `tolerance`; where the frames differ, both are drawn once more with the first wrong pixel
/// traced, so that the student's run there is compared with pipelens' value by value.
///
/// # Errors
/// Either frame's render error (a run-time error of the student's shader: an endless loop, an
/// index out of range), worded as the status line words it.
pub fn check(spec: &SceneSpec, exercise: &Exercise) -> Result<Findings, pipeline::RenderError> {
    let (tolerance, rules) = (exercise.tolerance, Rules::of(exercise));
    let reference = reference_scene(&spec.scene, &spec.settings);
    let draw = |scene: &Scene, pixel: Option<(u32, u32)>| {
        let settings = RenderSettings {
            capture: Capture::COLOR.with_pixel(pixel),
            ..spec.settings
        };
        pipeline::render(scene, &settings)
    };
    let (mine, theirs) = (draw(&spec.scene, None)?, draw(&reference, None)?);
    let findings = Findings::between(&spec.scene, (&mine, &theirs), tolerance, rules);
    let first = findings.difference.as_ref().and_then(|d| d.first);
    match first {
        Some(pixel) if findings.curve.is_none() && spec.scene.has_shaders() => {
            let (mine, theirs) = (
                draw(&spec.scene, Some(pixel))?,
                draw(&reference, Some(pixel))?,
            );
            Ok(Findings::between(
                &spec.scene,
                (&mine, &theirs),
                tolerance,
                rules,
            ))
        }
        _ => Ok(findings),
    }
}
