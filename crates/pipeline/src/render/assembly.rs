//! Primitive assembly, clipping, perspective division, the viewport transform and triangle
//! setup (with culling), one primitive at a time in parallel chunks; and flat shading's lighting
//! of each face.

use glam::{I64Vec2, Vec3, Vec4};
use rayon::prelude::*;

use crate::capture::{Fate, Matrices, PrimitiveRecord};
use crate::clip::{self, ClipOutcome, ClipVertex};
use crate::lighting::{self, ShadeTerms};
use crate::raster::{Corners, RasterCounts, RasterTriangle, SetupRejection, snap_xy};
use crate::scene::Scene;
use crate::settings::RenderSettings;
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
    // together, in order, in the storage of the frame before. (The vertices packed for the
    // assembly are a vector of their own each frame, 48 bytes a vertex.)
    let packed: Vec<AssemblyVertex> = vertices.par_iter().map(AssemblyVertex::of).collect();
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
                    id as u32, object, rows, settings, matrices, &packed, &mut fan,
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

/// What primitive assembly reads of a vertex, packed: its clip position, and where `w > 0` its
/// window position and that position snapped to the sub-pixel grid. A vertex's record is about
/// 140 bytes, read for each of the (about six) triangles around it; these 48 are written once a
/// frame, in parallel, and a vertex is snapped once rather than once for each of its triangles.
#[derive(Clone, Copy)]
struct AssemblyVertex {
    clip: Vec4,
    window: Vec3,
    /// Whether the vertex has a window position (`w > 0`): `window` and `fixed` are its.
    placed: bool,
    fixed: I64Vec2,
}

