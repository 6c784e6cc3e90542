//! Every matrix against a reference that does not come from the code under test.

use glam::{Mat4, Vec3, Vec4};
use pipeline::transform::{self as tf, Quaternion, rows};

fn assert_mat_eq(a: &Mat4, b: &Mat4, tol: f32, what: &str) {
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

fn assert_vec_eq(a: Vec3, b: Vec3, tol: f32, what: &str) {
    assert!((a - b).abs().max_element() <= tol, "{what}: {a} vs {b}");
}

/// The `glOrtho` reference page: tx = −(r+l)/(r−l), ty = −(t+b)/(t−b), tz = −(f+n)/(f−n).
fn gl_ortho(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    rows([
        [2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
        [0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b)],
        [0.0, 0.0, -2.0 / (f - n), -(f + n) / (f - n)],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// The `glFrustum` reference page: A = (r+l)/(r−l), B = (t+b)/(t−b), C = −(f+n)/(f−n), D = −2fn/(f−n).
fn gl_frustum(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    rows([
        [2.0 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2.0 * n / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n)],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// The `gluPerspective` reference page: f = cotangent(fovy/2).
fn glu_perspective(fovy_deg: f32, aspect: f32, z_near: f32, z_far: f32) -> Mat4 {
    let f = 1.0 / (fovy_deg.to_radians() / 2.0).tan();
    rows([
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [
            0.0,
            0.0,
            (z_far + z_near) / (z_near - z_far),
            2.0 * z_far * z_near / (z_near - z_far),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// The `gluLookAt` reference page: f = normalize(center − eye), s = normalize(f × UP), u = s × f,
/// M = [s; u; −f] followed by glTranslated(−eye).
fn glu_look_at(eye: Vec3, center: Vec3, up: Vec3) -> Mat4 {
    let f = (center - eye).normalize();
    let s = f.cross(up).normalize();
    let u = s.cross(f);
    let m = rows([
        [s.x, s.y, s.z, 0.0],
        [u.x, u.y, u.z, 0.0],
        [-f.x, -f.y, -f.z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    m * Mat4::from_translation(-eye)
}

fn random_vec(rng: &mut fastrand::Rng, scale: f32) -> Vec3 {
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
fn look_at_matches_glu_look_at_glam_and_the_gt_form() {
    let mut rng = fastrand::Rng::with_seed(11);
    for _ in 0..300 {
        let eye = random_vec(&mut rng, 10.0);
        let at = random_vec(&mut rng, 10.0);
        let up = random_vec(&mut rng, 1.0);
        let dir = (at - eye).normalize();
        if (at - eye).length() < 0.1
            || up.length() < 0.1
            || dir.cross(up.normalize()).length() < 0.05
        {
            continue;
        }
        let m = tf::look_at(eye, at, up).expect("not degenerate");
        assert_mat_eq(&m, &glu_look_at(eye, at, up), 1e-4, "LookAt vs gluLookAt");
        let glam_m = glam::camera::rh::view::look_at_mat4(eye, at, up.normalize());
        assert_mat_eq(&m, &glam_m, 1e-4, "LookAt vs glam");
        let gt = tf::look_at_gt(eye, at - eye, up).expect("not degenerate");
        assert_mat_eq(&gt.matrix, &m, 1e-4, "R_view·T_view vs LookAt");
        // The eye goes to the origin, the gaze to −z.
        assert_vec_eq(m.transform_point3(eye), Vec3::ZERO, 1e-3, "eye → origin");
        assert_vec_eq(m.transform_vector3(dir), Vec3::NEG_Z, 1e-5, "g → −z");
    }
    // Angel's construction with v = v_up − (v_up·n)n gives the same frame.
    let (eye, at, up) = (
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(0.0, 0.5, -1.0),
        Vec3::new(0.2, 1.0, 0.1),
    );
    let n = (eye - at).normalize();
    let v = (up - up.dot(n) * n).normalize();
    let u = v.cross(n);
    let frame = tf::camera_frame(eye, at, up).expect("not degenerate");
    assert_vec_eq(frame.u, u, 1e-6, "u");
    assert_vec_eq(frame.v, v, 1e-6, "v");
    assert_vec_eq(frame.n, n, 1e-6, "n");
}

#[test]
fn look_at_reports_degenerate_cameras() {
    assert!(matches!(
        tf::look_at(Vec3::ONE, Vec3::ONE, Vec3::Y),
        Err(tf::TransformError::EyeAtCoincide(_))
    ));
    assert!(matches!(
        tf::look_at(Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y),
        Err(tf::TransformError::UpParallelToView { .. })
    ));
}

#[test]
fn ortho_frustum_perspective_match_the_reference_pages_and_glam() {
    let cases = [
        (-1.0, 1.0, -1.0, 1.0, 0.1, 100.0),
        (-2.0, 3.0, -0.5, 1.5, 1.0, 10.0),
        (0.5, 4.0, -3.0, -1.0, 2.0, 3.0),
    ];
    for (l, r, b, t, n, f) in cases {
        let o = tf::ortho(l, r, b, t, n, f);
        assert_mat_eq(
            &o.matrix,
            &gl_ortho(l, r, b, t, n, f),
            1e-6,
            "Ortho vs glOrtho",
        );
        let glam_o = glam::camera::rh::proj::opengl::orthographic(l, r, b, t, n, f);
        assert_mat_eq(&o.matrix, &glam_o, 1e-6, "Ortho vs glam");
        let st = o.factors[0].matrix * o.factors[1].matrix;
        assert_mat_eq(&st, &o.matrix, 1e-6, "S·T = Ortho");

        let p = tf::frustum(l, r, b, t, n, f);
        assert_mat_eq(
            &p.matrix,
            &gl_frustum(l, r, b, t, n, f),
            1e-6,
            "Frustum vs glFrustum",
        );
        let glam_p = glam::camera::rh::proj::opengl::frustum(l, r, b, t, n, f);
        assert_mat_eq(&p.matrix, &glam_p, 1e-5, "Frustum vs glam");
        let nsh = p.factors[0].matrix * p.factors[1].matrix * p.factors[2].matrix;
        assert_mat_eq(&nsh, &p.matrix, 1e-6, "N·S·H = Frustum");
        // H makes the frustum symmetric: the centre of the near rectangle goes onto the −z axis.
        let centre = Vec3::new((l + r) / 2.0, (b + t) / 2.0, -n);
        let hc = p.factors[2].matrix.transform_point3(centre);
        assert_vec_eq(hc, Vec3::new(0.0, 0.0, -n), 1e-5, "H·centre");
        // S·H puts the corner (r, t, −near) on the planes x = −z, y = −z.
        let sh = p.factors[1].matrix * p.factors[2].matrix;
        let corner = sh.transform_point3(Vec3::new(r, t, -n));
        assert!(
            (corner.x - n).abs() < 1e-5 && (corner.y - n).abs() < 1e-5,
            "S·H corner {corner}"
        );
    }
    for (fovy, aspect, n, f) in [
        (45.0, 16.0 / 9.0, 0.1, 50.0),
        (90.0, 1.0, 1.0, 10.0),
        (30.0, 0.5, 2.0, 7.0),
    ] {
        let p = tf::perspective(fovy, aspect, n, f);
        assert_mat_eq(
            &p.matrix,
            &glu_perspective(fovy, aspect, n, f),
            1e-5,
            "vs gluPerspective",
        );
        let glam_p =
            glam::camera::rh::proj::opengl::perspective(f32::to_radians(fovy), aspect, n, f);
        assert_mat_eq(&p.matrix, &glam_p, 1e-5, "vs glam perspective");
    }
    // The erratum: top = near·tan(fovy/2), not near·tan(fovy). For fovy = 90°, near = 1: top = 1.
    let [l, r, b, t] = tf::perspective_bounds(90.0, 2.0, 1.0);
    assert!((t - 1.0).abs() < 1e-6 && (b + 1.0).abs() < 1e-6, "top {t}");
    assert!(
        (r - 2.0).abs() < 1e-6 && (l + 2.0).abs() < 1e-6,
        "right {r}"
    );
}

#[test]
fn frustum_maps_its_corners_to_the_canonical_cube() {
    let (l, r, b, t, n, f) = (-2.0f32, 3.0, -0.5, 1.5, 1.0, 10.0);
    let p = tf::frustum(l, r, b, t, n, f).matrix;
    for (x, y, z, expect) in [
        (l, b, -n, Vec3::new(-1.0, -1.0, -1.0)),
        (r, t, -n, Vec3::new(1.0, 1.0, -1.0)),
        (l * f / n, t * f / n, -f, Vec3::new(-1.0, 1.0, 1.0)),
        (r * f / n, b * f / n, -f, Vec3::new(1.0, -1.0, 1.0)),
    ] {
        let c = p * Vec4::new(x, y, z, 1.0);
        assert_vec_eq(c.truncate() / c.w, expect, 1e-5, "corner");
    }
}

#[test]
fn games101_perspective_is_the_gl_one_with_depth_mirrored() {
    let (l, r, b, t, near, far) = (-1.5f32, 1.0, -0.75, 1.25, 0.5, 20.0);
    let z = tf::games101_relation();
    let gl = tf::frustum(l, r, b, t, near, far).matrix;
    let g = tf::perspective_games101(l, r, b, t, -near, -far);
    // The stated relation: M_ortho·M_persp→ortho = −Z·P_GL.
    assert_mat_eq(&g.matrix, &(-(z * gl)), 1e-5, "M_persp = −Z·P");
    let product = g.factors[0].matrix * g.factors[1].matrix;
    assert_mat_eq(&product, &g.matrix, 1e-6, "factors");
    // The squish keeps the near plane and the far plane's z.
    let squish = tf::persp_to_ortho(-near, -far);
    let on_near = squish * Vec4::new(0.3, -0.2, -near, 1.0);
    assert_vec_eq(
        on_near.truncate() / on_near.w,
        Vec3::new(0.3, -0.2, -near),
        1e-6,
        "near kept",
    );
    let on_far = squish * Vec4::new(4.0, 2.0, -far, 1.0);
    let q = on_far.truncate() / on_far.w;
    assert!((q.z + far).abs() < 1e-3, "far z kept: {q}");
    // Hand-computed: x' = n·x/z = (−0.5·4)/(−20) = 0.1.
    assert!((q.x - 0.1).abs() < 1e-6 && (q.y - 0.05).abs() < 1e-6, "{q}");
    // Same point, same NDC x and y, opposite NDC z.
    let mut rng = fastrand::Rng::with_seed(3);
    for _ in 0..100 {
        let p = Vec4::new(
            rng.f32() * 4.0 - 2.0,
            rng.f32() * 4.0 - 2.0,
            -near - rng.f32() * 15.0,
            1.0,
        );
        let (a, c) = (gl * p, g.matrix * p);
        let (na, nc) = (a.truncate() / a.w, c.truncate() / c.w);
        assert_vec_eq(Vec3::new(na.x, na.y, -na.z), nc, 1e-4, "NDC relation");
    }
    // Orthographic: M_ortho = Z·Ortho_GL.
    let o = tf::ortho_games101(l, r, b, t, -far, -near).matrix;
    assert_mat_eq(
        &o,
        &(z * tf::ortho(l, r, b, t, near, far).matrix),
        1e-6,
        "M_ortho = Z·Ortho",
    );
}

#[test]
fn viewport_by_hand() {
    let v = tf::viewport(640.0, 480.0);
    assert_vec_eq(
        v.transform_point3(Vec3::new(-1.0, -1.0, -1.0)),
        Vec3::ZERO,
        0.0,
        "corner",
    );
    assert_vec_eq(
        v.transform_point3(Vec3::new(1.0, 1.0, 1.0)),
        Vec3::new(640.0, 480.0, 1.0),
        0.0,
        "corner",
    );
    assert_vec_eq(
        v.transform_point3(Vec3::new(0.5, 0.0, 0.0)),
        Vec3::new(480.0, 240.0, 0.5),
        0.0,
        "inside",
    );
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

#[test]
fn window_depth_against_eye_distance_is_the_projection_s_and_inverts() {
    use pipeline::camera::Projection;
    // By hand, near 1 and far 3: z_ndc = (3+1)/(3−1) − 2·3·1/((3−1)·d) = 2 − 3/d, so d = 1 gives
    // z_w = 0, d = 1.5 gives z_ndc = 0 and z_w = ½, d = 3 gives z_w = 1.
    let p = Projection::Perspective {
        fovy_deg: 60.0,
        aspect: Some(1.0),
        near: 1.0,
        far: 3.0,
    };
    for (d, z_w) in [(1.0, 0.0), (1.5, 0.5), (3.0, 1.0), (2.0, 0.75)] {
        assert!((p.window_depth(d) - z_w).abs() < 1e-6, "d = {d}");
        assert!((p.eye_distance(z_w) - d).abs() < 1e-5, "z_w = {z_w}");
    }
    // The same as the projection matrix and the viewport applied to (0, 0, −d).
    let m = p.matrix(1.0).matrix;
    for d in [1.2f32, 2.0, 2.9] {
        let c = m * glam::Vec4::new(0.0, 0.0, -d, 1.0);
        assert!((p.window_depth(d) - (c.z / c.w + 1.0) / 2.0).abs() < 1e-6);
    }
    // Parallel projection: linear in d.
    let o = Projection::Ortho {
        left: -1.0,
        right: 1.0,
        bottom: -1.0,
        top: 1.0,
        near: 1.0,
        far: 5.0,
    };
    assert!((o.window_depth(2.0) - 0.25).abs() < 1e-6);
    assert!((o.eye_distance(0.25) - 2.0).abs() < 1e-6);
}
