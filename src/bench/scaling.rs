//! `pipelens bench --scaling`: how the frame scales with threads. The same cases rendered in
//! pools of 1, 2, 4, … threads, each case's median beside its one-thread median:
//! speed-up s = t₁ / tₙ and efficiency e = s / n (1 where the n threads share the work
//! perfectly; a serial part f caps the speed-up at 1 / (f + (1 − f)/n), Amdahl's law).

use std::io::Write;
use std::time::Duration;

use pipeline::buffers::Capture;
use pipeline::lighting::Frequency;
use pipeline::raster::Samples;
use pipeline::settings::RenderSettings;

use super::{lit_textured_scene, measure, sphere_scene, with_shaders};

/// What one case measures of a frame.
#[derive(Clone, Copy)]
enum Part {
    /// The whole frame (every stage).
    Frame,
    /// The resolve stage alone.
    Resolve,
    /// The student's GLSL frame over the built-in path's frame on the same scene (a ratio).
    ShaderRatio,
}

/// The thread counts to measure on a machine with `cores`: 1, then doubling, with `cores`
/// itself last (1, 2 on two cores; 1, 2, 4, 8, 16 on sixteen; 1, 2, 4, 6 on six).
#[must_use]
pub fn thread_counts(cores: usize) -> Vec<usize> {
    let cores = cores.max(1);
    let mut counts: Vec<usize> = std::iter::successors(Some(1usize), |n| n.checked_mul(2))
        .take_while(|&n| n < cores)
        .collect();
    counts.push(cores);
    counts
}

/// Speed-up and efficiency of a time `t` on `n` threads against `one` on a single thread:
/// `(t₁ / tₙ, t₁ / (n·tₙ))`.
#[must_use]
pub fn speed_up(one: f64, t: f64, n: usize) -> (f64, f64) {
    let s = one / t.max(1e-12);
    (s, s / n.max(1) as f64)
}

/// One row of the table: what is rendered and what of it is shown.
struct Case<'a> {
    label: &'static str,
    scene: &'a pipeline::scene::Scene,
    settings: RenderSettings,
    part: Part,
}

/// The median of `case` over `frames` frames in a pool of `n` threads: milliseconds, or the
/// ratio of the student's GLSL (`glsl`) to the built-in path.
fn measure_case(
    case: &Case<'_>,
    glsl: &pipeline::scene::Scene,
    n: usize,
    frames: usize,
) -> anyhow::Result<f64> {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let pool = super::pool(n)?;
    pool.install(|| {
        let t = measure(case.scene, &case.settings, frames)?;
        Ok(match case.part {
            Part::Frame => ms(t.total()),
            Part::Resolve => ms(t.resolve),
            Part::ShaderRatio => {
                let g = measure(glsl, &case.settings, frames)?;
                ms(g.total()) / ms(t.total()).max(1e-9)
            }
        })
    })
}

