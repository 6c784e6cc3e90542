//! `pipelens bench --steps LESSON`: each step of a built-in lesson rendered as the app renders
//! it on entering the step (the session's job: the view's capture keeping what the step shows),
//! on one thread and on every thread. The time is the one the app reports and a page writes
//! into `<html data-frame-ms>`: the view's capture, stage by stage (`StageTimes::total`), so the
//! browser test prints the page's frames beside these (`scripts/web-test.sh`).

use std::io::Write;

use crate::app::command::LessonCommand;
use crate::app::session::{Command, Session};

/// One step's frame times: the median of `frames` on one thread and on `threads`.
#[derive(Clone, Debug)]
pub struct StepTimes {
    /// The step, counted from 1.
    pub step: usize,
    /// Its English title.
    pub title: String,
    /// The capture's size and samples, as "640×400, 4 samples".
    pub frame: String,
    /// Milliseconds on one thread.
    pub one: f64,
    /// Milliseconds on every thread.
    pub all: f64,
}

/// Renders each step of the built-in lesson `file` (as `00-tour.toml`) `frames` times after a
/// warm-up, in a pool of one thread and one of `threads`, and prints a row per step and the
/// heaviest step last.
///
/// # Errors
/// When the lesson is not built in, or a step cannot be rendered.
pub fn run(
    file: &str,
    frames: usize,
    threads: usize,
    out: &mut dyn Write,
) -> anyhow::Result<Vec<StepTimes>> {
    let lesson = crate::lesson::library::lesson(file).map_err(|d| anyhow::anyhow!("{d}"))?;
    let steps = lesson.steps.len();
    let doc = crate::lesson::Document::Lesson(Box::new(lesson));
    let mut session = Session::with_document(doc, "bench", None);
    let (one, all) = (super::pool(1)?, super::pool(threads)?);
    writeln!(
        out,
        "{file}, each step as the app renders it on entering it (the view's capture; \
         medians of {frames}):"
    )?;
    writeln!(
        out,
        "  step  {:<44} {:<20} {:>10} {:>12}",
        "title",
        "frame",
        "1 thread",
        format!("{threads} threads")
    )?;
    let mut rows = Vec::with_capacity(steps);
    for k in 0..steps {
        session.apply(Command::Lesson(LessonCommand::GoToStep(k)));
        let job = session.job();
        let settings = &job.spec.settings;
        let row = StepTimes {
            step: k + 1,
            title: session
                .lesson
                .as_ref()
                .map(|p| p.lesson.steps[k].title.en.clone())
                .unwrap_or_default(),
            frame: format!(
                "{}×{}, {} sample{}",
                settings.width,
                settings.height,
                settings.samples.count(),
                if settings.samples.count() == 1 {
                    ""
                } else {
                    "s"
                }
            ),
            one: one.install(|| median_ms(&job, frames))?,
            all: all.install(|| median_ms(&job, frames))?,
        };
        writeln!(
            out,
            "  {:>4}  {:<44} {:<20} {:>7.1} ms {:>9.1} ms",
            row.step,
            row.title.chars().take(44).collect::<String>(),
            row.frame,
            row.one,
            row.all
        )?;
        rows.push(row);
    }
    if let Some(h) = rows.iter().max_by(|a, b| a.one.total_cmp(&b.one)) {
        writeln!(
            out,
            "heaviest step {}: {:.1} ms on 1 thread, {:.1} ms on {threads} threads",
            h.step, h.one, h.all
        )?;
    }
    Ok(rows)
}

/// The median over `frames` renders (after one to warm up) of the view's capture's stage
/// times, each frame written into the storage of the one before, as the render worker does.
fn median_ms(job: &crate::app::worker::Job, frames: usize) -> anyhow::Result<f64> {
    let mut times: Vec<f64> = super::job_frames(job, frames)?
        .into_iter()
        .map(|(stages, _)| stages.total().as_secs_f64() * 1e3)
        .collect();
    Ok(super::median(&mut times))
}
