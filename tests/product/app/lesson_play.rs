//! A lesson played in the app: the arrow keys step it and its animations play, every step draws
//! in both languages, the picture of every step takes most of the window, and a step that asks
//! before it animates waits for Space.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::vocabulary::{Lang, Stage};

use super::{go_to_last_step, lesson_harness, sized_lesson_harness, step_of};

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
        for lang in [Lang::EN, Lang::ZH] {
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

/// In a lesson, and in classroom mode, the picture of every step (the stage's buffer or
/// geometry, the observer beside it, the compared images and their plot) covers at least 60 %
/// of the window with the narration folded (N), at 1920×1080 and at 1366×768, and classroom
/// mode never makes it smaller (but for a lab's, whose companions' captions in the larger type
/// take more of their room). With the card shown, the picture is framed clear of it.
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
                // A lab's two companion pictures keep their whole captions above them: in
                // classroom type those take more of the companions' room, by design.
                let lab = h.state().session.current_exercise().is_some();
                assert!(
                    lab || classroom_folded >= lesson_folded - 0.002,
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

/// A step's animation lines are said as the language writes them: lesson 17 step 4 animates
/// the humanoid's four limbs (its TOML: `figures.body.left_upper_leg` from −40 to 40 first),
/// and the Chinese line puts a full-width colon after the limb's name, as Chinese does — not
/// the English ": " the code once joined them with.
#[test]
fn an_animation_line_is_said_in_the_language_shown() {
    let path = crate::support::repo().join("lessons/17-hierarchy.toml");
    let mut h = sized_lesson_harness(&path, [1366.0, 768.0]);
    super::go_to_step(&mut h, 3);
    for (lang, line) in [
        (Lang::EN, "▶ Left upper leg of humanoid: -40 → 40"),
        (Lang::ZH, "▶ 人体模型的左大腿：-40 → 40"),
    ] {
        h.state_mut()
            .session
            .apply(pipelens::app::command::Command::View(
                pipelens::app::command::ViewCommand::SetLang(lang),
            ));
        h.run_steps(3);
        assert!(
            h.query_by_label_contains(line).is_some(),
            "no {line:?} in {}",
            lang.tag()
        );
    }
}
