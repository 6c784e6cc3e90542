//! The lesson editor (R): a teacher records what is on screen as steps (a drag as an
//! animation), words them in both languages, moves them, undoes and redoes, and saves the file;
//! unsaved edits are kept in a recovery copy and offered again; a file changed on disk is not
//! overwritten without asking (a new lesson from a mesh of one's own: `new_lesson.rs`).

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::app::command::{LessonCommand, SceneCommand, SelectionCommand};
use pipelens::app::session::Command;
use pipelens::lesson::param::{self, Value};

fn copy_of(lesson: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join(lesson);
    std::fs::copy(crate::support::repo().join("lessons").join(lesson), &file).expect("copied");
    (dir, file)
}

/// Types `text` into the `k`-th multi-line box of the window (the editor's, in order: the
/// current step's title, narration, question and answer, English then Chinese; then the new
/// step's title and narration).
fn type_into(h: &mut Harness<'_, PipelensApp>, k: usize, text: &str) {
    h.get_all_by_role(Role::MultilineTextInput)
        .nth(k)
        .expect("a box")
        .focus();
    h.run_steps(1);
    h.get_all_by_role(Role::MultilineTextInput)
        .nth(k)
        .expect("a box")
        .type_text(text);
    h.run_steps(2);
}

/// Replaces the text of the `k`-th one-line box of the window with `text`.
pub(super) fn replace_in(h: &mut Harness<'_, PipelensApp>, k: usize, text: &str) {
    h.get_all_by_role(Role::TextInput)
        .nth(k)
        .expect("a box")
        .focus();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run_steps(1);
    h.get_all_by_role(Role::TextInput)
        .nth(k)
        .expect("a box")
        .type_text(text);
    h.run_steps(1);
}

/// A slider dragged from the scene on screen to `name = value`, as the app sees a drag: the
/// draft starts before the first change and ends when the pointer is let go.
fn drag(h: &mut Harness<'_, PipelensApp>, name: &str, value: f32) {
    let s = &mut h.state_mut().session;
    s.set_drafting(true);
    let mut spec = s.spec.clone();
    param::apply(&mut spec, name, &Value::Number(value)).expect("a parameter");
    s.apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    h.run_steps(3);
}

fn titles(h: &Harness<'_, PipelensApp>) -> Vec<String> {
    super::lesson_of(h)
        .steps
        .iter()
        .map(|s| s.title.en.clone())
        .collect()
}

