//! What a lab's check finds besides the pixel count: where the student's run first parts from
//! pipelens' own at a pixel, the first vertex whose clip position is off, and a matrix the
//! student built compared entry by entry with pipelens' own. The app's card and `pipelens grade`
//! both read them.

use pipeline::capture::FrameCapture;
use pipeline::scene::Scene;
use pipeline::shader::{HookKind, Step, TraceLine, Value};

/// How far (in the curve's units) a student's curve (or patch) point may be from pipelens' `b(t)` and
/// still match: far below a pixel of the lesson's view (3 units across 720 pixels), far above
/// the rounding of a correct construction in `f32`.
pub const CURVE_TOLERANCE: f32 = 1e-4;

/// Where the student's run at the inspected pixel first parts from pipelens' own shader's run:
/// a variable both assign in the same stretch of the run (before the first loop iteration, or
/// within the same iteration), whose last values there differ.
#[derive(Clone, Debug, PartialEq)]
pub struct Mismatch {
    /// The variable.
    pub name: String,
    /// Its line in the student's source.
    pub line: usize,
    /// The student's value, as the trace writes it.
    pub yours: String,
    /// pipelens' value.
    pub theirs: String,
    /// For a vector that points pipelens' way: its length in each run (a normal not
    /// normalized shows here).
    pub lengths: Option<(f64, f64)>,
    /// The pixel whose runs were compared (the inspected one; `pipelens grade` inspects the
    /// first that differs), for a fragment shader's runs.
    pub pixel: Option<(u32, u32)>,
    /// Where the runs were compared: the vertex shader's at this row of the vertex table (a
    /// corner of the first wrong pixel's triangle), or `None` for the fragment shader's at the
    /// inspected pixel.
    pub vertex: Option<u32>,
}

/// A value as the card shows it: GLSL's spelling with three decimals, or six significant digits
/// where three decimals would show `other` the same.
fn shown(value: &Value, other: &Value) -> (String, String) {
    let write = |v: &Value, digits: usize| {
        let numbers: Vec<String> = v
            .numbers
            .iter()
            .map(|x| {
                if digits == 3 {
                    pipeline::shader::float_text(*x as f32)
                } else {
                    format!("{x:.6}")
                }
            })
            .collect();
        match numbers.as_slice() {
            [one] => one.clone(),
            _ => format!("{}({})", v.ty, numbers.join(", ")),
        }
    };
    let (a, b) = (write(value, 3), write(other, 3));
    if a == b {
        (write(value, 6), write(other, 6))
    } else {
        (a, b)
    }
}

/// The student's length of a vector whose length is 1 in pipelens' run and not in theirs (a
/// normal left unnormalized: an interpolated unit normal is about 0.999 long between vertices),
/// from `(yours, pipelens')`.
#[must_use]
pub fn unnormalized(lengths: Option<(f64, f64)>) -> Option<f64> {
    lengths
        .filter(|(yours, theirs)| (theirs - 1.0).abs() < 1e-4 && (yours - 1.0).abs() > 2e-4)
        .map(|(yours, _)| yours)
}

/// The lengths `(yours, pipelens')` of two vectors that point the same way (within about
/// 2.5°): a vector that differs from pipelens' by its length alone. `None` for other values.
fn lengths_along(yours: &Value, theirs: &Value) -> Option<(f64, f64)> {
    let (a, b) = (yours.length()?, theirs.length()?);
    let dot: f64 = yours
        .numbers
        .iter()
        .zip(&theirs.numbers)
        .map(|(x, y)| x * y)
        .sum();
    (a > 0.0 && b > 0.0 && dot / (a * b) > 0.999).then_some((a, b))
}

/// A run's values by stretch: the stretch (how many loop iterations began before it), the name
/// (a function's return as `name()`), and every value it took there with its place in the run
/// and its line, in the order first written.
type Stretches = Vec<((usize, String), Vec<(usize, usize, Value)>)>;

/// `trace`'s values by stretch (see [`Stretches`]).
fn stretches(trace: &[TraceLine]) -> Stretches {
    let mut stretch = 0;
    let mut values: Stretches = Vec::new();
    for (at, l) in trace.iter().enumerate() {
        if let Step::Iteration { .. } = l.step {
            stretch += 1;
            continue;
        }
        let Some((name, value)) = l.step.written() else {
            continue;
        };
        let key = (stretch, name);
        let taken = (at, l.line, value.clone());
        match values.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(taken),
            None => values.push((key, vec![taken])),
        }
    }
    values
}

/// The first value at which the student's fragments at the inspected pixel part from pipelens'
/// own shader's (fragments paired by their triangle), in the order of the student's run.
#[must_use]
pub fn first_mismatch(
    student: &[pipeline::capture::FragmentTrace],
    reference: &[pipeline::capture::FragmentTrace],
) -> Option<Mismatch> {
    student.iter().find_map(|mine| {
        let theirs = reference.iter().find(|f| f.triangle == mine.triangle)?;
        first_difference(&mine.trace, &theirs.trace)
    })
}

