//! Drawing in 3-D with egui: a camera that projects points onto the view (it draws; it is not
//! part of the pipeline being taught), and the lights of a scene drawn where they are.

use egui::{Pos2, Rect};
use glam::{Mat4, Vec3, Vec4};

use super::palette;
use super::words::{label_with_background, picture_font};
use crate::vocabulary::Lang;

/// A camera for drawing 3-D lines with egui: points go through `m = P·V` and the viewport of
/// `rect`. It draws; it is not part of the pipeline being taught.
pub struct Projector {
    /// Projection times view.
    pub m: Mat4,
    /// Where on screen.
    pub rect: Rect,
    /// Magnification about the rect's centre, then a shift (screen points): zooming and
    /// panning the picture as a photograph.
    pub zoom: f32,
    /// The shift after the magnification.
    pub pan: egui::Vec2,
}

impl Projector {
    /// The screen position of `p`, if it is in front of the camera.
    #[must_use]
    pub fn project(&self, p: Vec3) -> Option<Pos2> {
        self.place(self.m * p.extend(1.0))
    }

    /// The screen position of the clip-space point `c`, if it is in front of the camera.
    fn place(&self, c: Vec4) -> Option<Pos2> {
        if c.w <= 1e-6 || !c.is_finite() {
            return None;
        }
        let n = c.truncate() / c.w;
        let q = Pos2::new(
            self.rect.left() + (n.x + 1.0) / 2.0 * self.rect.width(),
            self.rect.top() + (1.0 - n.y) / 2.0 * self.rect.height(),
        );
        Some(self.rect.center() + (q - self.rect.center()) * self.zoom + self.pan)
    }

    /// Draws a 3-D segment: its part in front of the camera
    /// ([`pipeline::clip::segment_in_front`]), so that a line running past the viewer shows.
    pub fn line(&self, painter: &egui::Painter, a: Vec3, b: Vec3, stroke: egui::Stroke) {
        let Some((ca, cb)) =
            pipeline::clip::segment_in_front(self.m * a.extend(1.0), self.m * b.extend(1.0))
        else {
            return;
        };
        if let (Some(pa), Some(pb)) = (self.place(ca), self.place(cb)) {
            painter.line_segment([pa, pb], stroke);
        }
    }
}

/// The lights of a capture drawn where they are (see `Light::gizmo`), through `to_view` (world
/// coordinates into the space drawn), in a scene centred at `centre` of about `size`; each with its
/// label, kept off the cards in `avoid` and whole inside `view` (none for a light outside it).
pub fn draw_lights(
    painter: &egui::Painter,
    cam: &Projector,
    lights: &[pipeline::light::Light],
    to_view: &dyn Fn(Vec3) -> Vec3,
    (centre, size): (Vec3, f32),
    (avoid, view): (&[egui::Rect], egui::Rect),
    lang: Lang,
) {
    let font = picture_font(painter.ctx(), 14.0);
    // What of the view is painted: the panel around it may cover its edge.
    let view = view.intersect(painter.clip_rect());
    for (k, light) in lights.iter().enumerate() {
        let Some(g) = light.gizmo(centre, size) else {
            continue;
        };
        let stroke = egui::Stroke::new(2.0, palette::LIGHT);
        for [a, b] in &g.segments {
            cam.line(painter, to_view(*a), to_view(*b), stroke);
        }
        // A light outside the view has no label: there is nothing in the picture to name.
        if let Some(p) = cam
            .project(to_view(g.label_at))
            .filter(|p| view.contains(*p))
        {
            let text = crate::vocabulary::light_name(light, k, lang);
            let size = painter
                .layout_no_wrap(text.clone(), font.clone(), palette::LIGHT)
                .size()
                + egui::Vec2::splat(8.0);
            let above = egui::Rect::from_center_size(p - egui::vec2(0.0, size.y / 2.0), size);
            // Above the light where that is clear and whole inside the view; else the nearest
            // place that is, so that no label runs off the picture's edge.
            let at = if avoid.iter().any(|r| r.intersects(above))
                || !view.shrink(4.0).contains_rect(above)
            {
                crate::app::views::place_label(p, size, avoid, view.shrink(4.0))
            } else {
                above
            };
            label_with_background(
                painter,
                at.center(),
                egui::Align2::CENTER_CENTER,
                &text,
                &font,
                palette::LIGHT,
            );
        }
    }
}
