//! Lessons: every file in `lessons/` loads, each step's scene renders, animations move as
//! specified, and broken lessons are reported at the right place.

use std::path::Path;

use glam::Vec3;
use pipelens::lesson::param::{Animation, Easing, Repeat, Value};
use pipelens::lesson::script::parse_lesson;
use pipelens::lesson::{Diagnostic, Document, load_file};
use pipelens::vocabulary::Lang;

use crate::support::{lesson_files, repo};

#[test]
fn every_lesson_loads_and_every_step_renders() {
    let files = lesson_files();
    assert!(!files.is_empty());
    for path in files {
        let doc = load_file(&path).unwrap_or_else(|e| panic!("{e}"));
        let Document::Lesson(lesson) = doc else {
            panic!("{} is not a lesson", path.display());
        };
        let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
        assert_eq!(lesson.id, name, "the id is the file name");
        assert!(
            (5..=12).contains(&lesson.steps.len()),
            "{name}: {} steps (a lesson has 5 to 12)",
            lesson.steps.len()
        );
        for k in 0..lesson.steps.len() {
            for t in [0.0, 1.7] {
                let mut spec = lesson.spec_playing(k, t);
                // Small, so that the whole set renders quickly.
                spec.settings.width = spec.settings.width.min(160);
                spec.settings.height = spec.settings.height.min(100);
                let c = pipeline::render(&spec.scene, &spec.settings)
                    .unwrap_or_else(|e| panic!("{name} step {k}: {e}"));
                assert!(
                    c.pixels.color.iter().flatten().all(|v| v.is_finite()),
                    "{name} step {k}: NaN in the image"
                );
            }
        }
    }
}

#[test]
fn the_built_in_lesson_is_the_tour() {
    let lesson = pipelens::lesson::default_lesson().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(lesson.id, "00-tour");
}

#[test]
fn animations_reach_their_values_at_the_right_times() {
    let a = Animation {
        param: "projection.fovy".into(),
        from: Value::Number(30.0),
        to: Value::Number(90.0),
        seconds: 4.0,
        easing: Easing::Linear,
        repeat: Repeat::PingPong,
    };
    let at = |a: &Animation, t: f32| match a.value_at(t) {
        Value::Number(x) => x,
        v => panic!("{v}"),
    };
    assert_eq!(at(&a, 0.0), 30.0);
    assert_eq!(at(&a, 1.0), 45.0);
    assert_eq!(at(&a, 4.0), 90.0);
    assert_eq!(at(&a, 6.0), 60.0, "on the way back");
    assert_eq!(at(&a, 8.0), 30.0);
    let once = Animation {
        repeat: Repeat::Once,
        ..a.clone()
    };
    assert_eq!(at(&once, 9.0), 90.0);
    assert!(once.finished(4.0) && !once.finished(3.9));
    let looped = Animation {
        repeat: Repeat::Loop,
        ..a.clone()
    };
    assert_eq!(at(&looped, 5.0), 45.0);
    // Smoothstep: 3t² − 2t³ is ½ halfway and 0.15625 at a quarter.
    let eased = Animation {
        easing: Easing::EaseInOut,
        repeat: Repeat::Once,
        ..a.clone()
    };
    assert_eq!(at(&eased, 2.0), 60.0);
    assert!((at(&eased, 1.0) - (30.0 + 60.0 * 0.156_25)).abs() < 1e-4);
    let v = Animation {
        param: "camera.eye".into(),
        from: Value::Vec3(Vec3::ZERO),
        to: Value::Vec3(Vec3::new(2.0, 4.0, -8.0)),
        seconds: 2.0,
        easing: Easing::Linear,
        repeat: Repeat::Once,
    };
    assert_eq!(v.value_at(0.5), Value::Vec3(Vec3::new(0.5, 1.0, -2.0)));
}

/// A minimal lesson around `steps`.
fn lesson_with(steps: &str) -> String {
    format!(
        "[lesson]\nid = \"t\"\ntitle = {{ en = \"T\", zh = \"题\" }}\nsummary = {{ en = \"S\", zh = \"概\" }}\n\n\
         [[scene.objects]]\nname = \"cube\"\nmesh = \"cube\"\n\n{steps}"
    )
}

const STEP: &str =
    "[[steps]]\ntitle = { en = \"a\", zh = \"甲\" }\nnarration = { en = \"b\", zh = \"乙\" }\n";

