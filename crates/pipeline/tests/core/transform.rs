//! The modelling transforms — rotations, translation, scale, shear, slerp, a rotation about any
//! axis, the planar shadow — against references that do not come from the code under test (the
//! viewing and projection matrices: `projection.rs`).

use glam::{Mat4, Vec3, Vec4};
use pipeline::transform::{self as tf, Quaternion};

pub(crate) fn assert_mat_eq(a: &Mat4, b: &Mat4, tol: f32, what: &str) {
    let (ra, rb) = (tf::to_rows(a), tf::to_rows(b));
    for i in 0..4 {
        for j in 0..4 {
            let scale = 1.0f32.max(ra[i][j].abs()).max(rb[i][j].abs());
            assert!(
                (ra[i][j] - rb[i][j]).abs() <= tol * scale,
                "{what}: element ({i},{j}) differs: {} vs {}\n{ra:?}\n{rb:?}",
                ra[i][j],
                rb[i][j]
            );
        }
    }
}

pub(crate) fn assert_vec_eq(a: Vec3, b: Vec3, tol: f32, what: &str) {
    assert!((a - b).abs().max_element() <= tol, "{what}: {a} vs {b}");
}

pub(crate) fn random_vec(rng: &mut fastrand::Rng, scale: f32) -> Vec3 {
    Vec3::new(rng.f32() - 0.5, rng.f32() - 0.5, rng.f32() - 0.5) * 2.0 * scale
}

#[test]
fn elementary_rotations_turn_axes_as_the_right_hand_rule_says() {
    let q = std::f32::consts::FRAC_PI_2;
    let p = |m: Mat4, v: Vec3| m.transform_point3(v);
    assert_vec_eq(p(tf::rotate_z(q), Vec3::X), Vec3::Y, 1e-6, "Rz(90°)·x");
    assert_vec_eq(p(tf::rotate_x(q), Vec3::Y), Vec3::Z, 1e-6, "Rx(90°)·y");
    assert_vec_eq(p(tf::rotate_y(q), Vec3::Z), Vec3::X, 1e-6, "Ry(90°)·z");
    // Hand-computed: Rz(30°)·(2, 0, 5) = (2cos30°, 2sin30°, 5) = (√3, 1, 5).
    let r = p(tf::rotate_z(30f32.to_radians()), Vec3::new(2.0, 0.0, 5.0));
    assert_vec_eq(r, Vec3::new(3f32.sqrt(), 1.0, 5.0), 1e-6, "Rz(30°)");
    for a in [-2.0f32, -0.3, 0.7, 3.0] {
        assert_mat_eq(
            &tf::rotate_x(a),
            &Mat4::from_rotation_x(a),
            1e-6,
            "Rx vs glam",
        );
        assert_mat_eq(
            &tf::rotate_y(a),
            &Mat4::from_rotation_y(a),
            1e-6,
            "Ry vs glam",
        );
        assert_mat_eq(
            &tf::rotate_z(a),
            &Mat4::from_rotation_z(a),
            1e-6,
            "Rz vs glam",
        );
    }
}

#[test]
fn translate_scale_shear_by_hand() {
    let p = Vec3::new(1.0, 2.0, 3.0);
    assert_vec_eq(
        tf::translate(Vec3::new(4.0, -1.0, 0.5)).transform_point3(p),
        Vec3::new(5.0, 1.0, 3.5),
        0.0,
        "T",
    );
    // A vector (w = 0) is not moved by a translation.
    let v = tf::translate(Vec3::new(4.0, -1.0, 0.5)) * Vec4::new(1.0, 2.0, 3.0, 0.0);
    assert_eq!(v, Vec4::new(1.0, 2.0, 3.0, 0.0));
    assert_vec_eq(
        tf::scale(Vec3::new(2.0, 3.0, -1.0)).transform_point3(p),
        Vec3::new(2.0, 6.0, -3.0),
        0.0,
        "S",
    );
    let h = tf::shear(tf::Shear {
        xy: 0.5,
        zx: 2.0,
        ..tf::Shear::default()
    });
    // x' = x + 0.5·y = 2, y' = y = 2, z' = z + 2·x = 5.
    assert_vec_eq(
        h.transform_point3(p),
        Vec3::new(2.0, 2.0, 5.0),
        1e-6,
        "shear",
    );
    // Order of composition: T·R ≠ R·T.
    let (t, r) = (
        tf::translate(Vec3::X),
        tf::rotate_z(std::f32::consts::FRAC_PI_2),
    );
    assert_vec_eq(
        (t * r).transform_point3(Vec3::X),
        Vec3::new(1.0, 1.0, 0.0),
        1e-6,
        "T·R",
    );
    assert_vec_eq(
        (r * t).transform_point3(Vec3::X),
        Vec3::new(0.0, 2.0, 0.0),
        1e-6,
        "R·T",
    );
}

