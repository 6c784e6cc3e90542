//! Functions the pipeline calls: the student's `inside` decides coverage sample by sample. An
//! inside test written as pipelens' rule (edge functions, top-left ties) gives pipelens'
//! samples exactly; a test that takes every tie covers a shared edge twice; one that answers
//! `false` covers nothing; a mistake in it is a message at its line.

use glam::Vec2;
use pipeline::raster::{NONE, Samples};
use pipeline::shader::compile_inside;

use crate::support::{cover_counts, pixel_scene, render};

/// The edge functions with the top-left rule, as a student writes them in GLSL: `E_ab(p) =
/// (b − a) × (p − a)`, a tie (`E = 0`) inside only on a top edge (horizontal, going left) or a
/// left edge (going down), the corners counter-clockwise.
const TOP_LEFT: &str = "
float edge(vec2 a, vec2 b, vec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}
bool owns(vec2 a, vec2 b, vec2 p) {
    float e = edge(a, b, p);
    vec2 d = b - a;
    bool top_left = (d.y == 0.0 && d.x < 0.0) || d.y < 0.0;
    return e > 0.0 || (e == 0.0 && top_left);
}
bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {
    return owns(a, b, p) && owns(b, c, p) && owns(c, a, p);
}
";

/// Every tie counted inside: GAMES101's `insideTriangle` as often first written.
const EVERY_TIE: &str = "
bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {
    float e0 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    float e1 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);
    float e2 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);
    return e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0;
}
";

/// Two triangles sharing the diagonal of a square whose corners lie on pixel centres, so
/// samples fall exactly on the shared edge and on the square's sides.
fn square() -> [[Vec2; 3]; 2] {
    let (a, b, c, d) = (
        Vec2::new(2.5, 2.5),
        Vec2::new(13.5, 2.5),
        Vec2::new(13.5, 13.5),
        Vec2::new(2.5, 13.5),
    );
    [[a, b, c], [a, c, d]]
}

#[test]
fn an_inside_test_with_the_top_left_rule_covers_pipelens_samples_exactly() {
    for samples in [Samples::X1, Samples::X4] {
        let (mut scene, mut settings) = pixel_scene(16, 16, &square());
        settings.samples = samples;
        let own = render(&scene, &settings);
        let test = compile_inside(TOP_LEFT).expect("the top-left test compiles");
        scene.set_inside(&test);
        let student = render(&scene, &settings);
        assert_eq!(
            student.samples.triangle, own.samples.triangle,
            "{samples:?}"
        );
        assert_eq!(cover_counts(&student), cover_counts(&own), "{samples:?}");
        // The shared diagonal and the square's sides: ties, each sample once.
        let (sum, distinct) = cover_counts(&student);
        assert_eq!(sum, distinct);
    }
}

#[test]
fn a_test_that_takes_every_tie_covers_the_shared_edge_twice() {
    let (mut scene, settings) = pixel_scene(16, 16, &square());
    let own = render(&scene, &settings);
    scene.set_inside(&compile_inside(EVERY_TIE).expect("compiles"));
    let student = render(&scene, &settings);
    let (sum, distinct) = cover_counts(&student);
    // The 12 centres on the diagonal (2.5, 2.5) … (13.5, 13.5) are covered by both halves.
    assert_eq!(sum - distinct, 12);
    // pipelens' rule covers each centre once, 11 × 11 of the closed square's 12 × 12: of two
    // opposite sides it keeps one (the top and the left, y up).
    let (own_sum, own_distinct) = cover_counts(&own);
    assert_eq!(own_sum, own_distinct);
    assert_eq!(own_distinct, 121);
    // Taking every tie adds the other two sides' 12 + 11 centres.
    assert_eq!(distinct, own_distinct + 12 + 11);
}

