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
