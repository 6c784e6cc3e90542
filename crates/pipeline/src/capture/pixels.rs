//! The per-pixel buffers of a frame, top image row first: the ones always kept (coverage,
//! depth, owner, colour) and the lighting and texturing terms kept as half floats, with the
//! rows the resolve writes in parallel and the values of one pixel read back as 32-bit floats.

use std::ops::Range;

use half::f16;
use serde::Serialize;

/// Per-pixel buffers, top image row first (`index = row·width + column`).
///
/// Where `coverage` is 0 (the background) `primitive` and `owner` are [`NONE`](crate::raster::NONE), the lighting
/// buffers hold zeros and the texturing buffers no lookup ([`NO_LOOKUP`]), and the colour and
/// depth are the background's ([`Self::background`]). The resolve relies on it when it renders
/// into the storage of the frame before: a background pixel's primitive, owner and terms are
/// written only in the background spans where that frame covered a pixel, its colour and
/// depth also only where the background changed.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PixelBuffers {
    /// Number of the pixel's samples that a primitive covers (after the depth test).
    pub coverage: Vec<u8>,
    /// Window depth `z_w ∈ [0, 1]`, the mean over the pixel's samples (cleared ones count as the
    /// clear depth); with one sample, the depth at the pixel centre.
    pub depth: Vec<f32>,
    /// The primitive that owns most of the pixel's samples (ties: the earliest sample), or
    /// [`NONE`](crate::raster::NONE).
    pub primitive: Vec<u32>,
    /// The raster triangle of that primitive seen at the pixel (an index into
    /// [`FrameCapture::triangles`](super::FrameCapture::triangles)), or [`NONE`](crate::raster::NONE).
    /// The barycentric weights at the pixel centre are a function of it
    /// ([`FrameCapture::barycentrics`](super::FrameCapture::barycentrics)), so they are derived, not stored.
    pub owner: Vec<u32>,
    /// The resolved colour: each sample takes the colour of its triangle evaluated once at the
    /// pixel centre (multisampling shades once per pixel), uncovered samples the background;
    /// the pixel is their mean.
    pub color: Vec<[f32; 3]>,
    /// The lighting terms of the owning fragment at the pixel centre, when lighting is on.
    pub shading: Option<ShadingBuffers>,
    /// The texture lookup of the owning fragment, when an object is textured.
    pub texturing: Option<TextureBuffers>,
    /// The terms and lookup of the capture's pixel ([`crate::buffers::Capture::pixel`]) when
    /// their buffers are not kept.
    pub inspected: Option<InspectedPixel>,
    /// The colour and depth that every pixel of coverage 0 holds — the background of the frame
    /// resolved into these buffers — when known (not for storage just made or resized). The
    /// resolve of the next frame into this storage then writes neither where that frame had the
    /// background too and its background is the same.
    pub(crate) background: Option<([f32; 3], f32)>,
}

impl PixelBuffers {
    /// The per-pixel buffers for a frame of `n` pixels, in this spare's storage: the lighting
    /// buffers when lighting is on and kept, the texturing buffers when an object is textured
    /// and they are kept. The resolve overwrites every element.
    #[must_use]
    pub(crate) fn reused(self, n: usize, lighting: bool, texturing: bool) -> Self {
        fn sized<T: Clone>(mut v: Vec<T>, n: usize, fill: T) -> Vec<T> {
            v.resize(n, fill);
            v
        }
        // Pixels added by a resize have coverage 0 but not the background's colour.
        let background = self.background.filter(|_| self.color.len() == n);
        Self {
            background,
            coverage: sized(self.coverage, n, 0),
            depth: sized(self.depth, n, 0.0),
            primitive: sized(self.primitive, n, crate::raster::NONE),
            owner: sized(self.owner, n, crate::raster::NONE),
            color: sized(self.color, n, [0.0; 3]),
            shading: lighting.then(|| self.shading.unwrap_or_default().resized(n)),
            texturing: texturing.then(|| self.texturing.unwrap_or_default().resized(n)),
            inspected: None,
        }
    }
}

/// One pixel's lighting terms and texture lookup, kept without their buffers, at the precision
/// the buffers would have (half floats).
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedPixel {
    /// The pixel's index, `row·width + column`.
    pub index: usize,
    /// Its lighting terms, when lighting is on (zeros where unlit, as in the buffers).
    pub lighting: Option<PixelLighting>,
    /// Its texture lookup, when a texture was read there.
    pub texture: Option<PixelTexture>,
}

impl InspectedPixel {
    /// The record of pixel `index` with terms `terms` (`lit`: lighting is on) and lookup
    /// `texture`, stored and read back through one-pixel buffers so that it holds what the
    /// full buffers would.
    #[must_use]
    pub fn new(
        index: usize,
        lit: bool,
        terms: Option<&crate::lighting::ShadeTerms>,
        texture: Option<&PixelTexture>,
    ) -> Self {
        let lighting = lit.then(|| {
            let mut b = ShadingBuffers::default().resized(1);
            if let Some(t) = terms {
                b.rows(1)[0].store(0, t);
            }
            b.at(0)
        });
        let texture = texture.map(|t| {
            let mut b = TextureBuffers::default().resized(1);
            b.rows(1)[0].store(0, t);
            b.at(0)
        });
        Self {
            index,
            lighting,
            texture,
        }
    }
}

impl PixelBuffers {
    /// The lighting terms of the owning fragment at pixel `i`: from the lighting buffers, or
    /// from the inspected pixel's record; `None` when neither is kept or lighting is off.
    #[must_use]
    pub fn lighting_at(&self, i: usize) -> Option<PixelLighting> {
        match (&self.shading, &self.inspected) {
            (Some(s), _) => Some(s.at(i)),
            (None, Some(p)) if p.index == i => p.lighting.clone(),
            _ => None,
        }
    }

