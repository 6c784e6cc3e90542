//! Labs by their kind of check: a function of the pipeline the student writes (the inside
//! test decided by its ties, the viewport matrix by depth, de Casteljau point by point), done
//! in the app and failed by the mistakes students make.

use std::sync::Arc;

use pipelens::app::command::{LessonCommand, SceneCommand};
use pipelens::lesson::Document;
use pipeline::scene::ObjectShader;

use crate::labs::{SOLUTIONS, compared};

/// The inside-test lab is decided by its ties: the square's sides and diagonal lie on pixel
/// centres, so an `inside` that takes every tie (E ≥ 0) or none (E > 0) fails, and only the
/// top-left rule passes.
#[test]
fn the_inside_lab_fails_a_test_that_takes_every_tie_or_none() {
    let path = crate::support::repo().join("lessons/07-rasterization.toml");
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("lesson 07 loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == "Lab: the inside test")
        .expect("the lab");
    let e = lesson.steps[k].exercise.as_ref().expect("a lab");
    for (ties, compare) in [("every tie", ">="), ("no tie", ">")] {
        let source = format!(
            "float edge(vec2 a, vec2 b, vec2 p) {{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}}
bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {{
    return edge(a, b, p) {compare} 0.0 && edge(b, c, p) {compare} 0.0 && edge(c, a, p) {compare} 0.0;
}}
"
        );
        let mut spec = lesson.spec_at(k);
        spec.scene
            .set_inside(&pipeline::shader::compile_inside(&source).expect("compiles"));
        let d = compared(&spec, e.tolerance);
        assert!(!d.passed(), "a test that takes {ties} passes");
        assert!(d.coverage_differs > 0, "{ties}: {d:?}");
    }
}

/// The inside-test lab in the app: the shader panel opens on the inside test's tab, the
/// starter's frame is "not yet", the solution passes, and the test that passed comes back when
/// the step is entered again.
#[test]
fn the_inside_lab_in_the_app_passes_and_keeps_the_inside_test() {
    use egui_kittest::kittest::Queryable;
    use pipelens::app::session::Command;
    let path = crate::support::repo().join("lessons/07-rasterization.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    let k = crate::app::go_to_last_step(&mut h);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    assert!(
        h.query_by_label("Inside test").is_some(),
        "the tab is there"
    );
    // The starter tests one edge of each triangle: the square's edge pixels on a tie are
    // covered where the top-left rule leaves them out, and the first triangle drawn takes the
    // second's pixels (the same colour: only the owner tells).
    assert!(h.query_by_label_contains("Not yet: ").is_some());
    let d = h
        .state()
        .session
        .exercise
        .findings
        .difference
        .clone()
        .expect("compared");
    assert_eq!(d.total, 24 * 16);
    assert!(d.coverage_differs > 0 && d.owner_differs > 0, "{d:?}");
    assert!(
        h.query_by_label_contains("belong to another triangle")
            .is_some()
    );
    let (_, _, todo, solution) = SOLUTIONS
        .iter()
        .find(|(id, ..)| *id == "07-rasterization")
        .expect("the lab's solution");
    let starter = h
        .state()
        .session
        .current_exercise()
        .and_then(|e| {
            e.starter
                .hooks
                .get(pipeline::shader::HookKind::Inside)
                .cloned()
        })
        .expect("an inside lab");
    let solved = starter.source.replace(todo, solution);
    let mut spec = h.state().session.spec.clone();
    spec.scene
        .set_inside(&pipeline::shader::compile_inside(&solved).expect("compiles"));
    h.state_mut()
        .session
        .apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("Passed: all 384 pixels match")
            .is_some()
    );
    let lesson = crate::app::lesson_of(&h);
    assert!(h.state().session.progress.passed(&lesson, k));
    // Away and back: the step runs the test that passed, not the starter.
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::PreviousStep));
    h.run_steps(4);
    h.state_mut()
        .session
        .apply(Command::Lesson(LessonCommand::NextStep));
    h.run_steps(6);
    let running = h.state().session.spec.scene.objects[0]
        .code
        .hooks
        .get(pipeline::shader::HookKind::Inside)
        .map(|i| i.source.clone());
    assert_eq!(running.as_deref(), Some(solved.as_str()));
    assert!(
        h.query_by_label_contains("Passed: all 384 pixels match")
            .is_some()
    );
}