/// slerp against glam's `Quat::slerp` on random pairs (sign-insensitive: q and −q are one
/// rotation), the constant angular speed (the angle from q₀ grows as t·2Ω), and the notes'
/// halfway example worked by hand: q₀ = 90° about (1, 1, 0)/√2 = (0.707, 0.5, 0.5, 0),
/// q₁ = 90° about z = (0.707, 0, 0, 0.707), cos Ω = 0.5, both weights sin 30°/sin 60° = 0.577,
/// slerp = (0.816, 0.289, 0.289, 0.408): 70.5° about (0.5, 0.5, 0.707).
#[test]
fn slerp_follows_the_shorter_arc_at_constant_speed() {
    let mut rng = fastrand::Rng::with_seed(11);
    let same = |a: &Quaternion, b: glam::Quat| -> f32 {
        let d = a.w * b.w + a.v.dot(glam::Vec3::new(b.x, b.y, b.z));
        1.0 - d.abs()
    };
    for _ in 0..500 {
        let (a0, a1) = (random_vec(&mut rng, 1.0), random_vec(&mut rng, 1.0));
        if a0.length() < 1e-3 || a1.length() < 1e-3 {
            continue;
        }
        let (t0, t1) = (rng.f32() * 6.0 - 3.0, rng.f32() * 6.0 - 3.0);
        let q0 = Quaternion::from_axis_angle(a0, t0).expect("axis has a length");
        let q1 = Quaternion::from_axis_angle(a1, t1).expect("axis has a length");
        let g0 = glam::Quat::from_axis_angle(a0.normalize(), t0);
        let g1 = glam::Quat::from_axis_angle(a1.normalize(), t1);
        let arc = q0.arc_to(&q1);
        for t in [0.0, 0.25, 0.5, 0.9, 1.0] {
            let q = q0.slerp(&q1, t);
            assert!(same(&q, g0.slerp(g1, t)) < 1e-4, "slerp vs glam at t = {t}");
            // The angle between q₀ and q(t) on the 4-D sphere is t·Ω.
            let travelled = q0.dot(&q).abs().min(1.0).acos();
            assert!((travelled - t * arc.omega).abs() < 2e-3, "constant speed");
        }
    }
    let q0 = Quaternion::from_axis_angle(Vec3::new(1.0, 1.0, 0.0), 90f32.to_radians())
        .expect("axis has a length");
    let q1 = Quaternion::from_axis_angle(Vec3::Z, 90f32.to_radians()).expect("axis has a length");
    let arc = q0.arc_to(&q1);
    assert!((arc.omega.to_degrees() - 60.0).abs() < 1e-3);
    let (a, b) = arc.weights(0.5);
    assert!((a - 0.577_35).abs() < 1e-4 && (b - 0.577_35).abs() < 1e-4);
    let half = q0.slerp(&q1, 0.5);
    assert!((half.w - 0.816_5).abs() < 1e-3);
    assert_vec_eq(half.v, Vec3::new(0.288_7, 0.288_7, 0.408_2), 1e-3, "v");
    let (axis, angle) = half.axis_angle();
    assert!((angle.to_degrees() - 70.53).abs() < 0.01);
    assert_vec_eq(
        axis,
        Vec3::new(0.5, 0.5, std::f32::consts::FRAC_1_SQRT_2),
        1e-3,
        "axis",
    );
    // Past a half turn apart the other sign is nearer: slerp takes −q₁.
    let far = Quaternion::from_axis_angle(Vec3::Y, 3.0).expect("axis has a length");
    let near = Quaternion::from_axis_angle(Vec3::Y, -3.0).expect("axis has a length");
    assert!(far.arc_to(&near).flipped);
}

