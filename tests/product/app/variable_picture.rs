//! The variable picture in the app: an expression of either shader over the whole frame — a
//! condition's first fragment found across it, the vertex shader's value carried to the pixels,
//! a watch dropped when the code under it no longer compiles — and the cost view, each drawn
//! by the view in place of the buffer.

use egui_kittest::kittest::Queryable;
use pipelens::app::command::SelectionCommand;
use pipelens::app::session::Command;
use pipelens::app::views::shader::Tab;
use pipeline::shader::Stage;

use super::debugger::{drawing_the_tests_shader, inspecting_the_centre};

/// Lesson 24's debugger step at 1920×1080 with the shader panel open on `stage`'s tab, where
/// `expression` was typed into the watch row, after `line`, and shown.
fn watching_on_the_debugger_step(
    stage: Stage,
    expression: &str,
    line: usize,
) -> egui_kittest::Harness<'static, pipelens::app::PipelensApp> {
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    crate::app::go_to_step_titled(&mut h, "The debugger: one fragment's run");
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    // The panel opens on the fragment shader, the one the lesson's student wrote.
    h.state_mut().shader_editor.tab = Tab::Shader(stage);
    h.run_steps(2);
    let field = || (egui::accesskit::Role::TextInput, "Watch over the frame:");
    h.get_by_role_and_label(field().0, field().1).focus();
    h.run_steps(2);
    h.get_by_role_and_label(field().0, field().1)
        .type_text(expression);
    let debugger = &mut h.state_mut().shader_editor.debugger;
    match stage {
        Stage::Vertex => debugger.vertex_watch.line = line,
        Stage::Fragment => debugger.watch.line = line,
    }
    h.run_steps(2);
    h.get_by_label("Show").click();
    h.run_steps(6);
    h
}

/// A condition watched over the frame is a mask with its legend, and "First where it holds"
/// inspects the first pixel from the top where it does, its run shown at the watched line.
#[test]
fn a_condition_over_the_frame_finds_its_first_fragment() {
    let mut h = watching_on_the_debugger_step(Stage::Fragment, "dot(n, l) < 0.0", 22);
    assert_eq!(
        h.state().session.selection.watch,
        Some(pipeline::shader::probe::WatchSpec::fragment(
            22,
            "dot(n, l) < 0.0"
        )),
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

/// On the vertex shader's tab the row watches the vertex shader: the frame's picture is the
/// vertex's value carried to each pixel as a varying, and its legend says so. Line 29 of
/// pipelens' vertex shader writes the unit world normal: its y is positive where the sphere
/// faces up (its top in the picture) and negative at its bottom.
#[test]
fn the_vertex_tab_watches_the_vertex_shader_over_the_frame() {
    let mut h = watching_on_the_debugger_step(Stage::Vertex, "w_nrm.y", 29);
    assert_eq!(
        h.state().session.selection.watch,
        Some(pipeline::shader::probe::WatchSpec::vertex(29, "w_nrm.y")),
        "{:?}",
        h.state().shader_editor.debugger.vertex_watch.error,
    );
    let picture = h
        .state()
        .session
        .capture
        .as_ref()
        .and_then(|c| c.shaders.as_ref())
        .and_then(|r| r.watch.clone())
        .expect("the frame keeps the watch");
    assert!(picture.from_vertex);
    assert_eq!(
        picture.kind,
        Some(pipeline::shader::probe::WatchKind::Float)
    );
    let x = picture.width / 2;
    let rows: Vec<u32> = (0..picture.height())
        .filter(|&y| picture.at(x, y).is_some())
        .collect();
    let (bottom, top) = (rows[0] + 2, rows[rows.len() - 1] - 2);
    assert!(picture.at(x, top).is_some_and(|v| v[0] > 0.8), "top");
    assert!(picture.at(x, bottom).is_some_and(|v| v[0] < -0.8), "bottom");
    assert!(
        h.query_by_label_contains("after line 29 of the vertex shader, interpolated")
            .is_some()
    );
    // The fragment shader's tab has its own row, which does not show the vertex's watch.
    h.state_mut().shader_editor.tab = Tab::Shader(Stage::Fragment);
    h.run_steps(3);
    assert!(h.state().shader_editor.debugger.watch.expression.is_empty());
}

/// A watch that the code, edited under it, no longer compiles is dropped with the reason; the
/// next watch asked for clears the reason.
#[test]
fn a_watch_the_edited_code_no_longer_compiles_is_dropped_with_why() {
    let mut h = drawing_the_tests_shader();
    let watch = |w: Option<(usize, &str)>| {
        Command::Selection(SelectionCommand::SetWatch(
            w.map(|(l, e)| pipeline::shader::probe::WatchSpec::fragment(l, e)),
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
