//! Two frames of the same scene compared pixel by pixel — a student's program against pipelens'
//! own stage: which pixels match (the same coverage, every colour channel within a tolerance of
//! 8-bit steps, and where asked the same depth and the same owning triangle), the largest
//! difference, the first pixel that does not match, and a picture of the difference.

use image::{Rgba, RgbaImage};

use super::FrameCapture;

/// What must agree for a pixel to match, beside its coverage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Criteria {
    /// How many 8-bit steps each colour channel may differ.
    pub tolerance: f32,
    /// How far the window depths `z_w ∈ [0, 1]` of a pixel both frames cover may differ, when
    /// depth is compared: a projection with the wrong z keeps the picture and moves every depth.
    pub depth: Option<f32>,
    /// Whether the same triangle must own the pixel: where the student decides which samples a
    /// triangle covers, a triangle that takes its neighbour's pixels shows nothing else when both
    /// have the same colour.
    pub owner: bool,
}

impl Criteria {
    /// The colour within `tolerance` steps and the coverage alone.
    #[must_use]
    pub const fn colour(tolerance: f32) -> Self {
        Self {
            tolerance,
            depth: None,
            owner: false,
        }
    }
}

/// What comparing a frame with a reference found.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// Pixels that match by every criterion.
    pub matching: u64,
    /// Every pixel of the frame.
    pub total: u64,
    /// Pixels covered in one frame and not in the other.
    pub coverage_differs: u64,
    /// Pixels both frames cover at depths further apart than the criteria allow.
    pub depth_differs: u64,
    /// Pixels both frames cover, owned by different triangles (when that is compared).
    pub owner_differs: u64,
    /// The largest colour difference of a pixel, in 8-bit steps (`max_c |a_c − b_c|·255`).
    pub largest: f32,
    /// The first pixel that does not match, in window coordinates (y up), reading the picture
    /// as a page (from its top row, left to right): where to look first.
    pub first: Option<(u32, u32)>,
    /// What was compared.
    pub criteria: Criteria,
}

impl Difference {
    /// Whether every pixel matches.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.matching == self.total
    }
}

/// How one pixel differs.
#[derive(Clone, Copy, Debug, Default)]
struct PixelDifference {
    /// The largest channel's difference in 8-bit steps.
    colour: f32,
    /// Covered by a different number of samples.
    coverage: bool,
    /// Covered by both, at depths further apart than allowed.
    depth: bool,
    /// Covered by both, owned by different triangles (when compared).
    owner: bool,
}

impl PixelDifference {
    /// Pixel `i` of `a` against `b`.
    fn of(a: &FrameCapture, b: &FrameCapture, i: usize, criteria: &Criteria) -> Self {
        let (pa, pb) = (&a.pixels, &b.pixels);
        let step = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round();
        let colour = (0..3)
            .map(|c| (step(pa.color[i][c]) - step(pb.color[i][c])).abs())
            .fold(0.0_f32, f32::max);
        let coverage = pa.coverage[i] != pb.coverage[i];
        let both = pa.coverage[i] > 0 && pb.coverage[i] > 0;
        Self {
            colour,
            coverage,
            depth: both
                && criteria
                    .depth
                    .is_some_and(|t| !((pa.depth[i] - pb.depth[i]).abs() <= t)),
            owner: both && criteria.owner && pa.primitive[i] != pb.primitive[i],
        }
    }

    /// Whether it matches.
    fn matches(&self, criteria: &Criteria) -> bool {
        self.colour <= criteria.tolerance && !self.coverage && !self.depth && !self.owner
    }
}

/// The difference picture's colours: a colour that differs (red, at its largest: dimmer for a
/// smaller difference, down to [`DIFFERENCE_DIMMEST`]), coverage that differs (yellow, striped
/// with [`COVERAGE_STRIPE`]), another
/// depth (blue), another triangle's pixel (pink). A pixel that differs in several ways shows
/// the first of coverage, colour, triangle, depth. Every pair, and each against the matching
/// pixels' greys (0 to [`MATCH_GREY_MAX`]), stays apart to colour-blind eyes too (the app's
/// `palette::vision` test): blue and magenta, (60, 140, 255) and (230, 60, 230), were 11 ΔE
/// apart to a protanope.
pub const DIFFERENCE_COLOURS: [[u8; 3]; 4] = [
    [255, 30, 30],
    [255, 220, 0],
    [80, 120, 255],
    [255, 120, 200],
];

/// The second colour of differing coverage's stripes ([`on_stripe`]): coverage is drawn in
/// diagonal bands, yellow and white, so that it reads apart from a colour difference by its
/// pattern and not by its hue alone (WCAG 1.4.1) — to a deuteranope a large colour difference's
/// red is a dark yellow, near the coverage's own.
pub const COVERAGE_STRIPE: [u8; 3] = [255, 255, 255];

