//! The built-in mesh `bezier_patch`: a bicubic Bézier patch with its control net and the
//! construction of one of its points, de Casteljau in u then in v.

use glam::{Vec2, Vec3};

use super::{Mesh, MeshLabel};
use crate::bezier;

/// The side of the square the control net stands on, in x and z.
const SIDE: f32 = 2.4;
/// Surface subdivisions per parameter.
const GRID: usize = 24;

const SURFACE: Vec3 = Vec3::new(0.55, 0.68, 0.85);
const NET: Vec3 = Vec3::new(0.85, 0.85, 0.88);
const ROWS: Vec3 = Vec3::new(0.3, 0.8, 0.4);
const COLUMN: Vec3 = Vec3::new(0.35, 0.6, 1.0);
const POINT: Vec3 = Vec3::new(1.0, 0.85, 0.2);

/// The control points `P_ij` of a patch whose heights are `heights[i][j]`: row `i` at
/// `z = −1.2 + 0.8·i`, column `j` at `x = −1.2 + 0.8·j`, so each row runs along +x.
#[must_use]
pub fn control_points(heights: &[[f32; 4]; 4]) -> [[Vec3; 4]; 4] {
    let at = |k: usize| -SIDE / 2.0 + SIDE / 3.0 * k as f32;
    std::array::from_fn(|i| std::array::from_fn(|j| Vec3::new(at(j), heights[i][j], at(i))))
}

/// The `(u, v)` of the surface grid's vertices, row by row (v), each row along u: 25 × 25.
#[must_use]
pub fn patch_parameters() -> Vec<Vec2> {
    (0..=GRID)
        .flat_map(|a| (0..=GRID).map(move |c| Vec2::new(c as f32, a as f32) / GRID as f32))
        .collect()
}

/// Where a patch's drawing takes its surface points: the points of the patch with control
/// points `rows` at the given `(u, v)`s, or why there are none (`E`).
pub type PatchPoints<'a, E> = dyn Fn(&[[Vec3; 4]; 4], &[Vec2]) -> Result<Vec<Vec3>, E> + 'a;

/// Builds the patch: the surface `b(u, v)` on a 24×24 grid with its exact normals, the control
/// net (white bars, a cube at each control point) and, as `levels` asks, the construction at
/// `(u, v)`: 1 adds each row's curve in u and its point `Q_i` (green); 2 adds the curve in v
/// through the `Q_i`, its control polygon (blue) and `b(u, v)` (yellow), labelled.
#[must_use]
pub fn patch_mesh(heights: &[[f32; 4]; 4], u: f32, v: f32, levels: u8) -> Mesh {
    let own = |rows: &[[Vec3; 4]; 4], uvs: &[Vec2]| -> Result<_, std::convert::Infallible> {
        Ok(uvs
            .iter()
            .map(|uv| bezier::patch_point(rows, uv.x, uv.y).1)
            .collect())
    };
    match patch_mesh_from(heights, u, v, levels, &own) {
        Ok(m) => m,
        Err(never) => match never {},
    }
}

