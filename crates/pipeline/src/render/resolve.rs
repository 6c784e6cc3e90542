//! The resolve: samples to pixels. Each pixel's coverage, mean depth and owning triangle; its
//! colour, shaded once per pixel and triangle at the centre (multisampling) or at every sample
//! (supersampling); and the owning fragment's lighting terms and texture lookup, written into
//! the kept buffers a row at a time, rows in parallel.

mod fragment;

use std::time::Duration;

use glam::{Vec2, Vec3};
use rayon::prelude::*;
use web_time::Instant;

use crate::capture::{
    InspectedPixel, PixelBuffers, PixelTexture, PrimitiveRecord, ShadingRow, TextureRow,
};
use crate::lighting::lanes::LANES;
use crate::lighting::{Frequency, ShadeTerms};
use crate::raster::{CoveredRows, NONE, RasterTriangle, SampleBuffers, SampleRows};
use crate::scene::Scene;
use crate::settings::RenderSettings;
use crate::texture::Lookup;
use crate::vertex::VertexRecord;

/// Everything the resolve computes for one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct ResolvedPixel {
    pub(super) terms: Option<ShadeTerms>,
    pub(super) texture: Option<(Vec2, Lookup)>,
    pub(super) coverage: u8,
    pub(super) depth: f32,
    pub(super) primitive: u32,
    pub(super) owner: u32,
    pub(super) color: [f32; 3],
}

/// One image row of every per-pixel buffer, written by one resolve task.
struct RowOut<'a> {
    /// This frame's background colour and depth, and whether a pixel the storage's frame left
    /// uncovered holds them already ([`PixelBuffers::background`]).
    background: (([f32; 3], f32), bool),
    /// The row's pixels with a covered sample lie in `first..end` (none when `first ≥ end`).
    covered: (u32, u32),
    coverage: &'a mut [u8],
    depth: &'a mut [f32],
    primitive: &'a mut [u32],
    owner: &'a mut [u32],
    color: &'a mut [[f32; 3]],
    shading: Option<ShadingRow<'a>>,
    texturing: Option<TextureRow<'a>>,
}

/// A resolve task's reused storage: with coarse shading, the shading of each 2×2 block of the
/// row pair being resolved.
#[derive(Default)]
struct RowScratch {
    blocks: Vec<Option<BlockShade>>,
}

/// What coarse shading reuses across a 2×2 block: the raster triangle shaded and the result.
#[derive(Clone, Copy)]
pub(super) struct BlockShade {
    pub(super) triangle: u32,
    pub(super) shaded: Shaded,
}

/// The result of shading a point: colour, lighting terms, texture lookup.
pub(super) type Shaded = (Vec3, Option<ShadeTerms>, Option<(Vec2, Lookup)>);

/// A pixel's lighting terms and texture lookup, where the frame keeps them.
pub(super) type Kept<'a> = (Option<&'a ShadeTerms>, Option<&'a (Vec2, Lookup)>);

