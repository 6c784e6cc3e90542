//! The app, driven headless through its accessibility tree (egui_kittest): no display, no GPU.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::session::Session;
use pipelens::app::{PipelensApp, setup_context};
use pipelens::vocabulary::{Lang, Stage};

mod accessible;
mod classroom;
mod contrast;
mod debugger;
mod export;
mod framing;
mod keyboard_alone;
mod keys;
mod labs;
mod lesson_play;
mod library;
mod new_lesson;
mod own_uniforms;
mod panels;
mod params;
mod phone;
mod phone_lab;
mod pseudo_locale;
mod recording;
mod steps;
mod targets;
mod variable_picture;

/// The app on the built-in scene, rendering synchronously so that tests are deterministic.
fn harness() -> Harness<'static, PipelensApp> {
    let spec = pipelens::lesson::default_scene().expect("the built-in scene is valid");
    let session = Session::new(spec, "test", None);
    Harness::builder()
        .with_size([1366.0, 768.0])
        .with_context_setup(setup_context)
        // Moving to the next stage animates for 1.5 s of frames.
        .with_max_steps(200)
        .build_ui_state(
            |ui, app: &mut PipelensApp| app.frame(ui),
            PipelensApp::new(session),
        )
}

#[test]
fn clicking_every_stage_shows_it() {
    let mut h = harness();
    h.run();
    for stage in Stage::ALL {
        h.get_by_label(stage.name(Lang::EN)).click();
        h.run();
        assert_eq!(h.state().session.selection.stage, stage);
    }
}

#[test]
fn arrow_keys_step_through_the_stages() {
    let mut h = harness();
    h.run();
    assert_eq!(h.state().session.selection.stage, Stage::World);
    h.key_press(egui::Key::ArrowRight);
    h.run();
    assert_eq!(h.state().session.selection.stage, Stage::View);
    h.key_press(egui::Key::ArrowLeft);
    h.key_press(egui::Key::ArrowLeft);
    h.run();
    assert_eq!(h.state().session.selection.stage, Stage::Model);
}

#[test]
fn switching_the_language_shows_chinese_labels() {
    let mut h = harness();
    h.run();
    h.get_by_label("中文").click();
    h.run();
    assert_eq!(h.state().session.lang, Lang::ZH);
    // Rendering these labels panics if no installed font has the glyphs: the embedded font works.
    h.get_by_label("光栅化").click();
    h.run();
    assert_eq!(h.state().session.selection.stage, Stage::Raster);
    assert!(h.query_all_by_label("参数").count() >= 1);
    h.get_by_label("English").click();
    h.run();
    assert!(h.query_all_by_label("Parameters").count() >= 1);
}

#[test]
fn clicking_a_pixel_lists_its_fragments() {
    let mut h = harness();
    h.run();
    h.get_by_label("Output").click();
    h.run();
    h.get_by_label("Pixel").click();
    h.run();
    // Just below the middle of the pixel view is on the image (fitted and centred in it), where
    // the floor covers the lower half.
    let r = h.get_by_label_contains("pixel view: ").rect();
    let p = egui::pos2(r.center().x, r.center().y + 30.0);
    h.hover_at(p);
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    let (x, y) = h
        .state()
        .session
        .selection
        .pixel
        .expect("a pixel is selected");
    let capture = h.state().session.capture.clone().expect("a capture");
    assert_eq!(
        capture.settings.capture,
        pipeline::buffers::Capture::FULL,
        "an inspected pixel shows every term"
    );
    let fragments = capture.fragments_at(x, y);
    assert!(!fragments.is_empty(), "the floor reaches pixel ({x}, {y})");
    let first = format!("fragment 1 · floor · triangle {}", fragments[0].primitive);
    assert!(
        h.query_by_label_contains(&first).is_some(),
        "the inspector lists {first}"
    );
    // And derives the colour, step by step, with the edge functions among the steps.
    assert!(h.query_by_label("Explain this pixel").is_some());
    assert!(
        h.query_by_label_contains("Inside test: edge functions")
            .is_some()
    );
}

