//! Rasterization: from a triangle in window coordinates to the samples it covers.
//!
//! **Window coordinates** have their origin at the bottom-left corner of the viewport, x to the
//! right, y up (OpenGL's convention); pixel `(i, j)` is the square `[i, i+1] × [j, j+1]` and its
//! centre is `(i + ½, j + ½)`. Images are stored top row first, so pixel row `j` is image row
//! `height − 1 − j`.
//!
//! **Snapping.** Vertex positions are snapped to a grid of 1/256 pixel ([`SUBPIXEL_BITS`] = 8) and
//! every inside test is done on integers, exactly: two triangles that share an edge see the same
//! edge function with opposite signs, so each sample on the edge goes to exactly one of them.
//!
//! **Edge functions.** For the edge `a → b`, `E(p) = (b.x − a.x)·(p.y − a.y) − (b.y − a.y)·(p.x − a.x)`,
//! twice the signed area of the triangle `a, b, p`. Triangles are made counter-clockwise first,
//! so that `E ≥ 0` on the inside of all three edges; `E_i` is the edge opposite vertex `i`, and the
//! screen-space barycentric weights are `λ_i = E_i / (E_0 + E_1 + E_2)`.
//!
//! **Fill rule (top-left).** A sample exactly on an edge (`E = 0`) belongs to the triangle only if
//! that edge is a *top* edge (horizontal, the triangle below it) or a *left* edge (the triangle to
//! its right), as seen on screen. For a counter-clockwise triangle with y up: a top edge has
//! `Δy = 0, Δx < 0`; a left edge has `Δy < 0`.
//!
//! **Depth** is `z_w = λ_0·z_0 + λ_1·z_1 + λ_2·z_2`, linear in screen space (NDC z is an affine
//! function of screen x, y across a triangle). **Attributes** are interpolated perspective-correctly,
//! `b_i = (λ_i / w_i) / Σ_k (λ_k / w_k)`, or affinely (`b_i = λ_i`) for comparison.

use glam::{I64Vec2, Vec3};
use serde::Serialize;

use crate::scene::{DepthTest, Samples};

/// Bits of sub-pixel precision of snapped vertex positions.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed-point units.
pub const ONE: i64 = 1 << SUBPIXEL_BITS;
/// The primitive / triangle id of a sample nothing covered.
pub const NONE: u32 = u32::MAX;

/// Sample positions of the standard multisample patterns (those of Direct3D, which OpenGL
/// implementations share), in 1/16 pixel from the pixel centre, **y down** as they are published.
const PATTERN_1: [(i8, i8); 1] = [(0, 0)];
const PATTERN_4: [(i8, i8); 4] = [(-2, -6), (6, -2), (-6, 2), (2, 6)];
const PATTERN_8: [(i8, i8); 8] = [
    (1, -3),
    (-1, 3),
    (5, 1),
    (-3, -5),
    (-5, 5),
    (-7, -1),
    (3, 7),
    (7, -7),
];
const PATTERN_16: [(i8, i8); 16] = [
    (1, 1),
    (-1, -3),
    (-3, 2),
    (4, -1),
    (-5, -2),
    (2, 5),
    (5, 3),
    (3, -5),
    (-2, 6),
    (0, -7),
    (-4, -6),
    (-6, 4),
    (-8, 0),
    (7, -4),
    (6, 7),
    (-7, -8),
];

fn pattern(samples: Samples) -> &'static [(i8, i8)] {
    match samples {
        Samples::X1 => &PATTERN_1,
        Samples::X4 => &PATTERN_4,
        Samples::X8 => &PATTERN_8,
        Samples::X16 => &PATTERN_16,
    }
}

/// The sample positions inside a pixel, as offsets from its bottom-left corner in fixed point
/// (window coordinates, y up).
#[must_use]
pub fn sample_offsets_fixed(samples: Samples) -> Vec<I64Vec2> {
    pattern(samples)
        .iter()
        .map(|&(dx, dy)| {
            I64Vec2::new(
                (8 + i64::from(dx)) * ONE / 16,
                (8 - i64::from(dy)) * ONE / 16,
            )
        })
        .collect()
}

/// The sample positions inside a pixel as fractions of a pixel from its **top-left** corner
/// (image coordinates, y down), for drawing them.
#[must_use]
pub fn sample_offsets_image(samples: Samples) -> Vec<[f32; 2]> {
    pattern(samples)
        .iter()
        .map(|&(dx, dy)| [(8.0 + f32::from(dx)) / 16.0, (8.0 + f32::from(dy)) / 16.0])
        .collect()
}

