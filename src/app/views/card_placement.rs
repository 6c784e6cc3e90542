//! Room for the subject beside the narration card. The card lies over the bottom-left of the
//! picture's area; a view frames its subject (the image, the geometry's bounding sphere, the
//! compared images) in the part of its area the card leaves free, so that the narration never
//! covers what the step is about. The card is drawn after the views, so they read where it
//! was in the frame before; a card that moved asks for one more frame.

use egui::{Context, Id, Rect};

/// The gap kept between the card and the subject, in points.
const GAP: f32 = 16.0;

fn key() -> Id {
    Id::unique("pipelens-narration-card-rect")
}

/// Where the narration card was drawn last frame, if it is shown.
#[must_use]
pub fn narration_card(ctx: &Context) -> Option<Rect> {
    ctx.data(|d| d.get_temp::<Option<Rect>>(key())).flatten()
}

/// Records where the narration card is (`None`: folded or no lesson); repaints once more when it
/// moved, so that the views frame their subjects clear of its new place.
pub fn set_narration_card(ctx: &Context, card: Option<Rect>) {
    if narration_card(ctx) != card {
        ctx.data_mut(|d| d.insert_temp(key(), card));
        ctx.request_repaint();
    }
}

/// How much of its own size a subject kept beside the card, the least a view reported this
/// frame (1: untouched).
fn kept_key() -> Id {
    Id::unique("pipelens-narration-kept")
}

/// A view reports that, framed clear of the card, its subject kept `share` of the area it
/// would have had without the card.
pub fn report_kept(ctx: &Context, share: f32) {
    ctx.data_mut(|d| {
        let least = d.get_temp::<f32>(kept_key()).unwrap_or(1.0).min(share);
        d.insert_temp(kept_key(), least);
    });
}

/// The least share the views reported since the last call (1 when none did).
pub fn take_kept(ctx: &Context) -> f32 {
    ctx.data_mut(|d| d.remove_temp::<f32>(kept_key()))
        .unwrap_or(1.0)
}

/// Below this share of its size a subject shrinks too much beside the card in the corner: the
/// card becomes a band across the bottom or a column down the left.
pub const LEAST_KEPT: f32 = 0.8;

/// How the narration card lies over the picture's area.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// In the bottom-left corner, over the picture.
    Corner,
    /// Across the bottom, as low as its words allow; the views keep the part above it.
    Band,
    /// Down the left, the area's height; the views keep the part right of it.
    Column,
}

/// The shape of what the views show, width/height: the stage's image (a geometry's subject is
/// a square), twice as wide with the observer beside it, half as wide again with an exercise's
/// two pictures stacked beside it; a comparison's grid fills any width (infinite).
#[must_use]
pub fn content_aspect(session: &crate::app::session::Session) -> f32 {
    let sel = &session.selection;
    let space = sel.stage.space();
    if sel.comparison.is_some() && space.is_none() {
        return f32::INFINITY;
    }
    let one = match (space, &session.capture) {
        (None, Some(c)) => c.width() as f32 / c.height().max(1) as f32,
        _ => 1.0,
    };
    if space.is_none() && session.current_exercise().is_some() {
        // The reference and the difference stacked beside the student's frame, half as high.
        one * 1.5
    } else if sel.show_observer {
        one * 2.0
    } else {
        one
    }
}