#[test]
fn a_test_that_answers_false_covers_nothing_and_a_mistake_is_a_message_at_its_line() {
    let (mut scene, settings) = pixel_scene(16, 16, &square());
    let never = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {\n    return false;\n}\n";
    scene.set_inside(&compile_inside(never).expect("compiles"));
    let frame = render(&scene, &settings);
    assert!(frame.samples.triangle.iter().all(|&t| t == NONE));
    assert!(frame.primitives.iter().all(|p| p.counts.covered == 0));

    let wrong_type = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {\n    return 1.0;\n}\n";
    let errors = compile_inside(wrong_type).expect_err("a float is not a bool");
    assert!(errors.iter().any(|e| e.line == 2), "{errors:?}");

    let misnamed = "bool in_triangle(vec2 p, vec2 a, vec2 b, vec2 c) {\n    return true;\n}\n";
    let errors = compile_inside(misnamed).expect_err("the rasterizer calls `inside`");
    assert!(
        errors.iter().any(|e| e
            .message
            .contains("bool inside(vec2 p, vec2 a, vec2 b, vec2 c)")),
        "{errors:?}"
    );
}

#[test]
fn an_endless_inside_test_is_a_render_error_not_a_hang() {
    let (mut scene, settings) = pixel_scene(16, 16, &square());
    let endless = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {\n    float x = 0.0;\n    while (x >= 0.0) { x += 1.0; }\n    return true;\n}\n";
    scene.set_inside(&compile_inside(endless).expect("compiles"));
    let err = pipeline::render(&scene, &settings).expect_err("the loop budget stops it");
    let text = err.to_string();
    assert!(text.contains("inside test of test"), "{text}");
    assert!(text.contains("line 3"), "{text}");
}

/// Two overlapping triangles, the nearer drawn first: a depth test decides which one the
/// overlap shows.
fn overlapping() -> (pipeline::scene::Scene, pipeline::settings::RenderSettings) {
    let near = [
        Vec2::new(2.0, 2.0),
        Vec2::new(14.0, 3.0),
        Vec2::new(6.0, 14.0),
    ];
    let far = [
        Vec2::new(3.0, 12.0),
        Vec2::new(4.0, 1.0),
        Vec2::new(15.0, 9.0),
    ];
    let (mut scene, mut settings) = pixel_scene(16, 16, &[near, far]);
    let mesh = std::sync::Arc::make_mut(&mut scene.objects[0].mesh);
    for (k, p) in mesh.positions.iter_mut().enumerate() {
        // The eye is at z = 1 looking down −z: the first triangle is nearer.
        p.z = if k < 3 { 0.5 } else { -0.5 };
    }
    settings.samples = Samples::X4;
    (scene, settings)
}

#[test]
fn a_depth_test_written_as_less_gives_pipelens_z_buffer_and_true_draws_over() {
    use pipeline::raster::DepthTest;
    use pipeline::shader::{HookKind, compile_hook};
    let (mut scene, mut settings) = overlapping();
    settings.depth_test = DepthTest::Less;
    let less = render(&scene, &settings);
    settings.depth_test = DepthTest::Always;
    let always = render(&scene, &settings);
    assert_ne!(
        less.samples.triangle, always.samples.triangle,
        "they overlap"
    );

    settings.depth_test = DepthTest::Less;
    let mine = "bool depth_test(float z, float stored) {\n    return z < stored;\n}\n";
    scene.set_depth_test(&compile_hook(HookKind::DepthTest, mine).expect("compiles"));
    let student = render(&scene, &settings);
    assert_eq!(student.samples.triangle, less.samples.triangle);
    assert_eq!(student.samples.depth, less.samples.depth);

    let painter = "bool depth_test(float z, float stored) {\n    return true;\n}\n";
    scene.set_depth_test(&compile_hook(HookKind::DepthTest, painter).expect("compiles"));
    let student = render(&scene, &settings);
    assert_eq!(student.samples.triangle, always.samples.triangle);

    let wrong = "bool depth_test(float z) {\n    return true;\n}\n";
    let errors = compile_hook(HookKind::DepthTest, wrong).expect_err("one argument short");
    assert!(
        errors
            .iter()
            .any(|e| e.message.contains("bool depth_test(float z, float stored)")),
        "{errors:?}"
    );
}