/// [`patch_mesh`] with the surface's points (and the construction's `b(u, v)`) from `points`:
/// the student's `bezier_patch`, say. The normals stay the patch's exact ones.
///
/// # Errors
/// Why `points` gave none (a run-time error of the student's function).
pub fn patch_mesh_from<E>(
    heights: &[[f32; 4]; 4],
    u: f32,
    v: f32,
    levels: u8,
    points: &PatchPoints<'_, E>,
) -> Result<Mesh, E> {
    let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
    let rows = control_points(heights);
    let mut m = Mesh {
        name: "bezier_patch".into(),
        ..Mesh::default()
    };
    surface(&mut m, &rows, &points(&rows, &patch_parameters())?);
    for i in 0..4 {
        for j in 0..4 {
            cube(&mut m, rows[i][j], 0.05, NET);
            if j < 3 {
                bar(&mut m, rows[i][j], rows[i][j + 1], 0.012, NET);
            }
            if i < 3 {
                bar(&mut m, rows[i][j], rows[i + 1][j], 0.012, NET);
            }
        }
    }
    for (text, p) in [
        ("P00", rows[0][0]),
        ("P03", rows[0][3]),
        ("P30", rows[3][0]),
        ("P33", rows[3][3]),
    ] {
        m.labels.push(MeshLabel {
            position: p + Vec3::new(0.0, 0.18, 0.0),
            text: text.into(),
        });
    }
    let (q, _, _) = bezier::patch_point(&rows, u, v);
    let b = points(&rows, &[Vec2::new(u, v)])?
        .first()
        .copied()
        .unwrap_or(Vec3::ZERO);
    if levels >= 1 {
        for (row, qi) in rows.iter().zip(q) {
            curve(&mut m, row, 0.01, ROWS);
            cube(&mut m, qi, 0.055, ROWS);
        }
    }
    if levels >= 2 {
        for w in q.windows(2) {
            bar(&mut m, w[0], w[1], 0.012, COLUMN);
        }
        curve(&mut m, &q, 0.016, COLUMN);
        cube(&mut m, b, 0.13, POINT);
        m.labels.push(MeshLabel {
            position: b + Vec3::new(0.0, 0.25, 0.0),
            text: format!("b(u, v), u = {u:.2}, v = {v:.2}"),
        });
    }
    Ok(m)
}

/// The surface on a grid: the vertex at [`patch_parameters`]' `k`-th `(u, v)` at `points[k]`,
/// with the patch's exact normal there.
fn surface(m: &mut Mesh, rows: &[[Vec3; 4]; 4], points: &[Vec3]) {
    let base = m.positions.len() as u32;
    for (uv, &p) in patch_parameters().into_iter().zip(points) {
        let (_, _, n) = bezier::patch_point(rows, uv.x, uv.y);
        m.positions.push(p);
        m.normals.push(n);
        m.uvs.push(uv);
        m.colors.push(SURFACE);
    }
    let w = GRID as u32 + 1;
    for a in 0..GRID as u32 {
        for c in 0..GRID as u32 {
            let k = base + a * w + c;
            // Counter-clockwise seen from above (+y): u along +x, v along +z.
            m.indices.push([k, k + w, k + 1]);
            m.indices.push([k + 1, k + w, k + w + 1]);
        }
    }
}

/// A cubic's curve through its control points as a chain of thin bars.
fn curve(m: &mut Mesh, points: &[Vec3], radius: f32, color: Vec3) {
    let samples: Vec<Vec3> = (0..=32)
        .map(|k| bezier::point(points, k as f32 / 32.0))
        .collect();
    for w in samples.windows(2) {
        bar(m, w[0], w[1], radius, color);
    }
}

/// A cube of half-side `h` centred at `p`.
fn cube(m: &mut Mesh, p: Vec3, h: f32, color: Vec3) {
    cuboid(m, p, [Vec3::X * h, Vec3::Y * h, Vec3::Z * h], color);
}

/// A square bar of half-width `r` from `a` to `b` (nothing when they coincide).
fn bar(m: &mut Mesh, a: Vec3, b: Vec3, r: f32, color: Vec3) {
    let d = b - a;
    let Some(dir) = d.try_normalize() else {
        return;
    };
    let side = dir.any_orthonormal_vector();
    let up = dir.cross(side);
    cuboid(m, (a + b) / 2.0, [d / 2.0, side * r, up * r], color);
}

/// A box centred at `c` with half-axes `e` (a right-handed, orthogonal set), each face with its
/// own four vertices and normal so that it shades flat.
fn cuboid(m: &mut Mesh, c: Vec3, e: [Vec3; 3], color: Vec3) {
    for k in 0..3 {
        let (n, s, t) = (e[k], e[(k + 1) % 3], e[(k + 2) % 3]);
        for sign in [1.0f32, -1.0] {
            let normal = (n * sign).normalize_or_zero();
            let base = m.positions.len() as u32;
            // s × t = n for a right-handed set; flipping n flips the winding with t.
            for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                m.positions.push(c + n * sign + s * a + t * (b * sign));
                m.normals.push(normal);
                m.uvs.push(Vec2::ZERO);
                m.colors.push(color);
            }
            m.indices.push([base, base + 1, base + 2]);
            m.indices.push([base, base + 2, base + 3]);
        }
    }
}
