//! Overlays: 2-D shapes in image pixel space (x right, y down, pixel `(c, r)` is the square
//! `[c, c+1] × [r, r+1]`), described once and drawn both by the app (egui) and, here, by
//! tiny-skia into exported PNGs.

use image::RgbaImage;
use serde::Serialize;
use tiny_skia::{Color, LineCap, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

/// A straight-alpha sRGB colour.
pub type Rgba = [u8; 4];

/// One shape.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "shape")]
pub enum Shape {
    /// A polygon outline (closed) or a polyline (open).
    Polyline {
        /// Points in image pixel coordinates.
        points: Vec<[f32; 2]>,
        /// Whether the last point joins the first.
        closed: bool,
        /// Stroke colour.
        color: Rgba,
        /// Stroke width in output pixels (independent of any zoom).
        width: f32,
    },
    /// An axis-aligned rectangle outline.
    Rect {
        /// Top-left corner.
        min: [f32; 2],
        /// Bottom-right corner.
        max: [f32; 2],
        /// Stroke colour.
        color: Rgba,
        /// Stroke width in output pixels.
        width: f32,
    },
    /// An arrow from `from` to `to` (a lighting vector at the inspected pixel).
    Arrow {
        /// Tail.
        from: [f32; 2],
        /// Head.
        to: [f32; 2],
        /// Stroke colour.
        color: Rgba,
        /// Stroke width in output pixels.
        width: f32,
    },
    /// A filled dot (a sample point, a vertex).
    Dot {
        /// Centre.
        center: [f32; 2],
        /// Radius in output pixels.
        radius: f32,
        /// Fill colour.
        color: Rgba,
    },
}

/// The overlays a capture can show.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OverlayKind {
    /// The edges of every rasterized triangle (after clipping).
    TriangleEdges,
    /// The pixel bounding box each triangle's rasterization scans.
    BoundingBoxes,
}

impl OverlayKind {
    /// Every overlay, in drawing order.
    pub const ALL: [OverlayKind; 2] = [Self::BoundingBoxes, Self::TriangleEdges];

    /// A file-name friendly name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::TriangleEdges => "edges",
            Self::BoundingBoxes => "bboxes",
        }
    }
}

/// A named group of shapes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Overlay {
    /// What it shows.
    pub kind: OverlayKind,
    /// The shapes.
    pub shapes: Vec<Shape>,
}

fn paint(c: Rgba) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(Color::from_rgba8(c[0], c[1], c[2], c[3]));
    p.anti_alias = true;
    p
}

/// The two ends of an arrow head of length `size` at `b`, for the arrow from `a`, 25° either
/// side of the shaft.
#[must_use]
pub fn arrow_head(a: [f32; 2], b: [f32; 2], size: f32) -> [[f32; 2]; 2] {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy).max(1e-6);
    let (ux, uy) = (dx / len, dy / len);
    let (s, c) = 25f32.to_radians().sin_cos();
    [
        [
            b[0] - size * (ux * c - uy * s),
            b[1] - size * (uy * c + ux * s),
        ],
        [
            b[0] - size * (ux * c + uy * s),
            b[1] - size * (uy * c - ux * s),
        ],
    ]
}

