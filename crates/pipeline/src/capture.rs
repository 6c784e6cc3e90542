//! `FrameCapture`: everything one frame did, stage by stage — the matrices with their factors,
//! the vertex table, the fate of every primitive, the raster triangles, the per-sample and
//! per-pixel buffers — and the images made from them. The app shows it, the exporter writes it,
//! the tests assert on it: a number comes from one place.

use glam::{I64Vec2, Vec3};
use half::f16;
use image::{ImageBuffer, Luma, Rgba, RgbaImage};
use serde::Serialize;

use crate::clip::{ClipPlane, ClipVertex};
use crate::overlay::{self, Overlay, OverlayKind, Shape};
use crate::raster::{NONE, ONE, RasterCounts, RasterTriangle, SampleBuffers};
use crate::scene::{Camera, Projection, RenderSettings};
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

/// Per-pixel buffers, top image row first (`index = row·width + column`).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PixelBuffers {
    /// Number of the pixel's samples that a primitive covers (after the depth test).
    pub coverage: Vec<u8>,
    /// Window depth `z_w ∈ [0, 1]`, the mean over the pixel's samples (cleared ones count as the
    /// clear depth); with one sample, the depth at the pixel centre.
    pub depth: Vec<f32>,
    /// The primitive that owns most of the pixel's samples (ties: the earliest sample), or
    /// [`NONE`].
    pub primitive: Vec<u32>,
    /// The raster triangle of that primitive seen at the pixel (an index into
    /// [`FrameCapture::triangles`]), or [`NONE`]. The barycentric weights at the pixel centre
    /// are a function of it ([`FrameCapture::barycentrics`]), so they are derived, not stored.
    pub owner: Vec<u32>,
    /// The resolved colour: each sample takes the colour of its triangle evaluated once at the
    /// pixel centre (multisampling shades once per pixel), uncovered samples the background;
    /// the pixel is their mean.
    pub color: Vec<[f32; 3]>,
    /// The lighting terms of the owning fragment at the pixel centre, when lighting is on.
    pub shading: Option<ShadingBuffers>,
    /// The texture lookup of the owning fragment, when an object is textured.
    pub texturing: Option<TextureBuffers>,
}

/// The barycentric weights of a pixel's owning fragment at the pixel centre.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Barycentrics {
    /// Perspective-correct: `(λ_k/w_k) / Σ_j(λ_j/w_j)`, relative to the original triangle.
    pub perspective: [f32; 3],
    /// Affine (screen-space) `λ_k`, relative to the original triangle.
    pub affine: [f32; 3],
}

/// Per-pixel texture lookups of the owning fragment, top image row first. The uvs are 32-bit
/// floats (a texel address needs their bits); the rest are half floats, 11 significant bits
/// (relative error ≤ 2⁻¹¹), as a GPU keeps a G-buffer: read them as `f32` with [`Self::at`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TextureBuffers {
    /// The texture coordinates at the pixel centre.
    pub uv: Vec<[f32; 2]>,
    /// The level of detail `λ = log₂ L + bias` (fractional, not clamped).
    pub lod: Vec<f16>,
    /// The level read: `k + blend` (trilinear blends levels k and k+1).
    pub level: Vec<f16>,
    /// The filtered texel colour.
    pub texel: Vec<[f16; 3]>,
    /// The footprint's axes in texels, `(∂s/∂x, ∂t/∂x, ∂s/∂y, ∂t/∂y)` with `(s, t) = (u·w, v·h)`.
    pub footprint: Vec<[f16; 4]>,
}

impl TextureBuffers {
    /// These buffers' storage holding `n` pixels (the new ones zero; from `default()`: new
    /// buffers).
    #[must_use]
    pub fn resized(mut self, n: usize) -> Self {
        self.uv.resize(n, [0.0; 2]);
        self.lod.resize(n, f16::ZERO);
        self.level.resize(n, f16::ZERO);
        self.texel.resize(n, [f16::ZERO; 3]);
        self.footprint.resize(n, [f16::ZERO; 4]);
        self
    }

    /// The buffers cut into image rows of `width` pixels, to be written in parallel.
    pub fn rows(&mut self, width: usize) -> Vec<TextureRow<'_>> {
        self.uv
            .chunks_mut(width)
            .zip(self.lod.chunks_mut(width))
            .zip(self.level.chunks_mut(width))
            .zip(self.texel.chunks_mut(width))
            .zip(self.footprint.chunks_mut(width))
            .map(|((((uv, lod), level), texel), footprint)| TextureRow {
                uv,
                lod,
                level,
                texel,
                footprint,
            })
            .collect()
    }

    /// The lookup at pixel `i`, as 32-bit floats.
    #[must_use]
    pub fn at(&self, i: usize) -> PixelTexture {
        PixelTexture {
            uv: self.uv[i],
            footprint: self.footprint[i].map(f16::to_f32),
            lod: self.lod[i].to_f32(),
            level: self.level[i].to_f32(),
            texel: self.texel[i].map(f16::to_f32),
        }
    }
}

