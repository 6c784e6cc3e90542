//! An exercise step's reference frame and what the frame on screen shows against it.

use std::sync::Arc;

use pipeline::capture::FrameCapture;

use crate::lab::Findings;

/// The reference of an exercise step and how the frame on screen compares with it.
#[derive(Clone, Debug, Default)]
pub struct Comparison {
    /// pipelens' own frame of the step's scene (kept through drafts).
    pub reference: Option<Arc<FrameCapture>>,
    /// What the frame on screen shows against the reference (empty while either is missing or
    /// the frame on screen is a draft).
    pub findings: Findings,
}

impl Comparison {
    /// Whether the exercise passed: every curve point within the tolerance where a curve is
    /// compared, else every pixel.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.findings.passed()
    }
}