/// Where the labels of arrows drawn from one point go, so that none covers another nor a box
/// of `avoid` (`[min, max]`, a legend): label `i`, a box `size` across, centred `gap` beyond the
/// head of arrow `arrows[i]` = `(from, to)` along its shaft; where that box meets one placed
/// before it, beside that place (a box across the shaft, on its left, then its right), then
/// further out along the shaft by half a box at a time, and so on up to a few boxes away; for
/// an arrow too short to have a direction (a vector pointing at the eye), round the point.
/// Arrows of close directions (`l` and `h` at a grazing light) then keep their letters apart,
/// in the order given. Each goes to the first place clear of the other labels, of `avoid` and
/// of the other arrows' shafts (on the desktop tour `h` sat over the end of `l`); where none
/// is, the first clear of the labels and `avoid`, then the first clear of the other labels (a
/// letter over the legend's edge hides less than one over another letter); else the first.
#[must_use]
pub fn spread_labels(
    arrows: &[([f32; 2], [f32; 2])],
    size: [f32; 2],
    gap: f32,
    avoid: &[[[f32; 2]; 2]],
) -> Vec<[f32; 2]> {
    let meets =
        |a: [f32; 2], b: [f32; 2]| (a[0] - b[0]).abs() < size[0] && (a[1] - b[1]).abs() < size[1];
    let covers = |c: [f32; 2], [min, max]: [[f32; 2]; 2]| {
        let h = [size[0] / 2.0, size[1] / 2.0];
        c[0] + h[0] > min[0] && c[0] - h[0] < max[0] && c[1] + h[1] > min[1] && c[1] - h[1] < max[1]
    };
    let step = 0.5 * size[0].max(size[1]);
    let mut placed: Vec<[f32; 2]> = Vec::with_capacity(arrows.len());
    for &(from, to) in arrows {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let len = dx.hypot(dy);
        let candidates: Vec<[f32; 2]> = if len >= 1.0 {
            let (ux, uy) = (dx / len, dy / len);
            // Across the shaft, a box's extent that way.
            let (px, py) = (-uy, ux);
            let across = px.abs() * size[0] + py.abs() * size[1];
            (0..6)
                .flat_map(|k| {
                    let d = gap + k as f32 * step;
                    let at = [to[0] + ux * d, to[1] + uy * d];
                    [0.0, 1.0, -1.0, 2.0, -2.0]
                        .map(|side| [at[0] + px * across * side, at[1] + py * across * side])
                })
                .collect()
        } else {
            // Eight places round the point, then eight further out.
            (0..16)
                .map(|k| {
                    let a = (k % 8) as f32 * std::f32::consts::FRAC_PI_4;
                    let d = gap + (k / 8) as f32 * 2.0 * step;
                    [to[0] + a.cos() * d, to[1] - a.sin() * d]
                })
                .collect()
        };
        let apart = |c: &[f32; 2]| placed.iter().all(|p| !meets(*c, *p));
        let clear = |c: &[f32; 2]| apart(c) && avoid.iter().all(|r| !covers(*c, *r));
        // The other arrows with a direction: a label over one hides where it goes.
        let shafts = arrows
            .iter()
            .filter(|&&(a, b)| (a, b) != (from, to) && (b[0] - a[0]).hypot(b[1] - a[1]) >= 1.0);
        let off_shafts = |c: &[f32; 2]| shafts.clone().all(|&(a, b)| !crosses(*c, size, a, b));
        let at = candidates
            .iter()
            .find(|c| clear(c) && off_shafts(c))
            .or_else(|| candidates.iter().find(|c| clear(c)))
            .or_else(|| candidates.iter().find(|c| apart(c)))
            .unwrap_or(&candidates[0]);
        placed.push(*at);
    }
    placed
}

/// Whether the segment from `a` to `b` runs through the inside of a box `size` across centred
/// at `c` (along its edge or through a corner does not count): the segment's parameters
/// `t ∈ [0, 1]` within the box's slab on each axis, `(min − a)/(b − a)` to `(max − a)/(b − a)`,
/// share an interval of some length (Liang and Barsky's clipping).
fn crosses(c: [f32; 2], size: [f32; 2], a: [f32; 2], b: [f32; 2]) -> bool {
    let (mut lo, mut hi) = (0.0f32, 1.0f32);
    for k in 0..2 {
        let (min, max) = (c[k] - size[k] / 2.0, c[k] + size[k] / 2.0);
        let d = b[k] - a[k];
        if d == 0.0 {
            if a[k] <= min || a[k] >= max {
                return false;
            }
        } else {
            let (t0, t1) = ((min - a[k]) / d, (max - a[k]) / d);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        }
    }
    lo < hi
}

/// Strokes the path built in `pb` with round caps.
fn stroke_round(pixmap: &mut Pixmap, pb: PathBuilder, color: Rgba, width: f32) {
    if let Some(path) = pb.finish() {
        let stroke = Stroke {
            width,
            line_cap: LineCap::Round,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &paint(color), &stroke, Transform::identity(), None);
    }
}

