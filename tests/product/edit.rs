//! Editing a lesson in the app (issue "A teacher builds a lesson in the app"), without a window:
//! steps moved, copied, deleted, updated and reworded through `lesson::edit::Draft`, each change
//! undone and redone, the file's other lines kept, and the text read back as the lesson the
//! changes describe.

use pipelens::lesson::edit::{Draft, Words};
use pipelens::lesson::{Lesson, library};
use pipelens::vocabulary::Lang;
use std::path::Path;

fn draft(file: &str) -> Draft {
    let text = library::LESSONS
        .iter()
        .find(|(f, _)| *f == file)
        .expect("a built-in lesson")
        .1;
    Draft::new(text, file, Path::new("lessons")).expect("a lesson file")
}

fn lesson(d: &Draft) -> Lesson {
    d.lesson().unwrap_or_else(|e| panic!("{e}\n{}", d.text()))
}

fn titles(l: &Lesson) -> Vec<String> {
    l.steps.iter().map(|s| s.title.en.clone()).collect()
}

/// The lines of `text`, sorted: a move changes where lines are, not what they say.
fn sorted_lines(text: &str) -> Vec<&str> {
    let mut v: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    v.sort_unstable();
    v
}

/// The steps' tables as the file writes them, in the order a reader finds them.
fn step_tables(text: &str) -> Vec<String> {
    let doc: toml_edit::DocumentMut = text.parse().expect("TOML");
    doc["steps"]
        .as_array_of_tables()
        .expect("steps")
        .iter()
        .map(ToString::to_string)
        .collect()
}

/// Every step of every built-in lesson moved to the front is read back first, the others in
/// their order, with the same lines in the file; undone, the file is what it was, byte for byte.
/// (A step moved before the one whose `set` it builds on may no longer check: a move is the
/// teacher's to judge, and the app shows `check`'s message.)
#[test]
fn a_moved_step_reads_back_in_its_new_place_and_undo_restores_the_file() {
    let mut moved = 0;
    for (file, text) in library::LESSONS {
        let mut d = draft(file);
        let before = step_tables(text);
        for from in 1..d.len() {
            d.move_step(from, 0).expect("moved");
            let mut want = before.clone();
            let s = want.remove(from);
            want.insert(0, s);
            assert_eq!(
                step_tables(d.text()),
                want,
                "{file}: step {} to the front",
                from + 1
            );
            assert_eq!(sorted_lines(d.text()), sorted_lines(text), "{file}");
            // Moving one step marks that step, not those it passed (when the one before it
            // moves to the front, either of the two is the one moved).
            let marked: Vec<usize> = (0..d.len()).filter(|&k| d.changed(k)).collect();
            assert!(
                marked == [0] || (from == 1 && marked == [1]),
                "{file}: step {} moved to the front marks {marked:?}",
                from + 1
            );
            assert!(d.undo());
            assert_eq!(d.text(), text, "{file}: undone");
            moved += 1;
        }
        // Moved back where it was, the file is as it was too.
        d.move_step(1, 0).expect("moved");
        d.move_step(0, 1).expect("moved back");
        assert_eq!(d.text(), text, "{file}: moved and moved back");
        assert!(!d.is_dirty());
        lesson(&d);
    }
    assert!(moved > 100, "{moved} moves");
}

/// A copy, a deletion and a move, undone one by one and redone, give each state back; the
/// steps changed since the save are the ones touched.
#[test]
fn every_edit_is_undone_and_redone() {
    let mut d = draft("05-perspective.toml");
    let original = d.text().to_owned();
    let names = titles(&lesson(&d));
    d.duplicate(1).expect("copied");
    let copied = d.text().to_owned();
    assert_eq!(titles(&lesson(&d))[1], titles(&lesson(&d))[2]);
    assert_eq!(
        d.changed_steps(),
        (0..d.len()).map(|k| k == 2).collect::<Vec<_>>(),
        "the copy is marked; the steps after it moved down one, not out of order"
    );
    d.delete(0).expect("deleted");
    let deleted = d.text().to_owned();
    assert_eq!(d.deleted(), 1);
    d.move_step(0, 2).expect("moved");
    let l = lesson(&d);
    assert_eq!(l.steps.len(), names.len());
    assert_eq!(titles(&l)[2], names[1]);
    assert!(d.undo() && d.text() == deleted);
    assert!(d.undo() && d.text() == copied);
    assert!(d.undo() && d.text() == original);
    assert!(!d.undo(), "nothing before the file as opened");
    assert!(!d.is_dirty() && (0..d.len()).all(|k| !d.changed(k)));
    assert!(d.redo() && d.text() == copied);
    assert!(d.redo() && d.text() == deleted);
    d.mark_saved();
    assert!(!d.is_dirty() && (0..d.len()).all(|k| !d.changed(k)));
    assert!(d.delete(0).is_ok());
    while d.len() > 1 {
        d.delete(0).expect("deleted");
    }
    assert!(d.delete(0).is_err(), "a lesson keeps one step");
    lesson(&d);
}

