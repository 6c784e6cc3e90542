//! Bézier curves: the de Casteljau construction and the Bernstein form. The drawing of a
//! cubic's construction as a mesh is the built-in mesh `bezier` (`mesh::BuiltinMesh::Bezier`).

use glam::{Vec2, Vec3};

/// A point that can be interpolated linearly: the de Casteljau construction works the same in
/// the plane (a curve's construction) and in space (a surface patch's).
pub trait Point: Copy + std::ops::Mul<f32, Output = Self> + std::iter::Sum<Self> {
    /// `(1 − t)·self + t·other`.
    #[must_use]
    fn lerp_to(self, other: Self, t: f32) -> Self;
}

impl Point for Vec2 {
    fn lerp_to(self, other: Self, t: f32) -> Self {
        self.lerp(other, t)
    }
}

impl Point for Vec3 {
    fn lerp_to(self, other: Self, t: f32) -> Self {
        self.lerp(other, t)
    }
}

/// De Casteljau's construction at `t`: level 0 is the control points; level k + 1 has the points
/// `(1 − t)·a + t·b` of each pair of neighbours of level k; the last level is the curve point.
/// The two points of the level before the last give the tangent: `b′(t) = n·(b − a)` for a curve
/// of degree n.
#[must_use]
pub fn de_casteljau<P: Point>(points: &[P], t: f32) -> Vec<Vec<P>> {
    let mut levels = vec![points.to_vec()];
    while let Some(last) = levels.last() {
        if last.len() <= 1 {
            break;
        }
        let next = last.windows(2).map(|w| w[0].lerp_to(w[1], t)).collect();
        levels.push(next);
    }
    levels
}

/// The Bernstein polynomial `B_i^n(t) = C(n, i)·t^i·(1 − t)^(n−i)`.
#[must_use]
pub fn bernstein(n: u32, i: u32, t: f32) -> f32 {
    if i > n {
        return 0.0;
    }
    let binomial = (0..i).fold(1.0f64, |c, k| c * f64::from(n - k) / f64::from(k + 1));
    (binomial * f64::from(t).powi(i as i32) * f64::from(1.0 - t).powi((n - i) as i32)) as f32
}

/// The curve point `b(t) = Σ_i B_i^n(t)·P_i` (the Bernstein form; equals de Casteljau's).
#[must_use]
pub fn point<P: Point>(points: &[P], t: f32) -> P {
    let n = points.len().saturating_sub(1) as u32;
    points
        .iter()
        .enumerate()
        .map(|(i, p)| *p * bernstein(n, i as u32, t))
        .sum()
}

/// A point of a tensor-product Bézier patch by de Casteljau **in u, then in v**: each row
/// `P_i0 … P_i3` is a curve in u whose point at `u` is `Q_i`; the `Q_i` are the control points
/// of a curve in v whose point at `v` is `b(u, v)`. Returns the `Q_i`, `b(u, v)` and the unit
/// normal `∂b/∂v × ∂b/∂u` (each partial from the construction's last two levels; up, +y, for a
/// patch whose rows run along +x and follow each other along +z).
#[must_use]
pub fn patch_point(rows: &[[Vec3; 4]; 4], u: f32, v: f32) -> ([Vec3; 4], Vec3, Vec3) {
    let last_two = |pts: &[Vec3], t: f32| {
        let levels = de_casteljau(pts, t);
        let n = levels.len();
        (levels[n - 1][0], levels[n - 2][1] - levels[n - 2][0])
    };
    let q = rows.map(|row| last_two(&row, u).0);
    let (b, dv) = last_two(&q, v);
    let columns: [[Vec3; 4]; 4] = std::array::from_fn(|j| std::array::from_fn(|i| rows[i][j]));
    let r = columns.map(|col| last_two(&col, v).0);
    let (_, du) = last_two(&r, u);
    let n = dv.cross(du).try_normalize().unwrap_or(Vec3::Y);
    (q, b, n)
}
