//! How a geometry view frames its subject: the box of what it frames, kept while the step,
//! the space and the orbit stay the same, and the room of the subject's shape that the view's
//! cards leave.

use egui::{Pos2, Rect, Vec2};
use glam::Vec3;

use super::legend;
use crate::vocabulary::Space;

/// The step entered, the space, the orbit's yaw and pitch (their bits): while they stay the
/// same, what was framed stays framed.
pub(super) type Key = (u64, Space, u32, u32);

/// What a geometry view frames, kept while the step, the space and the orbit stay the same
/// (`key`), so that a moving subject (an arm turning, a joint swinging) stays inside while
/// the picture keeps still: the box `lo`…`hi` (in the space) of every point framed since, whose
/// sphere the camera frames in a square ([`crate::spaces::framing`] of aspect 1), and the box
/// `min`…`max` those points filled in that camera's normalized device coordinates (x right,
/// y up, the sphere within ±1) since the space's box last grew.
#[derive(Clone, Copy, PartialEq)]
pub(super) struct SubjectBox {
    key: Key,
    lo: Vec3,
    hi: Vec3,
    min: glam::Vec2,
    max: glam::Vec2,
}

impl SubjectBox {
    /// The camera that frames `points` together with what was framed `before` (when under the
    /// same `key`), and what it frames; none when there is nothing finite to frame.
    pub(super) fn framing(
        points: &[Vec3],
        before: Option<Self>,
        key: Key,
    ) -> Option<(glam::Mat4, Self)> {
        let before = before.filter(|b| b.key == key);
        let finite = || points.iter().copied().filter(|p| p.is_finite());
        let (mut lo, mut hi) = (finite().reduce(Vec3::min)?, finite().reduce(Vec3::max)?);
        if let Some(b) = before {
            (lo, hi) = (lo.min(b.lo), hi.max(b.hi));
        }
        let mut next = Self {
            key,
            lo,
            hi,
            min: glam::Vec2::splat(f32::INFINITY),
            max: glam::Vec2::splat(f32::NEG_INFINITY),
        };
        let (centre, radius) = next.sphere();
        let (yaw, pitch) = (f32::from_bits(key.2), f32::from_bits(key.3));
        let m = crate::spaces::framing(centre, radius, yaw, pitch, 1.0)?;
        // The same camera as before (the box did not grow): what it saw still counts.
        if let Some(b) = before.filter(|b| b.lo == lo && b.hi == hi) {
            (next.min, next.max) = (b.min, b.max);
        }
        for p in finite() {
            let c = m * p.extend(1.0);
            if c.w > 1e-6 && c.is_finite() {
                let n = glam::Vec2::new(c.x, c.y) / c.w;
                (next.min, next.max) = (next.min.min(n), next.max.max(n));
            }
        }
        if !next.min.cmple(next.max).all() {
            // Nothing in front of the camera: the sphere's whole square.
            (next.min, next.max) = (glam::Vec2::splat(-1.0), glam::Vec2::splat(1.0));
        }
        Some((m, next))
    }

    /// The sphere framed: around the box's middle, reaching its corners (at least 10⁻³).
    pub(super) fn sphere(self) -> (Vec3, f32) {
        let centre = (self.lo + self.hi) / 2.0;
        (centre, ((self.hi - self.lo).length() / 2.0).max(1e-3))
    }

    /// The box framed: a margin of 4 % a side, at least an eighth of the sphere's square
    /// each way (a lone vertex, a plane seen edge-on), and no more than four times as long
    /// as it is wide (the rest of the picture around a thin subject stays in sight).
    fn framed(self) -> (glam::Vec2, glam::Vec2) {
        let centre = (self.min + self.max) / 2.0;
        let size = ((self.max - self.min) * 1.08).max(glam::Vec2::splat(0.25));
        let size = size.max(glam::Vec2::new(size.y, size.x) / 4.0);
        (centre, size)
    }

