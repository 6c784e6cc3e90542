//! Classroom mode on a projector: what the room reads fits and grows.

use egui_kittest::kittest::Queryable;

/// In classroom mode on a 1366×768 projector, the narration card says all of each step
/// without scrolling: the type shrinks until the question and its answer button fit (never
/// below the normal size), and the button lies inside the window.
#[test]
fn the_classroom_card_fits_its_question_and_answer_button_at_1366() {
    for name in ["17-hierarchy", "10-blinn-phong", "07-rasterization"] {
        let path = crate::support::repo().join(format!("lessons/{name}.toml"));
        let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
        let ctx = h.ctx.clone();
        h.state_mut().set_classroom(&ctx, true);
        let steps = h
            .state()
            .session
            .lesson
            .as_ref()
            .map_or(0, |p| p.lesson.steps.len());
        let mut checked = 0;
        for k in 0..steps {
            h.state_mut()
                .session
                .apply(pipelens::app::session::Command::Lesson(
                    pipelens::app::session::LessonCommand::GoToStep(k),
                ));
            h.run_steps(8);
            let step = &h
                .state()
                .session
                .lesson
                .as_ref()
                .expect("a lesson")
                .lesson
                .steps[k];
            if step.answer.is_none() {
                continue;
            }
            let button = h.get_by_label("Show the answer").rect();
            assert!(
                button.bottom() <= 768.0 - 12.0 && button.top() > 0.0,
                "{name} step {}: the answer button is at {button:?}, outside the card",
                k + 1
            );
            checked += 1;
        }
        assert!(checked > 0, "{name}: no step with an answer was checked");
    }
}
