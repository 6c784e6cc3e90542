//! The vertex stage: every vertex through model → world → eye → clip, then (when `w > 0`) the
//! perspective division to NDC and the viewport transform to window coordinates, all recorded.
//!
//! - world `= M·p`, eye `= V·world`, clip `= P·eye` (homogeneous 4-vectors);
//! - NDC `= (x_c/w_c, y_c/w_c, z_c/w_c)`, defined only for `w_c > 0` (a vertex behind the eye
//!   has `w_c ≤ 0`: its division means nothing, the clipper deals with it);
//! - window `= viewport·(NDC, 1)`.

use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};
use serde::Serialize;

use crate::light::Light;
use crate::lighting::{self, Frequency, Reflection, ShadeTerms};
use crate::scene::{ColorSource, Object};

/// One vertex through every space, a row of the vertex table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct VertexRecord {
    /// Index of the object in the scene.
    pub object: u32,
    /// Index of the vertex in its mesh.
    pub index: u32,
    /// Object (model) coordinates, `w = 1` (after displacement mapping, if any).
    pub object_pos: Vec4,
    /// World coordinates `M·p`.
    pub world: Vec4,
    /// Eye (camera) coordinates `V·M·p`.
    pub eye: Vec4,
    /// Clip coordinates `P·V·M·p`.
    pub clip: Vec4,
    /// Normalized device coordinates, `None` when `w_clip ≤ 0`.
    pub ndc: Option<Vec3>,
    /// Window coordinates `(x_w, y_w, z_w)`, `None` when `w_clip ≤ 0`.
    pub window: Option<Vec3>,
    /// The vertex colour that is interpolated across the triangle.
    pub color: Vec3,
    /// Texture coordinates, when the mesh has them.
    pub uv: Option<Vec2>,
    /// The unit normal in world coordinates, `N·n` with the normal matrix `N = (M⁻¹)ᵀ`.
    pub normal_world: Vec3,
}

/// The matrices the vertex stage applies to one object.
#[derive(Clone, Copy, Debug)]
pub struct VertexMatrices {
    /// Model matrix `M`.
    pub model: Mat4,
    /// View matrix `V`.
    pub view: Mat4,
    /// Projection matrix `P`.
    pub projection: Mat4,
    /// Viewport matrix.
    pub viewport: Mat4,
}

/// What per-vertex (Gouraud) lighting needs.
#[derive(Clone, Copy, Debug)]
pub struct VertexLighting<'a> {
    /// Where lighting is evaluated; only `Gouraud` lights vertices.
    pub frequency: Frequency,
    /// The specular term.
    pub reflection: Reflection,
    /// The lights.
    pub lights: &'a [Light],
    /// The eye position in world coordinates.
    pub eye: Vec3,
}

/// The perspective division and the viewport transform of a clip-space position with `w > 0`:
/// `NDC = (x_c, y_c, z_c)·(1/w_c)`, `window = viewport·(NDC, 1)`, and `1/w_c` (kept for
/// perspective-correct interpolation). The one place both are computed: the vertex stage
/// records them and the assembly reuses them, so a vertex has the same window position in the
/// vertex table as in the triangles the rasterizer covers.
#[must_use]
#[inline]
pub fn to_window(clip: Vec4, viewport: &Mat4) -> (Vec3, Vec3, f32) {
    let inv_w = 1.0 / clip.w;
    let ndc = clip.truncate() * inv_w;
    (ndc, (*viewport * ndc.extend(1.0)).truncate(), inv_w)
}

/// The normal matrix `N = (M⁻¹)ᵀ` (upper 3×3): normals stay perpendicular to surfaces under
/// non-uniform scaling.
#[must_use]
pub fn normal_matrix(model: &Mat4) -> Mat3 {
    Mat3::from_mat4(*model).inverse().transpose()
}

/// The clip positions a vertex shader wrote (`gl_Position`), one per vertex of an object: the
/// 4 floats at `values[i·stride + position ..]` for vertex `i`.
#[derive(Clone, Copy, Debug)]
pub struct ShaderClip<'a> {
    /// Every output of every vertex, vertex by vertex.
    pub values: &'a [f32],
    /// Floats per vertex.
    pub stride: usize,
    /// Where `gl_Position` starts among a vertex's outputs.
    pub position: usize,
}

