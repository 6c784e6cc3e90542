//! The shader machine against values computed by hand and by glam: the student's GLSL adapted,
//! compiled by naga, run over batches of lanes with divergent control flow (its mistakes
//! reported at their lines: `shader_errors.rs`).

use glam::{Mat3, Mat4, Vec3};
use pipeline::shader::{self, Bindings, LANES, Program, Stage, Uniforms};
use pipeline::texture::{Sampler, Texture};

/// Compiles, or fails the test with every message.
pub(crate) fn compile(stage: Stage, src: &str) -> Program {
    match shader::compile(stage, src) {
        Ok(p) => p,
        Err(errors) => panic!(
            "{}",
            errors
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        ),
    }
}

/// The messages of a shader that must not compile.
pub(crate) fn errors(stage: Stage, src: &str) -> Vec<shader::ShaderError> {
    match shader::compile(stage, src) {
        Ok(_) => panic!("compiled, but should not:\n{src}"),
        Err(e) => e,
    }
}

/// Each input's rows for `lanes` invocations: `values[input][lane]` are its components.
fn pack(values: &[Vec<Vec<f32>>]) -> Vec<Vec<u32>> {
    values
        .iter()
        .map(|lanes| {
            let comps = lanes[0].len();
            let mut rows = vec![0u32; comps * LANES];
            for (l, v) in lanes.iter().enumerate() {
                for (c, x) in v.iter().enumerate() {
                    rows[c * LANES + l] = x.to_bits();
                }
            }
            rows
        })
        .collect()
}

/// Runs `program` over the lanes of `values` (all live); returns each lane's result components
/// as floats and the discarded lanes.
pub(crate) fn run(
    program: &Program,
    uniforms: &Uniforms,
    values: &[Vec<Vec<f32>>],
    textures: &[Option<&Texture>],
) -> Result<(Vec<Vec<f32>>, u64), shader::ShaderError> {
    let n = values.first().map_or(4, Vec::len);
    let rows = pack(values);
    let inputs: Vec<&[u32]> = rows.iter().map(Vec::as_slice).collect();
    let mut m = program.machine();
    program.set_uniforms(&mut m, uniforms);
    let bound: Vec<_> = textures
        .iter()
        .map(|t| t.map(|t| pipeline::shader::Bound::Image(t, Sampler::default())))
        .collect();
    let killed = m
        .run(&inputs, n, u64::MAX, &Bindings { textures: &bound })
        .map_err(|e| program.run_error(&e))?;
    let comps = m.result().len() / LANES;
    let out = (0..n)
        .map(|l| {
            (0..comps)
                .map(|c| f32::from_bits(m.result()[c * LANES + l]))
                .collect()
        })
        .collect();
    Ok((out, killed))
}

/// The trace of lane 1 of a one-input program whose input is `x` there (0 in lanes 0, 2, 3),
/// as `line: text` lines.
pub(crate) fn traced_lane_1(program: &Program, x: f32) -> Vec<String> {
    let rows: Vec<Vec<u32>> = vec![
        (0..LANES)
            .map(|l| if l == 1 { x.to_bits() } else { 0 })
            .collect(),
    ];
    let inputs: Vec<&[u32]> = rows.iter().map(Vec::as_slice).collect();
    let mut m = program.machine();
    m.trace_lane(Some(1));
    m.run(&inputs, 4, u64::MAX, &Bindings { textures: &[] })
        .expect("runs");
    program
        .describe(&m.take_trace())
        .iter()
        .map(|t| format!("{}: {}", t.line, t.text))
        .collect()
}

fn close(a: &[f32], b: &[f32]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= 1e-5 * (1.0 + y.abs()))
}

