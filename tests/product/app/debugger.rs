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
fn drawing_the_tests_shader() -> egui_kittest::Harness<'static, pipelens::app::PipelensApp> {
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
fn inspecting_the_centre() -> egui_kittest::Harness<'static, pipelens::app::PipelensApp> {
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

#[test]
fn a_condition_over_the_frame_finds_its_first_fragment() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    crate::app::go_to_step_titled(&mut h, "The debugger: one fragment's run");
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    let field = || (egui::accesskit::Role::TextInput, "Watch over the frame:");
    h.get_by_role_and_label(field().0, field().1).focus();
    h.run_steps(2);
    h.get_by_role_and_label(field().0, field().1)
        .type_text("dot(n, l) < 0.0");
    h.state_mut().shader_editor.debugger.watch.line = 22;
    h.run_steps(2);
    h.get_by_label("Show").click();
    h.run_steps(6);
    assert_eq!(
        h.state().session.selection.watch,
        Some((22, "dot(n, l) < 0.0".to_owned())),
        "{:?} {:?}",
        h.state().shader_editor.debugger.watch.error,
        h.state().shader_editor.debugger.watch.expression
    );
    assert!(h.query_by_label_contains("true (").is_some(), "the legend");
    h.get_by_label("First where it holds ▶").click();
    h.run_steps(8);
    let app = h.state();
    let capture = app.session.capture.as_ref().expect("a frame");
    assert_eq!(capture.settings.capture.pixel, app.session.selection.pixel);
    let run = &capture.shaders.as_ref().expect("shaders").pixel[0].trace;
    let value = |name: &str| {
        run.iter()
            .rev()
            .find_map(|t| match &t.step {
                pipeline::shader::Step::Assign { name: n, value } if n == name => {
                    Some(value.numbers.clone())
                }
                _ => None,
            })
            .unwrap_or_else(|| panic!("{name} in the run"))
    };
    let (n, l) = (value("n"), value("l"));
    let n_dot_l: f64 = (0..3).map(|k| n[k] * l[k]).sum();
    assert!(
        n_dot_l < 0.0,
        "n·l = {n_dot_l} at {:?}",
        app.session.selection.pixel
    );
    assert_eq!(value("diffuse"), [0.0]);
    let at = app
        .shader_editor
        .debugger
        .at
        .expect("the debugger shows a step");
    assert_eq!(run[at].line, 22);
    assert!(
        h.query_by_label_contains("watch `dot(n, l) < 0.0` after line 22 = true")
            .is_some(),
        "the watch's value at the step"
    );
    // The same fragment as a breakpoint's condition on line 22: diffuse = max(n·l, 0) is 0
    // exactly where n·l ≤ 0, so the first fragment where `diffuse <= 0.0` is the same one.
    let first = app.session.selection.pixel;
    h.state_mut()
        .session
        .apply(Command::Selection(SelectionCommand::SelectPixel(Some((
            240, 180,
        )))));
    h.state_mut()
        .shader_editor
        .debugger
        .breakpoints
        .toggle(pipeline::shader::Stage::Fragment, 22);
    h.run_steps(6);
    let field = || (egui::accesskit::Role::TextInput, "where");
    h.get_by_role_and_label(field().0, field().1).focus();
    h.run_steps(2);
    h.get_by_role_and_label(field().0, field().1)
        .type_text("diffuse <= 0.0");
    h.run_steps(2);
    h.get_by_label("Find in the frame").click();
    h.run_steps(10);
    assert_eq!(h.state().session.selection.pixel, first);
    let app = h.state();
    let capture = app.session.capture.as_ref().expect("a frame");
    let run = &capture.shaders.as_ref().expect("shaders").pixel[0].trace;
    let at = app.shader_editor.debugger.at.expect("a step");
    assert_eq!(run[at].line, 22);
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

