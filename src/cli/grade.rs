//! `pipelens grade`: a class's lab hand-ins checked with no window, exactly as the app checks
//! them, in parallel, with a table on stdout and, on request, a CSV file for a spreadsheet and a
//! Gradescope `results.json`. A hand-in that cannot be read or checked — a syntax error, an
//! endless loop, a file far too large, binary bytes, a link out of its folder — is graded
//! failed with its reason; the batch goes on.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use rayon::prelude::*;

use crate::lab::submission::{Code, Grade, Work, grade};
use crate::lesson::{self, Lesson};
use crate::vocabulary::Lang;

/// The most a hand-in's source file may hold: far above any shader a lab asks for.
const MAX_SOURCE_BYTES: u64 = 256 * 1024;

/// The most files a hand-in folder is searched through for its sources.
const MAX_FOLDER_ENTRIES: usize = 1000;

/// What `pipelens grade` was asked.
#[derive(Debug)]
pub struct GradeRequest {
    /// The lesson: a file, or a built-in lesson's name (`10-blinn-phong`).
    pub lesson: String,
    /// The lab steps to grade (1-based); every lab step of the lesson when empty.
    pub steps: Vec<usize>,
    /// The hand-ins: one folder or file per student.
    pub submissions: Vec<PathBuf>,
    /// Where to write a CSV file of the grades.
    pub csv: Option<PathBuf>,
    /// Where to write Gradescope's `results.json` (one hand-in).
    pub gradescope: Option<PathBuf>,
    /// The feedback's language.
    pub lang: Lang,
}

/// One student's hand-in graded at one step.
struct Row {
    student: String,
    step: usize,
    title: String,
    grade: Grade,
}

/// Runs `pipelens grade`.
///
/// # Errors
/// A lesson that does not load, a step that is not a lab, no hand-in, or an output file that
/// cannot be written. A hand-in's own faults are grades, not errors.
pub fn run(req: &GradeRequest) -> Result<()> {
    let lesson = load_lesson(&req.lesson)?;
    let steps = lab_steps(&lesson, &req.steps)?;
    anyhow::ensure!(!req.submissions.is_empty(), "name at least one hand-in");
    if req.gradescope.is_some() && req.submissions.len() != 1 {
        anyhow::bail!(
            "--gradescope writes the results.json of one hand-in (Gradescope runs one container per submission); {} were named. For a class, use --csv",
            req.submissions.len()
        );
    }
    let bar = super::export::Progress::new();
    let jobs: Vec<(usize, usize)> = (0..req.submissions.len())
        .flat_map(|s| steps.iter().map(move |&k| (s, k)))
        .collect();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let rows: Vec<Row> = jobs
        .par_iter()
        .map(|&(s, k)| {
            let path = &req.submissions[s];
            let grade = std::panic::catch_unwind(|| match read_hand_in(path, &lesson.id, k) {
                Ok(code) => grade(&lesson, k, &code, req.lang),
                Err(reason) => Grade::failed(reason.words(path, req.lang)),
            })
            .unwrap_or_else(|_| {
                Grade::failed(
                    req.lang
                        .t("grade-pipelens-failed-while-checking-this")
                        .to_owned(),
                )
            });
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            let student = student_name(path);
            bar.show(n, jobs.len(), &student);
            Row {
                student,
                step: k + 1,
                title: lesson.steps[k].title.get(req.lang).to_owned(),
                grade,
            }
        })
        .collect();
    drop(bar);
    print_table(&rows, req.lang);
    if let Some(csv) = &req.csv {
        crate::export::write_atomically(csv, csv_text(&rows, req.lang).as_bytes(), req.lang)?;
        say!("Wrote {}", csv.display());
    }
    if let Some(json) = &req.gradescope {
        let text = serde_json::to_string_pretty(&gradescope_results(&rows, req.lang))
            .context("cannot encode results.json")?;
        crate::export::write_atomically(json, text.as_bytes(), req.lang)?;
        say!("Wrote {}", json.display());
    }
    Ok(())
}

