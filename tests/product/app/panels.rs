//! The picture beside the panels a student or a teacher opens (issue "The room and the
//! editor"): on a 1920×1080 window the view frames its picture in what the shader panel, the
//! inspector and the lesson editor leave, and keeps at least 35 % of the window with one of them
//! open and 25 % with two, on every step of lesson 24 and on every lab.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::app::command::LessonCommand;
use pipelens::app::session::Command;

/// Which of the shader panel, the inspector and the lesson editor are open.
type Open = [bool; 3];

/// Opens and closes the panels to `want`, as a user does (the editor with its key, R).
fn set_panels(h: &mut Harness<'_, PipelensApp>, shown: &mut Open, want: Open) {
    h.state_mut().panels.shader = want[0];
    h.state_mut().panels.inspector = want[1];
    if shown[2] != want[2] {
        h.key_press(egui::Key::R);
    }
    *shown = want;
    h.run_steps(8);
    assert_eq!(
        h.query_all_by_label_contains("Lesson editor")
            .next()
            .is_some(),
        want[2],
        "the editor's panel follows R"
    );
}

/// Every step of lesson 24 and every lab, with each panel and each pair of panels open: the
/// picture's share of the window. (Before the panels started narrower beside each other, the
/// code and the inspector left a step's picture 20 % and the code and the floating editor
/// 15.9 %, the editor covering it; beside the code a lab's three pictures kept 26–31 %.)
#[test]
fn the_picture_keeps_its_share_beside_open_panels() {
    let screen = egui::Rect::from_min_size(egui::pos2(8.0, 8.0), egui::vec2(1920.0, 1080.0));
    let mut small = Vec::new();
    let mut measured = 0;
    for entry in std::fs::read_dir(crate::support::repo().join("lessons")).expect("lessons") {
        let path = entry.expect("an entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let every = path.ends_with("24-shader-programs.toml");
        let lesson = super::lesson_of(&super::sized_lesson_harness(&path, [400.0, 300.0]));
        let steps: Vec<usize> = (0..lesson.steps.len())
            .filter(|&k| every || lesson.steps[k].exercise.is_some())
            .collect();
        if steps.is_empty() {
            continue;
        }
        // The harness keeps 8 points around the app: 1920×1080 inside.
        let mut h = super::sized_lesson_harness(&path, [1936.0, 1096.0]);
        h.run_steps(2);
        let mut shown = [false; 3];
        for k in steps {
            h.state_mut()
                .session
                .apply(Command::Lesson(LessonCommand::GoToStep(k)));
            h.run_steps(2);
            for (want, least) in [
                ([true, false, false], 0.35),
                ([false, true, false], 0.35),
                ([false, false, true], 0.35),
                ([true, true, false], 0.25),
                ([true, false, true], 0.25),
                ([false, true, true], 0.25),
            ] {
                set_panels(&mut h, &mut shown, want);
                let share = h.state().picture_share(screen);
                measured += 1;
                eprintln!(
                    "{} step {} {want:?}: {:.1} %",
                    path.display(),
                    k + 1,
                    share * 100.0
                );
                if share < least {
                    small.push(format!(
                        "{} step {} with {want:?} open: {:.1} % (at least {:.0} %)",
                        path.file_name()
                            .map(|n| n.to_string_lossy())
                            .unwrap_or_default(),
                        k + 1,
                        share * 100.0,
                        least * 100.0
                    ));
                }
            }
        }
    }
    // Lesson 24's 12 steps, 6 arrangements each, and 16 more labs.
    assert!(
        measured >= 12 * 6 + 16 * 4,
        "only {measured} pictures measured"
    );
    assert!(
        small.is_empty(),
        "the picture is too small beside its panels: {small:#?}"
    );
}