/// De Casteljau written in GLSL: three levels of `mix`.
const DE_CASTELJAU: &str = "
vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t) {
    vec2 a = mix(p0, p1, t);
    vec2 b = mix(p1, p2, t);
    vec2 c = mix(p2, p3, t);
    vec2 d = mix(a, b, t);
    vec2 e = mix(b, c, t);
    return mix(d, e, t);
}
";

#[test]
fn de_casteljau_in_glsl_draws_pipelens_curve_and_a_straight_line_does_not() {
    use pipeline::mesh::BuiltinMesh;
    use pipeline::shader::{HookKind, compile_hook};
    let points = [
        Vec2::new(-1.2, -0.7),
        Vec2::new(-0.7, 0.8),
        Vec2::new(0.6, 0.85),
        Vec2::new(1.2, -0.6),
    ];
    let hook = compile_hook(HookKind::Curve, DE_CASTELJAU).expect("compiles");
    let d = hook.curve_difference(points, 1e-5).expect("runs");
    assert!(d.passed(), "{d:?}");
    assert_eq!(d.total, 161);
    // By hand: b(½) = (P0 + 3·P1 + 3·P2 + P3)/8.
    let half = hook.curve_points(points, &[0.5]).expect("runs")[0];
    let want = (points[0] + 3.0 * points[1] + 3.0 * points[2] + points[3]) / 8.0;
    assert!(half.distance(want) < 1e-6, "{half} != {want}");

    let line = "vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t) {\n    return mix(p0, p3, t);\n}\n";
    let line = compile_hook(HookKind::Curve, line).expect("compiles");
    let d = line.curve_difference(points, 1e-5).expect("runs");
    assert!(!d.passed());
    // The ends agree (b(0) = P0, b(1) = P3); the first point off is the second.
    assert_eq!(d.matching, 2);
    assert_eq!(
        d.first.map(|f| f.0),
        Some(pipeline::shader::At::T(1.0 / 160.0))
    );

    // The frame: the curve object drawn with the student's points, pixel for pixel.
    let curve = BuiltinMesh::Bezier {
        points,
        t: 0.6,
        levels: 3,
    };
    let mut object = pipeline::scene::Object::new("curve", curve.build());
    object.builtin = Some(curve);
    object.color = pipeline::scene::ColorSource::Vertex;
    let (mut scene, settings) = pixel_scene(64, 48, &[]);
    scene.objects = vec![object];
    scene.projection = pipeline::camera::Projection::Ortho {
        left: -1.5,
        right: 1.5,
        bottom: -1.0,
        top: 1.0,
        near: 0.0,
        far: 2.0,
    };
    let own = render(&scene, &settings);
    scene.objects[0].code.hooks.set(line);
    let wrong = render(&scene, &settings);
    assert!(own.difference(&wrong, 1.0).is_some_and(|d| !d.passed()));
    scene.objects[0].code.hooks.set(hook);
    let mine = render(&scene, &settings);
    assert!(own.difference(&mine, 1.0).is_some_and(|d| d.passed()));
}

/// A pipeline function that stops at run time (here an endless de Casteljau) is the frame's
/// error as data: which function, on which object, the complaint at its line.
#[test]
fn a_pipeline_function_that_stops_is_named_as_the_frame_s_error() {
    use pipeline::mesh::BuiltinMesh;
    use pipeline::shader::{Complaint, HookKind, compile_hook};
    let endless = "vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t) {\n    float x = 0.0;\n    while (x >= 0.0) {\n        x += 1.0;\n    }\n    return p0;\n}\n";
    let curve = BuiltinMesh::Bezier {
        points: [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y],
        t: 1.0,
        levels: 0,
    };
    let mut object = pipeline::scene::Object::new("curve", curve.build());
    object.builtin = Some(curve);
    object
        .code
        .hooks
        .set(compile_hook(HookKind::Curve, endless).expect("compiles"));
    let (mut scene, settings) = pixel_scene(16, 16, &[]);
    scene.objects = vec![object];
    let e = pipeline::render(&scene, &settings).expect_err("stops");
    let pipeline::RenderError::Code {
        part,
        object,
        error,
        ..
    } = &e
    else {
        panic!("{e}");
    };
    assert_eq!(*part, pipeline::CodePart::Function(HookKind::Curve));
    assert_eq!(object, "curve");
    assert_eq!(error.complaint, Complaint::EndlessLoop { budget: 65_536 });
    assert_eq!(error.line, 3, "{error:?}");
    assert!(e.to_string().contains("de_casteljau() of curve"), "{e}");
}

