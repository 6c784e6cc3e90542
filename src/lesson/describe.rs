//! A picture of a scene in words, for its text alternative: the handout's `alt` and the name a
//! screen reader gives the app's picture ([`crate::vocabulary::alt_text`] writes the words; here
//! the scene's objects are named in the reader's language, the step's subject first).

use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;

use super::SceneSpec;
use crate::vocabulary::alt_text::{Shown, alt_text};
use crate::vocabulary::{Lang, Stage};

/// `capture`, drawn from `spec` on `stage` showing `buffer`, in words: the objects `focus`
/// names first (every object when it names none), a figure's parts read as the figure, and at
/// window pixel `pixel` the first and last lines of its derivation.
#[must_use]
pub fn picture(
    spec: &SceneSpec,
    capture: &FrameCapture,
    (stage, buffer): (Stage, Option<BufferKind>),
    focus: &[String],
    pixel: Option<(u32, u32)>,
    lang: Lang,
) -> String {
    let (mut subject, mut rest) = (Vec::new(), Vec::new());
    for o in &capture.objects {
        let whole = o.name.split_once(": ").map_or(o.name.as_str(), |(f, _)| f);
        let name = spec.label(whole, lang);
        let list = if focus.is_empty() || crate::spaces::named_in(focus, &o.name) {
            &mut subject
        } else {
            &mut rest
        };
        if !list.contains(&name) {
            list.push(name);
        }
    }
    let explained = pixel.and_then(|(x, y)| capture.explain(x, y));
    let pixel = explained.as_ref().map(|p| (p, spec.label(&p.object, lang)));
    alt_text(
        &Shown {
            stage,
            buffer,
            objects: (&subject, &rest),
            size: (capture.width(), capture.height()),
            pixel,
        },
        lang,
    )
}
