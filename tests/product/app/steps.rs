//! What a lesson step shows when it does not say: the rules a lesson's author relies on.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::app::command::ViewCommand;

use super::{go_to_last_step, lesson_harness, step_of};

#[test]
fn a_step_without_buffer_shows_its_stages_default_even_after_a_reload() {
    use pipeline::buffers::BufferKind;
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("lesson.toml");
    let head = "[lesson]\nid = \"lesson\"\ntitle = { en = \"A\", zh = \"甲\" }\n\
                summary = { en = \"A.\", zh = \"甲。\" }\n\n[[scene.objects]]\nmesh = \"sphere\"\n\n\
                [[scene.lights]]\nkind = \"point\"\nposition = [2, 2, 2]\n";
    let step = |keys: &str| {
        format!(
            "\n[[steps]]\ntitle = {{ en = \"A\", zh = \"甲\" }}\nnarration = {{ en = \"A.\", zh = \"甲。\" }}\n{keys}"
        )
    };
    let first = step("stage = \"shading\"\noverlays = [\"edges\"]\n");
    let second = step("buffer = \"normal\"\n");
    // The third names neither stage nor buffer: it stays on the shading stage.
    let three = format!("{head}{first}{second}{}", step(""));
    std::fs::write(&path, &three).expect("write");
    let mut h = lesson_harness(Some(path.clone()));
    h.run_steps(2);
    let buffer = |h: &Harness<'_, PipelensApp>| h.state().session.selection.buffer;
    assert_eq!(buffer(&h), BufferKind::Diffuse, "step 1: the stage's own");
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(2);
    assert_eq!(buffer(&h), BufferKind::Normal, "step 2 names it");
    assert!(
        h.state().session.selection.overlays.is_empty(),
        "step 2 names no overlays: none, not step 1's edges"
    );
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(2);
    assert_eq!(
        (step_of(&h), buffer(&h)),
        (2, BufferKind::Diffuse),
        "step 3 names none: the stage's default, not what step 2 showed"
    );
    // A reload that removes step 3 lands on step 2 and shows what step 2 says.
    crate::support::save_edited(
        &path,
        &format!("{head}{first}{second}"),
        std::time::SystemTime::now() + std::time::Duration::from_secs(2),
    );
    std::thread::sleep(std::time::Duration::from_millis(600));
    h.run_steps(3);
    assert_eq!((step_of(&h), buffer(&h)), (1, BufferKind::Normal));
    // The viewer goes to another stage, then back to step 1 and on to step 2: each step's
    // stage and buffer again, not what the viewer looked at.
    h.get_by_label("Depth").click();
    h.run_steps(2);
    h.key_press(egui::Key::ArrowLeft);
    h.run_steps(2);
    assert_eq!((step_of(&h), buffer(&h)), (0, BufferKind::Diffuse));
    h.get_by_label("Depth").click();
    h.run_steps(2);
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(2);
    let stage = h.state().session.selection.stage;
    assert_eq!(
        (step_of(&h), stage, buffer(&h)),
        (1, pipelens::vocabulary::Stage::Shading, BufferKind::Normal),
        "step 2 names no stage: step 1's"
    );
}

/// Lesson 02, inspector open. Its last step stands halfway between two orientations: the
/// Matrices tab works the slerp number by number (q₀ = 90° about (1, 1, 0)/√2, q₁ = 90° about z,
/// cos Ω = 0.5, weights sin 30°/sin 60° = 0.577, slerp = (0.816, 0.289, 0.289, 0.408), 70.5° about
/// (0.5, 0.5, 0.707), as its question works it by hand). Two steps back, beside the five-factor
/// model matrix, the same rotation by Rodrigues' formula and by the quaternion
/// (q = (cos 45°, sin 45°·n) = (0.707, 0.5, 0.5, 0)).
#[test]
fn the_inspector_shows_an_axis_rotation_by_rodrigues_by_quaternion_and_a_slerp() {
    let path = crate::support::repo().join("lessons/02-arbitrary-axis.toml");
    let mut h = lesson_harness(Some(path));
    h.run_steps(2);
    let last = go_to_last_step(&mut h);
    assert_eq!(step_of(&h), last);
    h.key_press(egui::Key::I);
    h.run_steps(3);
    for shown in [
        "q₀·q₁ = 0.500; Ω = 60.0°",
        "t = 0.50: weights 0.577, 0.577",
        "slerp = (0.816, 0.289, 0.289, 0.408) = 70.5° about (0.500, 0.500, 0.707)",
    ] {
        assert!(h.query_by_label_contains(shown).is_some(), "{shown}");
    }
    for _ in 0..2 {
        h.key_press(egui::Key::ArrowLeft);
        h.run_steps(2);
    }
    assert_eq!(step_of(&h), last - 2);
    h.run_steps(3);
    assert!(
        h.query_by_label_contains("q = (0.707, 0.500, 0.500, 0.000)")
            .is_some(),
        "the quaternion's numbers"
    );
    assert!(h.query_by_label_contains("slerp(1, q, ½)").is_some());
    assert!(
        h.query_by_label_contains("N the cross-product matrix of n")
            .is_some()
    );
}

