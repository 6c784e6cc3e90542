//! The student's shaders inside a frame: pipelens' own vertex and fragment stages, written as
//! GLSL and run by the shader machine, give the built-in path's pixels; the qualifiers
//! interpolate as GLSL says; `discard` and run-time errors reach the frame (the trace of a
//! frame's fragment shader: `shader_frame_trace.rs`).

use std::sync::Arc;

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::capture::FrameCapture;
use pipeline::light::{Light, Material};
use pipeline::lighting::{Frequency, Reflection};
use pipeline::mesh::BuiltinMesh;
use pipeline::raster::Samples;
use pipeline::scene::{ColorSource, Object, ObjectShader, Scene};
use pipeline::settings::RenderSettings;
use pipeline::texture::{Mipmap, Sampler, Texture};

use crate::support::render;

/// A sphere lit by every kind of light, seen from the front right.
pub(crate) fn sphere_scene(textured: bool) -> Scene {
    let mut sphere = Object::new(
        "sphere",
        BuiltinMesh::UvSphere {
            segments: 48,
            rings: 24,
        }
        .build(),
    );
    sphere.color = ColorSource::Uniform(Vec3::new(0.9, 0.6, 0.3));
    sphere.material = Material {
        ka: Vec3::splat(0.2),
        kd: Vec3::new(0.7, 0.6, 0.5),
        ks: Vec3::splat(0.5),
        shininess: 24.0,
    };
    sphere.rotate_deg = Vec3::new(10.0, 30.0, 0.0);
    if textured {
        sphere.texture = Some(Arc::new(Texture::checkerboard(256, 8)));
    }
    Scene {
        uniforms: Default::default(),
        objects: vec![sphere],
        camera: Camera {
            eye: Vec3::new(1.0, 0.5, 4.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 40.0,
            aspect: None,
            near: 0.5,
            far: 20.0,
        },
        lights: vec![
            Light::Ambient {
                intensity: Vec3::splat(0.3),
            },
            Light::Point {
                position: Vec3::new(3.0, 3.0, 3.0),
                intensity: Vec3::new(1.0, 0.9, 0.8),
                attenuation: Vec3::new(1.0, 0.05, 0.01),
            },
            Light::Directional {
                direction: Vec3::new(1.0, -0.5, -0.2),
                intensity: Vec3::splat(0.4),
            },
            Light::Spot {
                position: Vec3::new(-2.0, 1.0, 3.0),
                direction: Vec3::new(2.0, -1.0, -3.0),
                cutoff_deg: 20.0,
                exponent: 8.0,
                intensity: Vec3::splat(0.6),
                attenuation: Vec3::X,
            },
        ],
        ..Scene::default()
    }
}

pub(crate) fn settings() -> RenderSettings {
    RenderSettings {
        width: 160,
        height: 120,
        shading: Frequency::Phong,
        reflection: Reflection::BlinnPhong,
        sampler: Sampler {
            mipmap: Mipmap::None,
            ..Sampler::default()
        },
        ..RenderSettings::default()
    }
}

pub(crate) fn with_shaders(
    mut scene: Scene,
    vertex: Option<&str>,
    fragment: Option<&str>,
) -> Scene {
    let programs = pipeline::shader::link(vertex, fragment).unwrap_or_else(|e| panic!("{e:?}"));
    for o in &mut scene.objects {
        o.code.shader = Some(ObjectShader {
            programs: Arc::new(programs.clone()),
            time: 0.0,
        });
    }
    scene
}

/// The largest difference of any colour component between two frames, and where.
fn largest_difference(a: &FrameCapture, b: &FrameCapture) -> (f32, usize) {
    a.pixels
        .color
        .iter()
        .zip(&b.pixels.color)
        .enumerate()
        .map(|(i, (x, y))| ((0..3).map(|c| (x[c] - y[c]).abs()).fold(0.0, f32::max), i))
        .fold((0.0, 0), |m, d| if d.0 > m.0 { d } else { m })
}

#[test]
fn pipelens_own_shading_as_glsl_gives_the_built_in_pixels() {
    // With 4 samples a silhouette pixel averages its shaded samples with the background ones,
    // and a pixel two triangles share runs the shader once for each. Every buffer kept, the
    // colour alone, and the colour with one pixel inspected (whose terms are kept, not the
    // frame's): the built-in path adds no colour of its own under the shaders' in any.
    use pipeline::buffers::Capture;
    let inspected = Capture {
        pixel: Some((80, 60)),
        ..Capture::COLOR
    };
    let cases = [Capture::FULL, Capture::COLOR, inspected]
        .into_iter()
        .flat_map(|c| [(Samples::X1, c), (Samples::X4, c)]);
    for (samples, capture) in cases {
        for textured in [false, true] {
            let settings = RenderSettings {
                samples,
                capture,
                ..settings()
            };
            let scene = sphere_scene(textured);
            let built_in = render(&scene, &settings);
            let shaded = render(&with_shaders(scene, None, None), &settings);
            let case = format!(
                "textured = {textured}, {} sample(s), {capture:?}",
                samples.count()
            );
            assert_eq!(
                built_in.pixels.coverage, shaded.pixels.coverage,
                "coverage, {case}"
            );
            let (d, at) = largest_difference(&built_in, &shaded);
            assert!(
                d <= 1.0 / 255.0,
                "{case}: pixel {at} differs by {d}: {:?} vs {:?}",
                built_in.pixels.color[at],
                shaded.pixels.color[at]
            );
            let record = shaded.shaders.as_ref().expect("a shader record");
            let covered = shaded.pixels.coverage.iter().filter(|&&c| c > 0).count() as u64;
            if samples == Samples::X1 {
                assert_eq!(record.fragments, covered, "{case}");
            } else {
                assert!(
                    record.fragments > covered,
                    "{case}: shared pixels shade twice"
                );
            }
            assert_eq!((record.discarded, record.not_finite), (0, 0));
        }
    }
}

#[test]
fn flat_takes_the_provoking_vertex_and_noperspective_is_affine_in_the_window() {
    // A plane receding from the eye; the vertex shader passes uv three ways.
    let mut plane = Object::new(
        "plane",
        BuiltinMesh::Plane {
            divisions: 1,
            repeat: 1.0,
        }
        .build(),
    );
    plane.scale = Vec3::splat(2.0);
    let mut scene = sphere_scene(false);
    scene.objects = vec![plane];
    scene.camera = Camera {
        eye: Vec3::new(0.0, 0.6, 2.0),
        at: Vec3::new(0.0, 0.0, -1.0),
        up: Vec3::Y,
    };
    let vs = "#version 330 core\nuniform mat4 mvp;\nin vec3 position;\nin vec2 uv;\nout vec2 smooth_uv;\nnoperspective out vec2 affine_uv;\nflat out vec2 flat_uv;\n\
              void main() { smooth_uv = uv; affine_uv = uv; flat_uv = uv; gl_Position = mvp * vec4(position, 1.0); }\n";
    let frag = |name: &str| {
        format!(
            "#version 330 core\nin vec2 smooth_uv;\nnoperspective in vec2 affine_uv;\nflat in vec2 flat_uv;\nout vec4 color;\nvoid main() {{ color = vec4({name}, 0.0, 1.0); }}\n"
        )
    };
    let s = RenderSettings {
        shading: Frequency::Unlit,
        ..settings()
    };
    let frame = |name: &str| {
        render(
            &with_shaders(scene.clone(), Some(vs), Some(&frag(name))),
            &s,
        )
    };
    let (smooth, affine, flat) = (frame("smooth_uv"), frame("affine_uv"), frame("flat_uv"));
    let mut differs = 0;
    for i in 0..smooth.pixels.color.len() {
        if smooth.pixels.coverage[i] == 0 {
            continue;
        }
        if (smooth.pixels.color[i][0] - affine.pixels.color[i][0]).abs() > 0.01 {
            differs += 1;
        }
        // Flat: one of the triangle's three corners' uv, each 0 or 1 on the plane.
        for c in 0..2 {
            let v = flat.pixels.color[i][c];
            assert!(v == 0.0 || v == 1.0, "flat uv {v} at pixel {i}");
        }
    }
    assert!(
        differs > 100,
        "perspective and affine uv should differ on a receding plane ({differs} pixels)"
    );
}

#[test]
fn behind_a_discarded_fragment_the_next_surface_shows() {
    // A square in front of the sphere, its checkerboard's even squares discarded: through the
    // holes the sphere shows, as OpenGL draws it (a discarded fragment writes no depth).
    let fs = "#version 330 core\nin vec2 v_uv;\nout vec4 color;\nvoid main() {\n  if (mod(floor(v_uv.x * 8.0) + floor(v_uv.y * 8.0), 2.0) < 1.0) discard;\n  color = vec4(1.0, 0.0, 0.0, 1.0);\n}\n";
    let mut scene = sphere_scene(false);
    let mut square = Object::new(
        "square",
        BuiltinMesh::Plane {
            divisions: 1,
            repeat: 1.0,
        }
        .build(),
    );
    square.rotate_deg = Vec3::new(90.0, 0.0, 0.0);
    square.translate = Vec3::new(0.0, 0.0, 1.5);
    square.scale = Vec3::splat(0.8);
    let programs = pipeline::shader::link(None, Some(fs)).unwrap_or_else(|e| panic!("{e:?}"));
    square.code.shader = Some(ObjectShader {
        programs: Arc::new(programs),
        time: 0.0,
    });
    let square_again = square.clone();
    scene.objects.push(square);
    let with_holes = render(&scene, &settings());
    scene.objects.pop();
    let sphere_alone = render(&scene, &settings());
    let record = with_holes.shaders.as_ref().expect("a shader record");
    assert!(record.discarded > 1000, "{record:?}");
    let red = [1.0, 0.0, 0.0];
    let mut sphere_seen = 0;
    for (i, (c, alone)) in with_holes
        .pixels
        .color
        .iter()
        .zip(&sphere_alone.pixels.color)
        .enumerate()
    {
        // Every pixel not painted red shows exactly what the sphere alone shows there.
        if *c != red {
            assert_eq!(c, alone, "pixel {i}");
            assert_eq!(
                with_holes.pixels.coverage[i], sphere_alone.pixels.coverage[i],
                "pixel {i}"
            );
            sphere_seen += usize::from(alone != &with_holes.settings.background.to_array());
        }
    }
    let reds = with_holes
        .pixels
        .color
        .iter()
        .filter(|c| **c == red)
        .count();
    assert!(
        reds > 1000 && sphere_seen > 1000,
        "{reds} red pixels, {sphere_seen} of the sphere"
    );
    // Inspected where the square's fragment was discarded and the sphere (no shader) shows:
    // the pixel's record keeps the discarded fragment's run, ending at its `discard`.
    let (w, h) = (with_holes.width() as usize, with_holes.height() as usize);
    let hole = (0..w * h)
        .find(|&i| {
            let (x, row) = (i % w, i / w);
            let in_square = (w / 3..2 * w / 3).contains(&x) && (h / 3..2 * h / 3).contains(&row);
            in_square
                && with_holes.pixels.color[i] != red
                && sphere_alone.pixels.color[i] != with_holes.settings.background.to_array()
        })
        .expect("a hole of the square over the sphere");
    let mut s = settings();
    s.capture.pixel = Some(((hole % w) as u32, (h - 1 - hole / w) as u32));
    scene.objects.push(square_again);
    let f = render(&scene, &s);
    let runs = &f.shaders.as_ref().expect("a shader record").pixel;
    assert_eq!(runs.len(), 1, "{runs:#?}");
    assert_eq!(runs[0].output, None);
    assert_eq!(
        runs[0].trace.last().map(|l| &l.step),
        Some(&pipeline::shader::Step::Discard),
        "{:#?}",
        runs[0].trace
    );
}

#[test]
fn a_run_time_error_in_a_frame_is_a_message_with_its_line() {
    let fs = "#version 330 core\nout vec4 color;\nvoid main() {\n  float x = 0.0;\n  while (x >= 0.0) {\n    x += 1.0;\n  }\n  color = vec4(x);\n}\n";
    let scene = with_shaders(sphere_scene(false), None, Some(fs));
    let e = pipeline::render(&scene, &settings()).expect_err("an endless loop");
    let text = e.to_string();
    assert!(
        text.contains("fragment shader of sphere") && text.contains("line 5"),
        "{text}"
    );
}

/// A valid loop longer than the default budget (70 000 iterations > 65 536) stops as "an endless
/// loop?" with the way to raise the limit; with `max_steps` raised the frame is drawn, the loop's
/// count in every pixel. The vertex shader's loops keep the same budget.
#[test]
fn a_long_loop_runs_when_max_steps_allows_it() {
    use pipeline::shader::Complaint;
    let fs = "#version 330 core\nout vec4 color;\nvoid main() {\n  int k = 0;\n  for (int i = 0; i < 70000; i++) {\n    k += 1;\n  }\n  color = vec4(float(k) / 70000.0, 0.0, 0.0, 1.0);\n}\n";
    let scene = with_shaders(sphere_scene(false), None, Some(fs));
    let mut s = settings();
    assert_eq!(s.max_steps, 65_536);
    let e = pipeline::render(&scene, &s).expect_err("over the default budget");
    let pipeline::RenderError::Code { error, .. } = &e else {
        panic!("{e}");
    };
    assert_eq!(error.complaint, Complaint::EndlessLoop { budget: 65_536 });
    assert!(
        e.to_string().contains("`max_steps` under [scene.render]"),
        "{e}"
    );
    s.max_steps = 70_001;
    let f = render(&scene, &s);
    let lit = f.pixels.color.iter().filter(|c| c[0] == 1.0).count();
    let covered = f.pixels.coverage.iter().filter(|&&c| c > 0).count();
    assert!(covered > 0 && lit == covered, "{lit} of {covered}");
    let vs = "#version 330 core\nuniform mat4 mvp;\nin vec3 position;\nvoid main() {\n  float y = 0.0;\n  for (int i = 0; i < 70000; i++) {\n    y += 0.0;\n  }\n  gl_Position = mvp * vec4(position + vec3(0.0, y, 0.0), 1.0);\n}\n";
    let red = "#version 330 core\nout vec4 color;\nvoid main() {\n  color = vec4(1.0, 0.0, 0.0, 1.0);\n}\n";
    let scene = with_shaders(sphere_scene(false), Some(vs), Some(red));
    s.max_steps = 65_536;
    assert!(pipeline::render(&scene, &s).is_err());
    s.max_steps = 70_001;
    render(&scene, &s);
}

/// A vertex shader whose `gl_Position` is infinite for some vertices (a division by zero made at
/// run time) does not stop the frame: the triangles with such a corner are dropped before
/// clipping ([`Fate::NotFinite`]), counted and said; the others are drawn.
#[test]
fn a_gl_position_that_is_not_finite_drops_its_triangles_not_the_frame() {
    use pipeline::capture::Fate;
    let vs = "#version 330 core\nuniform mat4 mvp;\nin vec3 position;\nvoid main() {\n  gl_Position = mvp * vec4(position, 1.0);\n  if (position.x > 0.5) {\n    gl_Position.w = 1.0 / (position.x - position.x);\n  }\n}\n";
    let red = "#version 330 core\nout vec4 color;\nvoid main() {\n  color = vec4(1.0, 0.0, 0.0, 1.0);\n}\n";
    let scene = with_shaders(sphere_scene(false), Some(vs), Some(red));
    let f = render(&scene, &settings());
    // By the mesh: the triangles with a corner at x > 0.5, and only those, are dropped.
    let mesh = &scene.objects[0].mesh;
    let far_right = |p: &pipeline::capture::PrimitiveRecord| {
        mesh.indices[p.id as usize]
            .iter()
            .any(|&i| mesh.positions[i as usize].x > 0.5)
    };
    let dropped = f.primitives.iter().filter(|p| p.fate == Fate::NotFinite);
    assert!(dropped.clone().all(far_right));
    let expected = f.primitives.iter().filter(|p| far_right(p)).count();
    assert!(expected > 0);
    assert_eq!(f.not_finite_primitives(), expected);
    assert_eq!(dropped.count(), expected);
    assert!(
        f.pixels.coverage.iter().any(|&c| c > 0),
        "the rest is drawn"
    );
    let words = f.not_finite_warnings();
    assert_eq!(words.len(), 1, "{words:?}");
    assert!(
        words[0].starts_with(&format!("{expected} triangle(s) dropped")),
        "{words:?}"
    );
}

/// A vertex shader's `gl_Position` is the table's clip position, and a `vec3` attribute read
/// as a `vec4` is filled with w = 1, as OpenGL fills it: `mvp * position` equals P·V·M·p for
/// every vertex, and the window positions follow from it as the built-in stage's do.
#[test]
fn gl_position_is_the_clip_position_and_a_vec4_attribute_has_w_one() {
    let scene = sphere_scene(false);
    let built_in = render(&scene, &settings());
    let vs = "#version 330 core
uniform mat4 mvp;
in vec4 position;
void main() { gl_Position = mvp * position; }
";
    let fs = "#version 330 core
out vec4 color;
void main() { color = vec4(1.0); }
";
    let shaded = render(&with_shaders(scene, Some(vs), Some(fs)), &settings());
    assert_eq!(built_in.vertices.len(), shaded.vertices.len());
    for (a, b) in built_in.vertices.iter().zip(&shaded.vertices) {
        assert!(
            (a.clip - b.clip).abs().max_element() <= 1e-5 * a.clip.abs().max_element().max(1.0),
            "vertex {}: P·V·M·p = {} vs gl_Position = {}",
            a.index,
            a.clip,
            b.clip
        );
        assert_eq!(
            (a.world, a.eye, a.normal_world),
            (b.world, b.eye, b.normal_world)
        );
        assert_eq!(a.window.is_some(), b.window.is_some());
    }
}