/// The card's shape this frame over `over`: in the corner; for the rest of the step (and this
/// window size), once a view's subject kept less than [`LEAST_KEPT`] of its size beside the
/// corner card, a band or a column, whichever leaves the subject larger ([`band_or_column`]).
/// The shares the views report in the first frame of a step or a size were measured against
/// the card of the layout before (the card's rect of the last frame): they decide nothing, and
/// the next frame measures against the card placed for this one.
pub fn shape(ctx: &Context, over: Rect, session: &crate::app::session::Session) -> Shape {
    let id = Id::unique("pipelens-narration-shape");
    let kept = take_kept(ctx);
    let key = (
        session.step_entered,
        over.width().round() as i64,
        over.height().round() as i64,
    );
    let kept_shape = ctx
        .data(|d| d.get_temp::<((u64, i64, i64), Shape)>(id))
        .filter(|(k, _)| *k == key)
        .map(|(_, s)| s);
    if kept_shape.is_none() {
        ctx.request_repaint();
    }
    let shape = if kept_shape == Some(Shape::Corner) && kept < LEAST_KEPT {
        ctx.request_repaint();
        let words = narration_card(ctx).map_or(0.0, |c| c.area());
        band_or_column(over, content_aspect(session), words)
    } else {
        kept_shape.unwrap_or(Shape::Corner)
    };
    ctx.data_mut(|d| d.insert_temp(id, (key, shape)));
    shape
}

/// Whether a band or a column leaves content of `aspect` larger in `over`, for a card whose
/// words took `words` square points in the corner: a band `words / width` high leaves the
/// content `min(H − h_band, W / aspect)` high, a column of [`card_size`]'s width
/// `min(H, (W − w_column) / aspect)`. A comparison's grid (infinitely wide) takes a band.
#[must_use]
pub fn band_or_column(over: Rect, aspect: f32, words: f32) -> Shape {
    if !aspect.is_finite() {
        return Shape::Band;
    }
    let (w, h) = (over.width(), over.height());
    let band = words / (w - 24.0).max(1.0) + 24.0 + GAP;
    let column = card_size(Shape::Column, over, aspect).0 + 12.0 + GAP;
    let beside_band = (h - band).min(w / aspect);
    let beside_column = h.min((w - column) / aspect);
    if beside_column > beside_band {
        Shape::Column
    } else {
        Shape::Band
    }
}

/// The card's width and its least and greatest heights for `shape` over `over`, with the views
/// showing content of `aspect`: a column as wide as the room the content leaves beside it
/// (between 320 points and 45 % of the area).
#[must_use]
pub fn card_size(shape: Shape, over: Rect, aspect: f32) -> (f32, f32, f32) {
    let most = over.width() - 24.0;
    // The card's frame adds 12 points of margin on each side and its stroke.
    let tall = over.height() - 24.0 - 26.0;
    match shape {
        Shape::Corner => (
            (over.width() * 0.42).clamp(320.0_f32.min(most), 760.0),
            0.0,
            over.height() * 0.55,
        ),
        Shape::Band => (most, 0.0, over.height() * 0.4),
        Shape::Column => {
            // In a narrow view (panels open beside it) 45 % is under 320 points: then 45 %.
            let widest = over.width() * 0.45;
            (
                (over.width() - over.height() * aspect)
                    .clamp(320.0_f32.min(widest), widest)
                    .min(most),
                tall,
                tall,
            )
        }
    }
}

/// The part of `area` a band or a column leaves the views ([`above_band`], [`beside_column`]).
#[must_use]
pub fn free(area: Rect, card: Option<Rect>) -> Rect {
    beside_column(above_band(area, card), card)
}

fn area_key() -> Id {
    Id::unique("pipelens-picture-area")
}

/// [`free`], recording `area` (below the stage's toolbar) as where the card goes next frame:
/// a column runs down beside the pictures, not over the toolbar.
pub fn free_recorded(ctx: &Context, area: Rect, card: Option<Rect>) -> Rect {
    ctx.data_mut(|d| d.insert_temp(area_key(), area));
    free(area, card)
}

/// The area the views laid out in last frame (see [`free_recorded`]).
#[must_use]
pub fn picture_area(ctx: &Context) -> Option<Rect> {
    ctx.data(|d| d.get_temp::<Rect>(area_key()))
}

