//! The keyboard: the keys fold the panels and switch classroom mode, and F1's help lists the
//! shortcut table the keys are read from.

use egui_kittest::kittest::Queryable;
use pipelens::vocabulary::Lang;

use super::lesson_harness;

#[test]
fn the_keys_fold_panels_switch_classroom_mode_and_list_themselves() {
    let mut h = lesson_harness(None);
    h.run_steps(4);
    assert!(h.state().panels.narration);
    h.key_press(egui::Key::N);
    h.run_steps(2);
    assert!(!h.state().panels.narration, "N folds the narration");
    assert!(
        h.query_by_label_contains("This is what the pipeline produces")
            .is_none()
    );
    assert!(!h.state().classroom());
    h.key_press(egui::Key::C);
    h.run_steps(2);
    assert!(h.state().classroom(), "C turns classroom mode on");
    h.key_press(egui::Key::C);
    h.run_steps(2);
    assert!(!h.state().classroom());
    assert!(h.query_by_label("Keyboard shortcuts").is_none());
    h.key_press(egui::Key::F1);
    h.run_steps(2);
    assert!(h.query_by_label("Keyboard shortcuts").is_some());
    assert!(h.query_by_label_contains("classroom mode").is_some());
    // The help is the table the keys are read from: every row of it, and Ctrl+Shift+Z written
    // as a reader types it.
    for s in &pipelens::app::shortcuts::SHORTCUTS {
        let keys = pipelens::app::shortcuts::keys_written(s);
        assert!(h.query_by_label(&keys).is_some(), "the help lists {keys}");
        assert!(
            h.query_by_label(Lang::EN.t(s.does)).is_some(),
            "the help says {}",
            Lang::EN.t(s.does)
        );
    }
    assert!(h.query_by_label("Ctrl+Shift+Z  Ctrl+Y").is_some());
    // And what a focused picture does with the keys, from the table its listener reads.
    for (keys, does) in pipelens::app::shortcuts::IN_A_PICTURE {
        let does = Lang::EN.t(does);
        assert!(h.query_by_label(keys).is_some(), "the help lists {keys}");
        assert!(h.query_by_label(does).is_some(), "the help says {does}");
    }
    h.key_press(egui::Key::F1);
    h.run_steps(2);
    assert!(h.query_by_label("Keyboard shortcuts").is_none());
}