/// Per-pixel lighting terms of the owning fragment (see `shade`), top image row first, as half
/// floats (11 significant bits, relative error ≤ 2⁻¹¹, as a GPU's RGBA16F G-buffer): read them
/// as `f32` with [`Self::at`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ShadingBuffers {
    /// `Σ k_a·I_a`.
    pub ambient: Vec<[f16; 3]>,
    /// `Σ f_att·k_d·I_d·max(l·n, 0)`.
    pub diffuse: Vec<[f16; 3]>,
    /// `Σ f_att·k_s·I_s·max(r·v, 0)^α` or `max(n·h, 0)^β`.
    pub specular: Vec<[f16; 3]>,
    /// The unit normal used, world coordinates.
    pub normal: Vec<[f16; 3]>,
    /// `n·l` of the key light.
    pub n_dot_l: Vec<f16>,
    /// `n·h` (Blinn-Phong) or `r·v` (Phong) of the key light.
    pub n_dot_h: Vec<f16>,
    /// `k·C_env(r)`, what a mirror surface reflects from its environment (zero elsewhere).
    pub reflected: Vec<[f16; 3]>,
}

impl ShadingBuffers {
    /// These buffers' storage holding `n` pixels (the new ones zero; from `default()`: new
    /// buffers).
    #[must_use]
    pub fn resized(mut self, n: usize) -> Self {
        for v in [
            &mut self.ambient,
            &mut self.diffuse,
            &mut self.specular,
            &mut self.normal,
            &mut self.reflected,
        ] {
            v.resize(n, [f16::ZERO; 3]);
        }
        self.n_dot_l.resize(n, f16::ZERO);
        self.n_dot_h.resize(n, f16::ZERO);
        self
    }

    /// The buffers cut into image rows of `width` pixels, to be written in parallel.
    pub fn rows(&mut self, width: usize) -> Vec<ShadingRow<'_>> {
        self.ambient
            .chunks_mut(width)
            .zip(self.diffuse.chunks_mut(width))
            .zip(self.specular.chunks_mut(width))
            .zip(self.normal.chunks_mut(width))
            .zip(self.n_dot_l.chunks_mut(width))
            .zip(self.n_dot_h.chunks_mut(width))
            .zip(self.reflected.chunks_mut(width))
            .map(
                |((((((ambient, diffuse), specular), normal), n_dot_l), n_dot_h), reflected)| {
                    ShadingRow {
                        ambient,
                        diffuse,
                        specular,
                        normal,
                        n_dot_l,
                        n_dot_h,
                        reflected,
                    }
                },
            )
            .collect()
    }

    /// The terms at pixel `i`, as 32-bit floats.
    #[must_use]
    pub fn at(&self, i: usize) -> PixelLighting {
        let f = |v: [f16; 3]| v.map(f16::to_f32);
        PixelLighting {
            ambient: f(self.ambient[i]),
            diffuse: f(self.diffuse[i]),
            specular: f(self.specular[i]),
            reflected: f(self.reflected[i]),
            normal: f(self.normal[i]),
            n_dot_l: self.n_dot_l[i].to_f32(),
            n_dot_h: self.n_dot_h[i].to_f32(),
        }
    }
}

/// One image row of the texturing buffers (see [`TextureBuffers::rows`]).
pub struct TextureRow<'a> {
    uv: &'a mut [[f32; 2]],
    lod: &'a mut [f16],
    level: &'a mut [f16],
    texel: &'a mut [[f16; 3]],
    footprint: &'a mut [[f16; 4]],
}

/// Half-float values a pixel's texture lookup has: λ, level, texel 3, footprint 4.
pub const TEXTURE_HALVES: usize = 9;
/// Half-float values a pixel's lighting has: ambient, diffuse, specular, normal, reflected 3
/// each, n·l, n·h.
pub const LIGHTING_HALVES: usize = 17;

impl TextureRow<'_> {
    /// A lookup as the row stores it: its uv (kept at 32 bits) and its [`TEXTURE_HALVES`]
    /// values in storage order (zero: no lookup).
    #[must_use]
    pub fn flatten(t: Option<&PixelTexture>) -> ([f32; 2], [f32; TEXTURE_HALVES]) {
        t.map_or(([0.0; 2], [0.0; TEXTURE_HALVES]), |t| {
            let ([a, b, c], [d, e, f, g]) = (t.texel, t.footprint);
            (t.uv, [t.lod, t.level, a, b, c, d, e, f, g])
        })
    }

    /// Stores a row: `uvs` and `floats` ([`TEXTURE_HALVES`] a pixel, from [`Self::flatten`])
    /// converted to half floats in one pass (vectorised where the processor converts in
    /// hardware) through the reused `halves`.
    pub fn store(&mut self, uvs: &[[f32; 2]], floats: &[f32], halves: &mut Vec<f16>) {
        self.uv.copy_from_slice(uvs);
        for (x, h) in convert(floats, halves)
            .chunks_exact(TEXTURE_HALVES)
            .enumerate()
        {
            self.lod[x] = h[0];
            self.level[x] = h[1];
            self.texel[x] = [h[2], h[3], h[4]];
            self.footprint[x] = [h[5], h[6], h[7], h[8]];
        }
    }
}

/// `floats` as half floats, in `halves`' storage.
fn convert<'a>(floats: &[f32], halves: &'a mut Vec<f16>) -> &'a [f16] {
    use half::slice::HalfFloatSliceExt;
    halves.resize(floats.len(), f16::ZERO);
    halves.convert_from_f32_slice(floats);
    halves
}

