//! Whole frames at the edges of the rules: a triangle across the near plane and across w = 0,
//! perspective-correct interpolation on a grazing plane, the depth test in any order,
//! multisampling and supersampling, the owner of a shared pixel, the fragment replay, linear
//! depth, the capture's memory bound, and coordinates far out of range.

use glam::{Vec2, Vec3};
use pipeline::camera::{Camera, Projection};
use pipeline::capture::Fate;
use pipeline::mesh::Mesh;
use pipeline::raster::NONE;
use pipeline::raster::{DepthTest, Samples};
use pipeline::scene::{ColorSource, Object, Scene};
use pipeline::settings::RenderSettings;

use crate::raster::inside_convex;
use crate::support::{pixel_scene, render};

/// A camera at the origin looking down −z, 90° field of view, square viewport.
fn camera_scene(mesh: Mesh, size: u32) -> (Scene, RenderSettings) {
    let mut object = Object::new("plane", mesh);
    object.color = ColorSource::Vertex;
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![object],
        camera: Camera {
            eye: Vec3::ZERO,
            at: Vec3::NEG_Z,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 90.0,
            aspect: None,
            near: 0.5,
            far: 200.0,
        },
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: size,
        height: size,
        ..RenderSettings::default()
    };
    (scene, settings)
}

/// The world point seen through the centre of window pixel (x, y) on the plane y = −1, for the
/// camera of [`camera_scene`]: the ray (sx, sy, −1) with s = 2(x+½)/size − 1 (tan 45° = 1).
fn floor_hit(x: u32, y: u32, size: u32) -> Option<Vec3> {
    let sx = 2.0 * (x as f32 + 0.5) / size as f32 - 1.0;
    let sy = 2.0 * (y as f32 + 0.5) / size as f32 - 1.0;
    (sy < 0.0).then(|| Vec3::new(sx, sy, -1.0) * (-1.0 / sy))
}

fn mesh_of(positions: Vec<Vec3>, colors: Vec<Vec3>, indices: Vec<[u32; 3]>) -> Mesh {
    let n = positions.len();
    Mesh {
        name: "test".into(),
        positions,
        normals: vec![Vec3::Y; n],
        uvs: Vec::new(),
        colors,
        indices,
        labels: Vec::new(),
    }
}

#[test]
fn a_triangle_crossing_the_near_plane_renders_exactly_its_visible_part() {
    // On the floor y = −1: one vertex far in front, two behind the camera (z = +10).
    let tri = [
        Vec3::new(-30.0, -1.0, 10.0),
        Vec3::new(30.0, -1.0, 10.0),
        Vec3::new(0.0, -1.0, -60.0),
    ];
    let size = 64;
    let (scene, settings) = camera_scene(
        mesh_of(tri.to_vec(), vec![Vec3::ONE; 3], vec![[0, 1, 2]]),
        size,
    );
    let capture = render(&scene, &settings);
    assert_eq!(capture.primitives[0].fate, Fate::Clipped);
    let poly = capture.primitives[0]
        .clipped_polygon
        .as_ref()
        .expect("clipped polygon recorded");
    for v in poly {
        let c = v.clip;
        assert!(
            c.w > 0.0 && c.z >= -c.w * (1.0 + 1e-5),
            "clipped vertex {c} outside"
        );
    }
    let tri2 = tri.map(|p| Vec2::new(p.x, p.z));
    let mut checked = 0;
    for y in 0..size {
        for x in 0..size {
            let covered = capture.samples.triangle[capture.samples.index(x, y, 0)] != NONE;
            let expected = floor_hit(x, y, size).map_or(Some(false), |hit| {
                let in_depth = -hit.z >= 0.5 && -hit.z <= 200.0;
                // The triangle's xz outline is clockwise seen from +y; test with both windings.
                let mut ring = tri2.to_vec();
                ring.reverse();
                if !in_depth {
                    Some(false)
                } else {
                    inside_convex(&ring, Vec2::new(hit.x, hit.z), 0.05)
                }
            });
            if let Some(e) = expected {
                assert_eq!(covered, e, "pixel ({x}, {y})");
                checked += 1;
            }
        }
    }
    assert!(
        checked > size * size * 9 / 10,
        "most pixels are decided analytically ({checked})"
    );
}

