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

/// A live region (ARIA's `aria-live="polite"`) saying `text`: a status node that a screen
/// reader reads out when it appears and again whenever its words change, without taking the
/// focus — the narration card on a new step, a lab's verdict as the student's code runs.
/// `salt` tells the live regions of one `ui` apart; each keeps its id from frame to frame, so
/// the same words are not read twice.
pub fn announce(ui: &egui::Ui, salt: &str, text: &str) {
    let id = ui.scope_id().with(("announced", salt));
    ui.ctx().accesskit_node_builder(id, |node| {
        node.set_role(egui::accesskit::Role::Status);
        node.set_label(text.to_owned());
        node.set_live(egui::accesskit::Live::Polite);
    });
}

/// A lesson's text with its marks taken out, its paragraphs run together: what a screen
/// reader reads of a narration (`**k_d·max(0, n·l)**` is read "kd·max(0, n·l)").
#[must_use]
pub fn plain_words(text: &str) -> String {
    text.split("\n\n")
        .map(|p| {
            crate::vocabulary::notation::read_aloud(&crate::vocabulary::notation::parse_paragraph(
                p,
            ))
        })
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .filter(|p| !p.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}