impl ShaderClip<'_> {
    /// Vertex `i`'s `gl_Position`.
    #[must_use]
    #[inline]
    pub fn at(&self, i: usize) -> Vec4 {
        Vec4::from_slice(&self.values[i * self.stride + self.position..][..4])
    }
}

/// Runs the vertex stage on every vertex of `object` (index `object_index` in the scene),
/// appending one row per vertex to `out` and, with Gouraud shading, its lighting to `lit`.
/// The vertices are independent: they are transformed in parallel, written straight into
/// `out`'s storage (which the frame before may have left with room enough). With `shader`,
/// the object's vertex shader gave each clip position: the division and viewport follow from
/// it, while world, eye and the normal stay the table's own (M·p, V·M·p, N·n).
pub fn transform_object(
    object: &Object,
    object_index: u32,
    m: &VertexMatrices,
    lighting: &VertexLighting<'_>,
    shader: Option<ShaderClip<'_>>,
    out: &mut Vec<VertexRecord>,
    lit: &mut Vec<ShadeTerms>,
) {
    use rayon::prelude::*;
    let mesh = &object.mesh;
    let n_matrix = normal_matrix(&m.model);
    let first = out.len();
    out.par_extend(
        (0..mesh.positions.len())
            .into_par_iter()
            .with_min_len(1024)
            .map(|i| {
                let clip = shader.map(|s| s.at(i));
                transform_vertex(object, object_index, i, m, &n_matrix, clip)
            }),
    );
    if lighting.frequency != Frequency::Gouraud {
        return;
    }
    // A textured surface is lit white here; the texel modulates the result per pixel.
    let textured = object.texture.is_some() && !mesh.uvs.is_empty();
    lit.par_extend(out[first..].par_iter().with_min_len(1024).map(|v| {
        if !object.lit {
            return ShadeTerms::default();
        }
        lighting::shade(
            v.world.truncate(),
            v.normal_world,
            lighting.eye,
            if textured { Vec3::ONE } else { v.color },
            lighting.lights,
            &object.material,
            lighting.reflection,
        )
    }));
}

/// Vertex `i` of `object` through every space: its row of the vertex table. `n_matrix` is the
/// object's normal matrix; `shader_clip` the clip position a vertex shader wrote, if it ran.
fn transform_vertex(
    object: &Object,
    object_index: u32,
    i: usize,
    m: &VertexMatrices,
    n_matrix: &Mat3,
    shader_clip: Option<Vec4>,
) -> VertexRecord {
    let mesh = &object.mesh;
    let object_pos = object_position(object, i).extend(1.0);
    let world = m.model * object_pos;
    let eye = m.view * world;
    let clip = shader_clip.unwrap_or_else(|| m.projection * eye);
    let (ndc, window) = if clip.w > 0.0 {
        let (ndc, window, _) = to_window(clip, &m.viewport);
        (Some(ndc), Some(window))
    } else {
        (None, None)
    };
    VertexRecord {
        object: object_index,
        index: i as u32,
        object_pos,
        world,
        eye,
        clip,
        ndc,
        window,
        color: vertex_color(object, i),
        uv: mesh.uvs.get(i).copied(),
        normal_world: (*n_matrix * mesh.normals[i]).normalize_or_zero(),
    }
}

/// Vertex `i`'s position in object coordinates, displaced along its normal when the object has
/// a displacement map: `p' = p + k·h(u, v)·n`.
#[must_use]
#[inline]
pub fn object_position(object: &Object, i: usize) -> Vec3 {
    let mesh = &object.mesh;
    let p = mesh.positions[i];
    match (&object.displacement, mesh.uvs.get(i)) {
        (Some(d), Some(&uv)) => p + mesh.normals[i] * d.offset(uv),
        _ => p,
    }
}

/// Vertex `i`'s colour: the object's one colour, the mesh's colour at the vertex, or its normal
/// shown as a colour, `(n + 1)/2`.
#[must_use]
#[inline]
pub fn vertex_color(object: &Object, i: usize) -> Vec3 {
    let mesh = &object.mesh;
    match object.color {
        ColorSource::Uniform(c) => c,
        ColorSource::Vertex if !mesh.colors.is_empty() => mesh.colors[i],
        ColorSource::Vertex | ColorSource::Normal => (mesh.normals[i] + 1.0) / 2.0,
    }
}