/// Lesson 17 from a file: R opens the editor; the arm's base dragged to 50° and a pixel
/// inspected are a new step 2, worded in both languages, with an animation of the drag; the step
/// moved down one, its question typed, the move undone and redone; the file untouched until
/// Save (the edits kept meanwhile in a recovery copy), then written, and read back it is the
/// lesson the app plays, passing `pipelens check`, every line the file had still there.
#[test]
fn a_lesson_is_recorded_arranged_and_saved_in_the_editor() {
    let (dir, file) = copy_of("17-hierarchy.toml");
    let before = std::fs::read_to_string(&file).expect("reads");
    let recovery = dir.path().join("17-hierarchy.toml.unsaved");
    let mut h = super::lesson_harness(Some(file.clone()));
    h.run_steps(2);
    h.key_press(egui::Key::R);
    h.run_steps(3);
    assert!(h.query_by_label("Resize panel: Lesson editor").is_some());
    drag(&mut h, "figures.arm.base", 50.0);
    h.state_mut()
        .session
        .apply(Command::Selection(SelectionCommand::SelectPixel(Some((
            120, 80,
        )))));
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("set figures.arm.base = 50")
            .is_some()
    );
    assert!(
        h.query_by_label_contains("animate figures.arm.base : 30 → 50")
            .is_some(),
        "the drag is an animation from where it began"
    );
    // Not worded: the note says so, and adding is refused.
    assert!(
        h.query_by_label_contains("Still needs: English, 中文")
            .is_some()
    );
    h.get_by_label("＋ Add as step 2").click_accesskit();
    h.run_steps(4);
    assert_eq!(titles(&h).len(), 5);
    // Why, under the button (not at the window's top, scrolled out of sight), in view.
    let button = h.get_by_label("＋ Add as step 2").rect();
    let why = h
        .get_by_label_contains("a lesson's step needs its words in both languages")
        .rect();
    assert!(
        why.top() >= button.bottom() - 1.0 && why.top() < button.bottom() + 40.0,
        "the refusal at {why:?}, the button at {button:?}"
    );
    let window = h.ctx.content_rect();
    assert!(window.contains_rect(why), "{why:?} is off {window:?}");
    let words = [
        "The base at 50°",
        "支架转到 50°",
        "The whole arm turns with the base: **M = T·R_y·…**",
        "整条手臂随支架转动。",
    ];
    for (k, text) in words.iter().enumerate() {
        type_into(&mut h, 8 + k, text);
    }
    h.get_by_label("＋ Add as step 2").click_accesskit();
    h.run_steps(3);
    let lesson = super::lesson_of(&h);
    assert_eq!(lesson.steps.len(), 6);
    assert_eq!(h.state().session.lesson.as_ref().map(|p| p.step), Some(1));
    let step = &lesson.steps[1];
    assert_eq!(
        (step.title.en.as_str(), step.title.zh.as_str()),
        (words[0], words[1])
    );
    assert_eq!(step.pixel, Some((120, 80)));
    assert_eq!(
        step.set,
        [("figures.arm.base".to_owned(), Value::Number(50.0))]
    );
    let a = &step.animate[0];
    assert_eq!(
        (a.param.as_str(), &a.from, &a.to),
        (
            "figures.arm.base",
            &Value::Number(30.0),
            &Value::Number(50.0)
        )
    );
    // Not saved yet: the file is as it was, the edits in the recovery copy beside it.
    assert_eq!(std::fs::read_to_string(&file).expect("reads"), before);
    assert!(recovery.exists(), "a recovery copy keeps the unsaved edits");
    assert!(h.query_by_label_contains("● unsaved").is_some());
    // Moved down one, and a question typed on the step.
    h.get_by_label("▼ Later").click_accesskit();
    h.run_steps(3);
    assert_eq!(titles(&h)[2], words[0]);
    assert_eq!(h.state().session.lesson.as_ref().map(|p| p.step), Some(2));
    type_into(&mut h, 4, "Where is the elbow now?");
    type_into(&mut h, 5, "肘部现在在哪里？");
    let asked = super::lesson_of(&h).steps[2]
        .question
        .clone()
        .expect("asked");
    assert_eq!(asked.en, "Where is the elbow now?");
    // Undo takes the Chinese question back, then the English one, then the move; redo brings
    // the move back.
    for _ in 0..3 {
        h.get_by_label("↶ Undo").click_accesskit();
        h.run_steps(3);
    }
    assert_eq!(titles(&h)[1], words[0], "the move undone");
    assert!(super::lesson_of(&h).steps[1].question.is_none());
    h.get_by_label("↷ Redo").click_accesskit();
    h.run_steps(3);
    assert_eq!(titles(&h)[2], words[0], "the move redone");
    saved_as_played(&mut h, &file, &before);
    assert!(!recovery.exists(), "saved: no recovery copy");
}

/// Save: the file read back is the lesson the app plays, passes `pipelens check`, and keeps
/// every line it had `before`.
fn saved_as_played(h: &mut Harness<'_, PipelensApp>, file: &std::path::Path, before: &str) {
    h.get_by_label("Save").click_accesskit();
    h.run_steps(3);
    assert!(h.query_by_label_contains("Saved: ").is_some());
    let dir = file.parent().expect("a folder");
    let saved = std::fs::read_to_string(file).expect("reads");
    let back = pipelens::lesson::script::parse_lesson(&saved, "lesson.toml", dir)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        back.steps,
        super::lesson_of(h).steps,
        "the file reads back as the lesson played"
    );
    let name = file.file_name().expect("a name").to_string_lossy();
    let o = crate::support::pipelens(dir, &["check", &name]);
    assert!(o.status.success(), "{}", crate::support::text(&o));
    let mut lines = saved.lines();
    for line in before.lines() {
        assert!(lines.any(|l| l == line), "lost: {line}");
    }
}