    /// Width over height of the framed box.
    pub(super) fn aspect(self) -> f32 {
        let (_, size) = self.framed();
        size.x / size.y
    }

    /// The square the camera's picture (NDC ±1) is drawn in so that the framed box fills
    /// `frame` (a rectangle of the box's aspect): side q = 2·frame.w / box.w, and the box's
    /// centre (cx, cy) on the frame's centre — the square's centre at frame.cx − cx·q/2,
    /// frame.cy + cy·q/2 (screen y runs down).
    pub(super) fn square_for(self, frame: Rect) -> Rect {
        let (centre, size) = self.framed();
        let q = (2.0 * frame.width() / size.x).min(2.0 * frame.height() / size.y);
        let c = Pos2::new(
            frame.center().x - centre.x * q / 2.0,
            frame.center().y + centre.y * q / 2.0,
        );
        Rect::from_center_size(c, Vec2::splat(q))
    }
}

/// Where the subject's box is framed: the largest rectangle of its `aspect` in `rect` clear of
/// the view's own cards drawn last frame (`own`: the header, the matrix card, the legend) and
/// of the narration card, with the legend where it leaves the largest one — one item a row
/// below the matrix card or at the bottom-right, or a strip along the foot — of the places the
/// narration card leaves in sight; a legend folded into a chip (a small screen's) only at the
/// foot, the chip at the bottom-right. Returns the rectangle and the legend's place and items a
/// row; reports the share of the rectangle the narration card left.
pub(super) fn clear_of_cards(
    ctx: &egui::Context,
    rect: Rect,
    own: &[Rect],
    legend: &legend::Legend,
    aspect: f32,
) -> (Rect, (Rect, usize)) {
    let narration = super::super::card_placement::narration_card(ctx);
    let header = own.first().copied().unwrap_or(Rect::NOTHING);
    let card = own.get(1).copied().unwrap_or(Rect::NOTHING);
    let right = rect.right() - 10.0;
    let column = legend.size(1);
    let top = [card, header]
        .iter()
        .filter(|r| r.is_positive() && r.right() > right - column.x)
        .map(|r| r.bottom() + 8.0)
        .fold(rect.top() + 10.0, f32::max);
    let per_row = legend.per_row(rect.width() - 20.0);
    let strip = legend.size(per_row);
    let all_places = [
        (
            Rect::from_min_size(Pos2::new(right - column.x, top), column),
            1,
        ),
        (
            Rect::from_min_size(Pos2::new(right, rect.bottom() - 10.0) - column, column),
            1,
        ),
        (
            Rect::from_min_size(Pos2::new(right, rect.bottom() - 10.0) - strip, strip),
            per_row,
        ),
    ];
    // A folded legend's chip is always at the bottom-right corner, where a student finds it
    // from step to step; opened, the legend grows from there (a column or the strip along the
    // foot), so that the chip stays under the finger.
    let places = match legend.chip() {
        Some(false) => &all_places[1..2],
        Some(true) => &all_places[1..],
        None => &all_places[..],
    };
    let square = |legend: Rect, narration: Option<Rect>| {
        let mut all = vec![header, card, legend];
        all.extend(narration);
        super::super::overlays::free_fit(rect, &all, aspect).unwrap_or(rect)
    };
    // A place under the narration card would hide the legend (the tour's NDC step at 1920
    // points with the inspector open); where every place is, the largest square decides alone.
    let mut clear: Vec<_> = places
        .iter()
        .filter(|p| narration.is_none_or(|n| !n.intersects(p.0)))
        .copied()
        .collect();
    if clear.is_empty() {
        clear = places.to_vec();
    }
    let (frame, place) = clear
        .iter()
        .map(|p| (square(p.0, narration), *p))
        .reduce(|best, next| {
            if next.0.height() > best.0.height() + 0.5 {
                next
            } else {
                best
            }
        })
        .unwrap_or((rect, places[0]));
    let alone = square(place.0, None);
    super::super::card_placement::report_kept(ctx, (frame.area() / alone.area().max(1.0)).min(1.0));
    (frame, place)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(step: u64) -> Key {
        (step, Space::World, 35f32.to_bits(), 22f32.to_bits())
    }

    fn boxed(min: [f32; 2], max: [f32; 2]) -> SubjectBox {
        SubjectBox {
            key: key(1),
            lo: Vec3::ZERO,
            hi: Vec3::ONE,
            min: min.into(),
            max: max.into(),
        }
    }

    #[test]
    fn a_box_twice_as_tall_as_wide_fills_a_frame_of_its_shape() {
        // The box ±0.5 × ±1 with its 4 % margins is 1.08 × 2.16 (aspect 0.5); in a frame
        // 100 × 200 at the origin the square is 2·100/1.08 = 185.19 a side, centred on the
        // frame.
        let b = boxed([-0.5, -1.0], [0.5, 1.0]);
        assert!((b.aspect() - 0.5).abs() < 1e-6);
        let q = b.square_for(Rect::from_min_size(Pos2::ZERO, Vec2::new(100.0, 200.0)));
        assert!((q.width() - 185.185).abs() < 0.01, "{q:?}");
        assert!(
            (q.center() - Pos2::new(50.0, 100.0)).length() < 0.01,
            "{q:?}"
        );
    }

    #[test]
    fn an_off_centre_box_is_moved_onto_the_frame() {
        // The box 0 … 1 both ways, centred at NDC (0.5, 0.5), in a frame 100 × 100: the
        // square 185.19 a side has its centre at 50 − 0.5·92.59 = 3.70 across and
        // 50 + 0.5·92.59 = 96.30 down, which puts NDC (0.5, 0.5) on (50, 50).
        let b = boxed([0.0, 0.0], [1.0, 1.0]);
        let q = b.square_for(Rect::from_min_size(Pos2::ZERO, Vec2::splat(100.0)));
        assert!(
            (q.center() - Pos2::new(3.70, 96.30)).length() < 0.01,
            "{q:?}"
        );
    }

    #[test]
    fn a_thin_subject_is_framed_no_longer_than_four_to_one() {
        // A line ±1 across and nothing up: 2.16 wide, at least 2.16 / 4 = 0.54 high.
        let b = boxed([-1.0, 0.0], [1.0, 0.0]);
        assert!((b.aspect() - 4.0).abs() < 1e-5, "{}", b.aspect());
    }

    #[test]
    fn what_was_framed_stays_framed_until_the_key_changes() {
        let cube: Vec<Vec3> = (0..8)
            .map(|k| Vec3::new((k & 1) as f32, (k >> 1 & 1) as f32, (k >> 2 & 1) as f32))
            .collect();
        let (m, first) = SubjectBox::framing(&cube, None, key(1)).expect("framed");
        // A frame later the subject is one corner: the camera and the box are the same.
        let (m2, again) = SubjectBox::framing(&cube[..1], Some(first), key(1)).expect("framed");
        assert_eq!(m, m2);
        assert!(again == first);
        // A corner moves out: the box grows to hold it and the cube.
        let out = [Vec3::new(3.0, 0.0, 0.0)];
        let (_, grown) = SubjectBox::framing(&out, Some(first), key(1)).expect("framed");
        assert_eq!((grown.lo, grown.hi), (Vec3::ZERO, Vec3::new(3.0, 1.0, 1.0)));
        // A new step frames only what it shows.
        let (_, fresh) = SubjectBox::framing(&cube[..1], Some(grown), key(2)).expect("framed");
        assert_eq!((fresh.lo, fresh.hi), (Vec3::ZERO, Vec3::ZERO));
        assert!(SubjectBox::framing(&[Vec3::NAN], None, key(1)).is_none());
    }
}
