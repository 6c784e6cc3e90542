//! "Explain this pixel": the colour of one pixel derived as a worked example, each line a formula
//! of the course with the capture's numbers substituted — the owning triangle's three vertices
//! from clip space through NDC to window coordinates, the edge functions and the screen-space
//! barycentrics, the interpolated attributes (perspective-correct), the texture lookup, the
//! lighting light by light, and the final colour.
//!
//! Everything is computed here, in the core, from what the capture recorded and with the same
//! functions the render used (`RasterTriangle::uv_at`, `Texture::sample`, `lighting::light_term`):
//! a view shows the lines, it computes nothing.

mod geometry;
mod lighting;
mod texture;

use glam::{I64Vec2, Vec2, Vec3, Vec4};
use serde::Serialize;

use super::{EdgeTest, FrameCapture, ObjectSummary, PrimitiveRecord};
use crate::light::Light;
use crate::lighting::{Frequency, LightTerm, Reflection, ShadeTerms};
use crate::raster::{ONE, RasterTriangle};
use crate::texture::BilinearTaps;
use crate::vertex::VertexRecord;

/// A part of the derivation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Section {
    /// The triangle's vertices through clip space, NDC and window coordinates.
    Vertices,
    /// The inside test: edge functions and screen-space barycentrics.
    Rasterization,
    /// Depth and the attributes at the pixel centre.
    Interpolation,
    /// The texture lookup.
    Texture,
    /// The lighting terms.
    Lighting,
    /// The colour of the pixel.
    Colour,
}

/// One line of the derivation: a formula, the same with the numbers substituted, and its value.
/// Formulas use `_` for subscripts, `^` for superscripts and `/` for fractions.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Line {
    /// Which part of the derivation.
    pub section: Section,
    /// The formula, as the course writes it.
    pub formula: String,
    /// The formula with the numbers substituted (empty when it would only repeat the value).
    pub numbers: String,
    /// The value.
    pub result: String,
    /// What the line means, in words (the words are the vocabulary's, in either language).
    pub remarks: Vec<Remark>,
}

