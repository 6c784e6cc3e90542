//! Functions the pipeline calls: GLSL the student writes for a stage that is not a shader, run
//! by the same machine, each a [`Hook`] of a [`HookKind`]. The rasterizer's inside test
//! (GAMES101, assignment 2: `insideTriangle`), [`HookKind::Inside`]:
//!
//! ```glsl
//! bool inside(vec2 p, vec2 a, vec2 b, vec2 c)
//! ```
//!
//! called once for every sample of a triangle's bounding box, `p` the sample's position and `a`,
//! `b`, `c` the triangle's corners, all in window pixels (y up, a pixel's centre at `k + ½`), the
//! corners counter-clockwise as the rasterizer snapped them (to 1/256 of a pixel). It replaces
//! pipelens' own test — the three edge functions `E_i(p) ≥ 0` with the top-left rule deciding
//! ties — for the triangles of the objects that carry it; the depth test, the interpolation and
//! the shading stay pipelens'. So the coverage, the MSAA and the z-buffer views show the
//! student's test, ties and all.
//!
//! The depth test (GAMES101, assignment 2: the z-buffer), [`HookKind::DepthTest`]:
//!
//! ```glsl
//! bool depth_test(float z, float stored)
//! ```
//!
//! called for every sample a triangle covers, `z` the triangle's window depth there (in
//! [0, 1], the depth plane through its corners) and `stored` what the z-buffer holds for the
//! sample (the clear value, 1, where nothing was drawn yet); `true` writes `z` and the
//! triangle into the sample. It replaces the settings' comparison (`less`: `z < stored`).
//! Within one triangle every sample is distinct, so a triangle's samples are asked in batches.
//!
//! De Casteljau's construction of a cubic Bézier curve (GAMES101, assignment 4),
//! [`HookKind::Curve`]:
//!
//! ```glsl
//! vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t)
//! ```
//!
//! called for every point of the curve a Bézier object draws (161 values of `t` from 0 to 1,
//! and those up to the construction's `t`), the control points in the object's plane; it
//! replaces pipelens' own curve point `b(t) = Σ B_i³(t)·P_i`.
//!
//! A bicubic Bézier patch's point (GAMES101 lecture 12: de Casteljau in u, then in v),
//! [`HookKind::Patch`]:
//!
//! ```glsl
//! vec3 bezier_patch(vec3 p[16], float u, float v)
//! ```
//!
//! called for every vertex of the surface grid a `bezier_patch` object draws (25 × 25 values of
//! `(u, v)`, and the construction's point), `p[4i + j]` the control point `P_ij` (row `i` along
//! v, column `j` along u); it replaces pipelens' own point `b(u, v) = Σ Σ B_i³(v)·B_j³(u)·P_ij`.
//! The surface keeps pipelens' exact normals: the function places the points.
//!
//! The planar shadow matrix (Angel's shadow projection), [`HookKind::ShadowMatrix`]:
//!
//! ```glsl
//! mat4 shadow_matrix(vec3 light)
//! ```
//!
//! called once a frame by the shadow pass, `light` the point light relative to the receiving
//! plane, which it takes to be `y = 0`; it replaces pipelens' own `T(l)·M_p·T(−l)` in every
//! shadow object's model matrix. Any positive multiple of the matrix casts the same shadow.
//!
//! The student writes the function alone; pipelens appends a `main` that calls it with its
//! arguments as inputs and writes the answer as its output, and compiles the two as one fragment
//! shader. The student's lines keep their numbers.

use std::sync::Arc;

mod compare;
mod kinds;

pub use compare::{At, CurveDifference};
pub use kinds::{
    CURVE_SIGNATURE, DEPTH_SIGNATURE, HOOKS, HookKind, HookSpec, INSIDE_SIGNATURE, PATCH_SIGNATURE,
    SHADOW_SIGNATURE,
};

use super::{Batch, LANES, Program, ShaderError, Stage, compile};

/// A function of the pipeline the student wrote, compiled.
#[derive(Clone, Debug)]
pub struct Hook {
    /// Which function it is.
    pub kind: HookKind,
    /// The student's source with pipelens' caller appended.
    pub program: Arc<Program>,
    /// The student's source alone.
    pub source: String,
    /// The loop iterations one call may run ([`crate::settings::RenderSettings::max_steps`]
    /// of the frame that calls it; the default until then).
    pub budget: u32,
}

impl Hook {
    /// This function, its calls allowed `budget` loop iterations each.
    #[must_use]
    pub fn within(&self, budget: u32) -> Self {
        Self {
            budget,
            ..self.clone()
        }
    }
}