impl RowOut<'_> {
    /// Resolves image row `row` (window `y`) into every kept buffer, so that reused storage
    /// holds nothing of the frame before.
    fn resolve(&mut self, ctx: &ResolveContext<'_>, row: usize, y: u32, s: &mut RowScratch) {
        let w = self.color.len();
        let (coarse, per_sample) = (ctx.settings.coarse_shading, ctx.settings.per_sample_shading);
        // Runs of pixels, each covered by triangles of one object, are shaded together, unless
        // every sample is shaded by itself. With coarse shading, at one sample, a run of up to
        // sixteen pixels shades together what its 2×2 blocks do not share (see `coarse`).
        let fast = ctx.path == super::Path::Fast;
        let runs = fast && !per_sample && !coarse;
        let coarse_runs = fast && !per_sample && coarse && ctx.settings.samples.count() == 1;
        let mut blocks = std::mem::take(&mut s.blocks);
        // The first covered pixel, and the last background span.
        let (mut first, mut last_background) = (None, None);
        let mut x = 0;
        while x < w {
            let i = row * w + x;
            // The background (most of a frame) is written without resolving pixel by pixel.
            let empty = if fast {
                ctx.background_run(i, w - x)
            } else {
                0
            };
            if empty > 0 {
                self.store_background(ctx, x, i, empty);
                last_background = Some((x, x + empty));
                x += empty;
                continue;
            }
            first.get_or_insert(x);
            // Shorter runs (a few pixels between a silhouette and a pixel with an uncovered
            // sample) cost more in lanes than they save: their pixels take the per-pixel path,
            // without looking again.
            let at = (x as u32, y);
            let len = if coarse_runs {
                let (span, n) = ctx.span_at_one_sample::<{ 2 * LANES }>(i, w - x);
                if n >= 4 {
                    let x0 = x;
                    x += ctx.resolve_coarse_run(&span[..n], at, i, &mut blocks, |k, r| {
                        self.store(x0 + k, r);
                    });
                    continue;
                }
                n.max(1)
            } else {
                let run = runs.then(|| ctx.run_at(i, w - x)).flatten();
                if let Some(run) = run.filter(|r| r.len >= 4) {
                    ctx.resolve_run(&run, at, i, |k, r, kept| {
                        self.store_with(x + k, r, kept);
                    });
                    x += run.pixels;
                    continue;
                }
                run.map_or(1, |r| r.pixels)
            };
            for x in x..x + len {
                let block = if coarse && ctx.settings.capture.pixel != Some((x as u32, y)) {
                    blocks.get_mut(x / 2)
                } else {
                    None
                };
                let r = ctx.pixel(x as u32, y, row * w + x, block);
                self.store(x, &r);
            }
            x += len;
        }
        // Background spans are as long as they go: the covered pixels end where one reaching
        // the row's end begins.
        let end = match last_background {
            Some((from, to)) if to == w => from,
            _ => w,
        };
        self.covered = first.map_or((0, 0), |first| (first as u32, end as u32));
        s.blocks = blocks;
    }

    /// Writes the `n` background pixels from `x` on (image index `i` on): no coverage, no
    /// owner, the background colour, the mean of the cleared sample depths, no terms and no
    /// lookup — what [`ResolveContext::pixel`] gives for each of them.
    fn store_background(&mut self, ctx: &ResolveContext<'_>, x: usize, i: usize, n: usize) {
        let span = x..x + n;
        // Where the frame before (whose storage this is) had the background too, the buffers
        // hold the background's primitive, owner and terms already (see `PixelBuffers`); so
        // they are written only in a span it covered somewhere (an OR over the span, without
        // a branch a pixel: the span is usually all zeros), and its colour and depth buffers
        // also when its background was not this frame's.
        let covered_before = self.coverage[span.clone()]
            .iter()
            .fold(0, |any, &c| any | c)
            != 0;
        if covered_before {
            self.coverage[span.clone()].fill(0);
            self.primitive[span.clone()].fill(NONE);
            self.owner[span.clone()].fill(NONE);
            if let Some(out) = &mut self.shading {
                out.unlit(span.clone());
            }
            if let Some(out) = &mut self.texturing {
                out.none(span.clone());
            }
        }
        // A sample no triangle covers holds the depth it was cleared to (every writer of a
        // sample's depth writes its triangle too), so the span's depths are one value, the mean
        // of that many cleared depths, and the samples need not be read.
        let ((color, depth), kept) = self.background;
        debug_assert!((i..i + n).all(|p| ctx.mean_depth(p).to_bits() == depth.to_bits()));
        if covered_before || !kept {
            self.color[span.clone()].fill(color);
            self.depth[span].fill(depth);
        } else {
            debug_assert!(self.color[span.clone()].iter().all(|c| *c == color));
            debug_assert!(
                self.depth[span]
                    .iter()
                    .all(|d| d.to_bits() == depth.to_bits())
            );
        }
    }

    /// Writes pixel `x`'s resolve into the row's buffers, its terms and lookup where their
    /// buffers are kept.
    #[inline]
    fn store(&mut self, x: usize, r: &ResolvedPixel) {
        self.store_with(x, r, (r.terms.as_ref(), r.texture.as_ref()));
    }

    /// [`Self::store`] with the pixel's terms and lookup given apart, where they are (a run's
    /// shading), rather than in `r`: read where they were written, not copied into `r` first
    /// (a copy that a read of the same bytes right after stalls on).
    #[inline]
    fn store_with(&mut self, x: usize, r: &ResolvedPixel, (terms, texture): Kept<'_>) {
        self.coverage[x] = r.coverage;
        self.depth[x] = r.depth;
        self.primitive[x] = r.primitive;
        self.owner[x] = r.owner;
        self.color[x] = super::stored_color(glam::Vec3::from(r.color)).to_array();
        if let Some(out) = &mut self.shading {
            match terms {
                Some(t) => out.store(x, t),
                None => out.unlit(x..x + 1),
            }
        }
        if let Some(out) = &mut self.texturing {
            match texture {
                Some((uv, l)) => out.store(x, &PixelTexture::new(*uv, l)),
                None => out.none(x..x + 1),
            }
        }
    }
}

