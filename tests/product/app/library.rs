//! Opening another lesson in the app: the Lessons menu (every built-in lesson) and a lesson
//! file dropped on the window — from its path (the desktop) or from its bytes alone (the
//! browser, where a dropped file has no path); a broken one says where it is broken and the
//! lesson open keeps running. And live reload: an edited lesson file loads again on the same step.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use pipelens::app::PipelensApp;

use super::{lesson_harness, step_of};

/// A dropped file as a browser gives it: a name and bytes.
#[derive(Debug)]
struct Dropped {
    path: PathBuf,
    bytes: Vec<u8>,
}

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.path
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        Ok(self.bytes.clone())
    }
}

fn lesson_id(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> String {
    h.state()
        .session
        .lesson
        .as_ref()
        .map_or_else(String::new, |p| p.lesson.id.clone())
}

#[test]
fn the_lessons_menu_opens_a_built_in_lesson_on_its_first_step() {
    let mut h = lesson_harness(None);
    h.run_steps(3);
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(3);
    assert_eq!(step_of(&h), 1);
    h.get_by_label("Lessons").click();
    h.run_steps(2);
    h.get_by_label_contains("Texture mapping and magnification")
        .click();
    h.run_steps(4);
    assert_eq!(lesson_id(&h), "13-texture-mapping");
    assert_eq!(step_of(&h), 0, "a lesson opens on its first step");
    assert_eq!(
        h.state().title(),
        "pipelens — 13-texture-mapping — step 1/7"
    );
    h.state_mut().session.lang = pipelens::vocabulary::Lang::ZH;
    h.run_steps(2);
    assert_eq!(
        h.state().title(),
        "pipelens — 13-texture-mapping — 第 1/7 步",
        "the window's title (what a screen reader says of the window) is in the language shown"
    );
    assert!(
        h.state().session.capture.is_some(),
        "its first step is drawn"
    );
}

#[test]
fn a_dropped_lesson_opens_from_its_bytes_and_a_broken_one_says_where() {
    let mut h = lesson_harness(None);
    h.run_steps(3);
    let text = std::fs::read(crate::support::repo().join("lessons/07-rasterization.toml"))
        .expect("the lesson file");
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("07-rasterization.toml"),
        bytes: text.clone(),
    }));
    h.run_steps(4);
    assert_eq!(lesson_id(&h), "07-rasterization");
    assert!(h.state().session.dropped_error.is_none());
    // A broken copy: the lesson open keeps running, the error names the line.
    let broken = String::from_utf8(text).expect("UTF-8").replacen(
        "stage = \"viewport\"",
        "stage = \"viewprot\"",
        1,
    );
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("mine.toml"),
        bytes: broken.into_bytes(),
    }));
    h.run_steps(4);
    assert_eq!(
        lesson_id(&h),
        "07-rasterization",
        "the open lesson keeps running"
    );
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(
        error.contains("mine.toml:") && error.contains("viewport"),
        "{error}"
    );
    // It says the dropped file, by its name, did not open (nothing changed on disk), and ×
    // closes it.
    assert!(
        h.query_by_label_contains("mine.toml could not be opened; what was open keeps running:")
            .is_some()
    );
    assert!(h.query_by_label_contains("changed on disk").is_none());
    h.get_by_label("×").click();
    h.run_steps(2);
    assert!(h.state().session.dropped_error.is_none());
    // A broken mesh dropped on the page (no path on disk) is read as a mesh, not as a lesson:
    // the message says which line is wrong; it goes when a step is entered.
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("bunny.obj"),
        bytes: b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n".to_vec(),
    }));
    h.run_steps(4);
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(
        error.starts_with("bunny.obj could not be opened")
            && error.contains("\nbunny.obj:4: `7`: v index 7, but the file has 3 `v` line(s)"),
        "{error}"
    );
    assert!(
        h.state().session.given.is_empty(),
        "a broken mesh is not kept"
    );
    assert_eq!(lesson_id(&h), "07-rasterization");
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(2);
    assert!(h.state().session.dropped_error.is_none());
    // Nor is a picture of a kind a lesson cannot name (PNG and JPEG are textures: the test
    // after this one).
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("brick.webp"),
        bytes: b"RIFF\0\0\0\0WEBP".to_vec(),
    }));
    h.run_steps(4);
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(error.contains("not .webp files"), "{error}");
    // Each said in the language shown: a picture, a lesson and a shader that are not text.
    h.state_mut().session.lang = pipelens::vocabulary::Lang::ZH;
    for (name, said) in [
        (
            "brick.webp",
            "无法打开 brick.webp；已打开的内容继续运行：\nbrick.webp：pipelens 打开课程和场景（.toml）",
        ),
        ("broken.toml", "该文件不是 UTF-8 文本"),
        ("mine.frag", "mine.frag 不是 UTF-8 文本"),
    ] {
        h.input_mut().dropped_files.push(Arc::new(Dropped {
            path: PathBuf::from(name),
            bytes: vec![0xff, 0xfe, 0x00, 0x9f],
        }));
        h.run_steps(4);
        let error = h.state().session.dropped_error.clone().unwrap_or_default();
        assert!(error.contains(said), "{name}: {error}");
    }
}

