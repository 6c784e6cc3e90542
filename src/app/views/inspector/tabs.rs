//! The inspector's tabs and what it keeps between frames: the tab shown (chosen by what the
//! step teaches when the step or stage changes), the spaces of the vertex table, and the
//! inspected pixel's record while the capture and the pixel stay the same.

use pipeline::capture::{FrameCapture, PixelRecord};

use crate::app::session::{Session, Teaching};
use crate::vocabulary::{Space, Stage};

/// The inspector's tabs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tab {
    /// The matrices.
    #[default]
    Matrices,
    /// The vertex table.
    Vertices,
    /// The pixel inspector.
    Pixel,
}

/// What the tab was chosen for: the step entered, the stage, the inspected pixel.
type Followed = (u64, Stage, Option<(u32, u32)>);

/// The inspector's state: the tab shown (chosen by what the step teaches when the step or stage
/// changes, by the user otherwise), the spaces the vertex table shows, and the inspected pixel's
/// record, kept while the capture and the pixel stay the same (replaying the fragments walks
/// every triangle).
#[derive(Default)]
pub struct Inspector {
    /// The tab shown.
    pub tab: Tab,
    /// The step, stage and pixel the tab was last chosen for.
    pub(super) followed: Option<Followed>,
    /// The spaces the vertex table shows (`None`: the stage's and the one before).
    pub(super) spaces: Option<Vec<Space>>,
    /// The vertex the table last scrolled to.
    pub(super) scrolled_to: Option<u32>,
    pub(super) record: Option<(u64, (u32, u32), PixelRecord)>,
}

impl Inspector {
    /// The record of the inspected pixel, computed once per capture and pixel.
    pub(super) fn record(
        &mut self,
        session: &Session,
        capture: &FrameCapture,
    ) -> Option<&PixelRecord> {
        let (x, y) = session.selection.pixel?;
        let key = (session.shown_generation, (x, y));
        if self.record.as_ref().is_none_or(|(g, p, _)| (*g, *p) != key) {
            self.record = capture.pixel_record(x, y).map(|r| (key.0, key.1, r));
        }
        self.record.as_ref().map(|(_, _, r)| r)
    }

    /// Opens the tab the step teaches when the step, the stage or the pixel changed.
    pub(super) fn follow(&mut self, session: &Session) {
        let sel = &session.selection;
        let key = (session.step_entered, sel.stage, sel.pixel);
        if self.followed == Some(key) {
            return;
        }
        if self
            .followed
            .is_none_or(|(step, stage, _)| (step, stage) != (key.0, key.1))
        {
            // A new step or stage shows its own spaces in the vertex table.
            self.spaces = None;
        }
        self.followed = Some(key);
        self.tab = match session.teaching() {
            Teaching::Pixel if sel.pixel.is_some() => Tab::Pixel,
            Teaching::Pixel => self.tab,
            _ => Tab::Matrices,
        };
    }
}