/// While a parameter is dragged the picture is a draft (one sample per pixel, shaded once per
/// 2×2 block but the inspected pixel, the observer at a quarter of its pixels), so that it
/// keeps up with the hand; letting go renders the full frame.
/// Through the app: the Parameters panel's fovy slider dragged, then let go.
#[test]
fn a_dragged_parameter_renders_drafts_then_the_full_frame_on_release() {
    use pipeline::raster::Samples;
    let mut h = lesson_harness(None);
    h.run_steps(3);
    let full = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        let s = &h.state().session;
        let c = s.capture.as_ref().expect("a capture");
        (s.shown_draft, c.settings.samples, c.settings.coarse_shading)
    };
    let exact = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        let s = &h.state().session;
        s.capture.as_ref().and_then(|c| c.settings.capture.pixel)
    };
    assert_eq!(full(&h), (false, Samples::X4, false));
    let observer_pixels = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        h.state()
            .session
            .observer
            .as_ref()
            .map(|o| o.width() * o.height())
    };
    // Drag the fovy slider of the Parameters panel (P opens it).
    h.key_press(egui::Key::P);
    h.run_steps(2);
    let before = observer_pixels(&h).expect("the tour shows the observer");
    let slider = h
        .get_by_role_and_label(egui::accesskit::Role::Slider, "fovy °")
        .rect();
    let fovy = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| match h
        .state()
        .session
        .spec
        .scene
        .projection
    {
        pipeline::camera::Projection::Perspective { fovy_deg, .. } => fovy_deg,
        _ => f32::NAN,
    };
    let start = fovy(&h);
    h.drag_at(slider.center());
    h.run();
    h.hover_at(slider.center() + egui::vec2(30.0, 0.0));
    h.run();
    h.hover_at(slider.center() + egui::vec2(60.0, 0.0));
    h.run();
    assert!(
        fovy(&h) > start,
        "the slider moved fovy: {start} → {}",
        fovy(&h)
    );
    // The tour's first step inspects a pixel: its explanation must agree with its colour, so
    // the draft shades it by itself.
    let inspected = h.state().session.selection.pixel;
    assert!(inspected.is_some());
    assert_eq!(
        full(&h),
        (true, Samples::X1, true),
        "a draft while dragging"
    );
    assert_eq!(exact(&h), inspected);
    // The draft keeps the shown buffer and the inspected pixel's terms, not every buffer.
    {
        let c = h.state().session.capture.clone().expect("a draft");
        let (x, y) = inspected.expect("inspected");
        let lit = c.settings.shading != pipeline::lighting::Frequency::Unlit;
        assert!(!c.settings.capture.covers(pipeline::buffers::Capture::FULL));
        assert!(c.pixels.shading.is_none() || c.settings.capture.lighting);
        let record = c.pixel_record(x, y).expect("a record");
        assert_eq!(record.lighting.is_some(), lit && record.primitive.is_some());
    }
    let draft = observer_pixels(&h).expect("the observer is drawn while dragging");
    assert!(draft * 3 < before, "{draft} of {before} pixels");
    h.drop_at(slider.center() + egui::vec2(60.0, 0.0));
    h.run_steps(3);
    assert_eq!(
        full(&h),
        (false, Samples::X4, false),
        "the full frame once let go"
    );
    assert_eq!(observer_pixels(&h), Some(before));
    // Nothing inspected: no pixel shaded by itself.
    h.state_mut().session.selection.pixel = None;
    h.drag_at(slider.center() + egui::vec2(60.0, 0.0));
    h.run();
    h.hover_at(slider.center() + egui::vec2(20.0, 0.0));
    h.run();
    assert_eq!(
        full(&h),
        (true, Samples::X1, true),
        "a coarse draft while dragging"
    );
    assert_eq!(exact(&h), None);
    h.drop_at(slider.center() + egui::vec2(20.0, 0.0));
    h.run_steps(3);
    assert_eq!(
        full(&h),
        (false, Samples::X4, false),
        "the full frame once let go"
    );
}

