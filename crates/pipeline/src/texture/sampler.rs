//! Samplers: nearest and bilinear filtering within a level, the level of detail
//! `λ = log₂ L + bias` from the screen derivatives of uv, nearest-level and trilinear
//! minification, and anisotropic filtering along the footprint's major axis.

use glam::{IVec2, Vec2, Vec3};
use serde::Serialize;

use super::{Texture, Wrap};

/// Filtering within one level.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    /// The nearest texel.
    Nearest,
    /// The four nearest texels, weighted.
    #[default]
    Bilinear,
}

/// How minification uses the mipmap pyramid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mipmap {
    /// Level 0 always (aliases when minified).
    None,
    /// The nearest level to `λ`.
    Nearest,
    /// Trilinear: the two levels around `λ`, blended by its fraction.
    #[default]
    Linear,
    /// A ripmap level chosen for each axis of the footprint's bounding box (see
    /// [`super::ripmap_sat_ewa`]).
    Ripmap,
    /// The exact mean over the footprint's bounding box, from a summed-area table.
    SummedArea,
    /// Elliptical weighted average over the footprint's ellipse.
    Ewa,
}

impl Mipmap {
    /// Whether the lookup is one of GAMES101's range queries beyond the mipmap pyramid.
    #[must_use]
    pub fn beyond_the_pyramid(self) -> bool {
        matches!(self, Self::Ripmap | Self::SummedArea | Self::Ewa)
    }
}

/// A sampler: how a texture is read.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sampler {
    /// Outside `[0, 1]`.
    pub wrap: Wrap,
    /// Within a level.
    pub filter: Filter,
    /// Across levels.
    pub mipmap: Mipmap,
    /// The most samples along the footprint's major axis (1: isotropic).
    pub anisotropy: u32,
    /// Added to `λ`.
    pub lod_bias: f32,
}

impl Sampler {
    /// Whether the colour a lookup returns depends on the screen derivatives of uv: to choose
    /// a mip level, or to place anisotropic taps. Without either, [`Texture::sample`] reads
    /// level 0 once whatever the footprint is.
    #[must_use]
    pub fn uses_footprint(&self) -> bool {
        self.mipmap != Mipmap::None || self.anisotropy > 1
    }
}

impl Default for Sampler {
    fn default() -> Self {
        Self {
            wrap: Wrap::Repeat,
            filter: Filter::Bilinear,
            mipmap: Mipmap::Linear,
            anisotropy: 1,
            lod_bias: 0.0,
        }
    }
}

/// What one texture lookup did, for the capture.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Lookup {
    /// The colour read.
    pub color: Vec3,
    /// `λ` (with the bias), before clamping to the pyramid.
    pub lod: f32,
    /// The finer level read.
    pub level: u32,
    /// The weight of the next level (trilinear), 0 otherwise.
    pub level_blend: f32,
    /// Samples taken along the major axis (anisotropic filtering).
    pub taps: u32,
    /// The pixel's footprint in texels: `(∂(u·w, v·h)/∂x, ∂(u·w, v·h)/∂y)`, the two axes of the
    /// parallelogram one pixel covers in the texture (level 0).
    pub footprint: [Vec2; 2],
}

impl Lookup {
    /// The record of a lookup that read `color` from level 0 with no footprint
    /// ([`Texture::sample_level0`]): λ left −∞, one tap.
    #[must_use]
    pub(crate) fn of_level0(color: Vec3) -> Self {
        Self {
            color,
            lod: f32::NEG_INFINITY,
            taps: 1,
            ..Self::default()
        }
    }
}

impl Texture {
    /// The footprint of a pixel in texels from the screen derivatives of `(u, v)`:
    /// `(|∂/∂x|, |∂/∂y|)` of `(u·w, v·h)`, and the axis (in uv) of the longer one.
    #[must_use]
    pub fn footprint(&self, duv_dx: Vec2, duv_dy: Vec2) -> (f32, f32, Vec2) {
        let size = self.levels[0].size();
        let (lx, ly) = ((duv_dx * size).length(), (duv_dy * size).length());
        if lx >= ly {
            (lx, ly, duv_dx)
        } else {
            (ly, lx, duv_dy)
        }
    }

    /// `λ = log₂ max(|∂(uw, vh)/∂x|, |∂(uw, vh)/∂y|)`, without bias.
    #[must_use]
    pub fn lod(&self, duv_dx: Vec2, duv_dy: Vec2) -> f32 {
        let (major, _, _) = self.footprint(duv_dx, duv_dy);
        major.max(1e-12).log2()
    }

    /// Samples at `uv` when the sampler needs no footprint ([`Sampler::uses_footprint`] is
    /// false: one level, one tap): level 0 read by the filter, the colour [`Self::sample`]
    /// gives, without the derivatives, λ (left −∞) or the footprint it would record.
    #[must_use]
    pub fn sample_level0(&self, uv: Vec2, s: &Sampler) -> Lookup {
        debug_assert!(!s.uses_footprint());
        Lookup::of_level0(self.sample_lod(uv, f32::NEG_INFINITY, s, IVec2::ZERO).0)
    }

    /// Samples at `uv` with the given screen derivatives of `uv`.
    #[must_use]
    pub fn sample(&self, uv: Vec2, duv_dx: Vec2, duv_dy: Vec2, s: &Sampler) -> Lookup {
        self.sample_shifted(uv, duv_dx, duv_dy, s, IVec2::ZERO)
    }

