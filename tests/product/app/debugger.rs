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

/// The inspected pixel's first fragment in the frame on screen.
pub(super) fn first_fragment<'h>(
    h: &'h egui_kittest::Harness<'_, pipelens::app::PipelensApp>,
) -> &'h pipeline::capture::FragmentTrace {
    &h.state()
        .session
        .capture
        .as_ref()
        .expect("a frame")
        .shaders
        .as_ref()
        .expect("shaders")
        .pixel[0]
}

fn press(h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>, m: Modifiers, key: Key) {
    h.key_press_modifiers(m, key);
    h.run_steps(2);
}

/// Lesson 24 at 1920 × 1080 with the shader panel open, drawing with [`SOURCE`] applied as the
/// panel applies it.
pub(super) fn drawing_the_tests_shader()
-> egui_kittest::Harness<'static, pipelens::app::PipelensApp> {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    let app = h.state_mut();
    app.shader_editor.fragment = SOURCE.to_owned();
    app.shader_editor.shaders_in_use = true;
    let applied = app
        .shader_editor
        .apply(&app.session)
        .expect("the test's shader compiles and links");
    app.session.apply(applied);
    h.run_steps(4);
    h
}

/// [`drawing_the_tests_shader`] with the frame's middle pixel inspected (the middle of the
/// 480 × 360 frame is on the sphere).
pub(super) fn inspecting_the_centre() -> egui_kittest::Harness<'static, pipelens::app::PipelensApp>
{
    let mut h = drawing_the_tests_shader();
    h.state_mut()
        .session
        .apply(Command::Selection(SelectionCommand::SelectPixel(Some((
            240, 180,
        )))));
    h.run_steps(6);
    h
}

#[test]
fn the_debugger_steps_through_the_inspected_fragments_run() {
    let mut h = inspecting_the_centre();
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
    press(&mut h, Modifiers::SHIFT, Key::F7);
    assert_eq!(line(&h), Some(10), "out: back in main");
    // Back to the call (return, h, the parameter x received on the function's line, call),
    // then into it.
    for expected in [6, 5, 4, 10] {
        press(&mut h, Modifiers::SHIFT, Key::F10);
        assert_eq!(line(&h), Some(expected));
    }
    press(&mut h, Modifiers::NONE, Key::F7);
    assert_eq!(line(&h), Some(4), "into half_of: x received");
    assert!(h.query_by_label_contains("x = 0.250   (line 4)").is_some());
    // The cursor on line 12: run to it; the variables show a as the loop left it.
    h.state_mut().shader_editor.debugger.cursor_line = Some(12);
    press(&mut h, Modifiers::COMMAND, Key::F10);
    assert_eq!(line(&h), Some(12));
    assert!(h.query_by_label_contains("a = 0.500   (line 11)").is_some());
    // A breakpoint by a click on line 11's number; Shift+F8 runs back to its last hit, F8
    // from the start to its first.
    // 14 numbers: the source's 13 lines and the empty one after its last newline (the gutter
    // is named by how many, for a screen reader).
    let gutter = h.get_by_label_contains("Line numbers 1 to 14 ").rect();
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
            .by_stage
            .values()
            .flatten()
            .map(|b| b.line)
            .collect::<Vec<_>>(),
        [11]
    );
    press(&mut h, Modifiers::SHIFT, Key::F8);
    assert_eq!(line(&h), Some(11), "back to the loop's last step");
    let last_hit = h.state().shader_editor.debugger.at;
    h.state_mut().shader_editor.debugger.at = None;
    press(&mut h, Modifiers::NONE, Key::F8);
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

