//! Scene files: the shipped ones parse; each kind of mistake is reported at its exact place.

use std::path::Path;

use pipelens::lesson::{self, Diagnostic};

fn errors(text: &str) -> Vec<Diagnostic> {
    match lesson::parse_scene(text, "t.toml", Path::new(".")) {
        Ok(_) => panic!("expected errors for:\n{text}"),
        Err(d) => d.0,
    }
}

/// Asserts that one error is at `line:column` and its message contains `needle`.
fn assert_error(text: &str, line: usize, column: usize, needle: &str) {
    crate::support::assert_found(&errors(text), line, column, needle);
}

const OBJECT: &str = "[[scene.objects]]\nmesh = \"cube\"\n";

#[test]
fn the_default_scene_parses() {
    let spec = lesson::default_scene().expect("the built-in scene is valid");
    assert_eq!(spec.scene.objects.len(), 3);
}

#[test]
fn syntax_errors_unknown_keys_and_wrong_types() {
    assert_error("[scene\n", 1, 7, "");
    assert_error(
        &format!("{OBJECT}[scene.camera]\neye = [0, 0, 3\n"),
        4,
        15,
        "unclosed array",
    );
    assert_error(
        &format!("{OBJECT}[scene.projection]\nfov = 45\n"),
        4,
        1,
        "did you mean `fovy`?",
    );
    assert_error(
        &format!("{OBJECT}[scene.camera]\neye = \"far away\"\n"),
        4,
        7,
        "",
    );
    assert_error(&format!("{OBJECT}[scene.render]\nwidth = 64.5\n"), 4, 9, "");
    assert_error("[scenery]\n", 1, 2, "did you mean `scene`?");
}

#[test]
fn out_of_range_values() {
    let p = |body: &str| format!("{OBJECT}[scene.projection]\n{body}\n");
    assert_error(&p("near = -1.0"), 4, 8, "near must be positive");
    assert_error(
        &p("near = 5.0\nfar = 2.0"),
        5,
        7,
        "far must be greater than near",
    );
    assert_error(&p("fovy = 0"), 4, 8, "between 0° and 180°");
    assert_error(&p("fovy = 180"), 4, 8, "between 0° and 180°");
    assert_error(&p("fovy = nan"), 4, 8, "must be a finite number");
    assert_error(&p("far = inf"), 4, 7, "must be a finite number");
    assert_error(
        &p("kind = \"fish-eye\""),
        4,
        8,
        "\"perspective\", \"frustum\" or \"ortho\"",
    );
    assert_error(
        &p("kind = \"ortho\"\nleft = 1\nright = 1\nbottom = -1\ntop = 1"),
        5,
        8,
        "left must be less than right",
    );
    assert_error(
        &p("kind = \"frustum\"\nleft = -1"),
        3,
        1,
        "missing: right, bottom, top",
    );
    let r = |body: &str| format!("{OBJECT}[scene.render]\n{body}\n");
    assert_error(&r("width = 0"), 4, 9, "from 1 to 16384");
    assert_error(
        &r("width = 100000\nheight = 100000"),
        4,
        9,
        "from 1 to 16384",
    );
    assert_error(&r("samples = 3"), 4, 11, "1, 4, 8 or 16");
    assert_error(
        &r("cull = \"sideways\""),
        4,
        8,
        "\"none\", \"back\", \"front\"",
    );
    assert_error(
        &r("width = 16384\nheight = 16384\nsamples = 16"),
        3,
        1,
        "needs about 54528 MB for a capture, more than the 2048 MB allowed",
    );
}

#[test]
fn cameras_meshes_and_objects() {
    assert_error(
        &format!("{OBJECT}[scene.camera]\neye = [0, 5, 0]\nat = [0, 0, 0]\nup = [0, 1, 0]\n"),
        3,
        1,
        "parallel to the view direction",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"cub\"\n",
        2,
        8,
        "did you mean \"cube\"?",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"missing.obj\"\n",
        2,
        8,
        "/missing.obj (paths are relative to the folder of the lesson or scene file",
    );
    assert_error(
        "[[scene.objects]]\nmesh = { builtin = \"uv_sphere\", segments = 2 }\n",
        2,
        8,
        "from 3 to 4096",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\nscale = 0\n",
        3,
        9,
        "must not be zero",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\ncolor = [2, 0, 0]\n",
        3,
        9,
        "between 0 and 1",
    );
    assert_error(
        "[scene.render]\nwidth = 64\n",
        1,
        2,
        "the scene has no objects",
    );
}