/// Snaps a window coordinate to the sub-pixel grid.
#[must_use]
#[inline]
pub fn snap(v: f32) -> i64 {
    (f64::from(v) * ONE as f64).round() as i64
}

/// A triangle ready to be rasterized: snapped, counter-clockwise, with its edge equations.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RasterTriangle {
    /// The primitive (input triangle) this piece belongs to.
    pub primitive: u32,
    /// Window coordinates `(x, y, z_w)` of the corners, counter-clockwise.
    pub window: [Vec3; 3],
    /// `1/w_clip` of the corners (for perspective-correct interpolation).
    pub inv_w: [f32; 3],
    /// Barycentric weights of the corners with respect to the original triangle.
    pub bary: [Vec3; 3],
    /// Pixel bounding box `[x_min, y_min, x_max, y_max]` (inclusive, window pixels, y up),
    /// clamped to the viewport.
    pub bbox: [u32; 4],
    #[serde(skip)]
    edges: [Edge; 3],
    #[serde(skip)]
    area2: i64,
}

/// One edge equation `E(p) = a·p.x + b·p.y + c`, plus the fill-rule bias (`0` for top-left edges,
/// `−1` otherwise, so that `E + bias ≥ 0` is the inside test on integers).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Edge {
    a: i64,
    b: i64,
    c: i64,
    bias: i64,
}

impl Edge {
    fn new(p: I64Vec2, q: I64Vec2) -> Self {
        let d = q - p;
        let (a, b) = (-d.y, d.x);
        let top_left = (d.y == 0 && d.x < 0) || d.y < 0;
        Self {
            a,
            b,
            c: -(a * p.x + b * p.y),
            bias: if top_left { 0 } else { -1 },
        }
    }

    #[inline]
    fn at(&self, p: I64Vec2) -> i64 {
        self.a * p.x + self.b * p.y + self.c
    }
}

/// Why a triangle produced no raster triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetupRejection {
    /// Zero area after snapping.
    Degenerate,
    /// Clockwise on screen (a back face) with back-face culling on.
    BackFace,
    /// Counter-clockwise (a front face) with front-face culling on.
    FrontFace,
}

impl RasterTriangle {
    /// Sets up a triangle from window coordinates. Returns the signed orientation test result
    /// through `Err` when it is degenerate or culled.
    ///
    /// # Errors
    /// [`SetupRejection`] when the triangle has no area or is culled.
    pub fn setup(
        primitive: u32,
        window: [Vec3; 3],
        inv_w: [f32; 3],
        bary: [Vec3; 3],
        cull: crate::scene::CullMode,
        size: (u32, u32),
    ) -> Result<Self, SetupRejection> {
        let mut fixed = window.map(|p| I64Vec2::new(snap(p.x), snap(p.y)));
        let area2 = (fixed[1] - fixed[0]).perp_dot(fixed[2] - fixed[0]);
        if area2 == 0 {
            return Err(SetupRejection::Degenerate);
        }
        let front = area2 > 0;
        match cull {
            crate::scene::CullMode::Back if !front => return Err(SetupRejection::BackFace),
            crate::scene::CullMode::Front if front => return Err(SetupRejection::FrontFace),
            _ => {}
        }
        let (mut window, mut inv_w, mut bary) = (window, inv_w, bary);
        if !front {
            fixed.swap(1, 2);
            window.swap(1, 2);
            inv_w.swap(1, 2);
            bary.swap(1, 2);
        }
        let edges = [
            Edge::new(fixed[1], fixed[2]),
            Edge::new(fixed[2], fixed[0]),
            Edge::new(fixed[0], fixed[1]),
        ];
        let lo = fixed[0].min(fixed[1]).min(fixed[2]);
        let hi = fixed[0].max(fixed[1]).max(fixed[2]);
        let clamp = |v: i64, max: u32| v.div_euclid(ONE).clamp(0, i64::from(max) - 1) as u32;
        let bbox = [
            clamp(lo.x, size.0),
            clamp(lo.y, size.1),
            clamp(hi.x, size.0),
            clamp(hi.y, size.1),
        ];
        Ok(Self {
            primitive,
            window,
            inv_w,
            bary,
            bbox,
            edges,
            area2: area2.abs(),
        })
    }

