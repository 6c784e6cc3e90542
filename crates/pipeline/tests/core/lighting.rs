//! Lighting against the notes' formulas, computed by hand here.

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::light::{Light, Material};
use pipeline::lighting::{self, Frequency, Reflection, attenuation, spot_factor};
use pipeline::mesh::BuiltinMesh;
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;

use crate::support::render;

fn material() -> Material {
    Material {
        ka: Vec3::splat(0.1),
        kd: Vec3::splat(0.7),
        ks: Vec3::splat(0.5),
        shininess: 32.0,
    }
}

fn close(a: f32, b: f32, tol: f32, what: &str) {
    assert!((a - b).abs() <= tol, "{what}: {a} vs {b}");
}

#[test]
fn one_point_each_term_by_hand() {
    // p at the origin facing +z, eye at (0, 0, 5), a white point light at (0, 3, 4) (distance 5).
    let lights = [
        Light::Ambient {
            intensity: Vec3::splat(0.2),
        },
        Light::Point {
            position: Vec3::new(0.0, 3.0, 4.0),
            intensity: Vec3::ONE,
            attenuation: Vec3::X,
        },
    ];
    let eye = Vec3::new(0.0, 0.0, 5.0);
    let blinn = lighting::shade(
        Vec3::ZERO,
        Vec3::Z,
        eye,
        Vec3::ONE,
        &lights,
        &material(),
        Reflection::BlinnPhong,
    );
    // l = (0, 0.6, 0.8), n·l = 0.8; v = (0, 0, 1); h = (l + v)/|l + v| = (0, 0.6, 1.8)/√3.6.
    close(blinn.ambient.x, 0.1 * 0.2, 1e-6, "k_a·I_a");
    close(blinn.diffuse.x, 0.7 * 0.8, 1e-6, "k_d·I_d·(n·l)");
    let n_dot_h = 1.8 / 3.6f32.sqrt();
    close(blinn.n_dot_h, n_dot_h, 1e-6, "n·h");
    close(
        blinn.specular.x,
        0.5 * n_dot_h.powf(32.0),
        1e-6,
        "k_s·(n·h)^β",
    );
    close(
        blinn.color().y,
        0.02 + 0.56 + 0.5 * n_dot_h.powf(32.0),
        1e-5,
        "sum",
    );
    // Phong: r = 2(n·l)n − l = (0, −0.6, 0.8), r·v = 0.8.
    let phong = lighting::shade(
        Vec3::ZERO,
        Vec3::Z,
        eye,
        Vec3::ONE,
        &lights,
        &material(),
        Reflection::Phong,
    );
    close(phong.n_dot_h, 0.8, 1e-6, "r·v");
    close(
        phong.specular.x,
        0.5 * 0.8f32.powf(32.0),
        1e-7,
        "k_s·(r·v)^α",
    );
    close(
        phong.diffuse.x,
        blinn.diffuse.x,
        0.0,
        "the diffuse term does not depend on the model",
    );
    // The surface colour multiplies k_a and k_d, not k_s.
    let red = lighting::shade(
        Vec3::ZERO,
        Vec3::Z,
        eye,
        Vec3::X,
        &lights,
        &material(),
        Reflection::BlinnPhong,
    );
    assert_eq!(red.diffuse.y, 0.0);
    close(
        red.specular.y,
        blinn.specular.y,
        0.0,
        "highlight keeps the light's colour",
    );
}

#[test]
fn a_light_behind_the_surface_gives_no_diffuse_and_no_highlight() {
    let lights = [Light::Point {
        position: Vec3::new(0.0, 0.0, -3.0),
        intensity: Vec3::ONE,
        attenuation: Vec3::X,
    }];
    let t = lighting::shade(
        Vec3::ZERO,
        Vec3::Z,
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::ONE,
        &lights,
        &material(),
        Reflection::Phong,
    );
    assert_eq!(t.diffuse, Vec3::ZERO);
    assert_eq!(t.specular, Vec3::ZERO);
}

