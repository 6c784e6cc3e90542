//! Textures and their samplers: nearest and bilinear filtering, the mipmap pyramid, level of
//! detail from screen-space derivatives, nearest-level and trilinear minification, anisotropic
//! filtering along the footprint's major axis.
//!
//! Conventions (OpenGL's): texture coordinates `(u, v)` run from `(0, 0)` at the bottom-left of
//! the image to `(1, 1)` at its top-right; texel `(i, j)` (column `i`, row `j` counted from the
//! bottom) covers `[i, i+1] × [j, j+1]` in texel units, its centre at `(i + ½, j + ½)`, so
//! `(u, v)` is the texel-space point `(u·w, v·h)`.
//!
//! - Nearest: the texel containing the point, `(⌊u·w⌋, ⌊v·h⌋)`.
//! - Bilinear: with `x = u·w − ½`, `y = v·h − ½`, the four texels around `(x, y)` weighted by
//!   `lerp(lerp(t00, t10, s), lerp(t01, t11, s), t)`, `s = x − ⌊x⌋`, `t = y − ⌊y⌋`.
//! - Level of detail (GAMES101, the GL spec): `L = max(|∂(u·w, v·h)/∂x|, |∂(u·w, v·h)/∂y|)`, the
//!   footprint of one pixel in texels, and `λ = log₂ L + bias`. Level `⌊λ + ½⌋` (nearest level)
//!   or the blend of levels `⌊λ⌋` and `⌊λ⌋ + 1` (trilinear); `λ ≤ 0` is magnification.
//! - Mip level `k + 1` is the 2×2 box filter of level `k` (odd sizes: the last row or column is
//!   averaged into its neighbour's box); levels go down to 1×1.
//!
//! This module holds the texture and its pyramid; the textures generated in code are in
//! [`generated`], the samplers in [`sampler`], what textures add to a surface (bump, normal, displacement and
//! environment mapping) in [`detail`].

mod bytes;
mod detail;
mod generated;
mod lanes;
pub mod ripmap_sat_ewa;
mod sampler;

pub use detail::*;
pub use generated::level_color;
pub use sampler::*;

use std::path::Path;

use glam::{Vec2, Vec3};
use image::{Rgba, RgbaImage};
use serde::Serialize;

/// What happens outside `[0, 1]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Wrap {
    /// The texture tiles: `u` is taken modulo 1.
    #[default]
    Repeat,
    /// The edge texels extend outwards.
    Clamp,
}

impl Wrap {
    /// Texel column or row `i` of a level `n` texels wide, wrapped: `i mod n` (repeat) or
    /// `clamp(i, 0, n − 1)` (clamp). Inside the level it is `i` itself, with no division.
    #[must_use]
    #[inline]
    pub fn index(self, i: i64, n: u32) -> usize {
        let n = i64::from(n);
        if (0..n).contains(&i) {
            return i as usize;
        }
        match self {
            Self::Repeat => i.rem_euclid(n) as usize,
            Self::Clamp => i.clamp(0, n - 1) as usize,
        }
    }

    /// Texel columns (or rows) `i` and `i + 1`, wrapped: [`Self::index`] of both; repeating,
    /// the second follows from the first, `(i + 1) mod n = (i mod n + 1) mod n`.
    #[must_use]
    #[inline]
    pub fn pair(self, i: i64, n: u32) -> (usize, usize) {
        let first = self.index(i, n);
        let second = match self {
            Self::Repeat if first + 1 == n as usize => 0,
            Self::Repeat => first + 1,
            // Saturating: a place past i64's end (a coordinate of +∞) stays at the last texel.
            Self::Clamp => self.index(i.saturating_add(1), n),
        };
        (first, second)
    }
}

/// One level of the pyramid: RGB texels in `[0, 1]`, bottom row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// Texel `(i, j)` (row `j` from the bottom) at `j·width + i`.
    pub texels: Vec<Vec3>,
}

impl Level {
    /// The level as an image, top row first: image row `r` is texel row `height − 1 − r`
    /// (texels are stored bottom row first, v up), each channel rounded to 8 bits.
    #[must_use]
    pub fn image(&self) -> RgbaImage {
        let grid = crate::grid::Grid::new(self.width, self.height);
        RgbaImage::from_fn(self.width, self.height, |x, r| {
            let c = self.texels[(grid.row(r) * self.width + x) as usize];
            let b = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
            Rgba([b(c.x), b(c.y), b(c.z), 255])
        })
    }

    /// `(width, height)` as a vector, to turn uv into texels.
    #[must_use]
    pub fn size(&self) -> Vec2 {
        Vec2::new(self.width as f32, self.height as f32)
    }