/// Whether image pixel (`x`, `row`) of differing coverage takes [`COVERAGE_STRIPE`]: bands two
/// pixels wide along the diagonals `x + row`, every other pair (`x + row` = 2, 3, 6, 7, …).
#[must_use]
pub const fn on_stripe(x: u32, row: u32) -> bool {
    (x + row) / 2 % 2 == 1
}

/// The smallest share of its red a differing colour keeps: at a quarter, a difference of a few
/// steps was (63, 30, 30), 4 ΔE from a matching pixel's grey to a protanope.
pub const DIFFERENCE_DIMMEST: f32 = 0.6;

/// The lightest grey of a matching pixel: its reference's luminance at a quarter, times 255.
pub const MATCH_GREY_MAX: u8 = 64;

impl FrameCapture {
    /// Compares this frame with `reference` (same size): a pixel matches when both cover it
    /// equally and each of its colour channels, rounded to 8 bits, is within `tolerance` steps
    /// of the reference's. `None` when the sizes differ.
    #[must_use]
    pub fn difference(&self, reference: &FrameCapture, tolerance: f32) -> Option<Difference> {
        self.difference_by(reference, Criteria::colour(tolerance))
    }

    /// Compares this frame with `reference` (same size) by `criteria`: a pixel matches when
    /// both cover it equally, its colour channels are within the tolerance and, where asked,
    /// its depths and its owning triangle agree. `None` when the sizes differ.
    #[must_use]
    pub fn difference_by(
        &self,
        reference: &FrameCapture,
        criteria: Criteria,
    ) -> Option<Difference> {
        let (w, h) = (self.width(), self.height());
        if (w, h) != (reference.width(), reference.height()) {
            return None;
        }
        let mut d = Difference {
            matching: 0,
            total: u64::from(w) * u64::from(h),
            coverage_differs: 0,
            depth_differs: 0,
            owner_differs: 0,
            largest: 0.0,
            first: None,
            criteria,
        };
        // As a page is read: the top image row first (window row h − 1), left to right.
        let grid = self.grid();
        for y in (0..h).rev() {
            for x in 0..w {
                let p = PixelDifference::of(self, reference, grid.index(x, y), &criteria);
                d.largest = d.largest.max(p.colour);
                d.coverage_differs += u64::from(p.coverage);
                d.depth_differs += u64::from(p.depth);
                d.owner_differs += u64::from(p.owner);
                if p.matches(&criteria) {
                    d.matching += 1;
                } else if d.first.is_none() {
                    d.first = Some((x, y));
                }
            }
        }
        Some(d)
    }

    /// The difference as a picture ([`DIFFERENCE_COLOURS`]): matching pixels dark grey (their reference's luminance at a
    /// quarter), pixels whose colour differs red, brighter the larger the difference (full red
    /// at 64 steps and beyond), pixels whose coverage differs striped yellow and white
    /// ([`on_stripe`]), pixels at another depth
    /// blue, pixels another triangle owns pink. Image rows run down.
    #[must_use]
    pub fn difference_image(&self, reference: &FrameCapture, criteria: Criteria) -> RgbaImage {
        let w = self.width();
        // Both the buffers and the picture run top row first: image pixel (x, row) is buffer
        // index row·w + x, the window position (x, h − 1 − row).
        RgbaImage::from_fn(w, self.height(), |x, row| {
            let i = row as usize * w as usize + x as usize;
            if i >= reference.pixels.color.len() {
                return Rgba([0, 0, 0, 255]);
            }
            let p = PixelDifference::of(self, reference, i, &criteria);
            let [colour, coverage, depth, owner] =
                DIFFERENCE_COLOURS.map(|c| Rgba([c[0], c[1], c[2], 255]));
            if p.coverage && on_stripe(x, row) {
                let [r, g, b] = COVERAGE_STRIPE;
                Rgba([r, g, b, 255])
            } else if p.coverage {
                coverage
            } else if p.colour > criteria.tolerance {
                let t = (p.colour / 64.0).clamp(DIFFERENCE_DIMMEST, 1.0);
                Rgba([(f32::from(colour[0]) * t) as u8, colour[1], colour[2], 255])
            } else if p.owner {
                owner
            } else if p.depth {
                depth
            } else {
                let [r, g, b] = reference.pixels.color[i];
                let y = (0.2126 * r + 0.7152 * g + 0.0722 * b).clamp(0.0, 1.0);
                let v = (y * f32::from(MATCH_GREY_MAX)) as u8;
                Rgba([v, v, v, 255])
            }
        })
    }
}
