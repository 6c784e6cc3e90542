//! Words drawn over pictures: their size (larger in classroom mode) and fonts, labels on a dark
//! box placed clear of the subject, the note on a dim term's gain, and the rect a picture of a
//! given aspect fills.

use egui::{Color32, Pos2, Rect};

/// How much larger the words drawn over pictures (labels, legends, cards) are than normal: 1,
/// or 1.6 in classroom mode — the body text's size over its normal 15 points.
#[must_use]
pub fn picture_scale(ctx: &egui::Context) -> f32 {
    ctx.global_style()
        .text_styles
        .get(&egui::TextStyle::Body)
        .map_or(1.0, |f| f.size / 15.0)
}

/// The size on screen of words of `size` normal points over a picture: scaled with the body
/// text, and in classroom mode never below the body (the narration's own size), so that a
/// label reads from the back of the room as the narration does.
fn picture_size(ctx: &egui::Context, size: f32) -> f32 {
    let scale = picture_scale(ctx);
    if scale > 1.0 {
        size.max(15.0) * scale
    } else {
        size * scale
    }
}

/// A proportional font of `size` normal points for words drawn over a picture.
#[must_use]
pub fn picture_font(ctx: &egui::Context, size: f32) -> egui::FontId {
    egui::FontId::proportional(picture_size(ctx, size))
}

/// A monospace font of `size` normal points for numbers drawn over a picture.
#[must_use]
pub fn picture_mono(ctx: &egui::Context, size: f32) -> egui::FontId {
    egui::FontId::monospace(picture_size(ctx, size))
}

/// Says over a picture that a dim lighting term is drawn `gain` times brighter than its values
/// (`vocabulary::gain_note`), in the accent colour at `at`, on one line at most `width` wide
/// (the picture's, less a margin): its type shrunk to fit, down to two thirds of its size, and
/// wrapped beyond; nothing when it is drawn as it is. Returns its box.
pub fn draw_gain_note(
    painter: &egui::Painter,
    (at, align, width): (Pos2, egui::Align2, f32),
    kind: pipeline::buffers::BufferKind,
    gain: f32,
    lang: crate::vocabulary::Lang,
) -> Option<Rect> {
    let note = crate::vocabulary::gain_note(kind, gain, lang)?;
    let color = egui::Color32::from_rgb(255, 214, 120);
    let mut font = picture_font(painter.ctx(), 15.0);
    let one_line = painter
        .layout_no_wrap(note.clone(), font.clone(), color)
        .size()
        .x;
    if one_line > width {
        font.size *= (width / one_line).max(2.0 / 3.0);
    }
    Some(wrapped_label(
        painter, at, align, &note, &font, color, width,
    ))
}

/// Text on a dark translucent box, legible over any picture; returns its rect.
pub fn label_with_background(
    painter: &egui::Painter,
    at: Pos2,
    align: egui::Align2,
    text: &str,
    font: &egui::FontId,
    color: Color32,
) -> Rect {
    wrapped_label(painter, at, align, text, font, color, f32::INFINITY)
}

/// [`label_with_background`] wrapped to lines at most `width` wide.
pub fn wrapped_label(
    painter: &egui::Painter,
    at: Pos2,
    align: egui::Align2,
    text: &str,
    font: &egui::FontId,
    color: Color32,
    width: f32,
) -> Rect {
    let galley = painter.layout(text.to_owned(), font.clone(), color, width);
    boxed_galley(painter, at, align, galley, color)
}

/// Text already laid out, on its dark box anchored at `at`; the box. The box lets 8 % of the
/// picture through: over white that is grey 20 (relative luminance 0.007), on which a colour
/// with a luminance of 0.21 or more — every palette colour's words — keeps WCAG AA's 4.5:1
/// (`(L + 0.05)/(0.007 + 0.05)`); at two thirds opaque it was grey 85, on which the x axis's red
/// was 1.6:1.
pub fn boxed_galley(
    painter: &egui::Painter,
    at: Pos2,
    align: egui::Align2,
    galley: std::sync::Arc<egui::Galley>,
    color: Color32,
) -> Rect {
    let rect = align.anchor_size(at, galley.size()).expand(3.0);
    painter.rect_filled(rect, 3.0, Color32::from_black_alpha(235));
    painter.galley(rect.min + egui::vec2(3.0, 3.0), galley, color);
    rect
}