/// The first value at which the student's run `mine` parts from pipelens' own run `theirs`
/// (of the same stage on the same input): a variable both assign in the same stretch of the
/// run (before the first loop iteration, or within the same iteration), whose last values
/// there differ — a vector of length 1 in pipelens' run that is not in the student's first.
/// Stretches pair only where both runs loop as often; runs that loop differently (one light
/// written out where pipelens loops over the scene's lights) compare each name's last value.
#[must_use]
pub fn first_difference(mine: &[TraceLine], theirs: &[TraceLine]) -> Option<Mismatch> {
    let iterations = |run: &[TraceLine]| {
        run.iter()
            .filter(|l| matches!(l.step, Step::Iteration { .. }))
            .count()
    };
    let alike = iterations(mine) == iterations(theirs);
    // A name written as often in both runs within a stretch is compared write by write (the
    // third `uv` with the third: a helper's argument); otherwise by its last value there.
    let (mine, theirs) = (stretches(mine), stretches(theirs));
    let reference_values: std::collections::HashMap<_, _> =
        theirs.iter().map(|(k, v)| (k, v)).collect();
    let mut paired: Vec<(usize, (String, usize, Value, Value))> = Vec::new();
    for (key, yours) in mine.iter().filter(|_| alike) {
        let Some(theirs) = reference_values.get(key) else {
            continue;
        };
        let pairs: Vec<_> = if yours.len() == theirs.len() {
            yours.iter().zip(theirs.iter()).collect()
        } else {
            yours.last().into_iter().zip(theirs.last()).collect()
        };
        for ((at, line, y), (.., t)) in pairs {
            paired.push((*at, (key.1.clone(), *line, y.clone(), t.clone())));
        }
    }
    paired.sort_by_key(|(at, _)| *at);
    let paired: Vec<_> = paired.into_iter().map(|(_, p)| p).collect();
    let mismatch = |(name, line, yours, theirs): &(String, usize, Value, Value)| {
        let (y, t) = shown(yours, theirs);
        Mismatch {
            name: name.clone(),
            line: *line,
            lengths: lengths_along(yours, theirs),
            yours: y,
            theirs: t,
            pixel: None,
            vertex: None,
        }
    };
    // A vector of length 1 in pipelens' run that is not in the student's — a normal left
    // unnormalized — says more than the first value it puts off, however small the gap.
    let unit = paired
        .iter()
        .find(|(_, _, yours, theirs)| unnormalized(lengths_along(yours, theirs)).is_some());
    if let Some(m) = unit.or_else(|| paired.iter().find(|(_, _, y, t)| !y.agrees(t))) {
        return Some(mismatch(m));
    }
    // Nothing differs stretch by stretch (the runs loop differently, or write their values in
    // different stretches): the last value of each name both runs write — the output's at
    // least — compared whatever the stretch, the student's first-computed first (a light
    // vector off before the sum it feeds).
    let last = |values: &Stretches| {
        let mut out: Vec<(String, (usize, usize, Value))> = Vec::new();
        for ((_, name), all) in values {
            let Some((at, line, value)) = all.last() else {
                continue;
            };
            let v = (*at, *line, value.clone());
            match out.iter_mut().find(|(n, _)| n == name) {
                Some((_, old)) => *old = v,
                None => out.push((name.clone(), v)),
            }
        }
        out.sort_by_key(|(_, (at, ..))| *at);
        out
    };
    let theirs_last: std::collections::HashMap<_, _> = last(&theirs).into_iter().collect();
    last(&mine)
        .into_iter()
        .find_map(|(name, (_, line, yours))| {
            let (.., theirs) = theirs_last.get(&name)?;
            (!yours.agrees(theirs)).then(|| (name, line, yours, theirs.clone()))
        })
        .map(|m| mismatch(&m))
}

/// The first row of the vertex table whose clip position in the student's frame differs from
/// the reference's (each coordinate within `10⁻⁴·max(1, |c|)`): the row, the student's clip
/// position and pipelens'. `None` when every row agrees or the tables differ in length.
#[must_use]
pub fn first_wrong_vertex(
    student: &FrameCapture,
    reference: &FrameCapture,
) -> Option<(u32, glam::Vec4, glam::Vec4)> {
    if student.vertices.len() != reference.vertices.len() {
        return None;
    }
    student
        .vertices
        .iter()
        .zip(&reference.vertices)
        .enumerate()
        .find(|(_, (a, b))| {
            (a.clip - b.clip)
                .abs()
                .cmpgt(1e-4 * a.clip.abs().max(glam::Vec4::ONE))
                .any()
        })
        .map(|(row, (a, b))| (row as u32, a.clip, b.clip))
}

/// A matrix the student's vertex shader built, compared with pipelens' own entry by entry.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixMismatch {
    /// The variable that holds it.
    pub name: String,
    /// Its line.
    pub line: usize,
    /// Which of pipelens' matrices it stands for: `M`, `V`, `P`, `V·M` or `P·V·M`.
    pub matrix: &'static str,
    /// The entries that differ: row and column (from 1), the student's value, pipelens'.
    pub entries: Vec<(usize, usize, f32, f32)>,
}

