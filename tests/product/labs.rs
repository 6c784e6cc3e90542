//! The labs: every exercise step's starter compiles and fails its check (its frame differs
//! from pipelens' own somewhere), and a reference solution kept here — not in the lesson —
//! passes it (every pixel matches). A lab without a solution here fails the test.

use std::sync::Arc;

use pipelens::lesson::Document;
use pipeline::scene::ObjectShader;

use crate::support::lesson_files;

pub(crate) use crate::lab_solutions::SOLUTIONS;

/// The open lab's fragment (or vertex) source with its solution in place of the TODO.
pub(crate) fn solved_source(session: &pipelens::app::session::Session, fragment: bool) -> String {
    let player = session.lesson.as_ref().expect("a lesson");
    let (lesson, step) = (&player.lesson, player.current());
    let (_, _, todo, solution) = SOLUTIONS
        .iter()
        .find(|(id, title, ..)| *id == lesson.id && *title == step.title.en)
        .expect("the lab has a solution");
    let programs = &step
        .exercise
        .as_ref()
        .expect("a lab")
        .starter
        .shader
        .as_ref()
        .expect("a shader lab")
        .programs;
    let source = if fragment {
        &programs.fragment.source
    } else {
        &programs.vertex.source
    };
    source.replace(todo, solution)
}

/// The frame of `spec` against pipelens' own (the same scene without shaders).
pub(crate) fn compared(
    spec: &pipelens::lesson::SceneSpec,
    tolerance: f32,
) -> pipeline::capture::Difference {
    let (mine, reference) = frames(spec);
    mine.difference(&reference, tolerance).expect("same size")
}

/// The frame of `spec` and pipelens' own (the same scene without the student's code).
fn frames(
    spec: &pipelens::lesson::SceneSpec,
) -> (
    pipeline::capture::FrameCapture,
    pipeline::capture::FrameCapture,
) {
    let mine = pipeline::render(&spec.scene, &spec.settings).expect("the lab renders");
    let mut own = spec.scene.clone();
    own.clear_code();
    let reference = pipeline::render(&own, &spec.settings).expect("the reference renders");
    (mine, reference)
}

/// Whether image pixel `(col, row)` (counted from the top, as the stored buffers and the
/// pictures run) differs between two frames: its coverage, or a colour channel by more than
/// `tolerance` 8-bit steps. Worked out here from the buffers as stored, not through the
/// product's window positions.
pub(crate) fn differs_at_image(
    a: &pipeline::capture::FrameCapture,
    b: &pipeline::capture::FrameCapture,
    (col, row): (u32, u32),
    tolerance: f32,
) -> bool {
    let i = (row * a.width() + col) as usize;
    let step = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round();
    a.pixels.coverage[i] != b.pixels.coverage[i]
        || (0..3)
            .any(|c| (step(a.pixels.color[i][c]) - step(b.pixels.color[i][c])).abs() > tolerance)
}