#[test]
fn attenuation_and_the_spot_cone_by_hand() {
    // 1/(a + b·d + c·d²) with (1, 0.5, 0.25) at d = 2: 1/(1 + 1 + 1).
    close(
        attenuation(Vec3::new(1.0, 0.5, 0.25), 2.0),
        1.0 / 3.0,
        1e-7,
        "1/(a+bd+cd²)",
    );
    // GAMES101's I/r²: (0, 0, 1) at r = 4 → 1/16.
    close(attenuation(Vec3::Z, 4.0), 1.0 / 16.0, 1e-7, "I/r²");
    // A spot pointing down −y with a 30° cone; l points from the surface to the light.
    let axis = Vec3::NEG_Y;
    let at = |deg: f32| {
        let a = deg.to_radians();
        // Direction from the light to the point, at `deg` from the axis; l is its opposite.
        let to_point = Vec3::new(a.sin(), -a.cos(), 0.0);
        spot_factor(-to_point, axis, 30.0, 4.0)
    };
    close(at(0.0), 1.0, 1e-6, "on the axis");
    close(
        at(20.0),
        20f32.to_radians().cos().powf(4.0),
        1e-6,
        "inside: cos^e φ",
    );
    assert_eq!(at(40.0), 0.0, "outside the cone");
    // Through shade(): a point light with the same geometry, distance 2, attenuation I/r².
    let light = Light::Spot {
        position: Vec3::new(0.0, 2.0, 0.0),
        direction: axis,
        cutoff_deg: 30.0,
        exponent: 4.0,
        intensity: Vec3::ONE,
        attenuation: Vec3::Z,
    };
    let t = lighting::shade(
        Vec3::ZERO,
        Vec3::Y,
        Vec3::new(0.0, 5.0, 0.0),
        Vec3::ONE,
        &[light],
        &material(),
        Reflection::BlinnPhong,
    );
    close(
        t.diffuse.x,
        0.7 * 1.0 / 4.0,
        1e-6,
        "k_d·I/r²·(n·l) on the axis",
    );
}

/// A sphere seen head-on, lit by a distant light from the upper right front.
fn lit_sphere(frequency: Frequency) -> pipeline::capture::FrameCapture {
    let mut sphere = Object::new(
        "sphere",
        BuiltinMesh::UvSphere {
            segments: 96,
            rings: 48,
        }
        .build(),
    );
    sphere.color = pipeline::scene::ColorSource::Uniform(Vec3::ONE);
    sphere.material = material();
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
        lights: vec![
            Light::Ambient {
                intensity: Vec3::splat(0.3),
            },
            Light::Directional {
                direction: -Vec3::new(1.0, 1.0, 1.0),
                intensity: Vec3::ONE,
            },
        ],
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: 101,
        height: 101,
        shading: frequency,
        ..RenderSettings::default()
    };
    render(&scene, &settings)
}

#[test]
fn the_centre_pixel_of_a_lit_sphere_by_hand() {
    // The centre pixel sees the point (0, 0, 1) of the unit sphere, normal (0, 0, 1), v = (0, 0, 1).
    // l = (1, 1, 1)/√3: n·l = 1/√3; h = (l + v)/|l + v|.
    let l = Vec3::ONE.normalize();
    let h = (l + Vec3::Z).normalize();
    let expect_diffuse = 0.7 * l.z;
    let expect_specular = 0.5 * h.z.powf(32.0);
    for (frequency, tol) in [(Frequency::Phong, 0.01), (Frequency::Gouraud, 0.03)] {
        let c = lit_sphere(frequency);
        let i = 50 * 101 + 50;
        // The lighting buffers keep half floats (relative error ≤ 2⁻¹¹).
        let sh = c.pixels.shading.as_ref().expect("lighting buffers").at(i);
        close(sh.ambient[0], 0.1 * 0.3, 0.03 / 2048.0, "ambient");
        close(sh.diffuse[0], expect_diffuse, tol, "diffuse");
        close(sh.specular[0], expect_specular, tol, "specular");
        close(sh.n_dot_l, l.z, tol, "n·l");
        close(
            c.pixels.color[i][1],
            0.03 + expect_diffuse + expect_specular,
            2.0 * tol,
            "colour",
        );
    }
    // Flat shading: every pixel of one face has one colour.
    let c = lit_sphere(Frequency::Flat);
    let i = 50 * 101 + 50;
    let prim = c.pixels.primitive[i];
    let same: Vec<usize> = (0..c.pixels.primitive.len())
        .filter(|&j| c.pixels.primitive[j] == prim)
        .collect();
    assert!(same.len() > 1);
    for j in same {
        assert_eq!(
            c.pixels.color[j], c.pixels.color[i],
            "flat: one colour per face"
        );
    }
}

