//! The student's mistakes in a shader, each reported at its line: an endless loop and a run-time
//! error (a division by zero, an index out of range) stop the run there; a typo, a type
//! mismatch, a missing output, an unknown uniform and an assignment to a uniform do not compile.

use pipeline::shader::{Stage, Uniforms};

use crate::shader::{compile, errors, run};

#[test]
fn an_endless_loop_stops_at_its_line() {
    let src = "#version 330 core\nout vec4 color;\nvoid main() {\n  float x = 0.0;\n  while (true) {\n    x += 1.0;\n  }\n  color = vec4(x);\n}\n";
    let p = compile(Stage::Fragment, src);
    let e = run(&p, &Uniforms::default(), &[], &[]).expect_err("stops");
    assert_eq!(e.line, 5, "{e}");
    assert!(e.message.contains("more than"), "{e}");
}

#[test]
fn integer_division_by_zero_and_a_bad_index_are_errors_at_their_lines() {
    let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n  int i = int(x);\n  int j = 7 / i;\n  color = vec4(float(j));\n}\n";
    let p = compile(Stage::Fragment, src);
    let e = run(
        &p,
        &Uniforms::default(),
        &[vec![vec![1.0], vec![0.0], vec![2.0], vec![3.0]]],
        &[],
    )
    .expect_err("division by zero");
    assert_eq!(e.line, 6, "{e}");
    assert!(e.message.contains("division by zero"), "{e}");
    let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n  float a[3] = float[3](1.0, 2.0, 3.0);\n  int i = int(x);\n  color = vec4(a[i]);\n}\n";
    let p = compile(Stage::Fragment, src);
    let e = run(
        &p,
        &Uniforms::default(),
        &[vec![vec![1.0], vec![5.0], vec![2.0], vec![0.0]]],
        &[],
    )
    .expect_err("out of range");
    assert_eq!(e.line, 7, "{e}");
    assert!(e.message.contains("index 5"), "{e}");
}

#[test]
fn a_typo_is_reported_at_its_line_and_column() {
    let src = "#version 330 core\nin vec2 uv;\nout vec4 color;\nvoid main() {\n  vex3 c = vec3(uv, 1.0);\n  color = vec4(c, 1.0);\n}\n";
    let e = errors(Stage::Fragment, src);
    assert_eq!((e[0].line, e[0].column), (5, 3), "{e:?}");
    assert!(e[0].message.contains("vex3"), "{e:?}");
}

#[test]
fn a_type_mismatch_is_reported_at_its_line() {
    let src = "#version 330 core\nuniform sampler2D tex;\nin vec2 uv;\nout vec4 color;\nvoid main() {\n  vec3 c = texture(tex, uv);\n  color = vec4(c, 1.0);\n}\n";
    let e = errors(Stage::Fragment, src);
    assert_eq!(e[0].line, 6, "{e:?}");
    assert!(e[0].message.contains("type"), "{e:?}");
}

#[test]
fn a_missing_output_and_an_unknown_uniform_are_explained() {
    let e = errors(
        Stage::Fragment,
        "#version 330 core\nout vec4 color;\nvoid main() {\n  vec4 c = vec4(1.0);\n}\n",
    );
    assert!(e[0].message.contains("never writes `color`"), "{e:?}");
    assert_eq!(e[0].line, 2);
    let e = errors(
        Stage::Vertex,
        "#version 330 core\nin vec3 position;\nvoid main() {\n}\n",
    );
    assert!(e[0].message.contains("gl_Position"), "{e:?}");
    let e = errors(
        Stage::Fragment,
        "#version 330 core\nuniform vec3 eyes;\nout vec4 color;\nvoid main() { color = vec4(eyes, 1.0); }\n",
    );
    assert_eq!((e[0].line, e[0].column), (2, 14), "{e:?}");
    assert!(e[0].message.contains("did you mean `eye`"), "{e:?}");
    let e = errors(
        Stage::Fragment,
        "#version 330 core\nuniform vec4 eye;\nout vec4 color;\nvoid main() { color = eye; }\n",
    );
    assert!(e[0].message.contains("is a vec3"), "{e:?}");
    let e = errors(
        Stage::Fragment,
        "#version 330 core\nuniform vec3 eye;\nout vec4 color;\nvoid main() { eye = vec3(1.0); color = vec4(eye, 1.0); }\n",
    );
    assert!(e[0].message.contains("cannot assign"), "{e:?}");
}
