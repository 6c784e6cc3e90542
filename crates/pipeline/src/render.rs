//! `render`: the stages in order, each recording into the [`FrameCapture`].
//!
//! vertex stage → primitive assembly → clipping → perspective division and viewport →
//! triangle setup (culling) → rasterization with the depth test → resolve to pixels.

use std::time::{Duration, Instant};

use glam::{I64Vec2, Vec2, Vec3, Vec4};
use half::f16;
use rayon::prelude::*;
use serde::Serialize;

use crate::capture::{
    Fate, FrameCapture, Matrices, ObjectSummary, PixelBuffers, PixelTexture, PrimitiveRecord,
    ShadingRow, TextureRow,
};
use crate::clip::{self, ClipOutcome, ClipVertex};
use crate::raster::{NONE, ONE, RasterCounts, RasterTriangle, SampleBuffers, SetupRejection};
use crate::scene::{RenderSettings, Scene};
use crate::shade::{self, Frequency, ShadeTerms};
use crate::texture::Lookup;
use crate::transform::{self, NamedMatrix};
use crate::vertex::{self, VertexMatrices, VertexRecord};

/// Why a frame cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The scene or the settings are invalid; each problem as a sentence.
    #[error("the scene cannot be drawn: {}", .0.join("; "))]
    Invalid(Vec<String>),
}

/// Wall-clock time spent in each stage of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StageTimes {
    /// Vertex stage (all transforms).
    pub vertex: Duration,
    /// Primitive assembly, clipping, division, viewport and triangle setup.
    pub clip_setup: Duration,
    /// Rasterization and the depth test.
    pub raster: Duration,
    /// Resolve of samples to pixels (barycentrics, colour).
    pub resolve: Duration,
}

impl StageTimes {
    /// The whole frame.
    #[must_use]
    pub fn total(&self) -> Duration {
        self.vertex + self.clip_setup + self.raster + self.resolve
    }
}

/// Renders one frame and records every stage. A pure function of its inputs.
///
/// # Errors
/// [`RenderError::Invalid`] listing every problem with the scene or the settings.
pub fn render(scene: &Scene, settings: &RenderSettings) -> Result<FrameCapture, RenderError> {
    render_timed(scene, settings).map(|(c, _)| c)
}

/// [`render`], also returning how long each stage took.
///
/// # Errors
/// As [`render`].
pub fn render_timed(
    scene: &Scene,
    settings: &RenderSettings,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    render_reusing(scene, settings, None)
}

/// [`render_timed`], writing the per-pixel and per-sample buffers into the storage of `spare`,
/// a capture no longer needed (the frame before). A full capture is tens to hundreds of
/// megabytes; memory fresh from the system costs a page fault and a zeroing every 4 KiB before
/// the pipeline writes a byte of it, which reusing storage avoids. The result is the same.
///
/// # Errors
/// As [`render`].
pub fn render_reusing(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<FrameCapture>,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    let problems = scene.problems(settings);
    if !problems.is_empty() {
        return Err(RenderError::Invalid(problems));
    }
    if scene.shadow.is_some() || !scene.figures.is_empty() {
        // Figures and the shadow pass become plain objects; the same pipeline draws them all.
        let (objects, steps) = scene.drawn_objects();
        let expanded = Scene {
            objects,
            shadow: None,
            figures: Vec::new(),
            ..scene.clone()
        };
        return render_stages(&expanded, settings, spare).map(|(mut c, t)| {
            c.hierarchy = steps;
            (c, t)
        });
    }
    render_stages(scene, settings, spare)
}

