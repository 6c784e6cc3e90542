//! The bad-input corpus in `tests/corpus/`: every broken lesson, mesh and texture gets one clear
//! message at the right place, the command line exits non-zero, nothing panics; inputs that
//! must work (non-power-of-two, grey and 16-bit textures, a million faces) work.

use std::path::PathBuf;

use crate::support::{pipelens, repo, text};

fn corpus(dir: &str) -> PathBuf {
    repo().join("tests/corpus").join(dir)
}

/// Each broken file of `tests/corpus/lessons/`, the line and column the error must point at,
/// and words its message must contain.
const LESSONS: &[(&str, usize, usize, &str)] = &[
    ("binary", 1, 1, "not UTF-8 text"),
    (
        "ambient-with-position",
        4,
        12,
        "an ambient light has no `position` (only point and spot lights do)",
    ),
    (
        "lesson-compare-single",
        15,
        10,
        "needs `layout = \"compare\"`",
    ),
    ("empty", 1, 1, "the file is empty"),
    ("syntax-error", 1, 14, "unclosed table, expected `]`"),
    ("unknown-key", 2, 1, "did you mean `fovy`?"),
    (
        "wrong-type",
        2,
        8,
        "invalid type: string \"close\", expected a number",
    ),
    ("negative-near", 2, 8, "near must be positive"),
    (
        "near-not-less-than-far",
        3,
        7,
        "far must be greater than near",
    ),
    (
        "fovy-zero",
        2,
        8,
        "fovy must be between 0° and 180° (exclusive), got 0",
    ),
    (
        "fovy-180",
        2,
        8,
        "fovy must be between 0° and 180° (exclusive), got 180",
    ),
    ("zero-viewport", 2, 9, "from 1 to 16384, got 0"),
    ("huge-viewport", 2, 9, "from 1 to 16384, got 100000"),
    ("samples-3", 2, 11, "`samples` must be 1, 4, 8 or 16, got 3"),
    (
        "max-steps-zero",
        2,
        13,
        "`max_steps` must be a whole number of loop iterations from 1 to 16777216, got 0",
    ),
    ("nan-value", 2, 8, "`fovy` must be a finite number, got NaN"),
    (
        "infinite-value",
        2,
        7,
        "`far` must be a finite number, got inf",
    ),
    ("huge-coordinate", 3, 13, "magnitude at most 1e15"),
    (
        "up-parallel-to-gaze",
        1,
        1,
        "is parallel to the view direction",
    ),
    (
        "missing-mesh",
        2,
        8,
        "there is no file {dir}/models/not-here.obj (paths are relative to the folder of the lesson or scene file, {dir})",
    ),
    (
        "missing-texture",
        3,
        11,
        "there is no file {dir}/not-here.png (paths are relative to the folder of the lesson or scene file, {dir})",
    ),
    (
        "unknown-builtin-mesh",
        2,
        8,
        "unknown built-in mesh \"sphear\"",
    ),
    (
        "too-many-triangles",
        2,
        8,
        "would have 33554432 triangles; a built-in mesh may have at most 4000000",
    ),
    ("no-objects", 1, 2, "the scene has no objects"),
    (
        "lesson-undefined-object",
        13,
        9,
        "unknown parameter \"objects.ghost.rotate\"",
    ),
    (
        "lesson-undefined-joint",
        17,
        22,
        "did you mean \"figures.arm.lower\"?",
    ),
    ("lesson-unknown-stage", 13, 9, "`stage` must be one of"),
    (
        "lesson-expect-without-question",
        13,
        10,
        "`expect` needs a `question` in the same step",
    ),
    (
        "lesson-expect-ragged-matrix",
        14,
        10,
        "every row of an `expect` matrix needs as many numbers as the first",
    ),
    (
        "lesson-expect-not-a-number",
        14,
        10,
        "`expect` takes a number (expect = 0.64), a vector",
    ),
    (
        "lesson-inside-misnamed",
        15,
        1,
        "inside test: the rasterizer calls `bool inside(vec2 p, vec2 a, vec2 b, vec2 c)`",
    ),
    (
        "lesson-tolerance-negative",
        15,
        13,
        "`tolerance` must be a positive number, got -1",
    ),
    (
        "lesson-missing-chinese",
        12,
        13,
        "`narration` needs both languages, { en = \"…\", zh = \"…\" }: `zh` is missing",
    ),
    (
        "unclosed-inline-table",
        11,
        9,
        "this `{` is never closed: a table written inline, `{ … }`, ends with `}` (the reader went on to line 12 and stopped there: missing comma between key-value pairs, expected `,`)",
    ),
    (
        "text-without-languages",
        11,
        9,
        "invalid type: string \"Seeing the normals\", expected a text in both languages, { en = \"…\", zh = \"…\" }",
    ),
    (
        "duplicate-key",
        14,
        1,
        "`set` is given twice in the same table: it was first given on line 13, column 1; give each key once",
    ),
    (
        "misspelt-material-parameter",
        13,
        9,
        "unknown parameter \"objects.teapot.shinyness\"; did you mean \"objects.teapot.shininess\"?",
    ),
    (
        "duplicate-light-name",
        16,
        8,
        "two lights are named \"key\" (the first on line 11); names must differ",
    ),
    (
        "misspelt-light-name",
        18,
        9,
        "unknown parameter \"lights.kye.position\"; did you mean \"lights.key.position\"?",
    ),
    ("lesson-no-steps", 1, 1, "the lesson has no steps"),
];

