//! `pipelens grade`: a class's hand-ins checked as the app checks a lab — right ones pass, wrong
//! ones fail with the check's sentence, and broken or hostile ones (a syntax error, an endless
//! loop, binary bytes, a file far too large, a link out of the folder, an empty folder) are
//! graded failed with their reason while the batch goes on; the CSV and Gradescope's
//! `results.json` hold the same; and the autograder folder runs as Gradescope runs it.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::labs::SOLUTIONS;

/// Lesson 10's lab: the specular term in a fragment shader (step 8).
const LESSON: &str = "10-blinn-phong";
const STEP: &str = "8";

/// The lab's starter fragment shader, read from the lesson.
fn starter() -> String {
    let lesson = pipelens::lesson::library::lesson(&format!("{LESSON}.toml")).expect("built in");
    let step = STEP.parse::<usize>().expect("a number") - 1;
    let e = lesson.steps[step].exercise.as_ref().expect("a lab");
    e.starter
        .shader
        .as_ref()
        .expect("a shader lab")
        .programs
        .fragment
        .source
        .clone()
}

/// The starter with the specular term written as `solution`.
fn solved(solution: &str) -> String {
    let (_, _, todo, _) = SOLUTIONS
        .iter()
        .find(|(id, title, ..)| *id == LESSON && title.contains("specular"))
        .expect("the lab's solution");
    let s = starter();
    assert!(s.contains(todo));
    s.replace(todo, solution)
}

/// A hand-in folder `name` under `root` holding `shader.frag` = `text`.
fn hand_in(root: &Path, name: &str, text: &[u8]) -> PathBuf {
    let dir = root.join(name);
    std::fs::create_dir_all(&dir).expect("a folder");
    std::fs::write(dir.join("shader.frag"), text).expect("written");
    dir
}

/// The CSV's rows as fields (the quoted fields this command writes, commas inside quotes kept).
fn csv_rows(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .skip(1)
        .map(|line| {
            let mut fields = Vec::new();
            let mut field = String::new();
            let (mut quoted, mut chars) = (false, line.chars().peekable());
            while let Some(c) = chars.next() {
                match c {
                    '"' if quoted && chars.peek() == Some(&'"') => {
                        field.push('"');
                        chars.next();
                    }
                    '"' => quoted = !quoted,
                    ',' if !quoted => fields.push(std::mem::take(&mut field)),
                    c => field.push(c),
                }
            }
            fields.push(field);
            fields
        })
        .collect()
}

/// A class's hand-ins under `root`, each with whether it should pass and the words its grade
/// should hold: right twice, a loose file, the starter, Phong's r·v, a syntax error, an endless
/// loop, binary bytes, 50 MB, a link out of its folder, an empty folder, a missing path.
fn class(root: &Path) -> Vec<(PathBuf, bool, &'static str)> {
    let right = "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }";
    // Written another way: the half vector by hand and the gate as a factor.
    let right_too = "        vec3 half_vector = (l + v) / length(l + v);
        float lit = n_dot_l > 0.0 ? 1.0 : 0.0;
        sum += lit * f * light.intensity * ks * pow(max(dot(half_vector, n), 0.0), shininess);";
    // Phong's r·v instead of n·h: another highlight.
    let phong = "        vec3 r = reflect(-l, n);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(r, v), 0.0), shininess);
        }";
    let mut expected: Vec<(PathBuf, bool, &'static str)> = vec![
        (
            hand_in(root, "ana", solved(right).as_bytes()),
            true,
            "Passed",
        ),
        (
            hand_in(root, "ben", solved(right_too).as_bytes()),
            true,
            "Passed",
        ),
        (
            hand_in(root, "chen", starter().as_bytes()),
            false,
            "Not yet",
        ),
        (
            hand_in(root, "dina", solved(phong).as_bytes()),
            false,
            "Not yet",
        ),
        (
            hand_in(
                root,
                "emil",
                solved(&right.replace("shininess);", "shininess)")).as_bytes(),
            ),
            false,
            "Does not compile: fragment shader, line",
        ),
        (
            hand_in(
                root,
                "fay",
                solved(&format!(
                    "        while (true) {{ n_dot_l += 0.0; }}\n{right}"
                ))
                .as_bytes(),
            ),
            false,
            "run stopped",
        ),
        (
            hand_in(root, "gus", &[0xff, 0xfe, 0x00, 0x41, 0x80]),
            false,
            "is not text",
        ),
    ];
    let huge = hand_in(root, "hana", b"");
    std::fs::File::options()
        .write(true)
        .open(huge.join("shader.frag"))
        .and_then(|f| f.set_len(50 * 1024 * 1024))
        .expect("a 50 MB file");
    expected.push((huge, false, "a shader is at most"));
    let outside = root.join("ivan");
    std::fs::create_dir_all(&outside).expect("a folder");
    let secret = root.join("secret.frag");
    std::fs::write(&secret, solved(right)).expect("written");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&secret, outside.join("shader.frag")).expect("a link");
    expected.push((outside, false, "leads out of the hand-in's folder"));
    let empty = root.join("jo");
    std::fs::create_dir_all(&empty).expect("a folder");
    expected.push((empty, false, "holds no shader.vert"));
    // One loose file is a hand-in too.
    let loose = root.join("kim.frag");
    std::fs::write(&loose, solved(right)).expect("written");
    expected.push((loose, true, "Passed"));
    expected.push((root.join("nobody"), false, "cannot be read"));

    expected
}

