//! Clearing the sample buffers for a frame: every sample to the depth the test starts from
//! (the far end for `<`, the near end for `>`) and to no triangle. Reused storage is cleared
//! only where the frame before covered samples, when its resolve said where that was: outside
//! those spans every sample still holds what a clear gives it (every writer of a sample's depth
//! writes its triangle too, and the resolve finds the samples with a triangle).

use rayon::prelude::*;

use super::bins::Bins;
use super::covered::Covered;
use super::zbuffer::SampleBuffers;
use super::{NONE, Samples, sample_offsets_fixed};

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
            bins: Bins::default(),
            covered: Covered::default(),
        }
    }

    /// These buffers' storage, resized and cleared as [`Self::new`] makes them. Where the
    /// frame before (of the same size, samples and cleared depth) said which spans of its rows
    /// it covered, only those are cleared: a lit model often fills a third of the frame, and a
    /// clear is a memory-bound pass over tens of megabytes (30 MB at 1280×720, 4 samples).
    #[must_use]
    pub fn cleared(mut self, width: u32, height: u32, samples: Samples, clear_depth: f32) -> Self {
        let same = self.width == width && self.height == height && self.samples == samples;
        let known = self.covered.0.take().filter(|c| {
            same && c.clear.to_bits() == clear_depth.to_bits() && c.spans.len() == height as usize
        });
        let s = samples.count();
        let n = width as usize * height as usize * s;
        match known {
            Some(covered) => {
                let row = width as usize * s;
                self.depth
                    .par_chunks_mut(row)
                    .zip(self.triangle.par_chunks_mut(row))
                    .zip(&covered.spans)
                    .for_each(|((d, t), &(first, end))| {
                        if first < end {
                            let span = first as usize * s..end as usize * s;
                            d[span.clone()].fill(clear_depth);
                            t[span].fill(NONE);
                        }
                    });
            }
            None => {
                // Grown or shrunk, then cleared in parallel chunks.
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
            }
        }
        debug_assert!(
            self.triangle.iter().all(|&t| t == NONE)
                && self
                    .depth
                    .iter()
                    .all(|d| d.to_bits() == clear_depth.to_bits()),
            "a sample outside the spans the frame before covered was not cleared"
        );
        Self {
            width,
            height,
            samples,
            offsets: sample_offsets_fixed(samples),
            ..self
        }
    }
}