/// What a line of the derivation means: the words beside its formula, as data, so that they can
/// be said in any language.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "remark")]
pub enum Remark {
    /// `w ≤ 0`: the vertex is behind the eye and has no NDC; clipping cut the triangle first.
    BehindEye,
    /// The triangle crosses the view volume: the pixel lies in a piece of the clipped polygon.
    Clipped,
    /// The corners, snapped to 1/256 pixel and counter-clockwise; `v_k` is vertex k of the
    /// triangle, `c_k` a corner clipping made.
    Corners,
    /// The centre of the pixel.
    PixelCentre,
    /// The edge function of the edge opposite corner `edge`.
    EdgeOpposite {
        /// The corner the edge faces.
        edge: usize,
    },
    /// Sample `index` of the pixel, covered or not.
    Sample {
        /// The sample.
        index: usize,
        /// Whether the triangle covers it.
        inside: bool,
    },
    /// A sample exactly on an edge: the top-left rule decides.
    OnEdge {
        /// The edge.
        edge: usize,
        /// Whether it is a top or a left edge (then the sample is inside).
        top_left: bool,
    },
    /// Depth is linear in screen space.
    ScreenLinear,
    /// Perspective-correct weights.
    PerspectiveCorrect,
    /// Affine (screen-space) weights, for comparison.
    Affine,
    /// Anisotropic filtering: taps along the footprint's major axis.
    Anisotropic,
    /// The screen derivatives are differences within the pixel's 2×2 quad, taken at its
    /// lower-left pixel `(x_q, y_q)`, as a GPU takes them: the quad's four pixels share them.
    Quad,
    /// `λ ≤ 0`: magnification, level 0.
    Magnification,
    /// No mipmap: level 0 always.
    NoMipmap,
    /// Mipmapping picks the nearest level, at most `max`.
    NearestLevel {
        /// The coarsest level.
        max: usize,
    },
    /// A ripmap: one level per axis of the footprint's bounding box.
    Ripmap,
    /// A summed-area table: the exact mean over the footprint's bounding box.
    SummedArea,
    /// EWA: a Gaussian over the footprint's ellipse.
    Ewa,
    /// Trilinear: levels `k` and `k + 1` blended by `t`, λ at most `max`.
    Trilinear {
        /// The coarsest level.
        max: usize,
    },
    /// The four texels bilinear filtering reads, in level `level` of `width × height`.
    Texels {
        /// The level.
        level: u32,
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
    /// Nearest filtering: the texel containing the point.
    NearestTexel,
    /// The mean of the anisotropic taps.
    TapsMean,
    /// Gouraud shading: lit at each vertex, the colours interpolated.
    Gouraud,
    /// Flat shading: lit once per face, at its provoking (last) vertex, with its own normal.
    Flat,
    /// A textured surface lit per vertex or face: the texel multiplies ambient and diffuse.
    Textured,
    /// Bump or normal mapping tilted the normal.
    Bump,
    /// A mirror: it reflects its environment along `r`, keeping `1 − k` of its own light.
    Mirror,
    /// The material's coefficients and shininess.
    Material,
    /// The ambient term `L_a`.
    Ambient,
    /// Light `index` of the scene (its kind: `point`, `directional`, `spot`).
    Light {
        /// Its index.
        index: usize,
        /// Its kind.
        kind: String,
    },
    /// The distance attenuation.
    Attenuation,
    /// A spotlight's cone: its factor is 0 outside the half-angle `cutoff`.
    SpotCone,
    /// The diffuse term `L_d`.
    Diffuse,
    /// The half vector (Blinn-Phong).
    HalfVector,
    /// The mirror direction of `l` (Phong).
    MirrorVector,
    /// The specular term `L_s`, zero where `n·l ≤ 0`.
    Specular,
    /// The colour: the terms' sum.
    Sum,
    /// The pixel: the mean of its samples (`covered` of `samples` by the owner).
    Samples {
        /// Covered samples.
        covered: usize,
        /// Samples per pixel.
        samples: usize,
    },
    /// A colour past [0, 1] clamped, as the colour buffer stores each sample.
    Clamped,
    /// The 8-bit colour written to the image.
    Bytes,
}

/// The texture lookup at the pixel, step by step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TextureStep {
    /// The texture's name.
    pub texture: String,
    /// Its level-0 size `(w, h)`.
    pub size: [u32; 2],
    /// `(u, v)` at the pixel centre.
    pub uv: Vec2,
    /// `∂(u, v)/∂x` and `∂(u, v)/∂y`: the differences to the next pixel.
    pub duv: [Vec2; 2],
    /// The footprint's axes in texels, `∂(u·w, v·h)/∂x` and `/∂y`.
    pub footprint: [Vec2; 2],
    /// Their lengths.
    pub lengths: [f32; 2],
    /// Taps along the major axis (anisotropic filtering).
    pub taps: u32,
    /// `λ` with the bias.
    pub lod: f32,
    /// The (finer) level read.
    pub level: u32,
    /// The weight of the next level (trilinear).
    pub blend: f32,
    /// The bilinear taps at the level read (one tap, bilinear filtering).
    pub bilinear: Option<BilinearTaps>,
    /// The colours of those four texels: `T(i0,j0), T(i1,j0), T(i0,j1), T(i1,j1)`.
    pub texels: Vec<Vec3>,
    /// The filtered colour.
    pub color: Vec3,
}

/// One light's part of the lighting at the pixel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LightStep {
    /// The light's index in the scene.
    pub index: usize,
    /// The light.
    pub light: Light,
    /// What it contributes (`None` for an ambient light: its term is `k_a·c·I_a`).
    pub term: Option<LightTerm>,
}

/// The lighting at the pixel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LightingStep {
    /// Where lighting was evaluated.
    pub frequency: Frequency,
    /// Phong or Blinn-Phong.
    pub reflection: Reflection,
    /// The normal used (world coordinates).
    pub normal: Vec3,
    /// `v = normalize(eye − p)`.
    pub view: Vec3,
    /// Each light (per-pixel lighting; for Gouraud and flat shading the vertices' or the face's
    /// terms are what was interpolated or used).
    pub lights: Vec<LightStep>,
    /// Gouraud: the lit colour at each vertex; flat: the face's (once).
    pub vertex_colors: Vec<Vec3>,
    /// The terms that sum to the shaded colour.
    pub terms: ShadeTerms,
}

