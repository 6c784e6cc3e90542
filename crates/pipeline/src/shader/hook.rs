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
//! The student writes the function alone; pipelens appends a `main` that calls it with its
//! arguments as inputs and writes the answer as its output, and compiles the two as one fragment
//! shader. The student's lines keep their numbers.

use std::sync::Arc;

use super::{Bindings, LANES, Program, ShaderError, Stage, compile};

/// The signature the rasterizer calls for the inside test, as the student writes it.
pub const INSIDE_SIGNATURE: &str = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c)";

/// The signature the rasterizer calls for the depth test, as the student writes it.
pub const DEPTH_SIGNATURE: &str = "bool depth_test(float z, float stored)";

/// Which function of the pipeline the student writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HookKind {
    /// `bool inside(vec2 p, vec2 a, vec2 b, vec2 c)`: which samples a triangle covers.
    Inside,
    /// `bool depth_test(float z, float stored)`: which covered samples it writes.
    DepthTest,
}

impl HookKind {
    /// Every kind, in the order the shader panel shows their tabs.
    pub const ALL: [Self; 2] = [Self::Inside, Self::DepthTest];

    /// The signature the pipeline calls.
    #[must_use]
    pub fn signature(self) -> &'static str {
        match self {
            Self::Inside => INSIDE_SIGNATURE,
            Self::DepthTest => DEPTH_SIGNATURE,
        }
    }

    /// Its name as the lesson's key and the messages say it: `inside`, `depth_test`.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::Inside => "inside",
            Self::DepthTest => "depth_test",
        }
    }

    /// When the pipeline calls it, for the messages.
    fn when(self) -> &'static str {
        match self {
            Self::Inside => "for every sample",
            Self::DepthTest => "for every sample a triangle covers",
        }
    }

    /// The inputs pipelens passes, in the signature's order.
    fn inputs(self) -> &'static [&'static str] {
        match self {
            Self::Inside => &["pipelens_p", "pipelens_a", "pipelens_b", "pipelens_c"],
            Self::DepthTest => &["pipelens_z", "pipelens_stored"],
        }
    }

    /// What pipelens appends to the student's function: its arguments as inputs, the answer
    /// (1 true, 0 false) as the output.
    fn caller(self) -> &'static str {
        match self {
            Self::Inside => {
                "
in vec2 pipelens_p;
in vec2 pipelens_a;
in vec2 pipelens_b;
in vec2 pipelens_c;
out vec4 pipelens_answer;
void main() {
    pipelens_answer = inside(pipelens_p, pipelens_a, pipelens_b, pipelens_c) ? vec4(1.0) : vec4(0.0);
}
"
            }
            Self::DepthTest => {
                "
in float pipelens_z;
in float pipelens_stored;
out vec4 pipelens_answer;
void main() {
    pipelens_answer = depth_test(pipelens_z, pipelens_stored) ? vec4(1.0) : vec4(0.0);
}
"
            }
        }
    }
}

/// A function of the pipeline the student wrote, compiled.
#[derive(Clone, Debug)]
pub struct Hook {
    /// Which function it is.
    pub kind: HookKind,
    /// The student's source with pipelens' caller appended.
    pub program: Arc<Program>,
    /// The student's source alone.
    pub source: String,
}

/// The student's inside test.
pub type InsideTest = Hook;

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
    text.push_str(kind.caller());
    let program = compile(Stage::Fragment, &text).map_err(|errors| {
        let mut mine: Vec<ShaderError> = errors
            .iter()
            .filter(|e| e.span.start < own)
            .cloned()
            .collect();
        if mine.len() < errors.len() || mine.is_empty() {
            // What went wrong is in the caller: the function it calls is not there as written.
            mine.push(super::error_at(
                source,
                0..0,
                format!(
                    "the rasterizer calls `{}` {}: define it with exactly that signature (no \
                     `main`, no inputs or outputs of your own)",
                    kind.signature(),
                    kind.when()
                ),
            ));
        }
        mine
    })?;
    Ok(Hook {
        kind,
        program: Arc::new(program),
        source: source.to_owned(),
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
        self.answers(points.len(), |k| {
            let [x, y] = points[k];
            [[x, y], a, b, c]
        })
    }

    /// The depth test at each covered sample: `z[k]` against `stored[k]`, in batches.
    ///
    /// # Errors
    /// A run-time error, at its line in the student's source.
    pub fn passes(&self, z: &[f32], stored: &[f32]) -> Result<Vec<bool>, ShaderError> {
        self.answers(z.len(), |k| {
            [[z[k], 0.0], [stored[k], 0.0], [0.0; 2], [0.0; 2]]
        })
    }

    /// The function's answer for `n` calls, call `k`'s arguments `args(k)` (each one or two
    /// floats, in the signature's order), 64 calls a batch.
    fn answers(
        &self,
        n: usize,
        args: impl Fn(usize) -> [[f32; 2]; 4],
    ) -> Result<Vec<bool>, ShaderError> {
        let program = &*self.program;
        let mut machine = program.machine();
        let bindings = Bindings { textures: &[] };
        let names = self.kind.inputs();
        // The entry point's inputs in its order: which argument each is, and its components.
        let which: Vec<(Option<usize>, usize)> = program
            .inputs
            .iter()
            .map(|v| {
                (
                    names.iter().position(|n| *n == v.name),
                    v.components as usize,
                )
            })
            .collect();
        let mut rows: Vec<Vec<u32>> = which.iter().map(|(_, c)| vec![0; c * LANES]).collect();
        let mut out = Vec::with_capacity(n);
        for first in (0..n).step_by(LANES) {
            let batch = (n - first).min(LANES);
            for l in 0..batch {
                let values = args(first + l);
                for (row, (arg, components)) in rows.iter_mut().zip(&which) {
                    if let Some(a) = arg {
                        for c in 0..*components {
                            row[c * LANES + l] = values[*a][c].to_bits();
                        }
                    }
                }
            }
            let live = if batch == LANES {
                u64::MAX
            } else {
                (1 << batch) - 1
            };
            let inputs: Vec<&[u32]> = rows.iter().map(Vec::as_slice).collect();
            machine
                .run(&inputs, batch, live, &bindings)
                .map_err(|e| program.run_error(&e))?;
            let result = machine.result();
            out.extend((0..batch).map(|l| f32::from_bits(result[l]) != 0.0));
        }
        Ok(out)
    }
}