    /// Whether the sample at fixed-point position `p` is covered (top-left rule).
    #[must_use]
    #[inline]
    pub fn covers(&self, p: I64Vec2) -> bool {
        self.edges.iter().all(|e| e.at(p) + e.bias >= 0)
    }

    /// Screen-space barycentric weights `λ` at a fixed-point position (extrapolated outside).
    #[must_use]
    #[inline]
    pub fn lambda(&self, p: I64Vec2) -> Vec3 {
        let inv = 1.0 / self.area2 as f64;
        let l1 = self.edges[1].at(p) as f64 * inv;
        let l2 = self.edges[2].at(p) as f64 * inv;
        Vec3::new((1.0 - l1 - l2) as f32, l1 as f32, l2 as f32)
    }

    /// The depth plane in edge-function terms, `(z_0, k_1, k_2)` with
    /// `z = z_0 + k_1·E_1 + k_2·E_2`, `k_i = (z_i − z_0)/area` (`E_i` without the fill-rule bias).
    #[must_use]
    #[inline]
    fn depth_plane(&self) -> (f64, f64, f64) {
        let inv_area = 1.0 / self.area2 as f64;
        let z0 = f64::from(self.window[0].z);
        (
            z0,
            (f64::from(self.window[1].z) - z0) * inv_area,
            (f64::from(self.window[2].z) - z0) * inv_area,
        )
    }

    /// Window depth at screen-space weights `λ`.
    #[must_use]
    #[inline]
    pub fn depth(&self, l: Vec3) -> f32 {
        l.x * self.window[0].z + l.y * self.window[1].z + l.z * self.window[2].z
    }

    /// Barycentric weights of the **original** triangle at screen-space weights `λ`:
    /// perspective-correct, `b = Σ (λ_i/w_i)·bary_i / Σ (λ_i/w_i)`, or affine, `b = Σ λ_i·bary_i`.
    #[must_use]
    #[inline]
    pub fn original_bary(&self, l: Vec3, perspective_correct: bool) -> Vec3 {
        let k = if perspective_correct {
            let k = l * Vec3::from(self.inv_w);
            k / (k.x + k.y + k.z)
        } else {
            l
        };
        self.bary[0] * k.x + self.bary[1] * k.y + self.bary[2] * k.z
    }
}

/// Per-sample visibility: the depth buffer and which raster triangle owns each sample.
/// Sample `s` of the pixel at image row `r`, column `c` is at `(r·width + c)·samples + s`.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleBuffers {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub samples: Samples,
    /// Window depth per sample.
    pub depth: Vec<f32>,
    /// Index of the raster triangle that wrote each sample last, or [`NONE`].
    pub triangle: Vec<u32>,
    offsets: Vec<I64Vec2>,
}

/// What rasterizing one triangle did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct RasterCounts {
    /// Samples inside the triangle.
    pub covered: u32,
    /// Samples that passed the depth test and were written.
    pub written: u32,
}

impl SampleBuffers {
    /// Buffers cleared to `clear_depth` and no triangle.
    #[must_use]
    pub fn new(width: u32, height: u32, samples: Samples, clear_depth: f32) -> Self {
        let n = width as usize * height as usize * samples.count();
        Self {
            width,
            height,
            samples,
            depth: vec![clear_depth; n],
            triangle: vec![NONE; n],
            offsets: sample_offsets_fixed(samples),
        }
    }

    /// These buffers' storage, resized and cleared as [`Self::new`] makes them.
    #[must_use]
    pub fn cleared(mut self, width: u32, height: u32, samples: Samples, clear_depth: f32) -> Self {
        use rayon::prelude::*;
        let n = width as usize * height as usize * samples.count();
        // Grown or shrunk, then cleared in parallel chunks (a clear is a memory-bound pass over
        // tens of megabytes).
        self.depth.resize(n, clear_depth);
        self.triangle.resize(n, NONE);
        const CHUNK: usize = 1 << 16;
        self.depth
            .par_chunks_mut(CHUNK)
            .zip(self.triangle.par_chunks_mut(CHUNK))
            .for_each(|(d, t)| {
                d.fill(clear_depth);
                t.fill(NONE);
            });
        Self {
            width,
            height,
            samples,
            offsets: sample_offsets_fixed(samples),
            ..self
        }
    }

    /// The position of sample `s` within a pixel, from its bottom-left corner, in fixed point.
    #[must_use]
    pub fn offset(&self, s: usize) -> I64Vec2 {
        self.offsets[s]
    }

