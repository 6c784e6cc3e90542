//! What GLSL refuses, pipelens refuses too: a shader that compiles here must also compile on
//! the course's real OpenGL.

use pipeline::shader::{self, Stage};

use crate::shader::{compile, errors};

/// What GLSL refuses, pipelens refuses too, so that a shader that passes here also compiles on
/// the course's real OpenGL: a `#version` GLSL does not have (at the directive, with what was
/// written), and `%` between floats (naga's WGSL-minded front end reads it; GLSL's `%` takes
/// integers). `mod` and an integer `%` still compile, and every version the course uses.
#[test]
fn a_version_glsl_lacks_and_a_float_modulo_are_refused() {
    use shader::Complaint;
    let body = "out vec4 color;\nvoid main() {\n    color = vec4(gl_FragCoord.x);\n}\n";
    for (version, written) in [
        ("#version 999 core", "999 core"),
        ("#version 3.30", "3.30"),
        ("  #version 330 cor", "330 cor"),
    ] {
        let e = errors(Stage::Fragment, &format!("{version}\n{body}"));
        assert_eq!(e.len(), 1, "{e:?}");
        assert_eq!(
            e[0].complaint,
            Complaint::InvalidVersion(written.to_owned())
        );
        assert_eq!(e[0].line, 1);
        assert!(
            e[0].message.contains(&format!("`{written}`")),
            "{}",
            e[0].message
        );
    }
    for version in [
        "#version 330 core",
        "#version 330",
        "#version 120",
        "#version 450 core",
        "#version 300 es",
    ] {
        compile(Stage::Fragment, &format!("{version}\n{body}"));
    }
    let float_modulo = "#version 330 core\nout vec4 color;\nvoid main() {\n    float a = gl_FragCoord.x % 2.0;\n    color = vec4(a);\n}\n";
    let e = errors(Stage::Fragment, float_modulo);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].complaint, Complaint::FloatModulo);
    assert_eq!(e[0].line, 4);
    compile(
        Stage::Fragment,
        &float_modulo.replace("gl_FragCoord.x % 2.0", "mod(gl_FragCoord.x, 2.0)"),
    );
    compile(
        Stage::Fragment,
        &float_modulo.replace("gl_FragCoord.x % 2.0", "float(int(gl_FragCoord.x) % 2)"),
    );
}

/// GLSL 1.20's `texture2D`, `texture2DLod` and `textureCube` (which OpenGL drivers still take in
/// `#version 330 core`) run as GLSL 1.30's `texture` and `textureLod`: the same lookups, value for
/// value, and a message still at the student's column (the names are padded, not moved).
#[test]
fn glsl_1_20_texture_calls_run_as_their_1_30_names() {
    use pipeline::shader::Uniforms;
    use pipeline::texture::Texture;
    let old = "#version 120\nuniform sampler2D tex;\nvarying vec2 uv;\nvoid main() {\n    gl_FragColor = texture2D(tex, uv) + texture2DLod(tex, uv, 1.0);\n}\n";
    let new = "#version 330 core\nuniform sampler2D tex;\nin vec2 uv;\nout vec4 color;\nvoid main() {\n    color = texture(tex, uv) + textureLod(tex, uv, 1.0);\n}\n";
    let t = Texture::checkerboard(64, 8);
    let d = 1.0 / 64.0;
    let quad = vec![
        vec![0.3, 0.6],
        vec![0.3 + d, 0.6],
        vec![0.3, 0.6 + d],
        vec![0.3 + d, 0.6 + d],
    ];
    let run = |src: &str| {
        crate::shader::run(
            &compile(Stage::Fragment, src),
            &Uniforms::default(),
            std::slice::from_ref(&quad),
            &[Some(&t)],
        )
        .expect("runs")
        .0
    };
    let (a, b) = (run(old), run(new));
    assert_eq!(a, b);
    // Not all black: the lookups read the texture.
    assert!(a.iter().any(|o| o[0] > 0.0), "{a:?}");
    let e = errors(
        Stage::Fragment,
        "#version 120\nuniform sampler2D tex;\nvoid main() {\n    gl_FragColor = texture2D(tex, vec2(0.5)) + undefined_name;\n}\n",
    );
    // 4 spaces, `gl_FragColor = ` (15), `texture2D(tex, vec2(0.5))` (25), ` + ` (3): column 48.
    assert_eq!((e[0].line, e[0].column), (4, 48), "{e:?}");
}

