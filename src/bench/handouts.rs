//! `pipelens bench --handouts`: how big each lesson's handout is and how long it takes to
//! export, in both languages, for every lesson of `lessons/` and for the six-step teapot lesson
//! (the case the handout's budget is stated for: one file of at most 3 MB in at most 3 s).

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result};

use crate::export::lesson::{LessonExport, export_lesson};
use crate::lesson::{Document, Lesson};
use crate::vocabulary::Lang;

/// The teapot lesson, `{mesh}` standing for the OBJ's path.
const TEAPOT: &str = include_str!("teapot-handout.toml");

/// One export: (bytes of index.html, seconds).
fn measure(lesson: &Lesson, lang: Lang, scratch: &Path) -> Result<(u64, f64)> {
    let out = scratch.join(format!("{}-{}", lesson.id, lang.t("handouts-en")));
    let opts = LessonExport {
        out: out.clone(),
        step: None,
        size: None,
        lang,
        max_records: 0,
        answers: false,
        slides: false,
        data: false,
        pixel: None,
        cancel: crate::export::Cancel::default(),
    };
    let start = Instant::now();
    export_lesson(lesson, &opts, &mut |_, _, _| {})?;
    let seconds = start.elapsed().as_secs_f64();
    let bytes = std::fs::metadata(out.join("index.html"))
        .context("index.html")?
        .len();
    Ok((bytes, seconds))
}

/// Prints the table: every lesson in `lessons`, then the teapot lesson if `data` has the teapot.
///
/// # Errors
/// A lesson that does not load or export, a scratch folder that cannot be written.
pub fn run(lessons: &Path, data: &Path, out: &mut dyn std::io::Write) -> Result<()> {
    let scratch = std::env::temp_dir().join(format!("pipelens-handouts-{}", std::process::id()));
    let mut cases: Vec<Lesson> = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir(lessons)
        .with_context(|| format!("cannot read {}", lessons.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    for f in &files {
        match crate::lesson::load_file(f).map_err(|d| anyhow::anyhow!("{d}"))? {
            Document::Lesson(l) => cases.push(*l),
            Document::Scene(_) => {}
        }
    }
    let teapot = data.join("models/teapot.obj");
    if teapot.is_file() {
        let teapot = std::path::absolute(&teapot).unwrap_or(teapot);
        let text = TEAPOT.replace("{mesh}", &teapot.display().to_string());
        let l = crate::lesson::script::parse_lesson(&text, "teapot-handout.toml", data)
            .map_err(|d| anyhow::anyhow!("{d}"))?;
        cases.push(l);
    } else {
        writeln!(
            out,
            "(no {}: the teapot case is left out)",
            teapot.display()
        )?;
    }
    writeln!(
        out,
        "{:<28} {:>5} {:>8} {:>10} {:>8} {:>10} {:>8}",
        "lesson", "steps", "animated", "en MB", "en s", "zh MB", "zh s"
    )?;
    for l in &cases {
        let (en_b, en_s) = measure(l, Lang::EN, &scratch)?;
        let (zh_b, zh_s) = measure(l, Lang::ZH, &scratch)?;
        let animated = l.steps.iter().filter(|s| !s.animate.is_empty()).count();
        let mb = |b: u64| b as f64 / 1_000_000.0;
        writeln!(
            out,
            "{:<28} {:>5} {:>8} {:>10.2} {:>8.2} {:>10.2} {:>8.2}",
            l.id,
            l.steps.len(),
            animated,
            mb(en_b),
            en_s,
            mb(zh_b),
            zh_s
        )?;
    }
    let _ = std::fs::remove_dir_all(&scratch);
    Ok(())
}
