//! The app, driven headless through its accessibility tree (egui_kittest): no display, no GPU.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::session::Session;
use pipelens::app::{PipelensApp, setup_context};
use pipelens::vocabulary::{Lang, Stage};

mod classroom;
mod export;
mod framing;
mod keys;
mod library;
mod params;
mod phone;
mod recording;
mod steps;

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
        h.get_by_label(stage.name(Lang::En)).click();
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
    assert_eq!(h.state().session.lang, Lang::Zh);
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
    let r = h.get_by_label("pixel view").rect();
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

#[test]
fn a_lesson_steps_with_the_arrow_keys_and_plays_its_animations() {
    let mut h = lesson_harness(None);
    h.run_steps(4);
    assert_eq!(step_of(&h), 0);
    assert_eq!(h.state().session.selection.stage, Stage::Output);
    assert!(
        h.query_by_label_contains("This is what the pipeline produces")
            .is_some()
    );
    // The step's pixel is selected for the inspector.
    assert_eq!(h.state().session.selection.pixel, Some((320, 200)));
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(4);
    assert_eq!(step_of(&h), 1);
    assert_eq!(h.state().session.selection.stage, Stage::Model);
    // Step 3 turns the cube: it plays by itself, and the cube's rotation moves.
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(4);
    assert_eq!(step_of(&h), 2);
    let rotation = |h: &Harness<'_, PipelensApp>| {
        h.state()
            .session
            .spec
            .scene
            .objects
            .iter()
            .find(|o| o.name == "cube")
            .map(|o| o.rotate_deg.y)
    };
    assert!(h.state().session.lesson.as_ref().is_some_and(|p| p.playing));
    let before = rotation(&h);
    h.run_steps(10);
    assert_ne!(rotation(&h), before, "the animation moves the cube");
    // Space pauses it; the rotation then stays.
    h.key_press(egui::Key::Space);
    h.run_steps(2);
    let paused = rotation(&h);
    h.run_steps(10);
    assert_eq!(rotation(&h), paused);
    // Back, and in Chinese.
    h.key_press(egui::Key::ArrowLeft);
    h.run_steps(4);
    assert_eq!(step_of(&h), 1);
    h.get_by_label("中文").click();
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("网格是围绕自己的原点建模的")
            .is_some()
    );
    // The last step's question: the answer appears on request.
    go_to_last_step(&mut h);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("相邻的面得到不同的常数颜色")
            .is_none()
    );
    h.get_by_label("显示答案").click();
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("相邻的面得到不同的常数颜色")
            .is_some()
    );
}

/// Every step of every lesson in `lessons/`, drawn by the app in both languages: a character
/// the embedded font lacks would panic here (the test harness forbids tofu).
#[test]
fn every_lesson_step_draws_in_both_languages() {
    for path in crate::support::lesson_files() {
        let mut h = lesson_harness(Some(path.clone()));
        let n = h
            .state()
            .session
            .lesson
            .as_ref()
            .map_or(0, |p| p.lesson.steps.len());
        for lang in [Lang::En, Lang::Zh] {
            h.state_mut()
                .session
                .apply(pipelens::app::session::Command::View(
                    pipelens::app::session::ViewCommand::SetLang(lang),
                ));
            for k in 0..n {
                let s = &mut h.state_mut().session;
                s.apply(pipelens::app::session::Command::Lesson(
                    pipelens::app::session::LessonCommand::GoToStep(k),
                ));
                s.apply(pipelens::app::session::Command::Lesson(
                    pipelens::app::session::LessonCommand::ShowAnswer(true),
                ));
                h.run_steps(2);
                assert!(
                    h.state().session.error.is_none(),
                    "{} step {k}: {:?}",
                    path.display(),
                    h.state().session.error
                );
            }
        }
    }
}

/// The app on a lesson file at a window size.
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