/// A triangle with a colour at each corner, as an OBJ file (`v x y z r g b`).
const TRIANGLE_OBJ: &[u8] = b"v -1 -1 0 1 0 0\nv 1 -1 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n";

/// Lesson 07, its triangle the mesh `mesh` names.
fn lesson_07_on(mesh: &str) -> String {
    std::fs::read_to_string(crate::support::repo().join("lessons/07-rasterization.toml"))
        .expect("the lesson file")
        .replacen("mesh = \"triangle\"", &format!("mesh = \"{mesh}\""), 1)
}

/// The mesh of the object named "triangle" in the scene on screen.
fn triangle_mesh(h: &Harness<'_, PipelensApp>) -> (String, usize) {
    let spec = &h.state().session.spec;
    let names = spec.scene.objects.iter().map(|o| o.name.as_str());
    let k = names
        .clone()
        .position(|n| n == "triangle")
        .unwrap_or_else(|| panic!("no triangle among {:?}", names.collect::<Vec<_>>()));
    let mesh = &spec.scene.objects[k].mesh;
    (mesh.name.clone(), mesh.positions.len())
}

/// A mesh dropped on the page (a name and bytes: a page cannot read a path) is read as a mesh
/// and offered as a new lesson in the editor; a lesson dropped after it, or with it, that
/// names it opens on it; a lesson naming a mesh the page was not given says which it has.
#[test]
fn a_mesh_dropped_on_the_page_is_kept_for_the_lessons_that_name_it() {
    let mut h = lesson_harness(None);
    h.run_steps(3);
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("tri.obj"),
        bytes: TRIANGLE_OBJ.to_vec(),
    }));
    h.run_steps(4);
    assert!(h.state().session.dropped_error.is_none());
    assert!(h.state().session.given.contains_key("tri.obj"));
    // Offered as a new lesson: the editor is open on "New lesson", the mesh filled in.
    assert!(
        h.query_by_label("Make the lesson").is_some(),
        "the editor offers a lesson"
    );
    assert!(
        h.query_all_by_value("tri.obj").count() >= 1,
        "the mesh's name is filled in"
    );
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    // A lesson naming it, dropped after it.
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("mine.toml"),
        bytes: lesson_07_on("tri.obj").into_bytes(),
    }));
    h.run_steps(4);
    assert!(
        h.state().session.dropped_error.is_none(),
        "{:?}",
        h.state().session.dropped_error
    );
    assert_eq!(lesson_id(&h), "07-rasterization");
    assert_eq!(triangle_mesh(&h), ("tri.obj".to_owned(), 3));
    // A lesson and its mesh dropped together (the lesson first): the mesh is read first.
    let quad = b"v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("again.toml"),
        bytes: lesson_07_on("./quad.obj")
            .replacen("color = \"vertex\"", "color = [1, 1, 1]", 1)
            .into_bytes(),
    }));
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("quad.obj"),
        bytes: quad.to_vec(),
    }));
    h.run_steps(4);
    assert!(
        h.state().session.dropped_error.is_none(),
        "{:?}",
        h.state().session.dropped_error
    );
    assert_eq!(triangle_mesh(&h), ("quad.obj".to_owned(), 4));
    // A lesson naming a mesh the page was not given: which it has, and how to give it.
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("third.toml"),
        bytes: lesson_07_on("models/trj.obj").into_bytes(),
    }));
    h.run_steps(4);
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(
        error.starts_with("third.toml could not be opened")
            && error.contains(
                "there is no file models/trj.obj among the files dropped on the page (quad.obj, tri.obj): \
                 a page cannot read a path, so drop trj.obj on the page with the lesson"
            )
            && error.contains("\"models/tri.obj\""),
        "{error}"
    );
    assert_eq!(
        triangle_mesh(&h),
        ("quad.obj".to_owned(), 4),
        "the lesson open keeps running"
    );
}

