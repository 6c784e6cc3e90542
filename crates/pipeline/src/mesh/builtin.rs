//! The built-in meshes, generated in code so that the product needs no files: the course's
//! triangle, GAMES101's two triangles, the cube, the uv sphere, the plane, the cylinder, the
//! torus, and the drawing of a cubic Bézier curve's de Casteljau construction.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};
use serde::Serialize;

use super::drawing::{polyline, square};
use super::{Mesh, MeshLabel, NormalAveraging};
use crate::bezier;

/// The built-in meshes, generated in code so that the product needs no files.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "shape")]
pub enum BuiltinMesh {
    /// The course's single triangle, corners red, green, blue.
    Triangle,
    /// The two coloured triangles of GAMES101 assignment 2 (world coordinates, z = −2 and −5).
    TwoTriangles,
    /// The unit cube `[−1, 1]³`, 24 vertices, one normal per face.
    Cube,
    /// A sphere of radius 1 with `segments` around and `rings` from pole to pole.
    UvSphere {
        /// Divisions around the y axis (≥ 3).
        segments: u32,
        /// Divisions from the south to the north pole (≥ 2).
        rings: u32,
    },
    /// A square `[−1, 1]²` in the plane y = 0, facing +y, `divisions` quads a side, its
    /// texture coordinates running from 0 to `repeat` (so a texture tiles `repeat` times).
    Plane {
        /// Quads along each side (≥ 1).
        divisions: u32,
        /// How many times a texture repeats across it (> 0).
        repeat: f32,
    },
    /// A closed cylinder of radius 1 along y from −1 to 1.
    Cylinder {
        /// Divisions around the axis (≥ 3).
        segments: u32,
    },
    /// A torus around the y axis: ring radius 1, tube radius `minor`.
    Torus {
        /// Tube radius relative to the ring radius 1 (between 0 and 1).
        minor: f32,
        /// Divisions around the ring (≥ 3).
        segments: u32,
        /// Divisions around the tube (≥ 3).
        sides: u32,
    },
    /// The construction of a cubic Bézier curve at parameter `t` in the plane z = 0 (see
    /// [`construction_mesh`]).
    Bezier {
        /// The control points `P0…P3`.
        points: [glam::Vec2; 4],
        /// The curve parameter, 0…1.
        t: f32,
        /// How many levels of de Casteljau's construction are drawn, 0…3 (3: down to b(t)).
        levels: u8,
    },
    /// A bicubic Bézier patch over the square [−1.2, 1.2]² of the xz plane, its control net and
    /// the construction of `b(u, v)` (see [`super::patch::patch_mesh`]).
    BezierPatch {
        /// The control points' heights (y), row `i` at `z = −1.2 + 0.8·i`, column `j` at
        /// `x = −1.2 + 0.8·j`.
        heights: [[f32; 4]; 4],
        /// The parameters of the constructed point, 0…1.
        u: f32,
        /// See `u`.
        v: f32,
        /// How much of the construction is drawn: 0 none, 1 the rows' curves in u, 2 also the
        /// curve in v and `b(u, v)`.
        levels: u8,
    },
    /// An implicit surface f(p) = 0, polygonized or as a point cloud (see
    /// [`super::implicit::Implicit`]).
    Implicit(super::implicit::Implicit),
    /// A sampled 1-D signal over its spectrum (see [`super::signal::Signal`]).
    Signal(super::signal::Signal),
    /// A spoked wheel filmed frame by frame (see [`super::signal::Wheel`]).
    Wheel(super::signal::Wheel),
}

impl BuiltinMesh {
    /// The names a scene file may use, with their meaning.
    pub const NAMES: [&'static str; 12] = [
        "triangle",
        "two_triangles",
        "cube",
        "uv_sphere",
        "plane",
        "cylinder",
        "torus",
        "bezier",
        "bezier_patch",
        "implicit",
        "signal",
        "wheel",
    ];

