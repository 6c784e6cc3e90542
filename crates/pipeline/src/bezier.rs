//! Bézier curves: the de Casteljau construction and the Bernstein form. The drawing of a
//! cubic's construction as a mesh is the built-in mesh `bezier` (`mesh::BuiltinMesh::Bezier`).

use glam::Vec2;

/// De Casteljau's construction at `t`: level 0 is the control points; level k + 1 has the points
/// `(1 − t)·a + t·b` of each pair of neighbours of level k; the last level is the curve point.
#[must_use]
pub fn de_casteljau(points: &[Vec2], t: f32) -> Vec<Vec<Vec2>> {
    let mut levels = vec![points.to_vec()];
    while let Some(last) = levels.last() {
        if last.len() <= 1 {
            break;
        }
        let next = last.windows(2).map(|w| w[0].lerp(w[1], t)).collect();
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
pub fn point(points: &[Vec2], t: f32) -> Vec2 {
    let n = points.len().saturating_sub(1) as u32;
    points
        .iter()
        .enumerate()
        .map(|(i, p)| *p * bernstein(n, i as u32, t))
        .sum()
}