/// The worked derivation of one pixel's colour.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelExplanation {
    /// Window column.
    pub x: u32,
    /// Window row (0 at the bottom).
    pub y: u32,
    /// The owning object's name.
    pub object: String,
    /// The owning primitive.
    pub primitive: u32,
    /// Whether the primitive was clipped (the pixel lies in a piece of it).
    pub clipped: bool,
    /// The primitive's three vertices through every space.
    pub vertices: [VertexRecord; 3],
    /// The inside test of the owning raster triangle at the pixel.
    pub edges: EdgeTest,
    /// `1/w_clip` of the raster triangle's corners.
    pub inv_w: [f32; 3],
    /// Which vertex of the primitive each corner of the raster triangle is (`None` for a corner
    /// that clipping made).
    pub corner_vertex: [Option<usize>; 3],
    /// Screen-space weights of the primitive's vertices (affine).
    pub bary_affine: [f32; 3],
    /// Perspective-correct weights of the primitive's vertices.
    pub bary_perspective: [f32; 3],
    /// Window depth at the centre.
    pub depth: f32,
    /// The surface point (world coordinates).
    pub position: Vec3,
    /// The interpolated unit normal (world coordinates).
    pub normal: Vec3,
    /// The interpolated vertex colour.
    pub vertex_color: Vec3,
    /// The texture lookup, when the object is textured.
    pub texture: Option<TextureStep>,
    /// The surface colour: the texel, or the interpolated vertex colour.
    pub surface: Vec3,
    /// The lighting, when it is on for the object.
    pub lighting: Option<LightingStep>,
    /// The owning triangle's colour at the centre.
    pub shaded: Vec3,
    /// Covered samples, and samples per pixel.
    pub coverage: [usize; 2],
    /// The pixel's final colour.
    pub color: Vec3,
    /// The derivation, line by line.
    pub lines: Vec<Line>,
}

/// A number as the derivation writes it: up to three decimals, no trailing zeros, `−` for minus.
pub(super) fn n(v: f32) -> String {
    if !v.is_finite() {
        return v.to_string();
    }
    let s = if v.abs() >= 1e5 || (v != 0.0 && v.abs() < 1e-3) {
        format!("{v:.3e}")
    } else {
        let s = format!("{v:.3}");
        let s = s.trim_end_matches('0').trim_end_matches('.').to_owned();
        if s == "-0" { "0".to_owned() } else { s }
    };
    s.replace('-', "−")
}

pub(super) fn n64(v: f64) -> String {
    n(v as f32)
}

pub(super) fn v2(v: Vec2) -> String {
    format!("({}, {})", n(v.x), n(v.y))
}

pub(super) fn v3(v: Vec3) -> String {
    format!("({}, {}, {})", n(v.x), n(v.y), n(v.z))
}

pub(super) fn v4(v: Vec4) -> String {
    format!("({}, {}, {}, {})", n(v.x), n(v.y), n(v.z), n(v.w))
}

/// Collects the lines.
pub(super) struct Lines(Vec<Line>);

impl Lines {
    pub(super) fn add(&mut self, section: Section, formula: &str, numbers: String, result: String) {
        self.0.push(Line {
            section,
            formula: formula.to_owned(),
            numbers,
            result,
            remarks: Vec::new(),
        });
    }

    /// Says what the last line means.
    pub(super) fn note(&mut self, remark: Remark) {
        if let Some(l) = self.0.last_mut() {
            l.remarks.push(remark);
        }
    }
}

/// `(x, y)` of a window point.
pub(super) fn pt(p: [f64; 2]) -> String {
    format!("({}, {})", n64(p[0]), n64(p[1]))
}

/// The fragment that owns the pixel being explained, and what is interpolated at its centre.
pub(super) struct Owner<'a> {
    /// The pixel's index in the image buffers.
    i: usize,
    tri: &'a RasterTriangle,
    prim: &'a PrimitiveRecord,
    object: &'a ObjectSummary,
    vertices: [VertexRecord; 3],
    /// The pixel centre, fixed point.
    centre: I64Vec2,
    /// The weights attributes are interpolated with (perspective-correct or affine).
    b: Vec3,
    /// `Σ b_k·p_k`, world coordinates.
    position: Vec3,
    /// `normalize(Σ b_k·n_k)`.
    normal: Vec3,
}