/// Where a box (a legend) goes in `view`, and which of its shapes `sizes` (in the order they
/// are preferred: a wide one, then narrower ones) it takes: each shape in the corners of
/// `view` 10 points in, then 4 points in — top-left, top-right, bottom-left, bottom-right — the
/// first place that fits in `view`, covers nothing in `avoid` (the subject on screen) and is
/// not under `card` (the narration card, which would hide it); else the one least out of the
/// view (a shape wider than a phone's view is cut at its edge), then least under the card, then
/// covering the least of the subject (the first of those). Returns the shape's index and its
/// box.
#[must_use]
pub fn clear_corner(
    sizes: &[egui::Vec2],
    view: Rect,
    (avoid, card): (&[Rect], Option<Rect>),
) -> (usize, Rect) {
    let places = sizes.iter().enumerate().flat_map(|(k, size)| {
        [10.0, 4.0].into_iter().flat_map(move |inset| {
            let inner = view.shrink(inset);
            [
                egui::Align2::LEFT_TOP,
                egui::Align2::RIGHT_TOP,
                egui::Align2::LEFT_BOTTOM,
                egui::Align2::RIGHT_BOTTOM,
            ]
            .map(|a| (k, a.align_size_within_rect(*size, inner)))
        })
    });
    // The covered areas are never negative: the first minimum is the first clear place, if any.
    places
        .map(|(k, r)| {
            let outside = r.area() - r.intersect(view).area();
            (
                k,
                r,
                [
                    outside,
                    covered_area(r, card.as_slice()),
                    covered_area(r, avoid),
                ],
            )
        })
        // In that order: out of the view, under the card, over the subject (areas, never NaN).
        .min_by(|a, b| a.2.partial_cmp(&b.2).unwrap_or(std::cmp::Ordering::Equal))
        .map_or((0, view), |(k, r, _)| (k, r))
}

/// How much of the rects in `avoid` the rect `r` covers (their overlaps' areas summed).
#[must_use]
fn covered_area(r: Rect, avoid: &[Rect]) -> f32 {
    avoid
        .iter()
        .filter(|a| r.intersects(**a))
        .map(|a| r.intersect(*a).area())
        .sum()
}

/// `r` moved the least distance that puts it inside `view` (where it fits).
#[must_use]
pub fn moved_inside(r: Rect, view: Rect) -> Rect {
    r.translate(egui::vec2(
        (view.left() - r.left()).max(0.0) - (r.right() - view.right()).max(0.0),
        (view.top() - r.top()).max(0.0) - (r.bottom() - view.bottom()).max(0.0),
    ))
}