    /// Texel `(i, j)` with wrapping.
    #[must_use]
    pub fn texel(&self, i: i64, j: i64, wrap: Wrap) -> Vec3 {
        self.at(wrap.index(i, self.width), wrap.index(j, self.height))
    }

    /// Texel `(i, j)` of the level (column, row from the bottom): [`Self::texels`]`[j·w + i]`.
    #[inline]
    fn at(&self, i: usize, j: usize) -> Vec3 {
        self.texels[j * self.width as usize + i]
    }

    /// Nearest filtering at `(u, v)`.
    #[must_use]
    pub fn nearest(&self, uv: Vec2, wrap: Wrap) -> Vec3 {
        let (i, j) = self.nearest_place(uv, wrap);
        self.at(i, j)
    }

    /// The texel nearest filtering reads at `(u, v)`: `(⌊u·w⌋, ⌊v·h⌋)`, wrapped.
    fn nearest_place(&self, uv: Vec2, wrap: Wrap) -> (usize, usize) {
        let x = (f64::from(uv.x) * f64::from(self.width)).floor() as i64;
        let y = (f64::from(uv.y) * f64::from(self.height)).floor() as i64;
        (wrap.index(x, self.width), wrap.index(y, self.height))
    }

    /// Bilinear filtering at `(u, v)`.
    #[must_use]
    pub fn bilinear(&self, uv: Vec2, wrap: Wrap) -> Vec3 {
        self.bilinear_of(uv, wrap, |i, j| self.at(i, j))
    }

    /// Bilinear filtering at `(u, v)` of the texels `at(i, j)` gives for column `i` and row
    /// `j` (the texels themselves, or their 8-bit copy).
    #[inline]
    fn bilinear_of(&self, uv: Vec2, wrap: Wrap, at: impl Fn(usize, usize) -> Vec3) -> Vec3 {
        let b = self.bilinear_taps(uv, wrap);
        let ([i0, i1], [j0, j1]) = (b.columns, b.rows);
        let bottom = at(i0, j0).lerp(at(i1, j0), b.s);
        let top = at(i0, j1).lerp(at(i1, j1), b.s);
        bottom.lerp(top, b.t)
    }

    /// The four texels bilinear filtering reads at `(u, v)` and their weights: with
    /// `x = u·w − ½`, `y = v·h − ½`, columns `⌊x⌋, ⌊x⌋ + 1` and rows `⌊y⌋, ⌊y⌋ + 1` (wrapped),
    /// `s = x − ⌊x⌋`, `t = y − ⌊y⌋`.
    #[must_use]
    #[inline]
    pub fn bilinear_taps(&self, uv: Vec2, wrap: Wrap) -> BilinearTaps {
        // In `f32`, as a GPU's texture unit works (llvmpipe weighs in 8 bits): `u·w` is exact
        // for a power-of-two width, and elsewhere within half an ulp, 6·10⁻⁵ of a texel at
        // 1024 texels, far below an 8-bit colour's step.
        let x = uv.x * self.width as f32 - 0.5;
        let y = uv.y * self.height as f32 - 0.5;
        let ((i, s), (j, t)) = (floor_and_fraction(x), floor_and_fraction(y));
        // The 2×2 texels' columns and rows, each wrapped once (as `texel` would wrap them).
        let (i0, i1) = wrap.pair(i, self.width);
        let (j0, j1) = wrap.pair(j, self.height);
        BilinearTaps {
            columns: [i0, i1],
            rows: [j0, j1],
            s,
            t,
        }
    }

    /// The 2×2 box filter of this level (the next mip level).
    #[must_use]
    pub fn box_filtered(&self) -> Level {
        self.halved(true, true)
    }

    /// This level halved along x, y or both by a box filter (a ripmap's neighbours halve one
    /// axis only); an axis of one texel stays one texel.
    #[must_use]
    pub fn halved(&self, x: bool, y: bool) -> Level {
        let fx = if x && self.width > 1 { 2 } else { 1 };
        let fy = if y && self.height > 1 { 2 } else { 1 };
        let (w, h) = (self.width / fx, self.height / fy);
        let mut texels = Vec::with_capacity((w * h) as usize);
        for j in 0..h {
            for i in 0..w {
                // The source texels of this box; an odd last row/column joins the last box.
                let xs = fx * i..if i + 1 == w { self.width } else { fx * i + fx };
                let ys = fy * j..if j + 1 == h { self.height } else { fy * j + fy };
                let mut sum = Vec3::ZERO;
                let mut n = 0.0;
                for y in ys {
                    for x in xs.clone() {
                        sum += self.texels[(y * self.width + x) as usize];
                        n += 1.0;
                    }
                }
                texels.push(sum / n);
            }
        }
        Level {
            width: w,
            height: h,
            texels,
        }
    }
}