impl AssemblyVertex {
    fn of(v: &VertexRecord) -> Self {
        let window = v.window.unwrap_or(Vec3::ZERO);
        Self {
            clip: v.clip,
            window,
            placed: v.window.is_some(),
            fixed: snap_xy(window),
        }
    }
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
/// place `c·chunk` on, its `excess` aside — and returns where each chunk's now begin. When an
/// excess would overtake a later chunk's places the list is rebuilt; otherwise the chunks move
/// in parallel, each within its own destination `starts[c]..starts[c + 1]`, which holds all of
/// its places but those the next chunk's destination covers (its "tail", when chunks before it
/// dropped triangles: a uv sphere's degenerate pole triangles shift every later chunk), and
/// those tails are set aside first.
fn gather(
    triangles: &mut Vec<RasterTriangle>,
    fans: &[(usize, Vec<RasterTriangle>)],
    chunk: usize,
) -> Vec<u32> {
    let mut starts = Vec::with_capacity(fans.len() + 1);
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
        return starts.into_iter().map(|s| s as u32).collect();
    }
    starts.push(next);
    // Chunk c's places `c·chunk .. c·chunk + placed`; those from `starts[c + 1]` on (its tail)
    // lie in the next chunk's destination.
    let places = |c: usize| {
        let placed = fans[c].0 - fans[c].1.len();
        let tail = starts[c + 1].clamp(c * chunk, c * chunk + placed);
        (c * chunk, tail, c * chunk + placed)
    };
    let tails: Vec<Vec<RasterTriangle>> = (0..fans.len())
        .into_par_iter()
        .map(|c| {
            let (_, tail, end) = places(c);
            triangles[tail..end].to_vec()
        })
        .collect();
    let mut parts = Vec::with_capacity(fans.len());
    let mut rest = &mut triangles[..next];
    for c in 0..fans.len() {
        let (part, after) = rest.split_at_mut(starts[c + 1] - starts[c]);
        parts.push(part);
        rest = after;
    }
    parts
        .into_par_iter()
        .zip(tails)
        .enumerate()
        .for_each(|(c, (part, tail))| {
            let (first, tail_from, _) = places(c);
            let held = tail_from - first;
            if held > 0 {
                let from = first - starts[c];
                part.copy_within(from..from + held, 0);
            }
            part[held..held + tail.len()].copy_from_slice(&tail);
            let excess = &fans[c].1;
            part[held + tail.len()..].copy_from_slice(excess);
        });
    triangles.truncate(next);
    starts.pop();
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
    vertices: &[AssemblyVertex],
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
    if input.iter().any(|v| !v.clip.is_finite()) {
        return PrimitiveRecord {
            id,
            object,
            vertices: rows,
            fate: Fate::NotFinite,
            clipped_polygon: None,
            triangles: [start, start],
            counts: RasterCounts::default(),
        };
    }
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
    // Perspective division, viewport and snapping for each polygon vertex (at most 10): a
    // triangle wholly inside has its corners' window positions, snapped, in the vertex table
    // already (`w > 0` there).
    let mut window = [(Vec3::ZERO, I64Vec2::ZERO, 0.0f32); 10];
    let inside = matches!(outcome, ClipOutcome::Inside);
    for (k, (slot, v)) in window.iter_mut().zip(polygon).enumerate() {
        let recorded = if inside {
            let a = &vertices[rows[k] as usize];
            a.placed.then_some((a.window, a.fixed))
        } else {
            None
        };
        *slot = match recorded {
            Some((w, fixed)) => (w, fixed, 1.0 / v.clip.w),
            None => {
                let (_, w, inv_w) = crate::vertex::to_window(v.clip, &viewport);
                (w, snap_xy(w), inv_w)
            }
        };
    }
    let mut rejection = None;
    for k in 1..polygon.len() - 1 {
        let idx = [0, k, k + 1];
        match RasterTriangle::setup_snapped(
            id,
            (idx.map(|i| window[i].0), idx.map(|i| window[i].1)),
            idx.map(|i| window[i].2),
            if inside {
                Corners::ORIGINAL
            } else {
                Corners::fan(k as u8)
            },
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
        lighting::shade(
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{Corners, CullMode};

    /// A distinct raster triangle: its primitive number is `id`.
    fn triangle(id: u32) -> RasterTriangle {
        let corner = Vec3::new(0.0, 0.0, 0.5);
        let window = [corner, corner + Vec3::X, corner + Vec3::Y];
        RasterTriangle::setup(
            id,
            window,
            [1.0; 3],
            Corners::ORIGINAL,
            CullMode::None,
            (4, 4),
        )
        .expect("a proper triangle")
    }

    /// Chunks of `chunk` places each holding `counts[c]` triangles (those past `chunk` in
    /// its excess), gathered, against the same triangles concatenated in order.
    fn check(counts: &[usize], chunk: usize) {
        let mut id = 0;
        let mut triangles = vec![RasterTriangle::default(); counts.len() * chunk];
        let mut fans = Vec::new();
        let mut want = Vec::new();
        for (c, &count) in counts.iter().enumerate() {
            let mut excess = Vec::new();
            for k in 0..count {
                let t = triangle(id);
                id += 1;
                want.push(t);
                if k < chunk {
                    triangles[c * chunk + k] = t;
                } else {
                    excess.push(t);
                }
            }
            fans.push((count, excess));
        }
        let starts = gather(&mut triangles, &fans, chunk);
        assert_eq!(triangles, want, "counts {counts:?}");
        let mut next = 0;
        for (s, (count, _)) in starts.iter().zip(&fans) {
            assert_eq!(*s as usize, next);
            next += count;
        }
    }

    #[test]
    fn the_chunks_triangles_are_gathered_in_order_whatever_each_dropped_or_added() {
        // Full chunks; a drop in the first shifting every later one (a sphere's poles); drops
        // larger than a chunk; an excess after drops (moved in place); an excess that
        // overtakes (the list rebuilt); empty chunks; no chunks.
        for counts in [
            &[8, 8, 8][..],
            &[5, 8, 8, 8, 8],
            &[0, 0, 3, 8, 1, 8, 8],
            &[2, 2, 11, 8, 0, 9],
            &[8, 12, 8],
            &[0, 0, 0],
            &[],
        ] {
            check(counts, 8);
        }
        // Random counts from 0 to 1.5 chunks.
        let mut x = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..200 {
            let counts: Vec<usize> = (0..1 + x as usize % 20)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    (x % 13) as usize
                })
                .collect();
            check(&counts, 8);
        }
    }
}