/// The stages, in order, over a scene whose figures and shadows are already plain objects.
fn render_stages(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<FrameCapture>,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    let (spare_pixels, spare_samples) = spare.map_or((PixelBuffers::default(), None), |c| {
        (c.pixels, Some(c.samples))
    });
    let matrices = frame_matrices(scene, settings)?;
    let mut times = StageTimes::default();

    let t = Instant::now();
    let (vertices, vertex_shading) = vertex_stage(scene, settings, &matrices);
    times.vertex = t.elapsed();

    let t = Instant::now();
    let (mut primitives, triangles) = assemble_and_clip(scene, settings, &matrices, &vertices);
    let face_shading = if settings.shading == Frequency::Flat {
        light_faces(scene, settings, &vertices, &primitives)
    } else {
        Vec::new()
    };
    times.clip_setup = t.elapsed();

    let t = Instant::now();
    let clear = settings.depth_test.clear_value();
    let (width, height) = (settings.width, settings.height);
    let mut samples = match spare_samples {
        Some(s) => s.cleared(width, height, settings.samples, clear),
        None => SampleBuffers::new(width, height, settings.samples, clear),
    };
    let counts = samples.rasterize_all(&triangles, settings.depth_test);
    for (tri, c) in triangles.iter().zip(counts) {
        let rec = &mut primitives[tri.primitive as usize];
        rec.counts.covered += c.covered;
        rec.counts.written += c.written;
    }
    times.raster = t.elapsed();

    let t = Instant::now();
    let ctx = ResolveContext {
        derivatives: settings.capture.texturing || settings.sampler.uses_footprint(),
        scene,
        settings,
        samples: &samples,
        triangles: &triangles,
        primitives: &primitives,
        vertices: &vertices,
        vertex_shading: &vertex_shading,
        face_shading: &face_shading,
    };
    let pixels = resolve(&ctx, spare_pixels);
    times.resolve = t.elapsed();

    let capture = FrameCapture {
        settings: *settings,
        camera: scene.camera,
        projection: scene.projection,
        lights: scene.lights.clone(),
        objects: scene
            .objects
            .iter()
            .map(|o| ObjectSummary {
                name: o.name.clone(),
                mesh: o.mesh.name.clone(),
                vertices: o.mesh.positions.len(),
                triangles: o.mesh.indices.len(),
            })
            .collect(),
        matrices,
        vertices,
        vertex_shading,
        face_shading,
        hierarchy: Vec::new(),
        textures: scene
            .objects
            .iter()
            .filter_map(|o| {
                o.texture
                    .as_ref()
                    .map(|t| (o.name.clone(), std::sync::Arc::clone(t)))
            })
            .collect(),
        primitives,
        triangles,
        samples,
        pixels,
    };
    Ok((capture, times))
}

/// The vertex stage: every vertex of every object through every space, in order, with its
/// lighting when shading is per vertex.
fn vertex_stage(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
) -> (Vec<VertexRecord>, Vec<ShadeTerms>) {
    let mut vertices = Vec::new();
    let mut vertex_shading = Vec::new();
    for (i, object) in scene.objects.iter().enumerate() {
        let m = VertexMatrices {
            model: matrices.models[i].matrix,
            view: matrices.view.matrix,
            projection: matrices.projection.matrix,
            viewport: matrices.viewport.matrix,
        };
        let lighting = vertex::VertexLighting {
            frequency: settings.shading,
            reflection: settings.reflection,
            lights: &scene.lights,
            eye: scene.camera.eye,
        };
        vertex::transform_object(
            object,
            i as u32,
            &m,
            &lighting,
            &mut vertices,
            &mut vertex_shading,
        );
    }
    (vertices, vertex_shading)
}

/// The frame's matrices: models, view, both courses' projections, viewport.
fn frame_matrices(scene: &Scene, settings: &RenderSettings) -> Result<Matrices, RenderError> {
    let view = scene
        .view_matrix()
        .map_err(|e| RenderError::Invalid(vec![e.to_string()]))?;
    let aspect = settings.aspect();
    Ok(Matrices {
        models: scene.objects.iter().map(|o| o.model_matrix()).collect(),
        projection: scene.projection.matrix(aspect),
        projection_games101: scene.projection.matrix_games101(aspect),
        viewport: NamedMatrix::new(
            "M_viewport",
            "x_w = (x+1)·width/2, y_w = (y+1)·height/2, z_w = (z+1)/2",
            transform::viewport(settings.width as f32, settings.height as f32),
        ),
        view,
    })
}

