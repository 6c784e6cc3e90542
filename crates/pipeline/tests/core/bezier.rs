//! Bézier curves: de Casteljau against the Bernstein form and hand values.

use glam::Vec2;
use pipeline::bezier::{bernstein, de_casteljau, point};

#[test]
fn de_casteljau_equals_the_bernstein_form() {
    let p = [
        Vec2::new(0.0, 0.0),
        Vec2::new(0.0, 1.0),
        Vec2::new(1.0, 1.0),
        Vec2::new(1.0, 0.0),
    ];
    // By hand at t = ½: level 1 (0, ½), (½, 1), (1, ½); level 2 (¼, ¾), (¾, ¾); b = (½, ¾).
    let levels = de_casteljau(&p, 0.5);
    assert_eq!(levels.len(), 4);
    assert_eq!(
        levels[1],
        [
            Vec2::new(0.0, 0.5),
            Vec2::new(0.5, 1.0),
            Vec2::new(1.0, 0.5)
        ]
    );
    assert_eq!(levels[2], [Vec2::new(0.25, 0.75), Vec2::new(0.75, 0.75)]);
    assert_eq!(levels[3], [Vec2::new(0.5, 0.75)]);
    // The Bernstein form gives the same point everywhere; the ends are interpolated.
    for k in 0..=100 {
        let t = k as f32 / 100.0;
        let a = de_casteljau(&p, t)[3][0];
        let b = point(&p, t);
        assert!((a - b).length() < 1e-5, "t = {t}: {a} vs {b}");
    }
    assert_eq!(point(&p, 0.0), p[0]);
    assert!((point(&p, 1.0) - p[3]).length() < 1e-6);
    // The Bernstein basis is a partition of unity; B_1^3(t) = 3t(1 − t)².
    for k in 0..=10 {
        let t = k as f32 / 10.0;
        let sum: f32 = (0..=3).map(|i| bernstein(3, i, t)).sum();
        assert!((sum - 1.0).abs() < 1e-6);
        assert!((bernstein(3, 1, t) - 3.0 * t * (1.0 - t).powi(2)).abs() < 1e-6);
    }
}

#[test]
fn the_construction_mesh_draws_each_part() {
    use pipeline::mesh::BuiltinMesh;
    let points = [
        Vec2::new(-1.0, -0.5),
        Vec2::new(-0.5, 0.8),
        Vec2::new(0.6, 0.9),
        Vec2::new(1.0, -0.4),
    ];
    let at = |t: f32| {
        BuiltinMesh::Bezier {
            points,
            t,
            levels: 3,
        }
        .build()
    };
    // More of the curve is drawn as t grows; every vertex lies in z ∈ [0, 0.005] and the
    // point b(t) is at the centre of one of the squares.
    assert!(at(0.9).indices.len() > at(0.1).indices.len());
    let m = at(0.5);
    assert!(m.positions.iter().all(|p| (0.0..=0.005).contains(&p.z)));
    let b = point(&points, 0.5);
    assert!(
        m.positions
            .chunks(4)
            .any(|q| (q.iter().map(|p| p.truncate()).sum::<Vec2>() / 4.0 - b).length() < 1e-5),
        "a square at b(t)"
    );
}