/// Draws `shapes` onto `pixmap`, whose pixels are `zoom` times the image's pixels.
pub fn draw(pixmap: &mut Pixmap, shapes: &[Shape], zoom: f32) {
    let t = Transform::identity();
    for shape in shapes {
        match shape {
            Shape::Polyline {
                points,
                closed,
                color,
                width,
            } => {
                let mut pb = PathBuilder::new();
                for (i, p) in points.iter().enumerate() {
                    if i == 0 {
                        pb.move_to(p[0] * zoom, p[1] * zoom);
                    } else {
                        pb.line_to(p[0] * zoom, p[1] * zoom);
                    }
                }
                if *closed {
                    pb.close();
                }
                stroke_round(pixmap, pb, *color, *width);
            }
            Shape::Rect {
                min,
                max,
                color,
                width,
            } => {
                if let Some(r) =
                    Rect::from_ltrb(min[0] * zoom, min[1] * zoom, max[0] * zoom, max[1] * zoom)
                {
                    let path = PathBuilder::from_rect(r);
                    let stroke = Stroke {
                        width: *width,
                        ..Stroke::default()
                    };
                    pixmap.stroke_path(&path, &paint(*color), &stroke, t, None);
                }
            }
            Shape::Arrow {
                from,
                to,
                color,
                width,
            } => {
                let (a, b) = (
                    [from[0] * zoom, from[1] * zoom],
                    [to[0] * zoom, to[1] * zoom],
                );
                let mut pb = PathBuilder::new();
                pb.move_to(a[0], a[1]);
                pb.line_to(b[0], b[1]);
                for [hx, hy] in arrow_head(a, b, 4.0 * width) {
                    pb.move_to(b[0], b[1]);
                    pb.line_to(hx, hy);
                }
                stroke_round(pixmap, pb, *color, *width);
            }
            Shape::Dot {
                center,
                radius,
                color,
            } => {
                if let Some(path) =
                    PathBuilder::from_circle(center[0] * zoom, center[1] * zoom, *radius)
                {
                    pixmap.fill_path(&path, &paint(*color), tiny_skia::FillRule::Winding, t, None);
                }
            }
        }
    }
}

/// `base` magnified `zoom`× (nearest, so pixels stay square) with `shapes` (in `base`'s pixel
/// coordinates) drawn over it.
#[must_use]
pub fn magnified_with_shapes(base: &RgbaImage, shapes: &[Shape], zoom: u32) -> RgbaImage {
    let zoom = zoom.max(1);
    let (w, h) = (base.width() * zoom, base.height() * zoom);
    let Some(mut pixmap) = Pixmap::new(w, h) else {
        return base.clone();
    };
    for (i, px) in pixmap.pixels_mut().iter_mut().enumerate() {
        let (x, y) = (i as u32 % w / zoom, i as u32 / w / zoom);
        let c = base.get_pixel(x, y).0;
        if let Some(p) = tiny_skia::PremultipliedColorU8::from_rgba(c[0], c[1], c[2], 255) {
            *px = p;
        }
    }
    draw(&mut pixmap, shapes, zoom as f32);
    RgbaImage::from_fn(w, h, |x, y| {
        let c = pixmap.pixel(x, y).map(|p| p.demultiply());
        c.map_or(image::Rgba([0, 0, 0, 255]), |c| {
            image::Rgba([c.red(), c.green(), c.blue(), c.alpha()])
        })
    })
}

#[cfg(test)]
mod tests {
    use super::spread_labels;

