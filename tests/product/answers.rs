//! Answers the student types (`expect`): the field under a question, checked entry by entry,
//! what is said when it is off, and the progress kept across runs by the app's storage and
//! shown in the Lessons menu.

use std::collections::HashMap;

use egui_kittest::kittest::Queryable;
use pipelens::app::command::{LessonCommand, ViewCommand};
use pipelens::app::progress::Progress;
use pipelens::app::session::Command;

use crate::app::sized_lesson_harness;
use crate::support::repo;

/// The app's storage as eframe gives it, in memory (on disk it is a file, in a page local
/// storage; both store these strings).
#[derive(Default)]
struct Memory(HashMap<String, String>);

impl eframe::Storage for Memory {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_owned(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}

/// Goes to the open lesson's first question with a value to type.
fn go_to_the_typed_question(h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>) {
    let k = crate::app::lesson_of(h)
        .steps
        .iter()
        .position(|s| s.expect.is_some())
        .expect("the lesson has a question with a value");
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(k)));
    h.run_steps(4);
}

/// Types `cells` into the answer field's boxes, row by row, and presses Check.
fn type_and_check(h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>, cells: &[&str]) {
    let boxes = h.get_all_by_role(egui::accesskit::Role::TextInput).count();
    assert_eq!(boxes, cells.len(), "the field has one box per entry");
    for (i, text) in cells.iter().enumerate() {
        h.state_mut()
            .session
            .apply(Command::Lesson(LessonCommand::TypeAnswer {
                cell: i,
                text: (*text).to_owned(),
            }));
    }
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(3);
}

/// Lesson 05's matrix question (Frustum for l = −1, r = 1, b = −1, t = 1, n = 1, f = 3): a
/// wrong third row is named cell by cell with how much it is off, the right matrix passes, and
/// the step stays answered after the app is closed and opened again.
#[test]
fn a_typed_matrix_is_checked_entry_by_entry_and_remembered_across_runs() {
    let path = repo().join("lessons/05-perspective.toml");
    let mut h = sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(2)));
    h.run_steps(4);
    let wrong = [
        "1", "0", "0", "0", "0", "1", "0", "0", "0", "0", "-1", "-2", "0", "0", "-1", "0",
    ];
    type_and_check(&mut h, &wrong);
    let said = h
        .query_all_by_label_contains("Not yet")
        .next()
        .map(|n| format!("{n:?}"))
        .expect("a mismatch is explained");
    assert!(
        said.contains("2 of 16 off")
            && said.contains("row 3, column 3 = -1 is 1 too large")
            && said.contains("row 3, column 4 = -2 is 1 too large"),
        "{said}"
    );
    let lesson = crate::app::lesson_of(&h);
    assert!(!h.state().session.progress.answered(&lesson, 2));
    // Typed as a student might: expressions and a comma for the decimal point.
    let right = [
        "2/(1+1)",
        "0",
        "0",
        "0",
        "0",
        "1,0",
        "0",
        "0",
        "0",
        "0",
        "-(3+1)/(3-1)",
        "-2*3*1/2",
        "0",
        "0",
        "-1",
        "0",
    ];
    type_and_check(&mut h, &right);
    assert!(
        h.query_by_label_contains("Right: every entry within ±0.0005")
            .is_some()
    );
    assert!(h.state().session.progress.answered(&lesson, 2));
    assert_eq!(h.state().session.progress.done(&lesson), (1, 2));

    // Closing saves to the storage; the next run loads it and the card says so.
    let mut storage = Memory::default();
    h.state().session.progress.save(&mut storage);
    let kept = Progress::load(Some(&storage));
    assert_eq!(kept, h.state().session.progress);
    let mut again = sized_lesson_harness(&path, [1920.0, 1080.0]);
    again.state_mut().session.progress = kept;
    again
        .state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(2)));
    again.run_steps(4);
    assert!(
        again
            .query_by_label_contains("answered right before")
            .is_some()
    );
    // The typed cells were kept too.
    let boxes: Vec<String> = again
        .get_all_by_role(egui::accesskit::Role::TextInput)
        .map(|n| n.value().unwrap_or_default())
        .collect();
    assert_eq!(boxes[10], "-(3+1)/(3-1)");
    // The Lessons menu counts it: 1 of lesson 05's 2 questions with a value to type.
    again.get_by_label("Lessons").click();
    again.run_steps(2);
    assert!(
        again
            .query_by_label_contains("Perspective projection   1/2")
            .is_some()
    );
}