#[test]
fn the_capture_keeps_what_the_view_shows() {
    use pipeline::buffers::BufferKind;
    use pipeline::buffers::Capture;
    let mut h = harness();
    h.run();
    let kept = |h: &Harness<'static, PipelensApp>| {
        let c = h.state().session.capture.clone().expect("a capture");
        (c.settings.capture, c.pixels.shading.is_some())
    };
    // The final image: the colour only; the lighting buffers are still offered.
    h.get_by_label("Output").click();
    h.run();
    assert_eq!(kept(&h), (Capture::COLOR, false));
    assert!(h.state().session.buffers.contains(&BufferKind::NDotL));
    // Showing a lighting term renders again, keeping the lighting buffers.
    h.get_by_label("Shading").click();
    h.run();
    assert_eq!(h.state().session.selection.buffer, BufferKind::Diffuse);
    let (capture, shaded) = kept(&h);
    assert!(capture.lighting && shaded, "{capture:?}");
}

#[test]
fn selecting_a_vertex_row_highlights_it() {
    let mut h = harness();
    h.run();
    h.get_by_label("Vertices").click();
    h.run();
    h.get_by_label("v3").click();
    h.run();
    assert_eq!(h.state().session.selection.vertex, Some(3));
    h.get_by_label("v3").click();
    h.run();
    assert_eq!(
        h.state().session.selection.vertex,
        None,
        "a second click clears it"
    );
}

#[test]
fn changing_a_parameter_renders_again() {
    let mut h = harness();
    h.run();
    let before = h.state().session.shown_generation;
    h.get_by_label("16").click();
    h.run();
    let s = &h.state().session;
    assert!(s.shown_generation > before);
    assert_eq!(
        s.capture.as_ref().map(|c| c.settings.samples.count()),
        Some(16)
    );
}

#[test]
fn comparing_shading_frequencies_side_by_side_with_a_profile() {
    let mut h = harness();
    h.run();
    h.get_by_label("Shading").click();
    h.run();
    h.get_by_label("side by side").click();
    h.run();
    h.get_by_label("flat | Gouraud | Phong").click();
    h.run();
    let labels: Vec<String> = h
        .state()
        .session
        .variants
        .iter()
        .map(|(l, _)| l.clone())
        .collect();
    assert_eq!(labels, ["flat", "Gouraud", "Phong"]);
    // A click is no line: the profile stays (a zero-length one would plot an empty chart).
    let first = h.get_by_label("compared image: flat").rect();
    let before = h.state().session.selection.profile;
    h.drag_at(first.center());
    h.run();
    h.drop_at(first.center());
    h.run();
    assert_eq!(h.state().session.selection.profile, before);
    // Drag across the first image: a profile line appears and each variant has a curve.
    let (a, b) = (
        first.left_center() + egui::vec2(5.0, 10.0),
        first.right_center() + egui::vec2(-5.0, 10.0),
    );
    h.drag_at(a);
    h.run();
    h.hover_at(b);
    h.run();
    h.drop_at(b);
    h.run();
    let line = h.state().session.selection.profile.expect("a profile line");
    assert!(line[2] > line[0], "{line:?}");
    let profiles: Vec<usize> = h
        .state()
        .session
        .variants
        .iter()
        .map(|(_, c)| c.profile([line[0], line[1]], [line[2], line[3]]).len())
        .collect();
    assert!(profiles.iter().all(|&n| n > 10), "{profiles:?}");
}

#[test]
fn the_depth_buffer_can_be_linearized_and_its_range_set() {
    let mut h = harness();
    h.run();
    h.get_by_label("Depth").click();
    h.run();
    h.get_by_label("linear: eye distance").click();
    h.run();
    assert!(h.state().session.selection.depth_view.linear);
    assert_eq!(
        h.state().session.selection.depth_view.range,
        None,
        "auto range after switching"
    );
    h.get_by_label("auto range").click();
    h.run();
    assert_eq!(h.state().session.selection.depth_view.range, None);
}

