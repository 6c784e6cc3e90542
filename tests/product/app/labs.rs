//! A lab in the app: it says "not yet", then "passed", and keeps the student's code; the source
//! keeps the keyboard while messages appear under it; the shader panel opens on the stage the
//! step is about; a lab's starter reads in Chinese and is still the starter.

use std::sync::Arc;

use pipelens::app::command::{SceneCommand, ViewCommand};
use pipelens::vocabulary::Lang;
use pipeline::scene::ObjectShader;

use crate::labs::{differs_at_image, solved_source};

/// The lab in the app: the starter's frame is "not yet" with its first wrong pixel; the code
/// the student runs is compared as it changes, passes, and is kept with the pass.
#[test]
fn a_lab_in_the_app_says_not_yet_then_passed_and_keeps_the_code() {
    use egui_kittest::kittest::Queryable;
    use pipelens::app::session::Command;
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    let k = crate::app::go_to_step_titled(&mut h, crate::app::SPECULAR_LAB);
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("Not yet: 162116 of 172800 pixels match")
            .is_some()
    );
    h.get_by_label("Inspect the first wrong pixel").click();
    h.run_steps(4);
    // The starter leaves the specular term out: the first pixel that differs, reading from the
    // top, is on the highlight's upper edge, and it is the one selected. Checked against the
    // frames themselves (the buffers as stored, top row first), not a copied number.
    let (x, y) = h
        .state()
        .session
        .selection
        .pixel
        .expect("a pixel is selected");
    let session = &h.state().session;
    let capture = session.capture.as_ref().expect("the student's frame");
    let reference = session.exercise.reference.as_ref().expect("the reference");
    let row = capture.height() - 1 - y;
    assert!(differs_at_image(capture, reference, (x, row), 1.0));
    assert!(
        (0..row).all(|r| (0..capture.width()).all(|c| !differs_at_image(
            capture,
            reference,
            (c, r),
            1.0
        ))),
        "a pixel above ({x}, {y}) differs"
    );
    let (mine, theirs) = (
        capture.pixel_record(x, y).expect("in the window"),
        reference.pixel_record(x, y).expect("in the window"),
    );
    assert!(mine.color != theirs.color, "the inspected pixel differs");
    assert!(
        mine.lighting.is_some() || mine.primitive.is_some(),
        "the first wrong pixel lies on the sphere"
    );
    assert!(
        h.state().panels.inspector,
        "the Inspector opens on that pixel"
    );
    // The student's code, run as the shader panel runs it.
    let mut spec = h.state().session.spec.clone();
    let vertex = h
        .state()
        .session
        .current_exercise()
        .expect("a lab")
        .starter
        .shader
        .as_ref()
        .expect("a shader lab")
        .programs
        .vertex
        .source
        .clone();
    let solved = pipeline::shader::link(
        Some(&vertex),
        Some(&solved_source(&h.state().session, true)),
    )
    .expect("the solution compiles");
    spec.scene.set_shaders(&ObjectShader {
        programs: Arc::new(solved),
        time: 0.0,
    });
    h.state_mut()
        .session
        .apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("Passed: all 172800 pixels match")
            .is_some()
    );
    let lesson = crate::app::lesson_of(&h);
    let progress = &h.state().session.progress;
    assert!(progress.passed(&lesson, k));
    let (_, fragment) = progress
        .code(&lesson, k)
        .and_then(|c| c.shaders)
        .expect("the code is kept");
    assert!(fragment.contains("pow(max(dot(n, h), 0.0), shininess)"));
}

