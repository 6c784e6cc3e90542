//! Two frames of the same scene compared pixel by pixel — a student's program against pipelens'
//! own stage: which pixels match (the same coverage, every colour channel within a tolerance of
//! 8-bit steps), the largest difference, the first pixel that does not match, and a picture of
//! the difference.

use image::{Rgba, RgbaImage};

use super::FrameCapture;

/// What comparing a frame with a reference found.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// Pixels whose coverage is the same and whose colour is within the tolerance.
    pub matching: u64,
    /// Every pixel of the frame.
    pub total: u64,
    /// Pixels covered in one frame and not in the other.
    pub coverage_differs: u64,
    /// The largest colour difference of a pixel, in 8-bit steps (`max_c |a_c − b_c|·255`).
    pub largest: f32,
    /// The first pixel that does not match, in window coordinates (y up), reading the picture
    /// as a page (from its top row, left to right): where to look first.
    pub first: Option<(u32, u32)>,
    /// The tolerance used, in 8-bit steps.
    pub tolerance: f32,
}

impl Difference {
    /// Whether every pixel matches.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.matching == self.total
    }
}

/// One pixel's colour difference in 8-bit steps, and whether its coverage differs.
fn pixel_difference(a: &FrameCapture, b: &FrameCapture, i: usize) -> (f32, bool) {
    let (pa, pb) = (&a.pixels, &b.pixels);
    let step = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round();
    let colour = (0..3)
        .map(|c| (step(pa.color[i][c]) - step(pb.color[i][c])).abs())
        .fold(0.0_f32, f32::max);
    (colour, pa.coverage[i] != pb.coverage[i])
}

impl FrameCapture {
    /// Compares this frame with `reference` (same size): a pixel matches when both cover it
    /// equally and each of its colour channels, rounded to 8 bits, is within `tolerance` steps
    /// of the reference's. `None` when the sizes differ.
    #[must_use]
    pub fn difference(&self, reference: &FrameCapture, tolerance: f32) -> Option<Difference> {
        let (w, h) = (self.width(), self.height());
        if (w, h) != (reference.width(), reference.height()) {
            return None;
        }
        let mut d = Difference {
            matching: 0,
            total: u64::from(w) * u64::from(h),
            coverage_differs: 0,
            largest: 0.0,
            first: None,
            tolerance,
        };
        // As a page is read: the top image row first (window row h − 1), left to right.
        let grid = self.grid();
        for y in (0..h).rev() {
            for x in 0..w {
                let (colour, coverage) = pixel_difference(self, reference, grid.index(x, y));
                d.largest = d.largest.max(colour);
                d.coverage_differs += u64::from(coverage);
                if colour <= tolerance && !coverage {
                    d.matching += 1;
                } else if d.first.is_none() {
                    d.first = Some((x, y));
                }
            }
        }
        Some(d)
    }

    /// The difference as a picture: matching pixels dark grey (their reference's luminance at a
    /// quarter), differing ones red, brighter the larger the difference (full red at 64 steps
    /// and beyond), pixels whose coverage differs yellow. Image rows run down.
    #[must_use]
    pub fn difference_image(&self, reference: &FrameCapture, tolerance: f32) -> RgbaImage {
        let w = self.width();
        // Both the buffers and the picture run top row first: image pixel (x, row) is buffer
        // index row·w + x, the window position (x, h − 1 − row).
        RgbaImage::from_fn(w, self.height(), |x, row| {
            let i = row as usize * w as usize + x as usize;
            if i >= reference.pixels.color.len() {
                return Rgba([0, 0, 0, 255]);
            }
            let (colour, coverage) = pixel_difference(self, reference, i);
            if coverage {
                Rgba([255, 220, 0, 255])
            } else if colour > tolerance {
                let t = (colour / 64.0).clamp(0.25, 1.0);
                Rgba([(255.0 * t) as u8, 30, 30, 255])
            } else {
                let [r, g, b] = reference.pixels.color[i];
                let y = (0.2126 * r + 0.7152 * g + 0.0722 * b).clamp(0.0, 1.0);
                let v = (y * 64.0) as u8;
                Rgba([v, v, v, 255])
            }
        })
    }
}