#[test]
fn vertices_behind_the_camera_and_across_w_zero() {
    let behind = vec![
        Vec3::new(-1.0, 0.0, 2.0),
        Vec3::new(1.0, 0.0, 2.0),
        Vec3::new(0.0, 1.0, 3.0),
    ];
    let (scene, settings) = camera_scene(mesh_of(behind, vec![Vec3::ONE; 3], vec![[0, 1, 2]]), 32);
    let capture = render(&scene, &settings);
    assert!(matches!(capture.primitives[0].fate, Fate::Outside { .. }));
    assert!(
        capture
            .vertices
            .iter()
            .all(|v| v.ndc.is_none() && v.clip.w < 0.0)
    );
    assert!(capture.samples.triangle.iter().all(|&t| t == NONE));

    // A triangle with a vertex at the eye is seen edge-on: a line on screen, nothing drawn.
    let edge_on = vec![
        Vec3::ZERO,
        Vec3::new(1.0, -1.0, -5.0),
        Vec3::new(-1.0, -1.0, -2.0),
    ];
    let (scene, settings) = camera_scene(mesh_of(edge_on, vec![Vec3::ONE; 3], vec![[0, 1, 2]]), 32);
    let capture = render(&scene, &settings);
    assert_eq!(capture.primitives[0].fate, Fate::Degenerate);
    assert!(capture.pixels.color.iter().flatten().all(|v| v.is_finite()));

    // A vertex beside the eye (z_eye = 0, so w = 0) and one exactly on the near plane.
    let mixed = vec![
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(1.0, -1.0, -5.0),
        Vec3::new(-0.2, -0.2, -0.5),
    ];
    let (scene, settings) = camera_scene(mesh_of(mixed, vec![Vec3::ONE; 3], vec![[0, 1, 2]]), 32);
    let capture = render(&scene, &settings);
    assert_eq!(capture.vertices[0].clip.w, 0.0);
    assert!(capture.vertices[0].ndc.is_none(), "no division by w = 0");
    assert_eq!(capture.primitives[0].fate, Fate::Clipped);
    let finite = capture.pixels.color.iter().flatten().all(|v| v.is_finite())
        && capture.pixels.depth.iter().all(|v| v.is_finite());
    assert!(finite, "no NaN or infinity in any buffer");
}

#[test]
fn perspective_correct_interpolation_on_a_grazing_plane() {
    // A floor quad x ∈ [−4, 4], z ∈ [−1, −41] at y = −1, colours = (u, v, 0) with
    // u = (x + 4)/8, v = (−1 − z)/40: the analytic u, v at each pixel come from the ray hit.
    let corners = [(-4.0, -1.0), (4.0, -1.0), (4.0, -41.0), (-4.0, -41.0)];
    let positions: Vec<Vec3> = corners
        .iter()
        .map(|&(x, z)| Vec3::new(x, -1.0, z))
        .collect();
    let uv = |p: Vec3| Vec3::new((p.x + 4.0) / 8.0, (-1.0 - p.z) / 40.0, 0.0);
    let colors = positions.iter().map(|&p| uv(p)).collect();
    let size = 96;
    let mesh = mesh_of(positions, colors, vec![[0, 1, 2], [0, 2, 3]]);
    let (scene, mut settings) = camera_scene(mesh, size);
    let correct = render(&scene, &settings);
    settings.perspective_correct = false;
    let affine = render(&scene, &settings);
    let (mut max_correct, mut max_affine, mut n) = (0.0f32, 0.0f32, 0);
    for y in 0..size {
        for x in 0..size {
            let i = ((size - 1 - y) * size + x) as usize;
            if correct.pixels.coverage[i] == 0 {
                continue;
            }
            let Some(hit) = floor_hit(x, y, size) else {
                panic!("pixel ({x}, {y}) covered above the horizon");
            };
            let expect = uv(hit);
            let got = Vec3::from(correct.pixels.color[i]);
            let got_affine = Vec3::from(affine.pixels.color[i]);
            max_correct = max_correct.max((got - expect).abs().max_element());
            max_affine = max_affine.max((got_affine - expect).abs().max_element());
            n += 1;
        }
    }
    assert!(
        n > 1000,
        "the plane covers the lower part of the image ({n} pixels)"
    );
    assert!(
        max_correct < 2e-3,
        "perspective-correct error {max_correct}"
    );
    assert!(
        max_affine > 0.1,
        "affine interpolation must visibly differ ({max_affine})"
    );
}