#[test]
fn an_edited_lesson_reloads_on_the_same_step_and_a_broken_edit_keeps_the_last_good_one() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("lesson.toml");
    let good = pipelens::lesson::DEFAULT_LESSON;
    std::fs::write(&path, good).expect("write");
    let mut h = lesson_harness(Some(path.clone()));
    h.run_steps(2);
    h.key_press(egui::Key::ArrowRight);
    h.run_steps(2);
    assert_eq!(step_of(&h), 1);
    let wait_and_run = |h: &mut Harness<'_, PipelensApp>| {
        std::thread::sleep(std::time::Duration::from_millis(600));
        h.run_steps(3);
    };
    // A broken edit: the error is shown, the lesson keeps running on its step.
    let later = std::time::SystemTime::now() + std::time::Duration::from_secs(2);
    crate::support::save_edited(&path, &good.replace("fovy = 45", "fovy = 450"), later);
    wait_and_run(&mut h);
    let err = h
        .state()
        .session
        .reload_error
        .clone()
        .expect("the error is shown");
    assert!(
        err.contains("lesson.toml:") && err.contains("fovy"),
        "{err}"
    );
    assert_eq!(step_of(&h), 1);
    assert!(h.query_by_label_contains("fovy must be between").is_some());
    // Fixed, with a new title for step 2: reloaded, still on step 2, the error gone.
    crate::support::save_edited(
        &path,
        &good.replace(
            "Model space: each object in its own frame",
            "Model space, edited",
        ),
        later + std::time::Duration::from_secs(2),
    );
    wait_and_run(&mut h);
    assert!(h.state().session.reload_error.is_none());
    assert_eq!(step_of(&h), 1);
    assert!(h.query_by_label_contains("Model space, edited").is_some());
}

/// A student's saved exercise code dropped back on the window (as the browser gives it: a name
/// and bytes) goes into the shader panel and runs: lesson 10's lab passes with the solution
/// loaded from a file, and the vertex stage stays the lab's.
#[test]
fn a_dropped_shader_file_loads_into_the_panel_and_runs() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    super::go_to_step_titled(&mut h, super::SPECULAR_LAB);
    h.run_steps(4);
    assert!(h.query_by_label_contains("Not yet").is_some());
    let solved = crate::labs::solved_source(&h.state().session, true);
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("shader.frag"),
        bytes: solved.into_bytes(),
    }));
    h.run_steps(8);
    assert!(h.state().panels.shader, "the shader panel opens");
    assert!(
        h.query_by_label_contains("Passed: all 172800 pixels match")
            .is_some(),
        "the dropped solution runs and passes"
    );
}

/// A saved depth test (`depth_test.glsl`, as the panel's Save names it) dropped back on the
/// window goes into its tab and runs: lesson 09's lab passes with it.
#[test]
fn a_dropped_depth_test_loads_into_its_tab_and_runs() {
    let path = crate::support::repo().join("lessons/09-z-buffer.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    super::go_to_last_step(&mut h);
    h.run_steps(4);
    assert!(h.query_by_label_contains("Not yet").is_some());
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("depth_test.glsl"),
        bytes: b"bool depth_test(float z, float stored) {\n    return z < stored;\n}\n".to_vec(),
    }));
    h.run_steps(8);
    assert!(h.state().panels.shader, "the shader panel opens");
    assert!(h.query_by_label("Depth test").is_some(), "on its tab");
    assert!(
        h.query_by_label_contains("Passed: all 256000 pixels match")
            .is_some(),
        "the dropped depth test runs and passes"
    );
}

/// A PNG `w`×`h` of one colour, as a file's bytes.
fn png(w: u32, h: u32) -> Vec<u8> {
    let img = image::RgbaImage::from_pixel(w, h, image::Rgba([200, 40, 40, 255]));
    let mut bytes = std::io::Cursor::new(Vec::new());
    img.write_to(&mut bytes, image::ImageFormat::Png)
        .expect("a PNG encodes");
    bytes.into_inner()
}