/// One image row of the lighting buffers (see [`ShadingBuffers::rows`]).
pub struct ShadingRow<'a> {
    ambient: &'a mut [[f16; 3]],
    diffuse: &'a mut [[f16; 3]],
    specular: &'a mut [[f16; 3]],
    normal: &'a mut [[f16; 3]],
    n_dot_l: &'a mut [f16],
    n_dot_h: &'a mut [f16],
    reflected: &'a mut [[f16; 3]],
}

impl ShadingRow<'_> {
    /// Lighting terms as the row stores them, in storage order (zero: unlit there).
    #[must_use]
    pub fn flatten(t: Option<&crate::shade::ShadeTerms>) -> [f32; LIGHTING_HALVES] {
        let Some(t) = t else {
            return [0.0; LIGHTING_HALVES];
        };
        let mut out = [0.0; LIGHTING_HALVES];
        for (k, v) in [t.ambient, t.diffuse, t.specular, t.normal, t.reflected]
            .into_iter()
            .enumerate()
        {
            out[3 * k..3 * k + 3].copy_from_slice(&v.to_array());
        }
        (out[15], out[16]) = (t.n_dot_l, t.n_dot_h);
        out
    }

    /// Stores a row: `floats` ([`LIGHTING_HALVES`] a pixel, from [`Self::flatten`]) converted to
    /// half floats in one pass through the reused `halves`.
    pub fn store(&mut self, floats: &[f32], halves: &mut Vec<f16>) {
        for (x, h) in convert(floats, halves)
            .chunks_exact(LIGHTING_HALVES)
            .enumerate()
        {
            self.ambient[x] = [h[0], h[1], h[2]];
            self.diffuse[x] = [h[3], h[4], h[5]];
            self.specular[x] = [h[6], h[7], h[8]];
            self.normal[x] = [h[9], h[10], h[11]];
            self.reflected[x] = [h[12], h[13], h[14]];
            self.n_dot_l[x] = h[15];
            self.n_dot_h[x] = h[16];
        }
    }
}

/// Which image of a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BufferKind {
    /// The final colour, 8 bits per channel = round(255·c), no gamma conversion.
    Color,
    /// Window depth as grey, stretched from the nearest (black) to the farthest (white) depth
    /// present; background white.
    Depth,
    /// Covered samples / samples per pixel as grey (black: none, white: all).
    Coverage,
    /// Each primitive id in its own hue (golden-ratio hue steps); background black.
    PrimitiveId,
    /// Perspective-correct barycentrics `(b0, b1, b2)` as `(R, G, B)`; background black.
    BaryPerspective,
    /// Affine barycentrics `(λ0, λ1, λ2)` as `(R, G, B)`; background black.
    BaryAffine,
    /// The ambient term, 8 bits per channel; background black.
    Ambient,
    /// The diffuse term.
    Diffuse,
    /// The specular term.
    Specular,
    /// The normal used for lighting, `(n + 1)/2` as RGB.
    Normal,
    /// `max(n·l, 0)` of the key light as grey.
    NDotL,
    /// `max(n·h, 0)` (or `r·v`) of the key light as grey.
    NDotH,
    /// Texture coordinates `(fract u, fract v)` as red and green.
    Uv,
    /// The mip level read, each level in its own colour (blended for trilinear).
    MipLevel,
    /// The filtered texel colour.
    Texel,
    /// The footprint of the pixel in the texture: hue the direction of its long axis,
    /// saturation its anisotropy.
    Footprint,
    /// The environment map's reflected term.
    Reflected,
}

impl BufferKind {
    /// Every 8-bit image kind, in the order of the stages.
    pub const ALL: [BufferKind; 17] = [
        Self::Coverage,
        Self::PrimitiveId,
        Self::Depth,
        Self::BaryPerspective,
        Self::BaryAffine,
        Self::Normal,
        Self::NDotL,
        Self::NDotH,
        Self::Uv,
        Self::MipLevel,
        Self::Footprint,
        Self::Texel,
        Self::Ambient,
        Self::Diffuse,
        Self::Specular,
        Self::Reflected,
        Self::Color,
    ];

    /// Whether the buffer holds a lighting term (present only when lighting is on).
    #[must_use]
    pub fn is_lighting(self) -> bool {
        matches!(
            self,
            Self::Ambient
                | Self::Diffuse
                | Self::Specular
                | Self::Normal
                | Self::NDotL
                | Self::NDotH
                | Self::Reflected
        )
    }

    /// Whether the buffer holds a texture lookup (present only when an object is textured).
    #[must_use]
    pub fn is_texturing(self) -> bool {
        matches!(
            self,
            Self::Uv | Self::MipLevel | Self::Texel | Self::Footprint
        )
    }

