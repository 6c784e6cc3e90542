//! Primitive assembly, clipping, perspective division, the viewport transform and triangle
//! setup (with culling), one primitive at a time in parallel chunks; and flat shading's lighting
//! of each face.

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use crate::capture::{Fate, Matrices, PrimitiveRecord};
use crate::clip::{self, ClipOutcome, ClipVertex};
use crate::raster::{RasterCounts, RasterTriangle, SetupRejection};
use crate::scene::Scene;
use crate::settings::RenderSettings;
use crate::shade::{self, ShadeTerms};
use crate::vertex::VertexRecord;

/// Primitive assembly, clipping, perspective division, viewport and triangle setup for every
/// triangle of every object: a record per primitive and the raster triangles, in order. The
/// primitives are independent, so they are processed in parallel chunks and joined in order.
pub(super) fn assemble_and_clip(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
) -> (Vec<PrimitiveRecord>, Vec<RasterTriangle>) {
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
pub(super) fn light_faces(
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