/// A slerp needs its first orientation (`rotate_axis`), a second axis with a length, and t in
/// [0, 1].
#[test]
fn slerp_between_two_orientations() {
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\nslerp_to = { axis = [0, 0, 1], angle = 90 }\n",
        3,
        12,
        "`slerp_to` needs `rotate_axis` on the same object",
    );
    let first =
        "[[scene.objects]]\nmesh = \"cube\"\nrotate_axis = { axis = [1, 1, 0], angle = 90 }\n";
    assert_error(
        &format!("{first}slerp_to = {{ axis = [0, 0, 0], angle = 90 }}\n"),
        4,
        21,
        "`axis` must not be the zero vector",
    );
    assert_error(
        &format!("{first}slerp_to = {{ axis = [0, 0, 1], angle = 90, t = 1.5 }}\n"),
        4,
        48,
        "`t` runs from 0 (the first orientation) to 1 (the second), got 1.5",
    );
    let good = format!("{first}slerp_to = {{ axis = [0, 0, 1], angle = 90, t = 0.5 }}\n");
    let spec = lesson::parse_scene(&good, "t.toml", Path::new(".")).expect("a good slerp");
    let s = spec.scene.objects[0].slerp.expect("the slerp");
    assert_eq!((s.axis, s.angle_deg, s.t), (glam::Vec3::Z, 90.0, 0.5));
}

#[test]
fn every_problem_is_reported_not_just_the_first() {
    let found = errors(&format!(
        "{OBJECT}[scene.render]\nwidth = 0\nheight = 0\nsamples = 5\n"
    ));
    assert_eq!(found.len(), 3, "{found:?}");
}

#[test]
fn files_that_are_not_scene_text() {
    let dir = tempfile::tempdir().expect("temp dir");
    let empty = dir.path().join("empty.toml");
    std::fs::write(&empty, "").expect("write");
    let e = lesson::load_scene_file(&empty).expect_err("empty file");
    assert!(e.to_string().contains("the file is empty"), "{e}");
    let binary = dir.path().join("binary.toml");
    std::fs::write(&binary, [0x89, b'P', b'N', b'G', 0xff, 0xfe, 0]).expect("write");
    let e = lesson::load_scene_file(&binary).expect_err("binary file");
    assert!(e.to_string().contains("not UTF-8 text"), "{e}");
    let e = lesson::load_scene_file(&dir.path().join("nope.toml")).expect_err("missing file");
    assert!(e.to_string().contains("cannot read the file"), "{e}");
}

