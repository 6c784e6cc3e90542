//! What a screen reader calls a view's picture: the view's name and the picture's text
//! alternative ([`crate::lesson::describe::picture`]: the stage, the buffer, the objects with
//! the step's subject first, at the inspected pixel the first and last lines of its
//! derivation). The words are made only when an accessibility client asks for them, or a page
//! keeps them.
//!
//! A page has no AccessKit (eframe's web build draws egui on a canvas), so there the same
//! words stand as text in the document beside the canvas ([`PageWords`]: the step's title, the
//! narration, each picture's text alternative, a lab's verdict, each in its element of
//! `web/index.html`, the title and the verdict in live regions); the window hands those that
//! changed to `platform::show_page_words`.

use pipeline::capture::FrameCapture;

use crate::app::session::Session;
use crate::vocabulary::Stage;

/// Names `response`, the picture of `capture` on `stage`, as an image: "`view`: the picture
/// in words" ("`view`：…" in Chinese).
pub fn name_picture(
    response: &egui::Response,
    view: &str,
    (session, capture, stage): (&Session, &FrameCapture, Stage),
) {
    name_image(response, || {
        let sel = &session.selection;
        let words = crate::lesson::describe::picture(
            &session.spec,
            capture,
            (stage, stage.space().is_none().then_some(sel.buffer)),
            sel.focus.as_deref().unwrap_or_default(),
            sel.pixel,
            session.lang,
        );
        format!("{view}{}{words}", session.lang.t("alt-name-colon"))
    });
}

/// Names `response` as an image by `words`, its text alternative: made when an accessibility
/// client asks for it, and in a page for the words beside its canvas ([`Part::Picture`]).
pub fn name_image(response: &egui::Response, words: impl Fn() -> String) {
    let info = |w: &str| egui::WidgetInfo::labeled(egui::Role::Image, true, w);
    if keeps_page_words(&response.ctx) {
        let w = words();
        for_the_page(&response.ctx, Part::Picture, &w);
        response.widget_info(|| info(&w));
    } else {
        response.widget_info(|| info(&words()));
    }
}

/// Seconds a live region's words must be gone for before the same words are said again.
pub const GONE: f64 = 1.0;

/// Makes `response`'s node, showing `text`, a live region (ARIA's `aria-live="polite"`) in the
/// frame its words are new: a screen reader reads them out then, without the focus moving —
/// the narration card's title on a new step, a lab's verdict as the student's code changes it.
/// Only then: AT-SPI reads a live node out each time it is added to the tree, and egui may
/// add a label's node anew in a frame where nothing about it changed. Words are new when they
/// differ from the last said for `part`, or when they were not shown for [`GONE`] (a pass that is
/// not seen does not count): a verdict that is left out of a few frames while an animated
/// lab's frame is checked again is not said again. The widget's own node, so that its words
/// stand once in the tree. In a page the words go to `part`'s live region instead.
pub fn announce(response: &egui::Response, (part, text): (Part, &str)) {
    let ctx = &response.ctx;
    for_the_page(ctx, part, text);
    let salt = part.id();
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

/// A part of the words a page keeps beside its canvas, for a screen reader there: each is an
/// element of `web/index.html`, by [`Part::id`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The step's number and title ("3. Clip space"), in a live region: read out on a new step.
    Title,
    /// The narration's text.
    Narration,
    /// Each picture's text alternative, named by its view as [`name_picture`] names it.
    Picture,
    /// A lab's verdict, in a live region (`role="status"`): read out as it changes.
    Verdict,
}

impl Part {
    /// Every part, in the page's order.
    pub const ALL: [Self; 4] = [Self::Title, Self::Narration, Self::Picture, Self::Verdict];

    /// The id of its element in `web/index.html`.
    #[must_use]
    pub fn id(self) -> &'static str {
        match self {
            Self::Title => "pipelens-step",
            Self::Narration => "pipelens-narration",
            Self::Picture => "pipelens-picture",
            Self::Verdict => "pipelens-verdict",
        }
    }

    /// Whether a screen reader reads it out as it changes (ARIA's `aria-live`).
    #[must_use]
    pub fn live(self) -> bool {
        matches!(self, Self::Title | Self::Verdict)
    }
}

/// The words a page shows beside its canvas: what each [`Part`] says now, and when it was last
/// said. A part not said in a frame keeps its words for [`GONE`] seconds before it empties, so
/// that a verdict left out of a few frames (an animated lab checked again) is not read out
/// again when it comes back.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PageWords {
    /// Each part's words (lines joined by a line break) and when they were last said.
    shown: [(String, f64); 4],
    /// The words said in the frame being drawn.
    said: [Vec<String>; 4],
}