#[test]
fn a_class_is_graded_right_wrong_broken_and_hostile_alike() {
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let root = tmp.path();
    let expected = class(root);
    let csv = root.join("grades.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_pipelens"))
        .args(["grade", LESSON, "--step", STEP, "--csv"])
        .arg(&csv)
        .args(expected.iter().map(|(p, ..)| p))
        .output()
        .expect("pipelens runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(
        stdout.contains("12 hand-ins, 12 checks, 3 passed"),
        "{stdout}"
    );
    let rows = csv_rows(&std::fs::read_to_string(&csv).expect("the CSV"));
    assert_eq!(rows.len(), expected.len());
    for (path, passed, words) in &expected {
        let student = path.file_name().expect("a name").to_string_lossy();
        let row = rows
            .iter()
            .find(|r| r[0] == student)
            .unwrap_or_else(|| panic!("{student} has a row: {rows:?}"));
        assert_eq!(row[1], STEP);
        assert_eq!(row[3], passed.to_string(), "{student}: {row:?}");
        assert!(
            row[6].contains(words),
            "{student}: {:?} lacks {words:?}",
            row[6]
        );
        if !passed && row[6].starts_with("Not yet") {
            // A wrong frame's count of matching pixels is below the whole.
            let (m, t) = (
                row[4].parse::<u64>().expect("m"),
                row[5].parse::<u64>().expect("t"),
            );
            assert!(m < t && t == 480 * 360, "{student}: {m} of {t}");
        }
    }
}

/// The autograder as Gradescope runs it, in a folder laid out as `/autograder`: the student's
/// `shader.frag` in `submission/`, `lab.conf` in `source/`, and `results/results.json` written
/// with one test for the step, in Chinese when asked.
#[test]
fn the_gradescope_autograder_writes_results_json() {
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let root = tmp.path();
    for dir in ["source", "submission"] {
        std::fs::create_dir_all(root.join(dir)).expect("a folder");
    }
    let here = crate::support::repo().join("scripts/gradescope");
    std::fs::write(
        root.join("source/lab.conf"),
        format!("LESSON={LESSON}\nSTEPS=\"{STEP}\"\nLANG_FEEDBACK=zh\n"),
    )
    .expect("lab.conf");
    std::fs::write(root.join("submission/shader.frag"), starter()).expect("the hand-in");
    let out = Command::new("bash")
        .arg(here.join("run_autograder"))
        .env("AUTOGRADER_ROOT", root)
        .env("PIPELENS", env!("CARGO_BIN_EXE_pipelens"))
        .output()
        .expect("bash runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(root.join("results/results.json")).expect("results.json");
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(json["score"], 0.0);
    let tests = json["tests"].as_array().expect("tests");
    assert_eq!(tests.len(), 1);
    assert_eq!(tests[0]["max_score"], 1.0);
    assert_eq!(tests[0]["score"], 0.0);
    assert_eq!(tests[0]["status"], "failed");
    let output = tests[0]["output"].as_str().expect("output");
    assert!(output.starts_with("还没有通过"), "{output}");
    // Its sentences (the verdict, the value at the first wrong pixel) follow one another as
    // Chinese sentences do, the full stop with no space after it.
    assert!(output.matches('。').count() >= 2, "{output}");
    assert!(!output.contains("。 "), "{output}");
    assert!(
        tests[0]["name"]
            .as_str()
            .is_some_and(|n| n.starts_with("第 8 步")),
        "{text}"
    );
    // The same hand-in with the solution: full marks.
    std::fs::write(
        root.join("submission/shader.frag"),
        solved(
            SOLUTIONS
                .iter()
                .find(|s| s.1.contains("specular"))
                .expect("it")
                .3,
        ),
    )
    .expect("the hand-in");
    let out = Command::new("bash")
        .arg(here.join("run_autograder"))
        .env("AUTOGRADER_ROOT", root)
        .env("PIPELENS", env!("CARGO_BIN_EXE_pipelens"))
        .output()
        .expect("bash runs");
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("results/results.json")).expect("results.json"),
    )
    .expect("JSON");
    assert_eq!(json["score"], 1.0);
    assert_eq!(json["tests"][0]["status"], "passed");
}

