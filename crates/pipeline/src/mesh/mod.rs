//! Triangle meshes: what a mesh holds and how its vertex normals are made. OBJ files are read in
//! [`obj`] (with `tobj`), the built-in shapes are generated in [`builtin`].
//!
//! A mesh has one index per corner (as OpenGL draws): positions, normals, texture coordinates and
//! colours share the index. Triangles are counter-clockwise seen from outside (their front face).

mod builtin;
mod drawing;
pub mod implicit;
mod obj;
pub mod patch;
pub mod signal;

pub use builtin::{BuiltinMesh, construction_mesh_from, curve_parameters};

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
    /// Names written beside points of the mesh (a Bézier curve's P0…P3 and b(t)); the views
    /// draw them where the points land in the image.
    pub labels: Vec<MeshLabel>,
}

/// A text written beside a point of a mesh, in object coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshLabel {
    /// The point, in object (model) coordinates.
    pub position: Vec3,
    /// What is written.
    pub text: String,
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
    /// A line of the file is wrong: `file.obj:LINE: what is wrong`.
    #[error("{path}:{line}: {reason}")]
    Line {
        /// The file.
        path: String,
        /// 1-based line.
        line: usize,
        /// What is wrong with it.
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

    /// The axis-aligned bounding box `(min, max)` of the positions; `None` for no vertices.
    #[must_use]
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let first = *self.positions.first()?;
        Some(
            self.positions
                .iter()
                .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))),
        )
    }

    /// Moves and scales the mesh into the unit sphere, as a lesson's `fit = true` asks:
    /// `p' = (p − c) / r` with `c = (min + max) / 2` the centre of the bounding box and
    /// `r = max |p − c|`. The scale is uniform, so normals keep their directions.
    pub fn fit_unit_sphere(&mut self) {
        let Some((lo, hi)) = self.bounds() else {
            return;
        };
        let c = (lo + hi) / 2.0;
        let r = self
            .positions
            .iter()
            .map(|&p| (p - c).length())
            .fold(0.0f32, f32::max);
        let s = if r > 0.0 { 1.0 / r } else { 1.0 };
        for p in &mut self.positions {
            *p = (*p - c) * s;
        }
    }

    /// The unnormalised normal of triangle `t`: `(p1 − p0) × (p2 − p0)`, whose length is twice its area.
    #[must_use]
    pub fn face_normal_scaled(&self, t: usize) -> Vec3 {
        let [a, b, c] = self.indices[t].map(|i| self.positions[i as usize]);
        (b - a).cross(c - a)
    }

    /// Recomputes every vertex normal from the faces around it (see [`NormalAveraging`]).
    /// "Around the vertex" means around its **position**: vertices split because they carry
    /// different texture coordinates or colours (a uv seam) share the faces of all the copies,
    /// so the surface has no crease along the seam. A vertex that belongs to no face (or only to
    /// degenerate ones) gets `+z`.
    pub fn compute_vertex_normals(&mut self, averaging: NormalAveraging) {
        // One group per distinct position (−0.0 and 0.0 the same).
        let mut groups = std::collections::HashMap::new();
        let group: Vec<usize> = self
            .positions
            .iter()
            .map(|p| {
                let key = (*p + Vec3::ZERO).to_array().map(f32::to_bits);
                let next = groups.len();
                *groups.entry(key).or_insert(next)
            })
            .collect();
        let mut sums = vec![Vec3::ZERO; groups.len()];
        for t in 0..self.indices.len() {
            let scaled = self.face_normal_scaled(t);
            let face = match averaging {
                NormalAveraging::Plain => scaled.normalize_or_zero(),
                NormalAveraging::AreaWeighted => scaled,
            };
            for &i in &self.indices[t] {
                sums[group[i as usize]] += face;
            }
        }
        self.normals = group
            .iter()
            .map(|&g| sums[g].try_normalize().unwrap_or(Vec3::Z))
            .collect();
    }

    /// Appends a triangle of fresh vertices with a flat normal (used to build faceted shapes).
    pub(crate) fn push_flat_triangle(&mut self, p: [Vec3; 3], uv: [Vec2; 3]) {
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
