//! The sample buffers: a depth value (the z-buffer) and the owning raster triangle per sample,
//! the depth test, and rasterizing triangles into them — in parallel bands of rows, and by the
//! simple reference rasterizer the fast one is checked against.

use glam::I64Vec2;
use serde::Serialize;
use wide::i64x4;

use super::bins::{Bins, RasterCounts};
use super::covered::Covered;
use super::{ONE, RasterTriangle, Samples};

/// The depth test: a fragment is kept when `compare(fragment_depth, stored_depth)` holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DepthTest {
    /// `<` (OpenGL's default `GL_LESS`): nearer wins, the first of equals stays.
    #[default]
    Less,
    /// `≤`: nearer wins, the last of equals replaces.
    LessEqual,
    /// `>`: farther wins.
    Greater,
    /// `≥`.
    GreaterEqual,
    /// Always pass: the last fragment drawn wins (painter's order).
    Always,
}

impl DepthTest {
    /// Whether a fragment at `z` replaces the stored `stored`.
    #[must_use]
    #[inline]
    pub fn passes(self, z: f32, stored: f32) -> bool {
        match self {
            Self::Less => z < stored,
            Self::LessEqual => z <= stored,
            Self::Greater => z > stored,
            Self::GreaterEqual => z >= stored,
            Self::Always => true,
        }
    }

    /// The depth the buffer is cleared to: the far end for `<`/`≤`, the near end otherwise.
    #[must_use]
    pub fn clear_value(self) -> f32 {
        match self {
            Self::Greater | Self::GreaterEqual => 0.0,
            _ => 1.0,
        }
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
    /// Index of the raster triangle that wrote each sample last, or [`NONE`](super::NONE).
    pub triangle: Vec<u32>,
    pub(super) offsets: Vec<I64Vec2>,
    pub(super) bins: Bins,
    /// Where the frame resolved from these buffers covered samples, so that the next clear
    /// clears there only ([`Self::cleared`]).
    pub(crate) covered: Covered,
}

/// Consecutive image rows of the sample buffers, read: the samples from index `first` of the
/// whole buffers on (sample `s` of image pixel `i` is at `i·samples + s`, as in
/// [`SampleBuffers`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct SampleRows<'a> {
    depth: &'a [f32],
    triangle: &'a [u32],
    first: usize,
    offsets: &'a [I64Vec2],
    /// The pixels of each row the rasterizer scanned, from image row `first_row` on; empty
    /// where it is not known.
    scanned: &'a [(u32, u32)],
    first_row: usize,
}

impl<'a> SampleRows<'a> {
    /// The owning triangles of samples `range` (indices of the whole buffers), which must lie
    /// in these rows.
    #[must_use]
    #[inline]
    pub fn triangles(&self, range: std::ops::Range<usize>) -> &'a [u32] {
        &self.triangle[range.start - self.first..range.end - self.first]
    }

    /// The depths of samples `range` (indices of the whole buffers), which must lie in these
    /// rows.
    #[must_use]
    #[inline]
    pub fn depths(&self, range: std::ops::Range<usize>) -> &'a [f32] {
        &self.depth[range.start - self.first..range.end - self.first]
    }

    /// The position of sample `s` within a pixel, from its bottom-left corner, in fixed point.
    #[must_use]
    pub fn offset(&self, s: usize) -> I64Vec2 {
        self.offsets[s]
    }

    /// The pixels `lo..hi` of image row `row` where the rasterizer looked for covered samples:
    /// no sample of the row's other pixels is covered (`lo ≥ hi` when no triangle reached the
    /// row). `None` where these rows were not drawn by [`SampleBuffers::rasterize_all_then`].
    #[must_use]
    #[inline]
    pub fn scanned(&self, row: usize) -> Option<(u32, u32)> {
        self.scanned.get(row.wrapping_sub(self.first_row)).copied()
    }
}

impl SampleBuffers {
    /// Every row, read.
    #[must_use]
    pub fn rows(&self) -> SampleRows<'_> {
        SampleRows {
            depth: &self.depth,
            triangle: &self.triangle,
            first: 0,
            offsets: &self.offsets,
            scanned: &[],
            first_row: 0,
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
        crate::grid::Grid::new(self.width, self.height).index(x, y) * self.samples.count() + s
    }

