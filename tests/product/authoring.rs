//! Writing lessons: `pipelens check` on folders, its warnings and mesh sizes, and
//! `pipelens new-lesson`.

use crate::support::{pipelens, repo, text};

/// `check FOLDER` checks every `.toml` file under it, as linters do, and says which is broken;
/// a folder with none is an error, not a silent success.
#[test]
fn check_reads_every_lesson_and_scene_in_a_folder() {
    let o = pipelens(&repo(), &["check", "lessons", "assets/scenes"]);
    let out = text(&o);
    assert!(o.status.success(), "{out}");
    let lessons = std::fs::read_dir(repo().join("lessons"))
        .expect("lessons")
        .filter(|e| {
            e.as_ref()
                .is_ok_and(|e| e.path().extension().is_some_and(|x| x == "toml"))
        })
        .count();
    assert_eq!(out.matches(": ok (lesson").count(), lessons, "{out}");
    assert!(
        out.contains("assets/scenes/default.toml: ok (scene)"),
        "{out}"
    );

    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::create_dir(dir.path().join("unit")).expect("mkdir");
    let scene =
        |eye: &str| format!("[scene.camera]\neye = {eye}\n\n[[scene.objects]]\nmesh = \"cube\"\n");
    std::fs::write(dir.path().join("unit/good.toml"), scene("[0, 0, 3]")).expect("write");
    std::fs::write(dir.path().join("unit/bad.toml"), scene("[0, 0]")).expect("write");
    std::fs::write(dir.path().join("unit/notes.txt"), "not a lesson").expect("write");
    let o = pipelens(dir.path(), &["check", "unit"]);
    let out = text(&o);
    assert!(!o.status.success());
    assert!(out.contains("good.toml: ok (scene)"), "{out}");
    assert!(
        out.contains("bad.toml:2:"),
        "the broken file with its line: {out}"
    );
    assert!(out.contains("1 of 2 file(s) have errors"), "{out}");
    std::fs::create_dir(dir.path().join("empty")).expect("mkdir");
    let o = pipelens(dir.path(), &["check", "empty"]);
    assert!(!o.status.success());
    assert!(text(&o).contains("this folder has no .toml file to check"));
}

#[test]
fn check_warns_of_an_id_unlike_the_file_name_and_describes_each_mesh() {
    let dir = tempfile::tempdir().expect("temp dir");
    // A 2×4×6 box whose corner is at the origin: centre (1, 2, 3); fitted, its half-diagonal
    // √(1 + 4 + 9) becomes 1.
    let obj = "v 0 0 0\nv 2 0 0\nv 2 4 0\nv 0 4 6\nf 1 2 3\nf 1 3 4\n";
    std::fs::write(dir.path().join("box.obj"), obj).expect("write");
    let lesson = |fit: bool| {
        format!(
            "[lesson]\nid = \"other\"\ntitle = {{ en = \"A\", zh = \"甲\" }}\n\
             summary = {{ en = \"A.\", zh = \"甲。\" }}\n\n[[scene.objects]]\nname = \"box\"\n\
             mesh = \"box.obj\"\nfit = {fit}\n\n[[scene.lights]]\nname = \"key\"\nkind = \"point\"\n\
             position = [1, 1, 1]\n\n[[steps]]\ntitle = {{ en = \"A\", zh = \"甲\" }}\n\
             narration = {{ en = \"A.\", zh = \"甲。\" }}\nset = {{ \"lights.key.intensity\" = 0.5 }}\n"
        )
    };
    std::fs::write(dir.path().join("mine.toml"), lesson(false)).expect("write");
    let o = pipelens(dir.path(), &["check", "mine.toml"]);
    let out = text(&o);
    assert!(
        o.status.success(),
        "a warning does not fail the check: {out}"
    );
    assert!(
        out.contains(
            "mine.toml:2:6: warning: the id \"other\" differs from the file's name \"mine\""
        ),
        "{out}"
    );
    assert!(
        out.contains("box: box.obj, 2 triangles, box [0, 0, 0] to [2, 4, 6], centre [1, 2, 3]"),
        "{out}"
    );
    // A narration left as the placeholder of a lesson started from the scene on screen.
    // So are its step's title and the lesson's title, each in the language it was left in.
    let placeholder = lesson(false)
        .replace(
            "narration = { en = \"A.\", zh = \"甲。\" }",
            "narration = { en = \"A.\", zh = \"在这里写下观众应当看到什么、为什么。\" }",
        )
        .replace(
            "[[steps]]\ntitle = { en = \"A\", zh = \"甲\" }",
            "[[steps]]\ntitle = { en = \"Name this step\", zh = \"给这一步起个名字\" }",
        )
        .replace(
            "id = \"other\"\ntitle = { en = \"A\", zh = \"甲\" }",
            "id = \"other\"\ntitle = { en = \"Name this lesson\", zh = \"我的\" }",
        );
    std::fs::write(dir.path().join("other.toml"), placeholder).expect("write");
    let o = pipelens(dir.path(), &["check", "other.toml"]);
    let out = text(&o);
    for said in [
        "warning: step 1's narration is still the new lesson's placeholder in Chinese",
        "warning: step 1's title is still the new lesson's placeholder in English and Chinese",
        "warning: the lesson's title is still the new lesson's placeholder in English",
    ] {
        assert!(out.contains(said), "{said}: {out}");
    }
    std::fs::write(dir.path().join("other.toml"), lesson(true)).expect("write");
    let o = pipelens(dir.path(), &["check", "other.toml"]);
    let out = text(&o);
    assert!(!out.contains("warning"), "{out}");
    // 1/√14 = 0.2673, 2/√14 = 0.5345, 3/√14 = 0.8018.
    assert!(
        out.contains("box [-0.267, -0.535, -0.802] to [0.267, 0.535, 0.802], centre [0, 0, 0]"),
        "{out}"
    );
}

