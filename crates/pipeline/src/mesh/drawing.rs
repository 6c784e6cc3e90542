//! Drawings in the plane made of triangles, for the meshes that show a construction or a
//! signal: a line as a strip of thin quads, a dot as a small square, each at a depth `z` and in
//! one colour.

use glam::{Vec2, Vec3};

use super::Mesh;

/// A strip of quads of width `w` along `pts`, at depth `z`.
pub(super) fn polyline(m: &mut Mesh, pts: &[Vec2], w: f32, z: f32, color: Vec3) {
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
pub(super) fn square(m: &mut Mesh, p: Vec2, s: f32, z: f32, color: Vec3) {
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
pub(super) fn quad(m: &mut Mesh, c: [Vec2; 4], z: f32, color: Vec3) {
    let base = m.positions.len() as u32;
    m.positions.extend(c.map(|p| p.extend(z)));
    m.colors.extend([color; 4]);
    m.indices.push([base, base + 1, base + 2]);
    m.indices.push([base, base + 2, base + 3]);
}
