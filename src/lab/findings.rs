//! What a lab's check finds besides the pixel count: where the student's run first parts from
//! pipelens' own at a pixel, the first vertex whose clip position is off, and a matrix the
//! student built compared entry by entry with pipelens' own. The app's card and `pipelens grade`
//! both read them.

use pipeline::capture::FrameCapture;
use pipeline::scene::Scene;
use pipeline::shader::HookKind;

/// How far (in the curve's units) a student's curve point may be from pipelens' `b(t)` and
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
    /// For a vector: its length in each run (a normal not normalized shows here).
    pub lengths: Option<(f64, f64)>,
    /// Where the runs were compared: the vertex shader's at this row of the vertex table (a
    /// corner of the first wrong pixel's triangle), or `None` for the fragment shader's at the
    /// inspected pixel.
    pub vertex: Option<u32>,
}

/// The numbers of a traced value (`vec3(0.000, 0.707, 0.707)` → 0, 0.707, 0.707), and its
/// words (`true`), each as a token.
fn tokens(value: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut chars = value.chars().peekable();
    while let Some(&c) = chars.peek() {
        if c.is_ascii_alphabetic() || c == '_' {
            let mut word = String::new();
            while let Some(&c) = chars.peek() {
                if !(c.is_ascii_alphanumeric() || c == '_') {
                    break;
                }
                word.push(c);
                chars.next();
            }
            // A constructor's name (`vec3(`) is not a value.
            if chars.peek() != Some(&'(') {
                out.push(word);
            }
        } else if c.is_ascii_digit() || c == '-' || c == '.' {
            let mut number = String::new();
            while let Some(&c) = chars.peek() {
                if !(c.is_ascii_alphanumeric() || c == '-' || c == '.' || c == '+') {
                    break;
                }
                number.push(c);
                chars.next();
            }
            out.push(number);
        } else {
            chars.next();
        }
    }
    out
}

/// Whether two traced values are the same as far as the trace shows them (three decimals, or
/// three significant digits).
fn same_value(a: &str, b: &str) -> bool {
    let (ta, tb) = (tokens(a), tokens(b));
    ta.len() == tb.len()
        && ta
            .iter()
            .zip(&tb)
            .all(|(x, y)| match (x.parse::<f64>(), y.parse::<f64>()) {
                (Ok(x), Ok(y)) => (x - y).abs() <= 0.0015 + 0.002 * x.abs().max(y.abs()),
                _ => x == y,
            })
}

