//! Reference images of the course's assignments, when `../shared/data` is beside the checkout.

use crate::support::{repo, shared_data};

#[test]
fn games101_assignment_2_without_antialiasing_matches_pixel_for_pixel() {
    let Some(data) = shared_data() else {
        eprintln!("skipped: ../shared/data is not present");
        return;
    };
    let reference =
        image::open(data.join("reference/games101_danieldfy/a2_output_with_no_anti_aliasing.png"))
            .expect("reference decodes")
            .to_rgb8();
    let spec = pipelens::lesson::load_scene_file(&repo().join("assets/scenes/games101_a2.toml"))
        .expect("scene");
    let capture = pipeline::render(&spec.scene, &spec.settings).expect("renders");
    let ours = capture.image(pipeline::buffers::BufferKind::Color);
    assert_eq!((ours.width(), ours.height()), reference.dimensions());
    let differing = ours
        .pixels()
        .zip(reference.pixels())
        .filter(|(a, b)| a.0[..3] != b.0[..])
        .count();
    assert_eq!(
        differing, 0,
        "{differing} pixels differ from the assignment's image"
    );
}

/// GAMES101 assignment 3's scene: Spot, `Ry(140°)·S(2.5)`, eye (0, 0, 10), fovy 45°, 700×700,
/// one sample at pixel centres, screen-space (affine) attributes, no culling. The lights are
/// at (20, 20, 20) and (−20, 20, 0) in view space; the view matrix is a translation by
/// (0, 0, −10), so they are at (20, 20, 30) and (−20, 20, 10) in the world. Intensity 500 with
/// `I/r²`, an ambient `I_a = 10` added once per light (20 in all), `k_s = 0.7937`, `p = 150`.
fn spot_scene(
    data: &std::path::Path,
    surface: glam::Vec3,
) -> (pipeline::scene::Scene, pipeline::settings::RenderSettings) {
    use glam::Vec3;
    use pipeline::camera::{Camera, Projection};
    use pipeline::light::Light;
    use pipeline::scene::Object;
    use pipeline::settings::RenderSettings;
    let mesh = pipeline::mesh::Mesh::load_obj(&data.join("models/spot/spot_triangulated_good.obj"))
        .expect("Spot loads");
    let mut spot = Object::new("spot", mesh);
    spot.rotate_deg = Vec3::new(0.0, 140.0, 0.0);
    spot.scale = Vec3::splat(2.5);
    spot.color = pipeline::scene::ColorSource::Uniform(surface);
    // The assignment's ambient term is k_a·I_a, not modulated by the surface colour as ours is:
    // k_a = 0.005 ⊘ surface gives the same product.
    spot.material = pipeline::light::Material {
        ka: Vec3::splat(0.005) / surface,
        kd: Vec3::ONE,
        ks: Vec3::splat(0.7937),
        shininess: 150.0,
    };
    let point = |p: Vec3| Light::Point {
        position: p,
        intensity: Vec3::splat(500.0),
        attenuation: Vec3::new(0.0, 0.0, 1.0),
    };
    let scene = pipeline::scene::Scene {
        uniforms: Default::default(),
        objects: vec![spot],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 10.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 45.0,
            aspect: Some(1.0),
            near: 0.1,
            far: 50.0,
        },
        lights: vec![
            Light::Ambient {
                intensity: Vec3::splat(20.0),
            },
            point(Vec3::new(20.0, 20.0, 30.0)),
            point(Vec3::new(-20.0, 20.0, 10.0)),
        ],
        ..pipeline::scene::Scene::default()
    };
    let settings = RenderSettings {
        width: 700,
        height: 700,
        perspective_correct: false,
        shading: pipeline::lighting::Frequency::Phong,
        cull: pipeline::raster::CullMode::None,
        background: Vec3::ZERO,
        ..RenderSettings::default()
    };
    (scene, settings)
}

/// How an image of ours compares with an assignment-3 reference, after moving the reference
/// up by the framework's one-row shift: pixels covered by one and not the other, the share of
/// pixels differing by more than `tolerance` in some channel, and the largest difference.
struct Comparison {
    coverage_mismatch: usize,
    share_over: f64,
    max: u8,
}

fn compare_a3(
    ours: &image::RgbaImage,
    reference: &std::path::Path,
    tolerance: u8,
    save: &str,
) -> Comparison {
    compare_a3_where(ours, reference, tolerance, save, |_, _| true)
}

/// [`compare_a3`] over the pixels `(x, row)` where `keep` holds.
fn compare_a3_where(
    ours: &image::RgbaImage,
    reference: &std::path::Path,
    tolerance: u8,
    save: &str,
    keep: impl Fn(u32, u32) -> bool,
) -> Comparison {
    let reference = image::open(reference).expect("reference decodes").to_rgb8();
    let (w, h) = reference.dimensions();
    assert_eq!((ours.width(), ours.height()), (w, h));
    let (mut coverage_mismatch, mut over, mut max, mut covered) = (0, 0usize, 0u8, 0usize);
    for y in 0..h - 1 {
        for x in 0..w {
            let a = &ours.get_pixel(x, y).0[..3];
            let b = &reference.get_pixel(x, y + 1).0[..];
            let (fa, fb) = (a != [0, 0, 0], b != [0, 0, 0]);
            if fa != fb {
                coverage_mismatch += 1;
                continue;
            }
            if !fa || !keep(x, y) {
                continue;
            }
            covered += 1;
            let d = a
                .iter()
                .zip(b)
                .map(|(p, q)| p.abs_diff(*q))
                .max()
                .unwrap_or(0);
            max = max.max(d);
            if d > tolerance {
                over += 1;
            }
        }
    }
    let out = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{save}.png"));
    ours.save(&out).expect("saves");
    Comparison {
        coverage_mismatch,
        share_over: over as f64 / covered.max(1) as f64,
        max,
    }
}