/// In Chinese the verdict names the entry in Chinese; an empty cell is named, not graded.
#[test]
fn the_verdict_speaks_chinese_and_names_empty_cells() {
    let path = repo().join("lessons/14-mipmaps.toml");
    let mut h = sized_lesson_harness(&path, [1366.0, 768.0]);
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SetLang(
            pipelens::vocabulary::Lang::ZH,
        )));
    go_to_the_typed_question(&mut h);
    h.get_by_label("检查").click();
    h.run_steps(3);
    assert!(h.query_by_label_contains("尚未填写：你的数值").is_some());
    h.get_by_role(egui::accesskit::Role::TextInput).focus();
    h.run_steps(2);
    h.get_by_role(egui::accesskit::Role::TextInput)
        .type_text("2");
    h.run_steps(3);
    h.get_by_label("检查").click();
    h.run_steps(3);
    assert!(h.query_by_label_contains("你的数值 = 2 小了 1").is_some());
}

/// The value each lesson's question expects, computed again here from the core's functions
/// (the course's matrices, de Casteljau, the shadow projection) or by hand from the question's
/// numbers, keyed by lesson id and the question's first words. A question with `expect` that
/// is not here fails the test: every typed answer is checked against an independent reference.
fn references() -> Vec<(&'static str, &'static str, Vec<f64>)> {
    use glam::{Vec2, Vec3, Vec4Swizzles};
    use pipeline::transform as projection;
    use pipeline::transform;
    let v = |a: &[f32]| a.iter().map(|&x| f64::from(x)).collect::<Vec<f64>>();
    let rad = f32::to_radians;
    let corner = (transform::translate(Vec3::new(1.5, 0.0, 0.0))
        * transform::rotate_y(rad(90.0))
        * transform::scale(Vec3::splat(0.5)))
    .transform_point3(Vec3::ONE);
    let [_, right, _, top] = projection::perspective_bounds(90.0, 1.0, 1.0);
    let frustum = transform::to_rows(&projection::frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 3.0).matrix);
    let clip = glam::Vec4::new(2.0, 1.0, 3.0, 4.0);
    let window = projection::viewport(640.0, 400.0) * (clip / clip.w);
    let (n, l, eye) = (Vec3::Y, Vec3::new(0.6, 0.8, 0.0), Vec3::Y);
    let r = 2.0 * n.dot(l) * n - l;
    let h = (l + eye).normalize();
    let lambda_over_w = [0.5 / 1.0, 0.5 / 3.0, 0.0];
    let sum: f32 = lambda_over_w.iter().sum();
    let shadow = projection::planar_shadow(Vec3::new(1.0, 5.0, 1.0)).matrix
        * Vec3::new(-0.5, 1.2, 0.0).extend(1.0);
    let elbow = (transform::translate(Vec3::new(-1.2, 0.0, 0.0))
        * transform::rotate_y(rad(30.0))
        * transform::translate(Vec3::new(0.0, 0.4, 0.0))
        * transform::rotate_z(rad(25.0)))
    .transform_point3(Vec3::new(0.0, 1.2, 0.0));
    let curve = [Vec2::ZERO, Vec2::Y, Vec2::ONE, Vec2::X];
    let b = pipeline::bezier::point(&curve, 0.5);
    let lens = projection::perspective(45.0, 1.6, 0.1, 50.0).matrix;
    vec![
        (
            "01-transforms",
            "The cube’s corner (1, 1, 1)",
            v(&corner.to_array()),
        ),
        ("05-perspective", "With fovy = 90°", v(&[top, right])),
        (
            "05-perspective",
            "Type the matrix Frustum",
            v(&frustum.concat()),
        ),
        (
            "06-clipping-ndc-viewport",
            "A vertex has clip coordinates (2, 1, 3, 4)",
            v(&window.xyz().to_array()),
        ),
        (
            "10-blinn-phong",
            "At a point n = (0, 1, 0)",
            v(&[r.dot(eye), n.dot(h), r.dot(eye).powi(32), n.dot(h).powi(32)]),
        ),
        (
            "12-interpolation",
            "At a pixel, λ = (0.5, 0.5, 0)",
            v(&lambda_over_w.map(|x| x / sum)),
        ),
        (
            "14-mipmaps",
            "A 1024×1024 texture",
            v(&[(1024.0f32 / 128.0).log2()]),
        ),
        (
            "16-planar-shadows",
            "The light is at (1, 5, 1).",
            v(&(shadow.xyz() / shadow.w).to_array()),
        ),
        (
            "17-hierarchy",
            "The base has height 0.4",
            v(&elbow.to_array()),
        ),
        (
            "18-bezier",
            "For the control points (0, 0), (0, 1), (1, 1), (1, 0)",
            v(&b.to_array()),
        ),
        (
            "25-lab-model-projection",
            "Where does Rz(30°) send",
            v(&transform::rotate_z(rad(30.0))
                .transform_point3(Vec3::ONE)
                .to_array()),
        ),
        (
            "25-lab-model-projection",
            "With fovy = 45° and aspect = 1.6",
            v(&[lens.y_axis.y, lens.x_axis.x]),
        ),
        (
            "23-beyond-mipmaps",
            "A 4×4 texture's summed-area table",
            vec![(160.0 - 40.0 - 40.0 + 10.0) / 9.0],
        ),
    ]
}