/// Where to put a label of `size` pointing at `anchor` so that it covers nothing in `avoid`
/// (first the subject on screen, then the cards and legends over the picture) and stays inside
/// `view`: the first place around the anchor, a little farther each round, that does neither;
/// else the first such place that covers the subject but no card (the label has its own dark
/// box: a label far from its point, with a leader line across the picture, reads worse); else
/// the view's corner farthest from the subject that covers nothing else; else the place along
/// the view's edges nearest the anchor that covers nothing else; else the corner farthest from
/// the subject.
#[must_use]
pub fn place_label(anchor: Pos2, size: egui::Vec2, avoid: &[Rect], view: Rect) -> Rect {
    let around = |avoid: &[Rect]| {
        let clear = |r: &Rect| avoid.iter().all(|a| !r.intersects(*a));
        for step in 1..=8 {
            let d = 12.0 * step as f32;
            for dir in [
                egui::vec2(1.0, -1.0),
                egui::vec2(1.0, 1.0),
                egui::vec2(-1.0, -1.0),
                egui::vec2(-1.0, 1.0),
                egui::vec2(0.0, -1.0),
                egui::vec2(0.0, 1.0),
            ] {
                let r = Rect::from_center_size(anchor + dir * (d + size.length() / 2.0), size);
                if view.contains_rect(r) && clear(&r) {
                    return Some(r);
                }
            }
        }
        None
    };
    if let Some(r) = around(avoid).or_else(|| around(avoid.get(1..).unwrap_or_default())) {
        return r;
    }
    let subject = avoid.first().map_or(view.center(), Rect::center);
    let mut corners: Vec<Rect> = [
        view.left_top(),
        view.right_top(),
        view.left_bottom(),
        view.right_bottom(),
    ]
    .into_iter()
    .map(|corner| moved_inside(Rect::from_center_size(corner, size), view))
    .collect();
    corners.sort_by(|a, b| {
        b.center()
            .distance(subject)
            .total_cmp(&a.center().distance(subject))
    });
    let clear_of_cards = |r: &Rect| avoid.iter().skip(1).all(|a| !r.intersects(*a));
    if let Some(r) = corners.iter().find(|r| clear_of_cards(r)) {
        return *r;
    }
    // Every corner has a card (a small view: the header, the matrix card, the legend, the
    // narration): along the edges, the free place nearest the anchor.
    let steps = 24;
    let along = |from: Pos2, to: Pos2| {
        (0..=steps).map(move |k| {
            let at = from + (to - from) * (k as f32 / steps as f32);
            moved_inside(Rect::from_center_size(at, size), view)
        })
    };
    let (lt, rt, lb, rb) = (
        view.left_top(),
        view.right_top(),
        view.left_bottom(),
        view.right_bottom(),
    );
    along(lt, rt)
        .chain(along(lb, rb))
        .chain(along(lt, lb))
        .chain(along(rt, rb))
        .filter(clear_of_cards)
        .min_by(|a, b| {
            let d = |r: &Rect| r.center().distance(anchor);
            d(a).total_cmp(&d(b))
        })
        .or(corners.first().copied())
        .unwrap_or(view)
}

/// The largest rectangle of `aspect` (width/height) centred in `outer`.
#[must_use]
pub fn fit_rect(outer: Rect, aspect: f32) -> Rect {
    let (w, h) = (outer.width(), outer.height());
    let size = if w / h > aspect {
        egui::vec2(h * aspect, h)
    } else {
        egui::vec2(w, w / aspect)
    };
    Rect::from_center_size(outer.center(), size)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
        Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1))
    }

    /// A legend's wide shape where it fits, its narrow one where the view is narrower than the
    /// wide one (a phone's pixel view: the wide one was cut at the edge), and where neither
    /// fits the one least out of the view. Worked by hand: shapes 240×50 and 120×90; a 180-wide
    /// view holds the narrow one at its top-left corner 10 in; in a 100-wide view the wide one
    /// is 7200 out at best (4 in), the narrow one 2160 (4 in: 120·90 − 96·90).
    #[test]
    fn a_legend_takes_the_shape_that_fits_in_the_view() {
        let sizes = [egui::vec2(240.0, 50.0), egui::vec2(120.0, 90.0)];
        let fits = |view: Rect| clear_corner(&sizes, view, (&[], None));
        assert_eq!(
            fits(rect(0.0, 0.0, 400.0, 300.0)),
            (0, rect(10.0, 10.0, 250.0, 60.0))
        );
        assert_eq!(
            fits(rect(0.0, 0.0, 180.0, 300.0)),
            (1, rect(10.0, 10.0, 130.0, 100.0))
        );
        assert_eq!(
            fits(rect(0.0, 0.0, 100.0, 300.0)),
            (1, rect(4.0, 4.0, 124.0, 94.0))
        );
    }
}
