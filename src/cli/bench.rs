//! `pipelens bench`: which of its forms the arguments ask for, run and printed to stdout.

use std::path::Path;
use std::process::ExitCode;

use anyhow::Result;

use super::Command;

/// `pipelens bench` in its six forms: the stages (with llvmpipe alongside on request), the
/// handouts, the student's shaders, a lesson's steps as the app renders them, a class's lab
/// hand-ins graded, the frame's scaling with threads.
pub(super) fn run(command: Command) -> Result<ExitCode> {
    match command {
        Command::Bench {
            handouts: true,
            data,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::handouts::run(Path::new("lessons"), &data, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            shaders: true,
            quick,
            frames,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::shader_rows(frames.unwrap_or(if quick { 1 } else { 5 }), &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            grade: Some(count), ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::grade::run(count, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            scaling: true,
            threads,
            quick,
            frames,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            let threads: Vec<usize> = if threads.is_empty() {
                let cores = std::thread::available_parallelism().map_or(1, usize::from);
                crate::bench::scaling::thread_counts(cores)
            } else {
                threads.into_iter().map(usize::from).collect()
            };
            let frames = frames.unwrap_or(if quick { 1 } else { 7 });
            crate::bench::scaling::run(&threads, frames, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            steps: Some(lesson),
            quick,
            frames,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            let threads = std::thread::available_parallelism().map_or(1, usize::from);
            let frames = frames.unwrap_or(if quick { 1 } else { 7 });
            crate::bench::steps::run(&format!("{lesson}.toml"), frames, threads, &mut out)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            quick,
            frames,
            peer_python,
            peer_script,
            data,
            handouts: false,
            shaders: false,
            steps: None,
            grade: None,
            scaling: false,
            ..
        } => {
            let mut out = std::io::stdout().lock();
            crate::bench::run(quick, frames, &mut out)?;
            if let Some(python) = peer_python {
                let peer = crate::bench::Peer {
                    python,
                    script: peer_script,
                };
                crate::bench::run_against_peer(&peer, &data, quick, &mut out)?;
            }
            Ok(ExitCode::SUCCESS)
        }
        _ => anyhow::bail!("run_bench is called with a bench command"),
    }
}
