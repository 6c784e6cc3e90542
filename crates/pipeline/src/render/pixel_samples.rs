//! A pixel's samples: which are covered, which raster triangle owns the pixel, and its mean
//! depth — what multisampling resolves of a pixel before (and apart from) its colour.

use super::resolve::ResolveContext;
use crate::raster::NONE;

impl ResolveContext<'_> {
    /// How many consecutive pixels from image index `i` on (at most `room`, which ends at or
    /// before the row's end) have no sample covered: the background. Pixels of the row that
    /// the rasterizer did not scan ([`SampleRows::scanned`](crate::raster::SampleRows::scanned))
    /// are not looked at: they are background.
    pub(super) fn background_run(&self, i: usize, room: usize) -> usize {
        let w = self.settings.width as usize;
        let (row, x) = (i / w, i % w);
        let (lo, hi) = self
            .samples
            .scanned(row)
            .map_or((0, w), |(lo, hi)| (lo as usize, hi as usize));
        // The scanned pixels from x on, `from..end`; before `from` and from `end` on, the
        // background.
        let end = hi.min(x + room);
        let from = lo.max(x).min(end);
        let n = self.scan_background(row * w + from, end - from);
        if from + n == end { room } else { from - x + n }
    }

    /// [`Self::background_run`] looking at every pixel's samples.
    fn scan_background(&self, i: usize, room: usize) -> usize {
        let s = self.settings.samples.count();
        let tris = self.samples.triangles(i * s..(i + room) * s);
        if tris.first().is_some_and(|&t| t != NONE) {
            return 0;
        }
        // Whole blocks first, each tested without a branch a sample (the compiler's lanes),
        // then the sample that ends the span within its block.
        const BLOCK: usize = 16;
        let empty_blocks = tris
            .chunks_exact(BLOCK)
            .take_while(|b| b.iter().fold(0, |any, &t| any | (t ^ NONE)) == 0)
            .count();
        let from = empty_blocks * BLOCK;
        tris[from..]
            .iter()
            .position(|&t| t != NONE)
            .map_or(room, |k| (from + k) / s)
    }

    /// The raster triangle that owns a pixel whose samples lie on raster triangles `tris`
    /// (at least one covered): of the primitive with the most samples, ties to the earliest
    /// sample, the triangle of that primitive's first sample.
    pub(super) fn owner_of(&self, tris: &[u32]) -> u32 {
        // Each sample's primitive is looked up once (at most 16 samples a pixel).
        let mut prims = [NONE; 16];
        for (p, &t) in prims.iter_mut().zip(tris).filter(|(_, t)| **t != NONE) {
            *p = self.triangles[t as usize].primitive;
        }
        let prims = &prims[..tris.len()];
        let mut best = (0usize, NONE);
        for (&t, &prim) in tris.iter().zip(prims).filter(|(t, _)| **t != NONE) {
            let count = prims.iter().filter(|&&p| p == prim).count();
            if count > best.0 {
                best = (count, t);
            }
        }
        best.1
    }

    /// The mean of image pixel `i`'s sample depths.
    pub(super) fn mean_depth(&self, i: usize) -> f32 {
        let s = self.settings.samples.count();
        mean(self.samples.depths(i * s..(i + 1) * s))
    }

    /// The mean depth of a pixel no triangle covers: [`Self::mean_depth`] of its samples, each
    /// still the depth the buffers were cleared to.
    pub(super) fn background_depth(&self) -> f32 {
        let cleared = [self.settings.depth_test.clear_value(); 16];
        mean(&cleared[..self.settings.samples.count()])
    }
}

/// `(d₀ + d₁ + … + d_{s−1})/s`, summed in order.
fn mean(depths: &[f32]) -> f32 {
    depths.iter().sum::<f32>() / depths.len() as f32
}

#[cfg(test)]
mod tests {
    use crate::raster::{NONE, Samples};
    use crate::render::fixtures::scene;
    use crate::settings::RenderSettings;

    /// The spans a frame's resolve hands its sample buffers are exactly where its samples are
    /// covered: every row's from its first pixel with a covered sample to just past its last.
    #[test]
    fn the_resolve_says_exactly_which_pixels_of_each_row_are_covered() {
        let mut ball = scene();
        ball.objects.retain(|o| o.name == "ball");
        for samples in [Samples::X1, Samples::X4] {
            let settings = RenderSettings {
                width: 48,
                height: 32,
                samples,
                ..RenderSettings::default()
            };
            let frame = crate::render::render(&ball, &settings).expect("renders");
            let buffers = &frame.samples;
            let spans = &buffers.covered.0.as_ref().expect("the resolve says").spans;
            let (w, s) = (48u32, samples.count());
            let mut inside = 0;
            for (row, &span) in spans.iter().enumerate() {
                let covered: Vec<u32> = (0..w)
                    .filter(|&x| {
                        let i = (row * w as usize + x as usize) * s;
                        buffers.triangle[i..i + s].iter().any(|&t| t != NONE)
                    })
                    .collect();
                let exact = match (covered.first(), covered.last()) {
                    (Some(&first), Some(&last)) => (first, last + 1),
                    _ => (0, 0),
                };
                assert_eq!(span, exact, "row {row}, {s} samples");
                inside += usize::from(span.0 > 0 && span.1 < w);
            }
            assert!(inside > 4, "the ball leaves some rows' ends uncovered");
            assert!(spans.contains(&(0, 0)), "and some rows entirely");
        }
    }
}