/// In a lesson, and in classroom mode, the picture of every step (the stage's buffer or
/// geometry, the observer beside it, the compared images and their plot) covers at least 60 %
/// of the window with the narration folded (N), at 1920×1080 and at 1366×768, and classroom
/// mode never makes it smaller. With the card shown, the picture is framed clear of it.
#[test]
fn the_picture_of_every_step_takes_most_of_the_window() {
    let lessons = [
        "00-tour",
        "01-transforms",
        "07-rasterization",
        "09-z-buffer",
        "14-mipmaps",
        "16-planar-shadows",
        "17-hierarchy",
    ];
    let mut worst = (1.0f32, String::new());
    for size in [[1920.0, 1080.0], [1366.0, 768.0]] {
        let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(size[0], size[1]));
        for name in lessons {
            let path = crate::support::repo().join(format!("lessons/{name}.toml"));
            let mut h = sized_lesson_harness(&path, size);
            let n = h
                .state()
                .session
                .lesson
                .as_ref()
                .map_or(0, |p| p.lesson.steps.len());
            for k in 0..n {
                h.state_mut()
                    .session
                    .apply(pipelens::app::session::Command::Lesson(
                        pipelens::app::session::LessonCommand::GoToStep(k),
                    ));
                h.run_steps(6);
                let lesson_share = h.state().picture_share(screen);
                let ctx = h.ctx.clone();
                h.state_mut().set_classroom(&ctx, true);
                h.run_steps(6);
                let classroom_share = h.state().picture_share(screen);
                // Classroom mode's larger card leaves less room beside it; what the mode itself
                // does (the panels folded, the type larger) is compared with the card folded.
                let folded = |h: &mut Harness<'static, PipelensApp>| {
                    h.state_mut().panels.narration = false;
                    h.run_steps(4);
                    let share = h.state().picture_share(screen);
                    h.state_mut().panels.narration = true;
                    share
                };
                let classroom_folded = folded(&mut h);
                h.state_mut().set_classroom(&ctx, false);
                h.run_steps(1);
                let lesson_folded = folded(&mut h);
                let label = format!("{name} step {} at {}×{}", k + 1, size[0], size[1]);
                for (share, what) in [
                    (lesson_folded, "in lesson mode"),
                    (classroom_folded, "in classroom mode"),
                ] {
                    assert!(
                        share >= 0.6,
                        "{label}: the picture covers {:.0} % {what}",
                        share * 100.0
                    );
                }
                // Beside the card (it never covers the subject) the picture is smaller; a
                // band of classroom type at 1366×768 leaves it a little over a quarter.
                for (share, what) in [
                    (lesson_share, "in lesson mode"),
                    (classroom_share, "in classroom mode"),
                ] {
                    assert!(
                        share >= 0.25,
                        "{label}: beside the card the picture covers {:.0} % {what}",
                        share * 100.0
                    );
                }
                assert!(
                    classroom_folded >= lesson_folded - 0.002,
                    "{label}: classroom mode shrinks the picture from {:.1} % to {:.1} %",
                    lesson_folded * 100.0,
                    classroom_folded * 100.0
                );
                if classroom_share.min(lesson_share) < worst.0 {
                    worst = (classroom_share.min(lesson_share), label);
                }
            }
        }
    }
    eprintln!(
        "smallest share beside the card: {:.1} % ({})",
        worst.0 * 100.0,
        worst.1
    );
}

#[test]
fn a_step_that_asks_before_it_animates_waits_for_space() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = lesson_harness(Some(path));
    h.run_steps(2);
    let spot = h
        .state()
        .session
        .lesson
        .as_ref()
        .and_then(|p| p.lesson.steps.iter().position(|s| s.predicts()))
        .expect("lesson 10 has a predict-then-watch step");
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Lesson(
            pipelens::app::session::LessonCommand::GoToStep(spot),
        ));
    h.run_steps(4);
    let playing =
        |h: &Harness<'_, PipelensApp>| h.state().session.lesson.as_ref().is_some_and(|p| p.playing);
    assert!(!playing(&h), "it waits for the prediction");
    assert!(h.query_by_label_contains("Predict first").is_some());
    h.key_press(egui::Key::Space);
    h.run_steps(4);
    assert!(playing(&h), "Space plays it");
    assert!(h.query_by_label_contains("Predict first").is_none());
}