#[test]
fn every_broken_lesson_is_one_clear_error_at_its_place() {
    let dir = corpus("lessons");
    let on_disk = std::fs::read_dir(&dir).expect("corpus").count();
    assert_eq!(
        on_disk,
        LESSONS.len(),
        "every corpus file has its expectation"
    );
    let shown = std::path::absolute(&dir).expect("absolute");
    for (name, line, column, needle) in LESSONS {
        let path = dir.join(format!("{name}.toml"));
        let e = pipelens::lesson::load_file(&path).expect_err(name);
        let first = &e.0[0];
        let needle = needle.replace("{dir}", &shown.to_string_lossy());
        assert!(
            first.line == *line && first.column == *column && first.message.contains(&needle),
            "{name}: expected {line}:{column} \"{needle}\", got\n{e}"
        );
        assert!(
            e.to_string()
                .contains(&format!("{name}.toml:{line}:{column}: error:"))
        );
    }
}

#[test]
fn the_command_line_reports_each_and_fails() {
    let dir = corpus("lessons");
    let paths: Vec<String> = LESSONS
        .iter()
        .map(|(n, ..)| dir.join(format!("{n}.toml")).to_string_lossy().into_owned())
        .collect();
    let mut args = vec!["check"];
    args.extend(paths.iter().map(String::as_str));
    let o = pipelens(&repo(), &args);
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o);
    assert!(
        out.contains(&format!(
            "{} of {} file(s) have errors",
            LESSONS.len(),
            LESSONS.len()
        )),
        "{out}"
    );
    assert!(!out.contains("panicked"), "{out}");
    // Export and the app refuse the same file with the same message.
    let broken = dir.join("fovy-180.toml");
    let o = pipelens(
        &repo(),
        &[
            "export",
            broken.to_str().expect("utf-8"),
            "--out",
            "/nonexistent/x",
        ],
    );
    assert!(!o.status.success());
    assert!(
        text(&o).contains("fovy-180.toml:2:8: error: fovy must be between"),
        "{}",
        text(&o)
    );
}

#[test]
fn a_50_megabyte_file_is_refused_before_it_is_read() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("huge.toml");
    let f = std::fs::File::create(&path).expect("create");
    f.set_len(50 * 1024 * 1024).expect("50 MB");
    let e = pipelens::lesson::load_file(&path).expect_err("too big");
    assert!(
        e.to_string()
            .contains("the file is 52428800 bytes; a scene or lesson file may have at most"),
        "{e}"
    );
}

/// Each broken OBJ and words of its message.
const MESHES: &[(&str, &str)] = &[
    (
        "truncated",
        "truncated.obj:3: `v` needs three numbers x y z (then w, or r g b for a colour), got 2 number(s)",
    ),
    (
        "index-out-of-range",
        "index-out-of-range.obj:4: `7`: v index 7, but the file has 3 `v` line(s)",
    ),
    (
        "uv-index-out-of-range",
        "uv-index-out-of-range.obj:5: `3/4`: vt index 4, but the file has 1 `vt` line(s)",
    ),
    (
        "zero-index",
        "zero-index.obj:4: `0`: index 0, but OBJ indices start at 1",
    ),
    (
        "two-vertex-face",
        "two-vertex-face.obj:4: a face needs at least three vertices, got 2",
    ),
    (
        "nan-coordinate",
        "nan-coordinate.obj:2: `nan` is not a finite number",
    ),
    ("bad-number", "bad-number.obj:3: `1.5.2` is not a number"),
    (
        "no-faces",
        "no-faces.obj: the file has no faces (an OBJ mesh needs `f` lines)",
    ),
];

