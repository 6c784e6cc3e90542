//! The command line, run as a user runs it: without a display, with bad input, `bench` (its
//! exports: `cli_export.rs`).

use crate::support::{pipelens, repo, text};

#[test]
fn without_a_display_the_app_says_so_and_points_to_export() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_pipelens"))
        .current_dir(dir.path())
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .expect("runs");
    assert!(!o.status.success());
    let t = text(&o);
    assert!(
        t.contains("cannot open the window") && t.contains("pipelens export"),
        "{t}"
    );
    assert!(!t.contains("panicked"), "{t}");
}

#[test]
fn a_broken_scene_is_one_clear_message_and_a_failure() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("bad.toml");
    std::fs::write(&scene, "[scene.projection]\nfov = 45\n").expect("write");
    let out = dir.path().join("never");
    let o = pipelens(
        dir.path(),
        &["export", "bad.toml", "--out", out.to_str().expect("utf-8")],
    );
    assert!(!o.status.success());
    let t = text(&o);
    assert!(
        t.contains("bad.toml:2:1: error: unknown field `fov`"),
        "{t}"
    );
    assert!(t.contains("did you mean `fovy`?"), "{t}");
    assert!(!out.exists(), "nothing is written for a broken scene");
}

#[test]
fn an_unwritable_output_is_a_clear_error() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("a-file");
    std::fs::write(&file, "not a folder").expect("write");
    let o = pipelens(
        dir.path(),
        &["export", "--out", file.to_str().expect("utf-8")],
    );
    assert!(!o.status.success());
    assert!(
        text(&o).contains("cannot create the folder"),
        "{}",
        text(&o)
    );
    // In the language asked for (zh-Hans.ftl's `export-cannot-create-the-folder`).
    let o = pipelens(
        dir.path(),
        &[
            "export",
            "--lang",
            "zh",
            "--out",
            file.to_str().expect("utf-8"),
        ],
    );
    assert!(!o.status.success());
    let said = format!("无法创建文件夹 {}", file.display());
    assert!(text(&o).contains(&said), "{}", text(&o));
}

#[test]
fn bad_sizes_and_samples_are_refused_before_rendering() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (args, expect) in [
        (
            vec!["export", "--out", "x", "--size", "0x10"],
            "from 1 to 16384",
        ),
        (
            vec!["export", "--out", "x", "--size", "100000x100000"],
            "from 1 to 16384",
        ),
        (
            vec!["export", "--out", "x", "--samples", "3"],
            "1, 4, 8 or 16",
        ),
        (
            vec![
                "export",
                "--out",
                "x",
                "--size",
                "16384x16384",
                "--samples",
                "16",
            ],
            "needs about 54528 MB for a capture, more than the 2048 MB allowed",
        ),
    ] {
        let o = pipelens(dir.path(), &args);
        assert!(!o.status.success(), "{args:?}");
        assert!(text(&o).contains(expect), "{args:?}: {}", text(&o));
    }
}

#[test]
fn bench_runs_and_prints_every_stage() {
    let o = pipelens(&repo(), &["bench", "--quick"]);
    assert!(o.status.success(), "{}", text(&o));
    let t = text(&o);
    for col in [
        "vertex",
        "clip+setup",
        "raster",
        "resolve",
        "frame",
        "1280×720",
    ] {
        assert!(t.contains(col), "{col} missing from\n{t}");
    }
}
