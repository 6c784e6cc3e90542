//! The fragment stage of the student's shaders: quads of pixels a triangle covers, their
//! inputs interpolated as their qualifiers say, sixteen quads a batch; the inspected pixel's
//! fragments run again by themselves to keep their traces.

use glam::{I64Vec2, Vec3};
use rayon::prelude::*;

use super::{shader_error, textures, uniforms};
use crate::capture::{FragmentTrace, Matrices, VertexResults};
use crate::raster::{NONE, ONE};
use crate::render::RenderError;
use crate::render::resolve::ResolveContext;
use crate::shader::probe::{WatchKind, Watched};
use crate::shader::{self, Batch, Bindings, Interpolate, LANES, Programs, Uniforms};

/// A fragment to shade: a triangle over a 2×2 quad, with the pixels it covers (live lanes) and
/// how many samples of each.
#[derive(Clone, Copy)]
struct QuadJob {
    triangle: u32,
    /// Window x of the quad's left pixels (its y is the row pair's).
    x: u32,
    /// Samples the triangle covers in each of the four pixels.
    samples: [u8; 4],
}

/// The counts of a frame's fragment shading, and the inspected pixel's fragments.
#[derive(Clone, Default)]
pub(in crate::render) struct FragmentCounts {
    pub(in crate::render) fragments: u64,
    pub(in crate::render) discarded: u64,
    pub(in crate::render) not_finite: u64,
    pub(in crate::render) pixel: Vec<FragmentTrace>,
    /// The fragments discarded: raster triangle and image pixel.
    pub(in crate::render) discards: Vec<(u32, u32)>,
    /// What a watch saw (`crate::shader::probe`): image pixel, and the value of the fragment
    /// that covers the most of its samples.
    pub(in crate::render) watch: Vec<(usize, Watched)>,
    /// The steps the fragment shader ran (the cost view, `Capture::cost`): image pixel, and
    /// the steps of the fragment that covers the most of its samples.
    pub(in crate::render) cost: Vec<(usize, u32)>,
}

impl std::ops::Add for FragmentCounts {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        self.pixel.extend(o.pixel);
        self.discards.extend(o.discards);
        self.watch.extend(o.watch);
        self.cost.extend(o.cost);
        Self {
            fragments: self.fragments + o.fragments,
            discarded: self.discarded + o.discarded,
            not_finite: self.not_finite + o.not_finite,
            pixel: self.pixel,
            discards: self.discards,
            watch: self.watch,
            cost: self.cost,
        }
    }
}

/// Runs the fragment shaders over every pixel a triangle of an object with shaders covers, and
/// writes their colours into `pixels` (a pixel's other samples keep their share of the
/// built-in resolve's colour).
///
/// # Errors
/// A run-time error of a fragment shader.
pub(in crate::render) fn fragment_shaders(
    ctx: &ResolveContext<'_>,
    matrices: &Matrices,
    results: &[Option<VertexResults>],
    color: &mut [[f32; 3]],
) -> Result<FragmentCounts, RenderError> {
    let settings = ctx.settings;
    let (w, h) = (settings.width as usize, settings.height as usize);
    let uniforms: Vec<Option<Uniforms>> = ctx
        .scene
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            o.code
                .shader
                .as_ref()
                .map(|sh| uniforms(ctx.scene, settings, matrices, i, sh.time))
        })
        .collect();
    let shading = FragmentShading {
        ctx,
        results,
        uniforms: &uniforms,
    };
    // Row pairs, bottom pair first in window terms does not matter: each pair is independent.
    // Each task keeps its machines (an object's registers, set to its uniforms, with their
    // invariants evaluated) from row pair to row pair rather than making them again.
    color
        .par_chunks_mut(2 * w)
        .enumerate()
        .map_init(
            || shading.no_machines(),
            |machines, (k, rows)| {
                // Image rows 2k (upper) and 2k + 1 (lower): window y of the lower one is the
                // quad's y.
                let y = (h as i64 - 2 - 2 * k as i64).max(-1);
                shading.row_pair(rows, (w, 2 * k * w), y, machines)
            },
        )
        .try_reduce(FragmentCounts::default, |a, b| Ok(a + b))
}

