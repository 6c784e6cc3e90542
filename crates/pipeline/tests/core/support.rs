//! Helpers shared by the tests: scenes whose world coordinates are window pixels, and a small
//! deterministic random source.

use glam::{Vec2, Vec3};
use pipeline::camera::{Camera, Projection};
use pipeline::capture::FrameCapture;
use pipeline::mesh::Mesh;
use pipeline::raster::NONE;
use pipeline::raster::{DepthTest, Samples};
use pipeline::scene::{ColorSource, Object, Scene};
use pipeline::settings::RenderSettings;

/// A scene in which world `(x, y)` is window `(x, y)` (an orthographic camera over
/// `[0, w] × [0, h]`), holding one object made of `triangles` (each CCW or not, as given).
pub fn pixel_scene(w: u32, h: u32, triangles: &[[Vec2; 3]]) -> (Scene, RenderSettings) {
    let mut mesh = Mesh {
        name: "test".into(),
        ..Mesh::default()
    };
    for (k, t) in triangles.iter().enumerate() {
        for p in t {
            mesh.positions.push(p.extend(0.0));
            mesh.normals.push(Vec3::Z);
            mesh.colors
                .push(Vec3::splat(k as f32 / triangles.len().max(1) as f32));
        }
        let b = 3 * k as u32;
        mesh.indices.push([b, b + 1, b + 2]);
    }
    let mut object = Object::new("test", mesh);
    object.color = ColorSource::Vertex;
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![object],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 1.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Ortho {
            left: 0.0,
            right: w as f32,
            bottom: 0.0,
            top: h as f32,
            near: 0.0,
            far: 2.0,
        },
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: w,
        height: h,
        samples: Samples::X1,
        depth_test: DepthTest::Always,
        ..RenderSettings::default()
    };
    (scene, settings)
}

/// Renders, failing the test with the error if the scene is rejected.
pub fn render(scene: &Scene, settings: &RenderSettings) -> FrameCapture {
    match pipeline::render(scene, settings) {
        Ok(c) => c,
        Err(e) => panic!("render failed: {e}"),
    }
}

/// The window position of sample `s` of window pixel `(x, y)`, from the published pattern
/// (1/16 pixel offsets from the centre) written out here independently, the numbers taken with
/// y up as Mesa's llvmpipe takes them.
pub fn sample_position(samples: Samples, x: u32, y: u32, s: usize) -> Vec2 {
    let pattern: &[(f32, f32)] = match samples {
        Samples::X1 => &[(0.0, 0.0)],
        Samples::X4 => &[(-2.0, -6.0), (6.0, -2.0), (-6.0, 2.0), (2.0, 6.0)],
        _ => unreachable!("tests use 1 or 4 samples"),
    };
    let (dx, dy) = pattern[s];
    Vec2::new(x as f32 + 0.5 + dx / 16.0, y as f32 + 0.5 + dy / 16.0)
}

/// Counts how often each sample is covered over all primitives (depth test `Always` keeps every
/// write visible in the counts) and returns (sum of per-primitive covered counts, distinct samples).
pub fn cover_counts(capture: &pipeline::capture::FrameCapture) -> (u64, u64) {
    let sum = capture
        .primitives
        .iter()
        .map(|p| u64::from(p.counts.covered))
        .sum();
    let distinct = capture
        .samples
        .triangle
        .iter()
        .filter(|&&t| t != NONE)
        .count() as u64;
    (sum, distinct)
}

/// A xorshift generator of 32-bit words from `seed` (not zero): reproducible random input
/// without a dependency.
pub fn xorshift(seed: u32) -> impl FnMut() -> u32 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    }
}

/// Uniform floats in `[0, 1]` from [`xorshift`].
pub fn uniform(seed: u32) -> impl FnMut() -> f32 {
    let mut bits = xorshift(seed);
    move || bits() as f32 / u32::MAX as f32
}