/// The student's inside test.
pub type InsideTest = Hook;

/// The student's functions, one slot for each kind (`None`: pipelens' own).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Hooks([Option<Hook>; HookKind::ALL.len()]);

impl Hooks {
    /// The student's function of kind `kind`, if given.
    #[must_use]
    pub fn get(&self, kind: HookKind) -> Option<&Hook> {
        self.0[kind as usize].as_ref()
    }

    /// Where the student's function of kind `kind` is kept.
    pub fn slot(&mut self, kind: HookKind) -> &mut Option<Hook> {
        &mut self.0[kind as usize]
    }

    /// `hook` kept in its kind's slot.
    pub fn set(&mut self, hook: Hook) {
        let kind = hook.kind;
        *self.slot(kind) = Some(hook);
    }

    /// The functions given, in [`HookKind::ALL`]'s order.
    pub fn iter(&self) -> impl Iterator<Item = &Hook> {
        self.0.iter().flatten()
    }
}

impl PartialEq for Hook {
    /// Two tests are the same when their sources are.
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source
    }
}

/// Compiles the student's `inside` (see the module's documentation).
///
/// # Errors
/// As [`compile_hook`].
pub fn compile_inside(source: &str) -> Result<Hook, Vec<ShaderError>> {
    compile_hook(HookKind::Inside, source)
}

/// Compiles the student's function of kind `kind` with its caller.
///
/// # Errors
/// Every message, at its line and column in the student's source; a missing function, or one
/// with another signature, is said so at the start of the source.
pub fn compile_hook(kind: HookKind, source: &str) -> Result<Hook, Vec<ShaderError>> {
    let mut text = source.to_owned();
    if !text.ends_with('\n') {
        text.push('\n');
    }
    let own = text.len();
    text.push_str(kind.spec().caller);
    let program = compile(Stage::Fragment, &text).map_err(|errors| {
        let mut mine: Vec<ShaderError> = errors
            .iter()
            .filter(|e| e.span.start < own)
            .cloned()
            .collect();
        if mine.len() < errors.len() || mine.is_empty() {
            // What went wrong is in the caller: the function it calls is not there as written.
            mine.push(super::complain(
                super::error_at(
                    source,
                    0..0,
                    format!(
                        "{} calls `{}` {}: define it with exactly that signature (no `main`, no \
                         inputs or outputs of your own)",
                        kind.spec().when.0,
                        kind.signature(),
                        kind.spec().when.1
                    ),
                ),
                super::Complaint::HookSignature(kind.signature().to_owned()),
            ));
        }
        mine
    })?;
    Ok(Hook {
        kind,
        program: Arc::new(program),
        source: source.to_owned(),
        budget: crate::settings::DEFAULT_MAX_STEPS,
    })
}

impl Hook {
    /// The test at each of `points` against the triangle `corners` (window pixels), in batches
    /// of [`LANES`].
    ///
    /// # Errors
    /// A run-time error (the loop budget spent, say), at its line in the student's source.
    pub fn covers(
        &self,
        points: &[[f32; 2]],
        corners: [[f32; 2]; 3],
    ) -> Result<Vec<bool>, ShaderError> {
        let [a, b, c] = corners;
        let flat = |[x, y]: [f32; 2]| [x, y, 0.0];
        let answers = self.answers(points.len(), |k| {
            let [x, y] = points[k];
            [[x, y, 0.0], flat(a), flat(b), flat(c), [0.0; 3]]
        })?;
        Ok(answers.iter().map(|a| a[0] != 0.0).collect())
    }

