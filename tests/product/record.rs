//! Recording a step from what is on screen (issue "A teacher builds a lesson in the app"): every
//! parameter reads back the value `set` gives it, and the parameters that differ between two
//! states of a scene are the `set` entries that lead from one to the other.

use pipelens::app::command::{LessonCommand, SceneCommand, SelectionCommand, ViewCommand};
use pipelens::lesson::param::{self, Value};

fn close(a: &Value, b: &Value) -> bool {
    let near = |x: f32, y: f32| (x - y).abs() <= 1e-5 * x.abs().max(y.abs()).max(1.0);
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => near(*x, *y),
        (Value::Vec3(x), Value::Vec3(y)) => (0..3).all(|k| near(x[k], y[k])),
        // `scale = 2` and `intensity = 1` read back as three equal numbers.
        (Value::Number(x), Value::Vec3(y)) | (Value::Vec3(y), Value::Number(x)) => {
            (0..3).all(|k| near(*x, y[k]))
        }
        _ => a == b,
    }
}

/// In every step of every lesson, every parameter the scene has reads back a value that `set`
/// accepts and that leaves the scene as it is.
#[test]
fn every_parameter_reads_back_what_set_gives_it() {
    let mut read = 0;
    for id in crate::support::lesson_files() {
        let lesson =
            crate::support::lesson(&id.file_stem().expect("a file name").to_string_lossy());
        for k in 0..lesson.steps.len() {
            let spec = lesson.spec_at(k);
            for name in param::names(&spec) {
                let Some(value) = param::get(&spec, &name) else {
                    continue;
                };
                read += 1;
                let mut again = spec.clone();
                param::apply(&mut again, &name, &value).unwrap_or_else(|e| {
                    panic!("{} step {}: {name} = {value}: {e}", id.display(), k + 1)
                });
                let back = param::get(&again, &name).expect("still there");
                assert!(close(&back, &value), "{name}: {value} read back as {back}");
                assert!(
                    param::differences(&spec, &again).is_empty(),
                    "{} step {}: setting {name} to its own value changed {:?}",
                    id.display(),
                    k + 1,
                    param::differences(&spec, &again)
                );
            }
        }
    }
    assert!(read > 1000, "only {read} values were read");
}