/// Typing into the shader panel keeps the focus while its messages come and go above the
/// source (a half-typed line does not compile): the next key still goes to the source.
#[test]
fn the_shader_source_keeps_the_focus_while_messages_appear() {
    use egui_kittest::kittest::Queryable;
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    let source = || egui::accesskit::Role::MultilineTextInput;
    h.get_by_role(source()).focus();
    h.run_steps(2);
    h.get_by_role(source()).type_text("x");
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("Fragment shader (!)").is_some(),
        "the half-typed source has a message"
    );
    assert!(
        h.get_by_role(source()).is_focused(),
        "the source lost the focus"
    );
    h.get_by_role(source()).type_text("y");
    h.run_steps(2);
    assert!(
        h.get_by_role(source())
            .value()
            .is_some_and(|v| v.contains("xy"))
    );
}

/// The lesson at `path` at 1920×1080 in `lang`, with the shader panel open.
fn in_language(
    path: &std::path::Path,
    lang: Lang,
) -> egui_kittest::Harness<'static, pipelens::app::PipelensApp> {
    let mut h = crate::app::sized_lesson_harness(path, [1920.0, 1080.0]);
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::View(ViewCommand::SetLang(
            lang,
        )));
    h.state_mut().panels.shader = true;
    h
}

/// The shader panel opens on the stage a step is about: lesson 24's vertex-shader step (its own
/// vertex shader beside pipelens' Blinn-Phong) and its Gouraud lab (both shaders its own, the
/// TODO in the vertex shader) show the vertex shader's source; the diffuse lab its fragment's.
/// In Chinese too, where the sources are shown with their comments translated.
#[test]
fn the_shader_panel_opens_on_the_stage_the_step_is_about() {
    use egui_kittest::kittest::Queryable;
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    for lang in [Lang::EN, Lang::ZH] {
        let mut h = in_language(&path, lang);
        for (title, shown) in [
            (
                "The vertex shader: a program per vertex",
                "gl_Position = projection",
            ),
            (
                "Lab: Gouraud shading in the vertex shader",
                "v_specular = specular;",
            ),
            ("Lab: the diffuse term", "out vec4 color;"),
        ] {
            crate::app::go_to_step_titled(&mut h, title);
            h.run_steps(4);
            let source = h
                .get_by_role(egui::accesskit::Role::MultilineTextInput)
                .value()
                .unwrap_or_default();
            assert!(
                source.contains(shown),
                "{lang:?} {title}: the panel shows {source}"
            );
        }
    }
}

/// In the Chinese interface the shader panel shows a lab's starter with its comments in
/// Chinese (the code as it was), and the starter so shown is still the starter: the lab's
/// check compares the same stages and finds the same first value as in English.
#[test]
fn a_lab_s_starter_reads_in_chinese_and_is_still_the_starter() {
    use egui_kittest::kittest::Queryable;
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let mut h = in_language(&path, Lang::ZH);
    crate::app::go_to_step_titled(&mut h, "Lab: Gouraud shading in the vertex shader");
    h.run_steps(4);
    let source = h
        .get_by_role(egui::accesskit::Role::MultilineTextInput)
        .value()
        .unwrap_or_default();
    assert!(
        source.contains("// TODO：把这个顶点的漫反射项加到 lit 上"),
        "the TODO in Chinese: {source}"
    );
    assert!(
        source.contains("vec3 lit = ka * c * ambient_light;"),
        "the code as it was"
    );
    // Applied as shown (one space typed and taken back), the lab says what it said before.
    let lesson = crate::app::lesson_of(&h);
    let k = crate::app::step_of(&h);
    let hand_in = |text: &str| {
        let mut code = pipelens::lab::submission::Code::default();
        code.take("shader.vert", text.to_owned());
        pipelens::lab::submission::grade(&lesson, k, &code, Lang::EN).sentences
    };
    let english = lesson.steps[k]
        .exercise
        .as_ref()
        .and_then(|e| e.starter.shader.as_ref())
        .map(|s| s.programs.vertex.source.clone())
        .expect("a vertex starter");
    assert_eq!(hand_in(&source), hand_in(&english));
    assert!(
        hand_in(&source)
            .join(" ")
            .contains("your vertex shader's `lit`"),
        "{:?}",
        hand_in(&source)
    );
}
