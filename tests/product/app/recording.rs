//! "Add step" (R): what is on screen, worded in both languages, is written into the lesson file
//! after the current step.

use egui_kittest::kittest::Queryable;
use pipelens::app::session::Command;
use pipelens::lesson::param::{self, Value};

/// A teacher opens lesson 17 from a file, turns the arm's base to 50° and inspects a pixel,
/// presses R, words the step in English and Chinese and records it: the file then holds six
/// steps, the new one second, with the stage, the layout, the pixel and the one parameter
/// changed, and it still passes the checker. Without words the button writes nothing.
#[test]
fn a_step_is_recorded_from_the_screen_into_the_lesson_file() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("17-hierarchy.toml");
    std::fs::copy(
        crate::support::repo().join("lessons/17-hierarchy.toml"),
        &file,
    )
    .expect("copied");
    let before = std::fs::read_to_string(&file).expect("reads");
    let mut h = super::lesson_harness(Some(file.clone()));
    h.run_steps(2);
    let mut spec = h.state().session.spec.clone();
    param::apply(&mut spec, "figures.arm.base", &Value::Number(50.0)).expect("a joint");
    h.state_mut()
        .session
        .apply(Command::SetSpec(Box::new(spec)));
    h.state_mut()
        .session
        .apply(Command::SelectPixel(Some((120, 80))));
    h.key_press(egui::Key::R);
    h.run_steps(3);
    assert!(h.query_by_label_contains("figures.arm.base = 50").is_some());
    // Not worded yet: the note says so, and recording writes nothing.
    assert!(
        h.query_by_label_contains("The narration still needs")
            .is_some()
    );
    h.get_by_label("Record as step 2").click();
    h.run_steps(2);
    assert_eq!(std::fs::read_to_string(&file).expect("reads"), before);
    assert!(
        h.query_by_label_contains("no narration in English and Chinese")
            .is_some()
    );
    // Worded: title and narration, English and Chinese.
    let words = [
        "The base at 50°",
        "支架转到 50°",
        "The whole arm turns with the base.",
        "整条手臂随支架转动。",
    ];
    for (k, text) in words.iter().enumerate() {
        let boxes: Vec<_> = h
            .get_all_by_role(egui::accesskit::Role::MultilineTextInput)
            .collect();
        boxes[k].focus();
        h.run_steps(1);
        let boxes: Vec<_> = h
            .get_all_by_role(egui::accesskit::Role::MultilineTextInput)
            .collect();
        boxes[k].type_text(text);
        h.run_steps(1);
    }
    h.get_by_label("Record as step 2").click();
    h.run_steps(2);
    assert!(h.query_by_label_contains("Written into").is_some());
    let text = std::fs::read_to_string(&file).expect("reads");
    let lesson = pipelens::lesson::script::parse_lesson(&text, "lesson.toml", dir.path())
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(lesson.steps.len(), 6);
    let step = &lesson.steps[1];
    assert_eq!(
        (step.title.en.as_str(), step.title.zh.as_str()),
        (words[0], words[1])
    );
    assert_eq!(step.narration.en, words[2]);
    assert_eq!(step.pixel, Some((120, 80)));
    assert_eq!(step.stage, Some(pipelens::vocabulary::Stage::World));
    assert_eq!(
        step.set,
        [("figures.arm.base".to_owned(), Value::Number(50.0))]
    );
    // The file passes `pipelens check`, every line it had still there.
    let o = crate::support::pipelens(dir.path(), &["check", "17-hierarchy.toml"]);
    assert!(o.status.success(), "{}", crate::support::text(&o));
    let mut lines = text.lines();
    for line in before.lines() {
        assert!(lines.any(|l| l == line), "lost: {line}");
    }
}