    /// Generates the mesh. Parameters below their minimum are raised to it.
    #[must_use]
    pub fn build(self) -> Mesh {
        match self {
            Self::Triangle => triangle(),
            Self::TwoTriangles => two_triangles(),
            Self::Cube => cube(),
            Self::UvSphere { segments, rings } => uv_sphere(segments.max(3), rings.max(2)),
            Self::Plane { divisions, repeat } => plane(divisions.max(1), repeat),
            Self::Cylinder { segments } => cylinder(segments.max(3)),
            Self::Torus {
                minor,
                segments,
                sides,
            } => torus(minor.clamp(0.01, 0.99), segments.max(3), sides.max(3)),
            Self::Bezier { points, t, levels } => construction_mesh(points, t, levels),
            Self::BezierPatch {
                heights,
                u,
                v,
                levels,
            } => super::patch::patch_mesh(&heights, u, v, levels),
            Self::Implicit(surface) => surface.build(),
            Self::Signal(signal) => signal.build(),
            Self::Wheel(wheel) => wheel.build(),
        }
    }
}

fn triangle() -> Mesh {
    Mesh {
        name: "triangle".into(),
        positions: vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ],
        normals: vec![Vec3::Z; 3],
        uvs: vec![
            Vec2::new(0.0, 0.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(0.5, 1.0),
        ],
        colors: vec![Vec3::X, Vec3::Y, Vec3::Z],
        indices: vec![[0, 1, 2]],
        labels: Vec::new(),
    }
}

fn two_triangles() -> Mesh {
    let a = Vec3::new(217.0, 238.0, 185.0) / 255.0;
    let b = Vec3::new(185.0, 217.0, 238.0) / 255.0;
    let mut mesh = Mesh {
        name: "two_triangles".into(),
        positions: vec![
            Vec3::new(2.0, 0.0, -2.0),
            Vec3::new(0.0, 2.0, -2.0),
            Vec3::new(-2.0, 0.0, -2.0),
            Vec3::new(3.5, -1.0, -5.0),
            Vec3::new(2.5, 1.5, -5.0),
            Vec3::new(-1.0, 0.5, -5.0),
        ],
        uvs: Vec::new(),
        colors: vec![a, a, a, b, b, b],
        indices: vec![[0, 1, 2], [3, 4, 5]],
        normals: Vec::new(),
        labels: Vec::new(),
    };
    mesh.compute_vertex_normals(NormalAveraging::Plain);
    mesh
}

fn cube() -> Mesh {
    let mut mesh = Mesh {
        name: "cube".into(),
        ..Mesh::default()
    };
    // Each face: its normal and two in-plane axes s, t with s × t = normal.
    let faces = [
        (Vec3::X, Vec3::NEG_Z, Vec3::Y),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::X, Vec3::NEG_Z),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::NEG_X, Vec3::Y),
    ];
    for (n, s, t) in faces {
        let corner = |a: f32, b: f32| n + s * a + t * b;
        let base = mesh.positions.len() as u32;
        for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            mesh.positions.push(corner(a, b));
            mesh.normals.push(n);
            mesh.uvs.push(Vec2::new((a + 1.0) / 2.0, (b + 1.0) / 2.0));
            mesh.colors.push((n + 1.0) / 2.0);
        }
        mesh.indices.push([base, base + 1, base + 2]);
        mesh.indices.push([base, base + 2, base + 3]);
    }
    mesh
}

/// Vertices on a (segments+1)×(rows+1) grid, `point(i, j)` giving position and normal;
/// uv = (i/segments, j/rows); quads split into two counter-clockwise triangles, skipping the
/// triangles that collapse at a pole when `poles` is set.
fn grid_mesh(
    name: String,
    segments: u32,
    rows: u32,
    poles: bool,
    point: impl Fn(f32, f32) -> (Vec3, Vec3),
) -> Mesh {
    let mut mesh = Mesh {
        name,
        ..Mesh::default()
    };
    for j in 0..=rows {
        for i in 0..=segments {
            let (u, v) = (i as f32 / segments as f32, j as f32 / rows as f32);
            let (p, n) = point(u, v);
            mesh.positions.push(p);
            mesh.normals.push(n);
            mesh.uvs.push(Vec2::new(u, v));
        }
    }
    let idx = |i: u32, j: u32| j * (segments + 1) + i;
    for j in 0..rows {
        for i in 0..segments {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            if !(poles && j == 0) {
                mesh.indices.push([a, b, c]);
            }
            if !(poles && j + 1 == rows) {
                mesh.indices.push([a, c, d]);
            }
        }
    }
    mesh
}