impl FrameCapture {
    /// The worked derivation of window pixel `(x, y)`'s colour (y up); `None` outside the
    /// viewport or where nothing was drawn.
    #[must_use]
    pub fn explain(&self, x: u32, y: u32) -> Option<PixelExplanation> {
        let i = self.grid().checked_index(x, y)?;
        let tri = self.triangles.get(self.pixels.owner[i] as usize)?;
        let prim = self.primitives.get(tri.primitive as usize)?;
        let object = self.objects.get(prim.object as usize)?;
        let vertices = prim.vertices.map(|r| self.vertices[r as usize]);
        let mut lines = Lines(Vec::new());
        self.explain_vertices(&vertices, prim.clipped_polygon.is_some(), &mut lines);

        let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
        let centre = Self::pixel_centre_fixed(x, y);
        let offsets = crate::raster::sample_offsets_fixed(self.settings.samples);
        let edges = EdgeTest::of(tri, corner, &offsets);
        // A corner of the original triangle has unit weights; one that clipping made, not.
        let bary = prim.bary_corners(tri);
        let corner_vertex = bary
            .map(|b| (0..3).find(|&k| (b[k] - 1.0).abs() < 1e-6 && b.element_sum() < 1.0 + 1e-6));
        geometry::explain_edges(&edges, &corner_vertex, &mut lines);

        let lambda = tri.lambda(centre);
        let pc = self.settings.perspective_correct;
        let (affine, perspective) = (
            tri.original_bary(&bary, lambda, false),
            tri.original_bary(&bary, lambda, true),
        );
        let b = if pc { perspective } else { affine };
        let depth = tri.depth_at(centre);
        geometry::explain_weights(tri, lambda, pc, b, depth, &mut lines);
        let blend = |f: &dyn Fn(&VertexRecord) -> Vec3| {
            f(&vertices[0]) * b.x + f(&vertices[1]) * b.y + f(&vertices[2]) * b.z
        };
        let owner = Owner {
            i,
            tri,
            prim,
            object,
            vertices,
            centre,
            b,
            position: blend(&|v| v.world.truncate()),
            normal: blend(&|v| v.normal_world).normalize_or_zero(),
        };
        let vertex_color = blend(&|v| v.color);
        geometry::explain_attributes(&owner, vertex_color, &mut lines);
        let texture = self.explain_texture(&owner, &mut lines);
        let surface = texture.as_ref().map_or(vertex_color, |t| t.color);
        let lighting = self.explain_lighting(&owner, surface, texture.is_some(), &mut lines);
        let shaded = lighting.as_ref().map_or(surface, |l| l.terms.color());
        let coverage = [
            usize::from(self.pixels.coverage[i]),
            self.settings.samples.count(),
        ];
        let color = Vec3::from(self.pixels.color[i]);
        self.explain_colour(lighting.as_ref(), shaded, coverage, color, &mut lines);
        Some(PixelExplanation {
            x,
            y,
            object: object.name.clone(),
            primitive: prim.id,
            clipped: prim.clipped_polygon.is_some(),
            vertices,
            edges,
            inv_w: tri.inv_w,
            corner_vertex,
            bary_affine: affine.to_array(),
            bary_perspective: perspective.to_array(),
            depth,
            position: owner.position,
            normal: owner.normal,
            vertex_color,
            texture,
            surface,
            lighting,
            shaded,
            coverage,
            color,
            lines: lines.0,
        })
    }

    /// The colour: the terms' sum, the samples' mean where the pixel is not wholly the owner's,
    /// and the 8-bit value.
    fn explain_colour(
        &self,
        lighting: Option<&LightingStep>,
        shaded: Vec3,
        [covered, samples]: [usize; 2],
        color: Vec3,
        lines: &mut Lines,
    ) {
        if let Some(l) = lighting {
            let t = &l.terms;
            let mirror = t.reflected != Vec3::ZERO;
            lines.add(
                Section::Colour,
                if mirror {
                    "c = L_a + L_d + L_s + L_r"
                } else {
                    "c = L_a + L_d + L_s"
                },
                format!(
                    "{} + {} + {}{}",
                    v3(t.ambient),
                    v3(t.diffuse),
                    v3(t.specular),
                    if mirror {
                        format!(" + {}", v3(t.reflected))
                    } else {
                        String::new()
                    }
                ),
                v3(shaded),
            );
            lines.note(Remark::Sum);
        }
        // The colour buffer keeps each sample clamped to [0, 1] (OpenGL 3.3 §4.1.8).
        let stored = shaded.clamp(Vec3::ZERO, Vec3::ONE);
        if stored != shaded {
            lines.add(
                Section::Colour,
                "c_s = clamp(c, 0, 1)",
                String::new(),
                v3(stored),
            );
            lines.note(Remark::Clamped);
        }
        if covered < samples || (color - stored).abs().max_element() > 1e-4 {
            lines.add(
                Section::Colour,
                "c_pixel = Σ_s c_s/S",
                format!(
                    "S = {samples}; c_background = {}",
                    v3(self.settings.background)
                ),
                v3(color),
            );
            lines.note(Remark::Samples { covered, samples });
        }
        let byte = |c: f32| (c.clamp(0.0, 1.0) * 255.0).round();
        lines.add(
            Section::Colour,
            "RGB_8 = round(255·c)",
            String::new(),
            format!("({}, {}, {})", byte(color.x), byte(color.y), byte(color.z)),
        );
        lines.note(Remark::Bytes);
    }
}
