//! The viewing and projection matrices against references that do not come from the code under
//! test: LookAt against gluLookAt and glam, glOrtho, glFrustum and gluPerspective as their
//! reference pages write them, GAMES101's perspective, the viewport by hand, and window depth
//! against eye distance.

use glam::{Mat4, Vec3, Vec4};
use pipeline::transform::{self as tf, rows};

use crate::transform::{assert_mat_eq, assert_vec_eq, random_vec};

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
