//! `pipelens bench`'s rows for the shader debugger, on lesson 24's first step (its Blinn-Phong
//! fragment shader) as the app renders it: a keystroke in the shader panel to the new picture
//! (the source compiled and linked, then the frame), a pixel's click to its fragment's traced
//! run (the frame with that pixel inspected), one watch-list entry read at a step (the shader
//! compiled with the watch, the fragment run again), and a variable's picture over a 1280×720
//! frame beside the same frame without it. Targets (issue 55): ≤ 100 ms for the keystroke and
//! the click, the picture ≤ 2× its frame.

use std::io::Write;
use std::time::{Duration, Instant};

use pipeline::buffers::Capture;
use pipeline::settings::RenderSettings;

use crate::app::session::Session;

/// The lesson whose first step the rows measure.
const LESSON: &str = "24-shader-programs.toml";

/// The middle of `runs` of `f`, in milliseconds, after one run to warm up.
fn median_ms(frames: usize, mut f: impl FnMut() -> anyhow::Result<()>) -> anyhow::Result<f64> {
    f()?;
    let mut v = Vec::with_capacity(frames.max(1));
    for _ in 0..frames.max(1) {
        let start = Instant::now();
        f()?;
        v.push(start.elapsed().as_secs_f64() * 1e3);
    }
    Ok(super::median(&mut v))
}

/// The rows, `frames` runs each.
///
/// # Errors
/// When the lesson is not built in, its shader does not compile, or a frame cannot be drawn.
pub fn rows(frames: usize, out: &mut dyn Write) -> anyhow::Result<()> {
    let lesson = crate::lesson::library::lesson(LESSON).map_err(|d| anyhow::anyhow!("{d}"))?;
    let doc = crate::lesson::Document::Lesson(Box::new(lesson));
    let mut session = Session::with_document(doc, "bench", None);
    let shader = session
        .spec
        .scene
        .objects
        .iter()
        .find_map(|o| o.code.shader.clone())
        .ok_or_else(|| anyhow::anyhow!("{LESSON}'s first step runs no shader"))?;
    let vertex = shader.programs.vertex.source.clone();
    let fragment = shader.programs.fragment.source.clone();
    let settings = &session.spec.settings;
    writeln!(
        out,
        "\nthe shader debugger on {LESSON}'s first step ({}×{}, {} samples, {} threads; medians of {frames}):",
        settings.width,
        settings.height,
        settings.samples.count(),
        rayon::current_num_threads()
    )?;
    // A keystroke: the edited source compiled and linked, then the frame the session asks for.
    let edited = format!("{fragment}// an edit\n");
    let compile = median_ms(frames, || {
        pipeline::shader::link(Some(&vertex), Some(&edited))
            .map(|_| ())
            .map_err(|e| anyhow::anyhow!("{e:?}"))
    })?;
    let frame = |session: &Session| -> anyhow::Result<f64> {
        let mut walls: Vec<f64> = super::job_frames(&session.job(), frames)?
            .into_iter()
            .map(|(_, wall)| wall.as_secs_f64() * 1e3)
            .collect();
        Ok(super::median(&mut walls))
    };
    let drawn = frame(&session)?;
    row(out, "keystroke: compile + link", compile, None)?;
    row(out, "keystroke: the frame", drawn, None)?;
    row(
        out,
        "keystroke → picture",
        compile + drawn,
        Some("target ≤ 100 ms"),
    )?;
    // A click: the frame with that pixel inspected, its fragment's run traced.
    let (w, h) = (session.spec.settings.width, session.spec.settings.height);
    session.selection.pixel = Some((w / 2, h / 2));
    let clicked = frame(&session)?;
    row(
        out,
        "pixel click → its traced run",
        clicked,
        Some("target ≤ 100 ms"),
    )?;
    // A watch-list entry: the shader compiled with the watch, the fragment run again.
    let mut job = session.job();
    job.spec.settings.capture = job.spec.settings.capture.with_pixel(Some((w / 2, h / 2)));
    let capture = pipeline::render(&job.spec.scene, &job.spec.settings)?;
    let line = line_starting(
        &fragment,
        "vec3 h =",
        "fragment shader computes no `vec3 h`",
    )?;
    let fragment_run = capture
        .shaders
        .as_ref()
        .and_then(|s| s.pixel.first())
        .ok_or_else(|| anyhow::anyhow!("no fragment at the frame's centre"))?;
    let read = median_ms(frames, || {
        pipeline::watch_fragment(&job.spec.scene, &capture, fragment_run, (line, "dot(n, l)"))
            .map(|_| ())
            .map_err(|e| anyhow::anyhow!("{e}"))
    })?;
    row(out, "watch list: one entry read at a step", read, None)?;
    // And a vertex shader's value: the world normal's y after the line that writes it.
    let vertex_line = line_starting(&vertex, "w_nrm =", "vertex shader writes no `w_nrm`")?;
    pictures(&session, (line, vertex_line), frames, out)
}

/// The variable picture at 1280×720: the frame with a watch of the fragment shader after
/// `line`, and one of the vertex shader after `vertex_line` (carried to the pixels as a
/// varying), against the frame without.
fn pictures(
    session: &Session,
    (line, vertex_line): (usize, usize),
    frames: usize,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    let wide = RenderSettings {
        width: 1280,
        height: 720,
        capture: Capture::COLOR,
        ..session.spec.settings
    };
    let watching = session
        .spec
        .scene
        .watching(&pipeline::shader::probe::WatchSpec::fragment(
            line,
            "dot(n, l)",
        ))
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let vertex_watching = session
        .spec
        .scene
        .watching(&pipeline::shader::probe::WatchSpec::vertex(
            vertex_line,
            "w_nrm.y",
        ))
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let plain = super::measure(&session.spec.scene, &wide, frames)?.total();
    let pictured = super::measure(&watching, &wide, frames)?.total();
    let vertex_pictured = super::measure(&vertex_watching, &wide, frames)?.total();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    row(out, "1280×720 frame, the colour", ms(plain), None)?;
    for (what, d) in [
        ("1280×720 frame with `dot(n, l)` pictured", pictured),
        ("… with the vertex's `w_nrm.y` pictured", vertex_pictured),
    ] {
        row(
            out,
            what,
            ms(d),
            Some(&format!(
                "{:.2}× the frame, target ≤ 2×",
                d.as_secs_f64() / plain.as_secs_f64().max(1e-9)
            )),
        )?;
    }
    Ok(())
}

/// The first line of `source` (from 1) that starts with `start`, where a watch is read: the
/// fragment shader's line that computes the half vector h (after n and l, so `dot(n, l)` can
/// be read), the vertex shader's that writes `w_nrm`. `missing` says what is not there.
fn line_starting(source: &str, start: &str, missing: &str) -> anyhow::Result<usize> {
    source
        .lines()
        .position(|l| l.trim_start().starts_with(start))
        .map(|i| i + 1)
        .ok_or_else(|| anyhow::anyhow!("{LESSON}'s {missing}"))
}

/// One row: what, milliseconds, and a note.
fn row(out: &mut dyn Write, what: &str, ms: f64, note: Option<&str>) -> anyhow::Result<()> {
    writeln!(
        out,
        "  {what:<44} {ms:>8.2} ms{}",
        note.map(|n| format!("   ({n})")).unwrap_or_default()
    )?;
    Ok(())
}
