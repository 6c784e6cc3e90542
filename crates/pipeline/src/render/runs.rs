//! Runs: up to eight fragments of consecutive pixels of a row, resolved together. Every
//! sample of the run's pixels is covered, by triangles of one object: the inside of a mesh's
//! surface, across its triangles' shared edges. A fragment is one triangle in one pixel, shaded
//! once at the pixel centre (multisampling): a pixel inside a triangle is one fragment, a pixel
//! on an edge between two is two. What belongs to the object — its texture, material, lights —
//! is looked up once for the run; where a fragment's right neighbour is the same triangle in the
//! next pixel, the texture coordinates' x derivative is that fragment's `uv` minus this one's
//! (the same evaluation one pixel over, which [`crate::raster::RasterTriangle::uv_at`] repeats
//! for each pixel); and Phong shading lights the fragments in SIMD lanes
//! ([`crate::lighting::lanes::shade_lanes`], in [`shading`]). Every value equals what
//! [`ResolveContext::pixel`] gives for the same pixel, bit for bit: the tests compare the two.

use glam::{Vec2, Vec3};

mod shading;

use super::resolve::{Kept, ResolveContext, ResolvedPixel};
use crate::lighting::ShadeTerms;
use crate::lighting::lanes::LANES;
use crate::raster::NONE;
use crate::texture::Lookup;

/// Consecutive pixels of a row resolved together, as fragments: fragment `f` is raster
/// triangle `triangle[f]` in the run's pixel `pixel[f]`, where it covers `weight[f]` samples;
/// a pixel's fragments follow one another in the order of their first sample, as
/// [`ResolveContext::pixel`] shades them.
#[derive(Clone, Copy, Debug)]
pub(super) struct Run {
    /// Each fragment's raster triangle; [`NONE`] past `len`.
    triangle: [u32; LANES],
    /// Each fragment's pixel, counted from the run's first.
    pixel: [u8; LANES],
    /// How many of its pixel's samples each fragment covers.
    weight: [u8; LANES],
    /// Each pixel's owner ([`ResolveContext::owner_of`]).
    owner: [u32; LANES],
    /// How many fragments, 1 to [`LANES`].
    pub(super) len: usize,
    /// How many pixels, 1 to `len`.
    pub(super) pixels: usize,
}

/// What [`ResolveContext::shade_run`] gives each fragment of a run: its colour, and its
/// lighting terms and texture lookup where the frame keeps them (their buffers, `None`
/// otherwise).
pub(super) struct RunShading {
    pub(super) color: [Vec3; LANES],
    pub(super) terms: [Option<ShadeTerms>; LANES],
    pub(super) texels: [Option<(Vec2, Lookup)>; LANES],
}

impl RunShading {
    /// Nothing shaded yet.
    pub(super) const EMPTY: Self = Self {
        color: [Vec3::ZERO; LANES],
        terms: [None; LANES],
        texels: [None; LANES],
    };
}

impl Run {
    /// No fragment yet.
    pub(super) fn empty() -> Self {
        Self {
            triangle: [NONE; LANES],
            pixel: [0; LANES],
            weight: [0; LANES],
            owner: [NONE; LANES],
            len: 0,
            pixels: 0,
        }
    }

    /// Adds raster triangle `t` in pixel `k` of the run (its one sample) as the run's pixel `k`
    /// and its next fragment.
    fn push(&mut self, t: u32, k: usize) {
        self.owner[k] = t;
        self.pixels = k + 1;
        self.push_fragment(t, k);
    }

    /// Adds raster triangle `t` in pixel `k` (counted from the run's first, which may be past
    /// [`LANES`]) as the next fragment to shade, covering one sample, and returns its index.
    pub(super) fn push_fragment(&mut self, t: u32, k: usize) -> usize {
        let f = self.len;
        self.triangle[f] = t;
        self.pixel[f] = k as u8;
        self.weight[f] = 1;
        self.len += 1;
        f
    }

    /// Whether a pixel of the run lies on two triangles or more.
    #[cfg(test)]
    fn has_edges(&self) -> bool {
        self.len > self.pixels
    }

    /// Whether the run crosses from one triangle to another.
    #[cfg(test)]
    fn crosses(&self) -> bool {
        self.triangle[..self.len].windows(2).any(|p| p[0] != p[1])
    }
}

