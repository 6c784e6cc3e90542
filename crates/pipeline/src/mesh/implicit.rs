//! The built-in mesh `implicit`: a surface given by a signed distance function f(p) = 0 (inside
//! where f < 0), made drawable either by **polygonizing** it (Naive Surface Nets from the
//! `fast-surface-nets` crate, over f sampled on a grid) or as a **point cloud** (points pushed
//! onto the surface along the gradient).

use fast_surface_nets::ndshape::{RuntimeShape, Shape};
use fast_surface_nets::{SurfaceNetsBuffer, surface_nets};
use glam::{Vec2, Vec3};
use serde::Serialize;

use super::Mesh;

/// The half-size of the sampled cube `[−H, H]³`.
const HALF: f32 = 1.7;

/// Which implicit surface: one primitive, or two combined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ImplicitShape {
    /// `f = |p| − 0.8`.
    Sphere,
    /// A ring of radius 0.9 and tube radius 0.3 around y: `f = |(|p_xz| − 0.9, p_y)| − 0.3`.
    Torus,
    /// Two spheres of radius 0.6 at x = ∓gap/2, blended: `f = smin(a, b, k)`.
    Blend,
    /// A sphere (radius 0.7, at x = −gap/2) and a box (half-size 0.55, at x = +gap/2): `min(a, b)`.
    Union,
    /// The same two: `max(a, b)`.
    Intersection,
    /// The same two: `max(a, −b)`, the sphere with the box cut out.
    Difference,
}

impl ImplicitShape {
    /// The names a scene file uses.
    pub const NAMES: [(&'static str, Self); 6] = [
        ("sphere", Self::Sphere),
        ("torus", Self::Torus),
        ("blend", Self::Blend),
        ("union", Self::Union),
        ("intersection", Self::Intersection),
        ("difference", Self::Difference),
    ];
}

/// An implicit surface and how it is made drawable.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Implicit {
    /// The surface.
    pub shape: ImplicitShape,
    /// The distance between the two primitives' centres (blend and CSG).
    pub gap: f32,
    /// The blend's smoothing distance `k` (0: a sharp `min`).
    pub smooth: f32,
    /// Grid cells per axis for polygonizing (4…96).
    pub resolution: u32,
    /// 0: polygonize; n > 0: a cloud of n points instead.
    pub points: u32,
}

/// The distance from `p` to a sphere of radius `r` at `c` (negative inside).
fn sphere(p: Vec3, c: Vec3, r: f32) -> f32 {
    (p - c).length() - r
}

/// The signed distance from `p` to an axis-aligned box of half-sizes `h` centred at `c`.
fn cuboid(p: Vec3, c: Vec3, h: Vec3) -> f32 {
    let q = (p - c).abs() - h;
    q.max(Vec3::ZERO).length() + q.max_element().min(0.0)
}

/// The polynomial smooth minimum: `min(a, b) − k·s²/4` with `s = max(k − |a − b|, 0)/k`, equal
/// to `min(a, b)` where the two differ by more than `k`.
#[must_use]
pub fn smooth_min(a: f32, b: f32, k: f32) -> f32 {
    if k <= 0.0 {
        return a.min(b);
    }
    let s = (k - (a - b).abs()).max(0.0) / k;
    a.min(b) - k * s * s / 4.0
}

impl Implicit {
    /// `f(p)`: negative inside, zero on the surface, positive outside (a distance, or close
    /// to one for the blend and the CSG results).
    #[must_use]
    pub fn f(&self, p: Vec3) -> f32 {
        let half = Vec3::X * (self.gap / 2.0);
        match self.shape {
            ImplicitShape::Sphere => sphere(p, Vec3::ZERO, 0.8),
            ImplicitShape::Torus => {
                Vec2::new(Vec2::new(p.x, p.z).length() - 0.9, p.y).length() - 0.3
            }
            ImplicitShape::Blend => {
                smooth_min(sphere(p, -half, 0.6), sphere(p, half, 0.6), self.smooth)
            }
            ImplicitShape::Union | ImplicitShape::Intersection | ImplicitShape::Difference => {
                let a = sphere(p, -half, 0.7);
                let b = cuboid(p, half, Vec3::splat(0.55));
                match self.shape {
                    ImplicitShape::Union => a.min(b),
                    ImplicitShape::Intersection => a.max(b),
                    _ => a.max(-b),
                }
            }
        }
    }

