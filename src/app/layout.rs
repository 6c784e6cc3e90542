//! The main view's space cut for what it shows side by side: a view and the observer, a lab's
//! student frame and its two companions; the room the panels at the right start with; and
//! what a screen reader calls a panel's divider.

/// The space left in `ui` cut in two with a gap: `(all, first, second)`, beside each other, or
/// (in a portrait space, a phone's) one over the other. With the `aspect` of the image in the
/// first part, it is as large as the image needs to fill the other side, but no more than two
/// thirds; the second part (the observer, which renders at any aspect) takes the rest. On a
/// small screen a space about as high as wide is cut the way that gives the image more area
/// (`stacks`): a 360-point phone's 640×400 picture is 320×200 over the observer, not 205×128
/// beside it.
pub(super) fn split(ui: &egui::Ui, aspect: Option<f32>) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    let gap = 8.0;
    let small = super::window_size::is_compact(ui.ctx());
    if area.height() > area.width() * 1.1 || (small && stacks(area.size(), aspect, gap)) {
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

/// Whether an image of `aspect` gets more area over the second part than beside it, in a space
/// of `size`, each cut as [`split`] cuts it.
fn stacks(size: egui::Vec2, aspect: Option<f32>, gap: f32) -> bool {
    let Some(a) = aspect.filter(|a| a.is_finite() && *a > 0.0) else {
        return false;
    };
    // The image fitted into a part `w`×`h`: its area.
    let fitted = |w: f32, h: f32| {
        let (w, h) = (w.min(h * a), h.min(w / a));
        w * h
    };
    let height = size.y - gap;
    let over = fitted(size.x, (size.x / a).clamp(height * 0.4, height * 0.64));
    let width = size.x - gap;
    let beside = fitted((size.y * a).clamp(width * 0.4, width * 0.64), size.y);
    over > beside
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
/// frame at the left, pipelens' own and the difference at the right, each under its caption,
/// `caption(width)` high when wrapped to that width (in a portrait space, as [`split`] cuts
/// it). The cut is the one that gives the three the most area, the student's frame never
/// narrower than the others nor wider than two thirds, the right two one over the other or
/// side by side as [`lab_pair`] arranges them: in a wide, low space (a projector with the
/// narration band) the student's frame is large beside two smaller ones side by side, each
/// under its whole caption; in a tall one (beside the code at 1920 points) the three are the
/// same size, one beside two.
pub(super) fn lab_split(
    ui: &egui::Ui,
    aspect: f32,
    caption: &dyn Fn(f32) -> f32,
) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    let gap = 8.0;
    if area.height() > area.width() * 1.1 || aspect <= 0.0 || !aspect.is_finite() {
        return split(ui, Some(aspect));
    }
    let (w, h) = (area.width() - gap, area.height());
    let right_of = |left: f32| {
        egui::Rect::from_min_max(egui::pos2(area.left() + left + gap, area.top()), area.max)
    };
    let total = |left: f32| {
        let pair = lab_pair(right_of(left), aspect, caption);
        fitted(egui::vec2(left, h), aspect) + pair.iter().map(|p| p.area).sum::<f32>()
    };
    // The right pictures, as wide as they can be: no wider than the left.
    let least = (w / 2.0).min(((h - gap) / 2.0) * aspect).min(w * 0.64);
    let left = (0..=32)
        .map(|k| least + (w * 0.64 - least) * k as f32 / 32.0)
        .max_by(|a, b| total(*a).total_cmp(&total(*b)))
        .unwrap_or(w / 2.0);
    let left_rect = egui::Rect::from_min_size(area.min, egui::vec2(left, area.height()));
    (area, left_rect, right_of(left))
}

/// One of a lab's two companion pictures: its space (caption included) and the area its
/// picture takes under the caption.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Companion {
    pub space: egui::Rect,
    pub area: f32,
}