    /// The texture lookup of the owning fragment at pixel `i`: from the texturing buffers, or
    /// from the inspected pixel's record; `None` when neither is kept or no texture was read.
    #[must_use]
    pub fn texture_at(&self, i: usize) -> Option<PixelTexture> {
        match (&self.texturing, &self.inspected) {
            (Some(t), _) => Some(t.at(i)).filter(|t| t.level >= 0.0),
            (None, Some(p)) if p.index == i => p.texture.clone(),
            _ => None,
        }
    }
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
    /// The level read: `k + blend` (trilinear blends levels k and k+1); −1 where no texture
    /// was read.
    pub level: Vec<f16>,
    /// The filtered texel colour.
    pub texel: Vec<[f16; 3]>,
    /// The footprint's axes in texels, `(∂s/∂x, ∂t/∂x, ∂s/∂y, ∂t/∂y)` with `(s, t) = (u·w, v·h)`.
    pub footprint: Vec<[f16; 4]>,
}

impl TextureBuffers {
    /// These buffers' storage holding `n` pixels (the new ones with no lookup, [`NO_LOOKUP`];
    /// from `default()`: new buffers).
    #[must_use]
    pub fn resized(mut self, n: usize) -> Self {
        self.uv.resize(n, [0.0; 2]);
        self.lod.resize(n, f16::ZERO);
        self.level.resize(n, f16::from_f32(NO_LOOKUP[1]));
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

/// Per-pixel lighting terms of the owning fragment (see `lighting::shade`), top image row first, as half
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
/// What the texturing buffers hold where no texture was read: zeros, the level −1 (a level
/// read is never negative).
pub const NO_LOOKUP: [f32; TEXTURE_HALVES] = [0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// Half-float values a pixel's lighting has: ambient, diffuse, specular, normal, reflected 3
/// each, n·l, n·h.
pub const LIGHTING_HALVES: usize = 17;

impl TextureRow<'_> {
    /// A lookup as the row stores it: its uv (kept at 32 bits) and its [`TEXTURE_HALVES`]
    /// values in storage order.
    #[must_use]
    pub(crate) fn flatten(t: &PixelTexture) -> ([f32; 2], [f32; TEXTURE_HALVES]) {
        let ([a, b, c], [d, e, f, g]) = (t.texel, t.footprint);
        (t.uv, [t.lod, t.level, a, b, c, d, e, f, g])
    }

    /// Stores pixel `x`'s lookup: its uv at 32 bits, its [`TEXTURE_HALVES`] values
    /// ([`Self::flatten`]) converted to half floats together (in vector instructions where the
    /// processor converts in hardware).
    #[inline]
    pub fn store(&mut self, x: usize, t: &PixelTexture) {
        let (uv, floats) = Self::flatten(t);
        let h = to_halves(&floats);
        self.uv[x] = uv;
        self.lod[x] = h[0];
        self.level[x] = h[1];
        self.texel[x] = [h[2], h[3], h[4]];
        self.footprint[x] = [h[5], h[6], h[7], h[8]];
    }

    /// Pixels `span` read no texture (an untextured surface, the background): [`NO_LOOKUP`],
    /// zeros with the level −1, so that they are told apart from level 0.
    pub fn none(&mut self, span: Range<usize>) {
        self.uv[span.clone()].fill([0.0; 2]);
        self.lod[span.clone()].fill(f16::ZERO);
        self.level[span.clone()].fill(f16::from_f32(NO_LOOKUP[1]));
        self.texel[span.clone()].fill([f16::ZERO; 3]);
        self.footprint[span].fill([f16::ZERO; 4]);
    }
}

/// `floats` as half floats, converted together (the `half` crate converts in vector
/// instructions where the processor has them, F16C on x86-64; rounding to nearest, ties to
/// even, either way).
#[inline]
fn to_halves<const N: usize>(floats: &[f32; N]) -> [f16; N] {
    use half::slice::HalfFloatSliceExt;
    let mut halves = [f16::ZERO; N];
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
    /// Lighting terms as the row stores them, in storage order.
    #[must_use]
    pub(crate) fn flatten(t: &crate::lighting::ShadeTerms) -> [f32; LIGHTING_HALVES] {
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

    /// Stores pixel `x`'s lighting terms, their [`LIGHTING_HALVES`] values ([`Self::flatten`])
    /// converted to half floats together.
    #[inline]
    pub fn store(&mut self, x: usize, t: &crate::lighting::ShadeTerms) {
        let h = to_halves(&Self::flatten(t));
        self.ambient[x] = [h[0], h[1], h[2]];
        self.diffuse[x] = [h[3], h[4], h[5]];
        self.specular[x] = [h[6], h[7], h[8]];
        self.normal[x] = [h[9], h[10], h[11]];
        self.reflected[x] = [h[12], h[13], h[14]];
        self.n_dot_l[x] = h[15];
        self.n_dot_h[x] = h[16];
    }

    /// Pixels `span` are not lit (unlit there, the background): zeros.
    pub fn unlit(&mut self, span: Range<usize>) {
        for v in [
            &mut self.ambient,
            &mut self.diffuse,
            &mut self.specular,
            &mut self.normal,
            &mut self.reflected,
        ] {
            v[span.clone()].fill([f16::ZERO; 3]);
        }
        self.n_dot_l[span.clone()].fill(f16::ZERO);
        self.n_dot_h[span].fill(f16::ZERO);
    }
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
