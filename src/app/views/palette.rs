//! Colours used across views, as egui's: the meanings' colours of [`crate::palette`] (the
//! axes, the frustum, clipped geometry, lights, the fates a triangle can meet, their ground)
//! and the selection.

use egui::Color32;

pub use crate::spaces::fate_index;

/// The x axis.
pub const X: Color32 = egui_colour(crate::palette::X);
/// The y axis.
pub const Y: Color32 = egui_colour(crate::palette::Y);
/// The z axis.
pub const Z: Color32 = egui_colour(crate::palette::Z);
/// The ground the geometry views and the observer's frame are drawn on.
pub const GROUND: Color32 = egui_colour(crate::palette::GROUND);
/// Selection highlight.
pub const SELECTED: Color32 = Color32::from_rgb(255, 215, 0);
/// The viewing frustum's near plane.
pub const NEAR: Color32 = egui_colour(crate::palette::NEAR);
/// The viewing frustum's far plane and sides.
pub const FAR: Color32 = egui_colour(crate::palette::FAR);
/// Clipped geometry.
pub const CLIPPED: Color32 = egui_colour(crate::palette::CLIPPED);
/// Lights.
pub const LIGHT: Color32 = egui_colour(crate::palette::LIGHT);

/// The colour of a primitive's fate, for wireframes.
#[must_use]
pub fn fate_color(f: &pipeline::capture::Fate) -> Color32 {
    FATES[fate_index(f)].0
}

/// A segment of an edge in the dashes of fate `fate` (by `fate_index`; `spaces::FATE_DASHES`,
/// lengths × `scale`); solid for none, or a fate drawn solid.
pub fn fate_segment(
    painter: &egui::Painter,
    ends: [egui::Pos2; 2],
    stroke: egui::Stroke,
    (fate, scale): (Option<usize>, f32),
) {
    let pattern = fate.map_or(&[][..], |k| crate::spaces::FATE_DASHES[k]);
    // `spaces::dashed` would give the whole segment too, through a vector: not for each edge
    // of tens of thousands of solid triangles a frame.
    if pattern.is_empty() {
        painter.line_segment(ends, stroke);
        return;
    }
    let [a, b] = ends.map(|p| [p.x, p.y]);
    for [p, q] in crate::spaces::dashed(a, b, pattern, scale) {
        painter.line_segment([p.into(), q.into()], stroke);
    }
}

/// The fates a triangle can meet, in the legend's order: colour and the message of its name
/// (`spaces::FATES`, the colours as egui's).
pub const FATES: [(Color32, &str); crate::spaces::FATES.len()] = {
    const fn fate(k: usize) -> (Color32, &'static str) {
        let f = crate::spaces::FATES[k];
        (egui_colour(f.0), f.1)
    }
    [fate(0), fate(1), fate(2), fate(3), fate(4), fate(5)]
};

/// A palette colour ([`crate::palette`]) as egui's.
const fn egui_colour([r, g, b]: crate::palette::Rgb) -> Color32 {
    Color32::from_rgb(r, g, b)
}

/// Black or white, whichever stands out more from `ground` by WCAG's contrast ratio
/// `(L₁ + 0.05)/(L₂ + 0.05)`: black where the ground's relative luminance L is above 0.179,
/// where `(L + 0.05)/0.05` passes `1.05/(L + 0.05)`.
#[must_use]
pub fn ink_on(ground: Color32) -> Color32 {
    if crate::palette::vision::luminance([ground.r(), ground.g(), ground.b()]) > 0.179 {
        Color32::BLACK
    } else {
        Color32::WHITE
    }
}

/// A colour as egui draws it, from a value in [0, 1].
pub fn swatch(c: [f32; 4]) -> Color32 {
    Color32::from(egui::Rgba::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]))
}