/// Unsaved edits outlive the app: a recovery copy beside the file is offered when the lesson is
/// opened again, and restored it is what the app plays. A file changed on disk while edits are
/// unsaved is not reloaded over them, and Save asks before overwriting it.
#[test]
fn unsaved_edits_are_offered_again_and_a_changed_file_is_not_overwritten_unasked() {
    let (dir, file) = copy_of("17-hierarchy.toml");
    let before = std::fs::read_to_string(&file).expect("reads");
    let edited = before.replacen("The robot arm", "The robot arm, kept", 1);
    assert_ne!(edited, before);
    std::fs::write(dir.path().join("17-hierarchy.toml.unsaved"), &edited).expect("written");
    let mut h = super::lesson_harness(Some(file.clone()));
    h.run_steps(3);
    assert!(
        h.query_by_label_contains("Unsaved changes to this lesson were kept")
            .is_some()
    );
    assert!(
        dir.path().join("17-hierarchy.toml.unsaved").exists(),
        "the copy stays until the teacher chooses"
    );
    h.get_by_label("Restore them").click_accesskit();
    h.run_steps(3);
    assert_eq!(titles(&h)[0], "The robot arm, kept");
    // Someone else changes the file meanwhile: the edits stay on screen.
    let theirs = format!("{before}\n# changed elsewhere\n");
    std::fs::write(&file, &theirs).expect("written");
    std::thread::sleep(std::time::Duration::from_millis(600));
    h.run_steps(3);
    assert_eq!(titles(&h)[0], "The robot arm, kept");
    assert!(
        h.query_by_label_contains("The file changed on disk")
            .is_some()
    );
    h.get_by_label("Save").click_accesskit();
    h.run_steps(3);
    assert_eq!(
        std::fs::read_to_string(&file).expect("reads"),
        theirs,
        "asked first"
    );
    h.get_by_label("Overwrite it with my edits")
        .click_accesskit();
    h.run_steps(3);
    assert_eq!(std::fs::read_to_string(&file).expect("reads"), edited);
    assert!(!dir.path().join("17-hierarchy.toml.unsaved").exists());
}

/// A move the checker would reject is not made: lesson 05's off-centre frustum (step 4) moved
/// before the step that sets fovy would leave that step a fovy the frustum has not. The editor
/// says why; the lesson, the file and the unsaved state are as they were.
#[test]
fn a_move_that_breaks_the_lesson_is_refused_with_the_reason() {
    let (_dir, file) = copy_of("05-perspective.toml");
    let mut h = super::lesson_harness(Some(file));
    h.run_steps(2);
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(3)));
    h.key_press(egui::Key::R);
    h.run_steps(3);
    let before = titles(&h);
    h.get_by_label("▲ Earlier").click_accesskit();
    h.run_steps(3);
    assert!(
        h.query_by_label_contains("Not done: the lesson would no longer pass the check")
            .is_some()
    );
    assert_eq!(titles(&h), before);
    assert_eq!(h.state().session.lesson.as_ref().map(|p| p.step), Some(3));
    assert!(h.query_by_label_contains("● unsaved").is_none());
}

/// A watch on screen is recorded where its step stands (it reads a line of the shaders in
/// effect there): lesson 24's debugger step, updated from the screen while the variable picture
/// draws `dot(n, l) < 0.0` after line 22, reads back with that watch.
#[test]
fn a_watch_is_recorded_into_the_step_it_is_drawn_in() {
    let (_dir, file) = copy_of("24-shader-programs.toml");
    let mut h = super::lesson_harness(Some(file));
    h.run_steps(2);
    let k = super::go_to_step_titled(&mut h, "The debugger: one fragment's run");
    assert_eq!(super::lesson_of(&h).steps[k].watch, None);
    h.key_press(egui::Key::R);
    h.run_steps(3);
    let watch = pipeline::shader::probe::WatchSpec::fragment(22, "dot(n, l) < 0.0");
    h.state_mut()
        .session
        .apply(Command::Selection(SelectionCommand::SetWatch(Some(
            watch.clone(),
        ))));
    h.run_steps(3);
    h.get_by_label(&format!("Update step {} from the screen", k + 1))
        .click_accesskit();
    h.run_steps(3);
    assert_eq!(super::lesson_of(&h).steps[k].watch, Some(watch));
}

