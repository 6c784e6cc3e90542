//! Colours used across views, chosen to read on a projector: the axes, the selection, the
//! frustum, clipped geometry, lights, and the fates a triangle can meet.

use egui::Color32;

pub use crate::spaces::fate_index;

/// The x axis.
pub const X: Color32 = Color32::from_rgb(235, 80, 80);
/// The y axis.
pub const Y: Color32 = Color32::from_rgb(90, 210, 90);
/// The z axis.
pub const Z: Color32 = Color32::from_rgb(90, 140, 255);
/// Selection highlight.
pub const SELECTED: Color32 = Color32::from_rgb(255, 215, 0);
/// The viewing frustum's near plane.
pub const NEAR: Color32 = Color32::from_rgb(255, 200, 60);
/// The viewing frustum's far plane and sides.
pub const FAR: Color32 = Color32::from_rgb(255, 140, 40);
/// Clipped geometry.
pub const CLIPPED: Color32 = Color32::from_rgb(255, 120, 200);
/// Lights.
pub const LIGHT: Color32 = Color32::from_rgb(255, 240, 120);

/// The colour of a primitive's fate, for wireframes.
#[must_use]
pub fn fate_color(f: &pipeline::capture::Fate) -> Color32 {
    FATES[fate_index(f)].0
}

/// The fates a triangle can meet, in the legend's order: colour, English name, Chinese name
/// (`spaces::FATES`, the colours as egui's).
pub const FATES: [(Color32, &str, &str); crate::spaces::FATES.len()] = {
    const fn fate(k: usize) -> (Color32, &'static str, &'static str) {
        let f = crate::spaces::FATES[k];
        (Color32::from_rgb(f.0[0], f.0[1], f.0[2]), f.1, f.2)
    }
    [fate(0), fate(1), fate(2), fate(3), fate(4), fate(5)]
};

/// A colour as egui draws it, from a value in [0, 1].
pub fn swatch(c: [f32; 4]) -> Color32 {
    Color32::from(egui::Rgba::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]))
}