/// `(⌊x⌋, x − ⌊x⌋)`, without a call to the C library's `floorf` (which x86-64's baseline,
/// without SSE4.1's rounding instruction, makes of `f32::floor`): truncate, then step down where
/// truncation rounded up (x < 0). The fraction is exact (−0 for x = −0). An `x` of 2²³ or more
/// in magnitude is a whole number already (fraction 0); a NaN gives `(0, NaN)`.
#[inline]
fn floor_and_fraction(x: f32) -> (i64, f32) {
    if !(x.abs() < 8_388_608.0) {
        return (x as i64, if x.is_nan() { x } else { 0.0 });
    }
    let mut i = x as i64;
    if i as f32 > x {
        i -= 1;
    }
    (i, x - i as f32)
}

/// The texels a bilinear lookup reads: columns `i0, i1`, rows `j0, j1` (from the bottom), and
/// the weights `s` (towards `i1`) and `t` (towards `j1`): the result is
/// `lerp(lerp(T(i0,j0), T(i1,j0), s), lerp(T(i0,j1), T(i1,j1), s), t)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BilinearTaps {
    /// `[i0, i1]`.
    pub columns: [usize; 2],
    /// `[j0, j1]`.
    pub rows: [usize; 2],
    /// The weight of column `i1`.
    pub s: f32,
    /// The weight of row `j1`.
    pub t: f32,
}

/// A texture with its mipmap pyramid.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Where it came from.
    pub name: String,
    /// Level 0 (full size) first, down to 1×1.
    pub levels: Vec<Level>,
    /// The ripmap and the summed-area table, built on first use (see [`ripmap_sat_ewa`]).
    prefiltered: std::sync::OnceLock<Box<ripmap_sat_ewa::Prefiltered>>,
    /// Level 0's texels in 8 bits, tile by tile, when they are exact (see [`bytes`]); the
    /// lookups of level 0 read them.
    level0_bytes: Option<bytes::TiledBytes>,
}

/// Why a texture could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum TextureError {
    /// The image could not be read or decoded.
    #[error("{path}: cannot load the texture: {reason}")]
    Image {
        /// The file.
        path: String,
        /// What the decoder said.
        reason: String,
    },
    /// The image has no pixels.
    #[error("{path}: the image is empty ({width}×{height})")]
    Empty {
        /// The file.
        path: String,
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
}

impl Texture {
    /// A texture from its level 0; the pyramid is built by repeated box filtering. Level 0
    /// must not change afterwards: its 8-bit copy, made here, would no longer match it.
    #[must_use]
    pub fn from_level(name: &str, base: Level) -> Self {
        let level0_bytes = bytes::TiledBytes::of(&base);
        let mut levels = vec![base];
        while let Some(last) = levels.last() {
            if last.width == 1 && last.height == 1 {
                break;
            }
            let next = last.box_filtered();
            levels.push(next);
        }
        Self {
            name: name.to_owned(),
            levels,
            prefiltered: std::sync::OnceLock::new(),
            level0_bytes,
        }
    }

    /// Whether level 0 is also kept in 8 bits (see [`bytes`]).
    #[must_use]
    pub fn has_8_bit_level0(&self) -> bool {
        self.level0_bytes.is_some()
    }

    /// Level `k` read at `(u, v)` by `filter`: level 0 from its 8-bit copy when there is one
    /// (the same values).
    #[must_use]
    #[inline]
    pub fn read_level(&self, k: usize, uv: Vec2, filter: Filter, wrap: Wrap) -> Vec3 {
        let level = &self.levels[k];
        match filter {
            Filter::Bilinear => level.bilinear_of(uv, wrap, |i, j| self.texel_of_level(k, i, j)),
            Filter::Nearest => {
                let (i, j) = level.nearest_place(uv, wrap);
                self.texel_of_level(k, i, j)
            }
        }
    }

    /// Texel `(i, j)` of level `k` (within it): from level 0's 8-bit copy where it has one
    /// (the same values), from the level's own texels otherwise.
    #[inline]
    fn texel_of_level(&self, k: usize, i: usize, j: usize) -> Vec3 {
        match &self.level0_bytes {
            Some(bytes) if k == 0 => bytes.texel(i, j),
            _ => self.levels[k].at(i, j),
        }
    }