/// The viewport lab checks depth too: GAMES101's M_viewport, which leaves z in [−1, 1], does not
/// land on gl_FragCoord (OpenGL's depth is in [0, 1]), nor does a matrix that forgets the shift.
#[test]
fn the_viewport_lab_fails_a_matrix_that_keeps_z_or_forgets_the_shift() {
    let path = crate::support::repo().join("lessons/06-clipping-ndc-viewport.toml");
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("lesson 06 loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == "Lab: the viewport matrix")
        .expect("the lab");
    let e = lesson.steps[k].exercise.as_ref().expect("a lab");
    let todo = "    // TODO: the viewport matrix (mat4 takes its numbers column by column).
    return mat4(1.0);";
    for (wrong, matrix) in [
        (
            "z kept",
            "    return mat4(w / 2.0, 0, 0, 0,  0, h / 2.0, 0, 0,  0, 0, 1, 0,  w / 2.0, h / 2.0, 0, 1);",
        ),
        (
            "no shift",
            "    return mat4(w / 2.0, 0, 0, 0,  0, h / 2.0, 0, 0,  0, 0, 0.5, 0,  0, 0, 0.5, 1);",
        ),
    ] {
        let p = &e.starter.shader.as_ref().expect("a shader lab").programs;
        let programs = pipeline::shader::link(
            Some(&p.vertex.source),
            Some(&p.fragment.source.replace(todo, matrix)),
        )
        .expect("compiles");
        let mut spec = lesson.spec_at(k);
        spec.scene.set_shaders(&ObjectShader {
            programs: Arc::new(programs),
            time: 0.0,
        });
        assert!(!compared(&spec, e.tolerance).passed(), "{wrong} passes");
    }
}

/// The de Casteljau lab in the app: its tab opens, the card counts the curve points that match
/// and gives the first one off with both values; the solution passes, and the pass is kept.
#[test]
fn the_de_casteljau_lab_compares_the_curve_point_by_point() {
    use egui_kittest::kittest::Queryable;
    use pipelens::app::session::Command;
    let path = crate::support::repo().join("lessons/18-bezier.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    let k = crate::app::go_to_last_step(&mut h);
    h.state_mut().panels.shader = true;
    h.run_steps(4);
    assert!(
        h.query_by_label("de Casteljau").is_some(),
        "the tab is there"
    );
    assert!(
        h.query_by_label_contains(
            "Not yet: 1 of 161 curve points lie within 1e-4 of pipelens' b(t)"
        )
        .is_some()
    );
    // b(1/160) by hand is (−1.1905, −0.6720); the starter's is on the segment P0P1.
    assert!(
        h.query_by_label_contains(
            "The first, t = 0.0063: yours (-1.1969, -0.6906), pipelens' (-1.1905, -0.6720)."
        )
        .is_some()
    );
    let (_, _, todo, solution) = SOLUTIONS
        .iter()
        .find(|(id, ..)| *id == "18-bezier")
        .expect("the lab's solution");
    let starter = h
        .state()
        .session
        .current_exercise()
        .and_then(|e| {
            e.starter
                .hooks
                .get(pipeline::shader::HookKind::Curve)
                .cloned()
        })
        .expect("a curve lab");
    let solved = pipeline::shader::compile_hook(
        pipeline::shader::HookKind::Curve,
        &starter.source.replace(todo, solution),
    )
    .expect("compiles");
    let mut spec = h.state().session.spec.clone();
    spec.scene.set_hook(&solved);
    h.state_mut()
        .session
        .apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("Passed: all 161 points of your curve lie within 1e-4")
            .is_some()
    );
    let lesson = crate::app::lesson_of(&h);
    assert!(h.state().session.progress.passed(&lesson, k));
}

/// A mismatch is explained in words at the inspected pixel: the first value in which the
/// student's run parts from pipelens' own shader's run, with both values; a normal left
/// unnormalized is named as such.
#[test]
fn a_mismatch_names_the_first_value_that_differs_and_an_unnormalized_normal() {
    use egui_kittest::kittest::Queryable;
    use pipelens::app::session::Command;
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    crate::app::go_to_step_titled(&mut h, crate::app::SPECULAR_LAB);
    h.run_steps(4);
    h.get_by_label("Inspect the first wrong pixel").click();
    h.run_steps(6);
    // The starter has no specular term: its sum parts from pipelens' where that term is added,
    // at the pixel now inspected — the first wrong one, which the sentence names.
    let first = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        let session = &h.state().session;
        let first = session
            .exercise
            .findings
            .difference
            .as_ref()
            .and_then(|d| d.first);
        assert_eq!(
            session.selection.pixel, first,
            "the first wrong pixel is inspected"
        );
        let (x, y) = first.expect("a wrong pixel");
        format!("At the inspected pixel ({x}, {y}) your ")
    };
    let at = first(&h);
    assert!(
        h.query_by_label_contains(&format!("{at}`sum` (line"))
            .is_some(),
        "the starter's mismatch is named at {at:?}"
    );
    let vertex = h
        .state()
        .session
        .current_exercise()
        .and_then(|e| e.starter.shader.as_ref())
        .map(|s| s.programs.vertex.source.clone())
        .expect("a shader lab");
    let fragment = crate::labs::solved_source(&h.state().session, true)
        .replace("vec3 n = normalize(w_nrm);", "vec3 n = w_nrm;");
    let programs = pipeline::shader::link(Some(&vertex), Some(&fragment)).expect("compiles");
    let mut spec = h.state().session.spec.clone();
    spec.scene.set_shaders(&ObjectShader {
        programs: Arc::new(programs),
        time: 0.0,
    });
    h.state_mut()
        .session
        .apply(Command::Scene(SceneCommand::SetSpec(Box::new(spec))));
    h.run_steps(6);
    assert!(h.query_by_label_contains("Not yet").is_some());
    h.get_by_label("Inspect the first wrong pixel").click();
    h.run_steps(6);
    let at = first(&h);
    assert!(
        h.query_by_label_contains(&format!("{at}`n` (line 23)"))
            .is_some()
    );
    assert!(h.query_by_label_contains("is it normalized?").is_some());
}

