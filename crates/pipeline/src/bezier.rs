//! Bézier curves: the de Casteljau construction and the Bernstein form, and a mesh that draws
//! a cubic's construction in the plane z = 0 (control polygon, the intermediate points at `t`,
//! the curve up to `t`) so the pipeline can render it like any other object.

use glam::{Vec2, Vec3};

use crate::mesh::Mesh;

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

/// Colours of the construction's parts.
const POLYGON: Vec3 = Vec3::new(0.6, 0.62, 0.68);
const LEVELS: [Vec3; 3] = [
    Vec3::new(0.3, 0.8, 0.4),
    Vec3::new(0.35, 0.6, 1.0),
    Vec3::new(1.0, 0.85, 0.2),
];
const CURVE: Vec3 = Vec3::new(0.95, 0.3, 0.25);
const WHOLE_CURVE: Vec3 = Vec3::new(0.55, 0.32, 0.3);

/// Builds the drawing of a cubic's construction at `t`, all in the plane z = 0 (each part a
/// little in front of the one before, so the depth test layers them): the whole curve faintly,
/// the control polygon, the lines of each de Casteljau level, the curve from 0 to `t`, and
/// squares at the control points, the intermediate points and `b(t)`.
#[must_use]
pub fn construction_mesh(points: [Vec2; 4], t: f32) -> Mesh {
    let t = t.clamp(0.0, 1.0);
    let mut m = Mesh {
        name: "bezier".into(),
        ..Mesh::default()
    };
    let samples = |upto: f32| -> Vec<Vec2> {
        let n = ((upto * 160.0).ceil() as usize).max(1);
        (0..=n)
            .map(|k| point(&points, upto * k as f32 / n as f32))
            .collect()
    };
    polyline(&mut m, &samples(1.0), 0.01, 0.0, WHOLE_CURVE);
    polyline(&mut m, &points, 0.018, 0.001, POLYGON);
    let levels = de_casteljau(&points, t);
    for (k, level) in levels.iter().enumerate().skip(1) {
        let color = LEVELS[(k - 1).min(2)];
        polyline(&mut m, level, 0.016, 0.002, color);
    }
    if t > 0.0 {
        polyline(&mut m, &samples(t), 0.035, 0.003, CURVE);
    }
    for p in points {
        square(&mut m, p, 0.05, 0.004, Vec3::ONE);
    }
    for (k, level) in levels.iter().enumerate().skip(1) {
        let last = k == levels.len() - 1;
        for p in level {
            let (size, color) = if last {
                (0.075, LEVELS[2])
            } else {
                (0.04, LEVELS[(k - 1).min(2)])
            };
            square(&mut m, *p, size, 0.005, color);
        }
    }
    m.normals = vec![Vec3::Z; m.positions.len()];
    m
}

/// A strip of quads of width `w` along `pts`, at depth `z`.
fn polyline(m: &mut Mesh, pts: &[Vec2], w: f32, z: f32, color: Vec3) {
    for seg in pts.windows(2) {
        let (a, b) = (seg[0], seg[1]);
        let Some(dir) = (b - a).try_normalize() else {
            continue;
        };
        // Extend each piece by half the width so that joints have no gaps.
        let (a, b) = (a - dir * w / 2.0, b + dir * w / 2.0);
        let side = dir.perp() * (w / 2.0);
        quad(m, [a - side, b - side, b + side, a + side], z, color);
    }
}

/// A square of side `s` centred at `p`.
fn square(m: &mut Mesh, p: Vec2, s: f32, z: f32, color: Vec3) {
    let h = s / 2.0;
    quad(
        m,
        [
            p + Vec2::new(-h, -h),
            p + Vec2::new(h, -h),
            p + Vec2::new(h, h),
            p + Vec2::new(-h, h),
        ],
        z,
        color,
    );
}

/// A counter-clockwise quad as two triangles.
fn quad(m: &mut Mesh, c: [Vec2; 4], z: f32, color: Vec3) {
    let base = m.positions.len() as u32;
    m.positions.extend(c.map(|p| p.extend(z)));
    m.colors.extend([color; 4]);
    m.indices.push([base, base + 1, base + 2]);
    m.indices.push([base, base + 2, base + 3]);
}