impl PageWords {
    /// What `part` says now.
    #[must_use]
    pub fn get(&self, part: Part) -> &str {
        &self.shown[part as usize].0
    }

    /// Ends a frame drawn at `now` (seconds): the parts whose words changed, with their new words.
    pub fn settle(&mut self, now: f64) -> Vec<(Part, String)> {
        let mut changed = Vec::new();
        for part in Part::ALL {
            let said = std::mem::take(&mut self.said[part as usize]).join("\n");
            let (words, when) = &mut self.shown[part as usize];
            if said.is_empty() && now - *when <= GONE {
                continue;
            }
            if !said.is_empty() {
                *when = now;
            }
            if *words != said {
                words.clone_from(&said);
                changed.push((part, said));
            }
        }
        changed
    }
}

/// Where the page's words are kept, in egui's memory, and whether they are.
fn page_words_ids() -> (egui::Id, egui::Id) {
    let id = egui::Id::unique("pipelens-page-words");
    (id, id.with("kept"))
}

/// Has the words of each frame kept for a page ([`PageWords`]): the browser's start calls it,
/// and a test that reads them.
pub fn keep_page_words(ctx: &egui::Context) {
    let (_, kept) = page_words_ids();
    ctx.data_mut(|d| d.insert_temp(kept, true));
}

/// Whether the words are kept for a page ([`keep_page_words`]).
#[must_use]
pub fn keeps_page_words(ctx: &egui::Context) -> bool {
    let (_, kept) = page_words_ids();
    ctx.data(|d| d.get_temp::<bool>(kept).unwrap_or(false))
}

/// Adds `text` to what `part` says in this frame, where a page keeps its words (once: egui may
/// draw a frame twice).
pub fn for_the_page(ctx: &egui::Context, part: Part, text: &str) {
    if text.is_empty() || !keeps_page_words(ctx) {
        return;
    }
    let (id, _) = page_words_ids();
    ctx.data_mut(|d| {
        let said = &mut d.get_temp_mut_or_default::<PageWords>(id).said[part as usize];
        if !said.iter().any(|s| s == text) {
            said.push(text.to_owned());
        }
    });
}

/// Ends the frame's page words ([`PageWords::settle`]): the parts that changed, for the page to
/// write; none where no page keeps them.
pub fn settle_page_words(ctx: &egui::Context) -> Vec<(Part, String)> {
    if !keeps_page_words(ctx) {
        return Vec::new();
    }
    let (id, _) = page_words_ids();
    let now = ctx.input(|i| i.time);
    ctx.data_mut(|d| d.get_temp_mut_or_default::<PageWords>(id).settle(now))
}

/// The page's words as they stand (after the last frame), where a page keeps them.
#[must_use]
pub fn page_words(ctx: &egui::Context) -> Option<PageWords> {
    let (id, _) = page_words_ids();
    keeps_page_words(ctx).then(|| ctx.data(|d| d.get_temp::<PageWords>(id).unwrap_or_default()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn say(w: &mut PageWords, part: Part, text: &str) {
        w.said[part as usize].push(text.to_owned());
    }

    /// A part's words change when new words are said, stay while they are said again or are
    /// left out for less than GONE seconds, and empty once gone longer.
    #[test]
    fn the_page_words_change_only_when_new_and_empty_once_gone() {
        let mut w = PageWords::default();
        assert!(w.settle(0.0).is_empty(), "nothing said, nothing changes");
        say(&mut w, Part::Title, "1. Ambient");
        say(&mut w, Part::Picture, "pixel view: a");
        say(&mut w, Part::Picture, "observer: b");
        assert_eq!(
            w.settle(0.1),
            vec![
                (Part::Title, "1. Ambient".to_owned()),
                (Part::Picture, "pixel view: a\nobserver: b".to_owned())
            ]
        );
        say(&mut w, Part::Title, "1. Ambient");
        assert!(w.settle(0.2).is_empty(), "the same words again: no change");
        // Left out of frames for 0.9 s (≤ GONE): kept, and back without a change.
        assert!(w.settle(1.0).is_empty());
        say(&mut w, Part::Title, "1. Ambient");
        say(&mut w, Part::Picture, "pixel view: a");
        say(&mut w, Part::Picture, "observer: b");
        assert!(w.settle(1.1).is_empty());
        assert_eq!(w.get(Part::Title), "1. Ambient");
        // Gone 1.5 s: emptied.
        say(&mut w, Part::Verdict, "Not yet");
        assert_eq!(w.settle(1.3), vec![(Part::Verdict, "Not yet".to_owned())]);
        assert_eq!(
            w.settle(2.6),
            vec![
                (Part::Title, String::new()),
                (Part::Picture, String::new()),
                (Part::Verdict, String::new())
            ]
        );
        assert!(w.settle(2.7).is_empty());
    }
}