#[test]
fn profiles_show_the_mach_band_difference_between_frequencies() {
    // Across the sphere's equator: flat shading is piecewise constant (steps between faces),
    // Gouraud and Phong are continuous; Phong has the sharpest highlight.
    let row = [0.0, 50.5];
    let end = [100.0, 50.5];
    let flat = lit_sphere(Frequency::Flat).profile(row, end);
    let gouraud = lit_sphere(Frequency::Gouraud).profile(row, end);
    let phong = lit_sphere(Frequency::Phong).profile(row, end);
    assert_eq!(flat.len(), 101);
    assert!(
        flat.iter()
            .zip(&phong)
            .all(|(a, b)| a.x == b.x && a.y == b.y && a.y == 50)
    );
    let on_sphere = |p: &[pipeline::capture::ProfileSample]| -> Vec<f32> {
        p.iter()
            .filter(|s| s.intensity > 0.1)
            .map(|s| s.intensity)
            .collect()
    };
    let (f, g, ph) = (on_sphere(&flat), on_sphere(&gouraud), on_sphere(&phong));
    let jumps = |v: &[f32]| v.windows(2).filter(|w| (w[1] - w[0]).abs() < 1e-6).count();
    assert!(
        jumps(&f) > f.len() / 3,
        "flat: runs of equal intensity (one per face)"
    );
    assert!(
        jumps(&g) < g.len() / 10,
        "Gouraud: intensity changes from pixel to pixel"
    );
    let max = |v: &[f32]| v.iter().copied().fold(0.0f32, f32::max);
    assert!(
        max(&ph) >= max(&g) - 1e-3,
        "Phong's highlight is at least Gouraud's"
    );
    // The profile reads the colour buffer: the middle sample is the centre pixel.
    let mid = &phong[50];
    let c = lit_sphere(Frequency::Phong);
    assert_eq!(mid.rgb, c.pixels.color[50 * 101 + 50]);
    let luma = 0.2126 * mid.rgb[0] + 0.7152 * mid.rgb[1] + 0.0722 * mid.rgb[2];
    assert!((mid.intensity - luma).abs() < 1e-6);
}