/// The entries of `columns` (column-major) that differ from `reference`'s beyond the trace's
/// three decimals: row and column (from 1), the student's value, pipelens'.
fn differing_entries(columns: &[f32; 16], reference: &glam::Mat4) -> Vec<(usize, usize, f32, f32)> {
    let theirs = reference.to_cols_array();
    (0..16)
        .filter(|&k| (columns[k] - theirs[k]).abs() > 0.0015 + 0.002 * theirs[k].abs())
        .map(|k| (k % 4 + 1, k / 4 + 1, columns[k], theirs[k]))
        .collect()
}

/// The student's shadow matrix against pipelens' `T(l)·M_p·T(−l)` for the scene's light, when
/// the scene runs one and it casts another shadow. A positive multiple casts the same shadow:
/// the student's matrix divided by the factor `k = ⟨S, M⟩/⟨M, M⟩` that brings it nearest
/// pipelens' (when `k > 0`) and then equal is not off; otherwise its own entries are compared.
#[must_use]
pub fn wrong_shadow_matrix(scene: &Scene) -> Option<MatrixMismatch> {
    let shadow = scene.shadow?;
    let hook = scene.hook(HookKind::ShadowMatrix)?;
    let light = shadow.light_over_plane();
    let yours = hook.shadow_matrix(light).ok()?;
    let theirs = pipeline::transform::planar_shadow(light).matrix;
    let (a, b) = (yours.to_cols_array(), theirs.to_cols_array());
    let k =
        a.iter().zip(&b).map(|(x, y)| x * y).sum::<f32>() / b.iter().map(|y| y * y).sum::<f32>();
    if k > 0.0 && differing_entries(&(yours * (1.0 / k)).to_cols_array(), &theirs).is_empty() {
        return None;
    }
    let entries = differing_entries(&a, &theirs);
    let line = hook
        .source
        .lines()
        .position(|l| l.contains("shadow_matrix"))
        .map_or(1, |i| i + 1);
    (!entries.is_empty()).then(|| MatrixMismatch {
        name: "shadow_matrix(light)".to_owned(),
        line,
        matrix: "M_shadow",
        entries,
    })
}

/// In a run of the student's shader, the first 4×4 matrix written or returned that is not
/// pipelens' own: one named as pipelens names its matrices (`model`, `view`, `projection`,
/// `mvp`, `viewport`, or a function `look_at()`, `perspective()`, …) stands for that one; another
/// is compared with M (the object's), V, P, V·M, P·V·M and M_viewport and stands for the one it
/// differs from in the fewest entries (at most 8 of 16, else it is some other matrix). Entries
/// agree within `0.0015 + 0.2 %`.
#[must_use]
pub fn wrong_matrix(
    trace: &[TraceLine],
    capture: &FrameCapture,
    object: usize,
) -> Option<MatrixMismatch> {
    let m = &capture.matrices;
    let model = m.models.get(object)?.matrix;
    let (v, p) = (m.view.matrix, m.projection.matrix);
    let candidates = [
        ("M", model),
        ("V", v),
        ("P", p),
        ("V·M", v * model),
        ("P·V·M", p * v * model),
        ("M_viewport", m.viewport.matrix),
    ];
    for l in trace {
        let Some((name, value)) = l.step.written() else {
            continue;
        };
        if value.ty != "mat4" {
            continue;
        }
        let Ok(columns) =
            <[f32; 16]>::try_from(value.numbers.iter().map(|&x| x as f32).collect::<Vec<_>>())
        else {
            continue;
        };
        // A matrix named as pipelens names its uniforms (or a function named for what it
        // builds) stands for that one; another for the one it is nearest.
        let lower = name.trim_end_matches("()").to_ascii_lowercase();
        let named = match lower.as_str() {
            "model" | "m" | "model_matrix" | "rotate_z" | "rotation_z" | "rotation" | "rz" => {
                Some("M")
            }
            "view" | "v" | "view_matrix" | "look_at" | "lookat" => Some("V"),
            "projection" | "proj" | "p" | "perspective" | "projection_matrix" | "frustum" => {
                Some("P")
            }
            "model_view" | "mv" | "modelview" => Some("V·M"),
            "mvp" => Some("P·V·M"),
            "viewport" | "m_viewport" | "viewport_matrix" => Some("M_viewport"),
            _ => None,
        };
        let best = candidates
            .iter()
            .filter(|(label, _)| named.is_none_or(|n| n == *label))
            .map(|(label, reference)| (*label, differing_entries(&columns, reference)))
            .min_by_key(|(_, e)| e.len())?;
        if !best.1.is_empty() && (named.is_some() || best.1.len() <= 8) {
            return Some(MatrixMismatch {
                name,
                line: l.line,
                matrix: best.0,
                entries: best.1,
            });
        }
    }
    None
}