    /// Rasterizes every triangle, in order, and returns what each did. The image rows are cut
    /// into bands ([`BANDS_A_THREAD`] a thread) rasterized in parallel; each triangle is first
    /// binned into the bands its bounding box reaches, and each band draws its triangles in
    /// order over its own rows. A sample belongs to one band, so the result is the same as drawing the
    /// triangles one after another over the whole image ([`Self::rasterize_reference`] checks
    /// it in the tests).
    pub fn rasterize_all(&mut self, tris: &[RasterTriangle], test: DepthTest) -> &[RasterCounts] {
        let rows_per = self.band_rows(1);
        // Nothing to do with a band once drawn (a `()` a band takes no memory).
        let mut bands = vec![(); (self.height as usize).div_ceil(rows_per).max(1)];
        self.rasterize_all_then(tris, test, rows_per, &mut bands, |(), _| ())
    }

    /// What each triangle did in the last [`Self::rasterize_all`] (or
    /// [`Self::rasterize_all_then`]) on these buffers: scratch kept with them, empty in a clone.
    #[must_use]
    pub fn drawn(&self) -> &[RasterCounts] {
        &self.bins.total
    }

    /// How many image rows each band of [`Self::rasterize_all`] takes: the image cut into
    /// [`BANDS_A_THREAD`] bands a thread, each a multiple of `align` rows (`align` ≥ 1).
    #[must_use]
    pub fn band_rows(&self, align: usize) -> usize {
        let h = self.height as usize;
        let bands = (rayon::current_num_threads() * BANDS_A_THREAD).clamp(1, h.max(1));
        h.div_ceil(bands).max(1).next_multiple_of(align.max(1))
    }

    /// [`Self::rasterize_all`] in bands of `rows_per` image rows, where each band, as soon as
    /// it has drawn every triangle over its rows, calls `then(&mut each[b], rows)` with its
    /// rows as drawn (band `b`; `each` holds one value a band): what is done
    /// with a band's samples is done while they are in the cache of the core that wrote them.
    /// The samples are those [`Self::rasterize_all`] gives, however the rows are cut.
    pub fn rasterize_all_then<T: Send>(
        &mut self,
        tris: &[RasterTriangle],
        test: DepthTest,
        rows_per: usize,
        each: &mut [T],
        then: impl Fn(&mut T, SampleRows<'_>) + Sync,
    ) -> &[RasterCounts] {
        use rayon::prelude::*;
        let (w, n) = (self.width as usize, self.offsets.len());
        let h = self.height as usize;
        let rows_per = rows_per.max(1);
        let bands = h.div_ceil(rows_per).max(1);
        debug_assert_eq!(each.len(), bands);
        self.bins
            .bin(tris, &self.offsets, (self.width, self.height), rows_per);
        let Bins {
            runs,
            counts,
            scanned,
            ..
        } = &mut self.bins;
        let offsets = &self.offsets;
        let chunk = rows_per * w * n;
        let height = self.height;
        counts.resize_with(bands, Vec::new);
        scanned.clear();
        scanned.resize(h, (u32::MAX, 0));
        let runs = &*runs;
        self.depth
            .par_chunks_mut(chunk)
            .zip(self.triangle.par_chunks_mut(chunk))
            .zip(scanned.par_chunks_mut(rows_per))
            .zip(counts.par_iter_mut())
            .zip(each.par_iter_mut())
            .enumerate()
            .for_each(|(b, ((((depth, owner), scanned), counts), each))| {
                let rows = depth.len() / (w * n);
                let mut band = Band {
                    depth,
                    owner,
                    scanned,
                    width: w,
                    height,
                    first_row: b * rows_per,
                    rows,
                    offsets,
                };
                counts.clear();
                counts.extend(
                    runs.iter()
                        .flat_map(|bins| {
                            let bin = &bins[b];
                            let ahead = bin.get(PREFETCH_AHEAD..).unwrap_or_default();
                            bin.iter()
                                .zip(ahead.iter().map(Some).chain(std::iter::repeat(None)))
                        })
                        .map(|(&i, next)| {
                            if let Some(&next) = next {
                                prefetch(&tris[next as usize]);
                            }
                            band.rasterize(&tris[i as usize], i, test)
                        }),
                );
                let rows = SampleRows {
                    depth: band.depth,
                    triangle: band.owner,
                    first: b * chunk,
                    offsets,
                    scanned: band.scanned,
                    first_row: band.first_row,
                };
                then(each, rows);
            });
        self.bins.total(tris.len())
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
        self.rasterize_where(tri, index, test, |_, p| tri.covers(p))
    }

    /// Each sample of `tri`'s bounding box, row by row from the box's bottom (window y up), each
    /// pixel's samples in turn: its index in the buffers and its fixed-point position.
    pub(super) fn box_sample_indices(
        &self,
        tri: &RasterTriangle,
    ) -> impl Iterator<Item = (usize, I64Vec2)> + '_ {
        let [x0, y0, x1, y1] = tri.bbox.map(u32::from);
        (y0..=y1).flat_map(move |y| {
            (x0..=x1).flat_map(move |x| {
                let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
                (0..self.offsets.len())
                    .map(move |s| (self.index(x, y, s), corner + self.offsets[s]))
            })
        })
    }