fn errors(text: &str) -> Vec<Diagnostic> {
    match parse_lesson(text, "t.toml", Path::new(".")) {
        Ok(_) => panic!("expected errors in:\n{text}"),
        Err(d) => d.0,
    }
}

/// Asserts that one error is at `line:column` and its message contains `needle`.
fn assert_error(text: &str, line: usize, column: usize, needle: &str) {
    crate::support::assert_found(&errors(text), line, column, needle);
}

#[test]
fn broken_lessons_are_reported_where_the_mistake_is() {
    // The step's keys start on line 12 (after the 10 lines of the header and scene).
    let base = lesson_with(STEP);
    assert!(
        parse_lesson(&base, "t.toml", Path::new(".")).is_ok(),
        "the base is valid"
    );
    // Each mistake on line 13, with the column of the text the error must point at.
    let check = |extra: &str, at: &str, needle: &str| {
        let column = extra.find(at).expect("`at` is in the line") + 1;
        assert_error(&format!("{base}{extra}\n"), 13, column, needle);
    };
    for (extra, at, needle) in crate::lesson_mistakes::MISTAKES {
        check(extra, at, needle);
    }
    // No steps; no [lesson] id.
    assert_error(&lesson_with(""), 1, 1, "no steps");
    assert_error(
        &base.replace("id = \"t\"\n", ""),
        1,
        1,
        "missing field `id`",
    );
}

#[test]
fn later_steps_keep_earlier_settings() {
    let text = lesson_with(&format!(
        "{STEP}set = {{ \"projection.fovy\" = 60 }}\n{STEP}set = {{ \"render.shading\" = \"flat\" }}\n{STEP}"
    ));
    let lesson = parse_lesson(&text, "t.toml", Path::new(".")).unwrap_or_else(|e| panic!("{e}"));
    let fovy = |k: usize| match lesson.spec_at(k).scene.projection {
        pipeline::camera::Projection::Perspective { fovy_deg, .. } => fovy_deg,
        _ => f32::NAN,
    };
    assert_eq!((fovy(0), fovy(1), fovy(2)), (60.0, 60.0, 60.0));
    assert_eq!(
        lesson.spec_at(0).settings.shading,
        lesson.scene.settings.shading
    );
    assert_eq!(
        lesson.spec_at(2).settings.shading,
        pipeline::lighting::Frequency::Flat
    );
}

#[test]
fn every_lesson_exports_a_handout() {
    let dir = tempfile::tempdir().expect("temp dir");
    // Each lesson in one language, alternating, so both handouts are covered without exporting
    // everything twice (the app test draws every step in both languages).
    for (index, path) in lesson_files().into_iter().enumerate() {
        let Ok(Document::Lesson(lesson)) = load_file(&path) else {
            panic!("{} loads", path.display());
        };
        for lang in [["en", "zh"][index % 2]] {
            let out = dir.path().join(format!("{}-{lang}", lesson.id));
            let o = crate::support::pipelens(
                dir.path(),
                &[
                    "export",
                    path.to_str().expect("utf-8"),
                    "--out",
                    out.to_str().expect("utf-8"),
                    "--size",
                    "160x100",
                    "--lang",
                    lang,
                ],
            );
            assert!(o.status.success(), "{}", crate::support::text(&o));
            let html = std::fs::read_to_string(out.join("index.html")).expect("index.html");
            let words = crate::support::without_tags(&html);
            for (k, step) in lesson.steps.iter().enumerate() {
                let title = if lang == "zh" {
                    &step.title.zh
                } else {
                    &step.title.en
                };
                assert!(
                    html.contains(&title.replace('&', "&amp;").replace('<', "&lt;")),
                    "{}: step {k}'s title in the handout",
                    lesson.id
                );
                // A lab prints the starter of every function the student completes.
                for hook in step.exercise.iter().flat_map(|e| {
                    pipeline::shader::HookKind::ALL
                        .into_iter()
                        .filter_map(|kind| e.starter.hooks.get(kind))
                }) {
                    // The listing colours its words (the page's text, tags left out), and
                    // its comments are in the handout's language.
                    let language = if lang == "zh" { Lang::ZH } else { Lang::EN };
                    let shown = pipelens::vocabulary::glsl::localize(
                        &hook.source,
                        language,
                        &lesson.comments,
                    );
                    let first = shown.trim().lines().next().unwrap_or_default();
                    let printed = first.replace('&', "&amp;").replace('<', "&lt;");
                    assert!(
                        words.contains(&printed),
                        "{}: step {k}'s starter {:?} in the handout",
                        lesson.id,
                        hook.kind
                    );
                }
            }
            crate::handout::assert_self_contained(&html, &lesson.id);
            if lang == "zh" {
                crate::handout::assert_captions_chinese(&html, &lesson.id);
            }
            let files: Vec<_> = std::fs::read_dir(&out).expect("out").collect();
            assert_eq!(files.len(), 1, "{}: index.html alone", lesson.id);
        }
    }
}

