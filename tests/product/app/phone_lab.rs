//! A lab on a phone, done by touch as a student does it (issue 60): at 390×844 the Code tab
//! puts the code over the screen with the verdict above it, a drag scrolls the code, the first
//! tap puts the cursor where it lands, the row of GLSL keys types without taking the keyboard
//! away, the messages never move the code, and the lab passes; the Picture tab brings the
//! picture back.

use super::{finger, tap};
use egui::{Event, Key, Modifiers, Pos2, Rect};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use pipelens::app::PipelensApp;

const SCREEN: [f32; 2] = [390.0, 844.0];

/// The rect of the widget named `label`.
fn rect_of(h: &Harness<'_, PipelensApp>, label: &str) -> Rect {
    h.get_by_label(label).rect()
}

/// The rect of the source's row whose text holds `text`.
fn row_of(h: &Harness<'_, PipelensApp>, text: &str) -> Rect {
    h.get_by(|n| {
        n.role() == egui::accesskit::Role::TextRun && n.value().is_some_and(|v| v.contains(text))
    })
    .rect()
}

/// A key of the phone's keyboard pressed and let go (Enter, Backspace), and a frame run.
fn press(h: &mut Harness<'_, PipelensApp>, key: Key) {
    for pressed in [true, false] {
        h.input_mut().events.push(Event::Key {
            key,
            physical_key: None,
            pressed,
            repeat: false,
            modifiers: Modifiers::NONE,
        });
    }
    h.run_steps(1);
}

/// Types `text` as a phone's keyboard and the key row do: each of the row's keys tapped on the
/// row, a line break with Enter, the rest as the keyboard's text.
fn type_text(h: &mut Harness<'_, PipelensApp>, text: &str) {
    let mut plain = String::new();
    let flush = |h: &mut Harness<'_, PipelensApp>, plain: &mut String| {
        if !plain.is_empty() {
            h.input_mut()
                .events
                .push(Event::Text(std::mem::take(plain)));
            h.run_steps(1);
        }
    };
    for c in text.chars() {
        let key = c.to_string();
        if pipelens::app::views::GLSL_KEYS.contains(&key.as_str()) {
            flush(h, &mut plain);
            let at = rect_of(h, &key).center();
            tap(h, at);
        } else if c == '\n' {
            flush(h, &mut plain);
            press(h, Key::Enter);
        } else {
            plain.push(c);
        }
    }
    flush(h, &mut plain);
}

/// Drags the code until the line holding `todo` is in sight between `top` and `bottom` (the
/// source's top and the key row's), then sideways until its end is, and taps just past its end:
/// as a student puts the cursor there.
fn tap_at_the_end_of(h: &mut Harness<'_, PipelensApp>, todo: &str, (top, bottom): (f32, f32)) {
    let row = into_sight(h, todo, (top, bottom));
    // The first tap, just past the end of the TODO's line: the cursor goes to that line's end.
    tap(h, Pos2::new(row.right() + 12.0, row.center().y));
}

/// Drags the code until the line holding `todo` is in sight between `top` and `bottom`, then
/// sideways until its end is: the line's rect.
fn into_sight(h: &mut Harness<'_, PipelensApp>, todo: &str, (top, bottom): (f32, f32)) -> Rect {
    // Drag the code up until the TODO's line is in sight above the key row.
    for _ in 0..12 {
        let row = row_of(h, todo);
        if row.top() > top + 40.0 && row.bottom() < bottom - 40.0 {
            break;
        }
        finger(h, Pos2::new(200.0, 600.0), Pos2::new(200.0, 400.0));
    }
    let row = row_of(h, todo);
    assert!(
        row.top() > top && row.bottom() < bottom,
        "the drag scrolled the TODO into sight: {row:?}"
    );
    assert_eq!(
        h.state().shader_editor.debugger.cursor_line,
        None,
        "a drag scrolls the code: it puts no cursor in it"
    );
    // The line runs past the screen's edge: a drag to the left brings its end in sight.
    let past = row.right() + 40.0 - SCREEN[0];
    if past > 0.0 {
        let y = row.center().y;
        finger(h, Pos2::new(300.0, y), Pos2::new(300.0 - past, y));
        h.run_steps(3);
    }
    let row = row_of(h, todo);
    assert!(
        row.right() + 20.0 < SCREEN[0],
        "a drag sideways scrolled the line's end into sight: {row:?}"
    );
    row
}