/// Primitive assembly, clipping, perspective division, viewport and triangle setup for every
/// triangle of every object: a record per primitive and the raster triangles, in order. The
/// primitives are independent, so they are processed in parallel chunks and joined in order.
fn assemble_and_clip(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
) -> (Vec<PrimitiveRecord>, Vec<RasterTriangle>) {
    use rayon::prelude::*;
    // (object, its first vertex-table row, the triangle) for every primitive, in order.
    let mut jobs = Vec::with_capacity(scene.objects.iter().map(|o| o.mesh.indices.len()).sum());
    let mut row_base = 0u32;
    for (object_index, object) in scene.objects.iter().enumerate() {
        jobs.extend(
            object
                .mesh
                .indices
                .iter()
                .map(|t| (object_index as u32, t.map(|i| row_base + i))),
        );
        row_base += object.mesh.positions.len() as u32;
    }
    const CHUNK: usize = 4096;
    let parts: Vec<(Vec<PrimitiveRecord>, Vec<RasterTriangle>)> = jobs
        .par_chunks(CHUNK)
        .enumerate()
        .map(|(c, chunk)| {
            let mut prims = Vec::with_capacity(chunk.len());
            let mut tris = Vec::with_capacity(chunk.len());
            for (k, &(object, rows)) in chunk.iter().enumerate() {
                let id = (c * CHUNK + k) as u32;
                prims.push(assemble_one(
                    id, object, rows, settings, matrices, vertices, &mut tris,
                ));
            }
            (prims, tris)
        })
        .collect();
    let mut primitives = Vec::with_capacity(jobs.len());
    let mut triangles = Vec::with_capacity(jobs.len());
    for (prims, tris) in parts {
        let offset = triangles.len() as u32;
        primitives.extend(prims.into_iter().map(|mut p| {
            p.triangles = p.triangles.map(|t| t + offset);
            p
        }));
        triangles.extend(tris);
    }
    (primitives, triangles)
}

/// One primitive through clipping, division, viewport and setup: its raster triangles are
/// pushed onto `triangles` (their range, relative to it, is in the record).
fn assemble_one(
    id: u32,
    object: u32,
    rows: [u32; 3],
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
    triangles: &mut Vec<RasterTriangle>,
) -> PrimitiveRecord {
    let size = (settings.width, settings.height);
    let viewport = matrices.viewport.matrix;
    let corners = [Vec3::X, Vec3::Y, Vec3::Z];
    let input = [0, 1, 2].map(|k| ClipVertex {
        clip: vertices[rows[k] as usize].clip,
        bary: corners[k],
    });
    let start = triangles.len() as u32;
    let outcome = clip::clip_triangle(input);
    let polygon: &[ClipVertex] = match &outcome {
        ClipOutcome::Inside => &input,
        ClipOutcome::Clipped(poly) => poly,
        &ClipOutcome::Outside(plane) => {
            return PrimitiveRecord {
                id,
                object,
                vertices: rows,
                fate: Fate::Outside { plane },
                clipped_polygon: None,
                triangles: [start, start],
                counts: RasterCounts::default(),
            };
        }
    };
    // Perspective division and viewport for each polygon vertex (at most 10).
    let mut window = [(Vec3::ZERO, 0.0f32); 10];
    for (slot, v) in window.iter_mut().zip(polygon) {
        let inv_w = 1.0 / v.clip.w;
        let ndc: Vec4 = (v.clip.truncate() * inv_w).extend(1.0);
        *slot = ((viewport * ndc).truncate(), inv_w);
    }
    let mut rejection = None;
    for k in 1..polygon.len() - 1 {
        let idx = [0, k, k + 1];
        match RasterTriangle::setup(
            id,
            idx.map(|i| window[i].0),
            idx.map(|i| window[i].1),
            idx.map(|i| polygon[i].bary),
            settings.cull,
            size,
        ) {
            Ok(t) => triangles.push(t),
            // A culled piece says more about the polygon than a degenerate sliver.
            Err(r) => {
                if matches!(rejection, None | Some(SetupRejection::Degenerate)) {
                    rejection = Some(r);
                }
            }
        }
    }
    let end = triangles.len() as u32;
    let clipped = matches!(outcome, ClipOutcome::Clipped(_));
    let fate = match (end > start, clipped, rejection) {
        (true, false, _) => Fate::Drawn,
        (true, true, _) => Fate::Clipped,
        (false, _, Some(SetupRejection::BackFace)) => Fate::Culled { back: true },
        (false, _, Some(SetupRejection::FrontFace)) => Fate::Culled { back: false },
        (false, _, _) => Fate::Degenerate,
    };
    PrimitiveRecord {
        id,
        object,
        vertices: rows,
        fate,
        clipped_polygon: match outcome {
            ClipOutcome::Clipped(poly) => Some(poly),
            _ => None,
        },
        triangles: [start, end],
        counts: RasterCounts::default(),
    }
}