/// What a row pair's batches add up, indexed like the row pair: each pixel's colour weighted
/// by the samples shaded, those samples, and, when the shaders watch an expression, the value
/// of the fragment covering the most samples with that count.
struct Sums {
    acc: Vec<Vec3>,
    shaded: Vec<u8>,
    watch: Option<Vec<(u8, Option<Watched>)>>,
    /// The cost view's steps, as `watch`.
    cost: Option<Vec<(u8, u32)>>,
}

impl Sums {
    /// What the pictures keep of this row pair (the cost view, a watch), as image pixels from
    /// `first` on, into `counts`.
    fn pictured(self, first: usize, counts: &mut FragmentCounts) {
        if let Some(cost) = self.cost {
            counts.cost.extend(
                cost.into_iter()
                    .enumerate()
                    .filter(|(_, (k, _))| *k > 0)
                    .map(|(i, (_, steps))| (first + i, steps)),
            );
        }
        if let Some(watch) = self.watch {
            counts.watch.extend(
                watch
                    .into_iter()
                    .enumerate()
                    .filter_map(|(i, (_, w))| Some((first + i, w?))),
            );
        }
    }
}

struct FragmentShading<'a> {
    ctx: &'a ResolveContext<'a>,
    results: &'a [Option<VertexResults>],
    uniforms: &'a [Option<Uniforms>],
}

