//! Surface detail: bump and normal mapping tilt the normal in the tangent frame, displacement
//! moves vertices, a cube map is read by direction and mirrored by a sphere.

use glam::{Vec2, Vec3};
use pipeline::camera::{Camera, Projection};
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;
use pipeline::texture::{Level, Texture};

use crate::support::render;
use crate::texture::{grey, quad_mesh};

/// The quad of [`textured_quad`] lit per pixel with a surface detail, facing the camera.
fn detailed_quad(detail: pipeline::texture::SurfaceDetail) -> pipeline::capture::FrameCapture {
    use pipeline::light::Light;
    use pipeline::lighting::Frequency;
    let mesh = quad_mesh();
    let mut quad = Object::new("quad", mesh);
    quad.detail = Some(detail);
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![quad],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 3.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 60.0,
            aspect: None,
            near: 0.1,
            far: 100.0,
        },
        lights: vec![Light::Directional {
            direction: Vec3::NEG_Z,
            intensity: Vec3::ONE,
        }],
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: 65,
        height: 65,
        shading: Frequency::Phong,
        ..RenderSettings::default()
    };
    render(&scene, &settings)
}

#[test]
fn bump_and_normal_maps_tilt_the_normal_in_the_tangent_frame() {
    use pipeline::texture::SurfaceDetail;
    let centre = 32 * 65 + 32;
    // A height ramp h = 0.01·i along u: dU = k·(h(u + 1/w) − h(u)) = k·0.01, dV = 0, so
    // n = normalize(−dU, 0, 1) (T = +x, B = +y for this quad).
    let ramp = Texture::from_level(
        "ramp",
        Level {
            width: 64,
            height: 64,
            texels: (0..64 * 64).map(|k| grey((k % 64) as f32 * 0.01)).collect(),
        },
    );
    let k = 5.0;
    let c = detailed_quad(SurfaceDetail::Bump {
        height: std::sync::Arc::new(ramp),
        strength: k,
    });
    // The lighting buffers keep half floats: 11 significant bits, so within 2⁻¹¹ ≈ 5·10⁻⁴.
    let n = Vec3::from(c.pixels.shading.as_ref().expect("lit").at(centre).normal);
    let expect = Vec3::new(-k * 0.01, 0.0, 1.0).normalize();
    assert!((n - expect).length() < 1e-3, "{n} vs {expect}");
    // A normal map storing the tangent-space normal (0.6, 0, 0.8) as (n + 1)/2.
    let stored = (Vec3::new(0.6, 0.0, 0.8) + Vec3::ONE) / 2.0;
    let map = Texture::from_level(
        "normal",
        Level {
            width: 4,
            height: 4,
            texels: vec![stored; 16],
        },
    );
    let c = detailed_quad(SurfaceDetail::Normal(std::sync::Arc::new(map)));
    let n = Vec3::from(c.pixels.shading.as_ref().expect("lit").at(centre).normal);
    assert!((n - Vec3::new(0.6, 0.0, 0.8)).length() < 1e-3, "{n}");
    // The diffuse term follows: light along −z, n·l = 0.8.
    let d = c.pixels.shading.as_ref().expect("lit").at(centre).n_dot_l;
    assert!((d - 0.8).abs() < 1e-3);
}

#[test]
fn displacement_moves_each_vertex_along_its_normal_by_the_height() {
    use pipeline::mesh::BuiltinMesh;
    use pipeline::texture::Displacement;
    // Vertex p moves to p + n·k·h(u, v): a constant white map (h = 1) inflates the unit sphere
    // to radius 1 + k.
    let white = Texture::from_level(
        "white",
        Level {
            width: 2,
            height: 2,
            texels: vec![Vec3::ONE; 4],
        },
    );
    let mut sphere = Object::new(
        "s",
        BuiltinMesh::UvSphere {
            segments: 16,
            rings: 8,
        }
        .build(),
    );
    sphere.displacement = Some(Displacement {
        height: std::sync::Arc::new(white),
        scale: 0.5,
    });
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![sphere],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 6.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::default(),
        ..Scene::default()
    };
    let c = render(&scene, &RenderSettings::default());
    for v in &c.vertices {
        assert!((v.object_pos.truncate().length() - 1.5).abs() < 1e-5);
    }
    // A grey level of 0.25 everywhere moves by k·0.25 along the normal.
    let grey4 = Texture::from_level(
        "g",
        Level {
            width: 2,
            height: 2,
            texels: vec![grey(0.25); 4],
        },
    );
    let d = Displacement {
        height: std::sync::Arc::new(grey4),
        scale: 2.0,
    };
    assert!(
        (d.offset(Vec2::new(0.3, 0.7)) - 0.5).abs() < 1e-6,
        "luminance of grey 0.25 is 0.25"
    );
}

