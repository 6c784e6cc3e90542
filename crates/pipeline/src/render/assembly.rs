//! Primitive assembly, clipping, perspective division, the viewport transform and triangle
//! setup (with culling), one primitive at a time in parallel chunks; and flat shading's lighting
//! of each face.

use glam::Vec3;
use rayon::prelude::*;

use crate::capture::{Fate, Matrices, PrimitiveRecord};
use crate::clip::{self, ClipOutcome, ClipVertex};
use crate::raster::{RasterCounts, RasterTriangle, SetupRejection};
use crate::scene::Scene;
use crate::settings::RenderSettings;
use crate::shade::{self, ShadeTerms};
use crate::vertex::VertexRecord;

/// Primitive assembly, clipping, perspective division, viewport and triangle setup for every
/// triangle of every object: a record per primitive and the raster triangles, in order, written
/// over what `primitives` and `triangles` hold (their storage kept). The primitives are
/// independent, so they are processed in parallel chunks and joined in order.
pub(super) fn assemble_and_clip(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
    primitives: &mut Vec<PrimitiveRecord>,
    triangles: &mut Vec<RasterTriangle>,
) {
    // Where each object's primitives and vertex-table rows begin.
    let mut firsts = Vec::with_capacity(scene.objects.len());
    let (mut first_primitive, mut first_row) = (0usize, 0u32);
    for object in &scene.objects {
        firsts.push((first_primitive, first_row));
        first_primitive += object.mesh.indices.len();
        first_row += object.mesh.positions.len() as u32;
    }
    let total = first_primitive;
    // Primitive `id`: its object and the vertex-table rows of its corners.
    let primitive = |id: usize| {
        let object = firsts.partition_point(|&(first, _)| first <= id) - 1;
        let (first, row) = firsts[object];
        let corners = scene.objects[object].mesh.indices[id - first];
        (object as u32, corners.map(|i| row + i))
    };
    const CHUNK: usize = 2048;
    // A primitive gives one raster triangle, or none (outside, culled, degenerate), or a fan of
    // up to eight (clipped). Each chunk of primitives writes its records in place and its
    // triangles into its own slice of `triangles` — as many places as it has primitives, the
    // rare excess into a vector of its own — and the chunks' triangles are then moved
    // together, in order. No memory is taken from the system for a frame of the same scene.
    resize_over(primitives, total, unwritten);
    resize_over(triangles, total, RasterTriangle::default);
    let fans: Vec<(usize, Vec<RasterTriangle>)> = primitives
        .par_chunks_mut(CHUNK)
        .zip(triangles.par_chunks_mut(CHUNK))
        .enumerate()
        .map(|(c, (records, places))| {
            let mut fan = Fan {
                places,
                count: 0,
                excess: Vec::new(),
            };
            for (k, record) in records.iter_mut().enumerate() {
                let id = c * CHUNK + k;
                let (object, rows) = primitive(id);
                *record = assemble_one(
                    id as u32, object, rows, settings, matrices, vertices, &mut fan,
                );
            }
            (fan.count, fan.excess)
        })
        .collect();
    let starts = gather(triangles, &fans, CHUNK);
    primitives
        .par_chunks_mut(CHUNK)
        .zip(starts)
        .for_each(|(records, start)| {
            for r in records {
                r.triangles = r.triangles.map(|t| t + start);
            }
        });
}

/// Where one chunk of primitives puts its raster triangles: its places in the frame's list,
/// then, when it has more triangles than primitives, `excess`.
struct Fan<'a> {
    places: &'a mut [RasterTriangle],
    count: usize,
    excess: Vec<RasterTriangle>,
}

impl Fan<'_> {
    fn push(&mut self, t: RasterTriangle) {
        match self.places.get_mut(self.count) {
            Some(place) => *place = t,
            None => self.excess.push(t),
        }
        self.count += 1;
    }
}

