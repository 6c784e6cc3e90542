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
/// `texelFetchOffset`'s offset (naga's front end drops it), GLSL 3.30's `modf` and
/// `matrixCompMult` (naga's front end does not know them).
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
    // Built-ins of GLSL 3.30 naga does not know, refused by name, not as a misspelling.
    for (call, name) in [
        ("modf(1.5, whole)", "modf"),
        (
            "matrixCompMult(mat2(1.0), mat2(2.0))[0].x",
            "matrixCompMult",
        ),
    ] {
        let src = format!(
            "#version 330 core\nout vec4 color;\nvoid main() {{\n    float whole;\n    float part = {call};\n    color = vec4(part);\n}}\n"
        );
        let e = errors(Stage::Fragment, &src);
        assert_eq!(
            e[0].complaint,
            Complaint::NotRunYet(name.to_owned()),
            "{e:?}"
        );
        assert_eq!((e[0].line, e[0].column), (5, 18), "{e:?}");
    }
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
    let no_return = "#version 330 core\nout vec4 color;\nfloat f(float x) {\n    if (x > 0.0) {\n        return 1.0;\n    }\n}\nvoid main() {\n    color = vec4(f(1.0));\n}\n";
    let e = errors(Stage::Fragment, no_return);
    assert_eq!(e[0].complaint, Complaint::ReturnType);
    assert!(e[0].message.contains("can end without `return`"), "{e:?}");
}
