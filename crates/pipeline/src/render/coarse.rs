//! Coarse shading, the draft a slider drag shows: each 2×2 block of pixels is shaded once per
//! raster triangle, at the centre of the first of its pixels (row by row, left to right) that
//! the triangle covers, and its other pixels on that triangle take that result.
//! [`ResolveContext::pixel`] does it pixel by pixel with the block's shading so far; a run of
//! pixels at one sample has here the fragments it must shade lit together in lanes
//! ([`ResolveContext::shade_run`]), with the same result bit for bit (the test compares the
//! two). A run spans up to sixteen pixels: in a row pair's first row about every other pixel is
//! shaded, so sixteen pixels fill the eight lanes.

use super::resolve::{BlockShade, ResolveContext, ResolvedPixel, Shaded};
use super::runs::{Run, RunShading};
use crate::lighting::lanes::LANES;

/// Where a pixel of a coarse run takes its shading from.
#[derive(Clone, Copy)]
enum Source {
    /// Its block's, shaded before the run.
    Block,
    /// A fragment shaded in the run.
    Fragment(usize),
}

impl ResolveContext<'_> {
    /// Resolves consecutive pixels from window `(x, y)` (image index `i`) on, at one sample
    /// a pixel, pixel `k` covered by raster triangle `span[k]` (all of one object, see
    /// [`Self::span_at_one_sample`]), with coarse shading, as [`Self::pixel`] resolves each
    /// with its block from `blocks` (block `x / 2` of the row pair); hands pixel `k` to
    /// `out(k, pixel)` (its terms and texture lookup only when the capture keeps them) and
    /// fills in the blocks it shades first. Returns how many pixels it resolved: all of
    /// `span`, or fewer when they need more than [`LANES`] fragments shaded.
    pub(super) fn resolve_coarse_run(
        &self,
        span: &[u32],
        (x, y): (u32, u32),
        i: usize,
        blocks: &mut [Option<BlockShade>],
        mut out: impl FnMut(usize, &ResolvedPixel),
    ) -> usize {
        let mut from = [Source::Fragment(0); 2 * LANES];
        let mut shade = Run::empty();
        // The blocks, empty before the run, whose shading is a fragment of it:
        // (block, triangle, fragment).
        let mut fills = [(usize::MAX, 0u32, 0usize); LANES];
        let mut filled = 0;
        let mut pixels = span.len().min(2 * LANES);
        for (k, from) in from.iter_mut().enumerate().take(pixels) {
            let (t, b) = (span[k], (x as usize + k) / 2);
            // The inspected pixel is shaded by itself (its explanation derives its colour
            // from its own records) and leaves its block alone.
            let inspected = self.settings.capture.pixel == Some((x + k as u32, y));
            let fill = fills[..filled].iter().find(|f| f.0 == b);
            if !inspected {
                match (blocks[b], fill) {
                    (Some(block), _) if block.triangle == t => {
                        *from = Source::Block;
                        continue;
                    }
                    (None, Some(&(_, ft, f))) if ft == t => {
                        *from = Source::Fragment(f);
                        continue;
                    }
                    _ => {}
                }
            }
            if shade.len == LANES {
                pixels = k;
                break;
            }
            let f = shade.push_fragment(t, k);
            *from = Source::Fragment(f);
            if !inspected && blocks[b].is_none() && fill.is_none() {
                fills[filled] = (b, t, f);
                filled += 1;
            }
        }
        let shaded = (shade.len > 0).then(|| {
            let mut shaded = RunShading::EMPTY;
            self.shade_run(&shade, (x, y), &mut shaded);
            shaded
        });
        let fragment = |f: usize| -> Shaded {
            shaded
                .as_ref()
                .map_or_else(Shaded::default, |s| (s.color[f], s.terms[f], s.texels[f]))
        };
        for &(b, triangle, f) in &fills[..filled] {
            blocks[b] = Some(BlockShade {
                triangle,
                shaded: fragment(f),
            });
        }
        // The pixel is built once and its fields set for each. A colour-only frame keeps no
        // terms: left empty, they cost nothing to hand over (two thirds of a pixel's bytes).
        let keeps = self.settings.capture.lighting || self.settings.capture.texturing;
        let mut pixel = ResolvedPixel {
            coverage: 1,
            ..ResolvedPixel::default()
        };
        for (k, from) in from.iter().enumerate().take(pixels) {
            let (color, terms, texture) = match (*from, &blocks[(x as usize + k) / 2], &shaded) {
                (Source::Block, Some(b), _) if keeps => b.shaded,
                (Source::Block, Some(b), _) => (b.shaded.0, None, None),
                (Source::Fragment(f), _, Some(s)) if keeps => (s.color[f], s.terms[f], s.texels[f]),
                (Source::Fragment(f), _, Some(s)) => (s.color[f], None, None),
                _ => Shaded::default(),
            };
            let owner = span[k];
            if keeps {
                (pixel.terms, pixel.texture) = (terms, texture);
            }
            if owner != pixel.owner || k == 0 {
                pixel.primitive = self.triangles[owner as usize].primitive;
            }
            pixel.owner = owner;
            pixel.depth = self.mean_depth(i + k);
            pixel.color = color.to_array();
            out(k, &pixel);
        }
        pixels
    }
}

