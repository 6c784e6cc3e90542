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
    let html = std::fs::read_to_string(dir.path().join("index.html")).expect("index.html");
    assert!(
        html.contains("<html lang=\"zh-CN\">"),
        "in Chinese, as the interface"
    );
    let steps = std::fs::read_dir(dir.path().join("slides"))
        .expect("slides")
        .count();
    assert_eq!(steps, expected, "one slide per step");
}
