//! `pipelens bench --grade`: a class's worth of hand-ins of lesson 10's specular lab graded as
//! `pipelens grade` grades them (in parallel, on the threads rayon has), timed: the whole batch
//! and the time per hand-in. The hand-ins are the starter with its TODO filled in several ways,
//! right and wrong, and one that does not compile, so that the batch costs what a class costs.

use std::io::Write;
use std::time::Instant;

use anyhow::{Context, Result};
use rayon::prelude::*;

use crate::lab::submission::{Code, grade};
use crate::vocabulary::Lang;

/// The lesson and the lab step graded.
const LESSON: &str = "10-blinn-phong.toml";
/// What the starter says where the specular term goes.
const TODO: &str = "        // TODO: the specular term, where n·l > 0.";

/// Ways students fill in the TODO: right, right written otherwise, and the usual mistakes.
const FILLINGS: [&str; 5] = [
    "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }",
    "        vec3 h = (l + v) / length(l + v);
        sum += (n_dot_l > 0.0 ? 1.0 : 0.0) * f * ks * light.intensity * pow(max(dot(h, n), 0.0), shininess);",
    "        vec3 h = normalize(l + v);
        sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);",
    "        vec3 r = reflect(-l, n);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(r, v), 0.0), shininess);
        }",
    "        vec3 h = normalize(l + v)
        sum += ks * pow(max(dot(n, h), 0.0), shininess);",
];

/// Grades `count` hand-ins and prints the batch's time, the time per hand-in and how many
/// passed.
///
/// # Errors
/// When the lesson or its lab is missing, or writing fails.
pub fn run(count: usize, out: &mut dyn Write) -> Result<()> {
    let lesson = crate::lesson::library::lesson(LESSON).map_err(|d| anyhow::anyhow!("{d}"))?;
    let k = lesson
        .steps
        .iter()
        .position(|s| s.exercise.is_some())
        .context("lesson 10 has a lab")?;
    let starter = lesson.steps[k]
        .exercise
        .as_ref()
        .and_then(|e| e.starter.shader.as_ref())
        .map(|s| s.programs.fragment.source.clone())
        .context("a shader lab")?;
    anyhow::ensure!(starter.contains(TODO), "the starter's TODO moved");
    let hand_ins: Vec<Code> = (0..count)
        .map(|i| {
            let mut code = Code::default();
            code.take(
                "shader.frag",
                starter.replace(TODO, FILLINGS[i % FILLINGS.len()]),
            );
            code
        })
        .collect();
    let threads = rayon::current_num_threads();
    writeln!(
        out,
        "grading {count} hand-ins of {} step {} on {threads} thread(s)…",
        lesson.id,
        k + 1
    )?;
    let start = Instant::now();
    let passed = hand_ins
        .par_iter()
        .filter(|code| grade(&lesson, k, code, Lang::EN).passed)
        .count();
    let seconds = start.elapsed().as_secs_f64();
    writeln!(
        out,
        "graded {count} in {seconds:.1} s: {:.3} s a hand-in, {passed} passed (target: 200 in ≤ 60 s on 2 threads, ≤ 0.3 s a hand-in)",
        seconds / count.max(1) as f64
    )?;
    Ok(())
}