/// Lesson 10 teaches k_a, k_d, k_s, the shininess and the lights: the Parameters panel has them,
/// and dragging a light's intensity changes the scene the picture is drawn from.
#[test]
fn the_lighting_lesson_s_lights_and_material_are_sliders() {
    let mut h = lesson_harness(Some(
        crate::support::repo().join("lessons/10-blinn-phong.toml"),
    ));
    h.run_steps(3);
    h.key_press(egui::Key::P);
    h.run_steps(2);
    assert!(h.query_by_label("Lights").is_some(), "the Lights section");
    assert!(h.query_by_label_contains("point light 1").is_some());
    let intensity = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        h.state()
            .session
            .spec
            .scene
            .lights
            .iter()
            .find_map(|l| match l {
                pipeline::light::Light::Point { intensity, .. } => Some(intensity.x),
                _ => None,
            })
    };
    let start = intensity(&h).expect("a point light");
    // Folded, the sections above leave the lights' sliders in view.
    for section in ["Rasterizer settings", "Projection", "Camera"] {
        h.get_by_label(section).click();
        h.run_steps(2);
    }
    // The sliders of the lights, in order: ambient, then the point light.
    let sliders: Vec<egui::Rect> = h
        .get_all_by_role_and_label(egui::accesskit::Role::Slider, "intensity I")
        .map(|n| n.rect())
        .collect();
    assert!(sliders.len() >= 2, "{} intensity sliders", sliders.len());
    let slider = sliders[1];
    h.drag_at(slider.center());
    h.run();
    h.hover_at(slider.center() + egui::vec2(40.0, 0.0));
    h.run();
    h.drop_at(slider.center() + egui::vec2(40.0, 0.0));
    h.run_steps(3);
    let now = intensity(&h).expect("a point light");
    assert!(now > start, "intensity {start} → {now}");
    // Each lit object's material: k_a, k_d, k_s and the shininess (under Objects).
    // Folded, the sections above leave the objects in view.
    h.get_by_label("Lights").click();
    h.run_steps(2);
    h.get_by_label("Objects").click();
    h.run_steps(2);
    // The object's section (the pictures' names say "sphere" too).
    h.query_all(egui_kittest::kittest::by().label_contains("sphere"))
        .find(|n| {
            use egui_kittest::kittest::NodeT;
            n.accesskit_node().role() != accesskit::Role::Image
        })
        .expect("the sphere's section")
        .click();
    h.run_steps(2);
    for label in ["material", "k_a", "k_d", "k_s", "shininess p"] {
        assert!(h.query_all_by_label(label).next().is_some(), "{label}");
    }
}

/// Shading steps on a projector (issue: a 640×400 buffer magnified ×2–3 showed stair-stepped
/// silhouettes): on the tour's first step (the output) at 1920×1080, the pixel view also has the
/// colour rendered at the size it draws it, the lesson's shape kept, while the capture the
/// inspector and the overlays read keeps the lesson's pixels. On the rasterization stage, and
/// while a parameter is dragged, there is none.
#[test]
fn a_shading_stage_shows_its_picture_at_the_views_resolution() {
    use pipelens::app::session::Command;
    use pipelens::vocabulary::Stage;
    let path = crate::support::repo().join("lessons/00-tour.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.run_steps(6);
    let s = &h.state().session;
    assert_eq!(s.selection.stage, Stage::Output);
    let capture = s.capture.clone().expect("a capture");
    let fine = s
        .view_resolution
        .capture
        .clone()
        .expect("a finer render on the output stage");
    let view = s.view_pixels.expect("the view said its size");
    let (lw, lh) = (capture.width(), capture.height());
    assert!(
        fine.width() >= lw * 3 / 2 && fine.width() <= view[0] + 1 && fine.height() <= view[1] + 1,
        "{}×{} for a view of {view:?} (lesson {lw}×{lh})",
        fine.width(),
        fine.height()
    );
    let aspect = |w: u32, h: u32| w as f32 / h as f32;
    assert!((aspect(fine.width(), fine.height()) - aspect(lw, lh)).abs() < 0.01);
    // The same picture, finer: the mean colour of the two agrees within 2 %.
    let mean = |c: &pipeline::capture::FrameCapture| {
        let img = c.image(pipeline::buffers::BufferKind::Color);
        let sum: f64 = img
            .pixels()
            .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
            .sum();
        sum / (3.0 * 255.0 * f64::from(img.width() * img.height()))
    };
    assert!((mean(&capture) - mean(&fine)).abs() < 0.02);
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SelectStage(Stage::Raster)));
    h.run_steps(6);
    assert!(
        h.state().session.view_resolution.capture.is_none(),
        "the pixel grid is the subject"
    );
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SelectStage(Stage::Output)));
    h.run_steps(6);
    assert!(
        h.state().session.view_resolution.capture.is_some(),
        "back on the output"
    );
    let s = &mut h.state_mut().session;
    s.drafting = true;
    assert!(
        s.view_resolution_job().is_none(),
        "a draft keeps up with the hand"
    );
}

/// A lab's reference is shown in the buffer the student's frame is shown in (issue: the buffer
/// menu named one buffer while the picture beside the student's showed the colour): in lesson
/// 10's specular lab, choosing the specular term renders the reference keeping it too.
#[test]
fn a_labs_reference_is_shown_in_the_students_buffer() {
    use pipelens::app::session::Command;
    use pipeline::buffers::{BufferKind, Capture};
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    super::go_to_step_titled(&mut h, super::SPECULAR_LAB);
    h.run_steps(4);
    assert!(
        h.state().session.current_exercise().is_some(),
        "the lab step"
    );
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SelectBuffer(
            BufferKind::Specular,
        )));
    h.run_steps(4);
    let s = &h.state().session;
    let reference = s.exercise.reference.as_ref().expect("the reference");
    assert!(
        reference
            .settings
            .capture
            .covers(Capture::showing([BufferKind::Specular])),
        "the reference keeps the specular term"
    );
    // What is drawn beside the student's frame: the reference's specular term, not its colour.
    assert_ne!(
        reference.image(BufferKind::Specular),
        reference.image(BufferKind::Color)
    );
}
