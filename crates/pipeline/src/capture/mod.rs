//! `FrameCapture`: everything one frame did, stage by stage — the matrices with their factors,
//! the vertex table, the fate of every primitive, the raster triangles, the per-sample and
//! per-pixel buffers — and the images made from them. The app shows it, the exporter writes it,
//! the tests assert on it: a number comes from one place.
//!
//! The records are here; the per-pixel buffers in [`pixels`]; the images made from them (each
//! buffer's colour mapping, overlays, projecting world points into the image) in [`images`];
//! everything about one pixel (its fragments, lighting vectors, a profile along a line) in
//! [`inspect`].

mod difference;
mod explain;
mod images;
mod inspect;
mod pixels;
mod watch;

pub use difference::{
    COVERAGE_STRIPE, Criteria, DIFFERENCE_COLOURS, DIFFERENCE_DIMMEST, Difference, MATCH_GREY_MAX,
    on_stripe,
};
pub use explain::*;
pub use images::OUTLINE;
pub use inspect::*;
pub use pixels::*;
pub use watch::{WatchPicture, WatchView, WatchedImage, ramp as watch_ramp};

use glam::{I64Vec2, Vec3};
use half::f16;
use serde::Serialize;

use crate::buffers::BufferKind;
use crate::camera::{Camera, Projection};
use crate::clip::{ClipPlane, ClipVertex};
use crate::light::Material;
use crate::raster::{ONE, RasterCounts, RasterTriangle, SampleBuffers};
use crate::settings::RenderSettings;
use crate::transform::NamedMatrix;
use crate::vertex::VertexRecord;

/// The matrices of the frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Matrices {
    /// One model matrix per object, with its factors `T·Rz·Ry·Rx·S`.
    pub models: Vec<NamedMatrix>,
    /// The view matrix `LookAt(eye, at, up)`, with GAMES101's factors `R_view·T_view`.
    pub view: NamedMatrix,
    /// The projection in Angel's / OpenGL's form, with its factors.
    pub projection: NamedMatrix,
    /// The same projection in GAMES101's form (`M_ortho·M_persp→ortho`); equals
    /// `−Z·P` (perspective) or `Z·P` (parallel) with `Z = diag(1, 1, −1, 1)`.
    pub projection_games101: NamedMatrix,
    /// The viewport transform.
    pub viewport: NamedMatrix,
}

/// What happened to a primitive (an input triangle).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "fate")]
pub enum Fate {
    /// Entirely inside the view volume, rasterized as it is.
    Drawn,
    /// Partly inside: clipped, and the remaining polygon rasterized as triangles.
    Clipped,
    /// Entirely outside one plane of the view volume: dropped by clipping.
    Outside {
        /// The plane all three vertices are outside of.
        plane: ClipPlane,
    },
    /// Discarded by face culling.
    Culled {
        /// `true` for a back face (clockwise on screen), `false` for a front face.
        back: bool,
    },
    /// No area on screen after snapping to the sub-pixel grid: nothing to rasterize.
    Degenerate,
    /// A corner's clip coordinates are not finite (NaN or ∞, from a vertex shader's
    /// `gl_Position`): dropped before clipping, as nothing can be drawn from them.
    NotFinite,
}

/// The record of one primitive.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PrimitiveRecord {
    /// The primitive id (triangles counted across objects in drawing order).
    pub id: u32,
    /// The object it belongs to.
    pub object: u32,
    /// Rows of the vertex table of its three vertices.
    pub vertices: [u32; 3],
    /// What happened to it.
    #[serde(flatten)]
    pub fate: Fate,
    /// The polygon left after clipping, when it was clipped.
    pub clipped_polygon: Option<Vec<ClipVertex>>,
    /// Its raster triangles: indices `start..end` into [`FrameCapture::triangles`].
    pub triangles: [u32; 2],
    /// Samples covered and written (after the depth test), over all its raster triangles.
    pub counts: RasterCounts,
}

impl PrimitiveRecord {
    /// The barycentric weights, with respect to this primitive, of the corners of `t`, one of
    /// its raster triangles ([`RasterTriangle::bary_corners`] with its clipped polygon).
    #[must_use]
    #[inline]
    pub fn bary_corners(&self, t: &RasterTriangle) -> [Vec3; 3] {
        t.bary_corners(self.clipped_polygon.as_deref())
    }
}

