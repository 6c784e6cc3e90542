//! `render`: the stages in order, each recording into the [`FrameCapture`].
//!
//! vertex stage → primitive assembly → clipping → perspective division and viewport →
//! triangle setup (culling) → rasterization with the depth test → resolve to pixels.

use std::time::{Duration, Instant};

use glam::{Vec3, Vec4};
use serde::Serialize;

use crate::capture::{Fate, FrameCapture, Matrices, ObjectSummary, PixelBuffers, PrimitiveRecord};
use crate::clip::{self, ClipOutcome, ClipVertex};
use crate::raster::{NONE, RasterCounts, RasterTriangle, SampleBuffers, SetupRejection};
use crate::scene::{RenderSettings, Scene};
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
    let problems = scene.problems(settings);
    if !problems.is_empty() {
        return Err(RenderError::Invalid(problems));
    }
    let view = scene
        .view_matrix()
        .map_err(|e| RenderError::Invalid(vec![e.to_string()]))?;
    let aspect = settings.aspect();
    let matrices = Matrices {
        models: scene.objects.iter().map(|o| o.model_matrix()).collect(),
        projection: scene.projection.matrix(aspect),
        projection_games101: scene.projection.matrix_games101(aspect),
        viewport: NamedMatrix::new(
            "M_viewport",
            "x_w = (x+1)·width/2, y_w = (y+1)·height/2, z_w = (z+1)/2",
            transform::viewport(settings.width as f32, settings.height as f32),
        ),
        view,
    };
    let mut times = StageTimes::default();

    let t = Instant::now();
    let mut vertices = Vec::new();
    for (i, object) in scene.objects.iter().enumerate() {
        let m = VertexMatrices {
            model: matrices.models[i].matrix,
            view: matrices.view.matrix,
            projection: matrices.projection.matrix,
            viewport: matrices.viewport.matrix,
        };
        vertex::transform_object(object, i as u32, &m, &mut vertices);
    }
    times.vertex = t.elapsed();

    let t = Instant::now();
    let (primitives, triangles) = assemble_and_clip(scene, settings, &matrices, &vertices);
    times.clip_setup = t.elapsed();

    let t = Instant::now();
    let mut primitives = primitives;
    let mut samples = SampleBuffers::new(
        settings.width,
        settings.height,
        settings.samples,
        settings.depth_test.clear_value(),
    );
    for (i, tri) in triangles.iter().enumerate() {
        let c = samples.rasterize(tri, i as u32, settings.depth_test);
        let rec = &mut primitives[tri.primitive as usize];
        rec.counts.covered += c.covered;
        rec.counts.written += c.written;
    }
    times.raster = t.elapsed();

    let t = Instant::now();
    let pixels = resolve(settings, &samples, &triangles, &primitives, &vertices);
    times.resolve = t.elapsed();

    let capture = FrameCapture {
        settings: *settings,
        camera: scene.camera,
        projection: scene.projection,
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
        primitives,
        triangles,
        samples,
        pixels,
    };
    Ok((capture, times))
}

/// Primitive assembly, clipping, perspective division, viewport and triangle setup.
fn assemble_and_clip(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
) -> (Vec<PrimitiveRecord>, Vec<RasterTriangle>) {
    let size = (settings.width, settings.height);
    let viewport = matrices.viewport.matrix;
    let corners = [Vec3::X, Vec3::Y, Vec3::Z];
    let mut primitives =
        Vec::with_capacity(scene.objects.iter().map(|o| o.mesh.indices.len()).sum());
    let mut triangles = Vec::with_capacity(primitives.capacity());
    let mut row_base = 0u32;
    for (object_index, object) in scene.objects.iter().enumerate() {
        for tri in &object.mesh.indices {
            let id = primitives.len() as u32;
            let rows = tri.map(|i| row_base + i);
            let input = [0, 1, 2].map(|k| ClipVertex {
                clip: vertices[rows[k] as usize].clip,
                bary: corners[k],
            });
            let start = triangles.len() as u32;
            let (polygon, clipped) = match clip::clip_triangle(input) {
                ClipOutcome::Inside => (input.to_vec(), false),
                ClipOutcome::Clipped(poly) => (poly, true),
                ClipOutcome::Outside(plane) => {
                    primitives.push(PrimitiveRecord {
                        id,
                        object: object_index as u32,
                        vertices: rows,
                        fate: Fate::Outside { plane },
                        clipped_polygon: None,
                        triangles: [start, start],
                        counts: RasterCounts::default(),
                    });
                    continue;
                }
            };
            // Perspective division and viewport for each polygon vertex.
            let window: Vec<(Vec3, f32)> = polygon
                .iter()
                .map(|v| {
                    let inv_w = 1.0 / v.clip.w;
                    let ndc: Vec4 = (v.clip.truncate() * inv_w).extend(1.0);
                    ((viewport * ndc).truncate(), inv_w)
                })
                .collect();
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
            let fate = match (end > start, clipped, rejection) {
                (true, false, _) => Fate::Drawn,
                (true, true, _) => Fate::Clipped,
                (false, _, Some(SetupRejection::BackFace)) => Fate::Culled { back: true },
                (false, _, Some(SetupRejection::FrontFace)) => Fate::Culled { back: false },
                (false, _, _) => Fate::Degenerate,
            };
            primitives.push(PrimitiveRecord {
                id,
                object: object_index as u32,
                vertices: rows,
                fate,
                clipped_polygon: clipped.then_some(polygon),
                triangles: [start, end],
                counts: RasterCounts::default(),
            });
        }
        row_base += object.mesh.positions.len() as u32;
    }
    (primitives, triangles)
}