/// The frame's loop budget (`max_steps`) holds for the pipeline functions too: an inside test
/// whose loop runs 70 000 times per call stops at the default 65 536 and runs when the lesson
/// allows more, giving the triangle's own coverage.
#[test]
fn a_pipeline_functions_loop_runs_as_long_as_max_steps_allows() {
    use pipeline::shader::{Complaint, HookKind, compile_hook};
    // 70 000 halvings of a counter that ends where it began: the edge function's sign, slowly.
    let slow = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {\n    float k = 0.0;\n    for (int i = 0; i < 70000; i++) {\n        k += 1.0;\n    }\n    float e0 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);\n    float e1 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);\n    float e2 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);\n    bool pos = e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0;\n    bool neg = e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0;\n    return k == 70000.0 && (pos || neg);\n}\n";
    let triangle = [
        Vec2::new(1.0, 1.0),
        Vec2::new(7.0, 2.0),
        Vec2::new(3.0, 7.0),
    ];
    let (mut scene, settings) = pixel_scene(8, 8, &[triangle]);
    let own = render(&scene, &settings);
    scene.objects[0]
        .code
        .hooks
        .set(compile_hook(HookKind::Inside, slow).expect("compiles"));
    let e = pipeline::render(&scene, &settings).expect_err("past the default budget");
    let pipeline::RenderError::Code { error, .. } = &e else {
        panic!("{e}");
    };
    assert_eq!(error.complaint, Complaint::EndlessLoop { budget: 65_536 });
    let allowed = pipeline::settings::RenderSettings {
        max_steps: 100_000,
        ..settings
    };
    let mine = render(&scene, &allowed);
    assert!(
        mine.pixels.coverage.iter().any(|&c| c > 0),
        "the triangle is drawn"
    );
    assert_eq!(own.pixels.coverage, mine.pixels.coverage);
}

/// Angel's shadow matrix written in GLSL (T(l)·P·T(−l), P the identity with last row
/// (0, −1/y_l, 0, 0)) is pipelens' own, entry by entry.
const SHADOW: &str = "mat4 shadow_matrix(vec3 light) {
    mat4 to_light = mat4(1.0);
    to_light[3] = vec4(-light, 1.0);
    mat4 project = mat4(1.0);
    project[1][3] = -1.0 / light.y;
    project[3][3] = 0.0;
    mat4 back = mat4(1.0);
    back[3] = vec4(light, 1.0);
    return back * project * to_light;
}";

#[test]
fn a_shadow_matrix_in_glsl_is_angels() {
    use glam::Vec3;
    use pipeline::shader::{HookKind, compile_hook};
    let hook = compile_hook(HookKind::ShadowMatrix, SHADOW).expect("compiles");
    for light in [Vec3::new(1.0, 5.0, 1.0), Vec3::new(-3.0, 2.5, 0.5)] {
        let mine = hook.shadow_matrix(light).expect("runs");
        let theirs = pipeline::transform::planar_shadow(light).matrix;
        assert!(
            mine.abs_diff_eq(theirs, 1e-6),
            "{light}: {mine} against {theirs}"
        );
    }
}