#[test]
fn one_step_of_a_lesson_exports_alone_and_a_wrong_step_is_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let tour = repo().join("lessons/00-tour.toml");
    let out = dir.path().join("one");
    let run = |step: &str| {
        crate::support::pipelens(
            dir.path(),
            &[
                "export",
                tour.to_str().expect("utf-8"),
                "--out",
                out.to_str().expect("utf-8"),
                "--size",
                "160x100",
                "--step",
                step,
            ],
        )
    };
    let o = run("99");
    assert!(!o.status.success());
    assert!(
        crate::support::text(&o).contains("out of range: the lesson has steps 1 to 10"),
        "{}",
        crate::support::text(&o)
    );
    assert!(!out.exists(), "nothing written");
    let o = run("3");
    assert!(o.status.success(), "{}", crate::support::text(&o));
    let entries: Vec<String> = std::fs::read_dir(&out)
        .expect("out")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    let mut entries = entries;
    entries.sort();
    assert_eq!(entries, ["index.html"], "the data only on request");
}

#[test]
fn the_complete_lesson_in_lessons_readme_is_valid() {
    let readme = std::fs::read_to_string(repo().join("lessons/README.md")).expect("README");
    let block = readme
        .split("```toml\n")
        .find(|b| b.starts_with("[lesson]"))
        .and_then(|b| b.split("```").next())
        .expect("a ```toml block with a lesson");
    let lesson = parse_lesson(block, "README lesson", Path::new("."))
        .unwrap_or_else(|e| panic!("the example is valid:\n{e}"));
    assert_eq!(lesson.steps.len(), 2);
    assert_eq!(lesson.steps[0].animate.len(), 1);
    assert_eq!(lesson.steps[1].pixel, Some((320, 200)));
}

#[test]
fn every_matrix_formula_a_lesson_shows_reads_in_chinese() {
    use pipelens::vocabulary::Lang;
    fn walk(m: &pipeline::transform::NamedMatrix, out: &mut std::collections::BTreeSet<String>) {
        out.insert(m.formula.clone());
        for f in &m.factors {
            walk(f, out);
        }
    }
    let mut formulas = std::collections::BTreeSet::new();
    for path in lesson_files() {
        let Ok(Document::Lesson(lesson)) = load_file(&path) else {
            panic!("{} loads", path.display());
        };
        // Every step, and the first step again with each other kind of projection (a lesson
        // may switch to any of them).
        let first = lesson.spec_at(0);
        let kinds = [
            pipeline::camera::Projection::Frustum {
                left: -0.4,
                right: 0.6,
                bottom: -0.3,
                top: 0.3,
                near: 1.0,
                far: 10.0,
            },
            pipeline::camera::Projection::Ortho {
                left: -2.0,
                right: 2.0,
                bottom: -1.5,
                top: 1.5,
                near: 0.5,
                far: 10.0,
            },
        ];
        let specs =
            (0..lesson.steps.len())
                .map(|k| lesson.spec_at(k))
                .chain(kinds.into_iter().map(|projection| {
                    let mut spec = first.clone();
                    spec.scene.projection = projection;
                    spec
                }));
        for mut spec in specs {
            spec.settings.width = 32;
            spec.settings.height = 20;
            let c = pipeline::render(&spec.scene, &spec.settings).expect("renders");
            let m = &c.matrices;
            for x in
                m.models
                    .iter()
                    .chain([&m.view, &m.projection, &m.projection_games101, &m.viewport])
            {
                walk(x, &mut formulas);
            }
            for step in &c.hierarchy {
                if let pipeline::hierarchy::Step::Visit { composite, .. } = step {
                    walk(composite, &mut formulas);
                }
            }
        }
    }
    let untranslated: Vec<&String> = formulas
        .iter()
        .filter(|f| is_prose(f) && Lang::ZH.formula(f) == **f)
        .collect();
    assert!(untranslated.is_empty(), "no Chinese for: {untranslated:#?}");
    assert!(formulas.len() > 20);
}