/// Resolves samples to pixels: coverage, mean depth, the owning primitive, barycentrics and
/// colour at the pixel centre (once per pixel and triangle, as multisampling shades).
fn resolve(
    settings: &RenderSettings,
    samples: &SampleBuffers,
    triangles: &[RasterTriangle],
    primitives: &[PrimitiveRecord],
    vertices: &[VertexRecord],
) -> PixelBuffers {
    let (w, h) = (settings.width, settings.height);
    let n = w as usize * h as usize;
    let s = settings.samples.count();
    let mut px = PixelBuffers {
        coverage: vec![0; n],
        depth: vec![0.0; n],
        primitive: vec![NONE; n],
        bary_perspective: vec![[0.0; 3]; n],
        bary_affine: vec![[0.0; 3]; n],
        color: vec![settings.background.to_array(); n],
    };
    let color_of = |t: &RasterTriangle, b: Vec3| -> Vec3 {
        let rows = primitives[t.primitive as usize].vertices;
        let c = rows.map(|r| vertices[r as usize].color);
        c[0] * b.x + c[1] * b.y + c[2] * b.z
    };
    for row in 0..h {
        let y = h - 1 - row;
        for x in 0..w {
            let i = (row * w + x) as usize;
            let tris = &samples.triangle[i * s..(i + 1) * s];
            let depths = &samples.depth[i * s..(i + 1) * s];
            px.depth[i] = depths.iter().sum::<f32>() / s as f32;
            let covered = tris.iter().filter(|&&t| t != NONE).count();
            px.coverage[i] = covered as u8;
            if covered == 0 {
                continue;
            }
            let centre = FrameCapture::pixel_centre_fixed(x, y);
            // The owning primitive: most samples, ties to the earliest sample.
            let mut best = (0usize, NONE);
            for &t in tris.iter().filter(|&&t| t != NONE) {
                let prim = triangles[t as usize].primitive;
                let count = tris
                    .iter()
                    .filter(|&&u| u != NONE && triangles[u as usize].primitive == prim)
                    .count();
                if count > best.0 {
                    best = (count, t);
                }
            }
            let owner = &triangles[best.1 as usize];
            let l = owner.lambda(centre);
            px.primitive[i] = owner.primitive;
            px.bary_perspective[i] = owner.original_bary(l, true).to_array();
            px.bary_affine[i] = owner.original_bary(l, false).to_array();
            // Colour: each distinct triangle once, at the centre, weighted by its samples.
            let mut sum = settings.background * (s - covered) as f32;
            let mut done: [u32; 16] = [NONE; 16];
            for (k, &t) in tris.iter().enumerate() {
                if t == NONE || done[..k].contains(&t) {
                    continue;
                }
                done[k] = t;
                let count = tris.iter().filter(|&&u| u == t).count() as f32;
                let tri = &triangles[t as usize];
                let b = tri.original_bary(tri.lambda(centre), settings.perspective_correct);
                sum += color_of(tri, b) * count;
            }
            px.color[i] = (sum / s as f32).to_array();
        }
    }
    px
}
