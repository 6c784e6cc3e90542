//! A student's own uniforms in the shader panel: a control per type (a slider, numbers, a
//! colour) that sets the scene's value, and the frame drawn with it.

use egui::Key;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::app::command::SelectionCommand;
use pipelens::app::session::Command;

use super::debugger::first_fragment;

/// Lesson 24 at 1920 × 1080, the shader panel open, drawing with the fragment shader `source`
/// applied as the panel applies it.
fn drawing(source: &str) -> Harness<'static, PipelensApp> {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    let app = h.state_mut();
    app.shader_editor.fragment = source.to_owned();
    app.shader_editor.shaders_in_use = true;
    let applied = app.shader_editor.apply(&app.session).expect("compiles");
    app.session.apply(applied);
    h.run_steps(4);
    h
}

/// The colour the fragment shader wrote at the frame's middle pixel (on the sphere), the
/// pixel inspected and the frame keeping its run drawn.
fn centre_output(h: &mut Harness<'static, PipelensApp>) -> [f32; 4] {
    h.state_mut()
        .session
        .apply(Command::Selection(SelectionCommand::SelectPixel(Some((
            240, 180,
        )))));
    for _ in 0..20 {
        h.run_steps(2);
        let done = h
            .state()
            .session
            .capture
            .as_ref()
            .is_some_and(|c| c.settings.capture.pixel == Some((240, 180)));
        if done {
            break;
        }
    }
    first_fragment(h).output.expect("an output")
}

/// A uniform of the student's own is a control in the panel: `level` from its comment starts
/// at 0.25 on a 0.01 grid (a hundredth of its range 0..1, a power of ten), so one → on the
/// focused slider makes it 0.26, and the frame draws grey 0.26 at the sphere's centre (the
/// shader writes `vec4(vec3(level), 1)`).
#[test]
fn a_uniform_of_ones_own_is_a_slider_that_redraws_the_frame() {
    let mut h = drawing(
        "#version 330 core
uniform float level; // 0..1 = 0.25
out vec4 color;
void main() {
    color = vec4(vec3(level), 1.0);
}
",
    );
    h.get_by_role_and_label(egui::accesskit::Role::Slider, "level")
        .focus();
    h.run_steps(2);
    h.key_press(Key::ArrowRight);
    h.run_steps(2);
    let level = h.state().session.spec.scene.uniforms.get("level").cloned();
    assert_eq!(level, Some(vec![0.26]));
    assert_eq!(centre_output(&mut h), [0.26, 0.26, 0.26, 1.0]);
}

/// A `vec2` of the student's own is two numbers and a `vec4` without a range a colour with
/// its alpha: ↑ on the focused first number moves `offset.x` by its step, a two-hundredth of
/// its range 0..1 (0.25 → 0.255), and the frame's centre draws red `glaze.r · glaze.a +
/// offset.x` = 0.5 · 0.5 + 0.255 = 0.505 (by hand, from the shader below).
#[test]
fn a_vec2_is_two_numbers_and_a_vec4_a_colour_with_its_alpha() {
    let mut h = drawing(
        "#version 330 core
uniform vec4 glaze;  // = 0.5, 0.5, 0.5, 0.5
uniform vec2 offset; // 0..1 = 0.25
out vec4 color;
void main() {
    color = vec4(glaze.rgb * glaze.a + vec3(offset, 0.0), 1.0);
}
",
    );
    let numbers = h.get_all_by_role_and_label(egui::accesskit::Role::SpinButton, "offset");
    assert_eq!(numbers.count(), 2, "offset is two numbers");
    assert!(
        h.query_by_role_and_label(egui::accesskit::Role::ColorWell, "glaze")
            .is_some(),
        "glaze is a colour"
    );
    h.get_all_by_role_and_label(egui::accesskit::Role::SpinButton, "offset")
        .next()
        .expect("the first number")
        .focus();
    h.run_steps(2);
    h.key_press(Key::ArrowUp);
    h.run_steps(2);
    let offset = h.state().session.spec.scene.uniforms.get("offset").cloned();
    assert_eq!(offset, Some(vec![0.255, 0.25]));
    let out = centre_output(&mut h);
    assert!((out[0] - 0.505).abs() < 1e-6, "{out:?}");
    assert!((out[1] - (0.25 + 0.25)).abs() < 1e-6, "{out:?}");
}
