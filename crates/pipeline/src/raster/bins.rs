//! The binning of the banded rasterizer: each triangle listed for the bands of rows its
//! bounding box reaches, in order; what a triangle drew (`RasterCounts`), summed over the bands.

use glam::I64Vec2;
use serde::Serialize;

use super::RasterTriangle;

/// The working lists of [`super::SampleBuffers::rasterize_all`], kept with the buffers so that
/// a frame drawn into the storage of the one before takes no memory from the system for them
/// (a million triangles fill some 20 MB of lists a frame). Scratch, not content: a clone starts empty and
/// any two compare equal.
#[derive(Default)]
pub(super) struct Bins {
    /// `runs[r][b]`: the triangles of run `r` whose bounding box reaches band `b`, in order.
    pub(super) runs: Vec<Vec<Vec<u32>>>,
    /// `counts[b]`: what each triangle band `b` drew did there, in the order of its lists.
    pub(super) counts: Vec<Vec<RasterCounts>>,
    /// What each triangle did over all bands.
    pub(super) total: Vec<RasterCounts>,
    /// `scanned[r]`: the pixels `lo..hi` of image row `r` the last banded rasterization scanned
    /// (see [`super::SampleRows::scanned`]).
    pub(super) scanned: Vec<(u32, u32)>,
}

impl Clone for Bins {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PartialEq for Bins {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for Bins {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Bins")
    }
}

/// Triangles are binned in runs of this many, each run in parallel.
const RUN: usize = 1 << 16;

impl Bins {
    /// Binning, in parallel over runs of triangles: each band of `rows_per` image rows (of an
    /// image `size` pixels) gets the triangles whose bounding box reaches its rows, run after
    /// run, so in order. A triangle whose box holds no sample position covers none and is left
    /// out (its counts stay zero).
    pub(super) fn bin(
        &mut self,
        tris: &[RasterTriangle],
        offsets: &[I64Vec2],
        (width, height): (u32, u32),
        rows_per: usize,
    ) {
        use rayon::prelude::*;
        let bands = (height as usize).div_ceil(rows_per).max(1);
        let grid = crate::grid::Grid::new(width, height);
        let runs = &mut self.runs;
        runs.resize_with(tris.len().div_ceil(RUN), Vec::new);
        runs.par_iter_mut()
            .zip(tris.par_chunks(RUN))
            .enumerate()
            .for_each(|(r, (bins, run))| {
                bins.resize_with(bands, Vec::new);
                bins.iter_mut().for_each(Vec::clear);
                for (k, t) in run.iter().enumerate() {
                    if !t.box_holds_a_sample(offsets) {
                        continue;
                    }
                    let [_, y0, _, y1] = t.bbox;
                    // Image rows of the box: from window row y1's (top) to y0's (bottom).
                    let (r0, r1) = (
                        grid.row(u32::from(y1)) as usize,
                        grid.row(u32::from(y0)) as usize,
                    );
                    for bin in &mut bins[r0 / rows_per..=r1 / rows_per] {
                        bin.push((r * RUN + k) as u32);
                    }
                }
            });
    }

    /// What each of the `triangles` did over all bands: each run's triangles summed over the
    /// bands' counts, in parallel over runs (run `r`'s entries in band `b`'s counts follow
    /// those of the runs before it).
    pub(super) fn total(&mut self, triangles: usize) -> &[RasterCounts] {
        use rayon::prelude::*;
        let Self {
            runs,
            counts,
            total,
            ..
        } = self;
        let bands = counts.len();
        let counts = &*counts;
        let mut firsts: Vec<Vec<usize>> = Vec::with_capacity(runs.len());
        let mut at = vec![0usize; bands];
        for bins in runs.iter() {
            firsts.push(at.clone());
            for (a, bin) in at.iter_mut().zip(bins) {
                *a += bin.len();
            }
        }
        total.clear();
        total.resize(triangles, RasterCounts::default());
        total
            .par_chunks_mut(RUN)
            .zip(runs.par_iter().zip(firsts))
            .enumerate()
            .for_each(|(r, (total, (bins, firsts)))| {
                for ((bin, first), counts) in bins.iter().zip(firsts).zip(counts) {
                    for (&i, c) in bin.iter().zip(&counts[first..]) {
                        let t = &mut total[i as usize - r * RUN];
                        t.covered += c.covered;
                        t.written += c.written;
                    }
                }
            });
        total
    }
}

/// What rasterizing one triangle did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct RasterCounts {
    /// Samples inside the triangle.
    pub covered: u32,
    /// Samples that passed the depth test and were written.
    pub written: u32,
}