/// Every per-pixel buffer cut into image rows, one [`RowOut`] a row, so that rows can be
/// resolved in parallel.
fn split_rows(
    px: &mut PixelBuffers,
    w: usize,
    h: usize,
    background: (([f32; 3], f32), bool),
) -> Vec<RowOut<'_>> {
    let mut texture_rows: Vec<Option<TextureRow<'_>>> = match &mut px.texturing {
        Some(tb) => tb.rows(w).into_iter().map(Some).collect(),
        None => (0..h).map(|_| None).collect(),
    };
    let mut shading_rows: Vec<Option<ShadingRow<'_>>> = match &mut px.shading {
        Some(sb) => sb.rows(w).into_iter().map(Some).collect(),
        None => (0..h).map(|_| None).collect(),
    };
    px.coverage
        .chunks_mut(w)
        .zip(px.depth.chunks_mut(w))
        .zip(px.primitive.chunks_mut(w))
        .zip(px.owner.chunks_mut(w))
        .zip(px.color.chunks_mut(w))
        .zip(shading_rows.drain(..).zip(texture_rows.drain(..)))
        .map(
            |(((((coverage, depth), primitive), owner), color), (shading, texturing))| RowOut {
                background,
                covered: (0, 0),
                coverage,
                depth,
                primitive,
                owner,
                color,
                shading,
                texturing,
            },
        )
        .collect()
}

/// Resolves samples to pixels: coverage, mean depth, the owning primitive and raster
/// triangle, and the colour at the pixel centre (once per pixel and triangle, as multisampling
/// shades), with the lighting terms and texture lookup of the owning fragment when the settings
/// keep them. Rows are independent, so they are resolved in parallel. Also says where the
/// samples are covered, row by row, for the next clear of their buffers.
pub(super) fn resolve(
    ctx: &ResolveContext<'_>,
    spare: PixelBuffers,
) -> (PixelBuffers, CoveredRows) {
    let (w, h) = (ctx.settings.width as usize, ctx.settings.height as usize);
    let (mut px, background) = kept_buffers(ctx, spare);
    let mut rows = split_rows(&mut px, w, h, background);
    let pair = row_pair(ctx.settings);
    rows.par_chunks_mut(pair)
        .enumerate()
        .for_each_init(RowScratch::default, |scratch, (k, outs)| {
            resolve_rows(ctx, outs, k * pair, scratch)
        });
    let covered = covered_rows(ctx.settings, &rows);
    drop(rows);
    px.background = Some(background.0);
    px.inspected = inspected(ctx, &px);
    (px, covered)
}