/// The app on the built-in lesson (the tour), rendering synchronously.
pub(crate) fn lesson_harness(path: Option<std::path::PathBuf>) -> Harness<'static, PipelensApp> {
    let doc = match &path {
        Some(p) => pipelens::lesson::load_file(p).expect("the lesson loads"),
        None => pipelens::lesson::Document::Lesson(Box::new(
            pipelens::lesson::default_lesson().expect("the built-in lesson is valid"),
        )),
    };
    let session = Session::with_document(doc, "test", None);
    let app = PipelensApp::new(session);
    let app = match path {
        Some(p) => app.watching(p),
        None => app,
    };
    Harness::builder()
        .with_size([1366.0, 768.0])
        .with_context_setup(setup_context)
        .with_max_steps(200)
        .build_ui_state(|ui, app: &mut PipelensApp| app.frame(ui), app)
}

/// The lesson open in the app.
pub(crate) fn lesson_of(h: &Harness<'_, PipelensApp>) -> std::sync::Arc<pipelens::lesson::Lesson> {
    h.state()
        .session
        .lesson
        .as_ref()
        .expect("a lesson")
        .lesson
        .clone()
}

/// Goes to the open lesson's last step; returns its index.
pub(crate) fn go_to_last_step(h: &mut Harness<'_, PipelensApp>) -> usize {
    let last = h
        .state()
        .session
        .lesson
        .as_ref()
        .map_or(0, |p| p.lesson.steps.len() - 1);
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Lesson(
            pipelens::app::session::LessonCommand::GoToStep(last),
        ));
    h.run_steps(2);
    last
}

/// Goes to the step titled `title` (in English) of the lesson on screen; returns its index.
pub(crate) fn go_to_step_titled(h: &mut Harness<'_, PipelensApp>, title: &str) -> usize {
    let k = h
        .state()
        .session
        .lesson
        .as_ref()
        .and_then(|p| p.lesson.steps.iter().position(|s| s.title.en == title))
        .unwrap_or_else(|| panic!("no step titled {title:?}"));
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Lesson(
            pipelens::app::session::LessonCommand::GoToStep(k),
        ));
    h.run_steps(2);
    k
}

/// Lesson 10's specular lab (not its last step: the light casters' lab follows it).
pub(crate) const SPECULAR_LAB: &str = "Lab: the specular term in a fragment shader";

pub(crate) fn step_of(h: &Harness<'_, PipelensApp>) -> usize {
    h.state()
        .session
        .lesson
        .as_ref()
        .map_or(usize::MAX, |p| p.step)
}

/// The app on a lesson file at a window size.
/// The number of steps of the lesson `h` plays (0 without one).
pub(crate) fn step_count(h: &Harness<'static, PipelensApp>) -> usize {
    h.state()
        .session
        .lesson
        .as_ref()
        .map_or(0, |p| p.lesson.steps.len())
}

/// Goes to step `k` (from 0) and runs six frames, enough for the views to place their cards.
pub(crate) fn go_to_step(h: &mut Harness<'static, PipelensApp>, k: usize) {
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Lesson(
            pipelens::app::command::LessonCommand::GoToStep(k),
        ));
    h.run_steps(6);
}

/// Every shape of the frame in paint order, with its clip rect.
pub(crate) fn flatten(h: &Harness<'_, PipelensApp>) -> Vec<(egui::Rect, egui::Shape)> {
    fn walk(clip: egui::Rect, s: &egui::Shape, out: &mut Vec<(egui::Rect, egui::Shape)>) {
        match s {
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(clip, s, out)),
            s => out.push((clip, s.clone())),
        }
    }
    let mut out = Vec::new();
    for c in &h.output().shapes {
        walk(c.clip_rect, &c.shape, &mut out);
    }
    out
}

