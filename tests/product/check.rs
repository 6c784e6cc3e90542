//! `pipelens check`, run as an author runs it: lessons, scenes and the shader panel's files.

use crate::support::{pipelens, repo, text};

#[test]
fn check_validates_the_shipped_scenes_and_reports_broken_ones() {
    let scenes = repo().join("assets/scenes");
    let mut paths: Vec<String> = std::fs::read_dir(&scenes)
        .expect("assets/scenes")
        .map(|e| e.expect("entry").path().to_string_lossy().into_owned())
        .filter(|p| p.ends_with(".toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 2);
    let mut args = vec!["check"];
    args.extend(paths.iter().map(String::as_str));
    let o = pipelens(&repo(), &args);
    assert!(o.status.success(), "{}", text(&o));

    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("a.toml"), "[scene.render]\nsamples = 3\n").expect("write");
    let o = pipelens(dir.path(), &["check", "a.toml"]);
    assert!(!o.status.success());
    assert!(
        text(&o).contains("a.toml:2:11: error: `samples` must be 1, 4, 8 or 16, got 3"),
        "{}",
        text(&o)
    );
}

/// `check` takes the shader panel's files too: a `.frag` or `.vert` compiled as that stage, a
/// pipeline function by its file's name, each message at file:line:column; a `.glsl` named for
/// no function is told which names there are.
#[test]
fn check_compiles_shader_files_as_the_panel_does() {
    let dir = tempfile::tempdir().expect("temp dir");
    let write =
        |name: &str, text: &str| std::fs::write(dir.path().join(name), text).expect("write");
    write(
        "ok.frag",
        "#version 330 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n",
    );
    write(
        "bad.vert",
        "#version 330 core\nin vec3 position;\nvoid main() {\n    gl_Position = vec4(position, 1.0)\n}\n",
    );
    write(
        "inside.glsl",
        "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {\n    return true;\n}\n",
    );
    write("mine.glsl", "bool inside(vec2 p) { return true; }\n");
    let o = pipelens(dir.path(), &["check", "ok.frag", "inside.glsl"]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(
        text(&o).contains("ok.frag: ok (fragment shader)"),
        "{}",
        text(&o)
    );
    assert!(
        text(&o).contains("inside.glsl: ok (`bool inside(vec2 p, vec2 a, vec2 b, vec2 c)`)"),
        "{}",
        text(&o)
    );
    let o = pipelens(dir.path(), &["check", "bad.vert", "mine.glsl"]);
    assert!(!o.status.success());
    // The `;` missing at the end of line 4 (after `1.0)`, column 38).
    assert!(
        text(&o).contains("bad.vert:4:38: error: a `;` is missing at the end of this line"),
        "{}",
        text(&o)
    );
    assert!(
        text(&o).contains("mine.glsl: error: a .glsl file is checked as the pipeline function its name says: inside.glsl, depth_test.glsl"),
        "{}",
        text(&o)
    );
    assert!(
        text(&o).contains("2 of 2 file(s) have errors"),
        "{}",
        text(&o)
    );
}
