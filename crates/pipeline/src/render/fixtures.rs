//! The scene and the check the resolve's tests share: runs and coarse shading are each
//! compared, pixel by pixel, with the per-pixel path on it.

use std::sync::Arc;

use glam::Vec3;

use super::resolve::{ResolveContext, ResolvedPixel};
use crate::buffers::Capture;
use crate::camera::{Camera, Projection};
use crate::capture::FrameCapture;
use crate::light::Light;
use crate::lighting::Frequency;
use crate::mesh::BuiltinMesh;
use crate::scene::{Object, Scene};
use crate::settings::RenderSettings;
use crate::texture::{CubeMap, Environment, SurfaceDetail, Texture};

/// A textured floor and sphere, a mirror torus and a bump-mapped cube, under every kind of
/// light, seen in perspective: runs with and without a texture, an environment, a detail map
/// (which the lanes leave to the per-pixel path), and an unlit object.
pub(crate) fn scene() -> Scene {
    let checker = Arc::new(Texture::checkerboard(64, 8));
    let mut floor = Object::new(
        "floor",
        BuiltinMesh::Plane {
            divisions: 2,
            repeat: 4.0,
        }
        .build(),
    );
    (floor.texture, floor.scale, floor.translate) = (
        Some(checker.clone()),
        Vec3::splat(4.0),
        Vec3::new(0.0, -1.0, 0.0),
    );
    let mut ball = Object::new(
        "ball",
        BuiltinMesh::UvSphere {
            segments: 24,
            rings: 12,
        }
        .build(),
    );
    ball.texture = Some(checker);
    let mut torus = Object::new(
        "torus",
        BuiltinMesh::Torus {
            minor: 0.3,
            segments: 24,
            sides: 12,
        }
        .build(),
    );
    torus.translate = Vec3::new(2.0, 0.0, -1.0);
    torus.environment = Some(Environment {
        cube: Arc::new(CubeMap::room(16)),
        reflectivity: 0.6,
    });
    let mut cube = Object::new("cube", BuiltinMesh::Cube.build());
    (cube.translate, cube.scale) = (Vec3::new(-2.2, 0.0, -1.0), Vec3::splat(0.7));
    cube.detail = Some(SurfaceDetail::Bump {
        height: Arc::new(Texture::bumps(32, 4)),
        strength: 0.5,
    });
    let mut unlit = Object::new("unlit", BuiltinMesh::Triangle.build());
    (unlit.translate, unlit.lit) = (Vec3::new(0.0, 1.6, -2.0), false);
    Scene {
        uniforms: Default::default(),
        objects: vec![floor, ball, torus, cube, unlit],
        camera: Camera {
            eye: Vec3::new(0.5, 1.5, 5.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 50.0,
            aspect: None,
            near: 0.5,
            far: 30.0,
        },
        lights: vec![
            Light::Ambient {
                intensity: Vec3::splat(0.2),
            },
            Light::Point {
                position: Vec3::new(3.0, 4.0, 3.0),
                intensity: Vec3::new(9.0, 8.0, 7.0),
                attenuation: Vec3::new(0.0, 0.0, 1.0),
            },
            Light::Directional {
                direction: Vec3::new(-1.0, -2.0, -0.5),
                intensity: Vec3::splat(0.3),
            },
            Light::Spot {
                position: Vec3::new(-2.0, 3.0, 2.0),
                direction: Vec3::new(0.6, -1.0, -0.6),
                cutoff_deg: 30.0,
                exponent: 2.0,
                intensity: Vec3::splat(0.8),
                attenuation: Vec3::new(1.0, 0.1, 0.0),
            },
        ],
        ..Scene::default()
    }
}

/// Asserts that the frame's buffers hold `want` at pixel `i`: its colour (as the buffer
/// stores it, clamped), depth, owner,
/// coverage and primitive, and, when every buffer is kept, its texture coordinates and
/// (as half floats) its normal.
pub(crate) fn assert_kept(
    px: &crate::capture::PixelBuffers,
    i: usize,
    want: &ResolvedPixel,
    settings: &RenderSettings,
    at: &str,
) {
    assert_eq!(
        (px.color[i], px.depth[i], px.owner[i], px.coverage[i]),
        (
            super::stored_color(Vec3::from(want.color)).to_array(),
            want.depth,
            want.owner,
            want.coverage
        ),
        "setting {at}"
    );
    assert_eq!(px.primitive[i], want.primitive, "setting {at}");
    if settings.capture == Capture::FULL {
        let uv = want.texture.map(|(uv, _)| uv.to_array());
        assert_eq!(px.texture_at(i).map(|t| t.uv), uv, "setting {at}");
        let normal = want.terms.map_or([0.0; 3], |t| t.normal.to_array());
        let half = |v: [f32; 3]| v.map(|c| half::f16::from_f32(c).to_f32());
        let lit = settings.shading != Frequency::Unlit;
        let kept = px.lighting_at(i).map(|l| l.normal);
        assert_eq!(kept, lit.then(|| half(normal)), "setting {at}");
    }
}

/// What the resolve of `frame` (rendered from `scene` with `settings`) read, for resolving its
/// pixels again by the per-pixel path.
pub(crate) fn context<'a>(
    frame: &'a FrameCapture,
    scene: &'a Scene,
    settings: &'a RenderSettings,
) -> ResolveContext<'a> {
    ResolveContext {
        path: crate::render::Path::Fast,
        derivatives: settings.capture.texturing || settings.sampler.uses_footprint(),
        vertex_shading: &frame.vertex_shading,
        face_shading: &frame.face_shading,
        scene,
        settings,
        samples: frame.samples.rows(),
        triangles: &frame.triangles,
        primitives: &frame.primitives,
        vertices: &frame.vertices,
    }
}