/// A finger's touch at `pos`, pressed and lifted, as a phone's browser sends it: from then on
/// the app is on a touch screen.
pub(crate) fn touch(h: &mut Harness<'_, PipelensApp>, pos: egui::Pos2) {
    for phase in [egui::TouchPhase::Start, egui::TouchPhase::End] {
        h.input_mut().events.push(egui::Event::Touch {
            device_id: egui::TouchDeviceId(1),
            id: egui::TouchId(0),
            phase,
            pos,
            force: None,
        });
        h.run_steps(1);
    }
}

/// A finger down at `from`, moved to `to` in steps, lifted: as a phone's browser sends it,
/// touch events and the pointer events made of them. `from == to` is a tap.
pub(crate) fn finger(h: &mut Harness<'_, PipelensApp>, from: egui::Pos2, to: egui::Pos2) {
    let touch = |phase, pos| egui::Event::Touch {
        device_id: egui::TouchDeviceId(1),
        id: egui::TouchId(0),
        phase,
        pos,
        force: None,
    };
    let button = |pos, pressed| egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    };
    let events = &mut h.input_mut().events;
    events.push(touch(egui::TouchPhase::Start, from));
    events.push(egui::Event::PointerMoved(from));
    events.push(button(from, true));
    h.run_steps(1);
    if from != to {
        for k in 1..=6 {
            let at = from + (to - from) * (k as f32 / 6.0);
            h.input_mut().events.push(touch(egui::TouchPhase::Move, at));
            h.input_mut().events.push(egui::Event::PointerMoved(at));
            h.run_steps(1);
        }
    }
    h.input_mut().events.push(touch(egui::TouchPhase::End, to));
    h.input_mut().events.push(button(to, false));
    h.input_mut().events.push(egui::Event::PointerGone);
    h.run_steps(3);
}

/// A finger's tap at `at` ([`finger`] without a move).
pub(crate) fn tap(h: &mut Harness<'_, PipelensApp>, at: egui::Pos2) {
    finger(h, at, at);
}

pub(crate) fn sized_lesson_harness(
    path: &std::path::Path,
    size: [f32; 2],
) -> Harness<'static, PipelensApp> {
    let doc = pipelens::lesson::load_file(path).expect("the lesson loads");
    let session = Session::with_document(doc, "test", None);
    Harness::builder()
        .with_size(size)
        .with_context_setup(setup_context)
        .with_max_steps(200)
        .build_ui_state(
            |ui, app: &mut PipelensApp| app.frame(ui),
            PipelensApp::new(session),
        )
}

/// A lesson in a language with no catalog: the switch lists it beside the catalogs' (a menu,
/// as there are three), and choosing it shows the lesson's own words in it and the interface
/// in English.
#[test]
fn a_lesson_in_another_language_is_offered_and_shown_in_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("t.toml");
    std::fs::write(
        &path,
        "[lesson]\nid = \"t\"\n\
         title = { en = \"T\", zh = \"题\", fr = \"Titre\" }\n\
         summary = { en = \"S\", zh = \"概\", fr = \"Résumé\" }\n\n\
         [[scene.objects]]\nname = \"cube\"\nmesh = \"cube\"\n\n\
         [[steps]]\ntitle = { en = \"The cube\", zh = \"立方体\", fr = \"Le cube\" }\n\
         narration = { en = \"A cube.\", zh = \"一个立方体。\", fr = \"Un cube.\" }\n",
    )
    .expect("written");
    let mut h = lesson_harness(Some(path));
    h.run();
    assert!(h.query_by_label_contains("1. The cube").is_some());
    h.get_by_label("English ▾").click();
    h.run();
    assert!(
        h.query_by_label("中文").is_some(),
        "the catalogs' languages are listed"
    );
    h.get_by_label("fr").click();
    h.run();
    assert_eq!(h.state().session.lang.tag(), "fr");
    assert!(h.query_by_label_contains("1. Le cube").is_some());
    assert!(h.query_by_label_contains("1. The cube").is_none());
    // The interface has no French catalog: it is in English.
    assert!(h.query_by_label("Next step").is_some());
    assert!(h.query_by_label("Step 1 / 1").is_some());
}