/// A summary of one object, for the capture's JSON.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ObjectSummary {
    /// Its name.
    pub name: String,
    /// Its mesh's name.
    pub mesh: String,
    /// Vertices in the mesh.
    pub vertices: usize,
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Its reflection coefficients.
    pub material: Material,
    /// Whether lighting applies to it.
    pub lit: bool,
    /// The name of its texture, when it is textured (it has a texture and its mesh has uvs).
    pub texture: Option<String>,
    /// Whether bump or normal mapping changes its normal per pixel.
    pub detail: bool,
    /// How much of its environment it mirrors (environment mapping), when it does.
    pub reflectivity: Option<f32>,
}

/// A mesh's label where its point lands in the image (see [`crate::mesh::MeshLabel`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ScreenLabel {
    /// The point in image pixel coordinates (y down).
    pub image: [f32; 2],
    /// What is written.
    pub text: String,
}

impl Matrices {
    /// Where the labels of `objects` land in a `width`×`height` image: each label's point through
    /// `M_viewport·P·V·M_model`, divided by w; labels behind the eye (w ≤ 0) or more than a
    /// pixel outside the image are left out.
    #[must_use]
    pub fn screen_labels(
        &self,
        objects: &[crate::scene::Object],
        width: u32,
        height: u32,
    ) -> Vec<ScreenLabel> {
        let pv = self.projection.matrix * self.view.matrix;
        let (w, h) = (width as f32, height as f32);
        objects
            .iter()
            .zip(&self.models)
            .flat_map(|(o, m)| {
                let mvp = pv * m.matrix;
                o.mesh.labels.iter().filter_map(move |l| {
                    let clip = mvp * l.position.extend(1.0);
                    if clip.w <= 1e-5 {
                        return None;
                    }
                    let win = self.viewport.matrix * (clip / clip.w);
                    let image = [win.x, h - win.y];
                    let inside = (-1.0..=w + 1.0).contains(&image[0])
                        && (-1.0..=h + 1.0).contains(&image[1]);
                    inside.then(|| ScreenLabel {
                        image,
                        text: l.text.clone(),
                    })
                })
            })
            .collect()
    }
}

/// Everything one frame did.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameCapture {
    /// The settings it was rendered with.
    pub settings: RenderSettings,
    /// The camera.
    pub camera: Camera,
    /// The projection.
    pub projection: Projection,
    /// The lights.
    pub lights: Vec<crate::light::Light>,
    /// The objects drawn.
    pub objects: Vec<ObjectSummary>,
    /// The matrices with their factors.
    pub matrices: Matrices,
    /// The vertex table: every vertex of every object through every space.
    pub vertices: Vec<VertexRecord>,
    /// The lighting at each vertex (a row per vertex-table row), with Gouraud shading; empty
    /// otherwise.
    pub vertex_shading: Vec<crate::lighting::ShadeTerms>,
    /// The lighting of each face (a row per primitive, evaluated once at its provoking vertex), with
    /// flat shading; empty otherwise.
    pub face_shading: Vec<crate::lighting::ShadeTerms>,
    /// The textures the frame read, by object name (their mip pyramids can be shown and exported).
    pub textures: Vec<(String, std::sync::Arc<crate::texture::Texture>)>,
    /// The cube maps the frame's mirrors reflect, by object name.
    pub cubes: Vec<(String, std::sync::Arc<crate::texture::CubeMap>)>,
    /// The figures' traversal with the matrix stack (push, visit with the composite, pop).
    pub hierarchy: Vec<crate::hierarchy::Step>,
    /// One record per input triangle.
    pub primitives: Vec<PrimitiveRecord>,
    /// The triangles that were rasterized, in order (clipping may split a primitive into several).
    pub triangles: Vec<RasterTriangle>,
    /// Per-sample depth and owner.
    pub samples: SampleBuffers,
    /// Per-pixel buffers.
    pub pixels: PixelBuffers,
    /// The meshes' labels where they land in the image.
    pub labels: Vec<ScreenLabel>,
    /// What the student's shaders computed: each object's vertex shader results, and the
    /// fragment shaders' counts (`None` when no object has shaders).
    pub shaders: Option<ShaderRecord>,
}

/// What the student's shaders computed in a frame.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct ShaderRecord {
    /// For each object with shaders: its first row of the vertex table, and each vertex's
    /// vertex-shader result (every output, `gl_Position` included), `stride` floats a vertex.
    pub vertex_results: Vec<Option<VertexResults>>,
    /// Fragments the fragment shaders ran for (helper invocations of a quad not counted).
    pub fragments: u64,
    /// Fragments a `discard` threw away.
    pub discarded: u64,
    /// Pixels whose colour came out NaN or infinite (shown black).
    pub not_finite: u64,
    /// The inspected pixel's fragments (`settings.capture.pixel`), each with its shader's run.
    pub pixel: Vec<FragmentTrace>,
    /// What a watch saw over the frame, when the fragment shader watched an expression
    /// (`Scene::watching`); written apart from `capture.json` (`pipelens export --watch`).
    #[serde(skip)]
    pub watch: Option<WatchPicture>,
    /// The cost view (`Capture::cost`): at each pixel the steps of the student's fragment shader
    /// the fragment covering the most of its samples ran (`line` 0, an `int` per pixel).
    #[serde(skip)]
    pub cost: Option<WatchPicture>,
}