#[cfg(test)]
mod tests {
    use crate::buffers::Capture;
    use crate::lighting::{Frequency, Reflection};
    use crate::raster::Samples;
    use crate::render::fixtures::{assert_kept, context, scene};
    use crate::settings::RenderSettings;

    /// Every pixel of coarse frames at one sample, resolved with runs, equals what the
    /// per-pixel path gives it with its 2×2 block's shading so far, row pair by row pair:
    /// colour, depth, owner, primitive and the kept terms, also with a pixel inspected (which
    /// is shaded by itself). The frames differ from full-rate ones: the blocks are shared.
    #[test]
    fn coarse_runs_resolve_as_the_per_pixel_blocks_do() {
        let scene = scene();
        let (w, h) = (161usize, 97usize);
        let mut shared = 0;
        for (k, (shading, reflection)) in [
            (Frequency::Phong, Reflection::BlinnPhong),
            (Frequency::Phong, Reflection::Phong),
            (Frequency::Gouraud, Reflection::BlinnPhong),
            (Frequency::Flat, Reflection::Phong),
            (Frequency::Unlit, Reflection::BlinnPhong),
        ]
        .into_iter()
        .enumerate()
        {
            let mut settings = RenderSettings {
                width: w as u32,
                height: h as u32,
                samples: Samples::X1,
                shading,
                reflection,
                coarse_shading: true,
                capture: if k % 2 == 0 {
                    Capture::FULL
                } else {
                    Capture::COLOR.with_pixel(Some((81, 5)))
                },
                ..RenderSettings::default()
            };
            settings.sampler.mipmap = crate::texture::Mipmap::Linear;
            let frame = crate::render::render(&scene, &settings).expect("renders");
            let full = crate::render::render(
                &scene,
                &RenderSettings {
                    coarse_shading: false,
                    ..settings
                },
            )
            .expect("renders");
            let ctx = context(&frame, &scene, &settings);
            for pair in (0..h).step_by(2) {
                let mut blocks = vec![None; w.div_ceil(2)];
                for row in pair..(pair + 2).min(h) {
                    let y = crate::grid::Grid::new(w as u32, h as u32).row(row as u32);
                    for x in 0..w {
                        let i = row * w + x;
                        let block = (settings.capture.pixel != Some((x as u32, y)))
                            .then(|| &mut blocks[x / 2]);
                        let want = ctx.pixel(x as u32, y, i, block);
                        assert_kept(
                            &frame.pixels,
                            i,
                            &want,
                            &settings,
                            &format!("{k} ({x}, {y})"),
                        );
                        shared += usize::from(full.pixels.color[i] != want.color);
                    }
                }
            }
        }
        assert!(
            shared > 5_000,
            "only {shared} pixels differ from full-rate shading"
        );
    }
}
