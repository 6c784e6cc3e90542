//! A lesson's keys about its shaders. A shader's own uniforms: `shader.uniforms` gives their values, a step's `set`
//! and `animate` change them as `"uniforms.NAME"`, and a wrong name, type or value is an error
//! at its place in the file. The frame's centre pixel is grey `level` (worked by hand: the
//! shader writes `vec4(vec3(level), 1)` and `level` stays inside [0, 1]). A step's
//! `shader_lines` and `panels`: lines the shader has, panels that exist.

use std::path::Path;

use pipelens::lesson::param::Value;
use pipelens::lesson::script::{StepPanel, parse_lesson};

const HEAD: &str = "[lesson]
id = \"t\"
title = { en = \"T\", zh = \"题\" }
summary = { en = \"S\", zh = \"概\" }

[[scene.objects]]
name = \"ball\"
mesh = { builtin = \"uv_sphere\", segments = 24, rings = 12 }

[scene.render]
width = 40
height = 30
samples = 1

[scene.shader]
fragment = \"\"\"
#version 330 core
uniform float level; // 0..1 = 0.25
uniform bool on;     // = true
out vec4 color;
void main() {
    color = vec4(on ? vec3(level) : vec3(0.0), 1.0);
}
\"\"\"
";

const STEP: &str =
    "[[steps]]\ntitle = { en = \"a\", zh = \"甲\" }\nnarration = { en = \"b\", zh = \"乙\" }\n";

fn centre(spec: &pipelens::lesson::SceneSpec) -> f32 {
    let f = pipeline::render(&spec.scene, &spec.settings).expect("draws");
    f.pixels.color[15 * 40 + 20][0]
}

#[test]
fn a_lesson_gives_sets_and_animates_a_shaders_own_uniform() {
    let text = format!(
        "{HEAD}uniforms = {{ level = 0.75 }}\n\n{STEP}\n{STEP}set = {{ \"uniforms.level\" = 0.5 }}\n\n{STEP}animate = [{{ param = \"uniforms.level\", from = 0.0, to = 1.0, seconds = 2.0, easing = \"linear\" }}]\n\n{STEP}set = {{ \"uniforms.on\" = false }}\n"
    );
    let lesson = parse_lesson(&text, "t.toml", Path::new(".")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(centre(&lesson.spec_at(0)), 0.75, "the file's value");
    assert_eq!(centre(&lesson.spec_at(1)), 0.5, "the step's set");
    assert_eq!(
        centre(&lesson.spec_playing(2, 0.5)),
        0.25,
        "a quarter of the way"
    );
    assert_eq!(centre(&lesson.spec_at(3)), 0.0, "switched off");
    assert_eq!(
        pipelens::lesson::param::get(&lesson.spec_at(1), "uniforms.level"),
        Some(Value::Number(0.5))
    );
    assert!(pipelens::lesson::param::names(&lesson.spec_at(0)).contains(&"uniforms.on".to_owned()));
}

/// A `vec4` colour and a `vec2` of the shader's own: the file's value, a step's `set` and an
/// animation between two `[x, y]`; the centre's red is `glaze.r · glaze.a + offset.x` (by
/// hand: the shader below).
#[test]
fn a_lesson_gives_sets_and_animates_a_vec2_and_a_vec4() {
    let head = HEAD.replace(
        "uniform float level; // 0..1 = 0.25\nuniform bool on;     // = true\nout vec4 color;\nvoid main() {\n    color = vec4(on ? vec3(level) : vec3(0.0), 1.0);",
        "uniform vec4 glaze;  // = 1, 1, 1, 1\nuniform vec2 offset; // 0..1 = 0\nout vec4 color;\nvoid main() {\n    color = vec4(glaze.rgb * glaze.a + vec3(offset, 0.0), 1.0);",
    );
    assert_ne!(head, HEAD, "the shader was replaced");
    let text = format!(
        "{head}uniforms = {{ glaze = [0.5, 0.0, 0.0, 0.5] }}\n\n{STEP}\n{STEP}set = {{ \"uniforms.offset\" = [0.5, 0.0] }}\n\n{STEP}animate = [{{ param = \"uniforms.offset\", from = [0.0, 0.0], to = [1.0, 1.0], seconds = 2.0, easing = \"linear\" }}]\n"
    );
    let lesson = parse_lesson(&text, "t.toml", Path::new(".")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(centre(&lesson.spec_at(0)), 0.25, "0.5 · 0.5");
    assert_eq!(centre(&lesson.spec_at(1)), 0.75, "0.25 + the step's 0.5");
    assert_eq!(
        centre(&lesson.spec_playing(2, 0.5)),
        0.5,
        "0.25 + a quarter of the way"
    );
    assert_eq!(
        pipelens::lesson::param::get(&lesson.spec_at(1), "uniforms.offset"),
        Some(Value::Vec2(glam::vec2(0.5, 0.0)))
    );
    let wrong = |extra: &str| match parse_lesson(
        &format!("{head}{extra}\n\n{STEP}"),
        "t.toml",
        Path::new("."),
    ) {
        Ok(_) => panic!("expected an error for {extra}"),
        Err(d) => d.0,
    };
    let found = wrong("uniforms = { glaze = [1.0, 0.0, 0.0] }");
    crate::support::assert_found(&found, 25, 22, "a vec4 takes four numbers [x, y, z, w]");
}

#[test]
fn a_wrong_uniform_name_type_or_value_is_an_error_at_its_place() {
    let errors = |extra: &str, step: &str| match parse_lesson(
        &format!("{HEAD}{extra}\n\n{STEP}{step}"),
        "t.toml",
        Path::new("."),
    ) {
        Ok(_) => panic!("expected an error for {extra} {step}"),
        Err(d) => d.0,
    };
    // The `uniforms` line is line 25 of the file: HEAD has 24.
    let found = errors("uniforms = { levle = 0.5 }", "");
    crate::support::assert_found(&found, 25, 14, "did you mean `level`?");
    let found = errors("uniforms = { level = 2.0 }", "");
    crate::support::assert_found(&found, 25, 22, "outside its control's range 0..1");
    let found = errors("uniforms = { on = 1 }", "");
    crate::support::assert_found(&found, 25, 19, "a bool takes true or false");
    let found = errors("", "set = { \"uniforms.level\" = -1.0 }");
    assert!(
        found
            .iter()
            .any(|d| d.message.contains("outside its control's range 0..1")),
        "{found:?}"
    );
}

#[test]
fn a_steps_shader_lines_and_panels_are_checked() {
    let lesson =
        |step: &str| parse_lesson(&format!("{HEAD}\n{STEP}{step}"), "t.toml", Path::new("."));
    // The fragment shader of HEAD has 7 lines (#version … the closing brace).
    let ok = lesson("shader_lines = [5, 6]\npanels = [\"inspector\", \"shader\"]\n")
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(ok.steps[0].shader_lines, Some((5, 6)));
    assert_eq!(
        ok.steps[0].panels,
        [StepPanel::Inspector, StepPanel::Shader]
    );
    let found = |step: &str| match lesson(step) {
        Ok(_) => panic!("expected an error for {step}"),
        Err(d) => d.0,
    };
    assert!(
        found("shader_lines = [5, 8]\n")
            .iter()
            .any(|d| d.message.contains("must be lines 1 to 7"))
    );
    assert!(
        found("shader_lines = [6, 5]\n")
            .iter()
            .any(|d| d.message.contains("the first not after the last"))
    );
    assert!(
        found("panels = [\"inspectr\"]\n")
            .iter()
            .any(|d| d.message.contains("\"inspector\""))
    );
}

/// A mistake in a lesson's GLSL is said at its place with the sentence the app shows the
/// student, not naga's words ("Unknown variable: lvl"): `lvl` on line 22 (HEAD's `color = …`
/// line), column 28 (four spaces and `color = vec4(on ? vec3(` before it, counted by hand).
#[test]
fn a_mistake_in_a_lessons_shader_is_the_students_sentence_at_its_place() {
    let source = format!("{HEAD}\n{STEP}").replace("vec3(level)", "vec3(lvl)");
    let Err(d) = parse_lesson(&source, "t.toml", Path::new(".")) else {
        panic!("an undeclared name is refused");
    };
    crate::support::assert_found(
        &d.0,
        22,
        28,
        "fragment shader: `lvl` is not declared here: declare it before its first use, or check its spelling",
    );
}