/// Rasterization with the depth test and the resolve together, band by band
/// ([`SampleBuffers::rasterize_all_then`]): each band of image rows resolves its pixels as
/// soon as it has drawn every triangle over them, on the core that drew them, while its samples
/// are in that core's cache — shading right after coverage, where [`resolve`] waits for the
/// whole image's coverage and then reads every sample again. A pixel's resolve reads its own
/// samples only (and coarse shading a 2×2 block's, so bands are whole row pairs), so the
/// buffers are those of rasterizing everything and then resolving. `ctx`'s samples are not
/// read: each band resolves with its own rows (what each triangle drew is left in
/// [`SampleBuffers::drawn`]). Also gives how long the rasterization and the resolve took: the
/// wall time shared out between them, the resolve's share its time summed over the bands and
/// divided by the cores.
pub(super) fn rasterize_and_resolve(
    ctx: &ResolveContext<'_>,
    samples: &mut SampleBuffers,
    spare: PixelBuffers,
) -> (PixelBuffers, CoveredRows, [Duration; 2]) {
    let (w, h) = (ctx.settings.width as usize, ctx.settings.height as usize);
    let (mut px, background) = kept_buffers(ctx, spare);
    let mut rows = split_rows(&mut px, w, h, background);
    let pair = row_pair(ctx.settings);
    let rows_per = samples.band_rows(pair);
    // Each band: its first row, its rows, how long its resolve took.
    let mut bands: Vec<_> = rows
        .chunks_mut(rows_per)
        .enumerate()
        .map(|(b, outs)| (b * rows_per, outs, Duration::ZERO))
        .collect();
    let start = Instant::now();
    samples.rasterize_all_then(
        ctx.triangles,
        ctx.settings.depth_test,
        rows_per,
        &mut bands,
        |(first, outs, resolving), drawn| {
            let t = Instant::now();
            let band = ResolveContext {
                samples: drawn,
                ..*ctx
            };
            let mut scratch = RowScratch::default();
            for (k, outs) in outs.chunks_mut(pair).enumerate() {
                resolve_rows(&band, outs, *first + k * pair, &mut scratch);
            }
            *resolving = t.elapsed();
        },
    );
    let wall = start.elapsed();
    // The resolve's share of the wall time: its time summed over the bands, over the cores
    // that ran them (each busy from start to end).
    let resolving: Duration = bands.iter().map(|b| b.2).sum();
    let cores = rayon::current_num_threads().clamp(1, bands.len().max(1)) as u32;
    let resolving = (resolving / cores).min(wall);
    drop(bands);
    let covered = covered_rows(ctx.settings, &rows);
    drop(rows);
    px.background = Some(background.0);
    (px, covered, [wall - resolving, resolving])
}

/// The per-pixel buffers the settings keep, in `spare`'s storage, and this frame's background
/// colour and depth with whether the storage holds them already where its frame was not covered.
fn kept_buffers(
    ctx: &ResolveContext<'_>,
    spare: PixelBuffers,
) -> (PixelBuffers, (([f32; 3], f32), bool)) {
    let settings = ctx.settings;
    let (w, h) = (settings.width as usize, settings.height as usize);
    let lit = settings.shading != Frequency::Unlit && settings.capture.lighting;
    let textured = settings.capture.texturing
        && ctx
            .scene
            .objects
            .iter()
            .any(|o| o.texture.is_some() && !o.mesh.uvs.is_empty());
    let px = spare.reused(w * h, lit, textured);
    let background = (settings.background.to_array(), ctx.background_depth());
    let kept = px.background.is_some_and(|b| b == background);
    (px, (background, kept))
}

/// How many image rows are resolved together: coarse shading shares a 2×2 block's shading
/// between two rows, so they are resolved in pairs.
fn row_pair(settings: &RenderSettings) -> usize {
    if settings.coarse_shading { 2 } else { 1 }
}