/// A change of words while a step's animation has moved keeps the animation's time with the
/// screen it drew: a step recorded then sets nothing the teacher did not set. (Typing a title
/// in the editor restarted the player at time 0 while the screen kept the light where the
/// animation had left it, and the step was saved with that light's position in its `set`.)
#[test]
fn a_change_of_words_keeps_the_animations_time() {
    use pipelens::app::command::EditorCommand;
    let lesson = pipelens::lesson::library::lesson("10-blinn-phong.toml").expect("lesson 10");
    let doc = pipelens::lesson::Document::Lesson(Box::new(lesson.clone()));
    let mut s = pipelens::app::session::Session::with_document(doc, "10-blinn-phong", None);
    s.apply(Command::Lesson(LessonCommand::GoToStep(1)));
    assert!(
        !lesson.steps[1].animate.is_empty(),
        "step 2 moves its light"
    );
    // The step plays on entering it: 0.7 s in, it is paused.
    if !s.lesson.as_ref().is_some_and(|p| p.playing) {
        s.apply(Command::Lesson(LessonCommand::TogglePlay));
    }
    s.apply(Command::Lesson(LessonCommand::Tick(0.7)));
    s.apply(Command::Lesson(LessonCommand::TogglePlay));
    assert!(!s.lesson.as_ref().is_some_and(|p| p.playing));
    let mut edited = lesson;
    edited.steps[1].title.zh = "漫反射（改）".to_owned();
    s.apply(Command::Editor(EditorCommand::ReviseLesson {
        lesson: Box::new(edited),
        step: 1,
        enter: false,
    }));
    let player = s.lesson.as_ref().expect("a lesson");
    assert!((player.time - 0.7).abs() < 1e-6, "time {}", player.time);
    let step = pipelens::app::record::recorded_step(&s).expect("a step");
    assert!(step.set.is_empty(), "{:?}", step.set);
}

/// Lesson 10's step 2 moves its light. Its animation stopped each way a teacher stops one — the
/// play key, typing a word of the step then Escape, leaving the step and coming back — and the
/// screen recorded as a new step, the saved file's new steps set nothing: the light's passing
/// position is the step's animation's, not a value the teacher set. (A recorded step once
/// saved `lights.1.intensity = [2.058401, …]`, a value from the middle of an animation.)
#[test]
fn a_recorded_step_holds_no_value_an_animation_passed_through() {
    let (_dir, file) = copy_of("10-blinn-phong.toml");
    let mut h = super::lesson_harness(Some(file.clone()));
    h.run_steps(2);
    h.key_press(egui::Key::R);
    h.run_steps(3);
    let ways = ["the play key", "typing then Escape", "a step change"];
    for (n, way) in ways.iter().enumerate() {
        h.state_mut()
            .session
            .apply(Command::Lesson(LessonCommand::GoToStep(1)));
        h.run_steps(20);
        match n {
            0 => h.key_press(egui::Key::Space),
            1 => {
                // The current step's Chinese title, a word added, then Escape.
                type_into(&mut h, 1, "（改）");
                h.key_press(egui::Key::Escape);
            }
            _ => {
                for k in [2, 1] {
                    h.state_mut()
                        .session
                        .apply(Command::Lesson(LessonCommand::GoToStep(k)));
                    h.run_steps(15);
                }
            }
        }
        h.run_steps(10);
        let player = h.state().session.lesson.as_ref().expect("a lesson");
        assert!(
            player.step == 1 && player.time > 0.1,
            "{way}: step {} at {} s, its animation under way",
            player.step + 1,
            player.time
        );
        let words = [format!("Recorded after {way}"), format!("记录 {n}")];
        for (k, text) in words.iter().enumerate() {
            type_into(&mut h, 8 + k, text);
        }
        for (k, text) in ["What the room sees.", "观众所见。"].iter().enumerate() {
            type_into(&mut h, 10 + k, text);
        }
        h.get_by_label("＋ Add as step 3").click_accesskit();
        h.run_steps(3);
        assert_eq!(
            super::lesson_of(&h).steps[2].title.en,
            words[0],
            "{way}: the step was added"
        );
    }
    h.get_by_label("Save").click_accesskit();
    h.run_steps(3);
    let text = std::fs::read_to_string(&file).expect("saved");
    let saved = pipelens::lesson::script::parse_lesson(
        &text,
        "10-blinn-phong.toml",
        file.parent().expect("a folder"),
    )
    .expect("the saved lesson reads back");
    let recorded: Vec<_> = saved
        .steps
        .iter()
        .filter(|s| s.title.en.starts_with("Recorded after"))
        .collect();
    assert_eq!(recorded.len(), ways.len(), "every recorded step was saved");
    for step in recorded {
        assert!(
            step.set.is_empty() && step.animate.is_empty(),
            "{}: sets {:?}, animates {:?}",
            step.title.en,
            step.set,
            step.animate
        );
    }
}

