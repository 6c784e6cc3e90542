//! The colours that carry a meaning, in one place for the app, the exports and the observer:
//! the axes, the viewing frustum, the fates a triangle meets, the lights, and the ground the
//! geometry views draw them on.
//!
//! Each set of meanings a picture shows together ([`SETS`]) keeps every pair at least
//! [`vision::APART`] apart in CIELAB, and each meaning as far from its ground, for normal vision
//! and as protanopes, deuteranopes and tritanopes see them ([`vision`]; the test
//! `palette::every_set_of_meanings_reads_apart_to_colour_blind_eyes`). The colours keep their
//! families — the axes red, green, blue; the near plane amber, the far plane coral, a light
//! pale — and separate by lightness where the hues merge: the old x and y axes, (235, 80, 80)
//! and (90, 210, 90), were 14 apart to a deuteranope, the near plane and the light 17.

pub mod vision;

/// A colour in 8-bit sRGB.
pub type Rgb = [u8; 3];

/// The ground the geometry views draw on.
pub const GROUND: Rgb = [18, 18, 18];

/// The x axis (and a camera frame's u).
pub const X: Rgb = [235, 70, 70];
/// The y axis (and v).
pub const Y: Rgb = [130, 245, 110];
/// The z axis (and n).
pub const Z: Rgb = [70, 120, 255];

/// The viewing frustum's near plane.
pub const NEAR: Rgb = [255, 160, 0];
/// The viewing frustum's far plane and sides.
pub const FAR: Rgb = [250, 100, 65];
/// A light: its place, its direction, its cone.
pub const LIGHT: Rgb = [245, 200, 145];

/// A triangle drawn.
pub const DRAWN: Rgb = [220, 220, 220];
/// A triangle cut by clipping, and the polygons clipping leaves.
pub const CLIPPED: Rgb = [205, 110, 240];
/// A triangle outside the view volume.
pub const OUTSIDE: Rgb = [90, 90, 90];
/// A triangle culled as back-facing.
pub const CULLED: Rgb = [115, 145, 180];
/// A degenerate triangle (no area on screen).
pub const DEGENERATE: Rgb = [170, 15, 0];
/// A triangle with a coordinate that is not finite.
pub const NOT_FINITE: Rgb = [135, 60, 255];

/// A set of meanings a picture shows together: its name, its meanings with their colours, and
/// the grounds they are drawn on.
pub struct MeaningSet {
    /// What shows them.
    pub name: &'static str,
    /// Each meaning's name and colour.
    pub meanings: &'static [(&'static str, Rgb)],
    /// What they are drawn on.
    pub grounds: &'static [Rgb],
}

/// The sets of meanings drawn together: a geometry view's (the fates, the frustum, the lights,
/// named by its legend) and its axes (named by their letters as well).
pub const SETS: [MeaningSet; 2] = [
    MeaningSet {
        name: "a geometry view's legend",
        meanings: &[
            ("drawn", DRAWN),
            ("clipped", CLIPPED),
            ("outside", OUTSIDE),
            ("culled", CULLED),
            ("degenerate", DEGENERATE),
            ("not finite", NOT_FINITE),
            ("near plane", NEAR),
            ("far plane", FAR),
            ("light", LIGHT),
        ],
        grounds: &[GROUND],
    },
    MeaningSet {
        name: "the axes",
        meanings: &[("x", X), ("y", Y), ("z", Z)],
        grounds: &[GROUND],
    },
];