/// Flat shading: each face lit once, with its own normal `(p1 − p0) × (p2 − p0)` (world
/// coordinates), at its centroid, with the mean of its vertices' colours (white for a textured
/// surface, whose texel then modulates the result per pixel). One entry per primitive; faces
/// that are not drawn get zero terms.
fn light_faces(
    scene: &Scene,
    settings: &RenderSettings,
    vertices: &[VertexRecord],
    primitives: &[PrimitiveRecord],
) -> Vec<ShadeTerms> {
    primitives
        .iter()
        .map(|prim| {
            if prim.triangles[1] == prim.triangles[0] {
                return ShadeTerms::default();
            }
            let v = prim.vertices.map(|r| &vertices[r as usize]);
            let p = v.map(|v| v.world.truncate());
            let normal = (p[1] - p[0]).cross(p[2] - p[0]);
            let centroid = (p[0] + p[1] + p[2]) / 3.0;
            let object = &scene.objects[prim.object as usize];
            if !object.lit {
                return ShadeTerms::default();
            }
            let color = if object.texture.is_some() && !object.mesh.uvs.is_empty() {
                Vec3::ONE
            } else {
                (v[0].color + v[1].color + v[2].color) / 3.0
            };
            shade::shade(
                centroid,
                normal,
                scene.camera.eye,
                color,
                &scene.lights,
                &object.material,
                settings.reflection,
            )
        })
        .collect()
}

/// Everything the resolve computes for one pixel.
struct ResolvedPixel {
    terms: Option<ShadeTerms>,
    texture: Option<(Vec2, Lookup)>,
    coverage: u8,
    depth: f32,
    primitive: u32,
    owner: u32,
    color: [f32; 3],
}

/// One image row of every per-pixel buffer, written by one resolve task.
struct RowOut<'a> {
    coverage: &'a mut [u8],
    depth: &'a mut [f32],
    primitive: &'a mut [u32],
    owner: &'a mut [u32],
    color: &'a mut [[f32; 3]],
    shading: Option<ShadingRow<'a>>,
    texturing: Option<TextureRow<'a>>,
}

/// A resolve task's reused storage: a row's lighting terms and lookups as 32-bit floats, before
/// they are converted to half floats.
#[derive(Default)]
struct RowScratch {
    lighting: Vec<f32>,
    uvs: Vec<[f32; 2]>,
    texturing: Vec<f32>,
    halves: Vec<f16>,
}

impl RowOut<'_> {
    /// Resolves image row `row` (window `y`) into every kept buffer, so that reused storage
    /// holds nothing of the frame before.
    fn resolve(&mut self, ctx: &ResolveContext<'_>, row: usize, y: u32, s: &mut RowScratch) {
        let w = self.color.len();
        s.lighting.clear();
        s.uvs.clear();
        s.texturing.clear();
        for x in 0..w {
            let r = ctx.pixel(x as u32, y, row * w + x);
            self.coverage[x] = r.coverage;
            self.depth[x] = r.depth;
            self.primitive[x] = r.primitive;
            self.owner[x] = r.owner;
            self.color[x] = r.color;
            if self.shading.is_some() {
                s.lighting
                    .extend_from_slice(&ShadingRow::flatten(r.terms.as_ref()));
            }
            if self.texturing.is_some() {
                let t = r.texture.map(|(uv, l)| PixelTexture::new(uv, &l));
                let (uv, halves) = TextureRow::flatten(t.as_ref());
                s.uvs.push(uv);
                s.texturing.extend_from_slice(&halves);
            }
        }
        if let Some(out) = &mut self.shading {
            out.store(&s.lighting, &mut s.halves);
        }
        if let Some(out) = &mut self.texturing {
            out.store(&s.uvs, &s.texturing, &mut s.halves);
        }
    }
}