/// In every lab whose starter is compared pixel by pixel, the first wrong pixel reported
/// (window position, y up) is the first differing pixel reading the picture from its top row:
/// it differs, no image row above it holds a difference, nor its row left of it; the
/// difference picture marks that spot (not dim) and nothing above it; and the pixel's record
/// (what **Inspect the first wrong pixel** opens) differs between the frames.
#[test]
fn the_first_wrong_pixel_of_every_lab_differs_and_is_the_topmost() {
    let mut labs = 0;
    for path in lesson_files() {
        let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
            panic!("{} loads", path.display());
        };
        for (k, step) in lesson.steps.iter().enumerate() {
            let Some(exercise) = &step.exercise else {
                continue;
            };
            if exercise
                .starter
                .hooks
                .get(pipeline::shader::HookKind::Curve)
                .is_some()
            {
                continue; // compared point by point, not pixel by pixel
            }
            let name = format!("{} step {}", lesson.id, k + 1);
            let spec = lesson.spec_at(k);
            let (mine, reference) = frames(&spec);
            let t = exercise.tolerance;
            let d = mine.difference(&reference, t).expect("same size");
            let (x, y) = d
                .first
                .unwrap_or_else(|| panic!("{name}: the starter matches"));
            let (w, h) = (mine.width(), mine.height());
            let row = h - 1 - y;
            assert!(
                differs_at_image(&mine, &reference, (x, row), t),
                "{name}: ({x}, {y}) matches"
            );
            for r in 0..=row {
                for c in 0..(if r == row { x } else { w }) {
                    assert!(
                        !differs_at_image(&mine, &reference, (c, r), t),
                        "{name}: image pixel ({c}, {r}) differs, above the first reported ({x}, {y})"
                    );
                }
            }
            let picture = mine.difference_image(&reference, pipeline::capture::Criteria::colour(t));
            let dim = |p: &image::Rgba<u8>| p.0[0] == p.0[1] && p.0[1] == p.0[2] && p.0[0] <= 64;
            assert!(
                !dim(picture.get_pixel(x, row)),
                "{name}: the picture is dim at the first wrong pixel"
            );
            assert!(
                (0..row).all(|r| (0..w).all(|c| dim(picture.get_pixel(c, r)))),
                "{name}: the difference picture marks a pixel above the first wrong one"
            );
            let (a, b) = (
                mine.pixel_record(x, y).expect("in the window"),
                reference.pixel_record(x, y).expect("in the window"),
            );
            assert!(
                a.coverage != b.coverage || a.color != b.color,
                "{name}: the inspected first wrong pixel ({x}, {y}) is the same in both frames"
            );
            labs += 1;
        }
    }
    assert!(labs >= 15, "only {labs} pixel-checked labs were found");
}

/// An exercise's check as the app makes it: the curve point by point where the scene runs the
/// student's de Casteljau, else every pixel. Whether it passed, and what was found.
pub(crate) fn checked(spec: &pipelens::lesson::SceneSpec, tolerance: f32) -> (bool, String) {
    let curve = spec.scene.objects.iter().find_map(|o| match o.builtin {
        Some(pipeline::mesh::BuiltinMesh::Bezier { points, .. }) => {
            Some((o.code.hooks.get(pipeline::shader::HookKind::Curve)?, points))
        }
        _ => None,
    });
    if let Some((hook, points)) = curve {
        let tolerance = pipelens::lab::CURVE_TOLERANCE;
        let d = hook
            .curve_difference(points, tolerance)
            .expect("the curve runs");
        let found = format!(
            "{} of {} curve points (farthest {}, first at {:?})",
            d.matching, d.total, d.largest, d.first
        );
        return (d.passed(), found);
    }
    let d = compared(spec, tolerance);
    let found = format!(
        "{} of {} pixels (largest difference {}/255, first at {:?})",
        d.matching, d.total, d.largest, d.first
    );
    (d.passed(), found)
}

/// Runs the starter `code` with `solution` in place of its line `todo` in `spec`'s scene;
/// whether the line was found.
///
/// # Errors
/// The compiler's messages when the solution does not compile.
fn solve(
    spec: &mut pipelens::lesson::SceneSpec,
    code: &pipeline::scene::StudentCode,
    todo: &str,
    solution: &str,
) -> Result<bool, String> {
    let mut found = false;
    if let Some(shader) = &code.shader {
        let programs = &shader.programs;
        found |= programs.fragment.source.contains(todo) || programs.vertex.source.contains(todo);
        let solved = pipeline::shader::link(
            Some(&programs.vertex.source.replace(todo, solution)),
            Some(&programs.fragment.source.replace(todo, solution)),
        )
        .map_err(|e| format!("{e:?}"))?;
        spec.scene.set_shaders(&ObjectShader {
            programs: Arc::new(solved),
            time: 0.0,
        });
    }
    for hook in pipeline::shader::HookKind::ALL
        .into_iter()
        .filter_map(|kind| code.hooks.get(kind))
    {
        found |= hook.source.contains(todo);
        let solved =
            pipeline::shader::compile_hook(hook.kind, &hook.source.replace(todo, solution))
                .map_err(|e| format!("{e:?}"))?;
        spec.scene.set_hook(&solved);
    }
    Ok(found)
}

