//! Triangle meshes: the built-in shapes generated in code, and OBJ files read with `tobj`.
//!
//! A mesh has one index per corner (as OpenGL draws): positions, normals, texture coordinates and
//! colours share the index. Triangles are counter-clockwise seen from outside (their front face).

use std::f32::consts::{PI, TAU};
use std::path::Path;

use glam::{Vec2, Vec3};
use serde::Serialize;

/// How a vertex normal is made from the normals of the faces around the vertex.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum NormalAveraging {
    /// The notes' rule: the plain average of the adjacent unit face normals,
    /// `n = (n1 + n2 + … + nk) / |n1 + n2 + … + nk|`.
    #[default]
    Plain,
    /// Each face normal weighted by the face's area (the unnormalised cross product).
    AreaWeighted,
}

/// A triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Where it came from, for messages and the capture (`uv_sphere(32×16)`, `bunny.obj`).
    pub name: String,
    /// Vertex positions in object (model) coordinates.
    pub positions: Vec<Vec3>,
    /// One unit normal per vertex.
    pub normals: Vec<Vec3>,
    /// Texture coordinates per vertex, `(0, 0)` at the bottom-left of the image; empty if none.
    pub uvs: Vec<Vec2>,
    /// Vertex colours (linear RGB in `[0, 1]`); empty if none.
    pub colors: Vec<Vec3>,
    /// Triangles as three vertex indices, counter-clockwise seen from the front.
    pub indices: Vec<[u32; 3]>,
}

/// Why a mesh could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The OBJ file could not be read or parsed.
    #[error("{path}: cannot load the OBJ file: {reason}")]
    Obj {
        /// The file.
        path: String,
        /// What `tobj` reported.
        reason: String,
    },
    /// The file has no triangles to draw.
    #[error("{path}: the file has no faces (an OBJ mesh needs `f` lines)")]
    NoFaces {
        /// The file.
        path: String,
    },
    /// A face refers to a vertex that does not exist.
    #[error("{path}: face {face} refers to vertex {index}, but the mesh has {count} vertices")]
    IndexOutOfRange {
        /// The file.
        path: String,
        /// The triangle (0-based).
        face: usize,
        /// The index found.
        index: u32,
        /// How many vertices there are.
        count: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("{path}: vertex {vertex} has a coordinate that is not a finite number ({value:?})")]
    NotFinite {
        /// The file.
        path: String,
        /// The vertex (0-based).
        vertex: usize,
        /// Its position.
        value: Vec3,
    },
}

impl Mesh {
    /// Number of triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.indices.len()
    }

    /// The unnormalised normal of triangle `t`: `(p1 − p0) × (p2 − p0)`, whose length is twice its area.
    #[must_use]
    pub fn face_normal_scaled(&self, t: usize) -> Vec3 {
        let [a, b, c] = self.indices[t].map(|i| self.positions[i as usize]);
        (b - a).cross(c - a)
    }

    /// Recomputes every vertex normal from the faces around it (see [`NormalAveraging`]).
    /// A vertex that belongs to no face (or only to degenerate ones) gets `+z`.
    pub fn compute_vertex_normals(&mut self, averaging: NormalAveraging) {
        let mut sums = vec![Vec3::ZERO; self.positions.len()];
        for t in 0..self.indices.len() {
            let scaled = self.face_normal_scaled(t);
            let face = match averaging {
                NormalAveraging::Plain => scaled.normalize_or_zero(),
                NormalAveraging::AreaWeighted => scaled,
            };
            for &i in &self.indices[t] {
                sums[i as usize] += face;
            }
        }
        self.normals = sums
            .into_iter()
            .map(|n| n.try_normalize().unwrap_or(Vec3::Z))
            .collect();
    }

    /// Loads a Wavefront OBJ file, triangulating polygons. Normals and texture coordinates are
    /// kept when the file has them; missing normals are computed with the notes' plain average.
    /// Vertex colours written as `v x y z r g b` are kept.
    ///
    /// # Errors
    /// A [`MeshError`] naming the file and what is wrong with it.
    pub fn load_obj(path: &Path) -> Result<Mesh, MeshError> {
        let shown = path.display().to_string();
        let file = std::fs::File::open(path).map_err(|e| MeshError::Obj {
            path: shown.clone(),
            reason: format!("cannot open it: {e}"),
        })?;
        let name = path
            .file_name()
            .map_or_else(|| shown.clone(), |n| n.to_string_lossy().into_owned());
        Self::parse_obj(&mut std::io::BufReader::new(file), &shown, &name)
    }

    /// Reads OBJ text from `reader` as [`Self::load_obj`] does; `shown` names it in errors.
    ///
    /// # Errors
    /// A [`MeshError`] naming `shown` and what is wrong.
    pub fn parse_obj(
        reader: &mut impl std::io::Read,
        shown: &str,
        name: &str,
    ) -> Result<Mesh, MeshError> {
        let options = tobj::LoadOptions {
            triangulate: true,
            single_index: true,
            ignore_points: true,
            ignore_lines: true,
        };
        let mut text = String::new();
        reader
            .read_to_string(&mut text)
            .map_err(|e| MeshError::Obj {
                path: shown.to_owned(),
                reason: format!("cannot read it as text: {e}"),
            })?;
        check_face_sizes(&text, shown)?;
        // Materials are not used: a missing .mtl file is no error.
        let (models, _materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| {
            Ok((Vec::new(), Default::default()))
        })
        .map_err(|e| MeshError::Obj {
            path: shown.to_owned(),
            reason: e.to_string(),
        })?;
        let mut mesh = Mesh {
            name: name.to_owned(),
            ..Mesh::default()
        };
        let mut has_normals = true;
        let mut has_uvs = true;
        let mut has_colors = true;
        for model in &models {
            let m = &model.mesh;
            let base = u32::try_from(mesh.positions.len()).unwrap_or(u32::MAX);
            let count = m.positions.len() / 3;
            mesh.positions.extend(
                m.positions
                    .chunks_exact(3)
                    .map(|p| Vec3::new(p[0], p[1], p[2])),
            );
            has_normals &= m.normals.len() == m.positions.len();
            has_uvs &= m.texcoords.len() / 2 == count;
            has_colors &= m.vertex_color.len() == m.positions.len();
            if has_normals {
                mesh.normals.extend(
                    m.normals
                        .chunks_exact(3)
                        .map(|n| Vec3::new(n[0], n[1], n[2])),
                );
            }
            if has_uvs {
                mesh.uvs
                    .extend(m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
            }
            if has_colors {
                mesh.colors.extend(
                    m.vertex_color
                        .chunks_exact(3)
                        .map(|c| Vec3::new(c[0], c[1], c[2])),
                );
            }
            mesh.indices.extend(
                m.indices
                    .chunks_exact(3)
                    .map(|f| [base + f[0], base + f[1], base + f[2]]),
            );
        }
        check_loaded(&mesh, shown)?;
        if !has_uvs {
            mesh.uvs.clear();
        }
        if !has_colors {
            mesh.colors.clear();
        }
        if has_normals && mesh.normals.iter().all(|n| n.is_finite()) {
            for n in &mut mesh.normals {
                *n = n.try_normalize().unwrap_or(Vec3::Z);
            }
        } else {
            mesh.compute_vertex_normals(NormalAveraging::Plain);
        }
        Ok(mesh)
    }

    /// Appends a triangle of fresh vertices with a flat normal (used to build faceted shapes).
    fn push_flat_triangle(&mut self, p: [Vec3; 3], uv: [Vec2; 3]) {
        let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
        let base = self.positions.len() as u32;
        for k in 0..3 {
            self.positions.push(p[k]);
            self.normals.push(n);
            self.uvs.push(uv[k]);
        }
        self.indices.push([base, base + 1, base + 2]);
    }
}