#[test]
fn a_fragment_shader_normalizes_its_input_in_every_lane() {
    let p = compile(
        Stage::Fragment,
        "#version 330 core\nin vec3 n;\nout vec4 color;\nvoid main() {\n  color = vec4(normalize(n), 1.0);\n}\n",
    );
    let lanes = vec![
        vec![3.0, 0.0, 4.0],
        vec![0.0, 5.0, 0.0],
        vec![1.0, 1.0, 1.0],
        vec![0.0, 0.0, -2.0],
    ];
    let (out, killed) = run(&p, &Uniforms::default(), &[lanes], &[]).expect("runs");
    let s = 1.0 / 3f32.sqrt();
    let want = [
        [0.6, 0.0, 0.8, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [s, s, s, 1.0],
        [0.0, 0.0, -1.0, 1.0],
    ];
    for (o, w) in out.iter().zip(want) {
        assert!(close(o, &w), "{o:?} != {w:?}");
    }
    assert_eq!(killed, 0);
}

#[test]
fn uniforms_are_set_by_name_as_the_course_names_them() {
    let src = "#version 330 core\nuniform mat4 model; uniform vec3 eye;\nuniform mat3 normal_matrix;\nin vec3 n;\nout vec4 color;\n\
               void main() { vec4 p = model * vec4(eye, 1.0); color = vec4(p.xyz, (normal_matrix * n).x); }\n";
    let p = compile(Stage::Fragment, src);
    let model = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
        * Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    let u = Uniforms {
        model,
        eye: Vec3::ONE,
        ..Uniforms::default()
    };
    let (out, _) = run(&p, &u, &[vec![vec![1.0, 0.0, 0.0]; 4]], &[]).expect("runs");
    // M·(1, 1, 1, 1) = (2 + 1, 1 + 2, 1 + 3); (M⁻¹)ᵀ·(1, 0, 0) = (1/2, 0, 0).
    assert!(close(&out[0], &[3.0, 3.0, 4.0, 0.5]), "{:?}", out[0]);
    let nm = Mat3::from_mat4(model).inverse().transpose() * Vec3::X;
    assert!((out[0][3] - nm.x).abs() < 1e-6);
}

#[test]
fn lanes_diverge_at_an_if_and_meet_again() {
    let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n  vec3 c;\n  if (x < 0.5) {\n    c = vec3(1.0, 0.0, 0.0);\n  } else {\n    c = vec3(0.0, 1.0, 0.0);\n  }\n  color = vec4(c, x);\n}\n";
    let p = compile(Stage::Fragment, src);
    let xs: Vec<Vec<f32>> = (0..8).map(|i| vec![i as f32 / 8.0]).collect();
    let (out, _) = run(&p, &Uniforms::default(), &[xs], &[]).expect("runs");
    for (i, o) in out.iter().enumerate() {
        let x = i as f32 / 8.0;
        let want = if x < 0.5 {
            [1.0, 0.0, 0.0, x]
        } else {
            [0.0, 1.0, 0.0, x]
        };
        assert!(close(o, &want), "lane {i}: {o:?}");
    }
}

#[test]
fn each_lane_runs_its_own_number_of_iterations_with_break_and_continue() {
    // s = Σ even i < min(n, 8): lanes n = 0..12 give 0, 0, 0, 2, 2, 6, 6, 12, 12, 12, …
    let src = "#version 330 core\nin float n;\nout vec4 color;\nvoid main() {\n  float s = 0.0;\n  for (int i = 0; i < int(n); i++) {\n    if (i == 8) break;\n    if (i % 2 == 1) continue;\n    s += float(i);\n  }\n  color = vec4(s);\n}\n";
    let p = compile(Stage::Fragment, src);
    let ns: Vec<Vec<f32>> = (0..12).map(|i| vec![i as f32]).collect();
    let (out, _) = run(&p, &Uniforms::default(), &[ns], &[]).expect("runs");
    for (n, o) in out.iter().enumerate() {
        let want: i32 = (0..n.min(8) as i32).filter(|i| i % 2 == 0).sum();
        assert_eq!(o[0], want as f32, "n = {n}");
    }
}

#[test]
fn discard_throws_away_the_lanes_that_reach_it() {
    let src = "#version 330 core\nin vec2 uv;\nout vec4 color;\nvoid main() {\n  if (mod(floor(uv.x * 4.0) + floor(uv.y * 4.0), 2.0) < 1.0) discard;\n  color = vec4(1.0);\n}\n";
    let p = compile(Stage::Fragment, src);
    let uvs: Vec<Vec<f32>> = vec![
        vec![0.1, 0.1],
        vec![0.3, 0.1],
        vec![0.1, 0.3],
        vec![0.3, 0.3],
    ];
    let (_, killed) = run(&p, &Uniforms::default(), &[uvs], &[]).expect("runs");
    // Squares (0,0) and (1,1) are even: lanes 0 and 3.
    assert_eq!(killed, 0b1001);
}

#[test]
fn functions_are_called_and_return_per_lane() {
    let src = "#version 330 core\nin float x;\nout vec4 color;\nfloat f(float a) {\n  if (a > 2.0) return a * a;\n  return -a;\n}\nvoid main() { color = vec4(f(x), f(x + 1.0), 0.0, 1.0); }\n";
    let p = compile(Stage::Fragment, src);
    let (out, _) = run(
        &p,
        &Uniforms::default(),
        &[vec![vec![1.0], vec![2.5], vec![3.0], vec![0.0]]],
        &[],
    )
    .expect("runs");
    let f = |a: f32| if a > 2.0 { a * a } else { -a };
    for (o, x) in out.iter().zip([1.0f32, 2.5, 3.0, 0.0]) {
        assert_eq!((o[0], o[1]), (f(x), f(x + 1.0)));
    }
}