/// GAMES101's assignment 3 is done on Spot, which may not be committed: with `../shared/data`
/// beside the checkout, the shading labs' solutions (Blinn-Phong's specular term, bilinear
/// filtering, the bump map, displacement) run on Spot with its texture in place of the lab's
/// meshes, and every pixel matches pipelens' own there too.
#[test]
fn the_shading_labs_solutions_pass_on_spot() {
    let Some(data) = crate::support::shared_data() else {
        eprintln!("skipped: ../shared/data is not present");
        return;
    };
    let dir = data.join("models/spot");
    let spot = Arc::new(
        pipeline::mesh::Mesh::load_obj(&dir.join("spot_triangulated_good.obj"))
            .expect("Spot loads"),
    );
    let texture = Arc::new(
        pipeline::texture::Texture::load(&dir.join("spot_texture.png")).expect("its texture loads"),
    );
    let labs = [
        (
            "10-blinn-phong",
            "Lab: the specular term in a fragment shader",
        ),
        (
            "13-texture-mapping",
            "Lab: bilinear filtering from texelFetch",
        ),
        (
            "15-surface-detail",
            "Lab: the bump map in a fragment shader",
        ),
        ("15-surface-detail", "Lab: displacement in a vertex shader"),
    ];
    for (id, title) in labs {
        let path = crate::support::repo().join(format!("lessons/{id}.toml"));
        let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
            panic!("{id} loads");
        };
        let k = lesson
            .steps
            .iter()
            .position(|s| s.title.en == title)
            .unwrap_or_else(|| panic!("{id} has the step {title}"));
        let exercise = lesson.steps[k].exercise.as_ref().expect("a lab");
        let mut spec = lesson.spec_at(k);
        for o in &mut spec.scene.objects {
            o.mesh = Arc::clone(&spot);
            o.scale = glam::Vec3::splat(1.2);
            if o.texture.is_some() {
                o.texture = Some(Arc::clone(&texture));
            }
        }
        let (_, _, todo, solution) = SOLUTIONS
            .iter()
            .find(|(i, t, ..)| *i == id && *t == title)
            .expect("a solution");
        let (starter, _) = checked(&spec, exercise.tolerance);
        assert!(!starter, "{id}, {title}: the starter passes on Spot");
        assert!(solve(&mut spec, &exercise.starter, todo, solution).expect("compiles"));
        let (passed, found) = checked(&spec, exercise.tolerance);
        assert!(passed, "{id}, {title} on Spot: {found}");
        eprintln!("{id}, {title} on Spot: {found}");
    }
}

#[test]
fn every_lab_starter_fails_and_its_solution_passes() {
    let mut labs = 0;
    for path in lesson_files() {
        let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
            panic!("{} loads", path.display());
        };
        for (k, step) in lesson.steps.iter().enumerate() {
            let Some(exercise) = &step.exercise else {
                continue;
            };
            let name = format!("{} step {} ({})", lesson.id, k + 1, step.title.en);
            let spec = lesson.spec_at(k);
            let (passed, starter) = checked(&spec, exercise.tolerance);
            assert!(!passed, "{name}: the starter passes already");
            let (_, _, todo, solution) = SOLUTIONS
                .iter()
                .find(|(id, title, ..)| *id == lesson.id && *title == step.title.en)
                .unwrap_or_else(|| {
                    panic!("{name}: no reference solution in tests/product/labs.rs")
                });
            let mut spec = spec.clone();
            let found = solve(&mut spec, &exercise.starter, todo, solution)
                .unwrap_or_else(|e| panic!("{name}: the solution does not compile: {e}"));
            assert!(found, "{name}: the starter has no line {todo:?}");
            let (passed, solution) = checked(&spec, exercise.tolerance);
            assert!(passed, "{name}: the solution matches {solution}");
            eprintln!("{name}: starter {starter}, solution {solution}");
            labs += 1;
        }
    }
    assert_eq!(labs, SOLUTIONS.len(), "every solution belongs to a lab");
}