/// `(sin, cos)` of the angle `u·2π`, a whole turn at `u = 1` giving exactly what `u = 0`
/// gives: the seam's two columns of vertices are at the very same positions, so averaged
/// normals (welded by position) show no crease there.
fn turn(u: f32) -> (f32, f32) {
    (u.fract() * TAU).sin_cos()
}

/// `(sin, cos)` of the angle `v·π`, exactly `(0, −1)` at `v = 1`: the north pole's vertices
/// coincide as the south pole's do.
fn half_turn(v: f32) -> (f32, f32) {
    if v >= 1.0 {
        (0.0, -1.0)
    } else {
        (v * PI).sin_cos()
    }
}

fn uv_sphere(segments: u32, rings: u32) -> Mesh {
    let mut mesh = grid_mesh(
        format!("uv_sphere({segments}×{rings})"),
        segments,
        rings,
        true,
        |u, v| {
            // φ around y (from +z towards +x), θ from the south pole (v = 0) to the north pole.
            let ((sp, cp), (st, ct)) = (turn(u), half_turn(v));
            let p = Vec3::new(st * sp, -ct, st * cp);
            (p, p)
        },
    );
    mesh.colors = mesh.normals.iter().map(|n| (*n + 1.0) / 2.0).collect();
    mesh
}

fn plane(divisions: u32, repeat: f32) -> Mesh {
    let mut mesh = grid_mesh(
        format!("plane({divisions})"),
        divisions,
        divisions,
        false,
        |u, v| (Vec3::new(2.0 * u - 1.0, 0.0, 1.0 - 2.0 * v), Vec3::Y),
    );
    mesh.colors = mesh.uvs.iter().map(|t| Vec3::new(t.x, t.y, 0.5)).collect();
    if repeat > 0.0 && repeat.is_finite() {
        mesh.uvs.iter_mut().for_each(|t| *t *= repeat);
    }
    mesh
}

fn cylinder(segments: u32) -> Mesh {
    let mut mesh = grid_mesh(
        format!("cylinder({segments})"),
        segments,
        1,
        false,
        |u, v| {
            let (sp, cp) = turn(u);
            let n = Vec3::new(sp, 0.0, cp);
            (n + Vec3::new(0.0, 2.0 * v - 1.0, 0.0), n)
        },
    );
    // Caps: flat fans, with their own vertices so that their normals are the axis.
    for (y, normal) in [(1.0f32, Vec3::Y), (-1.0, Vec3::NEG_Y)] {
        for i in 0..segments {
            let (a0, a1) = (i as f32 / segments as f32, (i + 1) as f32 / segments as f32);
            let rim = |a: f32| {
                let (s, c) = turn(a);
                Vec3::new(s, y, c)
            };
            let disc = |a: f32| {
                let (s, c) = turn(a);
                Vec2::new(0.5 + 0.5 * s, 0.5 + 0.5 * c)
            };
            let centre = Vec3::new(0.0, y, 0.0);
            let (p, uv) = if normal.y > 0.0 {
                (
                    [centre, rim(a0), rim(a1)],
                    [Vec2::splat(0.5), disc(a0), disc(a1)],
                )
            } else {
                (
                    [centre, rim(a1), rim(a0)],
                    [Vec2::splat(0.5), disc(a1), disc(a0)],
                )
            };
            mesh.push_flat_triangle(p, uv);
        }
    }
    mesh.colors = mesh.normals.iter().map(|n| (*n + 1.0) / 2.0).collect();
    mesh
}

