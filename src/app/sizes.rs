//! What a frame shows at its smallest, measured from what egui laid out: the smallest text
//! (its font's size, in points — CSS pixels in a page) and the smallest control a finger or
//! the mouse must hit. A page reports them (`platform::report`) for the browser test, which
//! has no AccessKit tree to measure: a phone's text must be 12 points or more and its
//! controls 44 (issue 60); the desktop's tests measure AccessKit's tree and these agree.

/// The frame's smallest text and control, in points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Least {
    /// The smallest font size of any text in sight (a word clipped out of sight is not).
    pub text: f32,
    /// The smallest side of any control in sight that takes a click or the keyboard: a button,
    /// a checkbox, a text box, a slider, a tab (not a label, which takes only a selection).
    pub target: f32,
    /// What the smallest control says of itself, for a message: its rect.
    pub target_rect: egui::Rect,
}

impl Default for Least {
    /// Nothing measured yet: no text, no control.
    fn default() -> Self {
        Self {
            text: f32::INFINITY,
            target: f32::INFINITY,
            target_rect: egui::Rect::NOTHING,
        }
    }
}

/// Measures the frame laid out so far in `ctx` (call at its end): infinite sizes when it has
/// no text or no control.
#[must_use]
pub fn least(ctx: &egui::Context) -> Least {
    let screen = ctx.content_rect();
    let layers: Vec<egui::LayerId> = ctx.memory(|m| m.layer_ids().collect());
    let text = ctx.graphics(|g| {
        layers
            .iter()
            .filter_map(|l| g.get(*l))
            .flat_map(egui::layers::PaintList::all_entries)
            .filter(|c| c.clip_rect.intersects(screen))
            .map(|c| smallest_text(&c.shape, c.clip_rect))
            .fold(f32::INFINITY, f32::min)
    });
    let (target, target_rect) = ctx.viewport(|v| {
        v.this_pass
            .widgets
            .layers()
            .flat_map(|(_, widgets)| widgets.iter())
            .filter(|w| {
                w.enabled
                    && w.sense.is_focusable()
                    && w.interact_rect.width() > 0.5
                    && w.interact_rect.height() > 0.5
                    && w.interact_rect.intersects(screen)
            })
            .map(|w| (w.rect.width().min(w.rect.height()), w.rect))
            .fold((f32::INFINITY, egui::Rect::NOTHING), |a, b| {
                if b.0 < a.0 { b } else { a }
            })
    });
    Least {
        text,
        target,
        target_rect,
    }
}

/// The smallest font size of the text in `shape` that shows inside `clip`.
fn smallest_text(shape: &egui::Shape, clip: egui::Rect) -> f32 {
    match shape {
        egui::Shape::Vec(v) => v
            .iter()
            .map(|s| smallest_text(s, clip))
            .fold(f32::INFINITY, f32::min),
        egui::Shape::Text(t)
            if !t.galley.text().trim().is_empty()
                && t.galley.rect.translate(t.pos.to_vec2()).intersects(clip) =>
        {
            t.galley
                .job
                .sections
                .iter()
                .filter(|s| {
                    t.galley
                        .job
                        .text
                        .get(s.byte_range.start.0..s.byte_range.end.0)
                        .is_some_and(|words| words.chars().any(|c| !c.is_whitespace()))
                })
                .map(|s| s.format.font_id.size)
                .fold(f32::INFINITY, f32::min)
        }
        _ => f32::INFINITY,
    }
}