/// Correct matrices written another way (cos/sin for the cotangent, the frustum's bounds,
/// an 8-digit π) pass too: the check does not ask for pipelens' own order of operations.
#[test]
fn other_correct_solutions_pass_too() {
    let path = crate::support::repo().join("lessons/25-lab-model-projection.toml");
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("the lab lesson loads");
    };
    let todo_of = |title: &str| {
        SOLUTIONS
            .iter()
            .find(|(_, t, ..)| *t == title)
            .expect("a solution")
            .2
    };
    for (k, variant) in [(4usize, "    float t = radians(fovy) * 0.5;
    float f = cos(t) / sin(t);
    float nf = zNear - zFar;
    return mat4(vec4(f / aspect, 0, 0, 0), vec4(0, f, 0, 0), vec4(0, 0, (zNear + zFar) / nf, -1), vec4(0, 0, 2.0 * zNear * zFar / nf, 0));"),
    (4, "    float top = zNear * tan(radians(fovy / 2.0));
    float right = top * aspect;
    return mat4(zNear / right, 0, 0, 0,  0, zNear / top, 0, 0,  0, 0, -(zFar + zNear) / (zFar - zNear), -1,  0, 0, -2.0 * zFar * zNear / (zFar - zNear), 0);"),
    (2, "    float a = deg * 3.14159265 / 180.0;
    return mat4(cos(a), sin(a), 0, 0, -sin(a), cos(a), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);")] {
        let e = lesson.steps[k].exercise.as_ref().expect("a lab");
        let todo = todo_of(&lesson.steps[k].title.en);
        let p = &e.starter.shader.as_ref().expect("a shader lab").programs;
        let solved = pipeline::shader::link(Some(&p.vertex.source.replace(todo, variant)), Some(&p.fragment.source)).expect("compiles");
        let mut spec = lesson.spec_at(k);
        spec.scene.set_shaders(&ObjectShader { programs: Arc::new(solved), time: 0.0 });
        let d = compared(&spec, e.tolerance);
        assert!(
            d.passed(),
            "step {}: {} of {} pixels (coverage differs at {}, largest {}/255)",
            k + 1,
            d.matching,
            d.total,
            d.coverage_differs,
            d.largest
        );
    }
}

/// The lab `pipelens new-lesson --lab` writes is a lab too: its starter fails, and the diffuse
/// term written where it says TODO passes.
#[test]
fn the_lab_template_fails_as_written_and_passes_when_done() {
    let text =
        std::fs::read_to_string(crate::support::repo().join("assets/templates/new-lab.toml"))
            .expect("the template");
    let text = text.replace("{id}", "lab").replace("{file}", "lab.toml");
    let lesson =
        pipelens::lesson::script::parse_lesson(&text, "lab.toml", std::path::Path::new("."))
            .expect("the template is a valid lesson");
    let e = lesson.steps[0].exercise.as_ref().expect("an exercise");
    let spec = lesson.spec_at(0);
    assert!(
        !compared(&spec, e.tolerance).passed(),
        "the starter passes already"
    );
    let p = &e.starter.shader.as_ref().expect("a shader lab").programs;
    let solved = pipeline::shader::link(
        Some(&p.vertex.source),
        Some(&p.fragment.source.replace(
            "    // TODO: the diffuse term k_d·c·I·max(0, n·l).",
            "    sum += kd * c * light_color * max(dot(n, l), 0.0);",
        )),
    )
    .expect("the solution compiles");
    let mut spec = spec.clone();
    spec.scene.set_shaders(&ObjectShader {
        programs: Arc::new(solved),
        time: 0.0,
    });
    let d = compared(&spec, e.tolerance);
    assert!(d.passed(), "{} of {} pixels", d.matching, d.total);
}