    /// The samples of `tri`'s bounding box in the order [`Self::rasterize_where`] visits them
    /// (see [`Self::box_sample_indices`]), each as its fixed-point position.
    #[must_use]
    pub fn box_samples(&self, tri: &RasterTriangle) -> Vec<I64Vec2> {
        self.box_sample_indices(tri).map(|(_, p)| p).collect()
    }

    /// Rasterizes `tri` with another inside test: `covers(k, p)` says whether the `k`-th sample
    /// of the box (in [`Self::box_samples`]' order), at fixed-point position `p`, is covered.
    /// Each covered sample takes the depth test with the triangle's depth plane.
    pub fn rasterize_where(
        &mut self,
        tri: &RasterTriangle,
        index: u32,
        test: DepthTest,
        mut covers: impl FnMut(usize, I64Vec2) -> bool,
    ) -> RasterCounts {
        let mut counts = RasterCounts::default();
        let plane = tri.depth_plane();
        let covered: Vec<(usize, I64Vec2)> = self
            .box_sample_indices(tri)
            .enumerate()
            .filter(|(k, (_, p))| covers(*k, *p))
            .map(|(_, sample)| sample)
            .collect();
        for (i, p) in covered {
            let sample = (&mut self.depth[i], &mut self.triangle[i]);
            depth_test(sample, plane.at(p), index, test, &mut counts);
        }
        counts
    }
}

/// A covered sample's depth test: when depth `z` passes against the sample's stored depth, `z`
/// and the triangle's `index` replace what the sample held. Counts the sample as covered, and
/// as written when it passed.
#[inline]
fn depth_test(
    (depth, owner): (&mut f32, &mut u32),
    z: f32,
    index: u32,
    test: DepthTest,
    counts: &mut RasterCounts,
) {
    counts.covered += 1;
    if test.passes(z, *depth) {
        *depth = z;
        *owner = index;
        counts.written += 1;
    }
}

/// The rows of a [`Band`] and where its samples lie: what scanning a triangle's rows needs.
#[derive(Clone, Copy)]
struct BandRows<'a> {
    height: u32,
    first_row: usize,
    rows: usize,
    offsets: &'a [I64Vec2],
}

impl BandRows<'_> {
    /// Calls `row(r, y, (xs, xe), e)` for each window row `y` (row `r` of the band) that `tri`
    /// can cover a sample of, `xs..=xe` its pixels that can be covered and `e` the biased edge
    /// values ([`RasterTriangle::biased_edge_values`]) of pixel `xs`'s `N` samples; and widens
    /// `scanned[r]` to hold `xs..=xe`.
    fn each<const N: usize>(
        self,
        tri: &RasterTriangle,
        scanned: &mut [(u32, u32)],
        mut row: impl FnMut(usize, u32, (u32, u32), &[[i64; 3]; N]),
    ) {
        let [x0, mut y0, x1, mut y1] = tri.bbox.map(u32::from);
        // Window rows y of this band: image rows r = height − 1 − y.
        let top = self.height as usize - 1 - self.first_row;
        let bottom = (top + 1).saturating_sub(self.rows);
        y0 = y0.max(bottom as u32);
        y1 = y1.min(top as u32);
        if y0 > y1 {
            return;
        }
        let offsets = &self.offsets[..N];
        let step = tri.edges.map(|e| i64::from(e.a) * ONE);
        let mut e = [[0i64; 3]; N];
        for y in y0..=y1 {
            let corner = I64Vec2::new(i64::from(x0) * ONE, i64::from(y) * ONE);
            for (es, off) in e.iter_mut().zip(offsets) {
                *es = tri.biased_edge_values(corner + *off);
            }
            // Wide boxes: only the pixels between the first and the last that can have a
            // covered sample in this row (found exactly, in integers), so the empty corners of
            // the box are not scanned.
            let span = if x1 - x0 >= SPAN_MIN_WIDTH {
                let Some((a, b)) = row_span(&e, step, x1 - x0) else {
                    continue;
                };
                for es in &mut e {
                    for k in 0..3 {
                        es[k] += step[k] * i64::from(a);
                    }
                }
                (x0 + a, x0 + b)
            } else {
                (x0, x1)
            };
            let r = top - y as usize;
            let seen = &mut scanned[r];
            *seen = (seen.0.min(span.0), seen.1.max(span.1 + 1));
            row(r, y, span, &e);
        }
    }
}

