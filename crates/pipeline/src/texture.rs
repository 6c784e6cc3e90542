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
            Self::Clamp => self.index(i + 1, n),
        };
        (first, second)
    }
}

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
    /// `(width, height)` as a vector, to turn uv into texels.
    #[must_use]
    pub fn size(&self) -> Vec2 {
        Vec2::new(self.width as f32, self.height as f32)
    }

    /// Texel `(i, j)` with wrapping.
    #[must_use]
    pub fn texel(&self, i: i64, j: i64, wrap: Wrap) -> Vec3 {
        let (i, j) = (wrap.index(i, self.width), wrap.index(j, self.height));
        self.texels[j * self.width as usize + i]
    }

    /// Nearest filtering at `(u, v)`.
    #[must_use]
    pub fn nearest(&self, uv: Vec2, wrap: Wrap) -> Vec3 {
        let x = (f64::from(uv.x) * f64::from(self.width)).floor() as i64;
        let y = (f64::from(uv.y) * f64::from(self.height)).floor() as i64;
        self.texel(x, y, wrap)
    }

    /// Bilinear filtering at `(u, v)`.
    #[must_use]
    pub fn bilinear(&self, uv: Vec2, wrap: Wrap) -> Vec3 {
        let x = f64::from(uv.x) * f64::from(self.width) - 0.5;
        let y = f64::from(uv.y) * f64::from(self.height) - 0.5;
        let (i, j) = (x.floor(), y.floor());
        let (s, t) = ((x - i) as f32, (y - j) as f32);
        let (i, j) = (i as i64, j as i64);
        // The 2×2 texels' columns and rows, each wrapped once (as `texel` would wrap them).
        let (i0, i1) = wrap.pair(i, self.width);
        let (j0, j1) = wrap.pair(j, self.height);
        let w = self.width as usize;
        let at = |i: usize, j: usize| self.texels[j * w + i];
        let bottom = at(i0, j0).lerp(at(i1, j0), s);
        let top = at(i0, j1).lerp(at(i1, j1), s);
        bottom.lerp(top, t)
    }

    /// The 2×2 box filter of this level (the next mip level).
    #[must_use]
    pub fn box_filtered(&self) -> Level {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
        let mut texels = Vec::with_capacity((w * h) as usize);
        for j in 0..h {
            for i in 0..w {
                // The source texels of this box; an odd last row/column joins the last box.
                let xs = 2 * i..if i + 1 == w { self.width } else { 2 * i + 2 };
                let ys = 2 * j..if j + 1 == h { self.height } else { 2 * j + 2 };
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

/// A texture with its mipmap pyramid.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Where it came from.
    pub name: String,
    /// Level 0 (full size) first, down to 1×1.
    pub levels: Vec<Level>,
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

impl Texture {
    /// A texture from its level 0; the pyramid is built by repeated box filtering.
    #[must_use]
    pub fn from_level(name: &str, base: Level) -> Self {
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
        let mut texels = Vec::with_capacity((w * h) as usize);
        for j in 0..h {
            for i in 0..w {
                let p = rgb.get_pixel(i, h - 1 - j).0;
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

    /// A checkerboard of `squares × squares` black and white squares, `size` texels a side.
    #[must_use]
    pub fn checkerboard(size: u32, squares: u32) -> Self {
        let cell = (size / squares.max(1)).max(1);
        Self::from_fn("checkerboard", size, |i, j| {
            if ((i / cell) + (j / cell)).is_multiple_of(2) {
                Vec3::splat(0.95)
            } else {
                Vec3::splat(0.1)
            }
        })
    }

    /// A uv grid: red grows with u, green with v, with white grid lines every 1/8 and a darker
    /// cell pattern, so orientation and distortion are visible.
    #[must_use]
    pub fn uv_grid(size: u32) -> Self {
        let line = (size / 8).max(1);
        Self::from_fn("uv_grid", size, |i, j| {
            let (u, v) = (
                (i as f32 + 0.5) / size as f32,
                (j as f32 + 0.5) / size as f32,
            );
            if i.is_multiple_of(line) || j.is_multiple_of(line) {
                Vec3::ONE
            } else if ((i / line) + (j / line)).is_multiple_of(2) {
                Vec3::new(u, v, 0.35)
            } else {
                Vec3::new(u, v, 0.35) * 0.7
            }
        })
    }

    /// A texture whose mip levels have distinct colours (level 0 a checkerboard): what is seen
    /// shows which level was read.
    #[must_use]
    pub fn mip_levels(size: u32) -> Self {
        let mut t = Self::checkerboard(size, 8);
        t.name = "mip_levels".to_owned();
        for (k, level) in t.levels.iter_mut().enumerate().skip(1) {
            let c = level_color(k as u32);
            level.texels.iter_mut().for_each(|x| *x = c);
        }
        t
    }

    fn from_fn(name: &str, size: u32, f: impl Fn(u32, u32) -> Vec3) -> Self {
        let size = size.max(1);
        let texels = (0..size)
            .flat_map(|j| (0..size).map(move |i| (i, j)))
            .map(|(i, j)| f(i, j))
            .collect();
        Self::from_level(
            name,
            Level {
                width: size,
                height: size,
                texels,
            },
        )
    }

    /// Level `k` as an image (top row first), for display and export.
    #[must_use]
    pub fn level_image(&self, k: usize) -> RgbaImage {
        let Some(l) = self.levels.get(k.min(self.levels.len().saturating_sub(1))) else {
            return RgbaImage::new(1, 1);
        };
        RgbaImage::from_fn(l.width, l.height, |x, y| {
            let c = l.texels[((l.height - 1 - y) * l.width + x) as usize];
            let b = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
            Rgba([b(c.x), b(c.y), b(c.z), 255])
        })
    }

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

    /// Samples at `uv` with the given screen derivatives of `uv`.
    #[must_use]
    pub fn sample(&self, uv: Vec2, duv_dx: Vec2, duv_dy: Vec2, s: &Sampler) -> Lookup {
        let (major, minor, axis) = self.footprint(duv_dx, duv_dy);
        // Anisotropic: N taps along the major axis, each with the footprint major/N.
        let taps = if s.anisotropy > 1 && minor > 0.0 {
            ((major / minor).ceil() as u32).clamp(1, s.anisotropy)
        } else {
            1
        };
        let lod = (major / taps as f32).max(1e-12).log2() + s.lod_bias;
        let size = self.levels[0].size();
        let mut out = Lookup {
            lod,
            taps,
            footprint: [duv_dx * size, duv_dy * size],
            ..Lookup::default()
        };
        let mut sum = Vec3::ZERO;
        for k in 0..taps {
            let offset = if taps > 1 {
                (k as f32 + 0.5) / taps as f32 - 0.5
            } else {
                0.0
            };
            let (c, level, blend) = self.sample_lod(uv + axis * offset, lod, s);
            sum += c;
            (out.level, out.level_blend) = (level, blend);
        }
        out.color = sum / taps as f32;
        out
    }

    /// One isotropic lookup at level of detail `lod`: returns the colour, the finer level read
    /// and the blend weight of the next one.
    fn sample_lod(&self, uv: Vec2, lod: f32, s: &Sampler) -> (Vec3, u32, f32) {
        let max = (self.levels.len() - 1) as f32;
        let read = |k: usize| match s.filter {
            Filter::Nearest => self.levels[k].nearest(uv, s.wrap),
            Filter::Bilinear => self.levels[k].bilinear(uv, s.wrap),
        };
        match s.mipmap {
            _ if lod <= 0.0 => (read(0), 0, 0.0),
            Mipmap::None => (read(0), 0, 0.0),
            Mipmap::Nearest => {
                let k = (lod + 0.5).floor().clamp(0.0, max) as usize;
                (read(k), k as u32, 0.0)
            }
            Mipmap::Linear => {
                let l = lod.clamp(0.0, max);
                let k = l.floor() as usize;
                let f = l - k as f32;
                if k + 1 < self.levels.len() && f > 0.0 {
                    (read(k).lerp(read(k + 1), f), k as u32, f)
                } else {
                    (read(k), k as u32, 0.0)
                }
            }
        }
    }
}

/// A distinct colour for mip level `k`, used by the mip-level texture and the level legend.
#[must_use]
pub fn level_color(k: u32) -> Vec3 {
    const COLORS: [[f32; 3]; 8] = [
        [0.95, 0.95, 0.95],
        [0.90, 0.25, 0.25],
        [0.95, 0.60, 0.15],
        [0.95, 0.90, 0.20],
        [0.30, 0.80, 0.30],
        [0.20, 0.75, 0.85],
        [0.30, 0.40, 0.95],
        [0.70, 0.35, 0.90],
    ];
    Vec3::from(COLORS[(k as usize).min(COLORS.len() - 1)])
}

/// Detail a texture adds to a surface's normal (used where lighting is per pixel).
#[derive(Clone, Debug, PartialEq)]
pub enum SurfaceDetail {
    /// Bump mapping from a height map `h(u, v)` (its texels' luminance), GAMES101's way: in the
    /// tangent frame, `dU = k_h·k_n·(h(u + 1/w, v) − h(u, v))`, `dV = k_h·k_n·(h(u, v + 1/h) −
    /// h(u, v))` (the notes write the first as dp/dv: it is dp/du), the perturbed normal is
    /// `normalize(TBN·(−dU, −dV, 1))`.
    Bump {
        /// The height map.
        height: std::sync::Arc<Texture>,
        /// `k_h·k_n`: how strongly height changes tilt the normal.
        strength: f32,
    },
    /// Normal mapping: the texel is a tangent-space normal, `n_t = 2·c − 1`, and the normal is
    /// `normalize(TBN·n_t)`.
    Normal(std::sync::Arc<Texture>),
}

/// The tangent and bitangent of a triangle from its positions and texture coordinates, the
/// directions in which `u` and `v` grow:
/// `T = (Δp₁·Δv₂ − Δp₂·Δv₁)/det`, `B = (Δp₂·Δu₁ − Δp₁·Δu₂)/det`, `det = Δu₁·Δv₂ − Δu₂·Δv₁`.
/// `None` when the uvs are degenerate.
#[must_use]
pub fn tangent_frame(p: [Vec3; 3], uv: [Vec2; 3]) -> Option<(Vec3, Vec3)> {
    let (dp1, dp2) = (p[1] - p[0], p[2] - p[0]);
    let (d1, d2) = (uv[1] - uv[0], uv[2] - uv[0]);
    let det = d1.x * d2.y - d2.x * d1.y;
    if det.abs() < 1e-12 {
        return None;
    }
    Some((
        (dp1 * d2.y - dp2 * d1.y) / det,
        (dp2 * d1.x - dp1 * d2.x) / det,
    ))
}

impl SurfaceDetail {
    /// The normal at `uv` perturbed from the unit normal `n` in the tangent frame `(t, b)`
    /// (made orthonormal to `n` first: `T' = normalize(t − n(n·t))`, `B' = ±n × T'`).
    #[must_use]
    pub fn perturb(&self, n: Vec3, t: Vec3, b: Vec3, uv: Vec2) -> Vec3 {
        let n = n.normalize_or_zero();
        let t1 = (t - n * n.dot(t)).normalize_or_zero();
        let handed = if n.cross(t1).dot(b) < 0.0 { -1.0 } else { 1.0 };
        let b1 = n.cross(t1) * handed;
        let local = match self {
            Self::Bump { height, strength } => {
                let l = &height.levels[0];
                let h = |uv: Vec2| {
                    let c = l.bilinear(uv, Wrap::Repeat);
                    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
                };
                let here = h(uv);
                let du = strength * (h(uv + Vec2::new(1.0 / l.width as f32, 0.0)) - here);
                let dv = strength * (h(uv + Vec2::new(0.0, 1.0 / l.height as f32)) - here);
                Vec3::new(-du, -dv, 1.0)
            }
            Self::Normal(map) => map.levels[0].bilinear(uv, Wrap::Repeat) * 2.0 - Vec3::ONE,
        };
        (t1 * local.x + b1 * local.y + n * local.z).normalize_or_zero()
    }
}

impl Texture {
    /// A height map of round bumps on a grid (`count × count` of them), for bump mapping.
    #[must_use]
    pub fn bumps(size: u32, count: u32) -> Self {
        let mut t = Self::from_fn("bumps", size, |i, j| {
            let cell = size as f32 / count.max(1) as f32;
            let (x, y) = (
                (i as f32 + 0.5) % cell / cell - 0.5,
                (j as f32 + 0.5) % cell / cell - 0.5,
            );
            let r2 = (x * x + y * y) * 4.0;
            Vec3::splat((1.0 - r2).max(0.0).sqrt())
        });
        t.name = "bumps".to_owned();
        t
    }

    /// The tangent-space normal map of the same bumps: from the height's central differences
    /// `∂h/∂u, ∂h/∂v` (per texel, times `strength`), `n = normalize(−∂h/∂u, −∂h/∂v, 1)` stored
    /// as `(n + 1)/2` — what a normal map holds, so that normal mapping reproduces bump mapping.
    #[must_use]
    pub fn bump_normals(size: u32, count: u32, strength: f32) -> Self {
        let height = Self::bumps(size, count);
        let l = &height.levels[0];
        let h = |i: i64, j: i64| l.texel(i, j, Wrap::Repeat).x;
        let mut t = Self::from_fn("bump_normals", size, |i, j| {
            let (i, j) = (i64::from(i), i64::from(j));
            let du = (h(i + 1, j) - h(i - 1, j)) / 2.0 * strength;
            let dv = (h(i, j + 1) - h(i, j - 1)) / 2.0 * strength;
            (Vec3::new(-du, -dv, 1.0).normalize() + Vec3::ONE) / 2.0
        });
        t.name = "bump_normals".to_owned();
        t
    }
}

/// Displacement mapping: every vertex moves along its normal by `scale·h(u, v)`, `h` the
/// height map's luminance (bilinear, level 0). It changes geometry, so it needs a finely
/// subdivided mesh; the normals are left as they were (add bump mapping with the same map to
/// light the new relief).
#[derive(Clone, Debug, PartialEq)]
pub struct Displacement {
    /// The height map.
    pub height: std::sync::Arc<Texture>,
    /// The largest displacement, in object units.
    pub scale: f32,
}

impl Displacement {
    /// `scale·h(u, v)`.
    #[must_use]
    pub fn offset(&self, uv: Vec2) -> f32 {
        let c = self.height.levels[0].bilinear(uv, Wrap::Repeat);
        self.scale * (0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z)
    }
}

/// A cube map: six square faces around the origin, looked up by direction (environment mapping).
/// Faces in the order +x, −x, +y, −y, +z, −z; on each, `(s, t)` run as in OpenGL's cube map table
/// (major axis `m`, `s = (sc/|m| + 1)/2`, `t = (tc/|m| + 1)/2`):
/// +x: `sc = −z, tc = y`; −x: `sc = z, tc = y`; +y: `sc = x, tc = −z`; −y: `sc = x, tc = z`;
/// +z: `sc = x, tc = y`; −z: `sc = −x, tc = y` — with `t` growing upwards (our texel rows count
/// from the bottom), so each face reads as seen from the centre with +y up.
#[derive(Clone, Debug, PartialEq)]
pub struct CubeMap {
    /// The faces +x, −x, +y, −y, +z, −z.
    pub faces: [Level; 6],
}

impl CubeMap {
    /// The face and `(s, t)` a direction falls on.
    #[must_use]
    pub fn face_coords(d: Vec3) -> (usize, Vec2) {
        let a = d.abs();
        let (face, sc, tc, m) = if a.x >= a.y && a.x >= a.z {
            if d.x > 0.0 {
                (0, -d.z, d.y, a.x)
            } else {
                (1, d.z, d.y, a.x)
            }
        } else if a.y >= a.z {
            if d.y > 0.0 {
                (2, d.x, -d.z, a.y)
            } else {
                (3, d.x, d.z, a.y)
            }
        } else if d.z > 0.0 {
            (4, d.x, d.y, a.z)
        } else {
            (5, -d.x, d.y, a.z)
        };
        let m = m.max(1e-12);
        (face, Vec2::new((sc / m + 1.0) / 2.0, (tc / m + 1.0) / 2.0))
    }

    /// The colour seen in direction `d` (bilinear within the face, edges clamped).
    #[must_use]
    pub fn sample(&self, d: Vec3) -> Vec3 {
        let (face, st) = Self::face_coords(d);
        self.faces[face].bilinear(st, Wrap::Clamp)
    }

    /// A procedural room: a sky gradient above, a checkered floor below, four walls each in its
    /// own colour with a grid, so a reflection shows which way it looks.
    #[must_use]
    pub fn room(size: u32) -> Self {
        let size = size.max(2);
        let face = |f: &dyn Fn(f32, f32) -> Vec3| {
            let texels = (0..size)
                .flat_map(|j| (0..size).map(move |i| (i, j)))
                .map(|(i, j)| {
                    f(
                        (i as f32 + 0.5) / size as f32,
                        (j as f32 + 0.5) / size as f32,
                    )
                })
                .collect();
            Level {
                width: size,
                height: size,
                texels,
            }
        };
        let wall = |c: Vec3| {
            move |s: f32, t: f32| {
                let grid = ((s * 8.0).fract() < 0.06) || ((t * 8.0).fract() < 0.06);
                let shade = 0.55 + 0.45 * t;
                if grid { Vec3::splat(0.95) } else { c * shade }
            }
        };
        let sky = |s: f32, t: f32| {
            let r = ((s - 0.5).powi(2) + (t - 0.5).powi(2)).sqrt();
            Vec3::new(0.45, 0.65, 0.95)
                .lerp(Vec3::new(1.0, 0.97, 0.85), (1.0 - r * 3.0).clamp(0.0, 1.0))
        };
        let floor = |s: f32, t: f32| {
            if ((s * 8.0) as u32 + (t * 8.0) as u32).is_multiple_of(2) {
                Vec3::splat(0.8)
            } else {
                Vec3::splat(0.25)
            }
        };
        Self {
            faces: [
                face(&wall(Vec3::new(0.9, 0.3, 0.3))),
                face(&wall(Vec3::new(0.3, 0.8, 0.4))),
                face(&sky),
                face(&floor),
                face(&wall(Vec3::new(0.3, 0.45, 0.9))),
                face(&wall(Vec3::new(0.9, 0.8, 0.3))),
            ],
        }
    }
}

/// Environment mapping: the surface mirrors the cube map in direction `r = 2(n·v)n − v`,
/// mixed into its lit colour by `reflectivity` (per-pixel lighting only).
#[derive(Clone, Debug, PartialEq)]
pub struct Environment {
    /// What the surface reflects.
    pub cube: std::sync::Arc<CubeMap>,
    /// 0: no reflection, 1: a perfect mirror.
    pub reflectivity: f32,
}