#[test]
fn new_lesson_writes_a_template_with_every_step_key_that_check_accepts() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = pipelens(dir.path(), &["new-lesson", "lessons/20-mine.toml"]);
    assert!(o.status.success(), "{}", text(&o));
    let path = dir.path().join("lessons/20-mine.toml");
    let o = pipelens(dir.path(), &["check", "lessons/20-mine.toml"]);
    let out = text(&o);
    assert!(o.status.success(), "{out}");
    assert!(out.contains("ok (lesson 20-mine, 3 steps)"), "{out}");
    assert!(!out.contains("warning"), "{out}");
    // Every key a step can take, as the reader itself lists them, is used by some step.
    let e = toml::from_str::<pipelens::lesson::raw::RawStep>("zzz = 1").expect_err("unknown");
    let listed = e.message().split_once("expected one of").expect("a list").1;
    let keys: Vec<&str> = listed.split('`').skip(1).step_by(2).collect();
    assert!(keys.len() >= 16, "{keys:?}");
    let written: toml::Table =
        toml::from_str(&std::fs::read_to_string(&path).expect("read")).expect("TOML");
    // The lab template (`--lab`) shows the exercise key; the lesson template every other.
    let o = pipelens(dir.path(), &["new-lesson", "--lab", "lessons/21-lab.toml"]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(text(&o).contains("a lab of 1 step."), "{}", text(&o));
    let o = pipelens(dir.path(), &["check", "lessons/21-lab.toml"]);
    assert!(o.status.success(), "{}", text(&o));
    let lab: toml::Table = toml::from_str(
        &std::fs::read_to_string(dir.path().join("lessons/21-lab.toml")).expect("read"),
    )
    .expect("TOML");
    let mut steps = written["steps"].as_array().expect("steps").clone();
    steps.extend(lab["steps"].as_array().expect("steps").iter().cloned());
    for k in keys {
        assert!(
            steps
                .iter()
                .any(|s| s.as_table().is_some_and(|t| t.contains_key(k))),
            "no step of the template uses `{k}`"
        );
    }
    // An existing lesson is never replaced.
    std::fs::write(&path, "mine").expect("write");
    let o = pipelens(dir.path(), &["new-lesson", "lessons/20-mine.toml"]);
    assert!(!o.status.success());
    assert!(text(&o).contains("exists already; it was left as it is"));
    assert_eq!(std::fs::read_to_string(&path).expect("read"), "mine");
}

/// `pipelens check lessons | head -0`: a reader that has gone ends the program quietly, as the
/// shell's tools do, not with a panic ("failed printing to stdout: Broken pipe").
#[test]
fn check_piped_into_a_reader_that_has_gone_ends_quietly() {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_pipelens"))
        .args(["check", "lessons"])
        .current_dir(repo())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("runs");
    // The reader closes its end before the first line is written: every write fails.
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("ends");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{:?}: {err}", out.status);
    assert!(!err.contains("panicked"), "{err}");
}
