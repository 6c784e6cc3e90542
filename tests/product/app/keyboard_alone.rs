//! The app with the keyboard alone: no pointer event is sent in these tests. A lesson is stepped,
//! a pixel inspected and moved, the observer turned, and a lab inspected and solved, each by
//! the keys a student without a mouse has (Tab, the arrows, Enter, V, S, Ctrl+Enter).

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::vocabulary::Stage;

/// Presses `key` and lets the app draw a few frames (the views read keys as they are drawn).
fn press(h: &mut Harness<'static, PipelensApp>, key: Key) {
    h.key_press(key);
    h.run_steps(3);
}

fn press_with(h: &mut Harness<'static, PipelensApp>, modifiers: Modifiers, key: Key) {
    h.key_press_modifiers(modifiers, key);
    h.run_steps(3);
}

fn pixel(h: &Harness<'static, PipelensApp>) -> Option<(u32, u32)> {
    h.state().session.selection.pixel
}

/// Presses Tab until the node labelled `label` has the focus (as a student tabbing through the
/// window would); panics after 300 presses.
fn tab_to(h: &mut Harness<'static, PipelensApp>, label: &str) {
    for _ in 0..300 {
        if h.query_by_label(label).is_some_and(|n| n.is_focused()) {
            return;
        }
        press(h, Key::Tab);
    }
    panic!("Tab never reached {label:?}");
}

/// The tour by keys: → steps; V gives the picture the keys, where the arrows move the inspected
/// pixel (up is +y, as window coordinates go; Shift moves ten) and do not step; Escape gives
/// the arrows back to the steps; V twice turns the observer; a letter shortcut still works
/// while a button has the focus.
#[test]
fn a_step_and_a_pixel_by_the_keys_alone() {
    let mut h = crate::app::lesson_harness(None);
    h.run_steps(4);
    let first = crate::app::step_of(&h);
    press(&mut h, Key::ArrowRight);
    assert_eq!(crate::app::step_of(&h), first + 1, "→ steps the lesson");
    // On to the first step that shows a pixel stage, by Page Down.
    while h.state().session.selection.stage.space().is_some() {
        let before = crate::app::step_of(&h);
        press(&mut h, Key::PageDown);
        assert_eq!(crate::app::step_of(&h), before + 1, "Page Down steps");
    }
    let step = crate::app::step_of(&h);
    let stage = h.state().session.selection.stage;
    assert!(pixel(&h).is_none(), "no pixel is inspected yet");
    press(&mut h, Key::V);
    press(&mut h, Key::ArrowRight);
    let (x, y) = pixel(&h).expect("the first arrow inspects a pixel");
    let capture = h.state().session.capture.clone().expect("a capture");
    assert!(x < capture.width() && y < capture.height());
    assert_eq!(
        crate::app::step_of(&h),
        step,
        "the arrow moved the pixel, not the step"
    );
    press(&mut h, Key::ArrowRight);
    assert_eq!(pixel(&h), Some((x + 1, y)), "→ moves one pixel right");
    press(&mut h, Key::ArrowDown);
    assert_eq!(
        pixel(&h),
        Some((x + 1, y - 1)),
        "↓ moves one pixel down (y is up)"
    );
    press_with(&mut h, Modifiers::SHIFT, Key::ArrowLeft);
    assert_eq!(pixel(&h), Some((x - 9, y - 1)), "Shift+← moves ten");
    // Down the picture is down the image's rows: the pixel one below is the next row down.
    let grid = capture.grid();
    assert_eq!(grid.row(y - 1), grid.row(y) + 1);
    assert!(
        h.query_all_by_label_contains(&format!("({}, {})", x - 9, y - 1))
            .count()
            > 0,
        "the inspector explains the pixel the keys chose"
    );
    // Escape: the arrows step again, the pixel stays inspected.
    press(&mut h, Key::Escape);
    press(&mut h, Key::ArrowRight);
    assert_eq!(crate::app::step_of(&h), step + 1);
    press(&mut h, Key::ArrowLeft);
    assert_eq!(crate::app::step_of(&h), step);
    assert_eq!(h.state().session.selection.stage, stage);
    // V twice: the observer beside the picture has the keys; ← turns it as a drag to the left
    // does (the yaw grows), ↑ tilts it (the pitch falls), and + brings it closer.
    if h.state().session.selection.show_observer {
        let orbit = h.state().session.orbit;
        press(&mut h, Key::V);
        press(&mut h, Key::V);
        press(&mut h, Key::ArrowLeft);
        press(&mut h, Key::ArrowUp);
        press(&mut h, Key::Plus);
        let turned = h.state().session.orbit;
        assert!(
            (turned.yaw - orbit.yaw - 5.0).abs() < 1e-4,
            "{orbit:?} → {turned:?}"
        );
        assert!(
            (orbit.pitch - turned.pitch - 5.0).abs() < 1e-4,
            "{orbit:?} → {turned:?}"
        );
        assert!((orbit.distance / turned.distance - 1.25).abs() < 1e-4);
        assert_eq!(
            crate::app::step_of(&h),
            step,
            "the observer's arrows do not step"
        );
        press(&mut h, Key::V);
        press(&mut h, Key::ArrowRight);
        assert_eq!(
            crate::app::step_of(&h),
            step + 1,
            "the third V gives the arrows back"
        );
    }
    // A button with the focus keeps Space and the arrows, not the letters: N folds the
    // narration.
    tab_to(&mut h, "Next step");
    assert!(h.state().panels.narration);
    press(&mut h, Key::N);
    assert!(
        !h.state().panels.narration,
        "N works beside a focused button"
    );
    press(&mut h, Key::Enter);
    assert!(
        crate::app::step_of(&h) > step,
        "Enter presses the focused button"
    );
}

