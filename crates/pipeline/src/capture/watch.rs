//! A watch over the frame as a picture: an expression of the fragment shader after a line, at
//! every pixel (`Scene::watching`) — or of the vertex shader, interpolated over each triangle — drawn so that every reader can tell its values apart — a
//! number on cividis (a ramp that keeps its order under every colour-blindness, dark blue to
//! yellow, Nuñez et al. 2018) from the frame's least to its greatest value, a vector as a
//! colour or one component on the ramp, a condition as a mask (the ramp's two ends). Where no
//! fragment ran the line, a grey checkerboard; a value that is NaN or infinite, magenta.

use crate::shader::probe::WatchKind;

/// An expression's value after a line of the fragment shader, at every pixel: the fragment
/// that covers the most of the pixel's samples (the one a single-sample frame keeps), where it
/// ran the line and was not discarded. For a line of the vertex shader, that fragment's
/// triangle's corners' values interpolated at the pixel, where all three corners ran it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WatchPicture {
    /// The line watched, from 1.
    pub line: usize,
    /// The line is the vertex shader's: each pixel holds the value at its triangle's corners
    /// interpolated as a varying is (perspective-correct; an `int` or a `bool` flat, from the
    /// provoking vertex, as GLSL passes them).
    pub from_vertex: bool,
    /// The expression, as typed.
    pub expression: String,
    /// Its type (`None` when no fragment of the frame ran the line).
    pub kind: Option<WatchKind>,
    /// The value at each pixel, image order (top row first); `None` where no fragment ran the
    /// line.
    pub values: Vec<Option<[f32; 4]>>,
    /// The image's width, pixels.
    pub width: u32,
}

/// How a watch is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WatchView {
    /// As its type asks: a number on the ramp, a vector as a colour (each component clamped
    /// to [0, 1] as red, green, blue), a condition as a mask.
    Value,
    /// One component of a vector on the ramp.
    Component(usize),
}

/// A watch drawn: its pixels, and the values the ramp's ends stand for (none for a colour or
/// a mask).
#[derive(Clone, Debug, PartialEq)]
pub struct WatchedImage {
    /// The image, RGBA, top row first.
    pub image: image::RgbaImage,
    /// The values at the ramp's dark and bright ends.
    pub range: Option<(f32, f32)>,
}

/// Where no fragment ran the line: a checkerboard of two greys, 4 pixels a square.
fn not_run(x: u32, y: u32) -> [u8; 4] {
    if (x / 4 + y / 4).is_multiple_of(2) {
        [56, 56, 56, 255]
    } else {
        [80, 80, 80, 255]
    }
}

/// A value that is not a number.
const NOT_FINITE: [u8; 4] = [255, 0, 255, 255];

/// The ramp at `t` in [0, 1].
#[must_use]
pub fn ramp(t: f32) -> [u8; 4] {
    let c = colorous::CIVIDIS.eval_continuous(f64::from(t.clamp(0.0, 1.0)));
    [c.r, c.g, c.b, 255]
}