#[test]
fn arbitrary_axis_rotation_four_ways_agree() {
    let mut rng = fastrand::Rng::with_seed(7);
    for _ in 0..500 {
        let axis = random_vec(&mut rng, 1.0);
        if axis.length() < 1e-3 {
            continue;
        }
        let theta = (rng.f32() - 0.5) * 4.0 * std::f32::consts::PI;
        let notes = tf::rotate_axis_aligned(axis, theta).expect("axis has a length");
        let rodrigues = tf::rotate_axis_rodrigues(axis, theta).expect("axis has a length");
        let quat = Quaternion::from_axis_angle(axis, theta).expect("axis has a length");
        let reference = Mat4::from_axis_angle(axis.normalize(), theta);
        assert_mat_eq(
            &notes.matrix,
            &reference,
            2e-5,
            "Rx(−θx)Ry(−θy)Rz(θ)Ry(θy)Rx(θx) vs glam",
        );
        assert_mat_eq(&rodrigues, &reference, 2e-5, "Rodrigues vs glam");
        assert_mat_eq(
            &quat.to_matrix(),
            &reference,
            2e-5,
            "quaternion matrix vs glam",
        );
        let p = random_vec(&mut rng, 3.0);
        assert_vec_eq(
            quat.rotate(p),
            reference.transform_point3(p),
            1e-4,
            "q·p·q*",
        );
        // The factors multiply to the matrix, and the first two align the axis with z.
        let product = notes
            .factors
            .iter()
            .fold(Mat4::IDENTITY, |m, f| m * f.matrix);
        assert_mat_eq(&product, &notes.matrix, 1e-6, "factor product");
        let align = notes.factors[3].matrix * notes.factors[4].matrix;
        assert_vec_eq(
            align.transform_vector3(axis.normalize()),
            Vec3::Z,
            1e-5,
            "Ry(θy)Rx(θx)·u = z",
        );
    }
    // Axes along x (d = 0) and along −z are handled.
    for axis in [Vec3::X, Vec3::NEG_X, Vec3::NEG_Z, Vec3::Y] {
        let m = tf::rotate_axis_aligned(axis, 0.4).expect("unit axis");
        assert_mat_eq(
            &m.matrix,
            &Mat4::from_axis_angle(axis, 0.4),
            1e-6,
            "special axis",
        );
    }
    assert!(tf::rotate_axis_rodrigues(Vec3::ZERO, 1.0).is_err());
}

#[test]
fn planar_shadow_matches_the_closed_form() {
    let light = Vec3::new(1.0, 5.0, -2.0);
    let m = tf::planar_shadow(light);
    let product = m.factors.iter().fold(Mat4::IDENTITY, |a, f| a * f.matrix);
    assert_mat_eq(&product, &m.matrix, 1e-6, "factors");
    for p in [
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(2.0, 3.0, 1.0),
        Vec3::new(-1.5, 0.5, 4.0),
    ] {
        let q = m.matrix * p.extend(1.0);
        let q = q.truncate() / q.w;
        let k = light.y / (p.y - light.y);
        let expect = Vec3::new(
            light.x - (p.x - light.x) * k,
            0.0,
            light.z - (p.z - light.z) * k,
        );
        assert_vec_eq(q, expect, 1e-5, "x_p = x_l − (x − x_l)·y_l/(y − y_l)");
        // The shadow point lies on the ray from the light through p.
        let along = (p - light).normalize().cross((q - light).normalize());
        assert!(along.length() < 1e-5);
    }
}

#[test]
fn an_object_rotated_about_an_arbitrary_axis() {
    use pipeline::mesh::BuiltinMesh;
    use pipeline::scene::Object;
    // 120° about (1, 1, 1) cycles the axes: x → y → z → x (by hand: the axis is fixed and
    // three turns of 120° are the identity).
    let mut o = Object::new("cube", BuiltinMesh::Cube.build());
    o.translate = glam::Vec3::new(0.0, 0.0, 5.0);
    o.axis_rotation = Some((glam::Vec3::ONE, 120.0));
    let m = o.model_matrix();
    let p = m.matrix * glam::Vec4::new(1.0, 0.0, 0.0, 1.0);
    assert!(
        (p - glam::Vec4::new(0.0, 1.0, 5.0, 1.0)).length() < 1e-5,
        "{p}"
    );
    // The factors: T, then the notes' five (Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)), then the Euler
    // rotations and S; their product is M.
    assert_eq!(m.factors[0].name, "T");
    assert_eq!(m.factors[1].factors.len(), 5);
    let product = m
        .factors
        .iter()
        .fold(glam::Mat4::IDENTITY, |a, f| a * f.matrix);
    assert!(product.abs_diff_eq(m.matrix, 1e-6));
}