#[test]
fn the_depth_test_keeps_the_nearest_whatever_the_order() {
    let near_tri = [
        Vec3::new(-1.0, -1.0, -2.0),
        Vec3::new(1.0, -1.0, -2.0),
        Vec3::new(0.0, 1.0, -2.0),
    ];
    let far_tri = [
        Vec3::new(-2.0, -2.0, -4.0),
        Vec3::new(2.0, -2.0, -4.0),
        Vec3::new(0.0, 2.0, -4.0),
    ];
    for order in [[near_tri, far_tri], [far_tri, near_tri]] {
        let positions: Vec<Vec3> = order.iter().flatten().copied().collect();
        let colors = positions
            .iter()
            .map(|p| if p.z == -2.0 { Vec3::X } else { Vec3::Y })
            .collect();
        let (scene, mut settings) =
            camera_scene(mesh_of(positions, colors, vec![[0, 1, 2], [3, 4, 5]]), 32);
        settings.depth_test = DepthTest::Less;
        let c = render(&scene, &settings);
        let centre = (16 * 32 + 16) as usize;
        assert_eq!(
            c.pixels.color[centre],
            [1.0, 0.0, 0.0],
            "the near (red) triangle wins"
        );
        // Depth at the centre: window z of eye depth 2 with near 0.5, far 200:
        // z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d), z_w = (z_ndc+1)/2.
        let (n, f, d) = (0.5f32, 200.0f32, 2.0f32);
        let z_ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * d);
        assert!((c.pixels.depth[centre] - (z_ndc + 1.0) / 2.0).abs() < 1e-5);
    }
}

#[test]
fn multisampling_counts_samples_and_resolves_colour() {
    // A half-plane x ≤ 8.5 (through the centres of column 8) over a 16×16 window, 4 samples.
    let (scene, mut settings) = pixel_scene(
        16,
        16,
        &[
            [
                Vec2::new(-10.0, -10.0),
                Vec2::new(8.5, -10.0),
                Vec2::new(8.5, 40.0),
            ],
            [
                Vec2::new(-10.0, -10.0),
                Vec2::new(8.5, 40.0),
                Vec2::new(-10.0, 40.0),
            ],
        ],
    );
    settings.samples = Samples::X4;
    settings.background = Vec3::ZERO;
    let c = render(&scene, &settings);
    // Column 8: the rotated-grid samples at x offsets 0.375, 0.875, 0.125, 0.625: two are left of
    // 8.5 → coverage 2 of 4 in every row; columns < 8 fully covered, > 8 empty.
    for y in 0..16 {
        let i = |x: u32| ((15 - y) * 16 + x) as usize;
        assert_eq!(c.pixels.coverage[i(7)], 4);
        assert_eq!(c.pixels.coverage[i(8)], 2);
        assert_eq!(c.pixels.coverage[i(9)], 0);
    }
}