/// The texture of the object named "cube" in the scene on screen: its name and size.
fn cube_texture(h: &Harness<'_, PipelensApp>) -> Option<(String, [f32; 2])> {
    let spec = &h.state().session.spec;
    let cube = spec.scene.objects.iter().find(|o| o.name == "cube")?;
    let t = cube.texture.as_ref()?;
    let size = t.levels.first()?.size();
    Some((t.name.clone(), [size.x, size.y]))
}

/// In a page a texture cannot be read from a path: dropped on it, it is kept for the lessons
/// that name it (alone, a note under the bar says so and how to use it; it goes away when the
/// lesson opens); dropped together with its lesson, it is read first. A file that does not
/// decode is refused with the decoder's words.
#[test]
fn a_texture_dropped_on_the_page_is_kept_for_the_lessons_that_name_it() {
    let lesson_13_on = |texture: &str| {
        std::fs::read_to_string(crate::support::repo().join("lessons/13-texture-mapping.toml"))
            .expect("the lesson file")
            .replacen(
                "texture = \"uv_grid\"",
                &format!("texture = \"{texture}\""),
                1,
            )
    };
    let mut h = lesson_harness(None);
    h.run_steps(3);
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("mine.png"),
        bytes: png(4, 2),
    }));
    h.run_steps(4);
    assert!(
        h.state().session.dropped_error.is_none(),
        "{:?}",
        h.state().session.dropped_error
    );
    assert!(h.state().session.given.contains_key("mine.png"));
    assert!(
        h.query_by_label_contains("mine.png is kept for the lessons that name it")
            .is_some(),
        "a note says the texture is kept"
    );
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("mine.toml"),
        bytes: lesson_13_on("textures/mine.png").into_bytes(),
    }));
    h.run_steps(4);
    assert!(
        h.state().session.dropped_error.is_none(),
        "{:?}",
        h.state().session.dropped_error
    );
    assert_eq!(lesson_id(&h), "13-texture-mapping");
    assert_eq!(cube_texture(&h), Some(("mine.png".to_owned(), [4.0, 2.0])));
    assert!(
        h.query_by_label_contains("is kept for the lessons")
            .is_none(),
        "the note went away when the lesson opened"
    );
    // A lesson dropped with its texture (the lesson first in the drop).
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("again.toml"),
        bytes: lesson_13_on("./wide.png").into_bytes(),
    }));
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("wide.png"),
        bytes: png(8, 2),
    }));
    h.run_steps(4);
    assert_eq!(cube_texture(&h), Some(("wide.png".to_owned(), [8.0, 2.0])));
    assert!(
        h.query_by_label_contains("is kept for the lessons")
            .is_none(),
        "no note when the lesson came with it"
    );
    // Bytes that are no image.
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: PathBuf::from("broken.png"),
        bytes: b"not a picture".to_vec(),
    }));
    h.run_steps(4);
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(
        error.starts_with("broken.png could not be opened") && error.contains("broken.png"),
        "{error}"
    );
    assert!(!h.state().session.given.contains_key("broken.png"));
    assert_eq!(
        lesson_id(&h),
        "13-texture-mapping",
        "the lesson keeps running"
    );
}

/// A texture dropped on the desktop window (a file with a path) is refused, and the message
/// says where a texture comes from there: the lesson that names it reads it from the lesson's
/// folder. Nothing is kept and the lesson open keeps running.
#[test]
fn a_texture_dropped_on_the_desktop_says_a_lesson_reads_it_from_its_folder() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("brick.png");
    std::fs::write(&file, png(4, 2)).expect("the texture written");
    let mut h = lesson_harness(None);
    h.run_steps(3);
    let before = lesson_id(&h);
    h.input_mut().dropped_files.push(Arc::new(Dropped {
        path: file,
        bytes: Vec::new(),
    }));
    h.run_steps(4);
    let error = h.state().session.dropped_error.clone().unwrap_or_default();
    assert!(
        error.starts_with("brick.png could not be opened")
            && error.contains("texture = \"brick.png\"")
            && error.contains("from the lesson's folder: open that lesson instead"),
        "{error}"
    );
    assert!(
        h.query_by_label_contains("a texture is read by the lesson that names it")
            .is_some(),
        "the window shows why"
    );
    assert!(!h.state().session.given.contains_key("brick.png"));
    assert_eq!(lesson_id(&h), before, "the lesson keeps running");
}