/// A watch that the code, edited under it, no longer compiles is dropped with the reason; the
/// next watch asked for clears the reason.
#[test]
fn a_watch_the_edited_code_no_longer_compiles_is_dropped_with_why() {
    let mut h = drawing_the_tests_shader();
    let watch = |w: Option<(usize, &str)>| {
        Command::Selection(SelectionCommand::SetWatch(
            w.map(|(l, e)| (l, e.to_owned())),
        ))
    };
    // Line 12 of the test's shader writes the colour from a and b.
    h.state_mut().session.apply(watch(Some((12, "a"))));
    h.run_steps(4);
    assert!(h.state().session.selection.watch.is_some());
    // pipelens' own Blinn-Phong has a declaration on line 12, outside any function.
    {
        let app = h.state_mut();
        app.shader_editor.fragment = pipeline::shader::BUILTIN_FRAGMENT.to_owned();
        let applied = app.shader_editor.apply(&app.session).expect("compiles");
        app.session.apply(applied);
    }
    h.run_steps(4);
    let s = &h.state().session;
    assert_eq!(s.selection.watch, None);
    assert!(
        s.watch_error
            .as_deref()
            .is_some_and(|e| e.contains("line 12 does not end a statement")),
        "{:?}",
        s.watch_error
    );
    h.state_mut().session.apply(watch(Some((29, "n"))));
    h.run_steps(4);
    assert_eq!(h.state().session.watch_error, None);
}

/// The cost view: ticked, the frame is drawn again keeping each pixel's steps, and at the
/// inspected pixel the picture says as many steps as that fragment's run lists (the test's
/// shader runs the same steps everywhere but for its loop, which runs twice at every pixel).
#[test]
fn the_cost_view_shows_each_pixels_steps() {
    let mut h = inspecting_the_centre();
    h.get_by_label("Cost: the steps each fragment ran").click();
    h.run_steps(8);
    let app = h.state();
    assert!(app.session.selection.cost);
    let record = app
        .session
        .capture
        .as_ref()
        .expect("a frame")
        .shaders
        .as_ref()
        .expect("shaders");
    let cost = record.cost.as_ref().expect("the frame kept the cost view");
    let steps = cost.at(240, 180).expect("the sphere is there")[0];
    assert_eq!(steps as usize, record.pixel[0].trace.len());
    // The same number everywhere on the sphere: the run does not depend on the pixel.
    assert_eq!(cost.at(250, 170).map(|v| v[0]), Some(steps));
}

/// The textures the last frame painted, by name (egui's texture manager names each), the
/// fonts' left out.
fn painted_textures(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> Vec<String> {
    let manager = h.ctx.tex_manager();
    let manager = manager.read();
    h.output()
        .shapes
        .iter()
        .filter_map(|c| match &c.shape {
            egui::Shape::Mesh(m) => Some(m.texture_id),
            egui::Shape::Rect(r) => r.fill_texture_id().into(),
            _ => None,
        })
        .filter_map(|id| manager.meta(id).map(|m| m.name.clone()))
        .filter(|name| name != "egui_font_texture")
        .collect()
}

/// Lesson 24's variable-picture step (`watch = "dot(n, l) < 0.0@22"`) draws the watch in the
/// view itself, the frame's size, in place of the colour buffer; unticking "variable picture"
/// brings the colour back.
#[test]
fn the_variable_picture_is_the_views_picture() {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().session.apply(Command::Lesson(
        pipelens::app::session::LessonCommand::GoToStep(7),
    ));
    for _ in 0..40 {
        h.run_steps(2);
        let drawn = h.state().session.capture.as_ref().is_some_and(|c| {
            c.shaders
                .as_ref()
                .is_some_and(|r| r.watch.as_ref().is_some_and(|w| w.kind.is_some()))
        });
        if drawn {
            break;
        }
    }
    h.run_steps(2);
    let painted = painted_textures(&h);
    assert!(
        painted.iter().any(|n| n == "pixel-view-watch"),
        "the view paints {painted:?}"
    );
    assert!(!painted.iter().any(|n| n == "pixel-view"), "{painted:?}");
    h.get_by_label("variable picture").click();
    h.run_steps(4);
    let painted = painted_textures(&h);
    assert!(
        painted
            .iter()
            .any(|n| n == "pixel-view" || n == "pixel-view-fine"),
        "the view paints {painted:?}"
    );
    assert!(
        !painted.iter().any(|n| n == "pixel-view-watch"),
        "{painted:?}"
    );
}