/// Renders the scaling cases in a pool of each of `threads`, `frames` frames a case, and
/// prints a row per case: the median at each thread count, and at the largest its speed-up
/// and efficiency; then the frame's targets of issue 59 (every buffer on 2 threads ≤ 0.55×
/// its one-thread time; on 16, ≤ 0.12×).
///
/// # Errors
/// When a pool cannot be started, a scene cannot be rendered or the shader does not compile.
pub fn run(threads: &[usize], frames: usize, out: &mut dyn Write) -> anyhow::Result<()> {
    let lit = lit_textured_scene();
    let sphere = sphere_scene(1_000_000);
    let glsl = with_shaders(&lit.scene, None, Some(pipeline::shader::BUILTIN_FRAGMENT))?;
    let at = |samples, capture| RenderSettings {
        width: 1280,
        height: 720,
        samples,
        capture,
        shading: Frequency::Phong,
        ..RenderSettings::default()
    };
    let case = |label, scene, settings, part| Case {
        label,
        scene,
        settings,
        part,
    };
    let every_buffer = at(Samples::X1, Capture::FULL);
    let colour = at(Samples::X1, Capture::COLOR);
    let sphere_settings = RenderSettings {
        shading: Frequency::Unlit,
        ..at(Samples::X4, Capture::FULL)
    };
    let cases = [
        case(EVERY_BUFFER, &lit.scene, every_buffer, Part::Frame),
        case("  its resolve", &lit.scene, every_buffer, Part::Resolve),
        case(
            "lit textured, 1 sample, colour only",
            &lit.scene,
            colour,
            Part::Frame,
        ),
        case(
            "1M sphere, 4 samples, every buffer",
            &sphere.scene,
            sphere_settings,
            Part::Frame,
        ),
        case(
            "student's Blinn-Phong GLSL / built-in",
            &lit.scene,
            colour,
            Part::ShaderRatio,
        ),
    ];
    writeln!(
        out,
        "\nscaling with threads, 1280×720, medians of {frames} frames in ms (a ratio on the \
         shader row); s = t₁/tₙ, e = s/n at the most threads\n"
    )?;
    write!(out, "{:<40}", "case")?;
    for n in threads {
        write!(out, " {:>10}", format!("{n} thr."))?;
    }
    writeln!(out, " {:>8} {:>8}", "s", "e")?;
    // Speed-up and efficiency need a one-thread time to compare with.
    let one_thread = threads.first() == Some(&1) && threads.len() > 1;
    let mut every_buffer_row = Vec::new();
    for case in &cases {
        write!(out, "{:<40}", case.label)?;
        let mut row = Vec::with_capacity(threads.len());
        for &n in threads {
            let value = measure_case(case, &glsl, n, frames)?;
            match case.part {
                Part::ShaderRatio => write!(out, " {value:>9.2}×")?,
                _ => write!(out, " {value:>10.2}")?,
            }
            row.push(value);
        }
        match (case.part, row.first(), row.last(), threads.last()) {
            (Part::Frame | Part::Resolve, Some(&one), Some(&t), Some(&n)) if one_thread => {
                let (s, e) = speed_up(one, t, n);
                writeln!(out, " {s:>7.2}× {:>7.0}%", e * 100.0)?;
            }
            _ => writeln!(out)?,
        }
        if case.label == EVERY_BUFFER {
            every_buffer_row = row;
        }
    }
    if one_thread {
        targets(threads, &every_buffer_row, out)?;
    }
    Ok(())
}

/// The label of the row the targets are about.
const EVERY_BUFFER: &str = "lit textured, 1 sample, every buffer";

/// The every-buffer frame's targets at 2 and 16 threads, where `row` (its times at `threads`,
/// the first one thread) has them.
fn targets(threads: &[usize], row: &[f64], out: &mut dyn Write) -> anyhow::Result<()> {
    let Some(&one) = row.first() else {
        return Ok(());
    };
    for (&n, &t) in threads.iter().zip(row).skip(1) {
        let limit = match n {
            2 => 0.55,
            16 => 0.12,
            _ => continue,
        };
        let ratio = t / one;
        writeln!(
            out,
            "every-buffer frame on {n} threads: {ratio:.2}× its 1-thread time (target ≤ \
             {limit:.2}×: {})",
            if ratio <= limit { "met" } else { "not met" }
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thread_counts_double_up_to_the_cores() {
        assert_eq!(thread_counts(1), vec![1]);
        assert_eq!(thread_counts(2), vec![1, 2]);
        assert_eq!(thread_counts(6), vec![1, 2, 4, 6]);
        assert_eq!(thread_counts(16), vec![1, 2, 4, 8, 16]);
        assert_eq!(thread_counts(0), vec![1]);
    }

    #[test]
    fn speed_up_and_efficiency_follow_their_definitions() {
        // The table: 116.4 ms on one thread, 35.4 on sixteen: s = 3.29, e = 20.5 %.
        let (s, e) = speed_up(116.4, 35.4, 16);
        assert!((s - 3.288).abs() < 1e-3, "{s}");
        assert!((e - 0.2055).abs() < 1e-4, "{e}");
        // Perfect sharing: half the time on two threads is an efficiency of 1.
        assert_eq!(speed_up(10.0, 5.0, 2), (2.0, 1.0));
    }
}
