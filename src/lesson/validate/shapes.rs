//! The built-in shapes with parameters of their own beyond a count: a Bézier curve's
//! construction, a Bézier patch, an implicit surface.

use std::ops::Range;

use pipeline::mesh::BuiltinMesh;
use pipeline::mesh::implicit::{Implicit, ImplicitShape};
use pipeline::mesh::signal::{Signal, Wheel};

use super::Checker;
use crate::lesson::raw::RawMeshTable;

/// `{ builtin = "bezier", points = [[x, y] × 4], t = …, levels = … }`.
pub(super) fn bezier(
    c: &mut Checker<'_>,
    span: Range<usize>,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let points = t.points.as_deref().unwrap_or(&[]);
    let finite = points
        .iter()
        .flatten()
        .all(|v| v.is_finite() && v.abs() <= 1e6);
    let [a, b, d, e] = points else {
        c.error(
            span,
            format!(
                "a bezier mesh needs `points` = four control points [[x, y], …], got {}",
                points.len()
            ),
        );
        return None;
    };
    if !finite {
        c.error(
            span,
            "the control points must be finite numbers of magnitude at most 1e6",
        );
        return None;
    }
    let param = t.t.unwrap_or(1.0);
    if !(0.0..=1.0).contains(&param) {
        c.error(
            span,
            format!("`t` of a bezier mesh must be from 0 to 1, got {param}"),
        );
        return None;
    }
    let levels = t.levels.unwrap_or(3);
    let Ok(levels @ 0..=3) = u8::try_from(levels) else {
        c.error(
            span,
            format!(
                "`levels` of a bezier mesh is how many de Casteljau levels are drawn, 0 to 3; got {levels}"
            ),
        );
        return None;
    };
    let v = |p: &[f64; 2]| glam::Vec2::new(p[0] as f32, p[1] as f32);
    Some(BuiltinMesh::Bezier {
        points: [v(a), v(b), v(d), v(e)],
        t: param as f32,
        levels,
    })
}

/// `{ builtin = "bezier_patch", heights = [[h × 4] × 4], u = …, v = …, levels = … }`.
pub(super) fn bezier_patch(
    c: &mut Checker<'_>,
    span: Range<usize>,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let default = [
        [0.0; 4],
        [0.0, 1.0, 1.0, 0.0],
        [0.0, 1.0, 1.0, 0.0],
        [0.0; 4],
    ];
    let rows = t.heights.clone().unwrap_or_else(|| default.to_vec());
    let Ok(rows) = <[[f64; 4]; 4]>::try_from(rows.as_slice()) else {
        c.error(
            span,
            format!(
                "a bezier_patch needs `heights` = four rows of four numbers [[h, h, h, h], …], got {} rows",
                rows.len()
            ),
        );
        return None;
    };
    if !rows
        .iter()
        .flatten()
        .all(|h| h.is_finite() && h.abs() <= 1e3)
    {
        c.error(
            span,
            "the heights must be finite numbers of magnitude at most 1000",
        );
        return None;
    }
    let what = "bezier_patch";
    let u = ranged(c, &span, what, "u", t.u, (0.5, 0.0, 1.0))?;
    let v = ranged(c, &span, what, "v", t.v, (0.5, 0.0, 1.0))?;
    let levels = t.levels.unwrap_or(2);
    let Ok(levels @ 0..=2) = u8::try_from(levels) else {
        c.error(
            span,
            format!("`levels` of a bezier_patch is 0 (the net), 1 (the rows' curves) or 2 (down to b(u, v)); got {levels}"),
        );
        return None;
    };
    Some(BuiltinMesh::BezierPatch {
        heights: rows.map(|r| r.map(|h| h as f32)),
        u,
        v,
        levels,
    })
}

/// `{ builtin = "implicit", shape = "blend", gap = 1.3, smooth = 0.4, resolution = 32, cloud = 0 }`.
pub(super) fn implicit(
    c: &mut Checker<'_>,
    span: Range<usize>,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let written = t.shape.as_deref().unwrap_or("sphere");
    let Some(shape) = ImplicitShape::NAMES
        .iter()
        .find(|(n, _)| *n == written)
        .map(|(_, s)| *s)
    else {
        let names: Vec<&str> = ImplicitShape::NAMES.iter().map(|(n, _)| *n).collect();
        c.error(
            span,
            format!(
                "`shape` of an implicit surface is one of {}; got \"{written}\"",
                names.join(", ")
            ),
        );
        return None;
    };
    let what = "implicit surface";
    let int = |v: Option<i64>| v.map(|n| n as f64);
    let gap = ranged(c, &span, what, "gap", t.gap, (1.4, 0.0, 3.0))?;
    let smooth = ranged(c, &span, what, "smooth", t.smooth, (0.3, 0.0, 2.0))?;
    let resolution = ranged(
        c,
        &span,
        what,
        "resolution",
        int(t.resolution),
        (32.0, 4.0, 96.0),
    )?;
    let points = ranged(c, &span, what, "cloud", int(t.cloud), (0.0, 0.0, 20_000.0))?;
    Some(BuiltinMesh::Implicit(Implicit {
        shape,
        gap,
        smooth,
        resolution: resolution as u32,
        points: points as u32,
    }))
}

/// A number of a built-in shape's table within `[min, max]`, or its default; an error names it.
fn ranged(
    c: &mut Checker<'_>,
    span: &Range<usize>,
    what: &str,
    key: &str,
    v: Option<f64>,
    (default, min, max): (f32, f32, f32),
) -> Option<f32> {
    match v {
        None => Some(default),
        Some(x) if (f64::from(min)..=f64::from(max)).contains(&x) => Some(x as f32),
        Some(x) => {
            c.error(
                span.clone(),
                format!("`{key}` of a {what} must be from {min} to {max}, got {x}"),
            );
            None
        }
    }
}

/// `{ builtin = "signal", frequency = 3, rate = 20, blur = 0 }`.
pub(super) fn signal(
    c: &mut Checker<'_>,
    span: Range<usize>,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let frequency = ranged(
        c,
        &span,
        "signal",
        "frequency",
        t.frequency,
        (3.0, 0.0, 40.0),
    )?;
    let rate = ranged(c, &span, "signal", "rate", t.rate, (20.0, 1.0, 100.0))?;
    let blur = ranged(c, &span, "signal", "blur", t.blur, (0.0, 0.0, 4.0))?;
    Some(BuiltinMesh::Signal(Signal {
        frequency,
        rate,
        blur,
    }))
}

/// `{ builtin = "wheel", spokes = 8, step = 40, frames = 5 }`.
pub(super) fn wheel(
    c: &mut Checker<'_>,
    span: Range<usize>,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let int = |v: Option<i64>| v.map(|n| n as f64);
    let spokes = ranged(c, &span, "wheel", "spokes", int(t.spokes), (8.0, 1.0, 36.0))?;
    let step = ranged(c, &span, "wheel", "step", t.step, (20.0, -360.0, 360.0))?;
    let frames = ranged(c, &span, "wheel", "frames", int(t.frames), (5.0, 1.0, 8.0))?;
    Some(BuiltinMesh::Wheel(Wheel {
        spokes: spokes as u32,
        step,
        frames: frames as u32,
    }))
}
