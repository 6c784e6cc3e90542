//! Clipping in homogeneous clip space, before the perspective division.
//!
//! A clip-space point `(x, y, z, w)` is inside the view volume when `−w ≤ x, y, z ≤ w`; the six
//! planes are tested as signed distances `w + x ≥ 0`, `w − x ≥ 0`, … . pipelens clips against
//! **all six planes** (near first) and one more, `w ≥ ε`, so that no vertex with `w ≤ 0` ever
//! reaches the perspective division (for a perspective projection the near plane already
//! implies `w ≥ near > 0`; the extra plane guards arbitrary matrices). There is no guard band:
//! every vertex that reaches the rasterizer lies in the view volume, so window coordinates stay
//! inside the viewport.
//!
//! The algorithm is Sutherland–Hodgman: the polygon is cut by one plane after the other. A new
//! vertex on an edge `a → b` is `a + t·(b − a)` with `t = d_a / (d_a − d_b)`, computed from the
//! inside end, so that two triangles sharing an edge get the very same new vertex (no cracks).
//! Everything linear in clip space (barycentric weights, hence every attribute) is interpolated
//! with the same `t`.

use glam::{Vec3, Vec4};
use serde::Serialize;

/// The smallest `w` a vertex may have after clipping.
pub const W_EPSILON: f32 = 1e-5;

/// A plane of the view volume in clip space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ClipPlane {
    /// `z ≥ −w` (the near plane).
    Near,
    /// `x ≥ −w`.
    Left,
    /// `x ≤ w`.
    Right,
    /// `y ≥ −w`.
    Bottom,
    /// `y ≤ w`.
    Top,
    /// `z ≤ w` (the far plane).
    Far,
    /// `w ≥ ε`: the point is in front of the eye (guards matrices that are not projections).
    W,
}

impl ClipPlane {
    /// The planes in the order they are applied.
    pub const ALL: [ClipPlane; 7] = [
        Self::Near,
        Self::Left,
        Self::Right,
        Self::Bottom,
        Self::Top,
        Self::Far,
        Self::W,
    ];

    /// Signed distance of `p` to the plane, up to a positive factor; `≥ 0` is inside.
    #[must_use]
    #[inline]
    pub fn distance(self, p: Vec4) -> f32 {
        match self {
            Self::Near => p.w + p.z,
            Self::Left => p.w + p.x,
            Self::Right => p.w - p.x,
            Self::Bottom => p.w + p.y,
            Self::Top => p.w - p.y,
            Self::Far => p.w - p.z,
            Self::W => p.w - W_EPSILON,
        }
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

/// Bit `k` set when `p` is outside plane `ClipPlane::ALL[k]`.
#[must_use]
#[inline]
pub fn outcode(p: Vec4) -> u8 {
    ClipPlane::ALL
        .iter()
        .filter(|pl| !(pl.distance(p) >= 0.0))
        .fold(0, |m, pl| m | pl.bit())
}

/// The part of the segment from `a` to `b` (clip space) in front of the camera, `w ≥ ε`
/// ([`W_EPSILON`]): `None` when both ends are behind; otherwise the end behind, if any, moved
/// along the segment to `t = (ε − w_a)/(w_b − w_a)` (a hair inside, so that it divides). A line
/// drawn over a picture (a frustum's edge running past the viewer) keeps its part in front
/// rather than vanishing whole.
#[must_use]
pub fn segment_in_front(a: Vec4, b: Vec4) -> Option<(Vec4, Vec4)> {
    let eps = W_EPSILON;
    match (a.w > eps, b.w > eps) {
        (false, false) => None,
        (true, true) => Some((a, b)),
        (front_a, _) => {
            let cut = a.lerp(b, (eps * 1.001 - a.w) / (b.w - a.w));
            Some(if front_a { (a, cut) } else { (cut, b) })
        }
    }
}

/// A vertex of a (clipped) polygon: its clip-space position and its barycentric weights with
/// respect to the original triangle (the corners are `(1,0,0)`, `(0,1,0)`, `(0,0,1)`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ClipVertex {
    /// Position in clip space.
    pub clip: Vec4,
    /// Weights of the original triangle's three vertices.
    pub bary: Vec3,
}

impl ClipVertex {
    fn lerp(self, other: Self, t: f32) -> Self {
        Self {
            clip: self.clip + (other.clip - self.clip) * t,
            bary: self.bary + (other.bary - self.bary) * t,
        }
    }
}

/// What clipping did to a triangle.
#[derive(Clone, Debug, PartialEq)]
pub enum ClipOutcome {
    /// Entirely inside: drawn as it is.
    Inside,
    /// Entirely outside this plane (all three vertices are): dropped.
    Outside(ClipPlane),
    /// Cut: the polygon that remains (3 to 10 vertices), drawn as a fan of triangles.
    Clipped(Vec<ClipVertex>),
}

/// Clips the triangle `v` against the view volume.
#[must_use]
pub fn clip_triangle(v: [ClipVertex; 3]) -> ClipOutcome {
    let codes = v.map(|p| outcode(p.clip));
    if codes.iter().all(|&c| c == 0) {
        return ClipOutcome::Inside;
    }
    let common = codes[0] & codes[1] & codes[2];
    if let Some(&plane) = ClipPlane::ALL.iter().find(|p| common & p.bit() != 0) {
        return ClipOutcome::Outside(plane);
    }
    let crossed = codes[0] | codes[1] | codes[2];
    let mut poly: Vec<ClipVertex> = v.to_vec();
    let mut next = Vec::with_capacity(10);
    for plane in ClipPlane::ALL {
        if crossed & plane.bit() == 0 {
            continue;
        }
        clip_polygon_against(&poly, plane, &mut next);
        std::mem::swap(&mut poly, &mut next);
        if poly.len() < 3 {
            return ClipOutcome::Outside(plane);
        }
    }
    ClipOutcome::Clipped(poly)
}

/// One Sutherland–Hodgman pass: keeps the part of `poly` on the inside of `plane`.
fn clip_polygon_against(poly: &[ClipVertex], plane: ClipPlane, out: &mut Vec<ClipVertex>) {
    out.clear();
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (da, db) = (plane.distance(a.clip), plane.distance(b.clip));
        let (a_in, b_in) = (da >= 0.0, db >= 0.0);
        if a_in {
            out.push(a);
        }
        if a_in != b_in {
            // Always interpolate from the inside end, so a shared edge gives the same point.
            let crossing = if a_in {
                a.lerp(b, da / (da - db))
            } else {
                b.lerp(a, db / (db - da))
            };
            out.push(crossing);
        }
    }
}