/// Resolves `outs`, consecutive image rows from `first` on (one row, or a pair with coarse
/// shading).
fn resolve_rows(
    ctx: &ResolveContext<'_>,
    outs: &mut [RowOut<'_>],
    first: usize,
    s: &mut RowScratch,
) {
    let grid = crate::grid::Grid::new(ctx.settings.width, ctx.settings.height);
    if ctx.settings.coarse_shading {
        s.blocks.clear();
        s.blocks
            .resize((ctx.settings.width as usize).div_ceil(2), None);
    }
    for (j, out) in outs.iter_mut().enumerate() {
        let row = first + j;
        out.resolve(ctx, row, grid.row(row as u32), s);
    }
}

/// Where the resolved rows' samples are covered, for the next clear of their buffers.
fn covered_rows(settings: &RenderSettings, rows: &[RowOut<'_>]) -> CoveredRows {
    CoveredRows {
        clear: settings.depth_test.clear_value(),
        spans: rows.iter().map(|r| r.covered).collect(),
    }
}

/// The inspected pixel's terms and lookup, where the frame does not keep their buffers
/// (`ctx` reads every row of the samples).
pub(super) fn inspected(ctx: &ResolveContext<'_>, px: &PixelBuffers) -> Option<InspectedPixel> {
    if px.shading.is_some() && px.texturing.is_some() {
        return None;
    }
    ctx.settings.capture.pixel.and_then(|at| ctx.inspected(at))
}

/// What the resolve of one pixel reads.
#[derive(Clone, Copy)]
pub(super) struct ResolveContext<'a> {
    /// The fast paths, or every pixel by itself ([`super::render_reference`]).
    pub(super) path: super::Path,
    /// Whether texture lookups need their screen derivatives: to choose a mip level or the
    /// anisotropic taps, or because the texturing buffers (λ, level, footprint) are kept.
    pub(super) derivatives: bool,
    pub(super) vertex_shading: &'a [ShadeTerms],
    pub(super) face_shading: &'a [ShadeTerms],
    pub(super) scene: &'a Scene,
    pub(super) settings: &'a RenderSettings,
    pub(super) samples: SampleRows<'a>,
    pub(super) triangles: &'a [RasterTriangle],
    pub(super) primitives: &'a [PrimitiveRecord],
    pub(super) vertices: &'a [VertexRecord],
}

#[cfg(test)]
mod tests {
    use crate::buffers::Capture;
    use crate::lighting::Frequency;
    use crate::raster::Samples;
    use crate::render::fixtures::scene;
    use crate::settings::RenderSettings;

    /// Rasterized and resolved band by band, on pools of 1, 3 and 5 threads (so bands of
    /// different heights, which with coarse shading are whole row pairs), frames of odd and
    /// even heights hold the bits the reference path gives — every sample, every pixel buffer,
    /// every primitive's counts, the inspected pixel — whether the storage they are written
    /// into is fresh or a frame of other settings.
    #[test]
    fn bands_rasterize_and_resolve_as_the_whole_image_does() {
        let scene = scene();
        let mut compared = 0;
        for threads in [1, 3, 5] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a pool");
            pool.install(|| {
                let mut spare = None;
                for (k, (height, samples, coarse, shading)) in [
                    (97, Samples::X1, true, Frequency::Phong),
                    (61, Samples::X4, false, Frequency::Gouraud),
                    (96, Samples::X1, false, Frequency::Phong),
                    (97, Samples::X4, true, Frequency::Flat),
                ]
                .into_iter()
                .enumerate()
                {
                    let settings = RenderSettings {
                        width: 150,
                        height,
                        samples,
                        coarse_shading: coarse,
                        shading,
                        capture: Capture {
                            pixel: Some((40 + k as u32, 50)),
                            ..if k % 2 == 0 {
                                Capture::FULL
                            } else {
                                Capture::COLOR
                            }
                        },
                        ..RenderSettings::default()
                    };
                    let reference =
                        crate::render::render_reference(&scene, &settings).expect("renders");
                    let (fast, _) =
                        crate::render::render_reusing(&scene, &settings, spare).expect("renders");
                    let at = format!("{threads} threads, case {k}");
                    let bits = |c: &[[f32; 3]]| -> Vec<[u32; 3]> {
                        c.iter().map(|c| c.map(f32::to_bits)).collect()
                    };
                    assert_eq!(
                        bits(&fast.pixels.color),
                        bits(&reference.pixels.color),
                        "{at}"
                    );
                    let depth = |d: &[f32]| -> Vec<u32> { d.iter().map(|d| d.to_bits()).collect() };
                    assert_eq!(
                        depth(&fast.pixels.depth),
                        depth(&reference.pixels.depth),
                        "{at}"
                    );
                    assert_eq!(fast.pixels, reference.pixels, "{at}");
                    assert_eq!(fast.samples.triangle, reference.samples.triangle, "{at}");
                    assert_eq!(
                        depth(&fast.samples.depth),
                        depth(&reference.samples.depth),
                        "{at}"
                    );
                    assert_eq!(fast.primitives, reference.primitives, "{at}");
                    assert!(
                        fast.primitives
                            .iter()
                            .map(|p| p.counts.written)
                            .sum::<u32>()
                            > 1000,
                        "{at}: little drawn"
                    );
                    // Where the frame keeps no terms, the inspected pixel's are resolved apart.
                    assert_eq!(fast.pixels.inspected.is_some(), k % 2 == 1, "{at}");
                    compared += 1;
                    spare = Some(fast);
                }
            });
        }
        assert_eq!(compared, 12);
    }
}
