//! A student's curve or surface against pipelens' own, point by point: what a lab with
//! `de_casteljau` or `bezier_patch` is checked by.

/// Where a curve or a surface is evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum At {
    /// A curve's `t`.
    T(f32),
    /// A surface's `(u, v)`.
    Uv(glam::Vec2),
}

/// A student's curve (or surface) compared with pipelens' own, point by point.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveDifference {
    /// Points within the tolerance of pipelens'.
    pub matching: usize,
    /// Points compared.
    pub total: usize,
    /// The largest distance from pipelens' point.
    pub largest: f32,
    /// The first point that does not match: where, the student's point and pipelens' (a
    /// curve's in its plane, `z = 0`).
    pub first: Option<(At, glam::Vec3, glam::Vec3)>,
    /// The tolerance used.
    pub tolerance: f32,
    /// Whether the points are a surface's (evaluated at `(u, v)`), not a curve's.
    pub surface: bool,
}

impl CurveDifference {
    /// The student's `mine[k]` against pipelens' `reference[k]` at `at[k]`: a point matches
    /// within `tolerance`; NaN (a division by zero, say) never does.
    #[must_use]
    pub fn between(
        at: &[At],
        mine: &[glam::Vec3],
        reference: &[glam::Vec3],
        tolerance: f32,
    ) -> Self {
        let mut d = Self {
            matching: 0,
            total: at.len(),
            largest: 0.0,
            first: None,
            tolerance,
            surface: matches!(at.first(), Some(At::Uv(_))),
        };
        for ((&at, &p), &r) in at.iter().zip(mine).zip(reference) {
            let off = p.distance(r);
            let off = if off.is_nan() { f32::INFINITY } else { off };
            d.largest = d.largest.max(off);
            if off <= tolerance {
                d.matching += 1;
            } else if d.first.is_none() {
                d.first = Some((at, p, r));
            }
        }
        d
    }
}

impl CurveDifference {
    /// Whether every point matches.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.matching == self.total
    }
}
