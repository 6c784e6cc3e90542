//! A run's fragments shaded together: each fragment's barycentric weights at its pixel's
//! centre, its texels (the uv's derivatives those of its 2×2 quad; the bilinear reads of the
//! run's one-tap lookups eight at a time in SIMD lanes), its points and normals, then Phong
//! lighting eight fragments at a time in lanes — each value what
//! [`ResolveContext::shade_at`] gives at that pixel, bit for bit.

use glam::{I64Vec2, Vec2, Vec3};
use wide::f32x8;

use super::{Run, RunShading};
use crate::capture::FrameCapture;
use crate::lighting::lanes::{LANES, Lighting, shade_lanes, shade_lanes_color};
use crate::lighting::{Frequency, ShadeTerms};
use crate::raster::{RasterTriangle, quad_offset};
use crate::render::resolve::ResolveContext;
use crate::texture::{Filter, Lookup, Texture, Wrap};

impl ResolveContext<'_> {
    /// The colours, lighting terms and texture lookups of `run`'s fragments (whose pixels
    /// are counted from window `(x, y)`), each as [`Self::shade_at`] gives it at its pixel's
    /// centre, written into `out`'s first `run.len` places (in place: a run's terms and
    /// lookups are over a kilobyte, which a returned value would copy).
    pub(in crate::render) fn shade_run(&self, run: &Run, (x, y): (u32, u32), out: &mut RunShading) {
        let n = run.len;
        let tri = |f: usize| &self.triangles[run.triangle[f] as usize];
        let object = &self.scene.objects[self.object_of(run.triangle[0]) as usize];
        // An object with shaders: no colour here, see `shade_at`.
        let shader = object.code.shader.is_some();
        if shader && !self.keeps_terms() {
            out.color[..n].fill(Vec3::ZERO);
            out.terms[..n].fill(None);
            out.texels[..n].fill(None);
            return;
        }
        let centre = |f: usize| FrameCapture::pixel_centre_fixed(x + u32::from(run.pixel[f]), y);
        let b = self.run_weights(run, centre);
        // What the frame keeps besides the colour (a pixel inspected is resolved by itself).
        let keeps = self.settings.capture;
        let texel_colors = self.run_texels(run, &b[..n], centre, keeps.texturing, &mut out.texels);
        let mut surface = [Vec3::ZERO; LANES];
        for f in 0..n {
            surface[f] = texel_colors[f].unwrap_or_else(|| self.color_of(tri(f), b[f]));
        }
        let phong = self.settings.shading == Frequency::Phong && object.lit;
        if phong && object.detail.is_none() {
            let (mut p, mut normal) = ([Vec3::ZERO; LANES], [Vec3::ZERO; LANES]);
            self.run_points(run, &b[..n], &mut p, &mut normal);
            let (p, normal, surface) = (&p[..n], &normal[..n], &surface[..n]);
            let lighting = Lighting {
                eye: self.scene.camera.eye,
                lights: &self.scene.lights,
                material: &object.material,
                model: self.settings.reflection,
            };
            if !keeps.lighting && !shader && object.environment.is_none() {
                // The colour alone: no terms taken out of the lanes, none handed on.
                shade_lanes_color(p, normal, surface, &lighting, &mut out.color[..n]);
                out.terms[..n].fill(None);
                return;
            }
            let mut lit = [ShadeTerms::default(); LANES];
            shade_lanes(p, normal, surface, &lighting, &mut lit[..n]);
            for f in 0..n {
                if let Some(env) = &object.environment {
                    self.mirror(&mut lit[f], env, p[f]);
                }
                out.terms[f] = Some(lit[f]);
            }
        } else {
            for f in 0..n {
                out.terms[f] = self.terms_of(tri(f), b[f], surface[f], texel_colors[f].is_some());
            }
        }
        for ((color, terms), &surface) in out.color.iter_mut().zip(&out.terms).zip(&surface[..n]) {
            *color = match terms {
                _ if shader => Vec3::ZERO,
                Some(t) => t.color(),
                None => surface,
            };
        }
    }

    /// Each fragment's weights of its original triangle at its pixel's centre (fixed point,
    /// `centre(f)`), as [`RasterTriangle::original_bary`] gives them from the screen-space
    /// weights λ: the perspective division `k = λ·(1/w) / Σ λ_i/w_i` and the corners' weights
    /// `b = (bary₀·k₀ + bary₁·k₁) + bary₂·k₂` in lanes, the same operations in the same order
    /// (so the same bits), where the fragments one by one would each wait on a division.
    fn run_weights(&self, run: &Run, centre: impl Fn(usize) -> I64Vec2) -> [Vec3; LANES] {
        // λ, 1/w and the corners' weights (corner, component) of each fragment, in lanes.
        let (mut l, mut inv_w) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
        let mut corners = [[[0.0; LANES]; 3]; 3];
        for f in 0..run.len {
            let t = &self.triangles[run.triangle[f] as usize];
            let bary = self.primitives[t.primitive as usize].bary_corners(t);
            let lambda = t.lambda(centre(f));
            for i in 0..3 {
                (l[i][f], inv_w[i][f]) = (lambda[i], t.inv_w[i]);
                for c in 0..3 {
                    corners[i][c][f] = bary[i][c];
                }
            }
        }
        let l = l.map(f32x8::new);
        let k = if self.settings.perspective_correct {
            let k: [f32x8; 3] = std::array::from_fn(|i| l[i] * f32x8::new(inv_w[i]));
            // Lanes past the run divide zero by zero; nothing reads them.
            let sum = k[0] + k[1] + k[2];
            k.map(|k| k / sum)
        } else {
            l
        };
        let corners = corners.map(|c| c.map(f32x8::new));
        let b: [[f32; LANES]; 3] = std::array::from_fn(|c| {
            (corners[0][c] * k[0] + corners[1][c] * k[1] + corners[2][c] * k[2]).to_array()
        });
        std::array::from_fn(|f| Vec3::new(b[0][f], b[1][f], b[2][f]))
    }

    /// The texture lookups of a run's fragments at original-triangle weights `b` (fragment
    /// `f` at its pixel's fixed-point centre `centre(f)`), as [`Self::texture_lookup`] makes
    /// each: `uv` interpolated from the same weights; its derivatives those of its 2×2 quad,
    /// taken once for the two fragments of one triangle in a quad's row; its footprint and λ
    /// fragment by fragment, and then, where the lookup is one bilinear tap (no anisotropic
    /// taps, no range query beyond the pyramid), the levels it reads read for the whole run
    /// together ([`Texture::bilinear_lanes`]).
    fn run_texels(
        &self,
        run: &Run,
        b: &[Vec3],
        centre: impl Fn(usize) -> I64Vec2,
        keep: bool,
        out: &mut [Option<(Vec2, Lookup)>; LANES],
    ) -> [Option<Vec3>; LANES] {
        let mut colors = [None; LANES];
        out[..b.len()].fill(None);
        let object = &self.scene.objects[self.object_of(run.triangle[0]) as usize];
        let Some(texture) = object.texture.as_ref() else {
            return colors;
        };
        let pc = self.settings.perspective_correct;
        // Each fragment's triangle's vertex uvs (`None` when a vertex has none).
        let mut uvs = [None; LANES];
        let mut uv = [Vec2::ZERO; LANES];
        for (f, &w) in b.iter().enumerate() {
            let t = &self.triangles[run.triangle[f] as usize];
            let prim = &self.primitives[t.primitive as usize];
            if let [Some(u0), Some(u1), Some(u2)] =
                prim.vertices.map(|r| self.vertices[r as usize].uv)
            {
                uvs[f] = Some([u0, u1, u2]);
                uv[f] = u0 * w.x + u1 * w.y + u2 * w.z;
            }
        }
        let sampler = &self.settings.sampler;
        let n = b.len();
        // Bilinear lookups of one tap are read in lanes: each one's record (its colour still
        // to come), the uv it reads at, its finer level and the next one's weight.
        let in_lanes = sampler.filter == Filter::Bilinear;
        let mut reads = LaneReads {
            summed: self.derivatives,
            ..LaneReads::default()
        };
        // Fragment `f`'s lookup made: its colour, and the lookup where the frame keeps it.
        let mut put = |f: usize, lookup: Lookup| {
            colors[f] = Some(lookup.color);
            if keep {
                out[f] = Some((uv[f], lookup));
            }
        };
        if !self.derivatives {
            // Level 0 alone, no footprint: what `sample_level0` reads.
            for f in (0..n).filter(|&f| uvs[f].is_some()) {
                if in_lanes {
                    reads.add(f, Lookup::of_level0(Vec3::ZERO), uv[f], (0, 0.0));
                    continue;
                }
                put(f, texture.sample_level0(uv[f], sampler));
            }
        } else {
            let in_lanes = in_lanes && !sampler.mipmap.beyond_the_pyramid();
            // The last derivatives taken: the triangle, its quad's lower-left place, the pair,
            // and (read in lanes) the one-tap lookup's record, axis and levels, which depend on
            // the pair alone: the two fragments of a triangle in a quad's row share them.
            type Quad = ((Vec2, Vec2), Option<(Lookup, Vec2, (usize, f32))>);
            let mut last: Option<(u32, I64Vec2, Quad)> = None;
            for f in 0..n {
                let Some(uvs) = uvs[f] else {
                    continue;
                };
                let c = centre(f);
                let o = c - quad_offset(c, self.settings.height);
                let ((dx, dy), one_tap) = match last {
                    Some((t, at, quad)) if t == run.triangle[f] && at == o => quad,
                    _ => {
                        let t: &RasterTriangle = &self.triangles[run.triangle[f] as usize];
                        let bary = self.primitives[t.primitive as usize].bary_corners(t);
                        let (dx, dy) = t.uv_derivatives(&bary, uvs, o, pc);
                        let one_tap = in_lanes
                            .then(|| texture.footprint_record(dx, dy, sampler))
                            .filter(|(record, _)| record.taps == 1)
                            .map(|(record, axis)| {
                                (record, axis, texture.levels_at(record.lod, sampler))
                            });
                        let quad = ((dx, dy), one_tap);
                        last = Some((run.triangle[f], o, quad));
                        quad
                    }
                };
                if let Some((record, axis, levels)) = one_tap {
                    // One tap, at `uv + axis·0` as `sample_shifted` places it.
                    reads.add(f, record, uv[f] + axis * 0.0, levels);
                    continue;
                }
                put(f, texture.sample(uv[f], dx, dy, sampler));
            }
        }
        for (f, lookup) in reads.read(texture, n, sampler.wrap) {
            put(f, lookup);
        }
        colors
    }

    /// The world positions `p` and normals `normal` (not yet unit) of a run's fragments at
    /// original-triangle weights `b`: `Σ b_k·p_k`, `Σ b_k·n_k` over each triangle's vertices.
    fn run_points(&self, run: &Run, b: &[Vec3], p: &mut [Vec3], normal: &mut [Vec3]) {
        for (f, &w) in b.iter().enumerate() {
            let t = &self.triangles[run.triangle[f] as usize];
            let v = self.primitives[t.primitive as usize]
                .vertices
                .map(|r| &self.vertices[r as usize]);
            p[f] = v[0].world.truncate() * w.x
                + v[1].world.truncate() * w.y
                + v[2].world.truncate() * w.z;
            normal[f] = v[0].normal_world * w.x + v[1].normal_world * w.y + v[2].normal_world * w.z;
        }
    }
}