    /// A file-name friendly name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Color => "color",
            Self::Depth => "depth",
            Self::Coverage => "coverage",
            Self::PrimitiveId => "primitive_id",
            Self::BaryPerspective => "bary_perspective",
            Self::BaryAffine => "bary_affine",
            Self::Ambient => "ambient",
            Self::Diffuse => "diffuse",
            Self::Specular => "specular",
            Self::Normal => "normal",
            Self::NDotL => "n_dot_l",
            Self::NDotH => "n_dot_h",
            Self::Uv => "uv",
            Self::MipLevel => "mip_level",
            Self::Texel => "texel",
            Self::Footprint => "footprint",
            Self::Reflected => "reflected",
        }
    }

    /// How the buffer's values become colours (for documentation and the capture's JSON).
    #[must_use]
    pub fn mapping(self) -> &'static str {
        match self {
            Self::Color => "RGB = round(255·colour), no gamma conversion",
            Self::Depth => {
                "grey = 255·(z_w − z_min)/(z_max − z_min) over covered pixels (depth_range); \
                 background white"
            }
            Self::Coverage => "grey = 255·covered samples/samples per pixel",
            Self::PrimitiveId => {
                "hue = fract(id·0.618034), full saturation and value; background black"
            }
            Self::BaryPerspective => {
                "RGB = 255·(b0, b1, b2), perspective-correct; background black"
            }
            Self::BaryAffine => "RGB = 255·(λ0, λ1, λ2), screen-space; background black",
            Self::Ambient => "RGB = round(255·Σ k_a·I_a), clamped; background black",
            Self::Diffuse => {
                "RGB = round(255·Σ f_att·k_d·I_d·max(l·n, 0)), clamped; background black"
            }
            Self::Specular => {
                "RGB = round(255·Σ f_att·k_s·I_s·max(n·h, 0)^β) (or (r·v)^α), clamped; background black"
            }
            Self::Normal => "RGB = 255·(n + 1)/2 of the unit world-space normal; background black",
            Self::NDotL => "grey = 255·max(n·l, 0) of the key light; background black",
            Self::NDotH => {
                "grey = 255·max(n·h, 0) (Blinn-Phong) or max(r·v, 0) (Phong); background black"
            }
            Self::Uv => "RGB = 255·(fract u, fract v, 0); background black",
            Self::MipLevel => {
                "level k in colour k (0 white, 1 red, 2 orange, 3 yellow, 4 green, 5 cyan, 6 blue, \
                 7+ violet), trilinear blends the two; background black"
            }
            Self::Texel => "RGB = round(255·filtered texel); background black",
            Self::Footprint => {
                "hue = direction of the footprint's long axis in the texture (0°–180°: red along s, \
                 cyan along t), saturation = min(log₂(major/minor)/3, 1): white isotropic, \
                 saturated ≥ 8:1; background black"
            }
            Self::Reflected => {
                "RGB = round(255·k·C_env(r)), r = 2(n·v)n − v, for mirror objects; black elsewhere"
            }
        }
    }
}

/// One fragment that reached a pixel: a raster triangle covering at least one of its samples,
/// replayed in drawing order against the pixel's depth values.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FragmentRecord {
    /// The primitive (input triangle).
    pub primitive: u32,
    /// The raster triangle (index into [`FrameCapture::triangles`]).
    pub triangle: u32,
    /// Per sample of the pixel: `None` not covered; `Some(true)` covered and passed the depth
    /// test against what was stored then; `Some(false)` covered and failed it.
    pub samples: Vec<Option<bool>>,
    /// Per sample: the fragment's window depth there (`None` where not covered).
    pub sample_depths: Vec<Option<f32>>,
    /// Window depth at the pixel centre.
    pub depth: f32,
    /// Affine (screen-space) barycentrics at the pixel centre.
    pub bary_affine: [f32; 3],
    /// Perspective-correct barycentrics at the pixel centre.
    pub bary_perspective: [f32; 3],
    /// Whether the fragment owns the pixel in the final image (most of its samples).
    pub visible: bool,
}

/// Everything the capture knows about one pixel: what reached it and what it computed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelRecord {
    /// Window column.
    pub x: u32,
    /// Window row (0 at the bottom).
    pub y: u32,
    /// Covered samples.
    pub coverage: u8,
    /// Mean window depth of the samples.
    pub depth: f32,
    /// The final colour.
    pub color: [f32; 3],
    /// The owning primitive, if any.
    pub primitive: Option<u32>,
    /// The owning fragment's lighting terms (when lit).
    pub lighting: Option<PixelLighting>,
    /// The owning fragment's texture lookup (when textured).
    pub texture: Option<PixelTexture>,
    /// The lighting vectors there (when lit).
    pub vectors: Option<PixelVectors>,
    /// Every fragment that reached the pixel, in drawing order.
    pub fragments: Vec<FragmentRecord>,
}

/// The lighting terms at one pixel (see [`ShadingBuffers`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelLighting {
    /// `Σ k_a·I_a`.
    pub ambient: [f32; 3],
    /// `Σ f_att·k_d·I_d·max(n·l, 0)`.
    pub diffuse: [f32; 3],
    /// `Σ f_att·k_s·I_s·max(n·h, 0)^p`.
    pub specular: [f32; 3],
    /// `k·C_env(r)`.
    pub reflected: [f32; 3],
    /// The unit normal.
    pub normal: [f32; 3],
    /// `n·l` of the key light.
    pub n_dot_l: f32,
    /// `n·h` (or `r·v`) of the key light.
    pub n_dot_h: f32,
}

