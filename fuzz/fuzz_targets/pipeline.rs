//! The whole pipeline on arbitrary triangles, camera, projection and settings: never a panic,
//! and a capture it returns has no NaN in its colour, depth or barycentric buffers.
#![no_main]

use arbitrary::Arbitrary;
use glam::{Vec2, Vec3};
use libfuzzer_sys::fuzz_target;
use pipeline::mesh::Mesh;
use pipeline::camera::{Camera, Projection};
use pipeline::light::Light;
use pipeline::raster::{CullMode, Samples};
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;
use pipeline::lighting::Frequency;

#[derive(Debug, Arbitrary)]
struct Input {
    triangles: Vec<[[f32; 3]; 3]>,
    eye: [f32; 3],
    at: [f32; 3],
    up: [f32; 3],
    projection: u8,
    a: f32,
    b: f32,
    near: f32,
    far: f32,
    width: u8,
    height: u8,
    samples: u8,
    mode: u8,
    translate: [f32; 3],
    rotate: [f32; 3],
    scale: [f32; 3],
}

fuzz_target!(|input: Input| {
    let v = |a: [f32; 3]| Vec3::from_array(a);
    let tris = &input.triangles[..input.triangles.len().min(64)];
    let mut mesh = Mesh {
        name: "fuzz".into(),
        ..Mesh::default()
    };
    for t in tris {
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(t.map(v));
        mesh.uvs.extend([Vec2::ZERO, Vec2::X, Vec2::Y]);
        mesh.indices.push([base, base + 1, base + 2]);
    }
    mesh.compute_vertex_normals(pipeline::mesh::NormalAveraging::Plain);
    let mut object = Object::new("fuzz", mesh);
    object.translate = v(input.translate);
    object.rotate_deg = v(input.rotate);
    object.scale = v(input.scale);
    let projection = match input.projection % 3 {
        0 => Projection::Perspective {
            fovy_deg: input.a,
            aspect: None,
            near: input.near,
            far: input.far,
        },
        1 => Projection::Frustum {
            left: -input.a,
            right: input.a,
            bottom: -input.b,
            top: input.b,
            near: input.near,
            far: input.far,
        },
        _ => Projection::Ortho {
            left: -input.a,
            right: input.a,
            bottom: -input.b,
            top: input.b,
            near: input.near,
            far: input.far,
        },
    };
    let scene = Scene {
        objects: vec![object],
        camera: Camera {
            eye: v(input.eye),
            at: v(input.at),
            up: v(input.up),
        },
        projection,
        lights: vec![
            Light::Ambient {
                intensity: Vec3::splat(0.2),
            },
            Light::Point {
                position: Vec3::new(1.0, 3.0, 2.0),
                intensity: Vec3::ONE,
                attenuation: Vec3::new(1.0, 0.0, 0.01),
            },
        ],
        shadow: None,
        figures: Vec::new(),
    };
    let settings = RenderSettings {
        width: u32::from(input.width % 48),
        height: u32::from(input.height % 48),
        samples: [Samples::X1, Samples::X4, Samples::X8, Samples::X16]
            [usize::from(input.samples % 4)],
        cull: [CullMode::None, CullMode::Back, CullMode::Front][usize::from(input.mode % 3)],
        shading: [
            Frequency::Unlit,
            Frequency::Flat,
            Frequency::Gouraud,
            Frequency::Phong,
        ][usize::from(input.mode / 3 % 4)],
        perspective_correct: input.mode & 0x80 == 0,
        ..RenderSettings::default()
    };
    if let Ok(c) = pipeline::render(&scene, &settings) {
        let px = &c.pixels;
        assert!(
            px.color.iter().flatten().all(|x| x.is_finite()),
            "NaN colour"
        );
        assert!(px.depth.iter().all(|x| x.is_finite()), "NaN depth");
        assert!(
            (0..px.owner.len())
                .filter_map(|i| c.barycentrics(i))
                .all(|b| b.perspective.iter().chain(&b.affine).all(|x| x.is_finite())),
            "NaN barycentrics"
        );
        // Every pixel's record can be built (the inspector's path).
        let _ = c.pixel_record(0, 0);
    }
});