/// Words typed in the editor land in the step's `title`, `narration` (multi-line, as the file
/// writes it: `"""…"""`), `question` and `answer`, both languages side by side; typing on in one
/// box is one change to undo; a comment after a value survives; an emptied question goes.
#[test]
fn words_typed_in_the_editor_are_the_steps_words() {
    let mut d = draft("05-perspective.toml");
    let original = d.text().to_owned();
    let narration = "The frustum **grows** with fovy.\n\n- top = near·tan(fovy/2)";
    for k in 1..=narration.len() {
        if narration.is_char_boundary(k) {
            d.set_words(0, Words::Narration, Lang::EN, &narration[..k])
                .expect("typed");
        }
    }
    d.set_words(0, Words::Narration, Lang::ZH, "视锥随 fovy 变大。")
        .expect("typed");
    d.set_words(0, Words::Title, Lang::ZH, "视锥体")
        .expect("typed");
    d.set_words(0, Words::Question, Lang::EN, "What grows?")
        .expect("typed");
    d.set_words(0, Words::Question, Lang::ZH, "什么变大？")
        .expect("typed");
    let l = lesson(&d);
    let s = &l.steps[0];
    assert_eq!(s.narration.en.trim_end(), narration);
    assert_eq!(s.narration.zh.trim_end(), "视锥随 fovy 变大。");
    assert_eq!(s.title.zh, "视锥体");
    let q = s.question.as_ref().expect("a question");
    assert_eq!(
        (q.en.as_str(), q.zh.as_str()),
        ("What grows?", "什么变大？")
    );
    assert_eq!(d.words(0, Words::Question).en, "What grows?");
    assert!(
        d.text().contains("\"\"\""),
        "multi-line words stay multi-line strings"
    );
    // The rest of the file is as it was: only the first step's lines differ.
    let first_step = original.find("[[steps]]").expect("steps");
    let second_step = original[first_step + 1..]
        .find("[[steps]]")
        .expect("a second")
        + first_step
        + 1;
    assert!(d.text().starts_with(&original[..first_step]));
    assert!(d.text().ends_with(&original[second_step..]));
    // Five boxes typed in: five changes to undo, however many keys.
    for _ in 0..5 {
        assert!(d.undo());
    }
    assert_eq!(d.text(), original);
    // The lesson's own title and summary, in `[lesson]`, whichever step is asked.
    d.set_words(3, Words::LessonTitle, Lang::EN, "Perspective, by hand")
        .expect("typed");
    d.set_words(0, Words::Summary, Lang::ZH, "透视投影，一步一步。")
        .expect("typed");
    let l = lesson(&d);
    assert_eq!(l.title.en, "Perspective, by hand");
    assert_eq!(l.summary.zh, "透视投影，一步一步。");
    assert_eq!(d.words(1, Words::LessonTitle).en, "Perspective, by hand");
    assert!(d.undo() && d.undo());
    assert_eq!(d.text(), original);
    // A question emptied in both languages is gone from the file.
    d.set_words(0, Words::Question, Lang::EN, "Why?")
        .expect("typed");
    d.set_words(0, Words::Question, Lang::EN, "")
        .expect("typed");
    assert_eq!(d.text(), original);
}