/// The texture lookup at one pixel (see [`TextureBuffers`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelTexture {
    /// `(u, v)`.
    pub uv: [f32; 2],
    /// The footprint's axes in texels, `[∂s/∂x, ∂t/∂x, ∂s/∂y, ∂t/∂y]`.
    pub footprint: [f32; 4],
    /// `λ` with the bias.
    pub lod: f32,
    /// The level read (`k + blend`).
    pub level: f32,
    /// The filtered texel.
    pub texel: [f32; 3],
}

impl PixelTexture {
    /// The record of lookup `l` at texture coordinates `uv`.
    #[must_use]
    pub fn new(uv: glam::Vec2, l: &crate::texture::Lookup) -> Self {
        let [dx, dy] = l.footprint;
        Self {
            uv: uv.to_array(),
            footprint: [dx.x, dx.y, dy.x, dy.y],
            lod: l.lod,
            level: l.level as f32 + l.level_blend,
            texel: l.color.to_array(),
        }
    }
}

/// The vectors of the lighting at a pixel, in world coordinates: where the surface is, its unit
/// normal, and the unit vectors to the key light, to the eye and halfway between them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PixelVectors {
    /// The surface point `p = Σ b_i·p_i` of the owning fragment.
    pub position: Vec3,
    /// `n`, as lit.
    pub normal: Vec3,
    /// `l`, towards the key light (the first light that is not ambient).
    pub light: Vec3,
    /// `v = normalize(eye − p)`.
    pub view: Vec3,
    /// `h = normalize(l + v)`.
    pub half: Vec3,
}

/// One sample of an intensity profile along a line of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ProfileSample {
    /// Position along the line, 0 at its start, 1 at its end.
    pub t: f32,
    /// Image column.
    pub x: u32,
    /// Image row (0 at the top).
    pub y: u32,
    /// The final colour there.
    pub rgb: [f32; 3],
    /// Luminance `0.2126·R + 0.7152·G + 0.0722·B` (Rec. 709 weights).
    pub intensity: f32,
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
    pub lights: Vec<crate::scene::Light>,
    /// The objects drawn.
    pub objects: Vec<ObjectSummary>,
    /// The matrices with their factors.
    pub matrices: Matrices,
    /// The vertex table: every vertex of every object through every space.
    pub vertices: Vec<VertexRecord>,
    /// The lighting at each vertex (a row per vertex-table row), with Gouraud shading; empty
    /// otherwise.
    pub vertex_shading: Vec<crate::shade::ShadeTerms>,
    /// The lighting of each face (a row per primitive, evaluated once at its centroid), with
    /// flat shading; empty otherwise.
    pub face_shading: Vec<crate::shade::ShadeTerms>,
    /// The textures the frame read, by object name (their mip pyramids can be shown and exported).
    pub textures: Vec<(String, std::sync::Arc<crate::texture::Texture>)>,
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
}

fn to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn hue_color(id: u32) -> [u8; 3] {
    hue((id as f32 * 0.618_034).fract()).map(to_u8)
}

/// The fully saturated colour of hue `h ∈ [0, 1)` (red, yellow, green, cyan, blue, magenta).
fn hue(h: f32) -> [f32; 3] {
    let h = h.rem_euclid(1.0) * 6.0;
    let x = 1.0 - ((h % 2.0) - 1.0).abs();
    match h as u32 {
        0 => [1.0, x, 0.0],
        1 => [x, 1.0, 0.0],
        2 => [0.0, 1.0, x],
        3 => [0.0, x, 1.0],
        4 => [x, 0.0, 1.0],
        _ => [1.0, 0.0, x],
    }
}

/// The colour of a lighting buffer at pixel `i`.
fn lighting_rgb(sh: &ShadingBuffers, kind: BufferKind, i: usize) -> [u8; 3] {
    let rgb = |v: [f16; 3]| v.map(|c| to_u8(c.to_f32()));
    match kind {
        BufferKind::Ambient => rgb(sh.ambient[i]),
        BufferKind::Diffuse => rgb(sh.diffuse[i]),
        BufferKind::Specular => rgb(sh.specular[i]),
        BufferKind::Normal => sh.normal[i].map(|v| to_u8((v.to_f32() + 1.0) / 2.0)),
        BufferKind::NDotL => [to_u8(sh.n_dot_l[i].to_f32()); 3],
        BufferKind::NDotH => [to_u8(sh.n_dot_h[i].to_f32()); 3],
        BufferKind::Reflected => rgb(sh.reflected[i]),
        _ => [0; 3],
    }
}

/// The footprint colour: the long axis' angle `θ ∈ [0°, 180°)` as hue (a line has no sign, so
/// hue = 2θ), the anisotropy `a = major/minor` as saturation `min(log₂ a / 3, 1)`.
fn footprint_rgb([sx, tx, sy, ty]: [f32; 4]) -> [u8; 3] {
    let (lx, ly) = (sx.hypot(tx), sy.hypot(ty));
    if lx == 0.0 && ly == 0.0 {
        return [0; 3];
    }
    let (major, minor, (s, t)) = if lx >= ly {
        (lx, ly, (sx, tx))
    } else {
        (ly, lx, (sy, ty))
    };
    let angle = t.atan2(s).rem_euclid(std::f32::consts::PI);
    let saturation = ((major / minor.max(1e-6)).log2() / 3.0).clamp(0.0, 1.0);
    hue(angle / std::f32::consts::PI).map(|c| to_u8(1.0 - saturation * (1.0 - c)))
}