/// The length of a traced vector of three or four numbers.
fn length(value: &str) -> Option<f64> {
    let v: Vec<f64> = tokens(value)
        .iter()
        .map(|t| t.parse::<f64>())
        .collect::<Result<_, _>>()
        .ok()?;
    (v.len() == 3).then(|| v.iter().map(|x| x * x).sum::<f64>().sqrt())
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
#[must_use]
pub fn first_difference(
    mine: &[pipeline::shader::TraceLine],
    theirs: &[pipeline::shader::TraceLine],
) -> Option<Mismatch> {
    // Each run's values by stretch: the stretch (how many loop iterations began before it), the
    // name, its line and its last value there, in the order first assigned.
    let stretches = |trace: &[pipeline::shader::TraceLine]| {
        let mut stretch = 0;
        let mut values: Vec<((usize, String), (usize, String))> = Vec::new();
        for l in trace {
            if l.text.starts_with("loop: iteration") {
                stretch += 1;
                continue;
            }
            let Some((name, value)) = l.text.split_once(" = ") else {
                continue;
            };
            let key = (stretch, name.to_owned());
            match values.iter_mut().find(|(k, _)| *k == key) {
                Some((_, v)) => *v = (l.line, value.to_owned()),
                None => values.push((key, (l.line, value.to_owned()))),
            }
        }
        values
    };
    let reference_values: std::collections::HashMap<_, _> = stretches(theirs).into_iter().collect();
    let paired: Vec<_> = stretches(mine)
        .into_iter()
        .filter_map(|(key, (line, yours))| {
            let (_, theirs) = reference_values.get(&key)?;
            Some((key.1, line, yours, theirs.clone()))
        })
        .collect();
    let mismatch = |(name, line, yours, theirs): &(String, usize, String, String)| Mismatch {
        name: name.clone(),
        line: *line,
        lengths: length(yours).zip(length(theirs)),
        yours: yours.clone(),
        theirs: theirs.clone(),
        vertex: None,
    };
    // A vector of length 1 in pipelens' run that is not in the student's — a normal left
    // unnormalized — says more than the first value it puts off, however small the gap.
    let unit = paired.iter().find(|(_, _, yours, theirs)| {
        length(yours)
            .zip(length(theirs))
            .is_some_and(|(y, t)| (t - 1.0).abs() < 0.001 && (y - 1.0).abs() > 0.0015)
    });
    if let Some(m) = unit.or_else(|| paired.iter().find(|(_, _, y, t)| !same_value(y, t))) {
        return Some(mismatch(m));
    }
    // Nothing differs stretch by stretch (the runs loop differently, or assign their values in
    // different stretches): the last value of each name both runs assign — the output's at
    // least — compared whatever the stretch.
    let last = |values: Vec<((usize, String), (usize, String))>| {
        let mut out: Vec<(String, (usize, String))> = Vec::new();
        for ((_, name), v) in values {
            match out.iter_mut().find(|(n, _)| *n == name) {
                Some((_, old)) => *old = v,
                None => out.push((name, v)),
            }
        }
        out
    };
    let theirs_last: std::collections::HashMap<_, _> =
        last(stretches(theirs)).into_iter().collect();
    last(stretches(mine))
        .into_iter()
        .find_map(|(name, (line, yours))| {
            let (_, theirs) = theirs_last.get(&name)?;
            (!same_value(&yours, theirs)).then(|| (name, line, yours, theirs.clone()))
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

/// In the student's vertex-shader run, the first 4×4 matrix assigned that is not pipelens' own:
/// one named as pipelens names its matrices (`model`, `view`, `projection`, `mvp`, …) stands for
/// that one; another is compared with M (the vertex's object's), V, P, V·M and P·V·M and stands
/// for the one it differs from in the fewest entries (at most 8 of 16, else it is some other
/// matrix). Entries agree within the trace's three decimals.
#[must_use]
pub fn wrong_matrix(
    trace: &pipeline::capture::VertexTrace,
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
    ];
    for l in &trace.trace {
        let Some((name, value)) = l.text.split_once(" = ") else {
            continue;
        };
        if !value.starts_with("mat4(") {
            continue;
        }
        let numbers: Vec<f32> = tokens(value)
            .iter()
            .filter_map(|t| t.parse::<f32>().ok())
            .collect();
        let Ok(columns) = <[f32; 16]>::try_from(numbers) else {
            continue;
        };
        // A matrix named as pipelens names its uniforms stands for that one; another for
        // the one it is nearest.
        let lower = name.to_ascii_lowercase();
        let named = match lower.as_str() {
            "model" | "m" | "model_matrix" => Some("M"),
            "view" | "v" | "view_matrix" | "look_at" | "lookat" => Some("V"),
            "projection" | "proj" | "p" | "perspective" | "projection_matrix" => Some("P"),
            "model_view" | "mv" | "modelview" => Some("V·M"),
            "mvp" => Some("P·V·M"),
            _ => None,
        };
        let best = candidates
            .iter()
            .filter(|(label, _)| named.is_none_or(|n| n == *label))
            .map(|(label, reference)| (*label, differing_entries(&columns, reference)))
            .min_by_key(|(_, e)| e.len())?;
        if !best.1.is_empty() && best.1.len() <= 8 {
            return Some(MatrixMismatch {
                name: name.to_owned(),
                line: l.line,
                matrix: best.0,
                entries: best.1,
            });
        }
    }
    None
}