/// A new lesson made from lesson 10's step 2 while its light is moving: its first step starts
/// where the step starts (the light at the animation's `from`, [-3, 2.5, 3] in the lesson's
/// file) and plays the same animation. (It was made with the light's passing position in its
/// `set`, [-2.9769993, 2.5, 3]: a value nobody set.)
#[test]
fn a_lesson_made_from_a_moving_step_starts_where_the_step_starts() {
    let (dir, source) = copy_of("10-blinn-phong.toml");
    let file = dir.path().join("moving.toml");
    let mut h = super::lesson_harness(Some(source));
    h.run_steps(2);
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(1)));
    h.run_steps(20);
    let time = h.state().session.lesson.as_ref().map_or(0.0, |p| p.time);
    assert!(time > 0.1, "the light is moving: {time} s into the step");
    h.key_press(egui::Key::R);
    h.run_steps(2);
    h.get_by_label("New lesson…").click_accesskit();
    h.run_steps(2);
    // From the scene on screen (the first choice); the last one-line box is the file's name.
    let n = h.get_all_by_role(Role::TextInput).count();
    replace_in(&mut h, n - 1, &file.display().to_string());
    h.get_by_label("Make the lesson").click_accesskit();
    h.run_steps(4);
    let text = std::fs::read_to_string(&file).expect("written");
    let made = pipelens::lesson::script::parse_lesson(&text, "moving.toml", dir.path())
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    let first = &made.steps[0];
    assert_eq!(
        param::get(&made.spec_at(0), "lights.1.position"),
        Some(Value::Vec3(glam::Vec3::new(-3.0, 2.5, 3.0))),
        "{text}"
    );
    let animate: Vec<_> = first
        .animate
        .iter()
        .map(|a| (a.param.as_str(), a.from.clone(), a.to.clone(), a.seconds))
        .collect();
    assert_eq!(
        animate,
        [(
            "lights.1.position",
            Value::Vec3(glam::Vec3::new(-3.0, 2.5, 3.0)),
            Value::Vec3(glam::Vec3::new(3.0, 2.5, 3.0)),
            5.0
        )],
        "{text}"
    );
    assert!(!text.contains("2.97"), "a passing value was kept:\n{text}");
}

/// The first change typed leaves every box where it was: the row of Undo, Redo and Save says
/// "● unsaved" in a word (its longer note wrapped to a second line and moved the boxes under
/// it down a line, so the next click landed a line off).
#[test]
fn typing_the_first_change_moves_no_box() {
    let (_dir, file) = copy_of("17-hierarchy.toml");
    let mut h = super::lesson_harness(Some(file));
    h.run_steps(2);
    h.key_press(egui::Key::R);
    h.run_steps(3);
    let boxes = |h: &Harness<'_, PipelensApp>| -> Vec<egui::Rect> {
        h.get_all_by_role(Role::TextInput)
            .chain(h.get_all_by_role(Role::MultilineTextInput))
            .map(|b| b.rect())
            .collect()
    };
    let before = boxes(&h);
    assert!(before.len() >= 4, "the editor's boxes: {before:?}");
    type_into(&mut h, 0, " arm");
    h.run_steps(2);
    assert!(h.query_by_label_contains("● unsaved").is_some());
    assert_eq!(boxes(&h), before, "the boxes moved");
    // The new step's title and narration worded in one language, then the other: the note
    // under them says what is still missing, then that both are there, and the Add button
    // stays where it was.
    let n = h.get_all_by_role(Role::MultilineTextInput).count();
    let add = |h: &Harness<'_, PipelensApp>| h.get_by_label_contains("Add as step").rect();
    type_into(&mut h, n - 4, "Next");
    type_into(&mut h, n - 2, "What comes next.");
    let waiting = add(&h);
    assert!(h.query_by_label_contains("Still needs: 中文").is_some());
    type_into(&mut h, n - 3, "下一步");
    type_into(&mut h, n - 1, "接下来是什么。");
    assert!(
        h.query_all_by_label_contains("Still needs")
            .next()
            .is_none()
    );
    assert_eq!(add(&h), waiting, "the Add button moved");
}