/// A geometry stage by keys: V, then the arrows orbit it (the picture changes and the step
/// stays), and `]` picks the first vertex, `[` goes back round to the last.
#[test]
fn a_geometry_view_orbits_and_picks_vertices_by_the_keys() {
    let mut h = crate::app::harness();
    h.run();
    assert_eq!(h.state().session.selection.stage, Stage::World);
    press(&mut h, Key::V);
    let count = h
        .state()
        .session
        .capture
        .as_ref()
        .map_or(0, |c| c.vertices.len());
    assert!(count > 1);
    press(&mut h, Key::CloseBracket);
    assert_eq!(h.state().session.selection.vertex, Some(0));
    press(&mut h, Key::OpenBracket);
    assert_eq!(
        h.state().session.selection.vertex,
        Some(count as u32 - 1),
        "[ from the first goes round to the last"
    );
    // What the frame paints, as a check of the picture: the same with no key pressed, and
    // another once the arrow has turned the view.
    let painted = |h: &Harness<'static, PipelensApp>| format!("{:?}", h.output().shapes);
    let before = painted(&h);
    h.run_steps(3);
    assert_eq!(painted(&h), before, "a still view paints the same");
    press(&mut h, Key::ArrowLeft);
    assert_eq!(
        h.state().session.selection.stage,
        Stage::World,
        "the arrow turned the view, not the stage"
    );
    assert_ne!(painted(&h), before, "the view turned");
    press(&mut h, Key::Escape);
    press(&mut h, Key::ArrowRight);
    assert_eq!(h.state().session.selection.stage, Stage::View);
}

/// Lesson 10's specular lab by keys: Page Down to it, Tab to "Inspect the first wrong pixel"
/// and Enter (the pixel is the first wrong one, read from the top), the arrows move it in the
/// student's frame, S opens the shader, Tab reaches the source, the fix is typed, Ctrl+Enter
/// runs it, and the lab says "Passed".
#[test]
fn a_lab_by_the_keys_alone() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.run_steps(4);
    let lab = crate::app::lesson_of(&h)
        .steps
        .iter()
        .position(|s| s.title.en == crate::app::SPECULAR_LAB)
        .expect("the lab");
    while crate::app::step_of(&h) < lab {
        press(&mut h, Key::PageDown);
    }
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("Not yet: 162116 of 172800 pixels match")
            .is_some()
    );
    tab_to(&mut h, "Inspect the first wrong pixel");
    press(&mut h, Key::Enter);
    let (x, y) = pixel(&h).expect("Enter inspected the first wrong pixel");
    {
        let session = &h.state().session;
        let capture = session.capture.as_ref().expect("the student's frame");
        let reference = session.exercise.reference.as_ref().expect("the reference");
        let row = capture.grid().row(y);
        assert!(crate::labs::differs_at_image(
            capture,
            reference,
            (x, row),
            1.0
        ));
        assert!(
            (0..row).all(
                |r| (0..capture.width()).all(|c| !crate::labs::differs_at_image(
                    capture,
                    reference,
                    (c, r),
                    1.0
                ))
            ),
            "a row above ({x}, {y}) differs"
        );
    }
    press(&mut h, Key::Escape);
    press(&mut h, Key::V);
    press(&mut h, Key::ArrowUp);
    assert_eq!(pixel(&h), Some((x, y + 1)), "↑ in the student's frame");
    press(&mut h, Key::Escape);
    press(&mut h, Key::S);
    assert!(h.state().panels.shader, "S opens the shader panel");
    // Tab goes through every control to the source, none of them keeping it (a single-line
    // code field did: WCAG 2.1.2, no keyboard trap).
    let source = egui::accesskit::Role::MultilineTextInput;
    for _ in 0..300 {
        if h.get_by_role(source).is_focused() {
            break;
        }
        press(&mut h, Key::Tab);
    }
    assert!(h.get_by_role(source).is_focused(), "Tab reached the source");
    let solved = crate::labs::solved_source(&h.state().session, true);
    press_with(&mut h, Modifiers::COMMAND, Key::A);
    h.get_by_role(source).type_text(&solved);
    h.run_steps(3);
    press_with(&mut h, Modifiers::COMMAND, Key::Enter);
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("Passed: all 172800 pixels match")
            .is_some(),
        "the typed fix passes"
    );
}