fn torus(minor: f32, segments: u32, sides: u32) -> Mesh {
    let mut mesh = grid_mesh(
        format!("torus({segments}×{sides})"),
        segments,
        sides,
        false,
        |u, v| {
            let ((sp, cp), (st, ct)) = (turn(u), turn(v));
            let ring = Vec3::new(sp, 0.0, cp);
            let n = ring * (-ct) + Vec3::Y * (-st);
            (ring + n * minor, n)
        },
    );
    mesh.colors = mesh.normals.iter().map(|n| (*n + 1.0) / 2.0).collect();
    mesh
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
/// the control polygon, the lines of the first `levels` de Casteljau levels (0…3), and squares
/// at the control points and those levels' points. With all three levels drawn, the curve from
/// 0 to `t` and `b(t)`. Labels name the control points `P0…P3` and give `t` beside the first
/// interpolated point (one level) or beside `b(t)` (all three).
#[must_use]
pub fn construction_mesh(points: [Vec2; 4], t: f32, levels: u8) -> Mesh {
    let own = |ts: &[f32]| -> Result<Vec<Vec2>, std::convert::Infallible> {
        Ok(ts.iter().map(|&t| bezier::point(&points, t)).collect())
    };
    match construction_mesh_from(points, t, levels, &own) {
        Ok(m) => m,
        Err(never) => match never {},
    }
}

/// The values of `t` at which a construction up to `upto` samples the curve: 160 steps over
/// the whole curve, as many in proportion up to `upto`.
#[must_use]
pub fn curve_parameters(upto: f32) -> Vec<f32> {
    let n = ((upto * 160.0).ceil() as usize).max(1);
    (0..=n).map(|k| upto * k as f32 / n as f32).collect()
}

/// Where a construction takes its curve's points: the points at the given parameters, or why
/// there are none (`E`: a run-time error of the student's function, say).
pub type CurvePoints<'a, E> = dyn Fn(&[f32]) -> Result<Vec<Vec2>, E> + 'a;

/// [`construction_mesh`] with the curve's points from `curve` (the points at the given `t`s):
/// the student's de Casteljau, say.
///
/// # Errors
/// What `curve` returned.
pub fn construction_mesh_from<E>(
    points: [Vec2; 4],
    t: f32,
    levels: u8,
    curve: &CurvePoints<'_, E>,
) -> Result<Mesh, E> {
    let t = t.clamp(0.0, 1.0);
    let drawn = usize::from(levels.min(3));
    let mut m = Mesh {
        name: "bezier".into(),
        ..Mesh::default()
    };
    let samples = |upto: f32| curve(&curve_parameters(upto));
    polyline(&mut m, &samples(1.0)?, 0.01, 0.0, WHOLE_CURVE);
    polyline(&mut m, &points, 0.018, 0.001, POLYGON);
    let levels = bezier::de_casteljau(&points, t);
    let levels = &levels[..=drawn.min(levels.len() - 1)];
    for (k, level) in levels.iter().enumerate().skip(1) {
        let color = LEVELS[(k - 1).min(2)];
        polyline(&mut m, level, 0.016, 0.002, color);
    }
    if t > 0.0 && drawn == 3 {
        polyline(&mut m, &samples(t)?, 0.035, 0.003, CURVE);
    }
    for p in points {
        square(&mut m, p, 0.05, 0.004, Vec3::ONE);
    }
    label_construction(&mut m, &points, levels, t);
    for (k, level) in levels.iter().enumerate().skip(1) {
        let last = level.len() == 1;
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
    Ok(m)
}

/// The labels of a construction: each control point's name beside it, on the side away from
/// the polygon's centre, and the parameter beside the deepest point drawn (`b(t)` when the
/// construction is complete).
fn label_construction(m: &mut Mesh, points: &[Vec2; 4], levels: &[Vec<Vec2>], t: f32) {
    let centre = points.iter().copied().sum::<Vec2>() / 4.0;
    let away = |p: Vec2| Vec2::new(if p.x < centre.x { -0.13 } else { 0.13 }, 0.0);
    for (i, p) in points.iter().enumerate() {
        m.labels.push(MeshLabel {
            position: (*p + away(*p)).extend(0.0),
            text: format!("P{i}"),
        });
    }
    let Some(last) = levels.last().filter(|_| levels.len() > 1) else {
        return;
    };
    let text = if last.len() == 1 {
        format!("b(t), t = {t:.2}")
    } else {
        format!("t = {t:.2}")
    };
    let p = last[0];
    m.labels.push(MeshLabel {
        position: (p + Vec2::new(0.06, -0.1)).extend(0.0),
        text,
    });
}
