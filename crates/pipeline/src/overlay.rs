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