#[test]
fn matrices_agree_with_glam() {
    let src = "#version 330 core\nuniform mat4 model; uniform mat4 view;\nin vec4 v;\nout vec4 color;\nvoid main() {\n  mat4 mv = view * model;\n  mat3 r = mat3(model);\n  float d = determinant(r);\n  vec3 t = (inverse(r) * transpose(r) * v.xyz);\n  color = mv * v + vec4(t, d);\n}\n";
    let p = compile(Stage::Fragment, src);
    let model = Mat4::from_rotation_y(0.7)
        * Mat4::from_scale(Vec3::new(1.0, 2.0, 3.0))
        * Mat4::from_translation(Vec3::X);
    let view = Mat4::from_rotation_x(-0.4) * Mat4::from_translation(Vec3::new(-1.0, -2.0, -5.0));
    let v = glam::Vec4::new(0.3, -0.2, 0.9, 1.0);
    let (out, _) = run(
        &p,
        &Uniforms {
            model,
            view,
            ..Uniforms::default()
        },
        &[vec![v.to_array().to_vec(); 4]],
        &[],
    )
    .expect("runs");
    let r = Mat3::from_mat4(model);
    let want =
        view * model * v + (r.inverse() * r.transpose() * v.truncate()).extend(r.determinant());
    assert!(
        out[0]
            .iter()
            .zip(want.to_array())
            .all(|(a, b)| (a - b).abs() < 1e-4),
        "{:?} != {want:?}",
        out[0]
    );
}

#[test]
fn an_outer_product_is_a_column_times_a_row_as_glam_builds_it() {
    // outerProduct(c, r) has columns c·r_j: a 3×2 product, read through a mat3×vec product.
    let src = "#version 330 core\nin vec3 c;\nout vec4 color;\nvoid main() {\n  mat3 m = outerProduct(c, vec3(1.0, -2.0, 0.5));\n  color = vec4(m * vec3(0.3, 0.7, -1.1), m[1][2]);\n}\n";
    let p = compile(Stage::Fragment, src);
    let c = Vec3::new(0.4, -1.5, 2.0);
    let (out, _) = run(
        &p,
        &Uniforms::default(),
        &[vec![c.to_array().to_vec(); 4]],
        &[],
    )
    .expect("runs");
    let r = Vec3::new(1.0, -2.0, 0.5);
    let m = Mat3::from_cols(c * r.x, c * r.y, c * r.z);
    let want = (m * Vec3::new(0.3, 0.7, -1.1)).extend(m.y_axis.z);
    assert!(
        out[0]
            .iter()
            .zip(want.to_array())
            .all(|(a, b)| (a - b).abs() < 1e-5),
        "{:?} != {want:?}",
        out[0]
    );
}

#[test]
fn dfdx_and_dfdy_are_differences_within_the_quad() {
    let src = "#version 330 core\nin vec2 p;\nout vec4 color;\nvoid main() { float f = p.x * p.x + 3.0 * p.y; color = vec4(dFdx(f), dFdy(f), fwidth(f), dFdxFine(f)); }\n";
    let p = compile(Stage::Fragment, src);
    // A quad at (x, y) = (2, 5): TL (2,5), TR (3,5), BL (2,6), BR (3,6).
    let quad: Vec<Vec<f32>> = vec![
        vec![2.0, 5.0],
        vec![3.0, 5.0],
        vec![2.0, 6.0],
        vec![3.0, 6.0],
    ];
    let (out, _) = run(&p, &Uniforms::default(), &[quad], &[]).expect("runs");
    // f = x² + 3y: dFdx = 9 − 4 = 5 (coarse, from the top row), dFdy = 3, fwidth 8.
    for o in &out {
        assert_eq!(&o[..3], &[5.0, 3.0, 8.0]);
    }
    // Fine dFdx is the same here: the bottom row's difference is 9 + 18 − (4 + 18) = 5.
    assert_eq!(out[3][3], 5.0);
}