    /// The depth test at each covered sample: `z[k]` against `stored[k]`, in batches.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn passes(&self, z: &[f32], stored: &[f32]) -> Result<Vec<bool>, ShaderError> {
        let answers = self.answers(z.len(), |k| {
            [
                [z[k], 0.0, 0.0],
                [stored[k], 0.0, 0.0],
                [0.0; 3],
                [0.0; 3],
                [0.0; 3],
            ]
        })?;
        Ok(answers.iter().map(|a| a[0] != 0.0).collect())
    }

    /// The curve's point at each of `ts`, the control points `p`, in batches.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn curve_points(
        &self,
        p: [glam::Vec2; 4],
        ts: &[f32],
    ) -> Result<Vec<glam::Vec2>, ShaderError> {
        let [a, b, c, d] = p.map(|v| [v.x, v.y, 0.0]);
        let answers = self.answers(ts.len(), |k| [a, b, c, d, [ts[k], 0.0, 0.0]])?;
        Ok(answers
            .iter()
            .map(|v| glam::Vec2::new(v[0], v[1]))
            .collect())
    }

    /// The student's curve against pipelens' own `b(t) = Σ B_i³(t)·P_i` at the 161 parameters
    /// a whole curve is drawn with: a point matches when it is within `tolerance` (in the
    /// curve's units) of pipelens' point.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn curve_difference(
        &self,
        points: [glam::Vec2; 4],
        tolerance: f32,
    ) -> Result<CurveDifference, ShaderError> {
        let ts = crate::mesh::curve_parameters(1.0);
        let flat = |p: glam::Vec2| p.extend(0.0);
        let mine: Vec<_> = self
            .curve_points(points, &ts)?
            .into_iter()
            .map(flat)
            .collect();
        let reference: Vec<_> = ts
            .iter()
            .map(|&t| flat(crate::bezier::point(&points, t)))
            .collect();
        let at: Vec<At> = ts.iter().map(|&t| At::T(t)).collect();
        Ok(CurveDifference::between(&at, &mine, &reference, tolerance))
    }

    /// The patch's point at each of `uvs`, the control points `rows` (`rows[i][j]` = `P_ij`),
    /// in batches.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn patch_points(
        &self,
        rows: &[[glam::Vec3; 4]; 4],
        uvs: &[glam::Vec2],
    ) -> Result<Vec<glam::Vec3>, ShaderError> {
        let answers = self.answers(uvs.len(), |k| {
            let mut args = [[0.0; 3]; 17];
            for (arg, p) in args.iter_mut().zip(rows.iter().flatten()) {
                *arg = p.to_array();
            }
            args[16] = [uvs[k].x, uvs[k].y, 0.0];
            args
        })?;
        Ok(answers
            .iter()
            .map(|v| glam::Vec3::new(v[0], v[1], v[2]))
            .collect())
    }

    /// The student's patch against pipelens' own `b(u, v)` at the surface grid's vertices: a
    /// point matches when it is within `tolerance` of pipelens' point.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn patch_difference(
        &self,
        rows: &[[glam::Vec3; 4]; 4],
        tolerance: f32,
    ) -> Result<CurveDifference, ShaderError> {
        let uvs = crate::mesh::patch::patch_parameters();
        let mine = self.patch_points(rows, &uvs)?;
        let reference: Vec<_> = uvs
            .iter()
            .map(|uv| crate::bezier::patch_point(rows, uv.x, uv.y).1)
            .collect();
        let at: Vec<At> = uvs.iter().map(|&uv| At::Uv(uv)).collect();
        Ok(CurveDifference::between(&at, &mine, &reference, tolerance))
    }

    /// The student's shadow matrix for the point light `light` (relative to the plane `y = 0`):
    /// the function called once for each of its four columns.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn shadow_matrix(&self, light: glam::Vec3) -> Result<glam::Mat4, ShaderError> {
        let l = light.to_array();
        let columns = self.answers(4, |k| {
            [l, [k as f32, 0.0, 0.0], [0.0; 3], [0.0; 3], [0.0; 3]]
        })?;
        Ok(glam::Mat4::from_cols_array_2d(&[
            columns[0], columns[1], columns[2], columns[3],
        ]))
    }

    /// The function's answer (the caller's output, four components) for `n` calls, call `k`'s
    /// arguments `args(k)` (each of one to three floats, in the caller's inputs' order), 64
    /// calls a batch.
    fn answers<const N: usize>(
        &self,
        n: usize,
        args: impl Fn(usize) -> [[f32; 3]; N],
    ) -> Result<Vec<[f32; 4]>, ShaderError> {
        let program = &*self.program;
        let mut machine = program.machine();
        machine.budget = self.budget;
        let names = self.kind.spec().inputs;
        // The entry point's inputs in its order: which argument each is.
        let which: Vec<Option<usize>> = program
            .inputs
            .iter()
            .map(|v| names.iter().position(|n| *n == v.name))
            .collect();
        let mut batch = Batch::new(program);
        let mut out = Vec::with_capacity(n);
        for first in (0..n).step_by(LANES) {
            batch.start((n - first).min(LANES));
            for l in 0..batch.lanes() {
                let values = args(first + l);
                for (input, arg) in which.iter().enumerate() {
                    if let Some(a) = arg {
                        batch.set(input, l, &values[*a]);
                    }
                }
            }
            let ran = machine
                .run_batch(&batch, &())
                .map_err(|e| program.run_error(&e))?;
            out.extend((0..batch.lanes()).map(|l| ran.outputs::<4>(l)));
        }
        Ok(out)
    }
}
