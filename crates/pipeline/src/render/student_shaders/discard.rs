//! `discard` and the depth test. OpenGL writes a fragment's depth only when it survives its
//! fragment shader, so behind a discarded fragment the next surface shows. pipelens tests depth
//! before shading (early z); for a shader that can discard, the fragments it discards are then
//! taken out of the depth test and the pixels they covered rasterized again, until no visible
//! fragment is discarded: one layer a round, as depth peeling does.

use std::collections::HashSet;

use glam::I64Vec2;

use super::Frame;
use super::fragment::fragment_shaders;
use crate::capture::VertexResults;
use crate::raster::{NONE, ONE, RasterTriangle, SampleBuffers};
use crate::render::RenderError;
use crate::render::resolve::ResolveContext;

/// The most layers peeled: a pixel behind more discarded surfaces than this shows the
/// background where the next one would be.
const LAYERS: usize = 16;

/// Whether some object's fragment shader has a `discard`.
fn may_discard(frame: &Frame<'_>) -> bool {
    frame.scene.objects.iter().any(|o| {
        o.code
            .shader
            .as_ref()
            .is_some_and(|s| s.programs.fragment.can_discard())
    })
}

/// What peeling took out: how many fragments were discarded, and the runs of those at the
/// inspected pixel (front first), each ending at the `discard` that took it out.
#[derive(Default)]
pub(in crate::render) struct Peeled {
    /// Fragments discarded.
    pub(in crate::render) fragments: u64,
    /// The inspected pixel's discarded fragments' runs, in the order they were peeled.
    pub(in crate::render) traces: Vec<crate::capture::FragmentTrace>,
}

/// Takes every fragment the shaders discard out of `samples`, rasterizing the pixels they
/// covered again without them. Returns how many fragments were discarded, with the runs of
/// those at the inspected pixel.
///
/// # Errors
/// A run-time error of a fragment shader.
pub(in crate::render) fn peel_discarded(
    frame: &Frame<'_>,
    results: &[Option<VertexResults>],
    samples: &mut SampleBuffers,
) -> Result<Peeled, RenderError> {
    if !may_discard(frame) {
        return Ok(Peeled::default());
    }
    let mut traces = Vec::new();
    let settings = frame.settings;
    let n = settings.width as usize * settings.height as usize;
    let mut discarded: HashSet<(u32, u32)> = HashSet::new();
    let mut scratch = vec![[0.0; 3]; n];
    for _ in 0..LAYERS {
        let ctx = ResolveContext {
            path: crate::render::Path::Fast,
            derivatives: true,
            scene: frame.scene,
            settings,
            samples: samples.rows(),
            triangles: frame.triangles,
            primitives: frame.primitives,
            vertices: frame.vertices,
            vertex_shading: frame.vertex_shading,
            face_shading: frame.face_shading,
        };
        let counts = fragment_shaders(&ctx, frame.matrices, results, &mut scratch)?;
        // The inspected pixel's fragments this layer discarded (no output): the final frame
        // no longer has them, so their runs are kept from here.
        traces.extend(counts.pixel.into_iter().filter(|t| t.output.is_none()));
        let fresh: Vec<(u32, u32)> = counts
            .discards
            .into_iter()
            .filter(|d| discarded.insert(*d))
            .collect();
        if fresh.is_empty() {
            break;
        }
        let mut again = vec![false; n];
        for &(_, pixel) in &fresh {
            again[pixel as usize] = true;
        }
        rasterize_again(samples, frame.triangles, &again, &discarded, settings);
    }
    Ok(Peeled {
        fragments: discarded.len() as u64,
        traces,
    })
}

/// Clears the pixels marked in `again` and rasterizes them again, in draw order, leaving out
/// each discarded fragment (raster triangle, pixel).
fn rasterize_again(
    samples: &mut SampleBuffers,
    triangles: &[RasterTriangle],
    again: &[bool],
    discarded: &HashSet<(u32, u32)>,
    settings: &crate::settings::RenderSettings,
) {
    let (w, h) = (settings.width as usize, settings.height as usize);
    let s = settings.samples.count();
    let clear = settings.depth_test.clear_value();
    for (i, _) in again.iter().enumerate().filter(|(_, a)| **a) {
        samples.depth[i * s..(i + 1) * s].fill(clear);
        samples.triangle[i * s..(i + 1) * s].fill(NONE);
    }
    let offsets: Vec<I64Vec2> = (0..s).map(|k| samples.offset(k)).collect();
    let grid = crate::grid::Grid::new(w as u32, h as u32);
    for (index, tri) in triangles.iter().enumerate() {
        let [x0, y0, x1, y1] = tri.bbox.map(usize::from);
        let plane = tri.depth_plane();
        for y in y0..=y1.min(h - 1) {
            for x in x0..=x1.min(w - 1) {
                let i = grid.index(x as u32, y as u32);
                if !again[i] || discarded.contains(&(index as u32, i as u32)) {
                    continue;
                }
                let corner = I64Vec2::new(x as i64 * ONE, y as i64 * ONE);
                for (k, offset) in offsets.iter().enumerate() {
                    let p = corner + *offset;
                    if !tri.covers(p) {
                        continue;
                    }
                    let z = plane.at(p);
                    let at = i * s + k;
                    if settings.depth_test.passes(z, samples.depth[at]) {
                        samples.depth[at] = z;
                        samples.triangle[at] = index as u32;
                    }
                }
            }
        }
    }
}