/// A cube map whose faces (+x, −x, +y, −y, +z, −z) are each one colour, 2 × 2 texels.
fn constant_faces(colors: [Vec3; 6]) -> pipeline::texture::CubeMap {
    pipeline::texture::CubeMap {
        faces: colors.map(|c| Level {
            width: 2,
            height: 2,
            texels: vec![c; 4],
        }),
    }
}

#[test]
fn cube_map_faces_and_a_mirror_sphere() {
    use pipeline::light::Light;
    use pipeline::lighting::Frequency;
    use pipeline::mesh::BuiltinMesh;
    use pipeline::texture::{CubeMap, Environment};
    // Direction → face and (s, t), by the table in the docs.
    assert_eq!(CubeMap::face_coords(Vec3::Z), (4, Vec2::new(0.5, 0.5)));
    let (f, st) = CubeMap::face_coords(Vec3::new(0.5, 0.2, 1.0));
    assert_eq!(f, 4);
    assert!((st - Vec2::new(0.75, 0.6)).length() < 1e-6);
    assert_eq!(CubeMap::face_coords(Vec3::new(-2.0, 1.0, 0.5)).0, 1);
    assert_eq!(CubeMap::face_coords(Vec3::new(0.1, -3.0, 0.5)).0, 3);
    // Six constant faces; a perfect mirror sphere seen head-on reflects the face behind the eye.
    let colors = [
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::ONE,
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(0.0, 1.0, 1.0),
    ];
    let cube = constant_faces(colors);
    let mut sphere = Object::new(
        "mirror",
        BuiltinMesh::UvSphere {
            segments: 64,
            rings: 32,
        }
        .build(),
    );
    sphere.environment = Some(Environment {
        cube: std::sync::Arc::new(cube),
        reflectivity: 1.0,
    });
    sphere.material.ks = Vec3::ZERO;
    let scene = Scene {
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
        lights: vec![Light::Ambient {
            intensity: Vec3::ONE,
        }],
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: 65,
        height: 65,
        shading: Frequency::Phong,
        ..RenderSettings::default()
    };
    let c = render(&scene, &settings);
    let centre = Vec3::from(c.pixels.color[32 * 65 + 32]);
    assert!(
        (centre - colors[4]).length() < 1e-4,
        "the +z face: {centre}"
    );
    // The reflected term is its own buffer: all of the colour here (no ambient is left).
    let sh = c.pixels.shading.as_ref().expect("lighting buffers");
    let reflected = Vec3::from(sh.at(32 * 65 + 32).reflected);
    assert!(
        (reflected - centre).length() < 1e-3,
        "{reflected} vs {centre}"
    );
    assert!(
        c.buffers()
            .contains(&pipeline::buffers::BufferKind::Reflected)
    );
}

