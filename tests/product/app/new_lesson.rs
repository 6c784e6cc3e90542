//! A new lesson in the lesson editor (R): from a mesh of one's own, written beside it and
//! opened; and the editor's refusals (a file that exists already, no mesh named) said in the
//! language shown.

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;
use pipelens::app::session::Command;

use super::recording::replace_in;

/// In the open editor: "New lesson…", "from a mesh of your own", the mesh and the lesson's file
/// typed into the last two one-line boxes, "Make the lesson" (each button by its `labels`, in
/// the language shown). Returns how many one-line boxes there are.
fn from_a_mesh(
    h: &mut Harness<'_, PipelensApp>,
    [new, from_mesh, make]: [&str; 3],
    mesh: &std::path::Path,
    file: &std::path::Path,
) -> usize {
    h.get_by_label(new).click_accesskit();
    h.run_steps(2);
    h.get_by_label(from_mesh).click_accesskit();
    h.run_steps(2);
    let n = h.get_all_by_role(Role::TextInput).count();
    for (k, text) in [
        (n - 2, mesh.display().to_string()),
        (n - 1, file.display().to_string()),
    ] {
        replace_in(h, k, &text);
    }
    h.get_by_label(make).click_accesskit();
    h.run_steps(4);
    n
}

/// A mesh of one's own: "New lesson", from a mesh file, writes a lesson file on it beside the
/// mesh and opens it; it passes `pipelens check`.
#[test]
fn a_new_lesson_starts_from_a_mesh_of_ones_own() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mesh = dir.path().join("tetra.obj");
    std::fs::write(
        &mesh,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .expect("written");
    let file = dir.path().join("my-tetra.toml");
    let mut h = super::lesson_harness(None);
    h.run_steps(2);
    // The tour, as the app opens on it.
    h.state_mut().session.source = pipelens::lesson::DEFAULT_LESSON_NAME.to_owned();
    h.key_press(egui::Key::R);
    h.run_steps(2);
    // The tour is built in: not edited in place, made one's own first.
    assert!(
        h.query_by_label_contains("A built-in lesson is not edited in place")
            .is_some()
    );
    from_a_mesh(
        &mut h,
        [
            "New lesson…",
            "from a mesh of your own (.obj; or drop one on the window):",
            "Make the lesson",
        ],
        &mesh,
        &file,
    );
    let text = std::fs::read_to_string(&file).expect("written");
    assert!(text.contains("mesh = \"tetra.obj\""), "{text}");
    assert_eq!(h.state().session.source, file.display().to_string());
    assert_eq!(super::lesson_of(&h).id, "my-tetra");
    let o = crate::support::pipelens(dir.path(), &["check", "my-tetra.toml"]);
    assert!(o.status.success(), "{}", crate::support::text(&o));
}

/// The editor's refusals are said in the language shown: in Chinese, a new lesson over a file
/// that exists already is refused in Chinese, the file left as it was, and so is one with no
/// mesh named (the words are zh-Hans.ftl's `new-exists-already` and `new-name-the-mesh-file`).
#[test]
fn the_editors_refusals_are_said_in_the_language_shown() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mesh = dir.path().join("tetra.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("written");
    let file = dir.path().join("taken.toml");
    std::fs::write(&file, "# a teacher's own file\n").expect("written");
    let mut h = super::lesson_harness(None);
    h.run_steps(2);
    h.state_mut().session.source = pipelens::lesson::DEFAULT_LESSON_NAME.to_owned();
    h.state_mut()
        .session
        .apply(Command::View(pipelens::app::command::ViewCommand::SetLang(
            pipelens::vocabulary::Lang::ZH,
        )));
    h.key_press(egui::Key::R);
    h.run_steps(2);
    let n = from_a_mesh(
        &mut h,
        [
            "新建课程…",
            "从你自己的网格开始（.obj；也可以把文件拖到窗口上）：",
            "新建课程",
        ],
        &mesh,
        &file,
    );
    let taken = format!(
        "{} 已经存在：请换一个名字（原文件保持不变）",
        file.display()
    );
    assert!(h.query_by_label_contains(&taken).is_some(), "no {taken:?}");
    assert_eq!(
        std::fs::read_to_string(&file).expect("still there"),
        "# a teacher's own file\n"
    );
    replace_in(&mut h, n - 2, " ");
    h.get_by_label("新建课程").click_accesskit();
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("请写出网格文件（.obj）的名字")
            .is_some()
    );
}