/// A loaded mesh has faces, indices in range and finite positions.
fn check_loaded(mesh: &Mesh, shown: &str) -> Result<(), MeshError> {
    if mesh.indices.is_empty() {
        return Err(MeshError::NoFaces {
            path: shown.to_owned(),
        });
    }
    let count = mesh.positions.len();
    for (face, tri) in mesh.indices.iter().enumerate() {
        if let Some(&index) = tri.iter().find(|&&i| i as usize >= count) {
            return Err(MeshError::IndexOutOfRange {
                path: shown.to_owned(),
                face,
                index,
                count,
            });
        }
    }
    if let Some((vertex, &value)) = mesh
        .positions
        .iter()
        .enumerate()
        .find(|(_, p)| !p.is_finite())
    {
        return Err(MeshError::NotFinite {
            path: shown.to_owned(),
            vertex,
            value,
        });
    }
    Ok(())
}

/// tobj drops a face of fewer than three vertices without a word: name it, with its line.
fn check_face_sizes(text: &str, shown: &str) -> Result<(), MeshError> {
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        if words.next() == Some("f") {
            let count = words.count();
            if count < 3 {
                return Err(MeshError::Obj {
                    path: shown.to_owned(),
                    reason: format!(
                        "line {}: a face needs at least three vertices, got {count}",
                        n + 1
                    ),
                });
            }
        }
    }
    Ok(())
}

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
    /// [`crate::bezier::construction_mesh`]).
    Bezier {
        /// The control points `P0…P3`.
        points: [glam::Vec2; 4],
        /// The curve parameter, 0…1.
        t: f32,
    },
}

impl BuiltinMesh {
    /// The names a scene file may use, with their meaning.
    pub const NAMES: [&'static str; 8] = [
        "triangle",
        "two_triangles",
        "cube",
        "uv_sphere",
        "plane",
        "cylinder",
        "torus",
        "bezier",
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
            Self::Bezier { points, t } => crate::bezier::construction_mesh(points, t),
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

fn uv_sphere(segments: u32, rings: u32) -> Mesh {
    let mut mesh = grid_mesh(
        format!("uv_sphere({segments}×{rings})"),
        segments,
        rings,
        true,
        |u, v| {
            // φ around y (from +z towards +x), θ from the south pole (v = 0) to the north pole.
            let (phi, theta) = (u * TAU, v * PI);
            let p = Vec3::new(
                theta.sin() * phi.sin(),
                -theta.cos(),
                theta.sin() * phi.cos(),
            );
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
            let phi = u * TAU;
            let n = Vec3::new(phi.sin(), 0.0, phi.cos());
            (n + Vec3::new(0.0, 2.0 * v - 1.0, 0.0), n)
        },
    );
    // Caps: flat fans, with their own vertices so that their normals are the axis.
    for (y, normal) in [(1.0f32, Vec3::Y), (-1.0, Vec3::NEG_Y)] {
        for i in 0..segments {
            let (a0, a1) = (
                i as f32 / segments as f32 * TAU,
                (i + 1) as f32 / segments as f32 * TAU,
            );
            let rim = |a: f32| Vec3::new(a.sin(), y, a.cos());
            let disc = |a: f32| Vec2::new(0.5 + 0.5 * a.sin(), 0.5 + 0.5 * a.cos());
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
            let (phi, theta) = (u * TAU, v * TAU);
            let ring = Vec3::new(phi.sin(), 0.0, phi.cos());
            let n = ring * (-theta.cos()) + Vec3::Y * (-theta.sin());
            (ring + n * minor, n)
        },
    );
    mesh.colors = mesh.normals.iter().map(|n| (*n + 1.0) / 2.0).collect();
    mesh
}