/// A built-in pipelens does not honour is refused at its name, never run without its argument:
/// `texelFetchOffset`'s offset (naga's front end drops it).
#[test]
fn a_built_in_pipelens_does_not_run_is_refused_at_its_name() {
    use shader::Complaint;
    let (call, name) = (
        "texelFetchOffset(tex, ivec2(3, 4), 0, ivec2(1, 0))",
        "texelFetchOffset",
    );
    let src = format!(
        "#version 330 core\nuniform sampler2D tex;\nout vec4 color;\nvoid main() {{\n    color = {call};\n}}\n"
    );
    let e = errors(Stage::Fragment, &src);
    assert_eq!(
        e[0].complaint,
        Complaint::NotRunYet(name.to_owned()),
        "{e:?}"
    );
    // `    color = ` is 12 characters: the name starts at column 13.
    assert_eq!((e[0].line, e[0].column), (5, 13), "{name}: {e:?}");
    assert_eq!(e[0].message, format!("pipelens does not run `{name}` yet"));
}

/// GLSL 3.30's `modf` and `matrixCompMult`, which naga's front end does not know, run as
/// pipelens wrote them in GLSL (§8.3: modf's parts both take x's sign; §8.5: component by
/// component); the trace shows the student's steps and the call's results, none of the
/// built-in's own.
#[test]
fn modf_and_matrix_comp_mult_run_and_their_insides_stay_out_of_the_trace() {
    use pipeline::shader::Uniforms;
    let src = "#version 330 core
in float x;
out vec4 color;
void main() {
    float whole;
    float part = modf(x, whole);
    vec3 wholes;
    vec3 parts = modf(vec3(x, -x, 2.0 * x), wholes);
    mat2 m = matrixCompMult(mat2(x, 2.0, 3.0, 4.0), mat2(5.0, 6.0, 7.0, x));
    color = vec4(whole + part * 10.0, wholes.y + parts.y * 10.0, m[0][0], m[1][1] + m[1][0]);
}
";
    let p = compile(Stage::Fragment, src);
    let xs: Vec<Vec<f32>> = [2.75f32, -1.25, 0.5, -3.0]
        .iter()
        .map(|&x| vec![x])
        .collect();
    let (out, _) =
        crate::shader::run(&p, &Uniforms::default(), std::slice::from_ref(&xs), &[]).expect("runs");
    for (o, x) in out.iter().zip(&xs) {
        let x = x[0];
        // modf(2.75) = 0.75, whole 2; modf(−1.25) = −0.25, whole −1 (both x's sign).
        let (w, f) = (x.trunc(), x - x.trunc());
        let (wy, fy) = ((-x).trunc(), -x - (-x).trunc());
        let want = [w + f * 10.0, wy + fy * 10.0, x * 5.0, x * 4.0 + 3.0 * 7.0];
        for (g, w) in o.iter().zip(want) {
            assert!((g - w).abs() < 1e-5, "x = {x}: {o:?} != {want:?}");
        }
    }
    // Lane 1 (x = −1.25): the trace names the student's writes, at their lines, and no step
    // of the built-ins (no call, no `i = trunc(x)`).
    let text = crate::shader::traced_lane_1(&p, -1.25);
    for want in ["6: whole = -1.000", "6: part = -0.250", "9: m = "] {
        assert!(
            text.iter().any(|t| t.starts_with(want)),
            "no `{want}` in {text:#?}"
        );
    }
    assert!(
        text.iter()
            .all(|t| !t.starts_with("1:") && !t.contains("modf") && !t.contains("matrixCompMult")),
        "{text:#?}"
    );
}