impl WatchPicture {
    /// The image's height, pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        (self.values.len() as u32)
            .checked_div(self.width)
            .unwrap_or(0)
    }

    /// Where the expression is read, in words: "after line N", of the vertex shader and
    /// interpolated when it is the vertex shader's.
    #[must_use]
    pub fn place(&self) -> String {
        if self.from_vertex {
            format!(
                "after line {} of the vertex shader, interpolated over each triangle",
                self.line
            )
        } else {
            format!("after line {}", self.line)
        }
    }

    /// What a pixel without a value means, in words ("where …").
    #[must_use]
    pub fn unrun(&self) -> &'static str {
        if self.from_vertex {
            "where a corner of the triangle did not run the line"
        } else {
            "where no fragment ran the line"
        }
    }

    /// The value at window pixel `(x, y)` (y up, as the inspector counts).
    #[must_use]
    pub fn at(&self, x: u32, y: u32) -> Option<[f32; 4]> {
        let h = self.height();
        if x >= self.width || y >= h {
            return None;
        }
        self.values[((h - 1 - y) * self.width + x) as usize]
    }

    /// The pixels where the line ran.
    #[must_use]
    pub fn pixels_run(&self) -> usize {
        self.values.iter().flatten().count()
    }

    /// The least and the greatest finite value of component `c` over the frame.
    #[must_use]
    pub fn range(&self, c: usize) -> Option<(f32, f32)> {
        self.values
            .iter()
            .flatten()
            .map(|v| v[c])
            .filter(|v| v.is_finite())
            .fold(None, |r, v| match r {
                None => Some((v, v)),
                Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
            })
    }

    /// The first pixel where a condition holds (or a number is not zero), reading the image
    /// from its top row, left to right, as window coordinates (y up).
    #[must_use]
    pub fn first_where(&self) -> Option<(u32, u32)> {
        let h = self.height();
        let i = self
            .values
            .iter()
            .position(|v| v.is_some_and(|v| v[0] != 0.0 && !v[0].is_nan()))?;
        let (x, row) = (i as u32 % self.width, i as u32 / self.width);
        Some((x, h - 1 - row))
    }

    /// The picture drawn as `view` says.
    #[must_use]
    pub fn drawn(&self, view: WatchView) -> WatchedImage {
        let kind = self.kind.unwrap_or(WatchKind::Float);
        let component = match (view, kind) {
            (WatchView::Component(c), _) => Some(c.min(kind.components() - 1)),
            (WatchView::Value, WatchKind::Float | WatchKind::Int) => Some(0),
            _ => None,
        };
        let range = component.and_then(|c| self.range(c));
        let mut image = image::RgbaImage::new(self.width, self.height());
        for (i, v) in self.values.iter().enumerate() {
            let (x, y) = (i as u32 % self.width, i as u32 / self.width);
            let px = match v {
                None => not_run(x, y),
                Some(v) => match (component, kind) {
                    (Some(c), _) if !v[c].is_finite() => NOT_FINITE,
                    (Some(c), _) => {
                        let (lo, hi) = range.unwrap_or((0.0, 1.0));
                        let t = if hi > lo {
                            (v[c] - lo) / (hi - lo)
                        } else {
                            0.5
                        };
                        ramp(t)
                    }
                    (None, WatchKind::Bool) => ramp(if v[0] != 0.0 { 1.0 } else { 0.0 }),
                    (None, _) if v.iter().any(|c| !c.is_finite()) => NOT_FINITE,
                    (None, _) => {
                        let byte = |c: usize| {
                            if c < kind.components() {
                                (v[c].clamp(0.0, 1.0) * 255.0).round() as u8
                            } else {
                                0
                            }
                        };
                        [byte(0), byte(1), byte(2), 255]
                    }
                },
            };
            image.put_pixel(x, y, image::Rgba(px));
        }
        WatchedImage { image, range }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2×2 picture written by hand: the top row ran the line (values 1 and 3), the bottom
    /// row's left pixel did not, its right pixel holds NaN.
    fn picture(kind: WatchKind) -> WatchPicture {
        WatchPicture {
            from_vertex: false,
            line: 1,
            expression: "x".to_owned(),
            kind: Some(kind),
            values: vec![
                Some([1.0, 0.0, 0.0, 0.0]),
                Some([3.0, 1.0, 0.5, 0.0]),
                None,
                Some([f32::NAN, 0.0, 0.0, 0.0]),
            ],
            width: 2,
        }
    }

    #[test]
    fn a_number_spans_the_ramp_from_its_least_to_its_greatest_value() {
        let p = picture(WatchKind::Float);
        let d = p.drawn(WatchView::Value);
        assert_eq!(d.range, Some((1.0, 3.0)));
        assert_eq!(d.image.get_pixel(0, 0).0, ramp(0.0));
        assert_eq!(d.image.get_pixel(1, 0).0, ramp(1.0));
        assert_eq!(d.image.get_pixel(0, 1).0, not_run(0, 1));
        assert_eq!(d.image.get_pixel(1, 1).0, NOT_FINITE);
        // The ramp's ends: cividis' dark blue and its yellow.
        assert!(ramp(0.0)[2] > ramp(0.0)[0] && ramp(1.0)[0] > ramp(1.0)[2]);
    }

    #[test]
    fn a_vector_is_a_colour_or_one_component_and_a_condition_a_mask() {
        let p = picture(WatchKind::Vec3);
        let d = p.drawn(WatchView::Value);
        assert_eq!(d.range, None);
        assert_eq!(
            d.image.get_pixel(1, 0).0,
            [255, 255, 128, 255],
            "3, 1, 0.5 clamped"
        );
        let g = p.drawn(WatchView::Component(1));
        assert_eq!(g.range, Some((0.0, 1.0)));
        let mask = picture(WatchKind::Bool).drawn(WatchView::Value);
        assert_eq!(mask.image.get_pixel(0, 0).0, ramp(1.0));
    }

    #[test]
    fn window_pixels_count_from_the_bottom_row() {
        let p = picture(WatchKind::Float);
        assert_eq!(p.at(1, 1).map(|v| v[0]), Some(3.0), "top right");
        assert_eq!(p.at(0, 0), None, "bottom left did not run");
        assert_eq!(p.at(2, 0), None);
        assert_eq!(p.first_where(), Some((0, 1)), "the top row's first");
    }
}
