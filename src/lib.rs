//! pipelens: a glass-box graphics pipeline. This library holds everything but `main`, so that
//! tests can drive it. The pipeline itself is the `pipeline` crate; above it, in the order data
//! flows:
//!
//! - [`vocabulary`]: the words everything shares (stages, spaces, comparisons, two languages);
//! - [`palette`]: the colours that carry a meaning, kept apart for colour-blind eyes;
//! - [`lesson`]: scene files and lessons, parsed and validated;
//! - [`observer`]: the scene seen from outside;
//! - [`export`]: snapshots and handouts written to disk;
//! - [`lab`]: a lab's check — the student's frame against pipelens' own — and its verdict in
//!   words, for the app and `pipelens grade`;
//! - [`app`]: the desktop app;
//! - [`cli`]: the command line, which opens the app or exports, checks and benchmarks
//!   ([`bench`](mod@bench)).

pub mod app;
#[cfg(not(target_arch = "wasm32"))]
pub mod bench;
#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod export;
pub mod lab;
pub mod lesson;
pub mod observer;
pub mod palette;
pub mod spaces;
pub mod vocabulary;
