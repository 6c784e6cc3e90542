//! pipelens: a glass-box graphics pipeline. This library holds everything but `main`, so that
//! tests can drive it: the desktop app ([`app`]), the command line ([`cli`]), scene files and lessons ([`lesson`]), the
//! exporter ([`export`]) and the benchmark ([`bench`]). The pipeline itself is the `pipeline` crate.

pub mod app;
pub mod bench;
pub mod cli;
pub mod export;
pub mod lesson;
