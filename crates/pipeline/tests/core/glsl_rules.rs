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