/// Every per-pixel buffer cut into image rows, one [`RowOut`] a row, so that rows can be
/// resolved in parallel.
fn split_rows(px: &mut PixelBuffers, w: usize, h: usize) -> Vec<RowOut<'_>> {
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

/// `v` holding `n` elements, reusing its storage (the resolve overwrites every element).
fn sized<T: Clone>(mut v: Vec<T>, n: usize, fill: T) -> Vec<T> {
    v.resize(n, fill);
    v
}

/// The per-pixel buffers for a frame of `n` pixels, in `spare`'s storage when it has some:
/// the lighting buffers when lighting is on and kept, the texturing buffers when an object is
/// textured and they are kept.
fn pixel_storage(spare: PixelBuffers, n: usize, lighting: bool, texturing: bool) -> PixelBuffers {
    PixelBuffers {
        coverage: sized(spare.coverage, n, 0),
        depth: sized(spare.depth, n, 0.0),
        primitive: sized(spare.primitive, n, NONE),
        owner: sized(spare.owner, n, NONE),
        color: sized(spare.color, n, [0.0; 3]),
        shading: lighting.then(|| spare.shading.unwrap_or_default().resized(n)),
        texturing: texturing.then(|| spare.texturing.unwrap_or_default().resized(n)),
    }
}

/// Resolves samples to pixels: coverage, mean depth, the owning primitive and raster
/// triangle, and the colour at the pixel centre (once per pixel and triangle, as multisampling
/// shades), with the lighting terms and texture lookup of the owning fragment when the settings
/// keep them. Rows are independent, so they are resolved in parallel.
fn resolve(ctx: &ResolveContext<'_>, spare: PixelBuffers) -> PixelBuffers {
    let settings = ctx.settings;
    let (w, h) = (settings.width as usize, settings.height as usize);
    let lit = settings.shading != Frequency::Unlit && settings.capture.lighting;
    let textured = settings.capture.texturing
        && ctx
            .scene
            .objects
            .iter()
            .any(|o| o.texture.is_some() && !o.mesh.uvs.is_empty());
    let mut px = pixel_storage(spare, w * h, lit, textured);
    let rows = split_rows(&mut px, w, h);
    rows.into_par_iter().enumerate().for_each_init(
        RowScratch::default,
        |scratch, (row, mut out)| {
            out.resolve(ctx, row, (h - 1 - row) as u32, scratch);
        },
    );
    px
}

/// What the resolve of one pixel reads.
struct ResolveContext<'a> {
    /// Whether texture lookups need their screen derivatives: to choose a mip level or the
    /// anisotropic taps, or because the texturing buffers (λ, level, footprint) are kept.
    derivatives: bool,
    vertex_shading: &'a [ShadeTerms],
    face_shading: &'a [ShadeTerms],
    scene: &'a Scene,
    settings: &'a RenderSettings,
    samples: &'a SampleBuffers,
    triangles: &'a [RasterTriangle],
    primitives: &'a [PrimitiveRecord],
    vertices: &'a [VertexRecord],
}