/// A band of image rows `first_row .. first_row + rows` of the sample buffers.
struct Band<'a> {
    depth: &'a mut [f32],
    owner: &'a mut [u32],
    /// Each row's pixels scanned ([`SampleRows::scanned`]).
    scanned: &'a mut [(u32, u32)],
    width: usize,
    height: u32,
    first_row: usize,
    rows: usize,
    offsets: &'a [I64Vec2],
}

/// How many bands of rows the image is cut into for each thread. A band is a task: bands
/// resolved right after they are drawn ([`SampleBuffers::rasterize_all_then`]) cost as their
/// rows do — the sky little, a textured floor much — and with four bands a thread, one thread
/// was left with the dearer ones (the lit textured floor's every-buffer frame on 2 threads
/// 0.61× its one-thread time, against 0.52× with sixteen; the rasterization alone is the same
/// with 4 to 32, BENCHMARKS.md).
pub const BANDS_A_THREAD: usize = 16;
/// How many triangles ahead in its list a band asks for a triangle's bytes
/// ([`prefetch`]): far enough that they arrive before they are read, near
/// enough that they are still in the cache then (4 to 8 measured best on the bunny, 16 and 32
/// less well; BENCHMARKS.md, session 67).
const PREFETCH_AHEAD: usize = 8;

/// Asks the processor to start bringing into its caches the bytes the rasterizer reads of
/// `tri` — its edges and their top-left flags, its box, its corners' window positions (the
/// depth plane) — without waiting for them. A band reads the triangles its bins list,
/// megabytes written by the assembly earlier in the frame, and its first read of each was a
/// wait on memory (a third of the rasterizer's time on the bunny); asked for
/// [`PREFETCH_AHEAD`] triangles ahead, they arrive while the ones before are drawn. It changes
/// no value.
#[inline]
fn prefetch(tri: &RasterTriangle) {
    use prefetch_index::prefetch_index;
    use std::slice::from_ref;
    prefetch_index(from_ref(&tri.edges), 0);
    prefetch_index(from_ref(&tri.bbox), 0);
    prefetch_index(from_ref(&tri.window), 0);
    prefetch_index(from_ref(&tri.top_left), 0);
}

/// Boxes at least this many pixels wide are scanned only over each row's span.
const SPAN_MIN_WIDTH: u32 = 16;

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

impl<'a> Band<'a> {
    /// Rasterizes `tri` over this band's rows. The edge functions are evaluated once per row at
    /// the first pixel's samples and then stepped by `a·ONE` per pixel (they are linear in x);
    /// depth is the triangle's plane ([`RasterTriangle::depth_plane`]).
    fn rasterize(&mut self, tri: &RasterTriangle, index: u32, test: DepthTest) -> RasterCounts {
        // One sample: its three edge values stay in registers. More: each group of four
        // samples is tested at once, in integer lanes.
        match self.offsets.len() {
            1 => self.rasterize_one(tri, index, test),
            4 => self.rasterize_lanes::<1>(tri, index, test),
            8 => self.rasterize_lanes::<2>(tri, index, test),
            _ => self.rasterize_lanes::<4>(tri, index, test),
        }
    }

