//! Where the image of a buffer is on screen: the viewport that maps image pixels to screen
//! points and back, and the split of the view between the image and the panel beside or below
//! it (the depth curve, the mip pyramid).

use egui::{Pos2, Rect, Vec2};
use pipeline::capture::FrameCapture;

/// Where the image is on screen: `centre` (image pixels) at the middle of `rect`, `zoom` screen
/// points per image pixel.
pub(super) struct ImageViewport {
    /// The view's area on screen.
    pub rect: Rect,
    /// The image point (pixels, y down) at the area's centre.
    pub centre: Vec2,
    /// Screen points per image pixel.
    pub zoom: f32,
    /// The image's size in pixels.
    pub size: Vec2,
}

impl ImageViewport {
    /// Window coordinates (y up) to the screen.
    pub fn window_to_screen(&self, p: [f64; 2]) -> Pos2 {
        self.to_screen([p[0] as f32, self.size.y - p[1] as f32])
    }

    /// Image coordinates (pixels, y down) to the screen.
    pub fn to_screen(&self, p: [f32; 2]) -> Pos2 {
        self.rect.center() + (Vec2::new(p[0], p[1]) - self.centre) * self.zoom
    }

    /// The screen to image coordinates.
    pub fn to_image(&self, s: Pos2) -> Vec2 {
        self.centre + (s - self.rect.center()) / self.zoom
    }

    /// The visible image pixels: columns `c0..c1`, rows `r0..r1`.
    pub fn visible(&self) -> (u32, u32, u32, u32) {
        let (a, b) = (self.to_image(self.rect.min), self.to_image(self.rect.max));
        (
            a.x.floor().clamp(0.0, self.size.x) as u32,
            a.y.floor().clamp(0.0, self.size.y) as u32,
            b.x.ceil().clamp(0.0, self.size.x) as u32,
            b.y.ceil().clamp(0.0, self.size.y) as u32,
        )
    }

    /// The window pixel (x, y up) under a screen point, if it is on the image.
    pub fn window_pixel(&self, pos: Pos2, capture: &FrameCapture) -> Option<(u32, u32)> {
        let ip = self.to_image(pos);
        (ip.x >= 0.0 && ip.y >= 0.0 && ip.x < self.size.x && ip.y < self.size.y)
            .then(|| (ip.x as u32, capture.grid().row(ip.y as u32)))
    }
}

/// Where the image goes in `full`, and the depth curve or the mip pyramid when `extra`: beside
/// the image when the view is wider than the image (the space would be empty otherwise), below it
/// when it is taller.
pub(super) fn layout(full: Rect, capture: &FrameCapture, extra: bool) -> (Rect, Option<Rect>) {
    let aspect = capture.width() as f32 / capture.height() as f32;
    if !extra {
        (full, None)
    } else if full.width() > full.height() * aspect * 1.15 {
        let w = (full.width() - full.height() * aspect).max(full.width() * 0.3);
        let image = Rect::from_min_max(full.min, egui::pos2(full.right() - w - 6.0, full.bottom()));
        (
            image,
            Some(Rect::from_min_max(
                egui::pos2(full.right() - w, full.top()),
                full.max,
            )),
        )
    } else {
        let h = full.height() * 0.32;
        let image = Rect::from_min_max(full.min, egui::pos2(full.right(), full.bottom() - h - 6.0));
        (
            image,
            Some(Rect::from_min_max(
                egui::pos2(full.left(), full.bottom() - h),
                full.max,
            )),
        )
    }
}

/// Where a picture of `size` goes to cover `outer` (a phone's tall, narrow view): as large as
/// filling it, but no larger than keeps `subject` (in the picture's units, y down) whole in it,
/// nor smaller than the whole picture fitted; the subject in the middle, then moved so that the
/// picture leaves no margin it can cover.
#[must_use]
pub fn cover(outer: Rect, size: Vec2, subject: Rect) -> Rect {
    let across = outer.width() / size.x;
    let down = outer.height() / size.y;
    let most =
        (outer.width() / subject.width().max(1.0)).min(outer.height() / subject.height().max(1.0));
    let k = across.max(down).min(most).max(across.min(down));
    let picture = size * k;
    let min = outer.center() - subject.center().to_vec2() * k;
    // Along each axis: centred when the picture is smaller than the view, else kept over it.
    let place = |at: f32, len: f32, lo: f32, hi: f32| {
        if len <= hi - lo {
            lo + (hi - lo - len) / 2.0
        } else {
            at.clamp(hi - len, lo)
        }
    };
    Rect::from_min_size(
        egui::pos2(
            place(min.x, picture.x, outer.left(), outer.right()),
            place(min.y, picture.y, outer.top(), outer.bottom()),
        ),
        picture,
    )
}

#[cfg(test)]
mod tests {
    use super::cover;
    use egui::{Rect, pos2, vec2};

    /// A tall view (a phone's): a picture whose subject is small fills the view's height, the
    /// subject whole and in the middle; one whose subject spans it is as wide as the view.
    #[test]
    fn a_picture_covers_a_tall_view_with_its_subject_whole() {
        let view = Rect::from_min_size(pos2(0.0, 60.0), vec2(390.0, 530.0));
        let size = vec2(32.0, 32.0);
        let small = Rect::from_min_max(pos2(8.0, 6.0), pos2(24.0, 26.0));
        let p = cover(view, size, small);
        assert!((p.height() - 530.0).abs() < 0.5, "{p:?}");
        let k = p.width() / size.x;
        let on_screen = Rect::from_min_max(
            p.min + small.min.to_vec2() * k,
            p.min + small.max.to_vec2() * k,
        );
        assert!(view.contains_rect(on_screen), "{on_screen:?} in {view:?}");
        assert!((on_screen.center().x - view.center().x).abs() < 1.0);
        let wide = vec2(640.0, 400.0);
        let all = Rect::from_min_size(pos2(0.0, 0.0), wide);
        let p = cover(view, wide, all);
        assert!(
            (p.width() - 390.0).abs() < 0.5 && view.contains_rect(p),
            "{p:?}"
        );
    }
}