/// The colour of a texturing buffer at pixel `i`.
fn texturing_rgb(tb: &TextureBuffers, kind: BufferKind, i: usize) -> [u8; 3] {
    match kind {
        BufferKind::Uv => {
            let [u, v] = tb.uv[i];
            [to_u8(u.rem_euclid(1.0)), to_u8(v.rem_euclid(1.0)), 0]
        }
        BufferKind::MipLevel => {
            let l = tb.level[i].to_f32();
            let k = l.floor().max(0.0) as u32;
            crate::texture::level_color(k)
                .lerp(crate::texture::level_color(k + 1), l.fract())
                .to_array()
                .map(to_u8)
        }
        BufferKind::Texel => tb.texel[i].map(|c| to_u8(c.to_f32())),
        BufferKind::Footprint => footprint_rgb(tb.footprint[i].map(f16::to_f32)),
        _ => [0; 3],
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
        let (w, h) = (self.width() as usize, self.height() as usize);
        let (x, y) = (i % w, h - 1 - i / w);
        let l = tri.lambda(Self::pixel_centre_fixed(x as u32, y as u32));
        Some(Barycentrics {
            perspective: tri.original_bary(l, true).to_array(),
            affine: tri.original_bary(l, false).to_array(),
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

    /// The image of one buffer (see [`BufferKind`] for each colour mapping).
    #[must_use]
    pub fn image(&self, kind: BufferKind) -> RgbaImage {
        if kind == BufferKind::Depth {
            return self.depth_image(false, None);
        }
        let (w, h) = (self.width(), self.height());
        let px = &self.pixels;
        let samples = self.settings.samples.count() as f32;
        ImageBuffer::from_fn(w, h, |x, y| {
            let i = (y * w + x) as usize;
            let covered = px.primitive[i] != NONE;
            let rgb = match kind {
                BufferKind::Color => px.color[i].map(to_u8),
                BufferKind::Depth => [255; 3], // drawn by depth_image
                BufferKind::Coverage => [to_u8(f32::from(px.coverage[i]) / samples); 3],
                BufferKind::PrimitiveId if covered => hue_color(px.primitive[i]),
                BufferKind::BaryPerspective if covered => self
                    .barycentrics(i)
                    .map_or([0; 3], |b| b.perspective.map(to_u8)),
                BufferKind::BaryAffine if covered => {
                    self.barycentrics(i).map_or([0; 3], |b| b.affine.map(to_u8))
                }
                BufferKind::PrimitiveId | BufferKind::BaryPerspective | BufferKind::BaryAffine => {
                    [0; 3]
                }
                k if k.is_texturing() => match (&px.texturing, covered) {
                    (Some(tb), true) => texturing_rgb(tb, k, i),
                    _ => [0; 3],
                },
                k => match (&px.shading, covered) {
                    (Some(sh), true) => lighting_rgb(sh, k, i),
                    _ => [0; 3],
                },
            };
            Rgba([rgb[0], rgb[1], rgb[2], 255])
        })
    }

    /// The eye-space distance along −z of window depth `z_w` (undoing the projection's depth
    /// mapping): perspective `d = 2·f·n / ((f + n) − z_ndc·(f − n))` with `z_ndc = 2·z_w − 1`;
    /// parallel `d = n + z_w·(f − n)`.
    #[must_use]
    pub fn eye_depth(&self, z_w: f32) -> f32 {
        let [.., n, f] = self.projection.bounds(self.settings.aspect());
        if self.projection.is_perspective() {
            let z_ndc = 2.0 * z_w - 1.0;
            2.0 * f * n / ((f + n) - z_ndc * (f - n))
        } else {
            n + z_w * (f - n)
        }
    }

    /// The depth buffer as grey over `range` (black at its start, white at its end), of window
    /// depth `z_w`, or of eye distance ([`Self::eye_depth`]) when `linear`. Without a range, the
    /// nearest and farthest covered values. Background white.
    #[must_use]
    pub fn depth_image(&self, linear: bool, range: Option<[f32; 2]>) -> RgbaImage {
        let value = |z: f32| if linear { self.eye_depth(z) } else { z };
        let [lo, hi] = range.unwrap_or_else(|| {
            self.depth_range()
                .map_or([0.0, 1.0], |[a, b]| [value(a), value(b)])
        });
        let span = (hi - lo).abs().max(f32::EPSILON);
        let w = self.width();
        ImageBuffer::from_fn(w, self.height(), |x, y| {
            let i = (y * w + x) as usize;
            let g = if self.pixels.primitive[i] == NONE {
                255
            } else {
                to_u8((value(self.pixels.depth[i]) - lo) / span)
            };
            Rgba([g, g, g, 255])
        })
    }

    /// The depth buffer as 16-bit grey, `round(z_w·65535)`, with no stretching.
    #[must_use]
    pub fn depth16(&self) -> ImageBuffer<Luma<u16>, Vec<u16>> {
        let w = self.width();
        ImageBuffer::from_fn(w, self.height(), |x, y| {
            let d = self.pixels.depth[(y * w + x) as usize];
            Luma([(d.clamp(0.0, 1.0) * 65535.0).round() as u16])
        })
    }

    /// Converts window coordinates (y up) to image pixel coordinates (y down).
    #[must_use]
    pub fn window_to_image(&self, p: Vec3) -> [f32; 2] {
        [p.x, self.height() as f32 - p.y]
    }

    /// The shapes of one overlay, in image pixel coordinates.
    #[must_use]
    pub fn overlay(&self, kind: OverlayKind) -> Overlay {
        Overlay {
            kind,
            shapes: self.overlay_shapes(kind).collect(),
        }
    }

    /// The shapes of one overlay, made one raster triangle at a time (a view that draws only
    /// some of a million need not build them all).
    pub fn overlay_shapes(&self, kind: OverlayKind) -> impl Iterator<Item = Shape> + '_ {
        let h = self.height() as f32;
        self.triangles.iter().map(move |t| match kind {
            OverlayKind::TriangleEdges => Shape::Polyline {
                points: t.window.iter().map(|p| self.window_to_image(*p)).collect(),
                closed: true,
                color: [255, 255, 255, 220],
                width: 1.0,
            },
            OverlayKind::BoundingBoxes => {
                let [x0, y0, x1, y1] = t.bbox.map(|v| v as f32);
                Shape::Rect {
                    min: [x0, h - (y1 + 1.0)],
                    max: [x1 + 1.0, h - y0],
                    color: [255, 200, 40, 200],
                    width: 1.0,
                }
            }
        })
    }

    /// `kind`'s image magnified `zoom` times (nearest neighbour, so pixels stay crisp) with the
    /// given overlays drawn over it by tiny-skia.
    #[must_use]
    pub fn image_with_overlays(
        &self,
        kind: BufferKind,
        overlays: &[OverlayKind],
        zoom: u32,
    ) -> RgbaImage {
        let shapes: Vec<Shape> = overlays
            .iter()
            .flat_map(|&k| self.overlay(k).shapes)
            .collect();
        self.image_with_shapes(kind, &shapes, zoom)
    }

    /// Where world point `p` lands in the image (pixels, y down): `P·V·p`, divided by `w`, through
    /// the viewport; `None` behind the camera (`w ≤ 1e-5`).
    #[must_use]
    pub fn world_to_image(&self, p: Vec3) -> Option<[f32; 2]> {
        let clip = self.matrices.projection.matrix * self.matrices.view.matrix * p.extend(1.0);
        self.clip_to_image(clip)
    }

    fn clip_to_image(&self, clip: glam::Vec4) -> Option<[f32; 2]> {
        (clip.w > 1e-5).then(|| {
            let (w, h) = (self.width() as f32, self.height() as f32);
            let ndc = clip.truncate() / clip.w;
            [(ndc.x + 1.0) * w / 2.0, h - (ndc.y + 1.0) * h / 2.0]
        })
    }

    /// The world segment `a`–`b` in image pixels, the part behind the camera cut away (at
    /// `w = 1e-5` in clip space, as clipping does); `None` when all of it is behind.
    #[must_use]
    pub fn world_segment_to_image(&self, a: Vec3, b: Vec3) -> Option<[[f32; 2]; 2]> {
        let pv = self.matrices.projection.matrix * self.matrices.view.matrix;
        let (mut ca, mut cb) = (pv * a.extend(1.0), pv * b.extend(1.0));
        let eps = 1e-5;
        if ca.w <= eps && cb.w <= eps {
            return None;
        }
        if ca.w <= eps || cb.w <= eps {
            let t = (eps * 1.001 - ca.w) / (cb.w - ca.w);
            let cut = ca.lerp(cb, t);
            if ca.w <= eps {
                ca = cut;
            } else {
                cb = cut;
            }
        }
        Some([self.clip_to_image(ca)?, self.clip_to_image(cb)?])
    }

    /// An image of buffer `kind`, magnified `zoom`× (nearest), with `shapes` drawn over it.
    #[must_use]
    pub fn image_with_shapes(&self, kind: BufferKind, shapes: &[Shape], zoom: u32) -> RgbaImage {
        let zoom = zoom.max(1);
        let base = self.image(kind);
        let (w, h) = (base.width() * zoom, base.height() * zoom);
        let Some(mut pixmap) = tiny_skia::Pixmap::new(w, h) else {
            return base;
        };
        for (i, px) in pixmap.pixels_mut().iter_mut().enumerate() {
            let (x, y) = (i as u32 % w / zoom, i as u32 / w / zoom);
            let c = base.get_pixel(x, y).0;
            if let Some(p) = tiny_skia::PremultipliedColorU8::from_rgba(c[0], c[1], c[2], 255) {
                *px = p;
            }
        }
        overlay::draw(&mut pixmap, shapes, zoom as f32);
        ImageBuffer::from_fn(w, h, |x, y| {
            let c = pixmap.pixel(x, y).map(|p| p.demultiply());
            c.map_or(Rgba([0, 0, 0, 255]), |c| {
                Rgba([c.red(), c.green(), c.blue(), c.alpha()])
            })
        })
    }

    /// The lighting vectors at window pixel `(x, y)`: `None` where nothing is drawn, lighting
    /// is off, or no light has a direction.
    #[must_use]
    pub fn pixel_vectors(&self, x: u32, y: u32) -> Option<PixelVectors> {
        if x >= self.width() || y >= self.height() {
            return None;
        }
        let i = ((self.height() - 1 - y) * self.width() + x) as usize;
        let prim = self.primitives.get(self.pixels.primitive[i] as usize)?;
        let normal = Vec3::from(self.pixels.shading.as_ref()?.at(i).normal);
        let b = self.barycentrics(i)?.perspective;
        let position = prim
            .vertices
            .iter()
            .zip(b)
            .map(|(&r, w)| self.vertices[r as usize].world.truncate() * w)
            .sum::<Vec3>();
        let light = self
            .lights
            .iter()
            .find_map(|l| crate::shade::light_vector(l, position))?;
        let view = (self.camera.eye - position).normalize_or_zero();
        Some(PixelVectors {
            position,
            normal,
            light,
            view,
            half: (light + view).normalize_or_zero(),
        })
    }

    /// Everything about window pixel `(x, y)` (y up): its buffers' values, the owning
    /// fragment's lighting terms and texture lookup, and every fragment that reached it (see
    /// [`Self::fragments_at`]); `None` outside the viewport.
    #[must_use]
    pub fn pixel_record(&self, x: u32, y: u32) -> Option<PixelRecord> {
        if x >= self.width() || y >= self.height() {
            return None;
        }
        let i = ((self.height() - 1 - y) * self.width() + x) as usize;
        let px = &self.pixels;
        let owned = px.primitive[i] != NONE;
        Some(PixelRecord {
            x,
            y,
            coverage: px.coverage[i],
            depth: px.depth[i],
            color: px.color[i],
            primitive: owned.then_some(px.primitive[i]),
            lighting: px.shading.as_ref().filter(|_| owned).map(|s| s.at(i)),
            texture: px
                .texturing
                .as_ref()
                .filter(|t| owned && t.footprint[i] != [f16::ZERO; 4])
                .map(|t| t.at(i)),
            vectors: self.pixel_vectors(x, y),
            fragments: self.fragments_at(x, y),
        })
    }

    /// Every fragment that reached window pixel `(x, y)` (y up), in drawing order, with the
    /// outcome of the depth test at each sample: the raster triangles are replayed against the
    /// pixel's depth values exactly as the rasterizer ran them.
    #[must_use]
    pub fn fragments_at(&self, x: u32, y: u32) -> Vec<FragmentRecord> {
        if x >= self.width() || y >= self.height() {
            return Vec::new();
        }
        let offsets = crate::raster::sample_offsets_fixed(self.settings.samples);
        let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
        let centre = Self::pixel_centre_fixed(x, y);
        let mut stored = vec![self.settings.depth_test.clear_value(); offsets.len()];
        let owner = self.pixels.primitive[((self.height() - 1 - y) * self.width() + x) as usize];
        let mut out = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            let [x0, y0, x1, y1] = tri.bbox;
            if x < x0 || x > x1 || y < y0 || y > y1 {
                continue;
            }
            let mut samples = vec![None; offsets.len()];
            let mut sample_depths = vec![None; offsets.len()];
            for (s, off) in offsets.iter().enumerate() {
                let p = corner + *off;
                if tri.covers(p) {
                    let z = tri.depth(tri.lambda(p));
                    let pass = self.settings.depth_test.passes(z, stored[s]);
                    if pass {
                        stored[s] = z;
                    }
                    samples[s] = Some(pass);
                    sample_depths[s] = Some(z);
                }
            }
            if samples.iter().all(Option::is_none) {
                continue;
            }
            let l = tri.lambda(centre);
            out.push(FragmentRecord {
                primitive: tri.primitive,
                triangle: t as u32,
                samples,
                sample_depths,
                depth: tri.depth(l),
                bary_affine: tri.original_bary(l, false).to_array(),
                bary_perspective: tri.original_bary(l, true).to_array(),
                visible: tri.primitive == owner,
            });
        }
        out
    }

    /// The intensity profile along the segment `from → to` (image pixel coordinates, y down):
    /// one sample per pixel step, each the pixel the point falls in (points off the image are
    /// skipped). This is what the Mach band comparison plots.
    #[must_use]
    pub fn profile(&self, from: [f32; 2], to: [f32; 2]) -> Vec<ProfileSample> {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let steps = dx.abs().max(dy.abs()).ceil().max(1.0) as u32;
        (0..=steps)
            .filter_map(|k| {
                let t = k as f32 / steps as f32;
                let (px, py) = (from[0] + dx * t, from[1] + dy * t);
                if !(px >= 0.0
                    && py >= 0.0
                    && px < self.width() as f32
                    && py < self.height() as f32)
                {
                    return None;
                }
                let (x, y) = (px as u32, py as u32);
                let rgb = self.pixels.color[(y * self.width() + x) as usize];
                let intensity = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
                Some(ProfileSample {
                    t,
                    x,
                    y,
                    rgb,
                    intensity,
                })
            })
            .collect()
    }

    /// The centre of window pixel `(x, y)` in fixed point.
    #[must_use]
    pub fn pixel_centre_fixed(x: u32, y: u32) -> I64Vec2 {
        I64Vec2::new(i64::from(x) * ONE + ONE / 2, i64::from(y) * ONE + ONE / 2)
    }
}