/// Whether `formula` reads as English prose (a lowercase word of three or more letters that is
/// not a name of the mathematics), and so needs a Chinese version.
fn is_prose(formula: &str) -> bool {
    formula
        .split(|c: char| !c.is_ascii_alphabetic())
        .filter(|w| w.len() >= 3 && w.chars().all(|c| c.is_ascii_lowercase()))
        .any(|w| {
            !matches!(
                w,
                "near"
                    | "far"
                    | "fovy"
                    | "aspect"
                    | "tan"
                    | "cot"
                    | "cos"
                    | "sin"
                    | "right"
                    | "top"
                    | "width"
                    | "height"
                    | "eye"
                    | "parent"
                    | "local"
                    | "torso"
                    | "upper"
                    | "lower"
            )
        })
}

/// Lesson 05's off-centre step: `projection.kind = "frustum"` keeps the near rectangle, and
/// with l = −0.3, r = 1.0, n = 1 the shear H of Frustum = N·S·H has (r + l)/(2n) = 0.35 in its
/// first row, third column; the next step is the symmetric perspective again.
#[test]
fn the_off_centre_frustum_step_shows_a_shear() {
    let Ok(Document::Lesson(lesson)) = load_file(&repo().join("lessons/05-perspective.toml"))
    else {
        panic!("lesson 05 loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en.starts_with("An off-centre frustum"))
        .expect("the step");
    let spec = lesson.spec_at(k);
    let capture = pipeline::render(&spec.scene, &spec.settings).expect("renders");
    let h = capture
        .matrices
        .projection
        .factors
        .iter()
        .find(|f| f.name.starts_with('H'))
        .expect("an H factor");
    let rows = h.matrix.transpose().to_cols_array_2d();
    assert!((rows[0][2] - 0.35).abs() < 1e-6, "{rows:?}");
    assert!(rows[1][2].abs() < 1e-6, "symmetric in y: {rows:?}");
    let before = lesson.spec_at(k - 1);
    let after = lesson.spec_at(k + 1);
    assert_eq!(
        before.scene.projection.bounds(1.6),
        after.scene.projection.bounds(1.6),
        "the next step is the symmetric frustum again"
    );
}

/// The app's built-in lessons (the Lessons menu, the browser build) are every file of
/// `lessons/`, each with its title in both languages.
#[test]
fn the_built_in_lessons_are_the_lessons_folder() {
    let on_disk: Vec<String> = lesson_files()
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    let built_in: Vec<String> = pipelens::lesson::library::LESSONS
        .iter()
        .map(|(f, _)| (*f).to_owned())
        .collect();
    assert_eq!(built_in, on_disk);
    for (file, text) in pipelens::lesson::library::LESSONS {
        assert_eq!(
            text,
            std::fs::read_to_string(repo().join("lessons").join(file)).expect("the file")
        );
        let t = pipelens::lesson::library::title(text, file);
        assert!(
            t.en != file && t.zh != file && t.en != t.zh,
            "{file}: {} / {}",
            t.en,
            t.zh
        );
    }
    let e = pipelens::lesson::library::lesson("99-nope.toml").expect_err("no such lesson");
    assert!(e.to_string().contains("there are 00-tour.toml"), "{e}");
}

/// The Lessons menu shows a lesson's title in the interface's language, as the lesson itself
/// is shown: so it reads every language the title gives, not English and Chinese alone.
#[test]
fn a_menu_title_keeps_every_language_of_the_lesson() {
    let text = "[lesson]\nid = \"x\"\ntitle = { en = \" Depth \", zh = \"深度\", pt-BR = \"Profundidade\" }\n";
    let t = pipelens::lesson::library::title(text, "x.toml");
    assert_eq!((t.en.as_str(), t.zh.as_str()), ("Depth", "深度"));
    assert_eq!(
        t.others.get("pt-BR").map(String::as_str),
        Some("Profundidade")
    );
    let untitled = pipelens::lesson::library::title("[lesson]\nid = \"x\"\n", "x.toml");
    assert_eq!(
        (untitled.en.as_str(), untitled.zh.as_str()),
        ("x.toml", "x.toml")
    );
}

#[test]
fn a_steps_shader_mistake_points_into_the_lesson() {
    let text = lesson_with(&format!(
        "{STEP}shader.fragment = \"\"\"\n#version 330 core\nout vec4 color;\nvoid main() {{\n    color = vec4(flot(1.0));\n}}\n\"\"\"\n"
    ));
    let found = errors(&text);
    let line = text
        .lines()
        .position(|l| l.contains("flot("))
        .expect("the line")
        + 1;
    assert!(
        found
            .iter()
            .any(|d| d.line == line && d.message.contains("flot")),
        "{found:?}"
    );
}

/// A step that compares objects names them in the picture: lesson 21's three shapes get their
/// labels above them, left to right as the narration says; lesson 15's first step shows one
/// labelled sphere (the others are moved away), which needs no name.
#[test]
fn the_objects_a_step_compares_are_named_in_the_picture() {
    use pipelens::vocabulary::Lang;
    let named = |file: &str, k: usize, lang: Lang| {
        let Ok(Document::Lesson(lesson)) = load_file(&repo().join(file)) else {
            panic!("{file} loads");
        };
        let spec = lesson.spec_at(k);
        let c = pipeline::render(&spec.scene, &spec.settings).expect("renders");
        let mut names = spec.object_labels(&c, &c.object_label_points(), lang);
        names.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
        names
    };
    let three = named("lessons/21-geometry-representations.toml", 0, Lang::ZH);
    let words: Vec<&str> = three.iter().map(|(_, n)| n.as_str()).collect();
    assert_eq!(words, ["参数球面", "隐式曲面", "点云"]);
    // Each name sits above its shape: in the upper half of a picture whose shapes are centred.
    assert!(
        three.iter().all(|([_, y], _)| *y < 360.0 / 2.0),
        "{three:?}"
    );
    assert!(named("lessons/15-surface-detail.toml", 0, Lang::EN).is_empty());
}

/// A lesson gives any language beside `en` and `zh` by its BCP 47 tag: its words show in that
/// language (found by its language alone too, `fr` for `fr-CA`), in English where a text lacks
/// it, and the lesson's warnings name the incomplete language at the first text without it.
#[test]
fn a_lesson_speaks_any_language_and_an_incomplete_one_is_reported() {
    let text = "[lesson]\nid = \"t\"\n\
                title = { en = \"T\", zh = \"题\", fr = \"Titre\" }\n\
                summary = { en = \"S\", zh = \"概\", fr = \"Résumé\" }\n\n\
                [[scene.objects]]\nname = \"cube\"\nmesh = \"cube\"\n\n\
                [[steps]]\ntitle = { en = \"a\", zh = \"甲\", fr = \"le a\" }\n\
                narration = { en = \"b\", zh = \"乙\" }\n";
    let lesson = parse_lesson(text, "t.toml", Path::new(".")).unwrap_or_else(|e| panic!("{e}"));
    let fr = Lang::uncatalogued("fr");
    assert_eq!(lesson.title.get(fr), "Titre");
    assert_eq!(lesson.summary.get(fr), "Résumé");
    assert_eq!(lesson.steps[0].title.get(fr), "le a");
    assert_eq!(
        lesson.steps[0].title.get(Lang::uncatalogued("fr-CA")),
        "le a"
    );
    assert_eq!(lesson.steps[0].narration.get(fr), "b");
    assert_eq!(lesson.steps[0].title.get(Lang::ZH), "甲");
    assert_eq!(lesson.steps[0].title.get(Lang::EN), "a");
    // Four texts, one without French: the step's narration, line 12, its `{` at column 13.
    crate::support::assert_found(
        &lesson.warnings,
        12,
        13,
        "the language `fr` is incomplete: 1 of the lesson's 4 texts lack it",
    );
    assert_eq!(lesson.warnings.len(), 1, "{:?}", lesson.warnings);
    // French everywhere: no warning.
    let whole = text.replace("乙\" }", "乙\", fr = \"le b\" }");
    let lesson = parse_lesson(&whole, "t.toml", Path::new(".")).unwrap_or_else(|e| panic!("{e}"));
    assert!(lesson.warnings.is_empty(), "{:?}", lesson.warnings);
    // A key that is no language tag is an error where the text is.
    let typo = text.replace("fr = \"le a\"", "\"fr!\" = \"le a\"");
    assert_error(&typo, 11, 9, "`fr!`, which is not a language tag");
}