/// One fragment of the inspected pixel through the fragment shader: what it received, what
/// each statement did, what it wrote.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct FragmentTrace {
    /// The raster triangle.
    pub triangle: u32,
    /// The primitive (input triangle).
    pub primitive: u32,
    /// Samples of the pixel it covers.
    pub samples: u32,
    /// Each input as the shader received it, interpolated: `(name, value)`.
    pub inputs: Vec<(String, String)>,
    /// The run, statement by statement.
    pub trace: Vec<crate::shader::TraceLine>,
    /// The colour it wrote, or `None` when it was discarded.
    pub output: Option<[f32; 4]>,
    /// When the frame watched an expression: each time this run stored it, the number of
    /// steps of `trace` before (the value stands from that step on) and the value, its
    /// components first (`ShaderRecord::watch` has its type).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub watch: Vec<(usize, [f32; 4])>,
    /// What it takes to run this fragment again (with a watch: `crate::watch_fragment`).
    #[serde(skip)]
    pub replay: Option<FragmentReplay>,
}

/// A fragment's run as the frame ran it, to run again: its object, its quad's inputs (the
/// quad's other lanes too, for derivatives; helpers marked) and which lane it is.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentReplay {
    /// The object, an index into the scene as drawn (figures and shadows expanded).
    pub object: usize,
    /// Its lane in the quad.
    pub lane: usize,
    /// The fragment shader's inputs, as the quad received them.
    pub inputs: Vec<crate::shader::Varying>,
    /// Their values, lane by lane.
    pub batch: crate::shader::Batch,
}

/// One vertex through the vertex shader: what it received, what each statement did, what it
/// wrote (`gl_Position` among its outputs).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct VertexTrace {
    /// Its row in the vertex table.
    pub row: u32,
    /// Its object.
    pub object: String,
    /// Each attribute as the shader received it: `(name, value)`.
    pub inputs: Vec<(String, String)>,
    /// The run, statement by statement.
    pub trace: Vec<crate::shader::TraceLine>,
    /// Each output as written: `(name, value)`.
    pub outputs: Vec<(String, String)>,
}

/// One object's vertex-shader results.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct VertexResults {
    /// The object's first row in the vertex table.
    pub first: u32,
    /// Floats a vertex.
    pub stride: u32,
    /// Every vertex's outputs, in the shader's output order.
    pub values: Vec<f32>,
    /// What each vertex's watch saw, when the vertex shader watches an expression
    /// (`Programs::watching`); empty otherwise.
    #[serde(skip)]
    pub watch: Vec<Option<crate::shader::probe::Watched>>,
}

impl FrameCapture {
    /// Primitives dropped because a corner's `gl_Position` was not finite
    /// ([`Fate::NotFinite`]).
    #[must_use]
    pub fn not_finite_primitives(&self) -> usize {
        self.primitives
            .iter()
            .filter(|p| p.fate == Fate::NotFinite)
            .count()
    }

    /// What of the frame is not a number, in words, for the command line: triangles dropped
    /// for a `gl_Position` that is NaN or ∞, pixels whose shader colour was (drawn black).
    #[must_use]
    pub fn not_finite_warnings(&self) -> Vec<String> {
        let mut out = Vec::new();
        let dropped = self.not_finite_primitives();
        if dropped > 0 {
            out.push(format!(
                "{dropped} triangle(s) dropped: a vertex shader's gl_Position was NaN or infinite (their fate in capture.json is \"NotFinite\")"
            ));
        }
        if let Some(s) = self.shaders.as_ref().filter(|s| s.not_finite > 0) {
            out.push(format!(
                "{} pixel(s) NaN or infinite (drawn black): a fragment shader's colour was not a finite number",
                s.not_finite
            ));
        }
        out
    }
}