#[test]
fn obj_files_load_with_normals_computed_and_bad_ones_are_named() {
    let dir = tempfile::tempdir().expect("temp dir");
    let good = dir.path().join("quad.obj");
    std::fs::write(&good, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").expect("write");
    let scene = format!("[[scene.objects]]\nmesh = \"{}\"\n", good.display());
    let spec = lesson::parse_scene(&scene, "t.toml", Path::new(".")).expect("valid");
    let mesh = &spec.scene.objects[0].mesh;
    assert_eq!(mesh.indices.len(), 2, "the quad is triangulated");
    assert!(
        mesh.normals
            .iter()
            .all(|n| (*n - glam::Vec3::Z).length() < 1e-6),
        "normals computed as +z"
    );
    for (name, body, needle) in [
        (
            "out.obj",
            "v 0 0 0\nv 1 0 0\nf 1 2 7\n",
            "out.obj:3: `7`: v index 7, but the file has 2 `v` line(s)",
        ),
        ("none.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "has no faces"),
        (
            "nan.obj",
            "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n",
            "nan.obj:2: `nan` is not a finite number",
        ),
        (
            "two.obj",
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
            "two.obj:3: a face needs at least three vertices, got 2",
        ),
    ] {
        let p = dir.path().join(name);
        std::fs::write(&p, body).expect("write");
        let scene = format!("[[scene.objects]]\nmesh = \"{}\"\n", p.display());
        let e = lesson::parse_scene(&scene, "t.toml", Path::new(".")).expect_err(name);
        assert!(
            e.0[0].message.contains(name) && e.0[0].message.contains(needle),
            "{name}: {e}"
        );
    }
}

#[test]
fn the_complete_example_in_lessons_readme_is_valid() {
    let readme =
        std::fs::read_to_string(crate::support::repo().join("lessons/README.md")).expect("README");
    let block = readme
        .split("```toml\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .expect("a ```toml block");
    // The example names an OBJ the reader would have; stand a built-in mesh in for it.
    let block = block.replace("\"models/bunny.obj\"", "\"cube\"");
    let spec = lesson::parse_scene(&block, "README example", Path::new("."))
        .expect("the example is valid");
    assert_eq!(spec.scene.objects.len(), 2);
    assert_eq!(spec.settings.samples.count(), 4);
    assert_eq!(spec.scene.lights.len(), 3);
    assert_eq!(spec.settings.shading, pipeline::lighting::Frequency::Phong);
}

#[test]
fn lights_and_materials_are_checked() {
    assert_error(
        &format!("{OBJECT}[[scene.lights]]\nkind = \"laser\"\n"),
        4,
        8,
        "\"ambient\", \"point\"",
    );
    assert_error(
        &format!("{OBJECT}[[scene.lights]]\nkind = \"point\"\n"),
        3,
        1,
        "needs `position`",
    );
    assert_error(
        &format!(
            "{OBJECT}[[scene.lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff = 120\n"
        ),
        7,
        10,
        "between 0° and 90°",
    );
    assert_error(
        &format!("{OBJECT}[[scene.lights]]\nkind = \"ambient\"\nintensity = -1\n"),
        5,
        13,
        "must not be negative",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\nmaterial = { kd = [1, 2] }\n",
        3,
        19,
        "one number, or an array of three numbers",
    );
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\nmaterial = { shine = 3 }\n",
        3,
        14,
        "did you mean `shininess`?",
    );
    assert_error(
        &format!("{OBJECT}[scene.render]\nshading = \"smooth\"\n"),
        4,
        11,
        "\"unlit\", \"flat\", \"gouraud\", \"phong\"",
    );
}

/// `normals = "average" | "area_weighted"` computes an object's vertex normals from its faces
/// (replacing a built-in's exact ones); the parameter `objects.NAME.normals` switches them.
#[test]
fn vertex_normals_can_be_averaged_plainly_or_by_area() {
    use pipelens::lesson::{param, parse_scene};
    let scene = |normals: &str| {
        let text = format!(
            "[[scene.objects]]\nname = \"c\"\nmesh = {{ builtin = \"cylinder\", segments = 8 }}\n{normals}"
        );
        parse_scene(&text, "t.toml", std::path::Path::new(".")).expect("valid")
    };
    let normals = |s: &pipelens::lesson::SceneSpec| s.scene.objects[0].mesh.normals.clone();
    let exact = normals(&scene(""));
    let plain = normals(&scene("normals = \"average\"\n"));
    let weighted = normals(&scene("normals = \"area_weighted\"\n"));
    // A rim vertex belongs to thin cap triangles and tall side triangles: the averages differ
    // from the exact (split) normals and from each other.
    assert_ne!(exact, plain);
    assert_ne!(plain, weighted);
    let mut spec = scene("");
    param::apply(
        &mut spec,
        "objects.c.normals",
        &param::Value::Name("area_weighted".into()),
    )
    .expect("a parameter");
    assert_eq!(normals(&spec), weighted);
    assert_error(
        "[[scene.objects]]\nmesh = \"cube\"\nnormals = \"avg\"\n",
        3,
        11,
        "`normals` must be one of \"average\", \"area_weighted\", got \"avg\"",
    );
}

#[test]
fn shaders_come_from_files_beside_the_scene_or_inline_and_their_mistakes_point_into_them() {
    let dir = tempfile::tempdir().expect("temp dir");
    let frag = "#version 330 core\nin vec3 v_color;\nout vec4 color;\nvoid main() {\n    color = vec4(v_color * 0.5, 1.0);\n}\n";
    std::fs::write(dir.path().join("half.frag"), frag).expect("write");
    let scene = format!("{OBJECT}shader = {{ fragment = \"half.frag\" }}\n");
    let spec = lesson::parse_scene(&scene, "t.toml", dir.path()).expect("valid");
    let sh = spec.scene.objects[0]
        .code
        .shader
        .as_ref()
        .expect("the object's shaders");
    assert_eq!(sh.programs.fragment.source, frag);
    // The scene's shader applies to every object without one of its own, inline GLSL too.
    let scene = format!("[scene]\nshader = {{ fragment = '''\n{frag}''' }}\n{OBJECT}{OBJECT}");
    let spec = lesson::parse_scene(&scene, "t.toml", dir.path()).expect("valid");
    assert!(spec.scene.objects.iter().all(|o| o.code.shader.is_some()));
    // A typo in the file: its own name, line and column.
    std::fs::write(
        dir.path().join("typo.frag"),
        frag.replace("vec4(v_color", "vec4(v_colour"),
    )
    .expect("write");
    let scene = format!("{OBJECT}shader = {{ fragment = \"typo.frag\" }}\n");
    let e = lesson::parse_scene(&scene, "t.toml", dir.path()).expect_err("a typo");
    assert!(
        e.0[0].file.ends_with("typo.frag") && e.0[0].line == 5 && e.0[0].column == 18,
        "{e}"
    );
    assert!(e.0[0].message.contains("v_colour"), "{e}");
    // A typo inline: its line in the scene file.
    let scene = format!(
        "[scene]\nshader = {{ fragment = '''\n{}''' }}\n{OBJECT}",
        frag.replace("out vec4", "out vex4")
    );
    let found = errors(&scene);
    crate::support::assert_found(&found, 5, 5, "vex4");
    // A missing file is named with the folder it was looked for in.
    let found = errors(&format!(
        "{OBJECT}shader = {{ vertex = \"nowhere.vert\" }}\n"
    ));
    crate::support::assert_found(&found, 3, 21, "there is no file");
}

#[test]
fn the_shader_pair_in_lessons_readme_compiles_and_links() {
    let readme =
        std::fs::read_to_string(crate::support::repo().join("lessons/README.md")).expect("README");
    let block = |name: &str| {
        readme
            .split("```glsl\n")
            .find(|b| b.starts_with(&format!("// {name}")))
            .and_then(|b| b.split("```").next())
            .unwrap_or_else(|| panic!("a ```glsl block starting // {name}"))
            .to_owned()
    };
    let programs = pipeline::shader::link(Some(&block("toon.vert")), Some(&block("toon.frag")))
        .unwrap_or_else(|e| panic!("the README's shaders: {e:?}"));
    assert_eq!(programs.fragment.inputs.len(), 2);
}
