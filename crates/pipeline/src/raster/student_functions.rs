//! Rasterization with the student's functions (see [`crate::shader::hook`]): the samples a
//! triangle covers gathered first, each with its depth, so that a depth test the student wrote
//! can be asked about all of them at once, then the triangle written where it said so. Within
//! one triangle every sample is distinct, so the result is that of testing them one by one.

use glam::I64Vec2;

use super::RasterTriangle;
use super::bins::RasterCounts;
use super::zbuffer::SampleBuffers;

impl SampleBuffers {
    /// The samples of `tri`'s bounding box that `covers(k, p)` says are covered (`k` the
    /// sample's place in [`Self::box_samples`]' order, `p` its fixed-point position): each as
    /// its index in the buffers and the triangle's depth there.
    pub fn covered_samples(
        &self,
        tri: &RasterTriangle,
        mut covers: impl FnMut(usize, I64Vec2) -> bool,
    ) -> Vec<(usize, f32)> {
        let plane = tri.depth_plane();
        self.box_sample_indices(tri)
            .enumerate()
            .filter(|(k, (_, p))| covers(*k, *p))
            .map(|(_, (i, p))| (i, plane.at(p)))
            .collect()
    }

    /// Writes triangle `index` into the `covered` samples (from [`Self::covered_samples`])
    /// where `passes[k]` (another depth test's answer for the `k`-th); counts them as
    /// [`Self::rasterize_all`] does.
    pub fn write_samples(
        &mut self,
        covered: &[(usize, f32)],
        passes: &[bool],
        index: u32,
    ) -> RasterCounts {
        let mut counts = RasterCounts::default();
        for (&(i, z), &pass) in covered.iter().zip(passes) {
            counts.covered += 1;
            if pass {
                self.depth[i] = z;
                self.triangle[i] = index;
                counts.written += 1;
            }
        }
        counts
    }
}
