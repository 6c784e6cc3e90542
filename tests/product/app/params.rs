//! The Parameters panel against a lesson's parameters: the same change made either way gives
//! the same scene.

use egui_kittest::kittest::Queryable;
use pipelens::lesson::param::{Value, apply};

/// The projection's kind switched in the panel's combo box and with a lesson's
/// `projection.kind` (one core function, `Projection::with_kind`) gives the same view volume:
/// they once differed (the panel made an ortho box four times the near rectangle and reset
/// fovy to 45°).
#[test]
fn the_projection_combo_box_and_a_lessons_projection_kind_give_the_same_view_volume() {
    let mut h = super::lesson_harness(None);
    h.run();
    h.key_press(egui::Key::P);
    h.run_steps(2);
    for (label, key) in [
        ("Ortho", "ortho"),
        ("Frustum", "frustum"),
        ("Perspective", "perspective"),
        ("Frustum", "frustum"),
        ("Ortho", "ortho"),
    ] {
        let mut want = h.state().session.spec.clone();
        apply(&mut want, "projection.kind", &Value::Name(key.to_owned())).expect("a valid kind");
        h.get_by_role_and_label(egui::accesskit::Role::ComboBox, "projection")
            .click();
        h.run();
        h.get_by_label(label).click();
        h.run();
        let got = h.state().session.spec.scene.projection;
        assert_eq!(got, want.scene.projection, "{label}");
        assert_eq!(got.kind().key(), key);
    }
}

/// While the student's shaders draw the picture, the shading frequency and the specular term
/// say that they change nothing on screen (they choose what "pipelens' own" writes); without
/// shaders of the student's, no such note.
#[test]
fn the_shading_choices_say_when_the_students_shaders_draw() {
    const NOTE: &str = "Your shaders draw the picture";
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.parameters = true;
    h.run_steps(4);
    assert!(h.state().session.spec.scene.has_shaders());
    assert!(h.query_by_label_contains(NOTE).is_some());
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.parameters = true;
    h.run_steps(4);
    assert!(!h.state().session.spec.scene.has_shaders());
    assert!(h.query_by_label_contains(NOTE).is_none());
}