impl FrameCapture {
    /// The buffers this capture holds (lighting buffers only when lighting was on, texturing
    /// buffers only when an object is textured, the reflected term only when a mirror shows).
    #[must_use]
    pub fn buffers(&self) -> Vec<BufferKind> {
        BufferKind::ALL
            .into_iter()
            .filter(|k| !k.is_lighting() || self.pixels.shading.is_some())
            .filter(|k| !k.is_texturing() || self.pixels.texturing.is_some())
            .filter(|&k| k != BufferKind::Reflected || self.reflects())
            .collect()
    }

    /// Whether some pixel shows a mirror's reflected term (only then is its buffer listed).
    fn reflects(&self) -> bool {
        self.pixels
            .shading
            .as_ref()
            .is_some_and(|s| s.reflected.iter().any(|c| *c != [f16::ZERO; 3]))
    }

    /// The barycentric weights of pixel `i`'s owning fragment at the pixel centre, relative to
    /// the original triangle's vertices: `λ` from the owner's edge functions at the centre, then
    /// affine `Σ λ_k·b_k` and perspective-correct `Σ (λ_k/w_k)/Σ(λ_j/w_j)·b_k` (what the resolve
    /// interpolated the pixel's attributes with). `None` where nothing is drawn.
    #[must_use]
    pub fn barycentrics(&self, i: usize) -> Option<Barycentrics> {
        let tri = self.triangles.get(*self.pixels.owner.get(i)? as usize)?;
        let (x, y) = self.grid().position(i);
        let l = tri.lambda(Self::pixel_centre_fixed(x, y));
        let bary = self
            .primitives
            .get(tri.primitive as usize)?
            .bary_corners(tri);
        Some(Barycentrics {
            perspective: tri.original_bary(&bary, l, true).to_array(),
            affine: tri.original_bary(&bary, l, false).to_array(),
        })
    }

    /// The bytes the per-pixel and per-sample buffers hold: what
    /// [`RenderSettings::capture_bytes`] bounds (equal to it when every kept buffer applies).
    #[must_use]
    pub fn buffer_bytes(&self) -> u64 {
        fn b<T>(v: &[T]) -> u64 {
            std::mem::size_of_val(v) as u64
        }
        let p = &self.pixels;
        let core = b(&p.coverage) + b(&p.depth) + b(&p.primitive) + b(&p.owner) + b(&p.color);
        let lighting = p.shading.as_ref().map_or(0, |s| {
            b(&s.ambient)
                + b(&s.diffuse)
                + b(&s.specular)
                + b(&s.normal)
                + b(&s.n_dot_l)
                + b(&s.n_dot_h)
                + b(&s.reflected)
        });
        let texturing = p.texturing.as_ref().map_or(0, |t| {
            b(&t.uv) + b(&t.lod) + b(&t.level) + b(&t.texel) + b(&t.footprint)
        });
        core + lighting + texturing + b(&self.samples.depth) + b(&self.samples.triangle)
    }

    /// The bytes the whole capture holds: its buffers ([`Self::buffer_bytes`]) and its records
    /// (the vertex table, the primitives with their clipped polygons, the raster triangles).
    #[must_use]
    pub fn memory_bytes(&self) -> u64 {
        fn b<T>(v: &[T]) -> u64 {
            std::mem::size_of_val(v) as u64
        }
        let polygons: u64 = self
            .primitives
            .iter()
            .filter_map(|p| p.clipped_polygon.as_deref())
            .map(b)
            .sum();
        self.buffer_bytes()
            + b(&self.vertices)
            + b(&self.vertex_shading)
            + b(&self.face_shading)
            + b(&self.primitives)
            + polygons
            + b(&self.triangles)
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.settings.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.settings.height
    }

    /// The frame's pixels as a grid: window positions (y up) against the buffers' indices
    /// (stored top row first).
    #[must_use]
    pub fn grid(&self) -> crate::grid::Grid {
        crate::grid::Grid::new(self.width(), self.height())
    }

    /// The nearest and farthest window depth over covered pixels, if any pixel is covered.
    #[must_use]
    pub fn depth_range(&self) -> Option<[f32; 2]> {
        let mut range: Option<[f32; 2]> = None;
        for (d, &c) in self.pixels.depth.iter().zip(&self.pixels.coverage) {
            if c > 0 {
                let r = range.get_or_insert([*d, *d]);
                r[0] = r[0].min(*d);
                r[1] = r[1].max(*d);
            }
        }
        range
    }

    /// The centre of window pixel `(x, y)` in fixed point.
    #[must_use]
    pub fn pixel_centre_fixed(x: u32, y: u32) -> I64Vec2 {
        I64Vec2::new(i64::from(x) * ONE + ONE / 2, i64::from(y) * ONE + ONE / 2)
    }
}
