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
    let small = super::window_size::is_compact(ui.ctx());
    if area.height() > area.width() * 1.1 || (small && stacks(area, aspect)) {
        let (first, second) = portrait_cut(area, aspect);
        return (area, first, second);
    }
    let width = area.width() - GAP;
    let left_width = aspect.map_or(width / 2.0, |a| {
        (area.height() * a).clamp(width * 0.4, width * 0.64)
    });
    let left = egui::Rect::from_min_size(area.min, egui::vec2(left_width, area.height()));
    let right = egui::Rect::from_min_max(egui::pos2(left.right() + GAP, area.top()), area.max);
    (area, left, right)
}

/// [`split`]'s cut of `area` one part over the other: the first as high as an image of `aspect`
/// as wide as the space, but between 40 % and 64 % of the height (half without an image).
fn portrait_cut(area: egui::Rect, aspect: Option<f32>) -> (egui::Rect, egui::Rect) {
    let height = area.height() - GAP;
    let top = aspect.map_or(height / 2.0, |a| {
        (area.width() / a).clamp(height * 0.4, height * 0.64)
    });
    over(area, top)
}

/// `area` cut one part over the other: the first `top` high, the second under it after the gap.
fn over(area: egui::Rect, top: f32) -> (egui::Rect, egui::Rect) {
    let first = egui::Rect::from_min_size(area.min, egui::vec2(area.width(), top));
    let second = egui::Rect::from_min_max(egui::pos2(area.left(), first.bottom() + GAP), area.max);
    (first, second)
}

/// The gap between two parts of a cut.
const GAP: f32 = 8.0;

/// Whether an image of `aspect` gets more area over the second part than beside it, in a space
/// `area`, each cut as [`split`] cuts it.
fn stacks(area: egui::Rect, aspect: Option<f32>) -> bool {
    let Some(a) = aspect.filter(|a| a.is_finite() && *a > 0.0) else {
        return false;
    };
    let over = fitted(portrait_cut(area, Some(a)).0.size(), a);
    let width = area.width() - GAP;
    let beside = fitted(
        egui::vec2(
            (area.height() * a).clamp(width * 0.4, width * 0.64),
            area.height(),
        ),
        a,
    );
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
/// same size, one beside two. On a phone held upright, where the picture covers its view
/// (cropped rather than shrunk), a space about as high as wide (a 360-point phone's, between its
/// bar and its sheet) puts the student's frame over the two where, cut as [`split`] cuts a
/// portrait space, that crops less of it:
/// beside the two, a 4:3 frame in a column 196 × 273 points showed 54 % of its width, the
/// sphere cut at both sides; over them, 336 × 170, 67 % of its height. The frame's height is
/// then the one that gives the three the most area ([`lab_over`]).
pub(super) fn lab_split(
    ui: &egui::Ui,
    aspect: f32,
    caption: &dyn Fn(f32) -> f32,
) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    if area.height() > area.width() * 1.1 || aspect <= 0.0 || !aspect.is_finite() {
        return split(ui, Some(aspect));
    }
    let (left, right) = lab_beside(area, aspect, caption);
    if super::window_size::is_narrow(ui.ctx()) {
        let (top, _) = portrait_cut(area, Some(aspect));
        if covered_share(top, aspect) > covered_share(left, aspect) {
            let (top, bottom) = lab_over(area, aspect, caption);
            return (area, top, bottom);
        }
    }
    (area, left, right)
}

/// [`lab_split`]'s cut of `area` on a phone with the student's frame over the two companions:
/// between 58 % and 64 % of the height (64 % as [`split`] cuts a portrait space), as high as
/// gives the three pictures the most area — the frame covering its whole space, as the pixel
/// view draws it there, the companions each under its caption. The least was found on a
/// 360 × 640 phone: at half the height lesson 07's square, kept whole, left its frame 289 of
/// 328 points wide; from three fifths lesson 10's difference has no room for its three-line
/// key above it, which then covers the picture's top.
fn lab_over(
    area: egui::Rect,
    aspect: f32,
    caption: &dyn Fn(f32) -> f32,
) -> (egui::Rect, egui::Rect) {
    let h = area.height() - GAP;
    let total = |top: f32| {
        let (first, second) = over(area, top);
        first.area() + pair_area(second, aspect, caption)
    };
    over(area, best(h * 0.58, h * 0.64, total))
}

/// Of 33 values evenly spaced from `lo` to `hi`, the one that gives the largest `total`.
fn best(lo: f32, hi: f32, total: impl Fn(f32) -> f32) -> f32 {
    (0..=32)
        .map(|k| lo + (hi - lo) * k as f32 / 32.0)
        .max_by(|a, b| total(*a).total_cmp(&total(*b)))
        .unwrap_or(lo)
}

/// The area of the two companions' pictures in `rect` ([`lab_pair`]).
fn pair_area(rect: egui::Rect, aspect: f32, caption: &dyn Fn(f32) -> f32) -> f32 {
    lab_pair(rect, aspect, caption).iter().map(|p| p.area).sum()
}

/// How much of a picture of `aspect` a phone's view shows when the picture covers `rect`
/// (the pixel view's `cover`: as large as needed to fill it, the rest cropped): the rect's
/// aspect over the picture's, or the inverse, whichever is at most 1.
fn covered_share(rect: egui::Rect, aspect: f32) -> f32 {
    let r = rect.width() / rect.height();
    (r / aspect).min(aspect / r)
}

/// [`lab_split`]'s cut of `area` with the student's frame at the left: its space and the two
/// companions'.
fn lab_beside(
    area: egui::Rect,
    aspect: f32,
    caption: &dyn Fn(f32) -> f32,
) -> (egui::Rect, egui::Rect) {
    let (w, h) = (area.width() - GAP, area.height());
    let right_of = |left: f32| {
        egui::Rect::from_min_max(egui::pos2(area.left() + left + GAP, area.top()), area.max)
    };
    let total = |left: f32| {
        fitted(egui::vec2(left, h), aspect) + pair_area(right_of(left), aspect, caption)
    };
    // The right pictures, as wide as they can be: no wider than the left.
    let least = (w / 2.0).min(((h - GAP) / 2.0) * aspect).min(w * 0.64);
    let left = best(least, w * 0.64, total);
    let left_rect = egui::Rect::from_min_size(area.min, egui::vec2(left, area.height()));
    (left_rect, right_of(left))
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
    let companion = |space: egui::Rect| {
        let room = egui::vec2(space.width(), space.height() - caption(space.width()));
        Companion {
            space,
            area: fitted(room, aspect),
        }
    };
    let (w, h) = ((rect.width() - GAP) / 2.0, (rect.height() - GAP) / 2.0);
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