impl FragmentShading<'_> {
    /// The image index of window pixel `(x, y)`, if it is in the image.
    fn index(&self, x: i64, y: i64) -> Option<usize> {
        let grid = crate::grid::Grid::new(self.ctx.settings.width, self.ctx.settings.height);
        grid.checked_index(u32::try_from(x).ok()?, u32::try_from(y).ok()?)
    }

    /// A machine for each object, none made yet (`run_batch` makes an object's when it first
    /// shades it).
    fn no_machines(&self) -> Vec<Option<shader::Machine<'_>>> {
        self.ctx.scene.objects.iter().map(|_| None).collect()
    }

    /// The object of raster triangle `t`.
    fn object_of(&self, t: u32) -> usize {
        let prim = self.ctx.triangles[t as usize].primitive;
        self.ctx.primitives[prim as usize].object as usize
    }

    /// Shades the quads of one row pair: `rows` is image rows 2k and 2k + 1 of the colour
    /// buffer, `first` the image index of its first pixel, `w` the image's width; `y` the
    /// window y of the lower row (−1 when the pair is a single top row); `machines` each
    /// object's machine, kept by the task from one row pair to the next.
    fn row_pair<'m>(
        &'m self,
        rows: &mut [[f32; 3]],
        (w, first): (usize, usize),
        y: i64,
        machines: &mut [Option<shader::Machine<'m>>],
    ) -> Result<FragmentCounts, RenderError> {
        let s = self.ctx.settings.samples.count();
        let watching = self.ctx.scene.objects.iter().any(|o| {
            o.code.shader.as_ref().is_some_and(|sh| {
                sh.programs.fragment.watch.is_some() || sh.programs.vertex.watch.is_some()
            })
        });
        let mut sums = Sums {
            acc: vec![Vec3::ZERO; rows.len()],
            shaded: vec![0u8; rows.len()],
            watch: watching.then(|| vec![(0, None); rows.len()]),
            cost: self
                .ctx
                .settings
                .capture
                .cost
                .then(|| vec![(0, 0); rows.len()]),
        };
        let mut counts = FragmentCounts::default();
        let mut batch: Vec<QuadJob> = Vec::with_capacity(LANES / 4);
        let mut batch_object = usize::MAX;
        let mut inputs = Batch::default();
        let inspected = self
            .ctx
            .settings
            .capture
            .pixel
            .map(|(x, y)| (i64::from(x), i64::from(y)));
        let mut traced: Vec<(QuadJob, usize)> = Vec::new();
        let mut flush = |batch: &mut Vec<QuadJob>,
                         object: usize,
                         sums: &mut Sums,
                         counts: &mut FragmentCounts| {
            if batch.is_empty() {
                return Ok(());
            }
            let r = self.run_batch(batch, object, machines, &mut inputs, sums, y, w);
            batch.clear();
            *counts = std::mem::take(counts) + r?;
            Ok::<(), RenderError>(())
        };
        // A quad's triangles, reused from quad to quad.
        let mut jobs: Vec<QuadJob> = Vec::new();
        for x in (0..w as i64).step_by(2) {
            let lanes = [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)];
            jobs.clear();
            for (j, &(px, py)) in lanes.iter().enumerate() {
                let Some(i) = self.index(px, py) else {
                    continue;
                };
                for &t in self.ctx.samples.triangles(i * s..(i + 1) * s) {
                    if t == NONE
                        || self.ctx.scene.objects[self.object_of(t)]
                            .code
                            .shader
                            .is_none()
                    {
                        continue;
                    }
                    let job = match jobs.iter_mut().find(|q| q.triangle == t) {
                        Some(q) => q,
                        None => {
                            jobs.push(QuadJob {
                                triangle: t,
                                x: x as u32,
                                samples: [0; 4],
                            });
                            jobs.last_mut().expect("just pushed")
                        }
                    };
                    job.samples[j] += 1;
                }
            }
            if let Some(j) = lanes.iter().position(|&p| Some(p) == inspected) {
                traced.extend(jobs.iter().filter(|q| q.samples[j] > 0).map(|q| (*q, j)));
            }
            for &job in &jobs {
                let object = self.object_of(job.triangle);
                if object != batch_object || batch.len() == LANES / 4 {
                    flush(&mut batch, batch_object, &mut sums, &mut counts)?;
                    batch_object = object;
                }
                batch.push(job);
            }
        }
        flush(&mut batch, batch_object, &mut sums, &mut counts)?;
        for (job, j) in traced {
            counts.pixel.push(self.trace(job, j, y, &mut inputs)?);
        }
        // A pixel is the average of its samples. The resolve averaged the background and the
        // objects without shaders, counting the shaded samples as zero: their share is added.
        for ((c, a), &n) in rows.iter_mut().zip(&sums.acc).zip(&sums.shaded) {
            if n > 0 {
                *c = (Vec3::from(*c) + *a / s as f32).to_array();
            }
        }
        sums.pictured(first, &mut counts);
        Ok(counts)
    }

    /// Runs one batch of quads of `object` and adds each live lane's colour, weighted by its
    /// samples, to the row pair's sums, with what a watch saw.
    #[allow(clippy::too_many_arguments)]
    fn run_batch<'m>(
        &'m self,
        batch: &[QuadJob],
        object: usize,
        machines: &mut [Option<shader::Machine<'m>>],
        inputs: &mut Batch,
        sums: &mut Sums,
        y: i64,
        w: usize,
    ) -> Result<FragmentCounts, RenderError> {
        let ctx = self.ctx;
        let o = &ctx.scene.objects[object];
        let Some(sh) = &o.code.shader else {
            return Ok(FragmentCounts::default());
        };
        let fs = &sh.programs.fragment;
        let m = machines[object].get_or_insert_with(|| {
            let mut m = fs.machine();
            m.budget = ctx.settings.max_steps;
            m.count_cost(ctx.settings.capture.cost);
            if let Some(u) = &self.uniforms[object] {
                fs.set_uniforms(&mut m, u);
            }
            m
        });
        inputs.start_for(fs, batch.len() * 4);
        for (q, job) in batch.iter().enumerate() {
            self.quad_inputs(&sh.programs, job, object, y, q * 4, inputs);
        }
        let tex = textures(fs, o, ctx.settings.sampler);
        let bindings = Bindings { textures: &tex };
        let ran = m
            .run_batch(inputs, &bindings)
            .map_err(|e| shader_error(fs, o, &e))?;
        let mut counts = FragmentCounts::default();
        let background = ctx.settings.background;
        for (q, job) in batch.iter().enumerate() {
            for j in 0..4 {
                let l = q * 4 + j;
                let k = job.samples[j];
                if k == 0 {
                    continue;
                }
                counts.fragments += 1;
                // The row pair's index: upper image row first.
                let x = job.x as usize + j % 2;
                let row = if j / 2 == 1 { 0 } else { 1 };
                let Some(i) = (x < w)
                    .then_some(row * w + x)
                    .filter(|&i| i < sums.acc.len())
                else {
                    continue;
                };
                if let (Some(cost), Some(steps)) = (sums.cost.as_mut(), ran.cost(l))
                    && k > cost[i].0
                {
                    // What was run for the pixel, whether or not it was then discarded.
                    cost[i] = (k, steps);
                }
                let color = if ran.discarded(l) {
                    counts.discarded += 1;
                    let (px, py) = (i64::from(job.x) + (j % 2) as i64, y + (j / 2) as i64);
                    if let Some(at) = self.index(px, py) {
                        counts.discards.push((job.triangle, at as u32));
                    }
                    background
                } else {
                    if let Some(watch) = sums.watch.as_mut()
                        && k > watch[i].0
                    {
                        let seen = match fs.watch.as_ref() {
                            Some(places) => ran.watched(places, l),
                            None => self.vertex_watch(job, j, y, object),
                        };
                        watch[i] = (k, seen);
                    }
                    let c = Vec3::from_array(ran.outputs::<3>(l));
                    if c.is_finite() {
                        c
                    } else {
                        counts.not_finite += 1;
                        Vec3::ZERO
                    }
                };
                sums.acc[i] += super::super::stored_color(color) * f32::from(k);
                sums.shaded[i] += k;
            }
        }
        Ok(counts)
    }

    /// Runs `job`'s quad again by itself, recording what lane `j` (the inspected pixel) does.
    fn trace(
        &self,
        job: QuadJob,
        j: usize,
        y: i64,
        inputs: &mut Batch,
    ) -> Result<FragmentTrace, RenderError> {
        let ctx = self.ctx;
        let object = self.object_of(job.triangle);
        let o = &ctx.scene.objects[object];
        let Some(sh) = &o.code.shader else {
            return Ok(FragmentTrace::default());
        };
        let fs = &sh.programs.fragment;
        let mut m = fs.machine();
        m.budget = ctx.settings.max_steps;
        if let Some(u) = &self.uniforms[object] {
            fs.set_uniforms(&mut m, u);
        }
        let t = &ctx.triangles[job.triangle as usize];
        inputs.start_for(fs, 4);
        self.quad_inputs(&sh.programs, &job, object, y, 0, inputs);
        let received = super::lane_values(&fs.inputs, inputs.rows(), j);
        let replay = crate::capture::FragmentReplay {
            object,
            lane: j,
            inputs: fs.inputs.clone(),
            batch: inputs.clone(),
        };
        let tex = textures(fs, o, ctx.settings.sampler);
        let bindings = Bindings { textures: &tex };
        m.trace_lane(Some(j));
        let ran = m
            .run_batch(inputs, &bindings)
            .map_err(|e| shader_error(fs, o, &e))?;
        let output = (!ran.discarded(j)).then(|| ran.outputs::<4>(j));
        let events = m.take_trace();
        Ok(FragmentTrace {
            triangle: job.triangle,
            primitive: t.primitive,
            samples: u32::from(job.samples[j]),
            inputs: received,
            trace: fs.describe(&events),
            watch: fs.watched_values(&events),
            output,
            replay: Some(replay),
        })
    }

    /// Writes the fragment inputs of `job`'s quad (its top row at window row `y`) into lanes
    /// `first..first + 4` of `inputs`, at each pixel's centre; a pixel the triangle covers no
    /// sample of is a helper lane. What the four lanes share — the triangle, its corners'
    /// weights, where its corners' outputs are, its area's inverse — is read once a quad.
    fn quad_inputs(
        &self,
        programs: &Programs,
        job: &QuadJob,
        object: usize,
        y: i64,
        first: usize,
        inputs: &mut Batch,
    ) {
        let ctx = self.ctx;
        let t = &ctx.triangles[job.triangle as usize];
        let prim = &ctx.primitives[t.primitive as usize];
        let bary = prim.bary_corners(t);
        let perspective = ctx.settings.perspective_correct;
        let results = self.results[object].as_ref();
        // Where the three corners' outputs start in the vertex shader's results.
        let corner_rows = results.map(|r| {
            prim.vertices
                .map(|v| (v as usize - r.first as usize) * r.stride as usize)
        });
        // The inverse of the triangle's doubled area, for the four lanes' weights.
        let inv_area = t.inv_area2();
        // Each lane's pixel, its centre, its λ and its weights, once a lane.
        let lanes: [_; 4] = std::array::from_fn(|j| {
            let (px, py) = (i64::from(job.x) + (j % 2) as i64, y + (j / 2) as i64);
            let centre = I64Vec2::new(px * ONE + ONE / 2, py * ONE + ONE / 2);
            let lambda = t.lambda_with(inv_area, centre);
            let weights = Weights {
                perspective: t.original_bary(&bary, lambda, perspective),
                linear: t.original_bary(&bary, lambda, false),
            };
            (px, py, centre, lambda, weights)
        });
        let rows = inputs.rows_mut();
        // Input by input, a component's corner values read once for the quad's four lanes.
        for ((input, link), rows) in programs
            .fragment
            .inputs
            .iter()
            .zip(&programs.links)
            .zip(rows.iter_mut())
        {
            match (link, input.builtin) {
                (Some(link), _) => {
                    let (Some(r), Some(corners)) = (results, corner_rows) else {
                        continue;
                    };
                    for c in 0..link.components as usize {
                        let v = corners.map(|at| r.values[at + link.from as usize + c]);
                        for (j, (.., weights)) in lanes.iter().enumerate() {
                            rows[c * LANES + first + j] =
                                weights.at(input.interpolate, &v).to_bits();
                        }
                    }
                }
                (None, Some(naga::BuiltIn::Position { .. })) => {
                    for (j, &(px, py, centre, lambda, _)) in lanes.iter().enumerate() {
                        // gl_FragCoord = (x + ½, y + ½, z_w, 1/w_clip).
                        let inv_w = lambda.dot(Vec3::from(t.inv_w));
                        let v = [px as f32 + 0.5, py as f32 + 0.5, t.depth_at(centre), inv_w];
                        for (c, x) in v.iter().enumerate() {
                            rows[c * LANES + first + j] = x.to_bits();
                        }
                    }
                }
                (None, Some(naga::BuiltIn::FrontFacing)) => {
                    // The piece's corners are counter-clockwise on screen; its barycentric
                    // corners keep the original order, so their determinant is negative when
                    // the original triangle ran clockwise (a back face), even when one of its
                    // vertices is behind the eye and has no window position.
                    let [b0, b1, b2] = bary;
                    let front = glam::Mat3::from_cols(b0, b1, b2).determinant() >= 0.0;
                    rows[first..first + 4].fill(u32::from(front));
                }
                _ => {}
            }
        }
        for j in (0..4).filter(|&j| job.samples[j] == 0) {
            inputs.helper(first + j);
        }
    }

    /// What the vertex shader's watch saw at the corners of `job`'s triangle, interpolated at
    /// the centre of lane `j`'s pixel as a smooth varying is (`Σ b_i·a_i` with the corners'
    /// perspective-correct weights `b_i`), an `int` or a `bool` flat from the provoking (last)
    /// vertex; `None` when the vertex shader watches nothing or a corner did not run the line.
    fn vertex_watch(&self, job: &QuadJob, j: usize, y: i64, object: usize) -> Option<Watched> {
        let r = self.results[object].as_ref()?;
        let t = &self.ctx.triangles[job.triangle as usize];
        let prim = &self.ctx.primitives[t.primitive as usize];
        let corner = |v: usize| -> Option<Watched> {
            let row = (prim.vertices[v] as usize).checked_sub(r.first as usize)?;
            *r.watch.get(row)?
        };
        let seen = [corner(0)?, corner(1)?, corner(2)?];
        let kind = seen[2].kind;
        if matches!(kind, WatchKind::Int | WatchKind::Bool) {
            return Some(seen[2]);
        }
        let (px, py) = (i64::from(job.x) + (j % 2) as i64, y + (j / 2) as i64);
        let centre = I64Vec2::new(px * ONE + ONE / 2, py * ONE + ONE / 2);
        let bary = prim.bary_corners(t);
        let b = t.original_bary(
            &bary,
            t.lambda(centre),
            self.ctx.settings.perspective_correct,
        );
        Some(Watched {
            kind,
            value: std::array::from_fn(|c| (0..3).map(|v| b[v] * seen[v].value[c]).sum()),
        })
    }
}

/// A fragment's weights of its original triangle's corners: perspective-correct and affine.
struct Weights {
    perspective: Vec3,
    linear: Vec3,
}

impl Weights {
    /// A varying's value from its values `v` at the three corners, as `interpolate` says:
    /// `Σ b_i·v_i` with the perspective-correct or the affine weights, or the provoking (last)
    /// corner's value for `flat`.
    #[inline]
    fn at(&self, interpolate: Interpolate, v: &[f32; 3]) -> f32 {
        let b = match interpolate {
            Interpolate::Flat => return v[2],
            Interpolate::Linear => self.linear,
            Interpolate::Perspective => self.perspective,
        };
        (0..3).map(|k| b[k] * v[k]).sum()
    }
}