impl ResolveContext<'_> {
    /// The run of pixels from image index `i` on (at most `room`, and at most [`LANES`]
    /// fragments): pixels whose samples are all covered, by triangles of the object that
    /// covers the first; `None` when a sample of the pixel at `i` is not covered (or, at 16
    /// samples, the pixel alone has more than [`LANES`] fragments).
    ///
    /// Runs used to be pixels wholly inside one triangle of a textured object, stopping at
    /// the triangle's edge. Across edges, the bunny's runs (its triangles a few pixels wide)
    /// fill the lanes too: its resolve fell from ~20 to ~13.5 ms at 1280×720 (one sample, 2
    /// threads, session 12); with fragments, the pixels on the edges at 4 samples join them.
    pub(super) fn run_at(&self, i: usize, room: usize) -> Option<Run> {
        let s = self.settings.samples.count();
        if s == 1 {
            return self.run_at_one_sample(i, room);
        }
        let mut run = Run::empty();
        // The run's object, and the last triangle found on it.
        let mut on: Option<(u32, u32)> = None;
        while run.pixels < room.min(LANES) {
            let px = self
                .samples
                .triangles((i + run.pixels) * s..(i + run.pixels + 1) * s);
            if px.contains(&NONE) {
                break;
            }
            // The pixel's distinct triangles, in the order of their first sample.
            let mut frags = [(NONE, 0u8); 16];
            let mut d = 0;
            for &t in px {
                match frags[..d].iter_mut().find(|f| f.0 == t) {
                    Some(f) => f.1 += 1,
                    None => {
                        frags[d] = (t, 1);
                        d += 1;
                    }
                }
            }
            if run.len + d > LANES {
                break;
            }
            let object = on.map_or_else(|| self.object_of(px[0]), |(o, _)| o);
            let mut last = on.map_or(NONE, |(_, t)| t);
            let mut same = true;
            for &(t, _) in &frags[..d] {
                if t != last {
                    same &= self.object_of(t) == object;
                    last = t;
                }
            }
            if !same {
                break;
            }
            on = Some((object, last));
            for &(t, w) in &frags[..d] {
                run.triangle[run.len] = t;
                run.pixel[run.len] = run.pixels as u8;
                run.weight[run.len] = w;
                run.len += 1;
            }
            run.owner[run.pixels] = if d == 1 { px[0] } else { self.owner_of(px) };
            run.pixels += 1;
        }
        (run.pixels > 0).then_some(run)
    }

    /// [`Self::run_at`] at one sample a pixel: each pixel is one fragment, its triangle.
    fn run_at_one_sample(&self, i: usize, room: usize) -> Option<Run> {
        let (triangles, n) = self.span_at_one_sample::<LANES>(i, room);
        let mut run = Run::empty();
        for (k, &t) in triangles[..n].iter().enumerate() {
            run.push(t, k);
        }
        (n > 0).then_some(run)
    }

    /// At one sample a pixel, the triangles of up to `N` consecutive pixels from image index
    /// `i` on (at most `room`), covered by triangles of the object that covers the first, and
    /// how many.
    pub(super) fn span_at_one_sample<const N: usize>(
        &self,
        i: usize,
        room: usize,
    ) -> ([u32; N], usize) {
        let mut span = [NONE; N];
        let (mut object, mut last) = (NONE, NONE);
        for (k, &t) in self
            .samples
            .triangles(i..i + room.min(N))
            .iter()
            .enumerate()
        {
            if t == NONE {
                return (span, k);
            }
            if t != last {
                let on = self.object_of(t);
                if k > 0 && on != object {
                    return (span, k);
                }
                (object, last) = (on, t);
            }
            span[k] = t;
        }
        (span, room.min(N))
    }

    /// The object raster triangle `t` belongs to.
    fn object_of(&self, t: u32) -> u32 {
        self.primitives[self.triangles[t as usize].primitive as usize].object
    }

    /// Resolves the pixels of `run`, from window `(x, y)` (image index `i`) on, as
    /// [`Self::pixel`] resolves each, and hands pixel `k` of the run to `out(k, pixel, kept)`:
    /// the pixel without its terms and lookup, which `kept` gives where the run's shading holds
    /// them (so that they are not copied around).
    pub(super) fn resolve_run(
        &self,
        run: &Run,
        (x, y): (u32, u32),
        i: usize,
        mut out: impl FnMut(usize, &ResolvedPixel, Kept<'_>),
    ) {
        let n = run.len;
        let tri = |f: usize| &self.triangles[run.triangle[f] as usize];
        let mut shaded = RunShading::EMPTY;
        self.shade_run(run, (x, y), &mut shaded);
        let color = |f: usize| shaded.color[f];
        let s = self.settings.samples.count();
        let mut f = 0;
        for k in 0..run.pixels {
            let first = f;
            while f < n && usize::from(run.pixel[f]) == k {
                f += 1;
            }
            let owner = run.owner[k];
            let primitive = self.triangles[owner as usize].primitive;
            // One fragment: its colour. More: their colours weighted by their samples, as
            // multisampling resolves them (every sample covered: no background in the sum).
            let (color, kept) = if f - first == 1 {
                (color(first), first)
            } else {
                let mut sum = self.settings.background * 0.0;
                for g in first..f {
                    sum += super::stored_color(color(g)) * f32::from(run.weight[g]);
                }
                let kept = (first..f)
                    .find(|&g| tri(g).primitive == primitive)
                    .unwrap_or(first);
                (sum / s as f32, kept)
            };
            out(
                k,
                &ResolvedPixel {
                    terms: None,
                    texture: None,
                    coverage: s as u8,
                    depth: self.mean_depth(i + k),
                    primitive,
                    owner,
                    color: color.to_array(),
                },
                (shaded.terms[kept].as_ref(), shaded.texels[kept].as_ref()),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::buffers::Capture;
    use crate::lighting::{Frequency, Reflection};
    use crate::raster::Samples;
    use crate::render::fixtures::{assert_kept, context, scene};
    use crate::settings::RenderSettings;
    use crate::texture::Mipmap;

    /// The settings the runs are checked with: every shading frequency, both reflection
    /// models, four minification filters, 1, 4 and 8 samples.
    const CASES: [(Frequency, Reflection, Mipmap, Samples); 7] = [
        (
            Frequency::Phong,
            Reflection::BlinnPhong,
            Mipmap::Linear,
            Samples::X1,
        ),
        (
            Frequency::Phong,
            Reflection::Phong,
            Mipmap::None,
            Samples::X4,
        ),
        (
            Frequency::Phong,
            Reflection::BlinnPhong,
            Mipmap::Ewa,
            Samples::X1,
        ),
        (
            Frequency::Gouraud,
            Reflection::BlinnPhong,
            Mipmap::Linear,
            Samples::X4,
        ),
        (
            Frequency::Flat,
            Reflection::Phong,
            Mipmap::Nearest,
            Samples::X1,
        ),
        (
            Frequency::Phong,
            Reflection::BlinnPhong,
            Mipmap::Linear,
            Samples::X8,
        ),
        (
            Frequency::Unlit,
            Reflection::BlinnPhong,
            Mipmap::None,
            Samples::X1,
        ),
    ];

    /// Every pixel of frames rendered with runs and background spans equals the per-pixel
    /// resolve of the same pixel (perspective-correct or affine), bit for bit: colour, depth,
    /// owner, primitive, and the kept lighting terms and texture lookup; and every run's resolve
    /// equals it too, in all that the frame keeps (a colour-only frame's runs light in lanes
    /// without the terms).
    #[test]
    fn runs_resolve_every_pixel_as_the_per_pixel_path_does() {
        let scene = scene();
        let (mut runs, mut crossing, mut edges, mut background) = (0, 0, 0, 0);
        for (k, (shading, reflection, mipmap, samples)) in CASES.into_iter().enumerate() {
            let mut settings = RenderSettings {
                width: 160,
                height: 96,
                samples,
                shading,
                reflection,
                capture: if k % 2 == 0 {
                    Capture::FULL
                } else {
                    Capture::COLOR
                },
                ..RenderSettings::default()
            };
            settings.sampler.mipmap = mipmap;
            // One setting interpolates affinely, without the perspective division.
            settings.perspective_correct = k != 2;
            let frame = crate::render::render(&scene, &settings).expect("renders");
            let ctx = context(&frame, &scene, &settings);
            let (w, h) = (settings.width as usize, settings.height as usize);
            for row in 0..h {
                let y = crate::grid::Grid::new(w as u32, h as u32).row(row as u32);
                for x in 0..w {
                    let i = row * w + x;
                    let want = ctx.pixel(x as u32, y, i, None);
                    assert_kept(
                        &frame.pixels,
                        i,
                        &want,
                        &settings,
                        &format!("{k} ({x}, {y})"),
                    );
                    background += usize::from(want.coverage == 0);
                    let Some(run) = ctx.run_at(i, w - x) else {
                        continue;
                    };
                    let n = run.pixels;
                    let mut got = [ResolvedPixel::default(); LANES];
                    ctx.resolve_run(&run, (x as u32, y), i, |k, r, (terms, texture)| {
                        got[k] = ResolvedPixel {
                            terms: terms.copied(),
                            texture: texture.copied(),
                            ..*r
                        };
                    });
                    // Everything the frame keeps: a run hands on no terms or lookups whose
                    // buffers the frame does not keep.
                    let kept = |r: &ResolvedPixel| ResolvedPixel {
                        terms: r.terms.filter(|_| settings.capture.lighting),
                        texture: r.texture.filter(|_| settings.capture.texturing),
                        ..*r
                    };
                    for (j, got) in got[..n].iter().enumerate() {
                        let want = ctx.pixel((x + j) as u32, y, i + j, None);
                        assert_eq!(
                            kept(got),
                            kept(&want),
                            "setting {k}, run at ({x}, {y}), pixel {j}"
                        );
                    }
                    runs += usize::from(n > 1);
                    crossing += usize::from(run.crosses());
                    edges += usize::from(run.has_edges());
                }
            }
        }
        assert!(runs > 10_000, "only {runs} runs of two pixels or more");
        assert!(crossing > 1_000, "only {crossing} runs across triangles");
        assert!(
            edges > 1_000,
            "only {edges} runs with a pixel on two triangles"
        );
        assert!(background > 5_000, "only {background} background pixels");
    }
}
