//! The main view's space cut for what it shows side by side: a view and the observer, a lab's
//! student frame and its two companions; and the room the panels at the right start with.

/// The space left in `ui` cut in two with a gap: `(all, first, second)`, beside each other, or
/// (in a portrait space, a phone's) one over the other. With the `aspect` of the image in the
/// first part, it is as large as the image needs to fill the other side, but no more than two
/// thirds; the second part (the observer, which renders at any aspect) takes the rest.
pub(super) fn split(ui: &egui::Ui, aspect: Option<f32>) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    let gap = 8.0;
    if area.height() > area.width() * 1.1 {
        let height = area.height() - gap;
        let top = aspect.map_or(height / 2.0, |a| {
            (area.width() / a).clamp(height * 0.4, height * 0.64)
        });
        let first = egui::Rect::from_min_size(area.min, egui::vec2(area.width(), top));
        let second =
            egui::Rect::from_min_max(egui::pos2(area.left(), first.bottom() + gap), area.max);
        return (area, first, second);
    }
    let width = area.width() - gap;
    let left_width = aspect.map_or(width / 2.0, |a| {
        (area.height() * a).clamp(width * 0.4, width * 0.64)
    });
    let left = egui::Rect::from_min_size(area.min, egui::vec2(left_width, area.height()));
    let right = egui::Rect::from_min_max(egui::pos2(left.right() + gap, area.top()), area.max);
    (area, left, right)
}

/// The room the panels at the right start with (see [`super::PipelensApp::room`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Room {
    /// One panel open.
    Alone,
    /// Two or more open.
    Beside,
    /// Two or more open beside a lab's three pictures.
    Crowded,
}

/// A lab's space cut for its three pictures of `aspect` (width over height): the student's
/// frame at the left, pipelens' own over the difference at the right (in a portrait space, as
/// [`split`] cuts it). The cut is the one that gives the three the most area, the student's
/// frame never narrower than the others nor wider than two thirds: in a wide, low space (a
/// projector with the narration band) the student's frame is large beside two small ones; in a
/// tall one (beside the code at 1920 points) the three are the same size, one beside two.
pub(super) fn lab_split(ui: &egui::Ui, aspect: f32) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    let gap = 8.0;
    if area.height() > area.width() * 1.1 || aspect <= 0.0 || !aspect.is_finite() {
        return split(ui, Some(aspect));
    }
    let (w, h) = (area.width() - gap, area.height());
    // An image of `aspect` fitted in width × height: its area.
    let fitted = |width: f32, height: f32| {
        let width = width.min(height * aspect).max(0.0);
        width * width / aspect
    };
    let total = |left: f32| fitted(left, h) + 2.0 * fitted(w - left, (h - gap) / 2.0);
    // The right column's pictures, as wide as they can be: no wider than the left.
    let least = (w / 2.0).min(((h - gap) / 2.0) * aspect).min(w * 0.64);
    let left = (0..=32)
        .map(|k| least + (w * 0.64 - least) * k as f32 / 32.0)
        .max_by(|a, b| total(*a).total_cmp(&total(*b)))
        .unwrap_or(w / 2.0);
    let left_rect = egui::Rect::from_min_size(area.min, egui::vec2(left, area.height()));
    let right = egui::Rect::from_min_max(egui::pos2(left_rect.right() + gap, area.top()), area.max);
    (area, left_rect, right)
}
