//! `capture.json`: the numbers of a capture, for handouts, scripts and other tools.

use glam::Vec3;
use pipeline::capture::FrameCapture;
use pipeline::raster::{RasterTriangle, SUBPIXEL_BITS};
use serde::Serialize;
use serde_json::{Value, json};

/// A raster triangle as `capture.json` writes it: its own fields and its corners' barycentric
/// weights with respect to the original triangle (`bary`, which the triangle keeps as indices
/// into its primitive).
#[derive(Serialize)]
struct RasterTriangleJson<'a> {
    #[serde(flatten)]
    triangle: &'a RasterTriangle,
    bary: [Vec3; 3],
}

/// The conventions a reader needs to interpret the numbers.
fn conventions() -> Value {
    json!({
        "matrices": "row-major: matrix[i][j] is row i, column j; column vectors, p' = M·p",
        "window": "origin at the bottom-left of the viewport, x right, y up; pixel (i, j) covers [i, i+1]×[j, j+1], centre (i+0.5, j+0.5); image row = height − 1 − j",
        "depth": "window depth z_w = (z_ndc + 1)/2 in [0, 1] (glDepthRange(0, 1)); interpolated linearly in screen space on the plane through the unsnapped window positions (snapping decides coverage only); exact floats in depth.pfm",
        "clipping": "Sutherland–Hodgman in clip space against all six planes −w ≤ x, y, z ≤ w (near first) and w ≥ 1e-5; no guard band",
        "rasterization": format!("vertices snapped to 1/{} pixel; edge functions on integers; top-left fill rule; counter-clockwise is front", 1 << SUBPIXEL_BITS),
        "barycentrics": "bary_affine = screen-space λ; bary_perspective = (λ_i/w_i)/Σ(λ_k/w_k); both relative to the original triangle's vertices",
        "multisampling": "standard sample patterns (1, rotated-grid 4, 8, 16), Direct3D's numbers taken with y up as Mesa's llvmpipe takes them; colour evaluated once per pixel and triangle at the pixel centre; pixel = mean of its samples",
    })
}

/// The JSON document of a capture. `files` lists the exported files with what each holds;
/// at most `max_records` vertex rows, primitives and raster triangles are written.
#[must_use]
pub fn capture_json(
    capture: &FrameCapture,
    files: &[(String, String)],
    max_records: usize,
) -> Value {
    let take = |n: usize| n.min(max_records);
    json!({
        "pipelens": env!("CARGO_PKG_VERSION"),
        "conventions": conventions(),
        "settings": capture.settings,
        "camera": capture.camera,
        "projection": capture.projection,
        "objects": capture.objects,
        "matrices": capture.matrices,
        "depth_range": capture.depth_range(),
        "files": files.iter().map(|(name, what)| json!({"file": name, "holds": what})).collect::<Vec<_>>(),
        "counts": {
            "vertices": capture.vertices.len(),
            "primitives": capture.primitives.len(),
            "raster_triangles": capture.triangles.len(),
            "written": {
                "vertices": take(capture.vertices.len()),
                "primitives": take(capture.primitives.len()),
                "raster_triangles": take(capture.triangles.len()),
            },
        },
        "vertices": &capture.vertices[..take(capture.vertices.len())],
        "primitives": &capture.primitives[..take(capture.primitives.len())],
        "raster_triangles": capture.triangles[..take(capture.triangles.len())]
            .iter()
            .map(|t| RasterTriangleJson {
                triangle: t,
                bary: capture.primitives.get(t.primitive as usize)
                    .map_or([Vec3::ZERO; 3], |p| p.bary_corners(t)),
            })
            .collect::<Vec<_>>(),
        "shaders": capture.shaders.as_ref().map(|sh| json!({
            "fragments": sh.fragments,
            "discarded": sh.discarded,
            "not_finite": sh.not_finite,
            "vertex_results": sh.vertex_results.iter().map(|r| r.as_ref().map(|r| json!({
                "first_vertex_row": r.first,
                "floats_per_vertex": r.stride,
            }))).collect::<Vec<_>>(),
            "inspected_pixel": sh.pixel,
        })),
    })
}
