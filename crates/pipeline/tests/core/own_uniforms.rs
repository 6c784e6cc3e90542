//! A student's own uniforms: a `float`, `int`, `bool`, `vec2`, `vec3` or `vec4` pipelens does not set is the
//! student's, its control's range and first value in the comment after it; the frame draws it
//! with the scene's value, or the comment's. A name close to one pipelens sets, of its type, is
//! a misspelling unless it has a control; a type no control sets is an error.

use pipeline::shader::own_uniform::{OwnKind, OwnUniform};
use pipeline::shader::{Complaint, Stage, compile};

use crate::shader_frame::{settings, sphere_scene, with_shaders};
use crate::support::render;

/// Grey `level` where `on`, black where not; `bands` and `tint` only declared.
const FS: &str = "#version 330 core
uniform float level; // 0..1 = 0.25
uniform bool on;     // = true
uniform int bands;   // 1..8 = 3
uniform vec3 tint;   // = 1, 0.5, 0
out vec4 color;
void main() {
    color = vec4(on ? vec3(level) : vec3(0.0), 1.0);
}
";

#[test]
fn the_comment_gives_each_control_its_range_and_first_value() {
    let p = compile(Stage::Fragment, FS).expect("compiles");
    let own = |name: &str, kind, range, value: &[f32], colour, line| OwnUniform {
        name: name.to_owned(),
        kind,
        range,
        value: value.to_vec(),
        colour,
        line,
    };
    assert_eq!(
        p.own_uniforms(),
        [
            own("level", OwnKind::Float, (0.0, 1.0), &[0.25], false, 2),
            own("on", OwnKind::Bool, (0.0, 1.0), &[1.0], false, 3),
            own("bands", OwnKind::Int, (1.0, 8.0), &[3.0], false, 4),
            own("tint", OwnKind::Vec3, (0.0, 1.0), &[1.0, 0.5, 0.0], true, 5),
        ]
    );
}

#[test]
fn the_frame_draws_the_scenes_value_or_the_comments() {
    let s = settings();
    let mut scene = with_shaders(sphere_scene(false), None, Some(FS));
    let centre = (s.height as usize / 2) * s.width as usize + s.width as usize / 2;
    let f = render(&scene, &s);
    // The comment's 0.25 (stored as computed: within [0, 1]).
    assert_eq!(f.pixels.color[centre], [0.25, 0.25, 0.25]);
    scene.uniforms.insert("level".to_owned(), vec![0.75]);
    let f = render(&scene, &s);
    assert_eq!(f.pixels.color[centre], [0.75, 0.75, 0.75]);
    scene.uniforms.insert("on".to_owned(), vec![0.0]);
    let f = render(&scene, &s);
    assert_eq!(f.pixels.color[centre], [0.0, 0.0, 0.0]);
}

/// A `vec4` without a range is a colour with its alpha; a `vec2` with one is two numbers, one
/// number in its comment standing for both.
const VECTORS: &str = "#version 330 core
uniform vec4 glaze;   // = 0.5, 0.25, 1, 0.75
uniform vec2 offset;  // -1..1 = 0.5
out vec4 color;
void main() {
    color = vec4(glaze.rgb * glaze.a + vec3(offset, 0.0), 1.0);
}
";

#[test]
fn a_vec2_and_a_vec4_are_controls_too() {
    let p = compile(Stage::Fragment, VECTORS).expect("compiles");
    let own = p.own_uniforms();
    assert_eq!(own.len(), 2);
    assert_eq!(
        (
            own[0].kind,
            own[0].range,
            own[0].colour,
            own[0].value.clone()
        ),
        (OwnKind::Vec4, (0.0, 1.0), true, vec![0.5, 0.25, 1.0, 0.75])
    );
    assert_eq!(
        (
            own[1].kind,
            own[1].range,
            own[1].colour,
            own[1].value.clone()
        ),
        (OwnKind::Vec2, (-1.0, 1.0), false, vec![0.5, 0.5])
    );
    // The frame: glaze.rgb · glaze.a + (offset, 0) = (0.375 + 0.5, 0.1875 + 0.5, 0.75), by
    // hand; then the scene's values, (0, 0, 0, 1) and (0.25, -0.25): (0.25, 0, 0) after the
    // colour buffer's clamp to [0, 1].
    let s = settings();
    let mut scene = with_shaders(sphere_scene(false), None, Some(VECTORS));
    let centre = (s.height as usize / 2) * s.width as usize + s.width as usize / 2;
    let f = render(&scene, &s);
    assert_eq!(f.pixels.color[centre], [0.875, 0.6875, 0.75]);
    scene
        .uniforms
        .insert("glaze".to_owned(), vec![0.0, 0.0, 0.0, 1.0]);
    scene
        .uniforms
        .insert("offset".to_owned(), vec![0.25, -0.25]);
    let f = render(&scene, &s);
    assert_eq!(f.pixels.color[centre], [0.25, 0.0, 0.0]);
}

#[test]
fn a_misspelling_a_bad_control_and_a_type_no_control_sets_are_errors() {
    let error = |decl: &str| {
        let src = format!(
            "#version 330 core\n{decl}\nout vec4 color;\nvoid main() {{ color = vec4(1.0); }}\n"
        );
        compile(Stage::Fragment, &src)
            .err()
            .map(|e| e[0].complaint.clone())
    };
    // `eyes` is a vec3 two letters from pipelens' `eye`: misspelt, unless it has a control.
    assert!(matches!(
        error("uniform vec3 eyes;"),
        Some(Complaint::UnknownUniform { suggestion: Some(s), .. }) if s == "eye"
    ));
    assert_eq!(error("uniform vec3 eyes; // = 0, 0, 1"), None);
    // `k` is near `ka`, a vec3: a float called k is the student's own.
    assert_eq!(error("uniform float k;"), None);
    assert!(matches!(
        error("uniform float k; // 4..1 = 2"),
        Some(Complaint::OwnUniformControl { .. })
    ));
    assert!(matches!(
        error("uniform float k; // 0..1 = 1, 2"),
        Some(Complaint::OwnUniformControl { .. })
    ));
    assert!(matches!(
        error("uniform vec4 tint4; // = 1, 0, 0"),
        Some(Complaint::OwnUniformControl { .. })
    ));
    assert!(matches!(
        error("uniform mat4 my_matrix;"),
        Some(Complaint::UnknownUniform { .. })
    ));
    // An ordinary comment is only a comment.
    assert_eq!(error("uniform float k; // the bands' count"), None);
}