#[test]
fn the_bumps_normal_map_matches_bump_mapping_the_bumps() {
    use pipeline::texture::SurfaceDetail;
    // The built-in normal map is the bumps' slope stored as (n + 1)/2: normal mapping with it
    // tilts the normals as bump mapping with the height does (up to the difference between
    // central and forward differences, which part only at the bumps' rims, where the slope of
    // √(1 − r²) is unbounded).
    let k = 6.0;
    let bump = detailed_quad(SurfaceDetail::Bump {
        height: std::sync::Arc::new(Texture::bumps(512, 8)),
        strength: k,
    });
    let mapped = detailed_quad(SurfaceDetail::Normal(std::sync::Arc::new(
        Texture::bump_normals(512, 8, k),
    )));
    let (a, b) = (
        &bump.pixels.shading.as_ref().expect("lit").normal,
        &mapped.pixels.shading.as_ref().expect("lit").normal,
    );
    let (mut tilted, mut apart, mut covered) = (0, 0, 0);
    for (i, (p, q)) in a.iter().zip(b).enumerate() {
        if bump.pixels.coverage[i] == 0 {
            continue;
        }
        let (p, q) = (Vec3::from(p.map(f32::from)), Vec3::from(q.map(f32::from)));
        covered += 1;
        apart += usize::from(p.angle_between(q) > 0.15);
        tilted += usize::from(p.z < 0.99 && q.z < 0.99);
    }
    assert!(
        tilted > covered / 4,
        "the bumps tilt the normals ({tilted} of {covered})"
    );
    assert!(
        apart * 10 < covered,
        "{apart} of {covered} pixels differ by more than 0.15 rad"
    );
}

/// A shader's `uniform samplerCube environment;` reads the cube map by direction: with a colour
/// of its own on each face, the direction's major axis picks the colour (OpenGL's cube map
/// table: +x, −x, +y, −y, +z, −z), whatever the direction's length. Declared as the other
/// sampler type, pipelens' texture is an error that says which type it binds.
#[test]
fn a_shader_s_sampler_cube_reads_the_face_a_direction_points_at() {
    use pipeline::shader::{self, Bindings, Bound, LANES, Stage, Uniforms};
    let src = "#version 330 core\nuniform samplerCube environment;\nin vec3 d;\nout vec4 color;\nvoid main() { color = texture(environment, d); }\n";
    let p = shader::compile(Stage::Fragment, src).expect("compiles");
    let colors = [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(0.0, 1.0, 1.0),
        Vec3::new(1.0, 0.0, 1.0),
    ];
    let cube = constant_faces(colors);
    // One direction towards each face, in face order, of assorted lengths.
    let dirs = [
        Vec3::new(2.0, 0.5, -0.3),
        Vec3::new(-3.0, 1.0, 1.0),
        Vec3::new(0.1, 5.0, 0.2),
        Vec3::new(0.2, -0.4, 0.1),
        Vec3::new(0.0, 0.0, 0.01),
        Vec3::new(0.3, 0.2, -0.9),
    ];
    let mut rows = vec![0u32; 3 * LANES];
    for (l, d) in dirs.iter().enumerate() {
        for (c, x) in d.to_array().iter().enumerate() {
            rows[c * LANES + l] = x.to_bits();
        }
    }
    let mut m = p.machine();
    p.set_uniforms(&mut m, &Uniforms::default());
    let bound = [Some(Bound::Cube(&cube))];
    m.run(
        &[&rows],
        dirs.len(),
        0b11_1111,
        &Bindings { textures: &bound },
    )
    .expect("runs");
    let out = m.result();
    for (l, want) in colors.iter().enumerate() {
        let got = Vec3::new(
            f32::from_bits(out[l]),
            f32::from_bits(out[LANES + l]),
            f32::from_bits(out[2 * LANES + l]),
        );
        assert_eq!(got, *want, "direction {:?}", dirs[l]);
    }
    for (src, says) in [
        (
            "#version 330 core\nuniform sampler2D environment;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n",
            "pipelens binds `environment` as a samplerCube, declared here as sampler2D",
        ),
        (
            "#version 330 core\nuniform samplerCube tex;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n",
            "pipelens binds `tex` as a sampler2D, declared here as samplerCube",
        ),
    ] {
        let Err(errors) = shader::compile(Stage::Fragment, src) else {
            panic!("compiled:\n{src}");
        };
        let text: Vec<String> = errors.iter().map(ToString::to_string).collect();
        assert!(text.iter().any(|e| e.contains(says)), "{text:?}");
        assert!(
            text.iter().any(|e| e.starts_with("line 2,")),
            "at line 2: {text:?}"
        );
    }
}
