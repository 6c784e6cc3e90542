//! Functions the pipeline calls: GLSL the student writes for a stage that is not a shader, run
//! by the same machine. The first is the rasterizer's inside test (GAMES101, assignment 2:
//! `insideTriangle`), [`InsideTest`]:
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
//! The student writes the function alone; pipelens appends a `main` that calls it with the
//! sample and the corners as inputs and writes the answer as its output, and compiles the two
//! as one fragment shader. The student's lines keep their numbers.

use std::sync::Arc;

use super::{Bindings, LANES, Program, ShaderError, Stage, compile};

/// The signature the rasterizer calls, as the student writes it.
pub const INSIDE_SIGNATURE: &str = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c)";

/// What pipelens appends to the student's `inside`: the sample and the corners as inputs, the
/// answer (1 inside, 0 outside) as the output.
const INSIDE_CALLER: &str = "
in vec2 pipelens_p;
in vec2 pipelens_a;
in vec2 pipelens_b;
in vec2 pipelens_c;
out vec4 pipelens_inside;
void main() {
    pipelens_inside = inside(pipelens_p, pipelens_a, pipelens_b, pipelens_c) ? vec4(1.0) : vec4(0.0);
}
";

/// The student's inside test, compiled.
#[derive(Clone, Debug)]
pub struct InsideTest {
    /// The student's source with pipelens' caller appended.
    pub program: Arc<Program>,
    /// The student's source alone.
    pub source: String,
}

impl PartialEq for InsideTest {
    /// Two tests are the same when their sources are.
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source
    }
}

/// Compiles the student's `inside` (see the module's documentation).
///
/// # Errors
/// Every message, at its line and column in the student's source; a missing `inside`, or one
/// with another signature, is said so at the start of the source.
pub fn compile_inside(source: &str) -> Result<InsideTest, Vec<ShaderError>> {
    let mut text = source.to_owned();
    if !text.ends_with('\n') {
        text.push('\n');
    }
    let own = text.len();
    text.push_str(INSIDE_CALLER);
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
                    "the rasterizer calls `{INSIDE_SIGNATURE}` for every sample: define it with \
                     exactly that signature (no `main`, no inputs or outputs of your own)"
                ),
            ));
        }
        mine
    })?;
    Ok(InsideTest {
        program: Arc::new(program),
        source: source.to_owned(),
    })
}

impl InsideTest {
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
        let program = &*self.program;
        let mut machine = program.machine();
        let bindings = Bindings { textures: &[] };
        // The inputs in the entry point's order: each its two rows of lanes.
        let which: Vec<Option<usize>> = program
            .inputs
            .iter()
            .map(|v| {
                ["pipelens_p", "pipelens_a", "pipelens_b", "pipelens_c"]
                    .iter()
                    .position(|n| *n == v.name)
            })
            .collect();
        let mut rows: Vec<Vec<u32>> = vec![vec![0; 2 * LANES]; which.len()];
        for (row, w) in rows.iter_mut().zip(&which) {
            if let Some(k @ 1..=3) = w {
                let [x, y] = corners[k - 1];
                row[..LANES].fill(x.to_bits());
                row[LANES..].fill(y.to_bits());
            }
        }
        let p_row = which.iter().position(|w| *w == Some(0));
        let mut out = Vec::with_capacity(points.len());
        for batch in points.chunks(LANES) {
            if let Some(r) = p_row {
                for (l, [x, y]) in batch.iter().enumerate() {
                    rows[r][l] = x.to_bits();
                    rows[r][LANES + l] = y.to_bits();
                }
            }
            let n = batch.len();
            let live = if n == LANES { u64::MAX } else { (1 << n) - 1 };
            let inputs: Vec<&[u32]> = rows.iter().map(Vec::as_slice).collect();
            machine
                .run(&inputs, n, live, &bindings)
                .map_err(|e| program.run_error(&e))?;
            let result = machine.result();
            out.extend((0..n).map(|l| f32::from_bits(result[l]) != 0.0));
        }
        Ok(out)
    }
}