#[test]
fn texture_reads_pipelens_samplers_at_the_quads_level_of_detail() {
    let src = "#version 330 core\nuniform sampler2D tex;\nin vec2 uv;\nout vec4 color;\nvoid main() { color = texture(tex, uv); }\n";
    let p = compile(Stage::Fragment, src);
    let t = Texture::checkerboard(64, 8);
    let sampler = Sampler::default();
    // A quad one texel apart: λ = 0, the lookup the sampler itself gives.
    let d = 1.0 / 64.0;
    let (u0, v0) = (0.3, 0.6);
    let quad: Vec<Vec<f32>> = vec![
        vec![u0, v0],
        vec![u0 + d, v0],
        vec![u0, v0 + d],
        vec![u0 + d, v0 + d],
    ];
    let (out, _) = run(
        &p,
        &Uniforms::default(),
        std::slice::from_ref(&quad),
        &[Some(&t)],
    )
    .expect("runs");
    for (o, uv) in out.iter().zip(&quad) {
        let want = t
            .sample(
                glam::Vec2::new(uv[0], uv[1]),
                glam::Vec2::new(d, 0.0),
                glam::Vec2::new(0.0, d),
                &sampler,
            )
            .color;
        assert!(close(&o[..3], &want.to_array()), "{o:?} != {want:?}");
        assert_eq!(o[3], 1.0);
    }
}

#[test]
fn a_vertex_shader_writes_the_clip_position_and_its_varyings() {
    let src = "#version 330 core\nuniform mat4 mvp;\nuniform mat4 model;\nin vec3 position;\nin vec3 normal;\nout vec3 w_pos;\nflat out vec3 c;\nnoperspective out float f;\nvoid main() {\n  w_pos = (model * vec4(position, 1.0)).xyz;\n  c = normal;\n  f = 2.0;\n  gl_Position = mvp * vec4(position, 1.0);\n}\n";
    let p = compile(Stage::Vertex, src);
    let names: Vec<&str> = p.outputs.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["w_pos", "c", "f", "gl_Position"]);
    let interp: Vec<_> = p.outputs[..3].iter().map(|o| o.interpolate).collect();
    assert_eq!(
        interp,
        [
            shader::Interpolate::Perspective,
            shader::Interpolate::Flat,
            shader::Interpolate::Linear
        ]
    );
    let inputs: Vec<(&str, Option<u32>)> = p
        .inputs
        .iter()
        .map(|i| (i.name.as_str(), i.location))
        .collect();
    assert_eq!(inputs, [("position", Some(0)), ("normal", Some(1))]);
    let model = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0));
    // gluPerspective(fovy = 90°, aspect 1.5, near 0.1, far 10): f = cot(45°) = 1.
    let (n, f) = (0.1f32, 10.0f32);
    let projection = Mat4::from_cols_array(&[
        1.0 / 1.5,
        0.0,
        0.0,
        0.0,
        0.0,
        1.0,
        0.0,
        0.0,
        0.0,
        0.0,
        (f + n) / (n - f),
        -1.0,
        0.0,
        0.0,
        2.0 * f * n / (n - f),
        0.0,
    ]);
    let u = Uniforms {
        model,
        projection,
        ..Uniforms::default()
    };
    let pos = vec![0.5, -0.5, 0.25];
    let (out, _) = run(
        &p,
        &u,
        &[vec![pos.clone(); 4], vec![vec![0.0, 1.0, 0.0]; 4]],
        &[],
    )
    .expect("runs");
    let clip = projection * model * Vec3::from_slice(&pos).extend(1.0);
    let world = (model * Vec3::from_slice(&pos).extend(1.0)).truncate();
    let want: Vec<f32> = world
        .to_array()
        .into_iter()
        .chain([0.0, 1.0, 0.0, 2.0])
        .chain(clip.to_array())
        .collect();
    assert!(close(&out[0], &want), "{:?} != {want:?}", out[0]);
}

#[test]
fn glsl_1_with_attribute_varying_and_gl_fragcolor_runs() {
    let vs = "attribute vec3 position;\nvarying vec3 v;\nuniform mat4 mvp;\nvoid main() { v = position; gl_Position = mvp * vec4(position, 1.0); }\n";
    compile(Stage::Vertex, vs);
    let fs = "varying vec3 v;\nvoid main() {\n  gl_FragColor = vec4(v * 2.0, 1.0);\n}\n";
    let p = compile(Stage::Fragment, fs);
    let (out, _) = run(
        &p,
        &Uniforms::default(),
        &[vec![vec![0.1, 0.2, 0.3]; 4]],
        &[],
    )
    .expect("runs");
    assert!(close(&out[0], &[0.2, 0.4, 0.6, 1.0]));
}