/// A run's bilinear lookups of one tap each, to be read together in lanes
/// ([`crate::texture::Texture::bilinear_lanes`]).
#[derive(Default)]
struct LaneReads {
    /// Lookup `f`'s record without its colour, where it is read here.
    record: [Option<Lookup>; LANES],
    /// Where it reads.
    at: [Vec2; LANES],
    /// Its finer level `k`.
    finer: [usize; LANES],
    /// The weight of level `k + 1` (0: level `k` alone).
    blend: [f32; LANES],
    /// Whether the colours are one tap's mean, summed from zero (`sample_shifted`: `0 + c`,
    /// +0 where `c` is −0), or level 0's texel as read (`sample_level0`).
    summed: bool,
}

impl LaneReads {
    /// Lookup `f`, `record` without its colour, reading at `at` the levels `(k, f)` of
    /// [`crate::texture::Texture::levels_at`].
    fn add(&mut self, f: usize, record: Lookup, at: Vec2, (k, blend): (usize, f32)) {
        self.record[f] = Some(record);
        self.at[f] = at;
        (self.finer[f], self.blend[f]) = (k, blend);
    }

    /// The lookups among the first `n`, each with the colour and levels `sample_shifted` (or
    /// `sample_level0`) gives it: `lerp(T_k, T_{k+1}, f)` where it blends, `T_k` elsewhere.
    fn read(
        &self,
        texture: &Texture,
        n: usize,
        wrap: Wrap,
    ) -> impl Iterator<Item = (usize, Lookup)> + '_ {
        let any = self.record[..n].iter().any(Option::is_some);
        let finer = any.then(|| texture.bilinear_lanes(&self.finer, &self.at, n, wrap));
        let coarser = self.blend[..n].iter().any(|&f| f > 0.0).then(|| {
            let next = std::array::from_fn(|f| self.finer[f] + usize::from(self.blend[f] > 0.0));
            texture.bilinear_lanes(&next, &self.at, n, wrap)
        });
        (0..n).filter_map(move |f| {
            let mut lookup = self.record[f]?;
            let c = finer.as_ref()?[f];
            let c = match &coarser {
                Some(next) if self.blend[f] > 0.0 => c.lerp(next[f], self.blend[f]),
                _ => c,
            };
            lookup.color = if self.summed { Vec3::ZERO + c } else { c };
            (lookup.level, lookup.level_blend) = (self.finer[f] as u32, self.blend[f]);
            Some((f, lookup))
        })
    }
}