/// GLSL allows no recursion, and a function must be declared above its first call: naga reads
/// both as an unknown function; pipelens says which it is, at the call. A function that can end
/// without `return` is said so.
#[test]
fn recursion_a_call_above_the_definition_and_a_missing_return_are_said_as_such() {
    use shader::Complaint;
    let recursive = "#version 330 core\nout vec4 color;\nfloat depth(float x) {\n    if (x < 1.0) {\n        return 0.0;\n    }\n    return 1.0 + depth(x / 2.0);\n}\nvoid main() {\n    color = vec4(depth(8.0));\n}\n";
    let e = errors(Stage::Fragment, recursive);
    assert_eq!(e[0].complaint, Complaint::Recursion("depth".to_owned()));
    assert_eq!((e[0].line, e[0].column), (7, 18), "{e:?}");
    assert_eq!(
        e[0].message,
        "GLSL does not allow recursion: `depth` calls itself"
    );
    let below = "#version 330 core\nout vec4 color;\nvoid main() {\n    color = vec4(shade(0.5));\n}\nfloat shade(float x) {\n    return x * x;\n}\n";
    let e = errors(Stage::Fragment, below);
    assert_eq!(e[0].complaint, Complaint::DefinedBelow("shade".to_owned()));
    assert_eq!(e[0].line, 4, "{e:?}");
    // With its prototype above, the same program compiles.
    compile(
        Stage::Fragment,
        &below.replace(
            "out vec4 color;\n",
            "out vec4 color;\nfloat shade(float x);\n",
        ),
    );
    // Defined above, called from `main` with a vec2 where it takes a float: neither.
    let mismatched = "#version 330 core\nout vec4 color;\nfloat shade(float x) {\n    return x * x;\n}\nvoid main() {\n    color = vec4(shade(vec2(0.5)));\n}\n";
    let e = errors(Stage::Fragment, mismatched);
    assert_eq!(
        e[0].complaint,
        Complaint::ArgumentTypes {
            name: "shade".to_owned(),
            parameters: "(float x)".to_owned()
        }
    );
    assert_eq!(e[0].line, 7, "{e:?}");
    assert_eq!(
        e[0].message,
        "the arguments do not match the parameters of `shade` (float x): check each argument's type"
    );
    let no_return = "#version 330 core\nout vec4 color;\nfloat f(float x) {\n    if (x > 0.0) {\n        return 1.0;\n    }\n}\nvoid main() {\n    color = vec4(f(1.0));\n}\n";
    let e = errors(Stage::Fragment, no_return);
    assert_eq!(e[0].complaint, Complaint::ReturnType);
    assert!(e[0].message.contains("can end without `return`"), "{e:?}");
}

/// `%` between an integer vector and a scalar applies the scalar to each component (GLSL 3.30
/// §5.9); naga's front end leaves it unsplatted, so pipelens rewrites it and a message after it
/// still points at the student's column.
#[test]
fn an_integer_vector_modulo_a_scalar_runs_component_by_component() {
    use pipeline::shader::Uniforms;
    let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n    ivec2 p = ivec2(int(x) + 17, 3 * int(x) + 5);\n    ivec2 m = p % 4;\n    uvec3 q = 50u % uvec3(uint(x) + 3u, 7u, 9u);\n    color = vec4(vec2(m), float(q.x), float(q.y + q.z));\n}\n";
    let xs: Vec<Vec<f32>> = (0..4).map(|l| vec![l as f32 * 3.0]).collect();
    let (out, _) = crate::shader::run(
        &compile(Stage::Fragment, src),
        &Uniforms::default(),
        &[xs],
        &[],
    )
    .expect("runs");
    for (l, o) in out.iter().enumerate() {
        let x = l as i32 * 3;
        let want = [
            ((x + 17) % 4) as f32,
            ((3 * x + 5) % 4) as f32,
            (50 % (x + 3)) as f32,
            (50 % 7 + 50 % 9) as f32,
        ];
        assert_eq!(o, &want.to_vec(), "lane {l} (x = {x})");
    }
    // A mistake naga's second reading finds (a float `%`, refused with GLSL's reason) is where
    // the same mistake is in the same source with `& 3` for `% 4` (nothing rewritten), on the
    // rewritten line and on the line below.
    let shader = |lines: &str| {
        format!(
            "#version 330 core\nout vec4 color;\nvoid main() {{\n{lines}\n    color = vec4(vec2(m), f, 1.0);\n}}\n"
        )
    };
    for (lines, line) in [
        (
            "    ivec2 m = ivec2(gl_FragCoord.xy) % 4; float f = gl_FragCoord.x % 2.0;",
            4,
        ),
        (
            "    ivec2 m = ivec2(gl_FragCoord.xy) % 4;\n    float f = gl_FragCoord.x % 2.0;",
            5,
        ),
    ] {
        let e = errors(Stage::Fragment, &shader(lines));
        let plain = errors(Stage::Fragment, &shader(&lines.replace("% 4", "& 3")));
        assert_eq!(e[0].complaint, shader::Complaint::FloatModulo, "{e:?}");
        assert_eq!(e[0].line, line, "{e:?}");
        assert_eq!((e[0].line, e[0].column), (plain[0].line, plain[0].column));
    }
}
