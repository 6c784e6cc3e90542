//! The finer render a session asks for: the buffer shown rendered again at the size its view
//! draws it (see `app/view_resolution.rs`), and whether the view now asks for one the latest job did not.

use pipeline::buffers::BufferKind;

use super::state::Session;
use crate::app::view_resolution::{size, wanted};

impl Session {
    /// What the next job renders at the view's resolution for this session, if anything: the buffer
    /// shown and the size. Not while a parameter is dragged or an animation plays (the frames must
    /// keep up; the finer picture follows when they stop), nor beside
    /// a comparison, nor when the student's shaders run (interpreted, each pixel traced: the lesson's
    /// pixels are the ones the exercise compares).
    #[must_use]
    pub fn view_resolution_job(&self) -> Option<(BufferKind, (u32, u32))> {
        let session = self;
        let sel = &session.selection;
        let settings = &session.spec.settings;
        let playing = session.lesson.as_ref().is_some_and(|p| p.playing);
        let shown = wanted(sel.stage, sel.buffer)
            && !session.drafting
            && !playing
            && sel.comparison.is_none()
            && !session.spec.scene.has_shaders();
        shown
            .then(|| size((settings.width, settings.height), session.view_pixels?))
            .flatten()
            .map(|s| (sel.buffer, s))
    }

    /// Whether the view now asks for a finer render the latest job did not: another buffer, or a
    /// size more than 5 % wider or narrower (a window being resized does not render every frame).
    #[must_use]
    pub fn view_resolution_missing(&self) -> bool {
        match (self.view_resolution_job(), self.view_resolution.asked) {
            (Some((b, size)), Some((asked_b, asked))) => {
                b != asked_b || size.0.abs_diff(asked.0) * 20 > asked.0
            }
            (Some(_), None) => true,
            (None, _) => false,
        }
    }
}