    /// The index of sample `s` of window pixel `(x, y)` (y up).
    #[must_use]
    #[inline]
    pub fn index(&self, x: u32, y: u32, s: usize) -> usize {
        let row = (self.height - 1 - y) as usize;
        (row * self.width as usize + x as usize) * self.samples.count() + s
    }

    /// Rasterizes `tri` (whose index in the capture's triangle list is `index`): every covered
    /// sample that passes the depth test takes the triangle's depth and index.
    pub fn rasterize(&mut self, tri: &RasterTriangle, index: u32, test: DepthTest) -> RasterCounts {
        let rows = self.height as usize;
        let mut band = Band {
            depth: &mut self.depth,
            owner: &mut self.triangle,
            width: self.width as usize,
            height: self.height,
            first_row: 0,
            rows,
            offsets: &self.offsets,
        };
        band.rasterize(tri, index, test)
    }

    /// Rasterizes every triangle, in order, and returns what each did. The image rows are cut
    /// into bands (four per thread) rasterized in parallel; each triangle is first binned into
    /// the bands its bounding box reaches, and each band draws its triangles in order over its
    /// own rows. A sample belongs to one band, so the result is the same as drawing the
    /// triangles one after another over the whole image ([`Self::rasterize_reference`] checks
    /// it in the tests).
    pub fn rasterize_all(&mut self, tris: &[RasterTriangle], test: DepthTest) -> Vec<RasterCounts> {
        use rayon::prelude::*;
        let (w, n) = (self.width as usize, self.offsets.len());
        let h = self.height as usize;
        let bands = (rayon::current_num_threads() * 4).clamp(1, h.max(1));
        let rows_per = h.div_ceil(bands).max(1);
        let bands = h.div_ceil(rows_per);
        // Binning: each band gets the triangles whose bounding box reaches its rows, in order.
        let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands];
        for (i, t) in tris.iter().enumerate() {
            let [_, y0, _, y1] = t.bbox;
            // Image rows of the box: h − 1 − y1 (top) to h − 1 − y0 (bottom).
            let (r0, r1) = (h - 1 - y1 as usize, h - 1 - y0 as usize);
            for bin in &mut bins[r0 / rows_per..=r1 / rows_per] {
                bin.push(i as u32);
            }
        }
        let chunk = rows_per * w * n;
        let (height, offsets) = (self.height, &self.offsets);
        let per_band: Vec<Vec<(u32, RasterCounts)>> = self
            .depth
            .par_chunks_mut(chunk)
            .zip(self.triangle.par_chunks_mut(chunk))
            .zip(bins.par_iter())
            .enumerate()
            .map(|(b, ((depth, owner), bin))| {
                let rows = depth.len() / (w * n);
                let mut band = Band {
                    depth,
                    owner,
                    width: w,
                    height,
                    first_row: b * rows_per,
                    rows,
                    offsets,
                };
                bin.iter()
                    .map(|&i| (i, band.rasterize(&tris[i as usize], i, test)))
                    .collect()
            })
            .collect();
        let mut total = vec![RasterCounts::default(); tris.len()];
        for (i, c) in per_band.into_iter().flatten() {
            let t = &mut total[i as usize];
            t.covered += c.covered;
            t.written += c.written;
        }
        total
    }

    /// The simple rasterizer the fast one is checked against: every sample of the bounding box
    /// tested on its own with [`RasterTriangle::covers`] (no stepping, no bands), its depth
    /// from the same plane.
    pub fn rasterize_reference(
        &mut self,
        tri: &RasterTriangle,
        index: u32,
        test: DepthTest,
    ) -> RasterCounts {
        let mut counts = RasterCounts::default();
        let [x0, y0, x1, y1] = tri.bbox;
        let (z0, k1, k2) = tri.depth_plane();
        for y in y0..=y1 {
            for x in x0..=x1 {
                let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
                for s in 0..self.offsets.len() {
                    let p = corner + self.offsets[s];
                    if !tri.covers(p) {
                        continue;
                    }
                    counts.covered += 1;
                    let e1 = tri.edges[1].at(p) as f64;
                    let e2 = tri.edges[2].at(p) as f64;
                    let z = (z0 + k1 * e1 + k2 * e2) as f32;
                    let i = self.index(x, y, s);
                    if test.passes(z, self.depth[i]) {
                        self.depth[i] = z;
                        self.triangle[i] = index;
                        counts.written += 1;
                    }
                }
            }
        }
        counts
    }
}