#[test]
fn the_shadow_pass_projects_every_vertex_by_the_closed_form() {
    use pipeline::scene::{PlanarShadow, SHADOW_LIFT};
    let light = Vec3::new(1.0, 6.0, 2.0);
    let mut cube = Object::new("cube", BuiltinMesh::Cube.build());
    cube.translate = Vec3::new(0.5, 2.0, -0.5);
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![cube],
        camera: Camera {
            eye: Vec3::new(0.0, 8.0, 10.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::default(),
        shadow: Some(PlanarShadow {
            light,
            plane_y: 0.0,
            color: Vec3::splat(0.1),
            yours: None,
        }),
        ..Scene::default()
    };
    let c = render(&scene, &RenderSettings::default());
    assert_eq!(c.objects.len(), 2);
    assert_eq!(c.objects[1].name, "shadow of cube");
    let n = c.objects[0].vertices;
    for (v, s) in c.vertices[..n].iter().zip(&c.vertices[n..]) {
        let p = v.world.truncate();
        let q = s.world.truncate() / s.world.w;
        let k = light.y / (p.y - light.y);
        // x_p = x_l − (x − x_l)·y_l/(y − y_l), y_p = 0 (+ the lift), z_p likewise.
        let expect = Vec3::new(
            light.x - (p.x - light.x) * k,
            SHADOW_LIFT,
            light.z - (p.z - light.z) * k,
        );
        assert!((q - expect).abs().max_element() < 1e-4, "{q} vs {expect}");
    }
    // Shadow fragments are unlit: exactly their colour.
    let shadow_pixels: Vec<usize> = (0..c.pixels.primitive.len())
        .filter(|&i| {
            c.pixels.primitive[i] != pipeline::raster::NONE
                && c.primitives[c.pixels.primitive[i] as usize].object == 1
        })
        .collect();
    assert!(
        shadow_pixels.len() > 100,
        "the shadow is visible ({} pixels)",
        shadow_pixels.len()
    );
    assert!(
        shadow_pixels
            .iter()
            .all(|&i| c.pixels.color[i].iter().all(|v| (v - 0.1).abs() < 1e-5))
    );
}

#[test]
fn render_is_a_pure_function_same_inputs_same_capture() {
    let a = lit_sphere(Frequency::Phong);
    let b = lit_sphere(Frequency::Phong);
    assert!(
        a == b,
        "two renders of the same scene must be identical, buffer for buffer"
    );
}

#[test]
fn the_lighting_vectors_at_a_pixel_agree_with_its_terms() {
    let c = lit_sphere(Frequency::Phong);
    let sh = c.pixels.shading.as_ref().expect("lit");
    let mut checked = 0;
    for y in (0..c.height()).step_by(7) {
        for x in (0..c.width()).step_by(7) {
            let Some(v) = c.pixel_vectors(x, y) else {
                continue;
            };
            let i = ((c.height() - 1 - y) * c.width() + x) as usize;
            // On the unit sphere the point is its own normal (up to the facets), the light is
            // the distant one, and h bisects l and v.
            assert!((v.position.length() - 1.0).abs() < 0.01, "{}", v.position);
            assert!((v.light - Vec3::ONE.normalize()).length() < 1e-5);
            // Both from the half-float buffers: the normal and n·l each within 2⁻¹¹.
            close(
                v.normal.dot(v.light),
                sh.at(i).n_dot_l,
                2e-3,
                "n·l from the buffer",
            );
            close(
                v.normal.dot(v.half),
                sh.at(i).n_dot_h,
                2e-3,
                "n·h from the buffer",
            );
            close(v.half.dot(v.light), v.half.dot(v.view), 1e-5, "h halfway");
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked} pixels");
}

#[test]
fn a_light_is_drawn_where_it_is_and_a_spot_with_its_cutoff() {
    let spot = Light::Spot {
        position: Vec3::new(0.0, 3.0, 0.0),
        direction: Vec3::new(0.0, -2.0, 0.0),
        cutoff_deg: 25.0,
        exponent: 2.0,
        intensity: Vec3::ONE,
        attenuation: Vec3::X,
    };
    let g = spot.gizmo(Vec3::ZERO, 4.0).expect("a spot is drawn");
    // The rays from the apex make the cutoff angle with the axis (straight down).
    let rays: Vec<_> = g
        .segments
        .iter()
        .filter(|[a, b]| {
            *a == Vec3::new(0.0, 3.0, 0.0) && (*b - *a).normalize().dot(Vec3::NEG_Y) < 0.999
        })
        .collect();
    assert_eq!(rays.len(), 8);
    for [a, b] in rays {
        let angle = (*b - *a).normalize().dot(Vec3::NEG_Y).acos().to_degrees();
        assert!((angle - 25.0).abs() < 1e-3, "{angle}");
    }
    // A directional light's arrows run along its direction.
    let sun = Light::Directional {
        direction: Vec3::new(1.0, -1.0, 0.0),
        intensity: Vec3::ONE,
    };
    let g = sun.gizmo(Vec3::ZERO, 4.0).expect("drawn");
    let shafts: Vec<_> = g.segments.iter().step_by(3).collect();
    for [a, b] in shafts {
        assert!(
            (*b - *a)
                .normalize()
                .dot(Vec3::new(1.0, -1.0, 0.0).normalize())
                > 0.9999
        );
    }
    // A point light's star is centred on it; ambient light has no place.
    let point = Light::Point {
        position: Vec3::new(1.0, 2.0, 3.0),
        intensity: Vec3::ONE,
        attenuation: Vec3::X,
    };
    for [a, b] in point.gizmo(Vec3::ZERO, 4.0).expect("drawn").segments {
        assert!(((a + b) / 2.0 - Vec3::new(1.0, 2.0, 3.0)).length() < 1e-6);
    }
    assert!(
        Light::Ambient {
            intensity: Vec3::ONE
        }
        .gizmo(Vec3::ZERO, 4.0)
        .is_none()
    );
}
