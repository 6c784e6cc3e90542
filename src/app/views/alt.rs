//! What a screen reader calls a view's picture: the view's name and the picture's text
//! alternative ([`crate::lesson::describe::picture`]: the stage, the buffer, the objects with
//! the step's subject first, at the inspected pixel the first and last lines of its
//! derivation). The words are made only when an accessibility client asks for them.

use pipeline::capture::FrameCapture;

use crate::app::session::Session;
use crate::vocabulary::Stage;

/// Names `response`, the picture of `capture` on `stage`, as an image: "`view`: the picture
/// in words".
pub fn name_picture(
    response: &egui::Response,
    view: &str,
    (session, capture, stage): (&Session, &FrameCapture, Stage),
) {
    response.widget_info(|| {
        let sel = &session.selection;
        let words = crate::lesson::describe::picture(
            &session.spec,
            capture,
            (stage, stage.space().is_none().then_some(sel.buffer)),
            sel.focus.as_deref().unwrap_or_default(),
            sel.pixel,
            session.lang,
        );
        egui::WidgetInfo::labeled(egui::Role::Image, true, format!("{view}: {words}"))
    });
}

/// Seconds a live region's words must be gone for before the same words are said again.
pub const GONE: f64 = 1.0;

/// Makes `response`'s node, showing `text`, a live region (ARIA's `aria-live="polite"`) in the
/// frame its words are new: a screen reader reads them out then, without the focus moving —
/// the narration card's title on a new step, a lab's verdict as the student's code changes it.
/// Only then: AT-SPI reads a live node out each time it is added to the tree, and egui may
/// add a label's node anew in a frame where nothing about it changed. Words are new when they
/// differ from the last `salt` said, or when they were not shown for [`GONE`] (a pass that is
/// not seen does not count): a verdict that is left out of a few frames while an animated
/// lab's frame is checked again is not said again. The widget's own node, so that its words
/// stand once in the tree.
pub fn announce(response: &egui::Response, (salt, text): (&'static str, &str)) {
    let ctx = &response.ctx;
    // Not said while no screen reader listens, nor in a pass that shows nothing (an area's
    // first frame sizes it unseen).
    if ctx.accesskit_node_builder(response.id, |_| ()).is_none() {
        return;
    }
    let key = egui::Id::unique(("announced", salt));
    let now = ctx.input(|i| i.time);
    let new = ctx.data_mut(|d| {
        // The words, when they were said, when they were last shown.
        let last = d.get_temp::<(String, f64, f64)>(key);
        let said = match last {
            Some((t, said, shown)) if t == text && now - shown <= GONE => said,
            _ => now,
        };
        d.insert_temp(key, (text.to_owned(), said, now));
        said == now
    });
    if new {
        ctx.accesskit_node_builder(response.id, |node| {
            node.set_live(egui::accesskit::Live::Polite);
        });
    }
}