/// A lesson file, or a built-in lesson by name (with or without `.toml`).
fn load_lesson(name: &str) -> Result<Lesson> {
    let path = Path::new(name);
    let doc = if path.exists() {
        lesson::load_file(path).map_err(|d| anyhow::anyhow!("{d}"))?
    } else {
        let file = if name.ends_with(".toml") {
            name.to_owned()
        } else {
            format!("{name}.toml")
        };
        let file = file.rsplit('/').next().unwrap_or(&file).to_owned();
        lesson::Document::Lesson(Box::new(
            lesson::library::lesson(&file).map_err(|d| anyhow::anyhow!("{d}"))?,
        ))
    };
    match doc {
        lesson::Document::Lesson(l) => Ok(*l),
        lesson::Document::Scene(_) => anyhow::bail!("{name} is a scene file, not a lesson"),
    }
}

/// The steps to grade (from 0): those asked for, each a lab, or every lab step.
fn lab_steps(lesson: &Lesson, asked: &[usize]) -> Result<Vec<usize>> {
    let labs: Vec<usize> = (0..lesson.steps.len())
        .filter(|&k| lesson.steps[k].exercise.is_some())
        .collect();
    let listed = || {
        labs.iter()
            .map(|k| format!("{} ({})", k + 1, lesson.steps[*k].title.en))
            .collect::<Vec<_>>()
            .join(", ")
    };
    anyhow::ensure!(!labs.is_empty(), "{} has no lab step", lesson.id);
    if asked.is_empty() {
        return Ok(labs);
    }
    asked
        .iter()
        .map(|&n| {
            let k = n.checked_sub(1).context("--step counts from 1")?;
            anyhow::ensure!(
                labs.contains(&k),
                "step {n} of {} is not a lab; its labs are steps {}",
                lesson.id,
                listed()
            );
            Ok(k)
        })
        .collect()
}

/// The student a hand-in is from: its folder's or file's name.
fn student_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// Why a hand-in could not be read.
enum Unreadable {
    /// It is not there, or cannot be opened.
    Missing(String),
    /// A file of it is larger than [`MAX_SOURCE_BYTES`].
    TooLarge(String, u64),
    /// A file of it is not UTF-8 text.
    NotText(String),
    /// A link in the folder that leads out of it.
    OutsideFolder(String),
    /// No source a lab reads.
    Nothing,
    /// A `.toml` file that is not a work file.
    NotWork(String),
    /// A work file of another lesson.
    OtherLesson(String),
    /// A work file with no code for the step.
    NoWorkAt(usize),
}

impl Unreadable {
    /// The reason in words, in `lang`.
    fn words(&self, path: &Path, lang: Lang) -> String {
        let at = path.display();
        let file = &at;
        match self {
            Self::Missing(e) => lang.t_with("grade-cannot-be-read", &[("file", file), ("why", e)]),
            Self::TooLarge(name, n) => lang.t_with(
                "grade-too-large",
                &[
                    ("name", name),
                    ("megabytes", &format!("{:.1}", *n as f64 / 1e6)),
                    ("kilobytes", &(MAX_SOURCE_BYTES / 1024)),
                ],
            ),
            Self::NotText(name) => lang.t_with("grade-not-text", &[("name", name)]),
            Self::OutsideFolder(name) => lang.t_with("grade-outside-folder", &[("name", name)]),
            Self::Nothing => lang.t_with(
                "grade-nothing",
                &[
                    ("file", file),
                    ("functions", &function_files(lang.t("list-separator"))),
                ],
            ),
            Self::NotWork(why) => lang.t_with("grade-not-work", &[("file", file), ("why", why)]),
            Self::OtherLesson(id) => {
                lang.t_with("grade-other-lesson", &[("file", file), ("lesson", id)])
            }
            Self::NoWorkAt(n) => lang.t_with("grade-no-work-at", &[("file", file), ("step", n)]),
        }
    }
}

/// The files a hand-in's functions are read from, `inside.glsl` …, joined by `sep`.
fn function_files(sep: &str) -> String {
    pipeline::shader::HookKind::ALL
        .map(|k| format!("{}.glsl", k.key()))
        .join(sep)
}