/// The variable picture of a condition, typed into the watch row, finds the first fragment
/// where it holds: lesson 24's debugger step, `dot(n, l) < 0.0` after line 22 (where
/// `diffuse = max(dot(n, l), 0.0)`). The pixel it inspects has, by its own run's values of n
/// and l (the trace, not the watch), n·l < 0, and the debugger shows that run at line 22 with
/// diffuse 0.
/// The watch list reads each expression just after the step's line in the run shown, worked by
/// hand from [`SOURCE`]'s run: after line 9 `a = 0.25`, so `a * 2.0` is 0.5; on line 11's first
/// step the loop has not finished (the watch follows the whole `for` statement, its line's last
/// `}`); after line 12 `a = 0.5`, so `a * 2.0` is 1 and `color` is `(0.5, 0.125, 0, 1)`, a colour;
/// `h` lives in `half_of`, not at line 9, and says so.
#[test]
fn the_watch_list_reads_each_expression_at_the_step() {
    let mut h = inspecting_the_centre();
    let field = || (egui::accesskit::Role::TextInput, "Add:");
    for expression in ["a * 2.0", "color", "h"] {
        h.get_by_role_and_label(field().0, field().1).focus();
        h.run_steps(1);
        h.get_by_role_and_label(field().0, field().1)
            .type_text(expression);
        h.run_steps(1);
        h.key_press(Key::Enter);
        h.run_steps(2);
    }
    assert_eq!(
        h.state().shader_editor.debugger.list.entries,
        ["a * 2.0", "color", "h"]
    );
    // The run's first step, line 9 (set directly: the field keeps the keyboard).
    h.state_mut().shader_editor.debugger.at = Some(0);
    h.run_steps(3);
    assert_eq!(line(&h), Some(9));
    assert!(
        h.query_by_label_contains("a * 2.0 = 0.500").is_some(),
        "a = 0.25 after line 9"
    );
    assert!(
        h.query_by_label_contains("not readable after line 9")
            .is_some(),
        "h is not in scope at line 9"
    );
    // Line 11's first step: the loop has not run to its end yet.
    let first_on_11 = {
        let run = &first_fragment(&h).trace;
        run.iter().position(|t| t.line == 11).expect("line 11 runs")
    };
    h.state_mut().shader_editor.debugger.at = Some(first_on_11);
    h.run_steps(3);
    assert!(
        h.query_by_label_contains("a * 2.0: up to this step, the run has not run this line")
            .is_some()
    );
    h.state_mut().shader_editor.debugger.cursor_line = Some(12);
    press(&mut h, Modifiers::COMMAND, Key::F10);
    assert_eq!(line(&h), Some(12));
    assert!(h.query_by_label_contains("a * 2.0 = 1.000").is_some());
    assert!(
        h.query_by_label_contains("color = vec4(0.500, 0.125, 0, 1.000)")
            .is_some()
    );
    // Taken off the list.
    h.get_all_by_label("×")
        .next()
        .expect("a remove button")
        .click();
    h.run_steps(2);
    assert_eq!(
        h.state().shader_editor.debugger.list.entries,
        ["color", "h"]
    );
}

/// "pipelens' own" replaces the student's code with the settings' shading as GLSL, and keeps
/// theirs one click away: "Back to your code" puts it back and draws with it again.
#[test]
fn pipelens_own_keeps_the_students_code_one_click_away() {
    let mut h = drawing_the_tests_shader();
    assert!(h.query_by_label("← Back to your code").is_none());
    h.get_by_label("pipelens' own").click();
    h.run_steps(4);
    assert_ne!(h.state().shader_editor.fragment, SOURCE);
    h.get_by_label("← Back to your code").click();
    h.run_steps(4);
    let app = h.state();
    assert_eq!(app.shader_editor.fragment, SOURCE);
    let drawn = app
        .session
        .spec
        .scene
        .objects
        .iter()
        .find_map(|o| o.code.shader.as_ref())
        .expect("shaders");
    assert_eq!(
        drawn.programs.fragment.source, SOURCE,
        "drawn with it again"
    );
}

/// A click on the picture of a pixel stage inspects that pixel and picks no vertex (whose label
/// would stand beside the pixel's lighting vectors): lesson 24's debugger step, its picture's
/// middle clicked.
#[test]
fn a_pixel_click_picks_the_pixel_only_and_opens_the_inspector() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    crate::app::go_to_step_titled(&mut h, "Edit: add a rim");
    h.state_mut().panels.inspector = false;
    h.run_steps(4);
    let before = h.state().session.selection.pixel;
    let picture = *h.state().picture.first().expect("a picture");
    let at = picture.center() + egui::vec2(-40.0, 30.0);
    h.drag_at(at);
    h.run_steps(1);
    h.drop_at(at);
    h.run_steps(3);
    let sel = &h.state().session.selection;
    assert!(
        sel.pixel.is_some() && sel.pixel != before,
        "{:?}",
        sel.pixel
    );
    assert_eq!(sel.vertex, None);
    assert!(
        h.state().panels.inspector,
        "the pixel's derivation is read there"
    );
}

/// The toon step asks the student to read a band in the inspector and is about the lines that
/// make the bands: entering it opens the inspector and the shader panel on the fragment shader,
/// its lines 16–18 (d, the band, the colour — counted in the lesson's source) marked.
#[test]
fn a_step_opens_the_panels_it_speaks_of_on_its_lines() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    assert!(!h.state().panels.inspector && !h.state().panels.shader);
    crate::app::go_to_step_titled(&mut h, "Edit: toon bands");
    h.run_steps(12);
    let app = h.state();
    assert!(app.panels.inspector && app.panels.shader);
    assert_eq!(
        app.shader_editor.tab,
        pipelens::app::views::shader::Tab::Shader(pipeline::shader::Stage::Fragment)
    );
    assert_eq!(
        app.shader_editor.debugger.lines,
        Some(((16, 18), 0)),
        "marked, and scrolled to over the step's first frames only"
    );
    let lines: Vec<&str> = app.shader_editor.fragment.lines().collect();
    assert!(lines[15].contains("float d = max(dot(n, l), 0.0);"));
    assert!(lines[16].contains("float band = floor(d * bands) / bands;"));
    assert!(lines[17].contains("vec3 c = v_color * (0.2 + 0.8 * band);"));
}