#[test]
fn the_fragment_replay_agrees_with_the_buffers() {
    // Overlapping triangles at different depths, in a random order, with 4 samples.
    let mut rng = fastrand::Rng::with_seed(21);
    let mut positions = Vec::new();
    for _ in 0..12 {
        let c = Vec3::new(
            rng.f32() * 2.0 - 1.0,
            rng.f32() * 2.0 - 1.0,
            -2.0 - rng.f32() * 6.0,
        );
        for _ in 0..3 {
            positions.push(c + Vec3::new(rng.f32() - 0.5, rng.f32() - 0.5, rng.f32() - 0.5) * 2.0);
        }
    }
    let indices = (0..12u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
    let colors = vec![Vec3::ONE; positions.len()];
    let (scene, mut settings) = camera_scene(mesh_of(positions, colors, indices), 24);
    settings.samples = Samples::X4;
    let c = render(&scene, &settings);
    for y in 0..24 {
        for x in 0..24 {
            let fragments = c.fragments_at(x, y);
            for s in 0..4 {
                // The last fragment that passed at a sample is the one the buffer holds.
                let last = fragments
                    .iter()
                    .rev()
                    .find(|f| f.samples[s] == Some(true))
                    .map(|f| f.triangle);
                let held = c.samples.triangle[c.samples.index(x, y, s)];
                assert_eq!(last.unwrap_or(NONE), held, "pixel ({x}, {y}) sample {s}");
            }
        }
    }
}

#[test]
fn supersampling_shades_each_sample_where_multisampling_shades_the_centre() {
    // A half-plane x ≤ 8.5 whose red channel is x/16 (colours are affine in x under this
    // orthographic camera), 4 samples. Column 8 keeps the two rotated-grid samples left of 8.5.
    // Multisampling: both take the colour at the centre (8.5/16); supersampling: their own.
    let corners = [
        Vec2::new(-16.0, -16.0),
        Vec2::new(8.5, -16.0),
        Vec2::new(8.5, 48.0),
        Vec2::new(-16.0, 48.0),
    ];
    let positions: Vec<Vec3> = corners.iter().map(|p| p.extend(0.0)).collect();
    let colors = corners
        .iter()
        .map(|p| Vec3::new(p.x / 16.0, 0.0, 0.0))
        .collect();
    let mesh = mesh_of(positions, colors, vec![[0, 1, 2], [0, 2, 3]]);
    let (mut scene, mut settings) = pixel_scene(16, 16, &[]);
    scene.objects = vec![Object::new("half-plane", mesh)];
    settings.samples = Samples::X4;
    settings.background = Vec3::ZERO;
    settings.depth_test = DepthTest::Less;
    let i = (8 * 16 + 8) as usize;
    let msaa = render(&scene, &settings);
    settings.per_sample_shading = true;
    let ssaa = render(&scene, &settings);
    let covered: Vec<f32> = (0..4)
        .map(|s| crate::support::sample_position(Samples::X4, 8, 7, s))
        .filter(|p| p.x < 8.5)
        .map(|p| p.x)
        .collect();
    assert_eq!(covered.len(), 2);
    let expect_msaa = 2.0 * (8.5 / 16.0) / 4.0;
    let expect_ssaa = covered.iter().map(|x| x / 16.0).sum::<f32>() / 4.0;
    assert!(
        (msaa.pixels.color[i][0] - expect_msaa).abs() < 1e-4,
        "{} vs {expect_msaa}",
        msaa.pixels.color[i][0]
    );
    assert!(
        (ssaa.pixels.color[i][0] - expect_ssaa).abs() < 1e-4,
        "{} vs {expect_ssaa}",
        ssaa.pixels.color[i][0]
    );
    assert!(
        (expect_msaa - expect_ssaa).abs() > 0.005,
        "the two differ here"
    );
}

#[test]
fn linearized_depth_is_the_eye_distance() {
    // Two parallel planes at eye distances 2 and 4 (near 0.5, far 200): the window depth is
    // non-linear, the eye distance recovered from it is exact.
    let quad = |z: f32, x0: f32| {
        [
            Vec3::new(x0, -1.0, z),
            Vec3::new(x0 + 0.5, -1.0, z),
            Vec3::new(x0 + 0.5, 1.0, z),
            Vec3::new(x0, 1.0, z),
        ]
    };
    let positions: Vec<Vec3> = quad(-2.0, -0.6)
        .into_iter()
        .chain(quad(-4.0, 0.4))
        .collect();
    let mesh = mesh_of(
        positions,
        vec![Vec3::ONE; 8],
        vec![[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]],
    );
    let (scene, settings) = camera_scene(mesh, 64);
    let c = render(&scene, &settings);
    for (x, d) in [(26u32, 2.0f32), (37, 4.0)] {
        let i = (32 * 64 + x) as usize;
        assert!(c.pixels.coverage[i] > 0, "pixel {x} covered");
        assert!(
            (c.eye_depth(c.pixels.depth[i]) - d).abs() < 1e-3,
            "{} vs {d}",
            c.eye_depth(c.pixels.depth[i])
        );
    }
    // Over the range [2, 4], linear depth maps the near plane to black, the far one to white.
    let img = c.depth_image(true, Some([2.0, 4.0]));
    assert_eq!(img.get_pixel(26, 32).0[0], 0);
    assert_eq!(img.get_pixel(37, 32).0[0], 255);
}

#[test]
fn the_capture_size_is_bounded_by_its_memory() {
    // 85 bytes a pixel (25 core, 34 lighting, 26 texturing) and 8 a sample.
    let s = RenderSettings {
        width: 1920,
        height: 1080,
        samples: Samples::X4,
        ..RenderSettings::default()
    };
    let pixels = 1920u64 * 1080;
    assert_eq!(s.capture_bytes(), pixels * 85 + pixels * 4 * 8);
    assert!(s.capture_bytes() < 250_000_000, "the issue's budget");
    assert!(s.capture_problem().is_none());
    let colour_only = RenderSettings {
        capture: pipeline::buffers::Capture::COLOR,
        ..s
    };
    assert_eq!(colour_only.capture_bytes(), pixels * 25 + pixels * 4 * 8);
    let uhd = RenderSettings {
        width: 3840,
        height: 2160,
        samples: Samples::X16,
        ..RenderSettings::default()
    };
    assert!(uhd.capture_problem().is_none(), "4K with 16 samples fits");
    let too_big = RenderSettings {
        width: 8192,
        height: 4320,
        ..uhd
    };
    let p = too_big
        .capture_problem()
        .expect("8K with 16 samples does not");
    // 8192·4320 pixels × (85 + 16·8) bytes = 7 537 950 720 bytes, 7188 MiB.
    assert_eq!(
        p,
        pipeline::settings::SettingsProblem::CaptureTooLarge {
            width: 8192,
            height: 4320,
            samples: 16,
            megabytes: 7188
        }
    );
    assert!(
        p.to_string()
            .starts_with("8192×4320 pixels × 16 samples needs about 7188 MB for a capture"),
        "{p}"
    );
}

#[test]
fn huge_and_coincident_coordinates_give_no_nan() {
    // Vertices at 1e30 (far outside every plane), one at 1e30 with two in view (clipped against
    // planes whose distances overflow nothing), and three coincident vertices.
    for positions in [
        vec![
            Vec3::new(1e30, 0.0, -5.0),
            Vec3::new(1e30, 1e30, -5.0),
            Vec3::new(0.0, 1e30, -1e30),
        ],
        vec![
            Vec3::new(1e30, 0.0, -5.0),
            Vec3::new(0.0, 0.5, -3.0),
            Vec3::new(-0.5, -0.5, -3.0),
        ],
        vec![Vec3::new(0.1, 0.1, -3.0); 3],
    ] {
        let (scene, settings) = camera_scene(
            mesh_of(positions.clone(), vec![Vec3::ONE; 3], vec![[0, 1, 2]]),
            32,
        );
        let c = render(&scene, &settings);
        let finite = c.pixels.color.iter().flatten().all(|v| v.is_finite())
            && c.pixels.depth.iter().all(|v| v.is_finite())
            && (0..c.pixels.owner.len())
                .filter_map(|i| c.barycentrics(i))
                .all(|b| b.perspective.iter().chain(&b.affine).all(|v| v.is_finite()));
        assert!(finite, "{positions:?}: a NaN or infinity in the buffers");
        assert!(c.pixel_record(16, 16).is_some());
    }
}

/// A pixel two primitives share belongs to the one that covers most of its samples, and on a
/// tie to the one at its earliest sample (not to the lower id). The 4× pattern's samples lie
/// at heights 1/8, 3/8, 5/8, 7/8 of the pixel (samples 0, 1, 2, 3): a horizontal edge at 1/4
/// leaves sample 0 alone below it, one at 1/2 splits them two and two.
#[test]
fn a_shared_pixel_belongs_to_the_primitive_with_most_samples_ties_to_the_earliest() {
    for (edge, above_first, above_owns) in [
        (8.25, false, true),
        (8.25, true, true),
        (8.5, true, false),
        (8.5, false, false),
    ] {
        let below = [
            Vec2::new(50.0, -300.0),
            Vec2::new(200.0, edge),
            Vec2::new(-100.0, edge),
        ];
        let above = [
            Vec2::new(-100.0, edge),
            Vec2::new(200.0, edge),
            Vec2::new(50.0, 300.0),
        ];
        let order = if above_first {
            [above, below]
        } else {
            [below, above]
        };
        let (scene, mut settings) = pixel_scene(16, 16, &order);
        settings.samples = Samples::X4;
        let c = render(&scene, &settings);
        let above_id = u32::from(!above_first);
        let want = if above_owns { above_id } else { 1 - above_id };
        for x in 0..16 {
            let i = (7 * 16 + x) as usize;
            assert_eq!(c.pixels.coverage[i], 4, "edge {edge}, pixel ({x}, 8)");
            assert_eq!(
                c.pixels.primitive[i], want,
                "edge {edge}, above first: {above_first}, pixel ({x}, 8)"
            );
        }
    }
}