/// A hand-in's code for step `k` (from 0) of lesson `lesson`: a folder as the shader panel's
/// Save writes it, one source file, or a work file as **Export my work** writes it.
fn read_hand_in(path: &Path, lesson: &str, k: usize) -> Result<Code, Unreadable> {
    let meta = std::fs::metadata(path).map_err(|e| Unreadable::Missing(e.to_string()))?;
    let mut code = Code::default();
    let name = student_name(path);
    if meta.is_file() && name.to_ascii_lowercase().ends_with(".toml") {
        let work = Work::from_text(&read_source(path, &name)?).map_err(Unreadable::NotWork)?;
        if work.lesson != lesson {
            return Err(Unreadable::OtherLesson(work.lesson));
        }
        return work
            .steps
            .get(&(k + 1))
            .map(|s| s.code.clone())
            .filter(|c| !c.is_empty())
            .ok_or(Unreadable::NoWorkAt(k + 1));
    }
    if meta.is_dir() {
        let root = path
            .canonicalize()
            .map_err(|e| Unreadable::Missing(e.to_string()))?;
        let entries = std::fs::read_dir(path).map_err(|e| Unreadable::Missing(e.to_string()))?;
        let mut names: Vec<PathBuf> = entries
            .take(MAX_FOLDER_ENTRIES)
            .filter_map(|e| Some(e.ok()?.path()))
            .collect();
        names.sort();
        for file in names {
            let name = student_name(&file);
            if !looks_like_source(&name) {
                continue;
            }
            let real = file
                .canonicalize()
                .map_err(|e| Unreadable::Missing(e.to_string()))?;
            if !real.starts_with(&root) {
                return Err(Unreadable::OutsideFolder(name));
            }
            if real.is_file() {
                code.take(&name, read_source(&real, &name)?);
            }
        }
    } else {
        let name = student_name(path);
        if looks_like_source(&name) {
            code.take(&name, read_source(path, &name)?);
        }
    }
    if code.is_empty() {
        return Err(Unreadable::Nothing);
    }
    Ok(code)
}

/// Whether a file's name is one a hand-in's sources have.
fn looks_like_source(name: &str) -> bool {
    Code::default().take(name, String::new())
}

/// One source file, bounded in size, as UTF-8 text.
fn read_source(path: &Path, name: &str) -> Result<String, Unreadable> {
    let size = std::fs::metadata(path)
        .map_err(|e| Unreadable::Missing(e.to_string()))?
        .len();
    if size > MAX_SOURCE_BYTES {
        return Err(Unreadable::TooLarge(name.to_owned(), size));
    }
    let bytes = std::fs::read(path).map_err(|e| Unreadable::Missing(e.to_string()))?;
    String::from_utf8(bytes).map_err(|_| Unreadable::NotText(name.to_owned()))
}

/// Everything the check says of a hand-in, as one paragraph: the verdict, then what is off
/// (sentences apart by a space in English, none in Chinese, whose full stop ends them).
fn feedback(grade: &Grade, lang: Lang) -> String {
    grade.sentences.join(lang.t("sentence-separator"))
}

/// The table on stdout: student, step, passed, matching pixels, the feedback.
fn print_table(rows: &[Row], lang: Lang) {
    let width = rows
        .iter()
        .map(|r| columns(&r.student))
        .max()
        .unwrap_or(0)
        .max(columns(lang.t("grade-student")));
    let line = |cells: [&str; 5]| {
        let pad = |text: &str, to: usize, right: bool| {
            let fill = " ".repeat(to.saturating_sub(columns(text)));
            if right {
                format!("{fill}{text}")
            } else {
                format!("{text}{fill}")
            }
        };
        say!(
            "{}  {}  {}  {}  {}",
            pad(cells[0], width, false),
            pad(cells[1], 4, true),
            pad(cells[2], 6, false),
            pad(cells[3], 13, true),
            cells[4]
        );
    };
    line([
        lang.t("grade-student"),
        lang.t("grade-step"),
        lang.t("grade-passed"),
        lang.t("grade-matching"),
        lang.t("grade-feedback"),
    ]);
    for r in rows {
        let matching = r
            .grade
            .matching
            .map_or_else(|| "—".to_owned(), |(m, t)| format!("{m}/{t}"));
        let passed = if r.grade.passed {
            lang.t("grade-yes")
        } else {
            lang.t("grade-no")
        };
        line([
            &r.student,
            &r.step.to_string(),
            passed,
            &matching,
            &feedback(&r.grade, lang),
        ]);
    }
    let students: std::collections::BTreeSet<&str> =
        rows.iter().map(|r| r.student.as_str()).collect();
    let passed = rows.iter().filter(|r| r.grade.passed).count();
    say!(
        "{}",
        lang.t_with(
            "grade-summary",
            &[
                ("handins", &students.len()),
                ("checks", &rows.len()),
                ("passed", &passed),
            ],
        )
    );
}