    /// A texture from an image (top row first, as images are stored), 8 or 16 bits, grey or
    /// colour; alpha is ignored.
    ///
    /// # Errors
    /// When the image is empty.
    pub fn from_image(name: &str, img: &image::DynamicImage) -> Result<Self, TextureError> {
        let rgb = img.to_rgb32f();
        let (w, h) = rgb.dimensions();
        if w == 0 || h == 0 {
            return Err(TextureError::Empty {
                path: name.to_owned(),
                width: w,
                height: h,
            });
        }
        // Texel rows count up (v up), the image's rows down.
        let grid = crate::grid::Grid::new(w, h);
        let mut texels = Vec::with_capacity((w * h) as usize);
        for j in 0..h {
            for i in 0..w {
                let p = rgb.get_pixel(i, grid.row(j)).0;
                texels.push(Vec3::from(p));
            }
        }
        Ok(Self::from_level(
            name,
            Level {
                width: w,
                height: h,
                texels,
            },
        ))
    }

    /// Loads a PNG or JPEG file.
    ///
    /// # Errors
    /// A [`TextureError`] naming the file.
    pub fn load(path: &Path) -> Result<Self, TextureError> {
        let shown = path.display().to_string();
        let img = image::open(path).map_err(|e| TextureError::Image {
            path: shown.clone(),
            reason: e.to_string(),
        })?;
        Self::from_image(&shown, &img)
    }

    /// Decodes a PNG or JPEG file's bytes (a file a page was given); `shown` names it.
    ///
    /// # Errors
    /// A [`TextureError`] naming `shown`.
    pub fn decode(shown: &str, bytes: &[u8]) -> Result<Self, TextureError> {
        let img = image::load_from_memory(bytes).map_err(|e| TextureError::Image {
            path: shown.to_owned(),
            reason: e.to_string(),
        })?;
        Self::from_image(shown, &img)
    }

    /// Level `k` as an image (top row first), for display and export.
    #[must_use]
    pub fn level_image(&self, k: usize) -> RgbaImage {
        self.levels
            .get(k.min(self.levels.len().saturating_sub(1)))
            .map_or_else(|| RgbaImage::new(1, 1), Level::image)
    }
}

#[cfg(test)]
mod tests {
    use super::{Wrap, floor_and_fraction};

    /// The pair of columns a bilinear lookup reads, wrapped: inside the level `(i, i + 1)`; at
    /// the last column, repeating goes round to 0 and clamping stays; far outside, at the ends
    /// of i64 (where `floor_and_fraction` puts ±∞), clamping gives the first or last column
    /// twice (by hand: a level 5 wide has columns 0 to 4) and does not overflow.
    #[test]
    fn a_pair_of_columns_wraps_and_clamps_at_every_place() {
        assert_eq!(Wrap::Repeat.pair(2, 5), (2, 3));
        assert_eq!(Wrap::Clamp.pair(2, 5), (2, 3));
        assert_eq!(Wrap::Repeat.pair(4, 5), (4, 0));
        assert_eq!(Wrap::Clamp.pair(4, 5), (4, 4));
        assert_eq!(Wrap::Repeat.pair(-1, 5), (4, 0));
        assert_eq!(Wrap::Clamp.pair(-1, 5), (0, 0));
        assert_eq!(Wrap::Clamp.pair(i64::MAX, 5), (4, 4));
        assert_eq!(Wrap::Clamp.pair(i64::MIN, 5), (0, 0));
        // i64::MAX = 5·1844674407370955161 + 2, so column 2, then 3.
        assert_eq!(Wrap::Repeat.pair(i64::MAX, 5), (2, 3));
    }

    /// The floor and fraction equal `f32::floor`'s and `x − ⌊x⌋` for whole numbers, halves,
    /// values a hair either side of a whole number, negative values, values past 2²³ and the
    /// non-finite ones, and for a sweep of random values over the range texture lookups meet.
    #[test]
    fn floor_and_fraction_agrees_with_f32_floor() {
        let mut xs = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            1023.5,
            -1024.0,
            8_388_607.5,
            8_388_608.0,
            -8_388_609.0,
            3.0e9,
            -3.0e9,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        for k in [-3.0f32, -1.0, 0.0, 1.0, 2.0, 1024.0] {
            xs.extend([k.next_down(), k.next_up()]);
        }
        let mut rng = fastrand::Rng::with_seed(7);
        xs.extend((0..100_000).map(|_| (rng.f32() - 0.5) * 4096.0));
        for x in xs {
            let (i, f) = floor_and_fraction(x);
            let floor = x.floor();
            if floor.abs() < 9.0e18 {
                assert_eq!(i, floor as i64, "⌊{x}⌋");
            }
            let fraction = if x.is_finite() { x - floor } else { 0.0 };
            // Equal values (−0 − 0 is −0 where x − ⌊x⌋ is +0: the same weight).
            assert_eq!(f, fraction, "fraction of {x}");
        }
        let (i, f) = floor_and_fraction(f32::NAN);
        assert_eq!(i, 0);
        assert!(f.is_nan());
    }
}