    /// The unit gradient of f at `p` by central differences: the outward normal on the surface.
    #[must_use]
    pub fn normal(&self, p: Vec3) -> Vec3 {
        let e = 1e-3;
        let d = |v: Vec3| self.f(p + v) - self.f(p - v);
        Vec3::new(d(Vec3::X * e), d(Vec3::Y * e), d(Vec3::Z * e))
            .try_normalize()
            .unwrap_or(Vec3::Y)
    }

    /// The drawable mesh: the polygonized surface, or the point cloud.
    #[must_use]
    pub fn build(&self) -> Mesh {
        if self.points > 0 {
            self.point_cloud()
        } else {
            self.polygonize()
        }
    }

    /// Naive Surface Nets over f sampled at the corners of a `resolution³` grid of `[−1.7, 1.7]³`
    /// (one sample of padding beyond each face, so a surface touching the box is still closed);
    /// the normals are f's gradient at each vertex.
    fn polygonize(&self) -> Mesh {
        let cells = self.resolution.clamp(4, 96);
        let n = cells + 3; // samples per axis: cells + 1 corners and a padding sample each side
        let step = 2.0 * HALF / cells as f32;
        let origin = Vec3::splat(-HALF - step);
        let shape = RuntimeShape::<u32, 3>::new([n, n, n]);
        let sdf: Vec<f32> = (0..shape.size())
            .map(|i| {
                let [x, y, z] = shape.delinearize(i);
                self.f(origin + Vec3::new(x as f32, y as f32, z as f32) * step)
            })
            .collect();
        let mut buffer = SurfaceNetsBuffer::default();
        surface_nets(&sdf, &shape, [0; 3], [n - 1; 3], &mut buffer);
        let positions: Vec<Vec3> = buffer
            .positions
            .iter()
            .map(|p| origin + Vec3::from_array(*p) * step)
            .collect();
        let normals: Vec<Vec3> = positions.iter().map(|p| self.normal(*p)).collect();
        let mut indices: Vec<[u32; 3]> = buffer
            .indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect();
        // Counter-clockwise seen from outside: where a triangle's winding disagrees with the
        // outward gradient, swap two corners.
        for t in &mut indices {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            let outward = normals[t[0] as usize] + normals[t[1] as usize] + normals[t[2] as usize];
            if (b - a).cross(c - a).dot(outward) < 0.0 {
                t.swap(1, 2);
            }
        }
        Mesh {
            name: format!("implicit({}³ grid)", cells),
            uvs: Vec::new(),
            colors: Vec::new(),
            positions,
            normals,
            indices,
            labels: Vec::new(),
        }
    }

    /// `points` points on the surface: starting from a fixed pseudo-random spread in the cube,
    /// each is moved along the gradient, `p ← p − f(p)·∇f`, until f is near 0; each is drawn as
    /// a small cube, lit with the surface's normal there.
    fn point_cloud(&self) -> Mesh {
        let mut m = Mesh {
            name: format!("point cloud ({} points)", self.points),
            ..Mesh::default()
        };
        let mut seed = 0x9e37_79b9_u32;
        let mut next = move || {
            // xorshift32: the same cloud every time.
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed as f32 / u32::MAX as f32 * 2.0 - 1.0
        };
        let count = self.points.min(20_000);
        let mut made = 0;
        let mut tries = 0;
        while made < count && tries < count * 8 {
            tries += 1;
            let mut p = Vec3::new(next(), next(), next()) * HALF;
            for _ in 0..12 {
                p -= self.normal(p) * self.f(p);
            }
            if self.f(p).abs() > 1e-3 {
                continue;
            }
            let n = self.normal(p);
            dot(&mut m, p, n, 0.018);
            made += 1;
        }
        m
    }
}

/// A small cube at `p`, every face with the surface normal `n` (so the point shades as the
/// surface would there).
fn dot(m: &mut Mesh, p: Vec3, n: Vec3, h: f32) {
    let base = m.positions.len() as u32;
    for k in 0..8u32 {
        let corner = Vec3::new(
            if k & 1 == 0 { -h } else { h },
            if k & 2 == 0 { -h } else { h },
            if k & 4 == 0 { -h } else { h },
        );
        m.positions.push(p + corner);
        m.normals.push(n);
    }
    // The six faces, counter-clockwise seen from outside.
    for [a, b, c, d] in [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ] {
        m.indices.push([base + a, base + b, base + c]);
        m.indices.push([base + a, base + c, base + d]);
    }
}