    /// Boxes 20 × 20, 10 beyond the heads; each place worked out by hand.
    #[test]
    fn labels_that_would_cover_one_another_are_moved_apart() {
        let size = [20.0, 20.0];
        let right = ([0.0, 0.0], [100.0, 0.0]);
        // Two directions: each label where it would be alone.
        let apart = spread_labels(&[right, ([0.0, 0.0], [0.0, 100.0])], size, 10.0, &[]);
        assert_eq!(apart, [[110.0, 0.0], [0.0, 110.0]]);
        // One direction twice: the second goes beside the first, a box across the shaft (on
        // its left as the arrow points: +y, image rows going down).
        let same = spread_labels(&[right, right], size, 10.0, &[]);
        assert_eq!(same, [[110.0, 0.0], [110.0, 20.0]]);
        // Three times: the third on the right side (−y).
        let three = spread_labels(&[right, right, right], size, 10.0, &[]);
        assert_eq!(three[2], [110.0, -20.0]);
        // A fourth and a fifth: two boxes across, (110, 40) and (110, −40).
        let five = spread_labels(&[right; 5], size, 10.0, &[]);
        assert_eq!(five[3..], [[110.0, 40.0], [110.0, -40.0]]);
        // A sixth: its five places at 110 are taken; half a box out, (120, 0) meets the
        // first (10 apart), (120, ±20) the second and third, (120, ±40) the fourth and fifth;
        // at 130, (130, 0) touches them.
        let six = spread_labels(&[right; 6], size, 10.0, &[]);
        assert_eq!(six[5], [130.0, 0.0]);
        // A legend over (100..200, −50..5) covers the first place; (110, 20) is clear of it.
        let legend = [[100.0, -50.0], [200.0, 5.0]];
        let avoided = spread_labels(&[right], size, 10.0, &[legend]);
        assert_eq!(avoided, [[110.0, 20.0]]);
        // A legend over everything near the second arrow: it goes where it covers the legend
        // but not the first label, beside it at (110, 20).
        let everywhere = [[0.0, -500.0], [500.0, 500.0]];
        let crowded = spread_labels(&[right, right], size, 10.0, &[everywhere]);
        assert_eq!(crowded, [[110.0, 0.0], [110.0, 20.0]]);
        // An arrow with no length (a vector at the eye) beside a label at (50, 50): the eight
        // places 10 round (40.5, 50) all meet it; the first of the next ring, 30 to the right
        // at (70.5, 50), is 20.5 from it.
        let short = spread_labels(
            &[([0.0, 50.0], [40.0, 50.0]), ([40.0, 50.0], [40.5, 50.0])],
            size,
            10.0,
            &[],
        );
        assert_eq!(short, [[50.0, 50.0], [70.5, 50.0]]);
        // An arrow pointing at the shaft of another, (50, −40) to (50, −15) towards y = 0:
        // its label 10 beyond the head, (50, −5), and beside it, (30 | 70 | 10 | 90, −5), all
        // straddle the first shaft; half a box further, (50, 5) still does (−5..15); a box
        // further, (50, 15), is clear (5..25). Alone, it would stay at (50, −5).
        let across = ([50.0, -40.0], [50.0, -15.0]);
        let off = spread_labels(&[right, across], size, 10.0, &[]);
        assert_eq!(off, [[110.0, 0.0], [50.0, 15.0]]);
        assert_eq!(spread_labels(&[across], size, 10.0, &[]), [[50.0, -5.0]]);
    }

    /// A segment through a box's inside crosses it; one along its edge, ending at its edge or
    /// passing by does not.
    #[test]
    fn a_shaft_crosses_a_box_only_through_its_inside() {
        let (c, size) = ([0.0, 0.0], [20.0, 20.0]);
        assert!(super::crosses(c, size, [-50.0, 0.0], [50.0, 0.0]));
        assert!(super::crosses(c, size, [-50.0, -50.0], [50.0, 50.0]));
        assert!(
            super::crosses(c, size, [1.0, 1.0], [2.0, 2.0]),
            "wholly inside"
        );
        assert!(
            !super::crosses(c, size, [-50.0, 10.0], [50.0, 10.0]),
            "along the edge"
        );
        assert!(
            !super::crosses(c, size, [-50.0, 0.0], [-10.0, 0.0]),
            "ending at the edge"
        );
        assert!(
            !super::crosses(c, size, [-50.0, 30.0], [50.0, 11.0]),
            "passing by"
        );
        assert!(
            !super::crosses(c, size, [-20.0, 0.0], [0.0, 20.0]),
            "through a corner"
        );
    }
}