/// Every broken OBJ of the corpus is reported as `file.obj:LINE: what is wrong` (the one with no
/// faces, as the whole file), and the corpus has no file without its expectation.
#[test]
fn every_broken_mesh_is_named_with_what_is_wrong() {
    let on_disk = std::fs::read_dir(corpus("meshes")).expect("corpus").count();
    assert_eq!(
        on_disk,
        MESHES.len(),
        "every corpus mesh has its expectation"
    );
    for (name, needle) in MESHES {
        let path = corpus("meshes").join(format!("{name}.obj"));
        let e = pipeline::mesh::Mesh::load_obj(&path)
            .expect_err(name)
            .to_string();
        assert!(e.ends_with(needle), "{name}: {e}");
    }
}

#[test]
fn a_million_faces_load_and_render() {
    let mut obj = String::with_capacity(40_000_000);
    let n = 709; // (n − 1)² · 2 = 1 002 528 triangles on an n×n grid
    for j in 0..n {
        for i in 0..n {
            obj.push_str(&format!(
                "v {} {} 0\n",
                i as f32 / n as f32 - 0.5,
                j as f32 / n as f32 - 0.5
            ));
        }
    }
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let a = j * n + i + 1;
            obj.push_str(&format!(
                "f {a} {} {}\nf {a} {} {}\n",
                a + 1,
                a + n + 1,
                a + n + 1,
                a + n
            ));
        }
    }
    let mesh = pipeline::mesh::Mesh::parse_obj(&mut obj.as_bytes(), "grid.obj", "grid.obj")
        .expect("loads");
    assert_eq!(mesh.indices.len(), 2 * (n - 1) * (n - 1));
    assert!(mesh.indices.len() > 1_000_000);
    let scene = pipeline::scene::Scene {
        uniforms: Default::default(),
        objects: vec![pipeline::scene::Object::new("grid", mesh)],
        ..scene_looking_at_the_origin()
    };
    let settings = pipeline::settings::RenderSettings {
        width: 64,
        height: 64,
        shading: pipeline::lighting::Frequency::Unlit,
        ..Default::default()
    };
    let c = pipeline::render(&scene, &settings).expect("renders");
    assert!(c.pixels.coverage.iter().filter(|&&k| k > 0).count() > 64 * 64 / 4);
}

fn scene_looking_at_the_origin() -> pipeline::scene::Scene {
    pipeline::scene::Scene {
        uniforms: Default::default(),
        objects: Vec::new(),
        camera: pipeline::camera::Camera {
            eye: glam::Vec3::new(0.0, 0.0, 1.5),
            at: glam::Vec3::ZERO,
            up: glam::Vec3::Y,
        },
        projection: pipeline::camera::Projection::default(),
        ..pipeline::scene::Scene::default()
    }
}

#[test]
fn textures_that_must_work_do_and_broken_ones_are_named() {
    use pipeline::texture::Texture;
    let t = |name: &str| Texture::load(&corpus("textures").join(name));
    // 3×5: not a power of two; its pyramid still ends at 1×1.
    let npot = t("npot-3x5.png").expect("non-power-of-two works");
    assert_eq!((npot.levels[0].width, npot.levels[0].height), (3, 5));
    let last = npot.levels.last().expect("levels");
    assert_eq!((last.width, last.height), (1, 1));
    assert!(
        (npot.levels[0].texels[0] - glam::Vec3::new(200.0, 100.0, 50.0) / 255.0).length() < 1e-3
    );
    // Grey: the value in all three channels.
    let grey = t("grey-4x4.png").expect("grey works");
    assert!((grey.levels[0].texels[1] - glam::Vec3::splat(90.0 / 255.0)).length() < 1e-3);
    // 16 bits a channel: full red, then full green.
    let deep = t("rgb16-2x2.png").expect("16-bit works");
    assert!((deep.levels[0].texels[0] - glam::Vec3::X).length() < 1e-3);
    assert!((deep.levels[0].texels[1] - glam::Vec3::Y).length() < 1e-3);
    for (name, needle) in [
        ("truncated.png", "cannot load the texture"),
        ("zero-size.png", "cannot load the texture"),
    ] {
        let e = t(name).expect_err(name).to_string();
        assert!(e.contains(name) && e.contains(needle), "{name}: {e}");
    }
}