/// The part of `area` right of the card when the card is a column down it (at least four
/// fifths of its height, at most half its width): a view then lays out all it shows there.
/// `area` otherwise.
#[must_use]
pub fn beside_column(area: Rect, card: Option<Rect>) -> Rect {
    match card.map(|c| c.expand(GAP)).filter(|c| c.intersects(area)) {
        Some(c) if c.height() >= area.height() * 0.8 && c.width() <= area.width() * 0.5 => {
            Rect::from_min_max(egui::pos2(c.right(), area.top()), area.max)
        }
        _ => area,
    }
}

/// The parts of `outer` a subject may be framed in, best first: `outer` itself, then (when
/// `card` lies over it) the part right of the card and the part above it, where not empty.
#[must_use]
pub fn candidates(outer: Rect, card: Option<Rect>) -> Vec<Rect> {
    let mut out = vec![outer];
    if let Some(card) = card.map(|c| c.expand(GAP)).filter(|c| c.intersects(outer)) {
        let right = Rect::from_min_max(egui::pos2(card.right(), outer.top()), outer.max);
        let above = Rect::from_min_max(outer.min, egui::pos2(outer.right(), card.top()));
        out.extend([right, above].into_iter().filter(Rect::is_positive));
    }
    out
}

/// Whether `subject` (on screen) is clear of the card, with at least half the gap between.
#[must_use]
pub fn misses(subject: Rect, card: Option<Rect>) -> bool {
    card.is_none_or(|c| !subject.intersects(c.expand(GAP / 2.0)))
}

/// Where a picture of `size` goes in `outer` so that its `subject` (a part of it, in the
/// picture's own units, y down) lies clear of `card`: as large as it can be, then as near the
/// middle. Each scale, from the whole area's fit down to the fits right of and above the card,
/// is tried centred in the area, shifted right or up just past the card, and centred in the
/// part right of or above it; the first placement whose subject is inside `outer` and clear of
/// the card is taken. A card that leaves no room leaves the picture centred. Returns the
/// picture's rectangle on screen.
#[must_use]
pub fn place(outer: Rect, size: egui::Vec2, subject: Rect, card: Option<Rect>) -> Rect {
    let centred = |r: Rect| super::fit_rect(r, size.x / size.y);
    let whole = centred(outer);
    let parts = candidates(outer, card);
    let mut scales: Vec<f32> = parts.iter().map(|r| centred(*r).width()).collect();
    scales.sort_by(|a, b| b.total_cmp(a));
    let on_screen = |picture: Rect| {
        let k = picture.width() / size.x;
        Rect::from_min_max(
            picture.min + subject.min.to_vec2() * k,
            picture.min + subject.max.to_vec2() * k,
        )
    };
    let fits = |picture: &Rect| {
        let s = on_screen(*picture);
        outer.expand(0.5).contains_rect(s) && misses(s, card)
    };
    for width in scales {
        let picture = Rect::from_center_size(outer.center(), size * (width / size.x));
        let mut tries = vec![picture];
        if let Some(c) = card.map(|c| c.expand(GAP)) {
            let s = on_screen(picture);
            tries.push(picture.translate(egui::vec2(c.right() - s.left(), 0.0)));
            tries.push(picture.translate(egui::vec2(0.0, c.top() - s.bottom())));
        }
        tries.extend(
            parts
                .iter()
                .skip(1)
                .map(|r| Rect::from_center_size(r.center(), picture.size())),
        );
        if let Some(found) = tries.into_iter().find(fits) {
            return found;
        }
    }
    whole
}

/// The part of `area` above the card when the card is a band across it (at least four fifths
/// of its width): a view then lays out all it shows there. `area` otherwise.
#[must_use]
pub fn above_band(area: Rect, card: Option<Rect>) -> Rect {
    match card.map(|c| c.expand(GAP)).filter(|c| c.intersects(area)) {
        Some(c) if c.width() >= area.width() * 0.8 && c.top() > area.top() + 40.0 => {
            Rect::from_min_max(area.min, egui::pos2(area.right(), c.top()))
        }
        _ => area,
    }
}