/// A Bézier patch by de Casteljau in u, then in v, written in GLSL (lesson 19's lab).
const PATCH: &str = "vec3 curve(vec3 a, vec3 b, vec3 c, vec3 d, float t) {
    vec3 ab = mix(a, b, t);
    vec3 bc = mix(b, c, t);
    vec3 cd = mix(c, d, t);
    return mix(mix(ab, bc, t), mix(bc, cd, t), t);
}
vec3 bezier_patch(vec3 p[16], float u, float v) {
    vec3 q[4];
    for (int i = 0; i < 4; i++) {
        q[i] = curve(p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3], u);
    }
    return curve(q[0], q[1], q[2], q[3], v);
}";

/// The student's patch is pipelens' `b(u, v)` at every grid vertex and at points worked out by
/// hand; a patch with u and v swapped is not, and its frame differs; a function that divides by
/// zero draws (NaN vertices are dropped) and is reported, not a panic.
#[test]
fn a_bezier_patch_in_glsl_is_pipelens_surface() {
    use glam::Vec3;
    use pipeline::mesh::BuiltinMesh;
    use pipeline::mesh::patch::control_points;
    use pipeline::shader::{At, HookKind, compile_hook};
    let heights = [
        [0.0, 0.3, 0.3, 0.0],
        [0.2, 1.2, 0.8, 0.1],
        [0.1, 0.9, 1.1, 0.2],
        [0.0, 0.2, 0.3, 0.0],
    ];
    let rows = control_points(&heights);
    let hook = compile_hook(HookKind::Patch, PATCH).expect("compiles");
    let d = hook.patch_difference(&rows, 1e-5).expect("runs");
    assert!(d.passed() && d.surface, "{d:?}");
    assert_eq!(d.total, 25 * 25);
    // By hand. b(1/24, 0) is on row 0 (heights 0, 0.3, 0.3, 0, x evenly spaced from −1.2 to
    // 1.2): x = −1.2 + 2.4/24 = −1.1, y = 0.9·t·(1 − t) = 0.9·(1/24)·(23/24).
    // b(½, ½): the weights B³(½) = (1, 3, 3, 1)/8 in each direction: rows give 0.225, 0.7875,
    // 0.7875, 0.1875, and those give 0.6421875; x = z = 0 by symmetry.
    let got = hook
        .patch_points(&rows, &[Vec2::new(1.0 / 24.0, 0.0), Vec2::splat(0.5)])
        .expect("runs");
    let want = [
        Vec3::new(-1.1, 0.9 * (1.0 / 24.0) * (23.0 / 24.0), -1.2),
        Vec3::new(0.0, 0.642_187_5, 0.0),
    ];
    for (g, w) in got.iter().zip(want) {
        assert!(g.distance(w) < 1e-6, "{g} != {w}");
    }

    let swapped = PATCH.replace(
        "u);\n    }\n    return curve(q[0], q[1], q[2], q[3], v);",
        "v);\n    }\n    return curve(q[0], q[1], q[2], q[3], u);",
    );
    assert_ne!(swapped, PATCH);
    let swapped = compile_hook(HookKind::Patch, &swapped).expect("compiles");
    let d = swapped.patch_difference(&rows, 1e-5).expect("runs");
    assert!(!d.passed());
    // The first row (v = 0) of the grid: b(1/24, 0) is the first point off (b(0, 0) = P00
    // either way).
    assert_eq!(
        d.first.map(|f| f.0),
        Some(At::Uv(Vec2::new(1.0 / 24.0, 0.0)))
    );

    // The frame: the patch drawn with the student's points.
    let patch = BuiltinMesh::BezierPatch {
        heights,
        u: 0.5,
        v: 0.5,
        levels: 0,
    };
    let mut object = pipeline::scene::Object::new("patch", patch.build());
    object.builtin = Some(patch);
    let (mut scene, mut settings) = pixel_scene(64, 48, &[]);
    settings.depth_test = pipeline::raster::DepthTest::Less;
    settings.shading = pipeline::lighting::Frequency::Phong;
    scene.lights = vec![pipeline::light::Light::Directional {
        direction: Vec3::new(-0.3, -1.0, -0.5),
        intensity: Vec3::ONE,
    }];
    scene.camera.eye = Vec3::new(1.8, 4.4, 3.3);
    scene.camera.at = Vec3::ZERO;
    scene.projection = pipeline::camera::Projection::Ortho {
        left: -2.0,
        right: 2.0,
        bottom: -1.5,
        top: 1.5,
        near: 0.1,
        far: 20.0,
    };
    scene.objects = vec![object];
    let own = render(&scene, &settings);
    scene.objects[0].code.hooks.set(swapped);
    let wrong = render(&scene, &settings);
    assert!(own.difference(&wrong, 1.0).is_some_and(|d| !d.passed()));
    scene.objects[0].code.hooks.set(hook);
    let mine = render(&scene, &settings);
    assert!(own.difference(&mine, 1.0).is_some_and(|d| d.passed()));
    let nan = "vec3 bezier_patch(vec3 p[16], float u, float v) {\n    return p[0] / (u - u);\n}\n";
    scene.objects[0]
        .code
        .hooks
        .set(compile_hook(HookKind::Patch, nan).expect("compiles"));
    let drawn = pipeline::render(&scene, &settings).expect("NaN points draw nothing, no panic");
    assert!(own.difference(&drawn, 1.0).is_some_and(|d| !d.passed()));
}

