//! Exports from the app: a lesson's handout and slides from the Export menu.

use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;

#[test]
fn the_export_menu_writes_the_lessons_handout_and_slides_in_the_interfaces_language() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/08-antialiasing.toml");
    let doc = pipelens::lesson::load_file(&lesson).expect("the lesson loads");
    let pipelens::lesson::Document::Lesson(l) = &doc else {
        panic!("a lesson");
    };
    let expected = l.steps.len();
    let session = pipelens::app::session::Session::with_document(doc, "test", None);
    let app = PipelensApp::new(session).exporting_to(dir.path());
    let mut h = egui_kittest::Harness::builder()
        .with_size([1366.0, 768.0])
        .with_context_setup(pipelens::app::setup_context)
        .with_max_steps(200)
        .build_ui_state(|ui, app: &mut PipelensApp| app.frame(ui), app);
    h.run_steps(2);
    h.get_by_label("中文").click();
    h.run_steps(2);
    h.get_by_label("导出 ▾").click();
    h.run_steps(2);
    h.get_by_label("导出讲义与幻灯片").click();
    h.run_steps(2);
    for _ in 0..600 {
        if !h.state().exporting() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
        h.run_steps(1);
    }
    assert!(!h.state().exporting(), "the export finished");
    h.run_steps(2);
    // Said in Chinese, with its full-width colon (zh-Hans.ftl's `export-task-exported-to`).
    let said = format!("已导出到 {}：", dir.path().display());
    assert!(h.query_by_label_contains(&said).is_some(), "no {said:?}");
    let html = std::fs::read_to_string(dir.path().join("index.html")).expect("index.html");
    assert!(
        html.contains("<html lang=\"zh-Hans\">"),
        "in Chinese, as the interface"
    );
    let steps = std::fs::read_dir(dir.path().join("slides"))
        .expect("slides")
        .count();
    assert_eq!(steps, expected, "one slide per step");
}

/// A student passes lesson 10's lab in the app and exports their work from the Export menu;
/// the one file holds the code that passed, and `pipelens grade` grades it passed — the same
/// verdict the app gave. The file names its lesson: graded as another lesson, it is refused.
#[test]
fn export_my_work_writes_a_file_grade_reads() {
    use std::sync::Arc;
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let doc = pipelens::lesson::load_file(&lesson).expect("the lesson loads");
    let session = pipelens::app::session::Session::with_document(doc, "test", None);
    let app = PipelensApp::new(session).exporting_to(dir.path());
    let mut h = egui_kittest::Harness::builder()
        .with_size([1920.0, 1080.0])
        .with_context_setup(pipelens::app::setup_context)
        .with_max_steps(200)
        .build_ui_state(|ui, app: &mut PipelensApp| app.frame(ui), app);
    let k = crate::app::go_to_step_titled(&mut h, crate::app::SPECULAR_LAB);
    h.run_steps(4);
    let vertex = h
        .state()
        .session
        .current_exercise()
        .and_then(|e| e.starter.shader.as_ref())
        .map(|s| s.programs.vertex.source.clone())
        .expect("a shader lab");
    let fragment = crate::labs::solved_source(&h.state().session, true);
    let programs = pipeline::shader::link(Some(&vertex), Some(&fragment)).expect("compiles");
    let mut spec = h.state().session.spec.clone();
    spec.scene.set_shaders(&pipeline::scene::ObjectShader {
        programs: Arc::new(programs),
        time: 0.0,
    });
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Scene(
            pipelens::app::session::SceneCommand::SetSpec(Box::new(spec)),
        ));
    h.run_steps(6);
    assert!(h.query_by_label_contains("Passed: all").is_some());
    h.get_by_label("Export ▾").click();
    h.run_steps(2);
    h.get_by_label("Export my work").click();
    h.run_steps(2);
    // One step has work, the lab's: the plural's `one` (en.ftl's `export-task-your-work-saved`).
    assert!(
        h.query_by_label_contains("-work.toml (1 step with work)")
            .is_some()
    );
    let file = dir.path().join("10-blinn-phong-work.toml");
    let text = std::fs::read_to_string(&file).expect("the work file");
    let work = pipelens::lab::submission::Work::from_text(&text).expect("reads back");
    let step = work.steps.get(&(k + 1)).expect("the lab's step");
    assert_eq!(step.code.fragment.as_deref(), Some(fragment.as_str()));
    let grade = |lesson: &str, step: usize| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_pipelens"))
            .args(["grade", lesson, "--step", &step.to_string()])
            .arg(&file)
            .output()
            .expect("pipelens runs");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let stdout = grade("10-blinn-phong", k + 1);
    assert!(stdout.contains("1 hand-in, 1 check, 1 passed"), "{stdout}");
    // Lesson 09's lab is its step 6.
    let stdout = grade("09-z-buffer", 6);
    assert!(
        stdout.contains("is work on lesson 10-blinn-phong, not on this one"),
        "{stdout}"
    );
}
