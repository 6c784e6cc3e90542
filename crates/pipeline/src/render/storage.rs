//! The storage a frame is written into: that of a capture no longer shown, emptied.

use crate::capture::{FrameCapture, PixelBuffers, PrimitiveRecord};
use crate::lighting::ShadeTerms;
use crate::raster::{RasterTriangle, SampleBuffers};
use crate::vertex::VertexRecord;

/// The storage of a capture no longer needed, emptied, for the next frame to write into: a
/// frame of a million triangles writes some 350 MB of records, and memory fresh from the system
/// costs a page fault and a zeroing every 4 KiB (measured: half the frame) before a byte of it
/// is written.
#[derive(Default)]
pub(super) struct Storage {
    pub(super) vertices: Vec<VertexRecord>,
    pub(super) vertex_shading: Vec<ShadeTerms>,
    pub(super) face_shading: Vec<ShadeTerms>,
    pub(super) primitives: Vec<PrimitiveRecord>,
    pub(super) triangles: Vec<RasterTriangle>,
    pub(super) samples: Option<SampleBuffers>,
    pub(super) pixels: PixelBuffers,
    /// The vertex shaders' output buffers, one per object that ran one.
    pub(super) shader_outputs: Vec<Vec<f32>>,
}

impl Storage {
    pub(super) fn of(spare: Option<FrameCapture>) -> Self {
        let Some(c) = spare else {
            return Self::default();
        };
        fn empty<T>(mut v: Vec<T>) -> Vec<T> {
            v.clear();
            v
        }
        Self {
            vertices: empty(c.vertices),
            vertex_shading: empty(c.vertex_shading),
            face_shading: empty(c.face_shading),
            // Written over in place, and resized, by the assembly.
            primitives: c.primitives,
            triangles: c.triangles,
            samples: Some(c.samples),
            pixels: c.pixels,
            shader_outputs: c
                .shaders
                .map(|s| {
                    s.vertex_results
                        .into_iter()
                        .flatten()
                        .map(|r| r.values)
                        .collect()
                })
                .unwrap_or_default(),
        }
    }
}