/// `levels` draws that many levels of the construction: none shows the control points and the
/// polygon only (labelled P0…P3), one adds the three first-level points with `t` written beside
/// the first, three ends at b(t) with its label; the labels land on the screen in the capture.
#[test]
fn the_construction_draws_the_levels_asked_for_and_labels_them() {
    use pipeline::mesh::BuiltinMesh;
    let points = [
        Vec2::new(-1.0, -0.5),
        Vec2::new(-0.5, 0.8),
        Vec2::new(0.6, 0.9),
        Vec2::new(1.0, -0.4),
    ];
    let build = |levels: u8| {
        BuiltinMesh::Bezier {
            points,
            t: 0.3,
            levels,
        }
        .build()
    };
    let texts =
        |m: &pipeline::mesh::Mesh| m.labels.iter().map(|l| l.text.clone()).collect::<Vec<_>>();
    let none = build(0);
    assert_eq!(texts(&none), ["P0", "P1", "P2", "P3"]);
    let one = build(1);
    assert_eq!(texts(&one)[4], "t = 0.30");
    let first = points[0].lerp(points[1], 0.3);
    assert!(
        (one.labels[4].position.truncate() - first).length() < 0.2,
        "beside P_0¹"
    );
    let all = build(3);
    assert_eq!(texts(&all)[4], "b(t), t = 0.30");
    assert!(none.indices.len() < one.indices.len() && one.indices.len() < all.indices.len());
    // Rendered: each label projected to the image, inside it.
    let mut object = pipeline::scene::Object::new("curve", all);
    object.color = pipeline::scene::ColorSource::Uniform(glam::Vec3::ONE);
    let scene = pipeline::scene::Scene {
        uniforms: Default::default(),
        objects: vec![object],
        camera: pipeline::camera::Camera {
            eye: glam::Vec3::new(0.0, 0.0, 5.0),
            at: glam::Vec3::ZERO,
            up: glam::Vec3::Y,
        },
        projection: pipeline::camera::Projection::Ortho {
            left: -1.5,
            right: 1.5,
            bottom: -1.0,
            top: 1.0,
            near: 1.0,
            far: 10.0,
        },
        ..pipeline::scene::Scene::default()
    };
    let settings = pipeline::settings::RenderSettings {
        width: 300,
        height: 200,
        ..Default::default()
    };
    let capture = pipeline::render(&scene, &settings).expect("renders");
    assert_eq!(capture.labels.len(), 5);
    // P0 = (−1, −0.5) is labelled 0.13 to its left: x_w = (−1.13 + 1.5)/3·300 = 37,
    // y_w = (−0.5 + 1)·200/2 = 50, image row 200 − 50 = 150.
    let p0 = &capture.labels[0];
    assert!(
        (p0.image[0] - 37.0).abs() < 0.01 && (p0.image[1] - 150.0).abs() < 0.01,
        "{p0:?}"
    );
}

/// A patch by de Casteljau in u then v equals the tensor-product Bernstein form
/// `Σ_i Σ_j B_i(v)·B_j(u)·P_ij`; its normal is perpendicular to the surface (checked against
/// finite differences) and points up; lesson 19's worked example: a flat net with its four middle
/// points at height 1 has b(½, ½) at height (3/4)² = 0.5625.
#[test]
fn a_patch_is_the_tensor_product_of_two_cubics() {
    use glam::Vec3;
    use pipeline::bezier::patch_point;
    use pipeline::mesh::patch::control_points;
    let heights = [
        [0.0, 0.3, -0.2, 0.1],
        [0.4, 1.2, 0.8, -0.3],
        [0.1, 0.9, 1.1, 0.2],
        [-0.2, 0.2, 0.5, 0.0],
    ];
    let rows = control_points(&heights);
    let tensor = |u: f32, v: f32| -> Vec3 {
        (0..4)
            .flat_map(|i| (0..4).map(move |j| (i, j)))
            .map(|(i, j)| rows[i][j] * bernstein(3, i as u32, v) * bernstein(3, j as u32, u))
            .sum()
    };
    for (u, v) in [(0.0, 0.0), (0.35, 0.65), (0.5, 0.5), (0.9, 0.2), (1.0, 1.0)] {
        let (_, b, n) = patch_point(&rows, u, v);
        assert!((b - tensor(u, v)).length() < 1e-5, "b({u}, {v})");
        assert!(n.y > 0.0, "the normal points up at ({u}, {v})");
        let h = 1e-3;
        let du = tensor((u + h).min(1.0), v) - tensor((u - h).max(0.0), v);
        let dv = tensor(u, (v + h).min(1.0)) - tensor(u, (v - h).max(0.0));
        assert!(n.dot(du.normalize()).abs() < 1e-2 && n.dot(dv.normalize()).abs() < 1e-2);
    }
    let raised = control_points(&[
        [0.0; 4],
        [0.0, 1.0, 1.0, 0.0],
        [0.0, 1.0, 1.0, 0.0],
        [0.0; 4],
    ]);
    let (q, b, _) = patch_point(&raised, 0.5, 0.5);
    assert!((q[1].y - 0.75).abs() < 1e-6 && q[0].y.abs() < 1e-6);
    assert!((b.y - 0.5625).abs() < 1e-6, "{}", b.y);
}