/// Moves each chunk's triangles together, in order — chunk `c` wrote `count` of them from
/// place `c·chunk` on, its `excess` aside — and returns where each chunk's now begin. The moves
/// go towards the front, in order, so each reads places not yet written; when an excess would
/// overtake a later chunk's places the list is rebuilt instead.
fn gather(
    triangles: &mut Vec<RasterTriangle>,
    fans: &[(usize, Vec<RasterTriangle>)],
    chunk: usize,
) -> Vec<u32> {
    let mut starts = Vec::with_capacity(fans.len());
    let mut next = 0;
    for (count, _) in fans {
        starts.push(next);
        next += count;
    }
    let overtakes =
        next > triangles.len() || starts.iter().enumerate().any(|(c, &s)| s > c * chunk);
    if overtakes {
        let mut all = Vec::with_capacity(next);
        for (c, (count, excess)) in fans.iter().enumerate() {
            let placed = count - excess.len();
            all.extend_from_slice(&triangles[c * chunk..c * chunk + placed]);
            all.extend_from_slice(excess);
        }
        *triangles = all;
    } else {
        for ((c, (count, excess)), &start) in fans.iter().enumerate().zip(&starts) {
            let placed = count - excess.len();
            if start != c * chunk {
                triangles.copy_within(c * chunk..c * chunk + placed, start);
            }
            triangles[start + placed..start + count].copy_from_slice(excess);
        }
        triangles.truncate(next);
    }
    starts.into_iter().map(|s| s as u32).collect()
}

/// `v` made `len` long without writing what it will be overwritten with: shortened, or (the
/// first frame, a bigger scene) grown with `fill`.
fn resize_over<T>(v: &mut Vec<T>, len: usize, fill: impl FnMut() -> T) {
    if v.len() >= len {
        v.truncate(len);
    } else {
        v.resize_with(len, fill);
    }
}

/// A record about to be overwritten.
fn unwritten() -> PrimitiveRecord {
    PrimitiveRecord {
        id: 0,
        object: 0,
        vertices: [0; 3],
        fate: Fate::Degenerate,
        clipped_polygon: None,
        triangles: [0; 2],
        counts: RasterCounts::default(),
    }
}

/// One primitive through clipping, division, viewport and setup: its raster triangles are
/// pushed onto `triangles` (their range, relative to the chunk's, is in the record).
fn assemble_one(
    id: u32,
    object: u32,
    rows: [u32; 3],
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &[VertexRecord],
    triangles: &mut Fan,
) -> PrimitiveRecord {
    let size = (settings.width, settings.height);
    let viewport = matrices.viewport.matrix;
    let corners = [Vec3::X, Vec3::Y, Vec3::Z];
    let input = [0, 1, 2].map(|k| ClipVertex {
        clip: vertices[rows[k] as usize].clip,
        bary: corners[k],
    });
    let start = triangles.count as u32;
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
    // Perspective division and viewport for each polygon vertex (at most 10): a triangle wholly
    // inside has its corners' window positions in the vertex table already (`w > 0` there).
    let mut window = [(Vec3::ZERO, 0.0f32); 10];
    let inside = matches!(outcome, ClipOutcome::Inside);
    for (k, (slot, v)) in window.iter_mut().zip(polygon).enumerate() {
        let recorded = if inside {
            vertices[rows[k] as usize].window
        } else {
            None
        };
        *slot = match recorded {
            Some(w) => (w, 1.0 / v.clip.w),
            None => {
                let (_, w, inv_w) = crate::vertex::to_window(v.clip, &viewport);
                (w, inv_w)
            }
        };
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
    let end = triangles.count as u32;
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
/// coordinates), at its provoking vertex `p2` with that vertex's colour, as OpenGL's `flat`
/// takes every value from the last vertex (white for a textured surface, whose texel then
/// modulates the result per pixel). One entry per primitive; faces
/// that are not drawn get zero terms. Appended to `faces` (the frame's storage, empty).
pub(super) fn light_faces(
    scene: &Scene,
    settings: &RenderSettings,
    vertices: &[VertexRecord],
    primitives: &[PrimitiveRecord],
    faces: &mut Vec<ShadeTerms>,
) {
    faces.par_extend(primitives.par_iter().with_min_len(1024).map(|prim| {
        if prim.triangles[1] == prim.triangles[0] {
            return ShadeTerms::default();
        }
        let v = prim.vertices.map(|r| &vertices[r as usize]);
        let p = v.map(|v| v.world.truncate());
        let normal = (p[1] - p[0]).cross(p[2] - p[0]);
        let object = &scene.objects[prim.object as usize];
        if !object.lit {
            return ShadeTerms::default();
        }
        let color = if object.texture.is_some() && !object.mesh.uvs.is_empty() {
            Vec3::ONE
        } else {
            v[2].color
        };
        shade::shade(
            p[2],
            normal,
            scene.camera.eye,
            color,
            &scene.lights,
            &object.material,
            settings.reflection,
        )
    }));
}
