//! Samples per pixel and where they lie: the standard multisample patterns.

use glam::I64Vec2;
use serde::Serialize;

use super::ONE;

/// The number of samples per pixel and where they lie.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum Samples {
    /// One sample at the pixel centre.
    #[default]
    X1,
    /// The standard rotated grid of four.
    X4,
    /// The standard pattern of eight.
    X8,
    /// The standard pattern of sixteen.
    X16,
}

impl Samples {
    /// The count, 1, 4, 8 or 16.
    #[must_use]
    pub fn count(self) -> usize {
        match self {
            Self::X1 => 1,
            Self::X4 => 4,
            Self::X8 => 8,
            Self::X16 => 16,
        }
    }

    /// The pattern for a count, if it is one of 1, 4, 8, 16.
    #[must_use]
    pub fn from_count(n: u32) -> Option<Self> {
        match n {
            1 => Some(Self::X1),
            4 => Some(Self::X4),
            8 => Some(Self::X8),
            16 => Some(Self::X16),
            _ => None,
        }
    }
}

/// Sample positions of the standard multisample patterns, in 1/16 pixel from the pixel centre:
/// the numbers Direct3D publishes (y down there), taken **with y up** in window coordinates, as
/// Mesa's llvmpipe takes them. OpenGL leaves the positions to the implementation; using the same
/// ones as a conformant OpenGL makes the coverage at 4 samples identical to it, not only at 1
/// (`scripts/reference-check.sh`). On screen (y down) the 4× pattern is therefore Direct3D's
/// drawing mirrored vertically: (−2, −6) lies in the pixel's lower half.
const PATTERN_1: [(i8, i8); 1] = [(0, 0)];
const PATTERN_4: [(i8, i8); 4] = [(-2, -6), (6, -2), (-6, 2), (2, 6)];
const PATTERN_8: [(i8, i8); 8] = [
    (1, -3),
    (-1, 3),
    (5, 1),
    (-3, -5),
    (-5, 5),
    (-7, -1),
    (3, 7),
    (7, -7),
];
const PATTERN_16: [(i8, i8); 16] = [
    (1, 1),
    (-1, -3),
    (-3, 2),
    (4, -1),
    (-5, -2),
    (2, 5),
    (5, 3),
    (3, -5),
    (-2, 6),
    (0, -7),
    (-4, -6),
    (-6, 4),
    (-8, 0),
    (7, -4),
    (6, 7),
    (-7, -8),
];

fn pattern(samples: Samples) -> &'static [(i8, i8)] {
    match samples {
        Samples::X1 => &PATTERN_1,
        Samples::X4 => &PATTERN_4,
        Samples::X8 => &PATTERN_8,
        Samples::X16 => &PATTERN_16,
    }
}

/// The sample positions inside a pixel, as offsets from its bottom-left corner in fixed point
/// (window coordinates, y up).
#[must_use]
pub fn sample_offsets_fixed(samples: Samples) -> Vec<I64Vec2> {
    pattern(samples)
        .iter()
        .map(|&(dx, dy)| {
            I64Vec2::new(
                (8 + i64::from(dx)) * ONE / 16,
                (8 + i64::from(dy)) * ONE / 16,
            )
        })
        .collect()
}

/// The sample positions inside a pixel as fractions of a pixel from its **top-left** corner
/// (image coordinates, y down), for drawing them.
#[must_use]
pub fn sample_offsets_image(samples: Samples) -> Vec<[f32; 2]> {
    pattern(samples)
        .iter()
        .map(|&(dx, dy)| [(8.0 + f32::from(dx)) / 16.0, (8.0 - f32::from(dy)) / 16.0])
        .collect()
}