/// The columns `text` takes in a terminal: two for each CJK character or full-width form, one
/// for any other.
fn columns(text: &str) -> usize {
    text.chars()
        .map(|c| {
            let wide = matches!(u32::from(c), 0x1100..=0x115F | 0x2E80..=0xA4CF | 0xAC00..=0xD7A3 | 0xF900..=0xFAFF | 0xFE30..=0xFE4F | 0xFF00..=0xFF60 | 0xFFE0..=0xFFE6);
            if wide { 2 } else { 1 }
        })
        .sum()
}

/// A CSV field: quoted, its quotes doubled (RFC 4180).
fn field(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

/// The grades as CSV: one row per student and step.
fn csv_text(rows: &[Row], lang: Lang) -> String {
    let mut out = String::from("student,step,title,passed,matching,total,feedback\n");
    for r in rows {
        let (m, t) = r
            .grade
            .matching
            .map_or((String::new(), String::new()), |(m, t)| {
                (m.to_string(), t.to_string())
            });
        out.push_str(&format!(
            "{},{},{},{},{m},{t},{}\n",
            field(&r.student),
            r.step,
            field(&r.title),
            r.grade.passed,
            field(&feedback(&r.grade, lang))
        ));
    }
    out
}

/// Gradescope's `results.json` for one hand-in: one test per step (score 1 when it passed, of
/// 1), the feedback as each test's output, the total as the score.
fn gradescope_results(rows: &[Row], lang: Lang) -> serde_json::Value {
    let tests: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "name": lang.t_with("grade-gradescope-step", &[("step", &r.step), ("title", &r.title)]),
                "score": if r.grade.passed { 1.0 } else { 0.0 },
                "max_score": 1.0,
                "status": if r.grade.passed { "passed" } else { "failed" },
                "output": feedback(&r.grade, lang),
                "visibility": "visible",
            })
        })
        .collect();
    let score = rows.iter().filter(|r| r.grade.passed).count() as f64;
    serde_json::json!({
        "score": score,
        "output": lang.t_with("grade-gradescope-output", &[("passed", &score), ("total", &rows.len())]),
        "visibility": "visible",
        "stdout_visibility": "visible",
        "tests": tests,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Why a hand-in is not graded, as whole sentences in both languages (written by hand: the
    /// limit is 256 KB, the function files are the five `HookKind`s' in their order).
    #[test]
    fn a_hand_in_that_cannot_be_read_is_told_why_in_both_languages() {
        let at = Path::new("class/ana");
        let large = Unreadable::TooLarge("shader.frag".to_owned(), 2_500_000);
        assert_eq!(
            large.words(at, Lang::EN),
            "shader.frag holds 2.5 MB; a shader is at most 256 KB: not graded"
        );
        assert_eq!(
            large.words(at, Lang::ZH),
            "shader.frag 有 2.5 MB；着色器最多 256 KB：不予评分"
        );
        assert_eq!(
            Unreadable::Nothing.words(at, Lang::EN),
            "class/ana holds no shader.vert, shader.frag or function file (inside.glsl, \
             depth_test.glsl, de_casteljau.glsl, shadow_matrix.glsl, bezier_patch.glsl)"
        );
        assert_eq!(
            Unreadable::Nothing.words(at, Lang::ZH),
            "class/ana 中没有 shader.vert、shader.frag 或函数文件（inside.glsl、depth_test.glsl、\
             de_casteljau.glsl、shadow_matrix.glsl、bezier_patch.glsl）"
        );
        assert_eq!(
            Unreadable::NoWorkAt(3).words(at, Lang::ZH),
            "class/ana 中没有第 3 步的代码"
        );
    }
}