#[test]
fn lights_reach_the_shader_as_records() {
    let src = "#version 330 core\nuniform Light lights[MAX_LIGHTS];\nuniform int light_count;\nout vec4 color;\nvoid main() {\n  vec3 sum = vec3(0.0);\n  for (int i = 0; i < light_count; i++) {\n    if (lights[i].kind == LIGHT_POINT) sum += lights[i].position;\n    else sum += lights[i].intensity;\n  }\n  color = vec4(sum, float(light_count));\n}\n";
    let p = compile(Stage::Fragment, src);
    let lights = vec![
        pipeline::light::Light::Ambient {
            intensity: Vec3::splat(0.25),
        },
        pipeline::light::Light::Point {
            position: Vec3::new(1.0, 2.0, 3.0),
            intensity: Vec3::ONE,
            attenuation: Vec3::X,
        },
    ];
    let (out, _) = run(
        &p,
        &Uniforms {
            lights,
            ..Uniforms::default()
        },
        &[],
        &[],
    )
    .expect("runs");
    assert!(close(&out[0], &[1.25, 2.25, 3.25, 2.0]), "{:?}", out[0]);
}

#[test]
fn the_trace_shows_each_assignment_branch_and_iteration_of_one_lane() {
    let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n  vec3 n = normalize(vec3(x, 0.0, 1.0));\n  float s = 0.0;\n  for (int i = 0; i < 2; i++) {\n    s += n.z;\n  }\n  if (s > 1.0) {\n    s = 1.0;\n  }\n  color = vec4(s);\n}\n";
    let p = compile(Stage::Fragment, src);
    let text = traced_lane_1(&p, 1.0);
    let has = |s: &str| text.iter().any(|t| t == s);
    assert!(has("5: n = vec3(0.707, 0.000, 0.707)"), "{text:#?}");
    assert!(
        has("7: loop: iteration 1") && has("7: loop: iteration 2"),
        "{text:#?}"
    );
    assert!(has("8: s = 1.414"), "{text:#?}");
    assert!(has("10: if: true → then"), "{text:#?}");
    assert!(has("11: s = 1.000"), "{text:#?}");
    assert!(
        has("13: color = vec4(1.000, 1.000, 1.000, 1.000)"),
        "{text:#?}"
    );
}

#[test]
fn the_builtin_shaders_link_and_a_fragment_input_finds_its_vertex_output() {
    let p = shader::link(None, None).unwrap_or_else(|e| panic!("{e:?}"));
    let names: Vec<&str> = p.fragment.inputs.iter().map(|i| i.name.as_str()).collect();
    assert_eq!(names, ["w_pos", "w_nrm", "v_uv", "v_color"]);
    assert!(p.links.iter().all(Option::is_some));
    let e = shader::link(None, Some("#version 330 core\nin vec3 w_norm;\nout vec4 color;\nvoid main() { color = vec4(w_norm, 1.0); }\n")).expect_err("no such output");
    assert_eq!((e[0].error.line, e[0].error.column), (2, 9), "{e:?}");
    assert!(
        e[0].error.message.contains("no output `w_norm`") && e[0].error.message.contains("w_nrm"),
        "{e:?}"
    );
}

/// The debugger never shows a value that is not zero as `0.000`: three decimals where they
/// show it, three significant digits in scientific form where they would not.
#[test]
fn the_debugger_shows_small_values_with_their_digits() {
    use pipeline::shader::float_text;
    assert_eq!(float_text(0.25), "0.250");
    assert_eq!(float_text(-1.5), "-1.500");
    assert_eq!(float_text(0.0), "0.000");
    assert_eq!(float_text(1.09e-5), "1.090e-5");
    assert_eq!(float_text(-4.066e-5), "-4.066e-5");
    assert_eq!(float_text(3.0e9), "3.000e9");
    assert_eq!(float_text(f32::NAN), "NaN");
    assert_eq!(float_text(f32::INFINITY), "inf");
}

/// The same stores in both stages' shaders: a fragment shader that writes a colour through
/// `c[1].gb` and `m[2].x` compiles and gives the colour worked out by hand, and a message after
/// the rewritten line is still at its own line.
#[test]
fn swizzle_stores_of_indexed_values_compile_in_a_fragment_shader() {
    let src = "#version 330 core
out vec4 color;
void main() {
    vec3 c[2];
    c[1] = vec3(0.0);
    c[1].gb = vec2(0.25, 0.5);
    mat3 m = mat3(0.0);
    m[2].x = 0.75;
    color = vec4(m[2].x, c[1].g, c[1].b, 1.0);
}
";
    let p = compile(Stage::Fragment, src);
    let (out, _) = run(&p, &Uniforms::default(), &[], &[]).expect("runs");
    assert!(close(&out[0], &[0.75, 0.25, 0.5, 1.0]), "{:?}", out[0]);
    let broken = src.replace("    color = vec4", "    float x = nope;\n    color = vec4");
    let e = errors(Stage::Fragment, &broken);
    assert_eq!(e[0].line, 9, "{e:?}");
}