/// Asking for a step that is not a lab names the lab steps there are; --gradescope with several
/// hand-ins says why not.
#[test]
fn grade_says_what_is_wrong_with_its_own_arguments() {
    let run = |args: &[&str]| {
        let o = Command::new(env!("CARGO_BIN_EXE_pipelens"))
            .args(args)
            .output()
            .expect("pipelens runs");
        (
            o.status.success(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let (ok, err) = run(&["grade", LESSON, "--step", "2", "x"]);
    assert!(!ok);
    assert!(err.contains("step 2 of 10-blinn-phong is not a lab; its labs are steps 8 (Lab: the specular term in a fragment shader), 9 (Lab: light casters)"), "{err}");
    let (ok, err) = run(&["grade", LESSON, "a", "b", "--gradescope", "r.json"]);
    assert!(!ok);
    assert!(
        err.contains("--gradescope writes the results.json of one hand-in"),
        "{err}"
    );
    let (ok, err) = run(&["grade", "no-such-lesson", "a"]);
    assert!(!ok);
    assert!(
        err.contains("no built-in lesson is called no-such-lesson.toml"),
        "{err}"
    );
}

/// `pipelens bench --grade N` grades N hand-ins of the specular lab and says how long each took
/// and how many passed: of every five, the two right ones (the hand-ins cycle through two right
/// fillings, the ungated term, Phong's r·v and one that does not compile).
#[test]
fn bench_grade_times_a_class() {
    let o = Command::new(env!("CARGO_BIN_EXE_pipelens"))
        .args(["bench", "--grade", "5"])
        .output()
        .expect("pipelens runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(stdout.contains("graded 5 in"), "{stdout}");
    assert!(stdout.contains(", 2 passed"), "{stdout}");
}

/// A hand-in whose run stops is told so in the grader's language: in Chinese, the loop's line,
/// the object and the endless loop in Chinese, and none of the core's English.
#[test]
fn a_run_that_stops_is_said_in_chinese() {
    use pipelens::lesson::Document;
    use pipelens::vocabulary::Lang;
    let path = crate::support::repo().join("lessons/24-shader-programs.toml");
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("lesson 24 loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == "Lab: the diffuse term")
        .expect("the diffuse lab");
    let starter = lesson.steps[k]
        .exercise
        .as_ref()
        .and_then(|e| e.starter.shader.as_ref())
        .map(|s| s.programs.fragment.source.clone())
        .expect("a fragment starter");
    let todo = "    // TODO: the diffuse term k_d·c·I·max(n·l, 0), added to L.";
    assert!(starter.contains(todo));
    // The loop is on the TODO's line (29), the first line of the replacement.
    let endless = starter.replace(todo, "    float d = 0.0; while (d < 1.0) { d *= 2.0; }");
    let mut code = pipelens::lab::submission::Code::default();
    code.take("shader.frag", endless);
    let zh = pipelens::lab::submission::grade(&lesson, k, &code, Lang::ZH);
    assert!(!zh.passed);
    let said = zh.sentences.join(" ");
    for words in [
        "运行中止",
        "物体 sphere 的片元着色器",
        "第 29 行",
        "循环执行超过了",
    ] {
        assert!(said.contains(words), "{said:?} lacks {words:?}");
    }
    for english in ["the scene", "loop ran", "shader of", "line "] {
        assert!(!said.contains(english), "English {english:?} in {said:?}");
    }
    let en = pipelens::lab::submission::grade(&lesson, k, &code, Lang::EN);
    assert!(
        en.sentences.join(" ").contains("an endless loop?"),
        "{:?}",
        en.sentences
    );
}