/// A matrix lab names the first vertex off and the matrix entry by entry: lesson 25's rotation
/// about z, whose starter returns the identity, is pipelens' M but for the four entries of the
/// rotation's 2×2 block (θ = 30°).
#[test]
fn a_matrix_lab_names_the_first_wrong_vertex_and_the_entries_off() {
    use egui_kittest::kittest::Queryable;
    let path = crate::support::repo().join("lessons/25-lab-model-projection.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut()
        .session
        .apply(pipelens::app::session::Command::Lesson(
            pipelens::app::session::LessonCommand::GoToStep(2),
        ));
    h.run_steps(6);
    assert!(
        h.query_by_label_contains("The first vertex off is row")
            .is_some()
    );
    assert!(
        h.query_by_label_contains(
            "Your `rotate_z()` (line 20) is pipelens' M but for 4 entries: row 1, column 1 is 1.000 (M has 0.866); row 2, column 1 is 0.000 (M has 0.500)"
        )
        .is_some()
    );
    h.get_by_label("Inspect the first wrong vertex").click();
    h.run_steps(4);
    assert!(h.state().session.selection.vertex.is_some());
    assert!(h.state().panels.inspector, "the Inspector opens on it");
}

/// The shadow-matrix lab: the starter's identities are named entry by entry against pipelens'
/// M_shadow; the solution and a positive multiple of it (the textbook's form, scaled by y_l)
/// cast pipelens' shadows and have no entry off; a negative multiple puts every point behind
/// the eye (w < 0) and fails.
#[test]
fn the_shadow_lab_compares_the_matrix_up_to_a_positive_factor() {
    use pipelens::lab::wrong_shadow_matrix;
    use pipeline::shader::{HookKind, compile_hook};
    let path = crate::support::repo().join("lessons/16-planar-shadows.toml");
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("lesson 16 loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == "Lab: the shadow matrix")
        .expect("the lab");
    let e = lesson.steps[k].exercise.as_ref().expect("a lab");
    let starter = e
        .starter
        .hooks
        .get(HookKind::ShadowMatrix)
        .expect("a shadow_matrix");
    let (_, _, todo, solution) = SOLUTIONS
        .iter()
        .find(|(id, ..)| *id == "16-planar-shadows")
        .expect("a solution");
    let spec = lesson.spec_at(k);
    let m = wrong_shadow_matrix(&spec.scene).expect("the starter's matrix is off");
    assert_eq!(m.matrix, "M_shadow");
    // The identity against T(l)·P·T(−l) for l = (1, 5, 1): row 2 and row 4 differ.
    assert!(
        m.entries
            .iter()
            .any(|&(r, c, yours, theirs)| (r, c) == (4, 2)
                && yours == 0.0
                && (theirs + 0.2).abs() < 1e-6),
        "{:?}",
        m.entries
    );
    let solved = starter.source.replace(todo, solution);
    let scaled = solved.replace(
        "return back * project * to_light;",
        "return light.y * (back * project * to_light);",
    );
    let negative = solved.replace(
        "return back * project * to_light;",
        "return -(back * project * to_light);",
    );
    for (name, source, passes) in [
        ("the solution", &solved, true),
        ("5 × the solution", &scaled, true),
        ("−1 × the solution", &negative, false),
    ] {
        let mut spec = spec.clone();
        spec.scene
            .set_hook(&compile_hook(HookKind::ShadowMatrix, source).expect("compiles"));
        let d = compared(&spec, e.tolerance);
        assert_eq!(d.passed(), passes, "{name}: {} of {}", d.matching, d.total);
        assert_eq!(
            wrong_shadow_matrix(&spec.scene).is_none(),
            passes,
            "{name}: {:?}",
            wrong_shadow_matrix(&spec.scene)
        );
    }
}

/// A texture lab's card names the quantity at the first wrong pixel, in the app as in `grade`:
/// lesson 14's starter returns λ = 0 where pipelens' λ is far above it (the horizon).
#[test]
fn a_texture_lab_names_its_quantity_at_the_inspected_pixel() {
    use egui_kittest::kittest::Queryable;
    let (h, said) = starter_inspected("14-mipmaps");
    assert!(
        said.contains("your `level_of_detail()` (line 13) gives λ = 0.000; pipelens' λ there is"),
        "{said}"
    );
    assert!(h.query_by_label_contains("pipelens' λ there is").is_some());
}

/// At a pixel the student's inside test leaves empty, the Inspector does not blame the depth
/// test: lesson 08's starter tests the pixel centre for every sample, so its first wrong pixel
/// (one pipelens covers at a sample) has no fragment kept, and the Inspector says that the
/// student's inside() covered none of the samples.
#[test]
fn an_empty_pixel_of_the_students_inside_test_is_not_blamed_on_the_depth_test() {
    use egui_kittest::kittest::Queryable;
    let (h, said) = starter_inspected("08-antialiasing");
    assert!(
        h.query_by_label_contains("Your inside() covers none of these fragments' samples")
            .is_some()
    );
    assert!(h.query_by_label_contains("failed the depth test").is_none());
    // The card's sample names its triangle as the Inspector numbers the fragments.
    let number: String = said
        .split("against triangle ")
        .nth(1)
        .unwrap_or_else(|| panic!("{said}"))
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    assert!(
        h.query_by_label_contains(&format!("· triangle {number}"))
            .is_some(),
        "{said}"
    );
}

/// Lesson `id`'s last step (its lab) with the starter as it is, after **Inspect the first wrong
/// pixel**: the harness and the card's sentences in English.
fn starter_inspected(
    id: &str,
) -> (
    egui_kittest::Harness<'static, pipelens::app::PipelensApp>,
    String,
) {
    use egui_kittest::kittest::Queryable;
    let path = crate::support::repo().join(format!("lessons/{id}.toml"));
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    crate::app::go_to_last_step(&mut h);
    h.run_steps(4);
    h.get_by_label("Inspect the first wrong pixel").click();
    h.run_steps(6);
    let said = h
        .state()
        .session
        .exercise
        .findings
        .sentences(pipelens::vocabulary::Lang::EN)
        .join(" ");
    (h, said)
}