impl ResolveContext<'_> {
    /// The surface colour of triangle `t` at original-triangle weights `b`: `Σ b_k·c_k`.
    fn color_of(&self, t: &RasterTriangle, b: Vec3) -> Vec3 {
        let rows = self.primitives[t.primitive as usize].vertices;
        let c = rows.map(|r| self.vertices[r as usize].color);
        c[0] * b.x + c[1] * b.y + c[2] * b.z
    }

    /// The texture lookup of triangle `t` at the pixel centre `centre`, when its object has a
    /// texture and its mesh has uvs: `uv` interpolated like every attribute, and its screen
    /// derivatives as the differences to the next pixel in x and in y (analytic: the same
    /// triangle's interpolation evaluated there).
    fn texture_lookup(&self, t: &RasterTriangle, centre: I64Vec2) -> Option<(Vec2, Lookup)> {
        let prim = &self.primitives[t.primitive as usize];
        let texture = self.scene.objects[prim.object as usize].texture.as_ref()?;
        let uvs = prim.vertices.map(|r| self.vertices[r as usize].uv);
        let [Some(a), Some(b), Some(c)] = uvs else {
            return None;
        };
        let pc = self.settings.perspective_correct;
        let uv_at = |p: I64Vec2| {
            let w = t.original_bary(t.lambda(p), pc);
            a * w.x + b * w.y + c * w.z
        };
        let uv = uv_at(centre);
        let sampler = &self.settings.sampler;
        if !self.derivatives {
            // Neither the colour (one level, one tap) nor a kept buffer needs the footprint.
            return Some((uv, texture.sample(uv, Vec2::ZERO, Vec2::ZERO, sampler)));
        }
        let dx = uv_at(centre + I64Vec2::new(ONE, 0)) - uv;
        let dy = uv_at(centre + I64Vec2::new(0, ONE)) - uv;
        Some((uv, texture.sample(uv, dx, dy, sampler)))
    }

    /// The lighting of triangle `t` at weights `b` with surface colour `surface`, by the shading
    /// frequency: the face's own terms (flat) or the vertices' terms interpolated (Gouraud) — a
    /// texture then modulates their ambient and diffuse terms, as OpenGL's `GL_MODULATE` does — or
    /// lighting evaluated here with the interpolated position and normal (Phong). `None` when unlit.
    fn terms_of(
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
                    // r = 2(n·v)n − v, the mirror direction of the view vector: a mirror of
                    // reflectivity k shows k of what it reflects and keeps 1 − k of its own
                    // ambient and diffuse light.
                    let (n, v) = (
                        terms.normal,
                        (self.scene.camera.eye - p).normalize_or_zero(),
                    );
                    let k = env.reflectivity.clamp(0.0, 1.0);
                    terms.reflected = env.cube.sample(2.0 * n.dot(v) * n - v) * k;
                    terms.ambient *= 1.0 - k;
                    terms.diffuse *= 1.0 - k;
                }
                Some(terms)
            }
        }
    }

    /// The colour of triangle `t` at the fixed-point position `at`, with its lighting terms and
    /// texture lookup: the surface colour is the texel (textured) or the interpolated vertex
    /// colour, then lit by the shading frequency.
    fn shade_at(
        &self,
        t: &RasterTriangle,
        at: I64Vec2,
    ) -> (Vec3, Option<ShadeTerms>, Option<(Vec2, Lookup)>) {
        let b = t.original_bary(t.lambda(at), self.settings.perspective_correct);
        let texel = self.texture_lookup(t, at);
        let surface = texel.map_or_else(|| self.color_of(t, b), |(_, l)| l.color);
        let terms = self.terms_of(t, b, surface, texel.is_some());
        (terms.map_or(surface, |t| t.color()), terms, texel)
    }

    /// Resolves window pixel `(x, y)`, whose image index is `i`.
    fn pixel(&self, x: u32, y: u32, i: usize) -> ResolvedPixel {
        let s = self.settings.samples.count();
        let tris = &self.samples.triangle[i * s..(i + 1) * s];
        let depths = &self.samples.depth[i * s..(i + 1) * s];
        let background = self.settings.background;
        let mut out = ResolvedPixel {
            terms: None,
            texture: None,
            coverage: 0,
            depth: depths.iter().sum::<f32>() / s as f32,
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
            let (color, terms, texel) = self.shade_at(owner, centre);
            return ResolvedPixel {
                terms,
                texture: texel,
                primitive: owner.primitive,
                owner: tris[0],
                color: color.to_array(),
                ..out
            };
        }
        // The owning primitive: most samples, ties to the earliest sample.
        let mut best = (0usize, NONE);
        for &t in tris.iter().filter(|&&t| t != NONE) {
            let prim = self.triangles[t as usize].primitive;
            let count = tris
                .iter()
                .filter(|&&u| u != NONE && self.triangles[u as usize].primitive == prim)
                .count();
            if count > best.0 {
                best = (count, t);
            }
        }
        let owner = &self.triangles[best.1 as usize];
        out.primitive = owner.primitive;
        out.owner = best.1;
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
            sum += color * weight;
            if tri.primitive == owner.primitive && out.terms.is_none() && out.texture.is_none() {
                out.terms = terms;
                out.texture = texel;
            }
        }
        out.color = (sum / s as f32).to_array();
        out
    }
}