#[test]
fn games101_assignment_3_spot_normal_and_blinn_phong() {
    use pipeline::buffers::BufferKind;
    let Some(data) = shared_data() else {
        eprintln!("skipped: ../shared/data is not present");
        return;
    };
    let refs = data.join("reference/games101_danieldfy");
    let kd = glam::Vec3::new(148.0, 121.0, 92.0) / 255.0;
    let (scene, settings) = spot_scene(&data, kd);
    let c = pipeline::render(&scene, &settings).expect("renders");
    // The normal shader: (n + 1)/2 of the interpolated unit normal (view = world here, the view
    // matrix being a translation).
    let normal = compare_a3(
        &c.image(BufferKind::Normal),
        &refs.join("a3_output_normal.png"),
        1,
        "a3_normal",
    );
    assert_eq!(normal.coverage_mismatch, 0, "the same pixels are covered");
    assert!(normal.max <= 1, "normals within rounding: {}", normal.max);
    // Blinn-Phong. The framework takes the view vector from (0, 0, 10) in view space, which is
    // (0, 0, 20) in the world, not from the camera: the highlights sit a little apart
    // (measured: 7 % of the pixels differ, by up to 61/255). Away from the highlights the
    // ambient and diffuse terms agree to rounding.
    let sh = c.pixels.shading.as_ref().expect("lighting buffers");
    let no_specular = |x: u32, y: u32| {
        let i = (y * 700 + x) as usize;
        sh.at(i).specular.iter().all(|&s| s < 0.5 / 255.0)
    };
    let diffuse = compare_a3_where(
        &c.image(BufferKind::Color),
        &refs.join("a3_output_blinn_phong.png"),
        2,
        "a3_blinn_phong",
        no_specular,
    );
    assert_eq!(diffuse.coverage_mismatch, 0);
    assert!(
        diffuse.share_over < 0.002 && diffuse.max <= 4,
        "{:.4} of the pixels over 2/255, max {}",
        diffuse.share_over,
        diffuse.max
    );
}

/// The assignment's colour `min(k_a·I_a + diffuse + specular, 1)` with its unmodulated ambient
/// `0.005·20 = 0.1`, from our own diffuse and specular buffers.
fn a3_formula(c: &pipeline::capture::FrameCapture) -> image::RgbaImage {
    let sh = c.pixels.shading.as_ref().expect("lighting buffers");
    image::RgbaImage::from_fn(700, 700, |x, y| {
        let i = (y * 700 + x) as usize;
        if c.pixels.coverage[i] == 0 {
            return image::Rgba([0, 0, 0, 255]);
        }
        let t = sh.at(i);
        let ch = |k: usize| ((0.1 + t.diffuse[k] + t.specular[k]).min(1.0) * 255.0) as u8;
        image::Rgba([ch(0), ch(1), ch(2), 255])
    })
}

#[test]
fn games101_assignment_3_spot_textured() {
    use pipeline::texture::{Filter, Mipmap, Sampler, Texture, Wrap};
    let Some(data) = shared_data() else {
        eprintln!("skipped: ../shared/data is not present");
        return;
    };
    let refs = data.join("reference/games101_danieldfy");
    let (mut scene, mut settings) = spot_scene(&data, glam::Vec3::ONE);
    scene.objects[0].texture = Some(std::sync::Arc::new(
        Texture::load(&data.join("models/spot/spot_texture.png")).expect("texture loads"),
    ));
    let measure = |scene: &pipeline::scene::Scene,
                   settings: &pipeline::settings::RenderSettings,
                   file: &str| {
        let c = pipeline::render(scene, settings).expect("renders");
        let sh = c.pixels.shading.as_ref().expect("lighting buffers");
        let r = compare_a3_where(&a3_formula(&c), &refs.join(file), 4, file, |x, y| {
            sh.at((y * 700 + x) as usize)
                .specular
                .iter()
                .all(|&s| s < 0.5 / 255.0)
        });
        eprintln!(
            "{file}: {} coverage mismatches, {:.4} of the pixels off by more than 4/255, max {}",
            r.coverage_mismatch, r.share_over, r.max
        );
        assert_eq!(r.coverage_mismatch, 0);
        r.share_over
    };
    // Nearest: the same texel but where u·W or (1 − v)·H falls within rounding of a texel edge.
    settings.sampler = Sampler {
        wrap: Wrap::Clamp,
        filter: Filter::Nearest,
        mipmap: Mipmap::None,
        anisotropy: 1,
        lod_bias: 0.0,
    };
    assert!(measure(&scene, &settings, "a3_output_texture.png") < 0.006);
    // Bilinear: the framework reads half a texel off OpenGL's convention (texel centres on
    // integers); with every uv moved by (+½, −½) texel the two agree.
    settings.sampler.filter = Filter::Bilinear;
    let as_is = measure(&scene, &settings, "a3_output_texture_bilinear.png");
    let mut mesh = (*scene.objects[0].mesh).clone();
    for uv in &mut mesh.uvs {
        *uv += glam::Vec2::new(0.5, -0.5) / 1024.0;
    }
    scene.objects[0].mesh = std::sync::Arc::new(mesh);
    let moved = measure(&scene, &settings, "a3_output_texture_bilinear.png");
    assert!(moved < 0.005 && moved < as_is / 4.0, "{moved} vs {as_is}");
}