/// The share of `screen` that `rects` cover: the area of their union, exactly (the rectangles
/// cut the screen into cells along their edges, and each cell is in or out), over the screen's.
#[must_use]
pub fn share(rects: &[Rect], screen: Rect) -> f32 {
    let rects: Vec<Rect> = rects
        .iter()
        .map(|r| r.intersect(screen))
        .filter(|r| r.is_positive())
        .collect();
    let mut xs: Vec<f32> = rects.iter().flat_map(|r| [r.left(), r.right()]).collect();
    let mut ys: Vec<f32> = rects.iter().flat_map(|r| [r.top(), r.bottom()]).collect();
    xs.sort_by(f32::total_cmp);
    ys.sort_by(f32::total_cmp);
    let mut area = 0.0;
    for x in xs.windows(2) {
        for y in ys.windows(2) {
            let centre = egui::pos2((x[0] + x[1]) / 2.0, (y[0] + y[1]) / 2.0);
            if rects.iter().any(|r| r.contains(centre)) {
                area += (x[1] - x[0]) * (y[1] - y[0]);
            }
        }
    }
    area / screen.area().max(1.0)
}

/// A panel in `area` (the depth curve, the mip pyramid) clear of `card`: the part of `area`
/// right of the card when the card covers it, unless that leaves less than a third of it.
#[must_use]
pub fn right_of(area: Rect, card: Option<Rect>) -> Rect {
    match card.map(|c| c.expand(GAP)).filter(|c| c.intersects(area)) {
        Some(c) if area.right() - c.right() >= area.width() / 3.0 => {
            Rect::from_min_max(egui::pos2(c.right(), area.top()), area.max)
        }
        _ => area,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::pos2;

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
        Rect::from_min_max(pos2(x0, y0), pos2(x1, y1))
    }

    /// A view 600 points wide (the shader panel, the inspector and the editor open beside it):
    /// a column is 45 % of it, 270 points, not the usual 320 — and nothing panics.
    #[test]
    fn a_column_in_a_narrow_view_is_45_percent_of_it() {
        let (w, _, _) = card_size(Shape::Column, rect(0.0, 0.0, 600.0, 400.0), 4.0 / 3.0);
        assert_eq!(w, 270.0);
    }

    #[test]
    fn a_subject_the_card_misses_keeps_the_whole_fit() {
        // A 2:1 image filling a 1600 × 800 area; its subject in the top-right quarter.
        let outer = rect(0.0, 0.0, 1600.0, 800.0);
        let size = egui::vec2(200.0, 100.0);
        let card = rect(12.0, 500.0, 700.0, 788.0);
        let subject = rect(120.0, 0.0, 200.0, 50.0);
        assert_eq!(place(outer, size, subject, Some(card)), outer);
        assert_eq!(
            place(outer, size, rect(0.0, 0.0, 200.0, 100.0), None),
            outer
        );
    }

    #[test]
    fn a_covered_subject_moves_before_it_shrinks() {
        let outer = rect(0.0, 0.0, 1600.0, 900.0);
        let size = egui::vec2(100.0, 100.0);
        // A square image in a wide area, its subject the whole image: centred it would meet a
        // card reaching x = 600; shifted right past the card it keeps its size.
        let card = rect(12.0, 500.0, 600.0, 888.0);
        let whole = rect(0.0, 0.0, 100.0, 100.0);
        let placed = place(outer, size, whole, Some(card));
        assert_eq!(placed.size(), egui::vec2(900.0, 900.0));
        assert_eq!(placed.left(), 600.0 + GAP);
        // A card too wide to pass: the image shrinks to the height above it.
        let card = rect(12.0, 500.0, 1500.0, 888.0);
        let placed = place(outer, size, whole, Some(card));
        assert_eq!(placed.size(), egui::Vec2::splat(500.0 - GAP));
        assert!(placed.bottom() <= 500.0 - GAP && placed.top() >= 0.0);
    }

    #[test]
    fn a_panel_under_the_card_moves_right_of_it() {
        let band = rect(0.0, 500.0, 1600.0, 800.0);
        let card = rect(12.0, 400.0, 350.0, 788.0);
        assert_eq!(
            right_of(band, Some(card)),
            rect(350.0 + GAP, 500.0, 1600.0, 800.0)
        );
        assert_eq!(right_of(band, None), band);
        // A card over most of the panel leaves it where it is.
        assert_eq!(right_of(band, Some(rect(0.0, 400.0, 1300.0, 800.0))), band);
    }

    #[test]
    fn a_band_leaves_the_area_above_it() {
        let area = rect(0.0, 60.0, 1366.0, 760.0);
        let band = rect(12.0, 500.0, 1354.0, 748.0);
        assert_eq!(
            above_band(area, Some(band)),
            rect(0.0, 60.0, 1366.0, 500.0 - GAP)
        );
        // A card in the corner is no band.
        let corner = rect(12.0, 500.0, 600.0, 748.0);
        assert_eq!(above_band(area, Some(corner)), area);
        assert_eq!(above_band(area, None), area);
    }

    #[test]
    fn a_column_leaves_the_area_right_of_it() {
        let area = rect(0.0, 60.0, 1366.0, 760.0);
        let column = rect(12.0, 72.0, 452.0, 748.0);
        assert_eq!(
            beside_column(area, Some(column)),
            rect(452.0 + GAP, 60.0, 1366.0, 760.0)
        );
        // A card in the corner, or a band, is no column.
        assert_eq!(
            beside_column(area, Some(rect(12.0, 400.0, 600.0, 748.0))),
            area
        );
        assert_eq!(
            beside_column(area, Some(rect(12.0, 500.0, 1354.0, 748.0))),
            area
        );
    }

    #[test]
    fn a_column_is_as_wide_as_the_room_beside_the_content() {
        let over = rect(0.0, 60.0, 1366.0, 760.0);
        // Two square pictures side by side (aspect 2) over 700 points of height leave 1366 −
        // 1400 < 320: the column's least width; one square leaves 666, more than 45 %.
        assert_eq!(card_size(Shape::Column, over, 2.0).0, 320.0);
        assert_eq!(card_size(Shape::Column, over, 1.0).0, 1366.0 * 0.45);
        let (_, least, most) = card_size(Shape::Column, over, 1.0);
        assert_eq!((least, most), (650.0, 650.0));
        assert_eq!(card_size(Shape::Band, over, 1.0).0, 1342.0);
    }

    #[test]
    fn a_wide_picture_takes_a_band_and_a_square_one_a_column() {
        let over = rect(0.0, 60.0, 1366.0, 760.0);
        // The corner card's words: 570 × 400 square points.
        let words = 570.0 * 400.0;
        // Two 5:4 pictures side by side (2.5) lack height: a band about 210 points high
        // leaves them 490 high, a column of 320 points 407.
        assert_eq!(band_or_column(over, 2.5, words), Shape::Band);
        // A 16:10 image keeps 636 beside a column, 490 over a band.
        assert_eq!(band_or_column(over, 1.6, words), Shape::Column);
        assert_eq!(band_or_column(over, 1.0, words), Shape::Column);
        assert_eq!(band_or_column(over, f32::INFINITY, words), Shape::Band);
    }

    #[test]
    fn a_card_that_leaves_no_room_leaves_the_area() {
        let outer = rect(0.0, 0.0, 400.0, 300.0);
        let card = rect(-10.0, -10.0, 410.0, 310.0);
        let size = egui::vec2(150.0, 100.0);
        let placed = place(outer, size, rect(0.0, 0.0, 150.0, 100.0), Some(card));
        assert_eq!(placed, super::super::fit_rect(outer, 1.5));
    }
}