/// A local initialised with a constant vector or matrix holds it from the function's start (the
/// machine had copied the initial value before the body computed it: `mat4 m = mat4(1.0)` was
/// all zeros), in a loop too.
#[test]
fn locals_start_with_their_constant_values() {
    use glam::{Mat4, Vec3, Vec4};
    use pipeline::shader::{HookKind, compile_hook};
    let source = "mat4 shadow_matrix(vec3 light) {
    mat4 m = mat4(1.0);
    vec4 third = vec4(2.0);
    float sum = 0.0;
    for (int i = 0; i < 3; i++) {
        vec2 v = vec2(1.0, 3.0);
        v.x += 1.0;
        sum += v.x;
    }
    m[2] = third;
    m[3][0] = sum;
    return m;
}";
    let hook = compile_hook(HookKind::ShadowMatrix, source).expect("compiles");
    let m = hook.shadow_matrix(Vec3::ONE).expect("runs");
    let expected = Mat4::from_cols(
        Vec4::X,
        Vec4::Y,
        Vec4::splat(2.0),
        Vec4::new(6.0, 0.0, 0.0, 1.0),
    );
    assert_eq!(m, expected);
}

/// Assigning through a swizzle of an indexed value — a matrix column (`m[1].w`, `t[3].xyz`), an
/// array element (`r[0].xy`), compound (`+=`) — is valid GLSL that naga's front end refuses;
/// written so, the shadow matrix is still Angel's, entry by entry (by glam's planar shadow).
#[test]
fn stores_through_a_swizzle_of_an_indexed_value_compile_and_run() {
    use glam::Vec3;
    use pipeline::shader::{HookKind, compile_hook};
    let source = "mat4 shadow_matrix(vec3 light) {
    mat4 to_light = mat4(1.0);
    to_light[3].xyz = -light;      // column 3: the translation
    mat4 project = mat4(1.0);
    project[1].w = -1.0 / light.y; // row 4, column 2
    project[3].w = 0.0;
    mat4 back = mat4(1.0);
    vec3 t[2];
    t[0].xy = light.xy;
    t[0].z = 0.0;
    t[0].z += light.z;
    back[3].rgb = t[0];
    return back * project * to_light;
}";
    let hook = compile_hook(HookKind::ShadowMatrix, source).unwrap_or_else(|e| panic!("{e:?}"));
    for light in [Vec3::new(1.0, 5.0, 1.0), Vec3::new(-3.0, 2.5, 0.5)] {
        let mine = hook.shadow_matrix(light).expect("runs");
        let theirs = pipeline::transform::planar_shadow(light).matrix;
        assert!(
            mine.abs_diff_eq(theirs, 1e-6),
            "{light}: {mine} against {theirs}"
        );
    }
}