/// A band of image rows `first_row .. first_row + rows` of the sample buffers.
struct Band<'a> {
    depth: &'a mut [f32],
    owner: &'a mut [u32],
    width: usize,
    height: u32,
    first_row: usize,
    rows: usize,
    offsets: &'a [I64Vec2],
}

/// Boxes at least this many pixels wide are scanned only over each row's span.
const SPAN_MIN_WIDTH: u32 = 8;

/// The pixels `a..=b` (offsets from the box's first column, within `0..=last`) of a row where
/// some sample can be inside all three edges: sample `s` is inside edge `k` at offset `x` when
/// `e_sk + x·step_k ≥ 0`, so for `step_k > 0` from `⌈−e_sk/step_k⌉` on and for `step_k < 0` up
/// to `⌊e_sk/(−step_k)⌋`. The union over the samples; `None` when no sample can be inside.
fn row_span(e: &[[i64; 3]], step: [i64; 3], last: u32) -> Option<(u32, u32)> {
    let last = i64::from(last);
    let mut span: Option<(i64, i64)> = None;
    for es in e {
        let (mut lo, mut hi) = (0i64, last);
        for k in 0..3 {
            let (v, d) = (es[k], step[k]);
            if d > 0 {
                if v < 0 {
                    lo = lo.max((-v + d - 1) / d);
                }
            } else if d < 0 {
                if v < 0 {
                    hi = -1;
                } else {
                    hi = hi.min(v / -d);
                }
            } else if v < 0 {
                hi = -1;
            }
        }
        if lo <= hi {
            span = Some(span.map_or((lo, hi), |(a, b)| (a.min(lo), b.max(hi))));
        }
    }
    span.map(|(a, b)| (a as u32, b as u32))
}

impl Band<'_> {
    /// Rasterizes `tri` over this band's rows. The edge functions are evaluated once per row at
    /// the first pixel's samples and then stepped by `a·ONE` per pixel (they are linear in x);
    /// depth is the plane `z = z_0 + k_1·E_1 + k_2·E_2`.
    fn rasterize(&mut self, tri: &RasterTriangle, index: u32, test: DepthTest) -> RasterCounts {
        let mut counts = RasterCounts::default();
        let [x0, mut y0, x1, mut y1] = tri.bbox;
        // Window rows y of this band: image rows r = height − 1 − y.
        let top = self.height as usize - 1 - self.first_row;
        let bottom = (top + 1).saturating_sub(self.rows);
        y0 = y0.max(bottom as u32);
        y1 = y1.min(top as u32);
        if y0 > y1 {
            return counts;
        }
        let n = self.offsets.len();
        let (z0, k1, k2) = tri.depth_plane();
        let step = tri.edges.map(|e| e.a * ONE);
        let mut e = [[0i64; 3]; 16];
        for y in y0..=y1 {
            let row = top - y as usize;
            let corner = I64Vec2::new(i64::from(x0) * ONE, i64::from(y) * ONE);
            for (s, off) in self.offsets.iter().enumerate() {
                e[s] = tri.edges.map(|edge| edge.at(corner + *off) + edge.bias);
            }
            // Wide boxes: only the pixels between the first and the last that can have a
            // covered sample in this row (found exactly, in integers), so the empty corners of
            // the box are not scanned.
            let (xs, xe) = if x1 - x0 >= SPAN_MIN_WIDTH {
                let Some((a, b)) = row_span(&e[..n], step, x1 - x0) else {
                    continue;
                };
                for es in &mut e[..n] {
                    for k in 0..3 {
                        es[k] += step[k] * i64::from(a);
                    }
                }
                (x0 + a, x0 + b)
            } else {
                (x0, x1)
            };
            for x in xs..=xe {
                let base = (row * self.width + x as usize) * n;
                for (s, es) in e.iter_mut().enumerate().take(n) {
                    if (es[0] | es[1] | es[2]) >= 0 {
                        counts.covered += 1;
                        // The bias (0 or −1) is removed again for the depth plane.
                        let e1 = (es[1] - tri.edges[1].bias) as f64;
                        let e2 = (es[2] - tri.edges[2].bias) as f64;
                        let z = (z0 + k1 * e1 + k2 * e2) as f32;
                        let i = base + s;
                        if test.passes(z, self.depth[i]) {
                            self.depth[i] = z;
                            self.owner[i] = index;
                            counts.written += 1;
                        }
                    }
                    es[0] += step[0];
                    es[1] += step[1];
                    es[2] += step[2];
                }
            }
        }
        counts
    }
}
