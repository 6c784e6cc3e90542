//! What a frame's resolve learned of where its samples are covered, kept with the sample
//! buffers for the next frame's clear, which then clears those rows' spans only.

/// Where a frame's samples are covered, row by row, as its resolve found them: image row `r`'s
/// pixels with a covered sample all lie in `spans[r] = (first, end)` (`first ≥ end`: none).
/// Every other sample holds `clear` (the frame's cleared depth) and [`NONE`](super::NONE).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CoveredRows {
    pub(crate) clear: f32,
    pub(crate) spans: Vec<(u32, u32)>,
}

/// What is known of where the buffers hold anything but cleared samples. Knowledge about the
/// contents, not contents: two buffers with the same samples compare equal whatever each knows,
/// and a clone knows nothing (the safe answer: the whole buffer is cleared).
#[derive(Debug, Default)]
pub(crate) struct Covered(pub(crate) Option<CoveredRows>);

impl Clone for Covered {
    fn clone(&self) -> Self {
        Self(None)
    }
}

impl PartialEq for Covered {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}