/// A lab's two companion pictures of `aspect` in `rect`, each under a caption `caption(width)`
/// high at its space's width: one over the other or side by side, whichever leaves the two
/// pictures more area (a caption that does not fit above its picture leaves it no area here;
/// the view then writes it over the picture's corner).
pub(super) fn lab_pair(
    rect: egui::Rect,
    aspect: f32,
    caption: &dyn Fn(f32) -> f32,
) -> [Companion; 2] {
    let gap = 8.0;
    let companion = |space: egui::Rect| {
        let room = egui::vec2(space.width(), space.height() - caption(space.width()));
        Companion {
            space,
            area: fitted(room, aspect),
        }
    };
    let (w, h) = ((rect.width() - gap) / 2.0, (rect.height() - gap) / 2.0);
    let stacked = [
        egui::Rect::from_min_size(rect.min, egui::vec2(rect.width(), h)),
        egui::Rect::from_min_max(egui::pos2(rect.left(), rect.bottom() - h), rect.max),
    ]
    .map(companion);
    let beside = [
        egui::Rect::from_min_size(rect.min, egui::vec2(w, rect.height())),
        egui::Rect::from_min_max(egui::pos2(rect.right() - w, rect.top()), rect.max),
    ]
    .map(companion);
    let area = |pair: &[Companion; 2]| pair[0].area + pair[1].area;
    if area(&beside) > area(&stacked) * 1.05 {
        beside
    } else {
        stacked
    }
}

/// The area of a picture of `aspect` fitted in `room` (none where the room is empty).
fn fitted(room: egui::Vec2, aspect: f32) -> f32 {
    let width = room.x.min(room.y * aspect).max(0.0);
    width * width / aspect
}

/// Names the divider of the resizable panel `salt`, just shown in `parent`, for a screen reader
/// in the language shown: "Resize panel: Inspector". egui calls every divider "Resize panel", in
/// English; it keys it `parent.scope_id().with(salt).with("__resize")`, and a test reads the
/// names in the AccessKit tree, so a change of that key in egui is seen.
pub(super) fn name_divider(
    parent: &egui::Ui,
    salt: &str,
    panel: &str,
    lang: crate::vocabulary::Lang,
) {
    let id = parent.scope_id().with(salt).with("__resize");
    let name = lang.t_with("layout-resize-panel", &[("panel", &panel)]);
    parent
        .ctx()
        .accesskit_node_builder(id, |node| node.set_label(name));
}

#[cfg(test)]
mod tests {
    use super::lab_pair;
    use egui::{Rect, pos2, vec2};

    /// Two lines of classroom type (28 points each) where the space is narrower than 400
    /// points, one line otherwise.
    fn caption(width: f32) -> f32 {
        if width < 400.0 { 62.0 } else { 34.0 }
    }

    /// A wide, low column (a projector with the narration band): the two pictures go side by
    /// side, each under its caption; the picture of aspect 1.6 in a 346 × 370 half under a
    /// two-line caption is 346 × 216, where stacked it would be 235 × 147 under one line.
    #[test]
    fn a_low_column_puts_the_pictures_side_by_side_under_their_captions() {
        let rect = Rect::from_min_size(pos2(600.0, 60.0), vec2(700.0, 370.0));
        let pair = lab_pair(rect, 1.6, &caption);
        let half = vec2(346.0, 370.0);
        let spaces = [pos2(600.0, 60.0), pos2(954.0, 60.0)].map(|at| Rect::from_min_size(at, half));
        assert_eq!(pair.map(|p| p.space), spaces);
        let (w, h) = (346.0f32, 346.0 / 1.6);
        assert!((pair[0].area - w * h).abs() < 0.5, "{}", pair[0].area);
    }

    /// A tall column (beside the code at 1920 points): one over the other, each as wide as the
    /// column: 400 wide in a 400 × 411 half under a one-line caption, 400 × 250.
    #[test]
    fn a_tall_column_stacks_the_pictures() {
        let rect = Rect::from_min_size(pos2(0.0, 0.0), vec2(400.0, 830.0));
        let pair = lab_pair(rect, 1.6, &caption);
        let half = vec2(400.0, 411.0);
        let spaces = [pos2(0.0, 0.0), pos2(0.0, 419.0)].map(|at| Rect::from_min_size(at, half));
        assert_eq!(pair.map(|p| p.space), spaces);
        assert!(
            (pair[1].area - 400.0 * 250.0).abs() < 0.5,
            "{}",
            pair[1].area
        );
    }
}