/// Lesson 10's specular lab on a 390×844 phone, by touch alone: the student opens the Code tab
/// (the verdict above the code says "Not yet"), drags the code up to the TODO, taps at the end
/// of its line (the cursor goes there, not to the end of the file), and types the specular
/// term with the keyboard and the row of GLSL keys. While the half-typed code does not
/// compile the code stays where it was (the message has a fixed place); the finished code
/// passes, the verdict above the code says so, and the Picture tab shows the picture again
/// with the code kept.
#[test]
fn lesson_10_s_lab_is_solved_on_a_phone_by_touch() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = super::sized_lesson_harness(&path, SCREEN);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    super::go_to_step_titled(&mut h, super::SPECULAR_LAB);
    h.run_steps(8);
    let screen = Rect::from_min_size(Pos2::ZERO, SCREEN.into());
    assert!(!h.state().panels.shader, "the step opens on the picture");

    let code_tab = rect_of(&h, "Code");
    assert!(code_tab.height() >= 44.0, "a finger's tab: {code_tab:?}");
    tap(&mut h, code_tab.center());
    h.run_steps(4);
    assert!(h.state().panels.shader, "one tap opens the code");
    let verdict = h.get_by_label_contains("Not yet:").rect();
    let source = rect_of(&h, "Fragment shader: source");
    assert!(
        screen.contains_rect(verdict) && verdict.bottom() <= source.top(),
        "the verdict is in sight above the code: {verdict:?}, code {source:?}"
    );
    let keys = rect_of(&h, ";");
    assert!(
        keys.bottom() <= SCREEN[1] && keys.width() >= 44.0 && keys.height() >= 44.0,
        "the key row is on the screen with a finger's keys: {keys:?}"
    );

    let todo = "TODO: the specular term";
    tap_at_the_end_of(&mut h, todo, (source.top(), keys.top()));
    h.run_steps(2);
    let line = h
        .state()
        .shader_editor
        .fragment
        .lines()
        .position(|l| l.contains(todo))
        .expect("the TODO's line")
        + 1;
    assert_eq!(
        h.state().shader_editor.debugger.cursor_line,
        Some(line),
        "the first tap puts the cursor on the line tapped"
    );
    let source_top = rect_of(&h, "Fragment shader: source").top();

    // Half a line: it does not compile, and the code has not moved.
    type_text(&mut h, "\n        vec3 h = normalize(l + v");
    h.run_steps(4);
    assert!(
        !h.state().shader_editor.compiles(),
        "half a line does not compile"
    );
    assert!(h.query_by_label("Code (!)").is_some(), "the tab says so");
    assert_eq!(
        rect_of(&h, "Fragment shader: source").top(),
        source_top,
        "the message does not move the code"
    );
    type_text(
        &mut h,
        ");\n        if (n_dot_l > 0.0) {\n            sum += f * ks * light.intensity * \
         pow(max(dot(n, h), 0.0), shininess);\n        }",
    );
    for _ in 0..40 {
        h.run_steps(5);
        if h.query_by_label_contains("Passed:").is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let fragment = &h.state().shader_editor.fragment;
    assert!(
        fragment.contains(&format!(
            "{todo}, where n·l > 0.\n        vec3 h = normalize(l + v);\n        if (n_dot_l"
        )),
        "typed after the TODO, at the cursor:\n{fragment}"
    );
    let passed = h
        .get_by_label_contains("Passed: all 172800 pixels match")
        .rect();
    assert!(
        screen.contains_rect(passed),
        "the verdict is in sight: {passed:?}"
    );

    // Back to the picture: one tap; the student's frame, pipelens' own and the difference.
    let picture_tab = rect_of(&h, "Picture").center();
    tap(&mut h, picture_tab);
    h.run_steps(6);
    assert!(!h.state().panels.shader);
    assert!(
        h.state().picture_share(screen) > 0.3,
        "the picture is back: {}",
        h.state().picture_share(screen)
    );
    assert!(
        h.state()
            .shader_editor
            .fragment
            .contains("if (n_dot_l > 0.0)")
    );
}

