//! The shader debugger in the app: the inspected fragment's run drives the source — stepped
//! forward and back with the keys and the bar, over, into and out of a call, to the cursor's
//! line and to a breakpoint set by a click on its line number — with each line's value beside
//! it and the variables of the step.

use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use pipelens::app::command::SelectionCommand;
use pipelens::app::session::Command;

/// A fragment shader written for the test (the trace writes a float with three decimals): a helper function and a loop. Its run at any
/// fragment, worked by hand: `a = 0.25` (line 9; `0.0 * w_nrm.x` is 0 for a finite normal),
/// `half_of(a)` called (line 10), its parameter `x = 0.25` received (line 4), `h = 0.125` (line 5), its return (line 6), `b = 0.125`
/// (line 10), the loop (line 11) adding b twice, `a = 0.5`, and the colour `vec4(0.5, 0.125,
/// 0, 1)` (line 12).
const SOURCE: &str = "#version 330 core
in vec3 w_nrm;
out vec4 color;
float half_of(float x) {
    float h = x * 0.5;
    return h;
}
void main() {
    float a = 0.25 + 0.0 * w_nrm.x;
    float b = half_of(a);
    for (int i = 0; i < 2; i++) { a += b; }
    color = vec4(a, b, 0.0, 1.0);
}
";

/// The line of the step shown.
fn line(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> Option<usize> {
    let app = h.state();
    let at = app.shader_editor.debugger.at?;
    let capture = app.session.capture.as_ref()?;
    let run = &capture.shaders.as_ref()?.pixel.first()?.trace;
    Some(run[at].line)
}

fn press(h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>, m: Modifiers, key: Key) {
    h.key_press_modifiers(m, key);
    h.run_steps(2);
}

#[test]
fn the_debugger_steps_through_the_inspected_fragments_run() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    {
        let app = h.state_mut();
        app.shader_editor.fragment = SOURCE.to_owned();
        app.shader_editor.shaders_in_use = true;
        let applied = app
            .shader_editor
            .apply(&app.session)
            .expect("the test's shader compiles and links");
        app.session.apply(applied);
        // The middle of the 480 × 360 frame is on the sphere.
        app.session
            .apply(Command::Selection(SelectionCommand::SelectPixel(Some((
                240, 180,
            )))));
    }
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("steps: F10 steps through them")
            .is_some(),
        "the bar offers the run"
    );
    assert_eq!(line(&h), None, "not stepping before the first key");
    // F10 shows the first step; then over the call, whole.
    press(&mut h, Modifiers::NONE, Key::F10);
    assert_eq!(line(&h), Some(9));
    press(&mut h, Modifiers::NONE, Key::F10);
    assert_eq!(line(&h), Some(10), "the call");
    press(&mut h, Modifiers::NONE, Key::F10);
    assert_eq!(
        line(&h),
        Some(10),
        "over the call: b's assignment, same line"
    );
    assert!(
        h.query_by_label_contains("b = 0.125   (line 10)").is_some(),
        "b in the variables"
    );
    // One step back in time is half_of's return; out of it, b's assignment again.
    press(&mut h, Modifiers::SHIFT, Key::F10);
    assert_eq!(line(&h), Some(6), "back: half_of's return");
    assert!(h.query_by_label_contains("h = 0.125   (line 5)").is_some());
    press(&mut h, Modifiers::SHIFT, Key::F8);
    assert_eq!(line(&h), Some(10), "out: back in main");
    // Back to the call (return, h, the parameter x received on the function's line, call),
    // then into it.
    for expected in [6, 5, 4, 10] {
        press(&mut h, Modifiers::SHIFT, Key::F10);
        assert_eq!(line(&h), Some(expected));
    }
    press(&mut h, Modifiers::NONE, Key::F8);
    assert_eq!(line(&h), Some(4), "into half_of: x received");
    assert!(h.query_by_label_contains("x = 0.250   (line 4)").is_some());
    // The cursor on line 12: run to it; the variables show a as the loop left it.
    h.state_mut().shader_editor.debugger.cursor_line = Some(12);
    press(&mut h, Modifiers::COMMAND, Key::F10);
    assert_eq!(line(&h), Some(12));
    assert!(h.query_by_label_contains("a = 0.500   (line 11)").is_some());
    // A breakpoint by a click on line 11's number; Shift+F5 runs back to its last hit, F5
    // from the start to its first.
    let gutter = h.get_by_label_contains("  11\n").rect();
    // 14 numbers: the source's 13 lines and the empty one after its last newline.
    let row = gutter.height() / 14.0;
    let on_11 = egui::pos2(gutter.center().x, gutter.top() + 10.5 * row);
    h.drag_at(on_11);
    h.run_steps(1);
    h.drop_at(on_11);
    h.run_steps(2);
    assert_eq!(
        h.state()
            .shader_editor
            .debugger
            .breakpoints
            .values()
            .flatten()
            .map(|b| b.line)
            .collect::<Vec<_>>(),
        [11]
    );
    press(&mut h, Modifiers::SHIFT, Key::F5);
    assert_eq!(line(&h), Some(11), "back to the loop's last step");
    let last_hit = h.state().shader_editor.debugger.at;
    h.state_mut().shader_editor.debugger.at = None;
    press(&mut h, Modifiers::NONE, Key::F5);
    assert_eq!(line(&h), Some(11), "on to the loop's first step");
    assert!(h.state().shader_editor.debugger.at < last_hit);
    // Nothing before the first step: the bar says so.
    h.state_mut().shader_editor.debugger.at = Some(0);
    press(&mut h, Modifiers::SHIFT, Key::F10);
    assert_eq!(line(&h), Some(9));
    assert!(
        h.query_by_label_contains("This is the run's first step.")
            .is_some()
    );
}