#[test]
fn every_typed_value_agrees_with_an_independent_reference() {
    let references = references();
    let mut checked = 0;
    for path in crate::support::lesson_files() {
        let Ok(pipelens::lesson::Document::Lesson(lesson)) = pipelens::lesson::load_file(&path)
        else {
            panic!("{} loads as a lesson", path.display());
        };
        for (k, step) in lesson.steps.iter().enumerate() {
            let (Some(e), Some(q)) = (&step.expect, &step.question) else {
                continue;
            };
            let reference = references
                .iter()
                .find(|(id, start, _)| *id == lesson.id && q.en.starts_with(start))
                .unwrap_or_else(|| {
                    panic!(
                        "{} step {}: no reference computes its `expect`",
                        lesson.id,
                        k + 1
                    )
                });
            assert_eq!(
                e.values.len(),
                reference.2.len(),
                "{} step {}",
                lesson.id,
                k + 1
            );
            for (i, (got, want)) in e.values.iter().zip(&reference.2).enumerate() {
                assert!(
                    (got - want).abs() <= e.tolerance / 2.0,
                    "{} step {}, entry {}: the lesson expects {got}, the reference gives {want}",
                    lesson.id,
                    k + 1,
                    i + 1
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, references.len(), "every reference is used");
}

/// A pass egui discards (a new grid's sizing pass, a resize) is followed by one with no input
/// events: what the app was asked in the discarded pass must still happen, once — a character
/// typed then enters once, neither lost nor doubled.
#[test]
fn a_character_typed_during_a_discarded_pass_enters_once() {
    let path = repo().join("lessons/14-mipmaps.toml");
    let doc = pipelens::lesson::load_file(&path).expect("the lesson loads");
    let session = pipelens::app::session::Session::with_document(doc, "test", None);
    let mut h = egui_kittest::Harness::builder()
        .with_size([1366.0, 768.0])
        .with_context_setup(pipelens::app::setup_context)
        .with_max_steps(200)
        .build_ui_state(
            |ui, app: &mut pipelens::app::PipelensApp| {
                // As egui does when something's size is not known yet: this pass is redone.
                if ui.input(|i| i.events.iter().any(|e| matches!(e, egui::Event::Text(_)))) {
                    ui.ctx().request_discard("a sizing pass while typing");
                }
                app.frame(ui);
            },
            pipelens::app::PipelensApp::new(session),
        );
    go_to_the_typed_question(&mut h);
    h.get_by_role(egui::accesskit::Role::TextInput).focus();
    h.run_steps(2);
    h.get_by_role(egui::accesskit::Role::TextInput)
        .type_text("3");
    h.run_steps(3);
    assert_eq!(
        h.get_by_role(egui::accesskit::Role::TextInput)
            .value()
            .as_deref(),
        Some("3")
    );
}

/// Two windows (or browser tabs) of the app save into one storage: each keeps what the other
/// recorded.
#[test]
fn two_windows_saving_keep_each_others_progress() {
    let path = repo().join("lessons/05-perspective.toml");
    let mut storage = Memory::default();
    let mut first = sized_lesson_harness(&path, [1366.0, 768.0]);
    let second = sized_lesson_harness(&path, [1366.0, 768.0]);
    first
        .state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::GoToStep(1)));
    first.run_steps(3);
    type_and_check(&mut first, &["1", "1"]);
    first.state().session.progress.save(&mut storage);
    // The second window answered nothing; its save must not erase the first's answer.
    second.state().session.progress.save(&mut storage);
    let lesson = crate::app::lesson_of(&first);
    let kept = Progress::load(Some(&storage));
    assert!(kept.answered(&lesson, 1), "{kept:?}");
}

/// Progress kept by the first version, which stored each kind of the student's functions in a
/// field of its own, is read into this version's map by kind: nothing a student ran is lost.
/// What is written back is this version's form, and a kind this version does not know (kept by
/// a newer one) stays.
#[test]
fn progress_kept_by_the_first_version_is_read_and_nothing_is_lost() {
    use pipelens::lesson::{Document, load_file};
    use pipeline::shader::HookKind;
    let Ok(Document::Lesson(lesson)) = load_file(&repo().join("lessons/07-rasterization.toml"))
    else {
        panic!("lesson 07 loads")
    };
    let mut storage = Memory::default();
    // Written by hand as the first version's RON: steps 4 and 6 of lesson 07, a curve in step 2.
    let old = r#"(lessons:{"07-rasterization":(answered:[1],typed:{1:["2"]},passed:[6],code:{},inside:{4:"bool inside4",6:"bool inside6"},depth_test:{6:"bool depth6"},curve:{2:"vec2 curve2"},shadow_matrix:{},bezier_patch:{})})"#;
    eframe::Storage::set_string(&mut storage, Progress::KEY, old.to_owned());
    let kept = Progress::load(Some(&storage));
    let record = kept
        .of("07-rasterization")
        .expect("the lesson's record is read");
    assert_eq!(record.functions["inside"][&4], "bool inside4");
    assert_eq!(record.functions["depth_test"][&6], "bool depth6");
    assert_eq!(record.functions["de_casteljau"][&2], "vec2 curve2");
    assert!(kept.answered(&lesson, 0) && kept.passed(&lesson, 5));
    // Step 6 (index 5) gives back both of its functions, by kind.
    let code = kept.code(&lesson, 5).expect("step 6's code is kept");
    assert_eq!(
        code.hooks,
        vec![
            (HookKind::Inside, "bool inside6".to_owned()),
            (HookKind::DepthTest, "bool depth6".to_owned())
        ]
    );
    // A newer version's kind survives a save by this one.
    let newer = r#"(lessons:{"07-rasterization":(answered:[],typed:{},passed:[],code:{},functions:{"a_later_kind":{3:"src"}})})"#;
    let mut other = Memory::default();
    eframe::Storage::set_string(&mut other, Progress::KEY, newer.to_owned());
    kept.save(&mut other);
    let written = eframe::Storage::get_string(&other, Progress::KEY).expect("saved");
    assert!(!written.contains("bezier_patch"), "{written}");
    let again = Progress::load(Some(&other));
    let record = again.of("07-rasterization").expect("read back");
    assert_eq!(record.functions["a_later_kind"][&3], "src");
    assert_eq!(record.functions["inside"][&4], "bool inside4");
}

/// Lesson 25's question asks for f = cot(fovy/2) and f/aspect, two numbers that are not a
/// vector's x and y: the boxes are named "f" and "f/aspect" (beside them, and for a screen
/// reader), the prompt asks for values, not components, and a wrong entry is named so in the
/// verdict. f = 2.414 right and f/aspect typed as 1.6 (the aspect itself): 1.6 − 1.50888 =
/// 0.09112 too large, by hand, said to four digits.
#[test]
fn the_entries_of_a_value_that_is_not_a_vector_are_named_as_the_question_names_them() {
    let path = repo().join("lessons/25-lab-model-projection.toml");
    let mut h = sized_lesson_harness(&path, [1366.0, 768.0]);
    crate::app::go_to_step(&mut h, 3);
    assert!(crate::app::lesson_of(&h).steps[3].expect.is_some());
    assert!(
        h.query_by_label("f/aspect").is_some(),
        "the name over the box"
    );
    // Each box is named by the name beside it, and has no x or y hint.
    let boxes: Vec<(Option<String>, Option<String>)> = h
        .get_all_by_role(egui::accesskit::Role::TextInput)
        .map(|b| {
            use egui_kittest::kittest::NodeT as _;
            let n = b.accesskit_node();
            (
                n.label(),
                n.placeholder().filter(|p| !p.is_empty()).map(str::to_owned),
            )
        })
        .collect();
    assert_eq!(
        boxes,
        [
            (Some("f".to_owned()), None),
            (Some("f/aspect".to_owned()), None)
        ]
    );
    assert!(
        h.query_by_label_contains("Type the 2 values").is_some(),
        "the prompt"
    );
    type_and_check(&mut h, &["2.414", "1.6"]);
    assert!(
        h.query_by_label_contains("f/aspect = 1.6 is 0.0911 too large")
            .is_some(),
        "the verdict names f/aspect"
    );
}