/// The differences between a step's scene and the one before it hold that step's `set` entries
/// (those that change something), and replayed from the step before they give the step's scene
/// back: what "record a step" would write leads where the lesson's author's entries lead.
#[test]
fn the_differences_between_two_steps_are_the_later_ones_set() {
    let mut compared = 0;
    for id in crate::support::lesson_files() {
        let lesson =
            crate::support::lesson(&id.file_stem().expect("a file name").to_string_lossy());
        for k in 1..lesson.steps.len() {
            let step = &lesson.steps[k];
            if step.exercise.is_some()
                || step
                    .set
                    .iter()
                    .any(|(n, _)| n.ends_with(".normals") || n == "projection.kind")
            {
                // An exercise's starter and a change of projection kind or normals rewrite
                // more than the entries name.
                continue;
            }
            let (before, after) = (lesson.spec_at(k - 1), lesson.spec_at(k));
            let found = param::differences(&before, &after);
            // Replayed from the step before, the differences give the step's scene back.
            let mut replay = before.clone();
            for (name, value) in &found {
                param::apply(&mut replay, name, value).unwrap_or_else(|e| {
                    panic!("{} step {}: {name} = {value}: {e}", id.display(), k + 1)
                });
            }
            assert!(
                param::differences(&replay, &after).is_empty()
                    && param::differences(&after, &replay).is_empty(),
                "{} step {}: replaying {found:?} leaves {:?}",
                id.display(),
                k + 1,
                param::differences(&replay, &after)
            );
            for (name, value) in &step.set {
                let changed = param::get(&before, name).is_none_or(|b| !close(&b, value));
                if changed {
                    assert!(
                        found.iter().any(|(n, _)| n == name),
                        "{} step {}: the step sets {name} = {value}, not found among {found:?}",
                        id.display(),
                        k + 1
                    );
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 20, "only {compared} set entries were compared");
}

/// Every step of every lesson that a recording could produce (no shaders, exercise or typed
/// answer), written back with `record::append_step`, reads as the same step, and the lesson file
/// around it is kept byte for byte.
#[test]
fn a_step_appended_to_a_lesson_reads_back_as_the_same_step() {
    let mut written = 0;
    for path in crate::support::lesson_files() {
        let text = std::fs::read_to_string(&path).expect("the lesson reads");
        let base = path.parent().expect("a folder");
        let lesson = pipelens::lesson::script::parse_lesson(&text, "lesson.toml", base)
            .unwrap_or_else(|e| panic!("{e}"));
        for (k, step) in lesson.steps.iter().enumerate() {
            if step.shader.is_some() || step.exercise.is_some() || step.expect.is_some() {
                assert!(pipelens::lesson::record::append_step(&text, step).is_err());
                continue;
            }
            // A watch reads a line of the shaders in effect where its step stands; appended
            // after the lesson's last step, the same line may be another statement. Its
            // recording is checked where it stands, in `app::recording`.
            if step.watch.is_some() {
                continue;
            }
            let out = pipelens::lesson::record::append_step(&text, step)
                .unwrap_or_else(|e| panic!("{} step {}: {e}", path.display(), k + 1));
            // The step goes in one place (after the last step, before a table that follows the
            // steps, such as `[comments.zh]`): the text before it and after it is kept.
            let before = text
                .bytes()
                .zip(out.bytes())
                .take_while(|(a, b)| a == b)
                .count();
            let after = text
                .bytes()
                .rev()
                .zip(out.bytes().rev())
                .take_while(|(a, b)| a == b)
                .count();
            assert!(
                before + after >= text.trim_end().len(),
                "{}: the file around the step changed",
                path.display()
            );
            let again = pipelens::lesson::script::parse_lesson(&out, "lesson.toml", base)
                .unwrap_or_else(|e| {
                    panic!(
                        "{} step {} written back:\n{e}\n{}",
                        path.display(),
                        k + 1,
                        &out[text.len().saturating_sub(10)..]
                    )
                });
            assert_eq!(again.steps.len(), lesson.steps.len() + 1);
            let last = again.steps.last().expect("the appended step");
            let label = format!("{} step {}", path.display(), k + 1);
            assert_eq!(last.title, step.title, "{label}");
            assert_eq!(last.narration, step.narration, "{label}");
            assert_eq!(
                (last.stage, last.layout, last.compare, last.buffer),
                (step.stage, step.layout, step.compare, step.buffer),
                "{label}"
            );
            assert_eq!(last.overlays, step.overlays, "{label}");
            assert_eq!(
                (&last.focus, last.orbit, last.pixel, last.vertex),
                (&step.focus, step.orbit, step.pixel, step.vertex),
                "{label}"
            );
            assert_eq!(
                (last.profile, last.depth_range),
                (step.profile, step.depth_range),
                "{label}"
            );
            assert_eq!(
                (&last.question, &last.answer),
                (&step.question, &step.answer),
                "{label}"
            );
            assert_eq!(last.set.len(), step.set.len(), "{label}");
            for ((n, v), (m, w)) in last.set.iter().zip(&step.set) {
                assert!(
                    n == m && close(v, w),
                    "{label}: {n} = {v} against {m} = {w}"
                );
            }
            assert_eq!(last.animate, step.animate, "{label}");
            written += 1;
        }
    }
    assert!(written > 100, "only {written} steps were written back");
}

/// What is on screen becomes a step: in lesson 17 at step 1, with the base turned to 50°, a
/// pixel inspected and the observer on and turned, the recorded step names the stage, the
/// layout, the pixel, the observer's direction and the one parameter changed; appended to the lesson file it reads back,
/// and replayed from the step before it gives the scene on screen.
#[test]
fn the_state_on_screen_is_recorded_as_a_step() {
    use pipelens::app::session::{Command, Session};
    use pipelens::lesson::script::Layout;
    let path = crate::support::repo().join("lessons/17-hierarchy.toml");
    let doc = pipelens::lesson::load_file(&path).expect("the lesson loads");
    let mut s = Session::with_document(doc, "test", None);
    s.apply(Command::Lesson(LessonCommand::GoToStep(0)));
    let mut spec = s.spec.clone();
    param::apply(&mut spec, "figures.arm.base", &Value::Number(50.0)).expect("a joint");
    s.apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    s.apply(Command::Selection(SelectionCommand::SelectPixel(Some((
        120, 80,
    )))));
    // The observer untouched: no direction to write, every observer starts from the default.
    let untouched = pipelens::app::record::recorded_step(&s).expect("a lesson is open");
    assert_eq!(untouched.orbit, None);
    // Turned by a drag that went once round and a little more: −335.04° round is 24.96°,
    // written to a tenth of a degree as 25°; 20.04° up as 20°.
    let mut turned = s.orbit;
    (turned.yaw, turned.pitch) = (-335.04, 20.04);
    s.apply(Command::View(ViewCommand::SetOrbit(turned)));
    let step = pipelens::app::record::recorded_step(&s).expect("a lesson is open");
    assert_eq!(step.orbit, Some([25.0, 20.0]));
    assert_eq!(step.stage, Some(pipelens::vocabulary::Stage::World));
    assert_eq!(step.layout, Layout::Observer);
    assert_eq!(step.pixel, Some((120, 80)));
    assert_eq!(step.focus.as_deref(), Some(&["arm".to_owned()][..]));
    assert_eq!(step.title.en, "World");
    let changed: Vec<&str> = step.set.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(changed, ["figures.arm.base"], "{:?}", step.set);
    let text = std::fs::read_to_string(&path).expect("the lesson reads");
    // Not worded yet: refused with a message, the file untouched.
    let refused = pipelens::lesson::record::append_step(&text, &step).expect_err("no words yet");
    assert!(refused.contains("English and Chinese"), "{refused}");
    // As the teacher words it.
    let mut step = step;
    step.narration = pipelens::vocabulary::Text::new("The base turned to 50°.", "支架转到 50°。");
    // After the step on screen (the first), before the second and its comment.
    let out = pipelens::lesson::record::insert_step(&text, 1, &step).expect("written");
    let again = pipelens::lesson::script::parse_lesson(
        &out,
        "lesson.toml",
        path.parent().expect("a folder"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(again.steps.len(), 6);
    assert_eq!(again.steps[1], step);
    assert!(out.contains("\norbit = [25, 20]\n"), "{out}");
    // Played, the new step's observer looks from where the teacher turned it.
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("17-hierarchy.toml");
    std::fs::write(&file, &out).expect("written");
    let mut played = Session::with_document(
        pipelens::lesson::load_file(&file).expect("the recorded lesson loads"),
        "test",
        None,
    );
    played.apply(Command::Lesson(LessonCommand::GoToStep(1)));
    assert_eq!((played.orbit.yaw, played.orbit.pitch), (25.0, 20.0));
    played.apply(Command::Lesson(LessonCommand::GoToStep(2)));
    assert_eq!((played.orbit.yaw, played.orbit.pitch), (60.0, 30.0));
    let lesson = pipelens::lesson::script::parse_lesson(
        &text,
        "lesson.toml",
        path.parent().expect("a folder"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        again.steps[2..],
        lesson.steps[1..],
        "the steps after it are unchanged"
    );
    // Replayed, the new step shows the scene that was on screen.
    assert!(param::differences(&again.spec_at(1), &s.spec).is_empty());
    // Every line of the file is still there, in order, the new step's lines among them.
    let mut lines = out.lines();
    for line in text.lines() {
        assert!(lines.any(|l| l == line), "lost: {line}");
    }
}