    /// The band's rows and sample positions, apart from its buffers.
    fn geometry(&self) -> BandRows<'a> {
        BandRows {
            height: self.height,
            first_row: self.first_row,
            rows: self.rows,
            offsets: self.offsets,
        }
    }

    /// [`Self::rasterize`] with one sample a pixel.
    fn rasterize_one(&mut self, tri: &RasterTriangle, index: u32, test: DepthTest) -> RasterCounts {
        let mut counts = RasterCounts::default();
        // The plane is worked out at the first covered sample: of a million triangles most
        // are smaller than a pixel and cover none.
        let mut plane = None;
        let step = tri.edges.map(|e| i64::from(e.a) * ONE);
        let band = self.geometry();
        let (depth, owner, width) = (&mut *self.depth, &mut *self.owner, self.width);
        let centre = self.offsets[0];
        band.each::<1>(tri, self.scanned, |row, y, (xs, xe), &[mut e]| {
            for x in xs..=xe {
                if (e[0] | e[1] | e[2]) >= 0 {
                    let z = plane
                        .get_or_insert_with(|| tri.depth_plane())
                        .at(I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE) + centre);
                    let i = row * width + x as usize;
                    depth_test((&mut depth[i], &mut owner[i]), z, index, test, &mut counts);
                }
                e[0] += step[0];
                e[1] += step[1];
                e[2] += step[2];
            }
        });
        counts
    }

    /// [`Self::rasterize`] with `4·G` samples a pixel: the edge values of each group of four
    /// samples in lanes, `E₀ | E₁ | E₂` giving in its four sign bits the samples outside, so
    /// that a pixel whose samples are all outside costs a few instructions a group.
    fn rasterize_lanes<const G: usize>(
        &mut self,
        tri: &RasterTriangle,
        index: u32,
        test: DepthTest,
    ) -> RasterCounts {
        let mut counts = RasterCounts::default();
        let mut plane = None;
        let step = tri.edges.map(|e| i64x4::splat(i64::from(e.a) * ONE));
        let band = self.geometry();
        let (depth, owner, width) = (&mut *self.depth, &mut *self.owner, self.width);
        let offsets = self.offsets;
        // How far each sample's edge values lie from sample 0's, `E_k(p_s) − E_k(p_0) =
        // a_k·(x_s − x_0) + b_k·(y_s − y_0)` (exact, in integers), in lanes, once for the
        // triangle: a row's lanes are then sample 0's values added to them, rather than loaded
        // back from the row's per-sample values (a store-forwarding stall a row).
        let apart: [[i64x4; 3]; G] = std::array::from_fn(|g| {
            std::array::from_fn(|k| {
                let (a, b) = (i64::from(tri.edges[k].a), i64::from(tri.edges[k].b));
                i64x4::new(std::array::from_fn(|l| {
                    let d = offsets[4 * g + l] - offsets[0];
                    a * d.x + b * d.y
                }))
            })
        });
        let mut scan = |row: usize, y: u32, (xs, xe): (u32, u32), e: &[[i64; 3]]| {
            // Edge k of samples 4g..4g+4 in lanes.
            let mut lanes: [[i64x4; 3]; G] = std::array::from_fn(|g| {
                std::array::from_fn(|k| i64x4::splat(e[0][k]) + apart[g][k])
            });
            debug_assert!(
                (0..4 * G).all(|s| (0..3).all(|k| lanes[s / 4][k].as_array()[s % 4] == e[s][k]))
            );
            for x in xs..=xe {
                let base = (row * width + x as usize) * 4 * G;
                for (g, l) in lanes.iter_mut().enumerate() {
                    let mut inside = !(l[0] | l[1] | l[2]).to_bitmask() & 0b1111;
                    while inside != 0 {
                        let s = 4 * g + inside.trailing_zeros() as usize;
                        inside &= inside - 1;
                        let z = plane
                            .get_or_insert_with(|| tri.depth_plane())
                            .at(I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE) + offsets[s]);
                        let i = base + s;
                        depth_test((&mut depth[i], &mut owner[i]), z, index, test, &mut counts);
                    }
                    for k in 0..3 {
                        l[k] += step[k];
                    }
                }
            }
        };
        match G {
            1 => band.each::<4>(tri, self.scanned, |r, y, span, e| scan(r, y, span, e)),
            2 => band.each::<8>(tri, self.scanned, |r, y, span, e| scan(r, y, span, e)),
            _ => band.each::<16>(tri, self.scanned, |r, y, span, e| scan(r, y, span, e)),
        }
        counts
    }
}
