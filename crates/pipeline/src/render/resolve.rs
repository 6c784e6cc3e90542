//! The resolve: samples to pixels. Each pixel's coverage, mean depth and owning triangle; its
//! colour, shaded once per pixel and triangle at the centre (multisampling) or at every sample
//! (supersampling); and the owning fragment's lighting terms and texture lookup, written into
//! the kept buffers a row at a time, rows in parallel.

use glam::{I64Vec2, Vec2, Vec3};
use half::f16;
use rayon::prelude::*;

use crate::capture::{
    FrameCapture, PixelBuffers, PixelTexture, PrimitiveRecord, ShadingRow, Stored, TextureRow,
};
use crate::raster::{CoveredRows, NONE, ONE, RasterTriangle, SampleBuffers};
use crate::scene::Scene;
use crate::settings::RenderSettings;
use crate::shade::lanes::LANES;
use crate::shade::{self, Frequency, ShadeTerms};
use crate::texture::{Environment, Lookup};
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

/// A resolve task's reused storage: a row's lighting terms and lookups as 32-bit floats, before
/// they are converted to half floats; with coarse shading, the shading of each 2×2 block of the
/// row pair being resolved.
#[derive(Default)]
struct RowScratch {
    lighting: Vec<f32>,
    lit: Vec<Stored>,
    uvs: Vec<[f32; 2]>,
    texturing: Vec<f32>,
    read: Vec<Stored>,
    halves: Vec<f16>,
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
        s.lighting.clear();
        s.lit.clear();
        s.uvs.clear();
        s.texturing.clear();
        s.read.clear();
        let (coarse, per_sample) = (ctx.settings.coarse_shading, ctx.settings.per_sample_shading);
        // Runs of pixels, each covered by triangles of one object, are shaded together, unless
        // every sample is shaded by itself. With coarse shading, at one sample, a run of up to
        // sixteen pixels shades together what its 2×2 blocks do not share (see `coarse`).
        let runs = !per_sample && !coarse;
        let coarse_runs = !per_sample && coarse && ctx.settings.samples.count() == 1;
        let mut blocks = std::mem::take(&mut s.blocks);
        // The first covered pixel, and the last background span.
        let (mut first, mut last_background) = (None, None);
        let mut x = 0;
        while x < w {
            let i = row * w + x;
            // The background (most of a frame) is written without resolving pixel by pixel.
            let empty = ctx.background_run(i, w - x);
            if empty > 0 {
                self.store_background(ctx, x, i, empty, s);
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
                        self.store(x0 + k, r, s);
                    });
                    continue;
                }
                n.max(1)
            } else {
                let run = runs.then(|| ctx.run_at(i, w - x)).flatten();
                if let Some(run) = run.filter(|r| r.len >= 4) {
                    ctx.resolve_run(&run, at, i, |k, r, kept| {
                        self.store_with(x + k, r, kept, s);
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
                self.store(x, &r, s);
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
        if let Some(out) = &mut self.shading {
            out.store(&s.lit, &s.lighting, &mut s.halves);
        }
        if let Some(out) = &mut self.texturing {
            out.store(&s.read, &s.uvs, &s.texturing, &mut s.halves);
        }
    }

    /// Writes the `n` background pixels from `x` on (image index `i` on): no coverage, no
    /// owner, the background colour, the mean of the cleared sample depths, no terms and no
    /// lookup — what [`ResolveContext::pixel`] gives for each of them.
    fn store_background(
        &mut self,
        ctx: &ResolveContext<'_>,
        x: usize,
        i: usize,
        n: usize,
        s: &mut RowScratch,
    ) {
        let span = x..x + n;
        // Where the frame before (whose storage this is) had the background too, the term
        // buffers hold no terms already (see `PixelBuffers`).
        let stored = |&c: &u8| {
            if c == 0 {
                Stored::Kept
            } else {
                Stored::Nothing
            }
        };
        if self.shading.is_some() {
            s.lit.extend(self.coverage[span.clone()].iter().map(stored));
        }
        if self.texturing.is_some() {
            s.read
                .extend(self.coverage[span.clone()].iter().map(stored));
        }
        // So do its primitive and owner buffers, where it had the background all along, and
        // its colour and depth buffers when its background was this frame's (an OR over the
        // span, without a branch a pixel: the span is usually all zeros).
        let covered_before = self.coverage[span.clone()]
            .iter()
            .fold(0, |any, &c| any | c)
            != 0;
        if covered_before {
            self.coverage[span.clone()].fill(0);
            self.primitive[span.clone()].fill(NONE);
            self.owner[span.clone()].fill(NONE);
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

    /// Writes pixel `x`'s resolve into the row's buffers, its terms and lookup into the
    /// scratch rows when their buffers are kept.
    #[inline]
    fn store(&mut self, x: usize, r: &ResolvedPixel, s: &mut RowScratch) {
        self.store_with(x, r, (r.terms.as_ref(), r.texture.as_ref()), s);
    }

    /// [`Self::store`] with the pixel's terms and lookup given apart, where they are (a run's
    /// shading), rather than in `r`: read where they were written, not copied into `r` first
    /// (a copy that a read of the same bytes right after stalls on).
    #[inline]
    fn store_with(
        &mut self,
        x: usize,
        r: &ResolvedPixel,
        (terms, texture): Kept<'_>,
        s: &mut RowScratch,
    ) {
        self.coverage[x] = r.coverage;
        self.depth[x] = r.depth;
        self.primitive[x] = r.primitive;
        self.owner[x] = r.owner;
        self.color[x] = super::stored_color(glam::Vec3::from(r.color)).to_array();
        if self.shading.is_some() {
            s.lit.push(Stored::given(terms.is_some()));
            if let Some(t) = terms {
                s.lighting.extend_from_slice(&ShadingRow::flatten(t));
            }
        }
        if self.texturing.is_some() {
            s.read.push(Stored::given(texture.is_some()));
            if let Some((uv, l)) = texture {
                let (uv, halves) = TextureRow::flatten(&PixelTexture::new(*uv, l));
                s.uvs.push(uv);
                s.texturing.extend_from_slice(&halves);
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
    let settings = ctx.settings;
    let (w, h) = (settings.width as usize, settings.height as usize);
    let lit = settings.shading != Frequency::Unlit && settings.capture.lighting;
    let textured = settings.capture.texturing
        && ctx
            .scene
            .objects
            .iter()
            .any(|o| o.texture.is_some() && !o.mesh.uvs.is_empty());
    let mut px = spare.reused(w * h, lit, textured);
    let background = (settings.background.to_array(), ctx.background_depth());
    let kept = px.background.is_some_and(|b| b == background);
    let mut rows = split_rows(&mut px, w, h, (background, kept));
    // Coarse shading shares a 2×2 block's shading between two rows: they are resolved in pairs.
    let pair = if settings.coarse_shading { 2 } else { 1 };
    let grid = crate::grid::Grid::new(w as u32, h as u32);
    rows.par_chunks_mut(pair).enumerate().for_each_init(
        RowScratch::default,
        |scratch, (k, outs)| {
            if settings.coarse_shading {
                scratch.blocks.clear();
                scratch.blocks.resize(w.div_ceil(2), None);
            }
            for (j, out) in outs.iter_mut().enumerate() {
                let row = k * pair + j;
                out.resolve(ctx, row, grid.row(row as u32), scratch);
            }
        },
    );
    let covered = CoveredRows {
        clear: settings.depth_test.clear_value(),
        spans: rows.iter().map(|r| r.covered).collect(),
    };
    drop(rows);
    px.background = Some(background);
    if px.shading.is_none() || px.texturing.is_none() {
        px.inspected = settings.capture.pixel.and_then(|at| ctx.inspected(at));
    }
    (px, covered)
}

/// What the resolve of one pixel reads.
pub(super) struct ResolveContext<'a> {
    /// Whether texture lookups need their screen derivatives: to choose a mip level or the
    /// anisotropic taps, or because the texturing buffers (λ, level, footprint) are kept.
    pub(super) derivatives: bool,
    pub(super) vertex_shading: &'a [ShadeTerms],
    pub(super) face_shading: &'a [ShadeTerms],
    pub(super) scene: &'a Scene,
    pub(super) settings: &'a RenderSettings,
    pub(super) samples: &'a SampleBuffers,
    pub(super) triangles: &'a [RasterTriangle],
    pub(super) primitives: &'a [PrimitiveRecord],
    pub(super) vertices: &'a [VertexRecord],
}

impl ResolveContext<'_> {
    /// The surface colour of triangle `t` at original-triangle weights `b`: `Σ b_k·c_k`.
    pub(super) fn color_of(&self, t: &RasterTriangle, b: Vec3) -> Vec3 {
        let rows = self.primitives[t.primitive as usize].vertices;
        let c = rows.map(|r| self.vertices[r as usize].color);
        c[0] * b.x + c[1] * b.y + c[2] * b.z
    }

    /// The texture lookup of `t` at pixel centre `centre` (a textured object, a mesh with uvs):
    /// `uv` and its 2×2 quad's differences, as a GPU takes them ([`RasterTriangle::uv_at`]).
    fn texture_lookup(&self, t: &RasterTriangle, centre: I64Vec2) -> Option<(Vec2, Lookup)> {
        let prim = &self.primitives[t.primitive as usize];
        let texture = self.scene.objects[prim.object as usize].texture.as_ref()?;
        let uvs = prim.vertices.map(|r| self.vertices[r as usize].uv);
        let [Some(a), Some(b), Some(c)] = uvs else {
            return None;
        };
        // Neither the colour (one level, one tap) nor a kept buffer may need the footprint.
        let (uv, dx, dy) = t.uv_at(
            &prim.bary_corners(t),
            [a, b, c],
            centre,
            self.settings.height,
            self.settings.perspective_correct,
            self.derivatives,
        );
        let sampler = &self.settings.sampler;
        if !self.derivatives {
            return Some((uv, texture.sample_level0(uv, sampler)));
        }
        Some((uv, texture.sample(uv, dx, dy, sampler)))
    }

    /// The lighting of triangle `t` at weights `b` with surface colour `surface`, by the shading
    /// frequency: the face's own terms (flat) or the vertices' terms interpolated (Gouraud) — a
    /// texture then modulates their ambient and diffuse terms, as OpenGL's `GL_MODULATE` does — or
    /// lighting evaluated here with the interpolated position and normal (Phong). `None` when unlit.
    pub(super) fn terms_of(
        &self,
        t: &RasterTriangle,
        b: Vec3,
        surface: Vec3,
        textured: bool,
    ) -> Option<ShadeTerms> {
        let prim = &self.primitives[t.primitive as usize];
        let v = prim.vertices.map(|r| &self.vertices[r as usize]);
        if !self.scene.objects[prim.object as usize].lit {
            return None;
        }
        match self.settings.shading {
            Frequency::Unlit => None,
            Frequency::Flat | Frequency::Gouraud => {
                let mut terms = if self.settings.shading == Frequency::Flat {
                    self.face_shading[t.primitive as usize]
                } else {
                    let s = prim.vertices.map(|r| &self.vertex_shading[r as usize]);
                    ShadeTerms::blend(s, b)
                };
                if textured {
                    terms.ambient *= surface;
                    terms.diffuse *= surface;
                }
                Some(terms)
            }
            Frequency::Phong => {
                let p = v[0].world.truncate() * b.x
                    + v[1].world.truncate() * b.y
                    + v[2].world.truncate() * b.z;
                let mut n =
                    v[0].normal_world * b.x + v[1].normal_world * b.y + v[2].normal_world * b.z;
                let object = &self.scene.objects[prim.object as usize];
                if let (Some(detail), [Some(a), Some(bb), Some(c)]) =
                    (&object.detail, v.map(|v| v.uv))
                {
                    let world = v.map(|v| v.world.truncate());
                    if let Some((tangent, bitangent)) =
                        crate::texture::tangent_frame(world, [a, bb, c])
                    {
                        let uv = a * b.x + bb * b.y + c * b.z;
                        n = detail.perturb(n, tangent, bitangent, uv);
                    }
                }
                let mut terms = shade::shade(
                    p,
                    n,
                    self.scene.camera.eye,
                    surface,
                    &self.scene.lights,
                    &object.material,
                    self.settings.reflection,
                );
                if let Some(env) = &object.environment {
                    self.mirror(&mut terms, env, p);
                }
                Some(terms)
            }
        }
    }

    /// Environment mapping at world point `p`, lit with `terms`: `r = 2(n·v)n − v`, the mirror
    /// direction of the view vector; a mirror of reflectivity k shows k of what it reflects and
    /// keeps 1 − k of its own ambient and diffuse light.
    pub(super) fn mirror(&self, terms: &mut ShadeTerms, env: &Environment, p: Vec3) {
        let (n, v) = (
            terms.normal,
            (self.scene.camera.eye - p).normalize_or_zero(),
        );
        let k = env.reflectivity.clamp(0.0, 1.0);
        terms.reflected = env.cube.sample(2.0 * n.dot(v) * n - v) * k;
        terms.ambient *= 1.0 - k;
        terms.diffuse *= 1.0 - k;
    }

    /// The colour of triangle `t` at the fixed-point position `at`, with its lighting terms and
    /// texture lookup: the surface colour is the texel (textured) or the interpolated vertex
    /// colour, then lit by the shading frequency.
    /// An object with shaders gets no colour here (the fragment shaders add it), only its
    /// terms and lookup where the frame keeps them (what pipelens' own shading would give).
    fn shade_at(&self, t: &RasterTriangle, at: I64Vec2) -> Shaded {
        let shader = self.has_shader(t);
        if shader && !self.keeps_terms() {
            return (Vec3::ZERO, None, None);
        }
        let bary = self.primitives[t.primitive as usize].bary_corners(t);
        let b = t.original_bary(&bary, t.lambda(at), self.settings.perspective_correct);
        let texel = self.texture_lookup(t, at);
        let surface = texel.map_or_else(|| self.color_of(t, b), |(_, l)| l.color);
        let terms = self.terms_of(t, b, surface, texel.is_some());
        let color = if shader {
            Vec3::ZERO
        } else {
            terms.map_or(surface, |t| t.color())
        };
        (color, terms, texel)
    }

    /// Whether raster triangle `t`'s object runs the student's shaders.
    pub(super) fn has_shader(&self, t: &RasterTriangle) -> bool {
        let prim = &self.primitives[t.primitive as usize];
        self.scene.objects[prim.object as usize]
            .code
            .shader
            .is_some()
    }

    /// Whether the frame keeps any pixel's lighting terms or texture lookup.
    pub(super) fn keeps_terms(&self) -> bool {
        let c = self.settings.capture;
        c.lighting || c.texturing || c.pixel.is_some()
    }

    /// Resolves window pixel `(x, y)`, whose image index is `i`; with coarse shading, `block`
    /// is the shading its 2×2 block has so far.
    pub(super) fn pixel(
        &self,
        x: u32,
        y: u32,
        i: usize,
        block: Option<&mut Option<BlockShade>>,
    ) -> ResolvedPixel {
        let s = self.settings.samples.count();
        let tris = &self.samples.triangle[i * s..(i + 1) * s];
        let background = self.settings.background;
        let mut out = ResolvedPixel {
            terms: None,
            texture: None,
            coverage: 0,
            depth: self.mean_depth(i),
            primitive: NONE,
            owner: NONE,
            color: background.to_array(),
        };
        let covered = tris.iter().filter(|&&t| t != NONE).count();
        if covered == 0 {
            return out;
        }
        out.coverage = covered as u8;
        let centre = FrameCapture::pixel_centre_fixed(x, y);
        if covered == s && !self.settings.per_sample_shading && tris.iter().all(|&t| t == tris[0]) {
            // Inside a triangle (the usual case): it owns the pixel and is shaded once. The
            // general path below gives the same, (0·background + c·s)/s = c exactly, s being a
            // power of two.
            let owner = &self.triangles[tris[0] as usize];
            let (color, terms, texel) = match block {
                Some(Some(b)) if b.triangle == tris[0] => b.shaded,
                Some(b) => {
                    let shaded = self.shade_at(owner, centre);
                    b.get_or_insert(BlockShade {
                        triangle: tris[0],
                        shaded,
                    });
                    shaded
                }
                None => self.shade_at(owner, centre),
            };
            return ResolvedPixel {
                terms,
                texture: texel,
                primitive: owner.primitive,
                owner: tris[0],
                color: color.to_array(),
                ..out
            };
        }
        out.owner = self.owner_of(tris);
        let owner = &self.triangles[out.owner as usize];
        out.primitive = owner.primitive;
        // Colour. Multisampling: each distinct triangle once, at the centre, weighted by its
        // samples. Supersampling: every covered sample shaded at its own position.
        let mut sum = background * (s - covered) as f32;
        let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
        for (k, &t) in tris.iter().enumerate() {
            let per_sample = self.settings.per_sample_shading;
            if t == NONE || (!per_sample && tris[..k].contains(&t)) {
                continue;
            }
            let tri = &self.triangles[t as usize];
            let (at, weight) = if per_sample {
                (corner + self.samples.offset(k), 1.0)
            } else {
                (centre, tris.iter().filter(|&&u| u == t).count() as f32)
            };
            let (color, terms, texel) = self.shade_at(tri, at);
            sum += super::stored_color(color) * weight;
            if tri.primitive == owner.primitive && out.terms.is_none() && out.texture.is_none() {
                out.terms = terms;
                out.texture = texel;
            }
        }
        out.color = (sum / s as f32).to_array();
        out
    }
}