    /// [`Self::sample`] with GLSL's texel offset (`textureOffset`, `textureGradOffset`): each
    /// level `k` read is read `offset` of its own texels away, `u = s·w_k + δu`,
    /// `v = t·h_k + δv` (GLSL 3.30 §8.9, OpenGL 3.3 §3.8.11). A range query beyond the pyramid
    /// (ripmap, summed-area table, EWA: no GLSL sampler has them) takes no offset.
    #[must_use]
    pub fn sample_shifted(
        &self,
        uv: Vec2,
        duv_dx: Vec2,
        duv_dy: Vec2,
        s: &Sampler,
        offset: IVec2,
    ) -> Lookup {
        if s.mipmap.beyond_the_pyramid() {
            return self.sample_beyond(uv, duv_dx, duv_dy, s);
        }
        let (mut out, axis) = self.footprint_record(duv_dx, duv_dy, s);
        let (lod, taps) = (out.lod, out.taps);
        let mut sum = Vec3::ZERO;
        for k in 0..taps {
            let tap = if taps > 1 {
                (k as f32 + 0.5) / taps as f32 - 0.5
            } else {
                0.0
            };
            let (c, level, blend) = self.sample_lod(uv + axis * tap, lod, s, offset);
            sum += c;
            (out.level, out.level_blend) = (level, blend);
        }
        // One tap is its own mean (`c / 1 = c`): no division waiting on the texels.
        out.color = if taps == 1 { sum } else { sum / taps as f32 };
        out
    }

    /// What a lookup within the pyramid records of its footprint `(duv_dx, duv_dy)`, before
    /// it reads a texel: the taps along the major axis (`⌈major/minor⌉`, at most the sampler's
    /// anisotropy), `λ = log₂(major/taps) + bias`, the footprint in texels; and the major
    /// axis in uv, along which the taps lie.
    #[must_use]
    pub(crate) fn footprint_record(
        &self,
        duv_dx: Vec2,
        duv_dy: Vec2,
        s: &Sampler,
    ) -> (Lookup, Vec2) {
        let (major, minor, axis) = self.footprint(duv_dx, duv_dy);
        // Anisotropic: N taps along the major axis, each with the footprint major/N.
        let taps = if s.anisotropy > 1 && minor > 0.0 {
            ((major / minor).ceil() as u32).clamp(1, s.anisotropy)
        } else {
            1
        };
        let lod = (major / taps as f32).max(1e-12).log2() + s.lod_bias;
        let size = self.levels[0].size();
        let record = Lookup {
            lod,
            taps,
            footprint: [duv_dx * size, duv_dy * size],
            ..Lookup::default()
        };
        (record, axis)
    }

    /// A ripmap, summed-area or EWA lookup (the filter within a level and the anisotropic taps
    /// do not apply); `level` is the level read (a ripmap's finer axis), `taps` the texels read
    /// (EWA) or 1.
    fn sample_beyond(&self, uv: Vec2, duv_dx: Vec2, duv_dy: Vec2, s: &Sampler) -> Lookup {
        let size = self.levels[0].size();
        let mut out = Lookup {
            lod: self.lod(duv_dx, duv_dy) + s.lod_bias,
            taps: 1,
            footprint: [duv_dx * size, duv_dy * size],
            ..Lookup::default()
        };
        match s.mipmap {
            Mipmap::Ripmap => {
                let (color, [i, j]) = self.sample_ripmap(uv, duv_dx, duv_dy, s.wrap);
                (out.color, out.level) = (color, i.min(j));
            }
            Mipmap::SummedArea => out.color = self.sample_summed_area(uv, duv_dx, duv_dy, s.wrap),
            _ => {
                let (color, level, read) = self.sample_ewa(uv, duv_dx, duv_dy, s.wrap);
                (out.color, out.level, out.taps) = (color, level, read.max(1));
            }
        }
        out
    }

    /// One isotropic lookup at level of detail `lod`, each level read `offset` of its own
    /// texels away (see [`Self::sample_shifted`]): returns the colour, the finer level read
    /// and the blend weight of the next one.
    pub(crate) fn sample_lod(
        &self,
        uv: Vec2,
        lod: f32,
        s: &Sampler,
        offset: IVec2,
    ) -> (Vec3, u32, f32) {
        let read = |k: usize| {
            let at = if offset == IVec2::ZERO {
                uv
            } else {
                uv + offset.as_vec2() / self.levels[k].size()
            };
            self.read_level(k, at, s.filter, s.wrap)
        };
        let (k, f) = self.levels_at(lod, s);
        let color = if f > 0.0 {
            read(k).lerp(read(k + 1), f)
        } else {
            read(k)
        };
        (color, k as u32, f)
    }

    /// The levels an isotropic lookup at level of detail `lod` reads: level `k`, and when
    /// `f > 0` level `k + 1` too, blended `lerp(T_k, T_{k+1}, f)`. Magnification (`λ ≤ 0`)
    /// and no mipmap: level 0; nearest level: `⌊λ + ½⌋`; trilinear: `k = ⌊λ⌋`, `f = λ − k`
    /// (λ clamped to the pyramid).
    #[must_use]
    pub(crate) fn levels_at(&self, lod: f32, s: &Sampler) -> (usize, f32) {
        let max = (self.levels.len() - 1) as f32;
        match s.mipmap {
            _ if lod <= 0.0 => (0, 0.0),
            Mipmap::None => (0, 0.0),
            Mipmap::Nearest => ((lod + 0.5).floor().clamp(0.0, max) as usize, 0.0),
            Mipmap::Linear | Mipmap::Ripmap | Mipmap::SummedArea | Mipmap::Ewa => {
                let l = lod.clamp(0.0, max);
                let k = l.floor() as usize;
                let f = l - k as f32;
                if k + 1 < self.levels.len() && f > 0.0 {
                    (k, f)
                } else {
                    (k, 0.0)
                }
            }
        }
    }
}
