//! The colour buffer keeps what OpenGL's fixed-point buffer keeps: each sample's colour
//! clamped to [0, 1] when it is written (OpenGL 3.3 §4.1.8), and multisampling averages those.
//! So a silhouette pixel of a surface brighter than white, k of its 4 samples covered over a
//! black background, is k/4 of white — found by llvmpipe on a student's rim shader whose edge
//! pixels came out brighter in pipelens than there.

use std::sync::Arc;

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::mesh::BuiltinMesh;
use pipeline::raster::Samples;
use pipeline::scene::{ColorSource, Object, ObjectShader, Scene};
use pipeline::settings::RenderSettings;

use crate::support::render;

/// An unlit sphere of colour (3, 0.5, 2) on black, seen from the front.
fn bright_sphere() -> Scene {
    let mut sphere = Object::new(
        "sphere",
        BuiltinMesh::UvSphere {
            segments: 32,
            rings: 16,
        }
        .build(),
    );
    sphere.color = ColorSource::Uniform(Vec3::new(3.0, 0.5, 2.0));
    Scene {
        uniforms: Default::default(),
        objects: vec![sphere],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 4.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 40.0,
            aspect: None,
            near: 0.5,
            far: 20.0,
        },
        ..Scene::default()
    }
}

#[test]
fn an_edge_pixel_averages_its_samples_after_each_is_clamped() {
    let settings = RenderSettings {
        width: 96,
        height: 72,
        samples: Samples::X4,
        background: Vec3::ZERO,
        ..RenderSettings::default()
    };
    let built_in = bright_sphere();
    let mut student = bright_sphere();
    let programs = pipeline::shader::link(
        None,
        Some("#version 330 core\nout vec4 color;\nvoid main() {\n    color = vec4(3.0, 0.5, 2.0, 1.0);\n}\n"),
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    student.objects[0].code.shader = Some(ObjectShader {
        programs: Arc::new(programs),
        time: 0.0,
    });
    for (what, scene) in [("built-in", built_in), ("student's shader", student)] {
        let frame = render(&scene, &settings);
        let mut edges = 0;
        for (c, &k) in frame.pixels.color.iter().zip(&frame.pixels.coverage) {
            let share = f32::from(k) / 4.0;
            // Red and blue pass white (clamped to 1); green, 0.5, does not.
            let want = [share, 0.5 * share, share];
            for (got, want) in c.iter().zip(want) {
                assert!((got - want).abs() < 1e-6, "{what}: {c:?} with {k} samples");
            }
            edges += usize::from(k > 0 && k < 4);
        }
        assert!(edges > 50, "{what}: {edges} edge pixels");
    }
}