/// "Update step": the step shows what is on screen now, its words kept.
#[test]
fn an_updated_step_shows_the_screen_and_keeps_its_words() {
    let mut d = draft("05-perspective.toml");
    let before = lesson(&d);
    let mut shown = before.steps[2].clone();
    shown.pixel = Some((12, 34));
    shown.set = vec![(
        "projection.fovy".to_owned(),
        pipelens::lesson::param::Value::Number(70.0),
    )];
    shown.title.en = "not this".to_owned();
    d.update(1, &shown).expect("updated");
    let after = lesson(&d);
    let s = &after.steps[1];
    assert_eq!(s.pixel, Some((12, 34)));
    assert_eq!(s.set, shown.set);
    assert_eq!(s.stage, shown.stage);
    assert_eq!(s.title, before.steps[1].title, "the words are kept");
    assert_eq!(s.narration, before.steps[1].narration);
    assert_eq!(s.question, before.steps[1].question);
    assert!(d.changed(1) && !d.changed(0) && !d.changed(2));
}

/// A new lesson's first text reads back through the checker: the template on a mesh of one's
/// own, a built-in lesson renamed, and the scene of a lesson with one step recorded on it (the
/// lesson's comments taken out; a scene file's kept).
#[test]
fn a_new_lesson_starts_from_a_mesh_a_built_in_lesson_or_the_scene_on_screen() {
    use pipelens::lesson::start;
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("mine.toml");
    std::fs::write(
        dir.path().join("tri.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .expect("written");
    let check = |text: &str| {
        pipelens::lesson::script::parse_lesson(text, "mine.toml", dir.path())
            .unwrap_or_else(|e| panic!("{e}\n{text}"))
    };
    let on_mesh = check(&start::from_mesh(&file, "tri.obj").expect("made"));
    assert_eq!((on_mesh.id.as_str(), on_mesh.steps.len()), ("mine", 1));
    let tour = library::LESSONS[0].1;
    let renamed = check(&start::renamed(tour, &file).expect("made"));
    assert_eq!(renamed.id, "mine");
    assert_eq!(
        renamed.steps,
        check(&tour.replacen("00-tour", "mine", 1)).steps
    );
    let lesson = check(&tour.replacen("00-tour", "mine", 1));
    let mut step = lesson.steps[3].clone();
    step.set = vec![(
        "projection.fovy".to_owned(),
        pipelens::lesson::param::Value::Number(60.0),
    )];
    let text = start::from_scene(tour, &file, &step).expect("made");
    let scene = check(&text);
    assert_eq!(scene.steps, vec![step.clone()]);
    assert_eq!(scene.scene, lesson.scene, "the same scene");
    // The tour's comments speak of its own steps: none is kept (they were, and a teacher's
    // new lesson started from lesson 10 explained lesson 10's lights).
    assert!(
        tour.lines().any(|l| l.trim_start().starts_with('#')),
        "the tour has comments"
    );
    let commented: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with('#') || l.contains(" # "))
        .collect();
    assert!(
        commented.is_empty(),
        "the tour's comments kept: {commented:?}"
    );
    assert!(
        !text.contains("\n\n\n"),
        "a comment's lines left blank:\n{text}"
    );
    // Lesson 10's `[comments.zh]` translate its labs' shader comments: a new lesson from its
    // scene, which runs no shader, leaves them behind.
    let lights = library::LESSONS[10].1;
    assert!(
        lights.contains("[comments.zh]"),
        "lesson 10 has shader comments"
    );
    let on_lights = start::from_scene(lights, &file, &step).expect("made");
    check(&on_lights);
    assert!(
        !on_lights.contains("[comments"),
        "lesson 10's shader comments kept:\n{on_lights}"
    );
    // A scene file's comments are the scene's own, and stay.
    let robot = std::fs::read_to_string(crate::support::repo().join("assets/scenes/robot.toml"))
        .expect("the robot scene");
    let on_robot = start::from_scene(&robot, &file, &step).expect("made");
    check(&on_robot);
    for comment in robot.lines().filter(|l| l.starts_with('#')) {
        assert!(on_robot.contains(comment), "{comment} was kept");
    }
    assert!(start::from_mesh(std::path::Path::new("no-extension"), "tri.obj").is_err());
}
