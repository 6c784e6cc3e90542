//! Room for the subject among a view's own cards. A view draws words over its picture — the
//! space's name and buttons at the top-left, the stage's matrix at the top-right, the legend —
//! and the narration card may lie over it too. The subject is framed in the largest rectangle
//! of its own shape that meets none of them, so that no card covers what the step is about
//! and the cards can be as large as the room reads them.

use egui::{Rect, pos2};

/// The gap kept between a card and the subject's square, in points.
const GAP: f32 = 8.0;

/// The largest rectangle of `aspect` (width / height) in `area` that overlaps none of
/// `cards` (each kept [`GAP`] away), as near the middle of `area` as the cards allow; `None`
/// when the cards leave no room at all. A subject framed by its box, not by its sphere, goes
/// where its shape has the most room: a standing figure in a tall gap, a wide one in a band.
///
/// Every maximal free rectangle has its sides on the area's or the cards' edges, so the
/// rectangles between two of those x's and two of those y's that meet no card hold the
/// answer: the largest fit is `h = min(w / aspect, h)` of the best one, slid along its
/// longer side toward the area's centre.
#[must_use]
pub fn free_fit(area: Rect, cards: &[Rect], aspect: f32) -> Option<Rect> {
    let aspect = if aspect.is_finite() && aspect > 0.0 {
        aspect
    } else {
        1.0
    };
    let cards: Vec<Rect> = cards
        .iter()
        .map(|c| c.expand(GAP).intersect(area))
        .filter(|c| c.is_positive())
        .collect();
    let edges = |ends: fn(&Rect) -> [f32; 2]| {
        let mut v: Vec<f32> = std::iter::once(ends(&area))
            .chain(cards.iter().map(ends))
            .flatten()
            .collect();
        v.sort_by(f32::total_cmp);
        v.dedup();
        v
    };
    let xs = edges(|r| [r.left(), r.right()]);
    let ys = edges(|r| [r.top(), r.bottom()]);
    let mut best: Option<(f32, f32, Rect)> = None;
    for (i, &x0) in xs.iter().enumerate() {
        for &x1 in &xs[i + 1..] {
            for (j, &y0) in ys.iter().enumerate() {
                for &y1 in &ys[j + 1..] {
                    let free = Rect::from_min_max(pos2(x0, y0), pos2(x1, y1));
                    if cards.iter().any(|c| c.intersect(free).is_positive()) {
                        continue;
                    }
                    let fit = centred_fit(free, aspect, area.center());
                    let (height, off) = (fit.height(), fit.center().distance(area.center()));
                    let better = best
                        .is_none_or(|(s, o, _)| height > s + 0.5 || (height > s - 0.5 && off < o));
                    if better {
                        best = Some((height, off, fit));
                    }
                }
            }
        }
    }
    best.map(|(_, _, fit)| fit)
        .filter(|s| s.width() >= 1.0 && s.height() >= 1.0)
}

/// The largest rectangle of `aspect` in `free`, as near `towards` as it stays inside.
fn centred_fit(free: Rect, aspect: f32, towards: egui::Pos2) -> Rect {
    let height = (free.width() / aspect).min(free.height());
    let size = egui::vec2(height * aspect, height);
    let half = size / 2.0;
    let clamp =
        |v: f32, lo: f32, hi: f32, half: f32| v.clamp(lo + half, (hi - half).max(lo + half));
    let c = pos2(
        clamp(towards.x, free.left(), free.right(), half.x),
        clamp(towards.y, free.top(), free.bottom(), half.y),
    );
    Rect::from_center_size(c, size)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest square: a fit of aspect 1.
    fn free_square(area: Rect, cards: &[Rect]) -> Option<Rect> {
        free_fit(area, cards, 1.0)
    }

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
        Rect::from_min_max(pos2(x0, y0), pos2(x1, y1))
    }

    #[test]
    fn with_no_card_the_square_is_the_narrow_side_in_the_middle() {
        let s = free_square(rect(0.0, 0.0, 800.0, 600.0), &[]).expect("room");
        assert_eq!(s, rect(100.0, 0.0, 700.0, 600.0));
    }

    #[test]
    fn a_card_at_the_top_right_leaves_the_room_below_or_beside_it() {
        // A 484 × 675 view, a card 450 × 180 at its top-right: below the card (y ≥ 198)
        // a square of 477 fits; left of it only 26.
        let area = rect(0.0, 0.0, 484.0, 675.0);
        let card = rect(24.0, 10.0, 474.0, 190.0);
        let s = free_square(area, &[card]).expect("room");
        assert!((s.width() - 477.0).abs() < 0.01, "{s:?}");
        assert!(s.top() >= 198.0 - 0.01 && s.bottom() <= 675.01, "{s:?}");
        // A legend down the right below the card as well: the square keeps left of it.
        let legend = rect(294.0, 198.0, 474.0, 408.0);
        let s = free_square(area, &[card, legend]).expect("room");
        // Left of the legend: 286 wide (0 … 286) and 477 high; under it: 259 high.
        assert!((s.width() - 286.0).abs() < 0.01, "{s:?}");
        assert!(!s.intersects(card) && !s.intersects(legend));
    }

    #[test]
    fn a_tall_subject_goes_to_the_tall_gap() {
        // A 1000 × 600 view with a card 300 wide down its left (0 … 300) and a band 600 wide
        // across the top 300 of the rest (300 … 900): left free are a column 100 × 600 at the
        // right (900 … 1000, less the gaps) and the lower right 700 × 300. A square fits
        // 300 − 8 (the gap below the band) = 292 in the lower right; a figure twice as tall
        // as wide is 292 tall there too, but 600 tall would need 300 wide, and the column
        // is only 100 − 8 = 92 wide: it is 184 tall there. In the lower right, 292.
        let area = rect(0.0, 0.0, 1000.0, 600.0);
        let cards = [rect(0.0, 0.0, 300.0, 600.0), rect(300.0, 0.0, 900.0, 300.0)];
        let tall = free_fit(area, &cards, 0.5).expect("room");
        assert!((tall.height() - 292.0).abs() < 0.01, "{tall:?}");
        assert!((tall.width() - 146.0).abs() < 0.01, "{tall:?}");
        // Without the band, the whole height beside the left card: 600 tall, 300 wide.
        let tall = free_fit(area, &cards[..1], 0.5).expect("room");
        assert!((tall.height() - 600.0).abs() < 0.01, "{tall:?}");
        assert!(
            tall.left() >= 308.0 - 0.01 && tall.right() <= 1000.01,
            "{tall:?}"
        );
        // A wide band (aspect 4) there is 692 / 4 = 173 tall.
        let wide = free_fit(area, &cards[..1], 4.0).expect("room");
        assert!((wide.width() - 692.0).abs() < 0.01, "{wide:?}");
        assert!((wide.height() - 173.0).abs() < 0.01, "{wide:?}");
    }

    #[test]
    fn cards_that_fill_the_area_leave_no_square() {
        let area = rect(0.0, 0.0, 100.0, 100.0);
        assert!(free_square(area, &[rect(-5.0, -5.0, 105.0, 105.0)]).is_none());
    }
}