/// The frame's highlight: its pixels whose blue is over 140 of 255, more than the ambient and
/// diffuse terms can give the sphere's blue (c = 0.25: 0.25·(0.2·0.2 + 0.8·1) = 0.21 of the
/// white light, 54 of 255, or 127 sRGB-encoded): only the specular term reaches it.
fn highlight(h: &Harness<'_, PipelensApp>) -> usize {
    let capture = h.state().session.capture.as_ref().expect("a frame");
    capture
        .image(pipeline::buffers::BufferKind::Color)
        .pixels()
        .filter(|p| p.0[2] > 140)
        .count()
}

/// Runs frames until the one on screen is of the code as it is now.
fn settle(h: &mut Harness<'_, PipelensApp>) {
    for _ in 0..40 {
        h.run_steps(5);
        if !h.state().session.rendering() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    h.run_steps(4);
}

/// Lesson 24's first edit on a 390×844 phone, by touch: the step runs GLSL, so the Code tab is
/// there; the student drags the code until `float p = 8.0;` is in sight, taps between the `8`
/// and the `.`, deletes the `8` and types `200` (the narration's "Try 200 in the panel"), and
/// the Picture tab shows the highlight shrunk: the area where max(n·h, 0)^p stays above a
/// level is a cap of angular radius θ with cos θ = level^(1/p), 1 − cos θ ≈ −ln(level)/p, so
/// its area falls as 1/p: from p = 8 to p = 200 to about 1/25 (asserted: under 1/4).
#[test]
fn lesson_24_s_exponent_is_edited_on_a_phone_by_touch() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = super::sized_lesson_harness(&path, SCREEN);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    super::go_to_step_titled(&mut h, "Edit: change the exponent");
    settle(&mut h);
    let before = highlight(&h);
    assert!(before > 200, "p = 8: a wide highlight ({before} pixels)");

    let code_tab = rect_of(&h, "Code").center();
    tap(&mut h, code_tab);
    h.run_steps(4);
    assert!(h.state().panels.shader, "one tap opens the code");
    let source = rect_of(&h, "Fragment shader: source");
    let keys = rect_of(&h, ";");
    let line = "float p = 8.0;";
    let row = into_sight(&mut h, line, (source.top(), keys.top()));
    // The row is the line's text in a monospace font: the gap after the `8` is found by its
    // characters.
    let text = h
        .get_by(|n| {
            n.role() == egui::accesskit::Role::TextRun
                && n.value().is_some_and(|v| v.contains(line))
        })
        .value()
        .unwrap_or_default();
    let chars = text.chars().count() as f32;
    let eight = text[..text.find("8.0").expect("the 8")].chars().count() as f32 + 1.0;
    tap(
        &mut h,
        Pos2::new(row.left() + row.width() * eight / chars, row.center().y),
    );
    press(&mut h, Key::Backspace);
    type_text(&mut h, "200");
    assert!(
        h.state()
            .shader_editor
            .fragment
            .contains("float p = 200.0;"),
        "the 8 became 200 where it was tapped:\n{}",
        h.state().shader_editor.fragment
    );
    settle(&mut h);
    let picture_tab = rect_of(&h, "Picture").center();
    tap(&mut h, picture_tab);
    settle(&mut h);
    assert!(!h.state().panels.shader, "the picture is back");
    let after = highlight(&h);
    assert!(
        after * 4 < before,
        "p = 200's highlight is a fraction of p = 8's: {after} pixels against {before}"
    );
}
