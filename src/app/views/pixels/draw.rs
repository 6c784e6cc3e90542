//! What the pixel view draws over the image: the pixel grid and sample points when zoomed in,
//! the overlays (the capture's own shapes), the lighting vectors at the inspected pixel, the
//! inspected pixel and the selected vertex, the inside test of the inspected pixel's triangle
//! (its edge functions), and the mip-level legend.

use crate::app::views::{picture_font, picture_mono};
use egui::{Color32, Pos2, Rect, Stroke, Vec2};
use pipeline::capture::FrameCapture;
use pipeline::overlay::{OverlayKind, Shape};
use pipeline::raster::{NONE, sample_offsets_image};

use super::viewport::ImageViewport;
use crate::app::session::Selection;
use crate::app::views::palette;
use crate::vocabulary::Lang;

/// The most overlay shapes drawn at once (a million-triangle mesh would stall the UI).
const MAX_SHAPES: usize = 20_000;

/// Draws an overlay shape (image pixel coordinates) with egui.
pub fn draw_shape(painter: &egui::Painter, shape: &Shape, to_screen: &dyn Fn([f32; 2]) -> Pos2) {
    let color = |c: [u8; 4]| Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]);
    match shape {
        Shape::Polyline {
            points,
            closed,
            color: c,
            width,
        } => {
            // Separate segments: a joined outline of a sliver triangle gets miter spikes.
            let pts: Vec<Pos2> = points.iter().map(|p| to_screen(*p)).collect();
            let stroke = Stroke::new(*width, color(*c));
            for pair in pts.windows(2) {
                painter.line_segment([pair[0], pair[1]], stroke);
            }
            if *closed && let (Some(first), Some(last)) = (pts.first(), pts.last()) {
                painter.line_segment([*last, *first], stroke);
            }
        }
        Shape::Rect {
            min,
            max,
            color: c,
            width,
        } => {
            painter.rect_stroke(
                Rect::from_min_max(to_screen(*min), to_screen(*max)),
                0.0,
                Stroke::new(*width, color(*c)),
                egui::StrokeKind::Middle,
            );
        }
        Shape::Arrow {
            from,
            to,
            color: c,
            width,
        } => {
            let (a, b) = (to_screen(*from), to_screen(*to));
            painter.arrow(a, b - a, Stroke::new(*width, color(*c)));
        }
        Shape::Dot {
            center,
            radius,
            color: c,
        } => {
            painter.circle_filled(to_screen(*center), *radius, color(*c));
        }
    }
}

/// Pixel borders, when pixels are big enough to see them.
pub(super) fn draw_grid(painter: &egui::Painter, view: &ImageViewport) {
    let (c0, r0, c1, r1) = view.visible();
    let stroke = Stroke::new(1.0, Color32::from_rgba_unmultiplied(128, 128, 128, 90));
    for c in c0..=c1 {
        let x = c as f32;
        painter.line_segment(
            [
                view.to_screen([x, r0 as f32]),
                view.to_screen([x, r1 as f32]),
            ],
            stroke,
        );
    }
    for r in r0..=r1 {
        let y = r as f32;
        painter.line_segment(
            [
                view.to_screen([c0 as f32, y]),
                view.to_screen([c1 as f32, y]),
            ],
            stroke,
        );
    }
}

/// Each visible pixel's sample positions (filled when covered) and, with several samples, its centre.
pub(super) fn draw_samples(painter: &egui::Painter, view: &ImageViewport, capture: &FrameCapture) {
    let (c0, r0, c1, r1) = view.visible();
    let offsets = sample_offsets_image(capture.settings.samples);
    let radius = (view.zoom / 14.0).clamp(1.5, 5.0);
    for r in r0..r1 {
        let y = capture.grid().row(r);
        for c in c0..c1 {
            for (k, o) in offsets.iter().enumerate() {
                let p = view.to_screen([c as f32 + o[0], r as f32 + o[1]]);
                if capture.samples.triangle[capture.samples.index(c, y, k)] != NONE {
                    painter.circle_filled(p, radius, Color32::WHITE);
                }
                painter.circle_stroke(p, radius, Stroke::new(1.0, Color32::BLACK));
            }
            if offsets.len() > 1 {
                let m = view.to_screen([c as f32 + 0.5, r as f32 + 0.5]);
                let s = Stroke::new(1.0, Color32::GRAY);
                painter.line_segment([m - Vec2::X * 3.0, m + Vec2::X * 3.0], s);
                painter.line_segment([m - Vec2::Y * 3.0, m + Vec2::Y * 3.0], s);
            }
        }
    }
}

/// The selected overlays, from the capture's own shape descriptions: the triangles in sight
/// (`visible`), the primitive `focus` strongly and the rest faintly.
pub(super) fn draw_overlays(
    painter: &egui::Painter,
    view: &ImageViewport,
    capture: &FrameCapture,
    (overlays, visible, focus): (&[OverlayKind], Option<&[bool]>, Option<u32>),
    lang: Lang,
) {
    let mut drawn = 0;
    for &kind in overlays {
        let shapes = capture.overlay_shapes_focused(kind, visible, focus);
        for shape in shapes.take(MAX_SHAPES - drawn) {
            drawn += 1;
            draw_shape(painter, &shape, &|p| view.to_screen(p));
        }
    }
    if drawn >= MAX_SHAPES {
        crate::app::views::label_with_background(
            painter,
            view.rect.left_bottom() + Vec2::new(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            lang.t("draw-overlays-first-20-000-shapes"),
            &picture_font(painter.ctx(), 13.0),
            Color32::YELLOW,
        );
    }
}

/// At the inspected pixel of a lit image, the vectors of the lighting drawn from the surface
/// point: the normal n, the light vector l, the view vector v and the half vector h (the capture
/// computes them; here they are only projected and drawn).
pub(super) fn draw_light_vectors(
    painter: &egui::Painter,
    view: &ImageViewport,
    capture: &FrameCapture,
    sel: &Selection,
    (subject, lang): (&[Rect], Lang),
) -> Option<Rect> {
    let arrows = sel
        .pixel
        .map(|(x, y)| capture.lighting_arrows(x, y))
        .unwrap_or_default();
    if arrows.is_empty() {
        return None;
    }
    for arrow in &arrows {
        let shape = Shape::Arrow {
            from: arrow.from,
            to: arrow.to,
            color: arrow.color,
            width: 2.5,
        };
        draw_shape(painter, &shape, &|p| view.to_screen(p));
    }
    // The legend, typeset, on a dark box in a corner clear of the subject and of the narration.
    let card = crate::app::views::card_placement::narration_card(painter.ctx());
    let style = crate::app::views::typeset::Style {
        size: picture_font(painter.ctx(), 15.0).size,
        color: Color32::WHITE,
        accent: Color32::from_rgb(255, 214, 120),
    };
    // Its two lines, or each part between the " · " on a line of its own (a narrower, taller
    // box), whichever covers the least of the subject (the two lines where both are clear).
    let wide: Vec<&str> = crate::vocabulary::lighting_legend(lang).to_vec();
    let narrow: Vec<&str> = wide.iter().flat_map(|l| l.split(" · ")).collect();
    let size = |lines: &[&str]| {
        let sizes: Vec<Vec2> = lines
            .iter()
            .map(|line| crate::app::views::typeset::formula_size(painter, line, &style))
            .collect();
        Vec2::new(
            sizes.iter().map(|s| s.x).fold(0.0, f32::max),
            sizes.iter().map(|s| s.y + 4.0).sum::<f32>() - 4.0,
        ) + Vec2::splat(10.0)
    };
    let (k, legend) =
        crate::app::views::clear_corner(&[size(&wide), size(&narrow)], view.rect, (subject, card));
    let lines = if k == 0 { wide } else { narrow };
    painter.rect_filled(legend, 4.0, Color32::from_black_alpha(180));
    let mut at = legend.min + Vec2::splat(5.0);
    for line in &lines {
        let r = crate::app::views::typeset::paint_formula(
            painter,
            at,
            egui::Align2::LEFT_TOP,
            line,
            &style,
        );
        at.y = r.bottom() + 4.0;
    }
    // The letters over every shaft, each on its box (it lies on the lit surface, which may be
    // as light as it is), clear of one another and of the legend: on a small picture the
    // arrows are short and their letters met at the pixel.
    let font = picture_font(painter.ctx(), 18.0);
    let letter = painter
        .layout_no_wrap("h".to_owned(), font.clone(), Color32::WHITE)
        .size()
        + Vec2::splat(6.0);
    let ends: Vec<([f32; 2], [f32; 2])> = arrows
        .iter()
        .map(|a| {
            let (from, to) = (view.to_screen(a.from), view.to_screen(a.to));
            ([from.x, from.y], [to.x, to.y])
        })
        .collect();
    let avoid = [[legend.min, legend.max].map(|p| [p.x, p.y])];
    let places = pipeline::overlay::spread_labels(&ends, [letter.x, letter.y], 14.0, &avoid);
    for (arrow, [x, y]) in arrows.iter().zip(places) {
        let [r, g, b, _] = arrow.color;
        crate::app::views::label_with_background(
            painter,
            Pos2::new(x, y),
            egui::Align2::CENTER_CENTER,
            arrow.name,
            &font,
            Color32::from_rgb(r, g, b),
        );
    }
    Some(legend)
}

/// The colours of the mip levels, with their numbers, on a dark box in a corner of `rect`
/// clear of the `subject`, at the size of the words over pictures (larger in classroom mode):
/// the eight swatches in a row, or where no corner has room for the row, in two rows of four
/// or four of two (beside a picture that fills the view's width, in the bars at its sides),
/// whichever covers the least of the subject.
/// Returns the box.
pub(super) fn draw_mip_legend(
    painter: &egui::Painter,
    rect: Rect,
    (subject, lang): (&[Rect], Lang),
) -> Rect {
    let title = painter.layout_no_wrap(
        lang.t("draw-mip-level").to_owned(),
        picture_font(painter.ctx(), 13.0),
        Color32::WHITE,
    );
    let number = picture_font(painter.ctx(), 12.0);
    // A swatch holds its number with a little room: the number's line height and a third.
    let swatch = painter.ctx().fonts_mut(|f| f.row_height(&number)) * 4.0 / 3.0;
    let (pad, gap) = (8.0, swatch * 0.18);
    let size = |columns: u32| {
        let rows = 8u32.div_ceil(columns) as f32;
        let columns = columns as f32;
        Vec2::new(
            (pad * 2.0 + columns * swatch + (columns - 1.0) * gap).max(title.size().x + pad * 2.0),
            pad + title.size().y + 4.0 + rows * swatch + (rows - 1.0) * gap + pad,
        )
    };
    let shapes = [8, 4, 2];
    let card = crate::app::views::card_placement::narration_card(painter.ctx());
    let (k, legend) = crate::app::views::clear_corner(&shapes.map(size), rect, (subject, card));
    let columns = shapes[k];
    painter.rect_filled(legend, 4.0, Color32::from_black_alpha(190));
    let top = legend.top() + pad + title.size().y + 4.0;
    painter.galley(
        legend.min + Vec2::new(pad, pad - 2.0),
        title,
        Color32::WHITE,
    );
    for k in 0..8u32 {
        let c = pipeline::texture::level_color(k)
            .to_array()
            .map(|v| (v.clamp(0.0, 1.0) * 255.0) as u8);
        let (column, row) = ((k % columns) as f32, (k / columns) as f32);
        let at = Pos2::new(
            legend.left() + pad + column * (swatch + gap),
            top + row * (swatch + gap),
        );
        let fill = Color32::from_rgb(c[0], c[1], c[2]);
        painter.rect_filled(Rect::from_min_size(at, Vec2::splat(swatch)), 2.0, fill);
        let label = if k == 7 {
            "7+".to_owned()
        } else {
            k.to_string()
        };
        painter.text(
            at + Vec2::splat(swatch / 2.0),
            egui::Align2::CENTER_CENTER,
            label,
            number.clone(),
            crate::app::views::palette::ink_on(fill),
        );
    }
    legend
}

/// The names of the objects a step compares, each above its object, on a dark box.
pub(super) fn draw_object_labels(
    painter: &egui::Painter,
    view: &ImageViewport,
    names: &[([f32; 2], String)],
) {
    let font = picture_font(painter.ctx(), 17.0);
    for (at, name) in names {
        crate::app::views::label_with_background(
            painter,
            view.to_screen(*at) - Vec2::new(0.0, 8.0),
            egui::Align2::CENTER_BOTTOM,
            name,
            &font,
            Color32::WHITE,
        );
    }
}

/// The meshes' labels (a Bézier curve's P0…P3 and t) centred on their points, in the picture's
/// type, which grows in classroom mode.
pub(super) fn draw_labels(painter: &egui::Painter, view: &ImageViewport, capture: &FrameCapture) {
    let font = picture_font(painter.ctx(), 20.0);
    for l in &capture.labels {
        crate::app::views::label_with_background(
            painter,
            view.to_screen(l.image),
            egui::Align2::CENTER_CENTER,
            &l.text,
            &font,
            Color32::WHITE,
        );
    }
}

/// The selected vertex (a ring at its window position) and the inspected pixel (a frame).
pub(super) fn draw_selection(
    painter: &egui::Painter,
    view: &ImageViewport,
    capture: &FrameCapture,
    sel: &Selection,
) {
    if let Some(v) = sel.vertex.and_then(|i| capture.vertices.get(i as usize))
        && let Some(win) = v.window
    {
        let p = view.to_screen(capture.window_to_image(win));
        painter.circle_stroke(p, 7.0, Stroke::new(2.5, palette::SELECTED));
        if let Some(i) = sel.vertex {
            crate::app::views::label_with_background(
                painter,
                p + Vec2::new(9.0, -9.0),
                egui::Align2::LEFT_BOTTOM,
                &format!("v{i}"),
                &picture_mono(painter.ctx(), 14.0),
                palette::SELECTED,
            );
        }
    }
    if let Some((x, y)) = sel.pixel {
        let r = capture.grid().row(y.min(capture.height() - 1)) as f32;
        let a = view.to_screen([x as f32, r]);
        let b = view.to_screen([x as f32 + 1.0, r + 1.0]);
        painter.rect_stroke(
            Rect::from_min_max(a, b).expand(1.0),
            0.0,
            Stroke::new(2.0, palette::SELECTED),
            egui::StrokeKind::Outside,
        );
    }
}

/// Where the edges' labels go so that none covers one placed before it: label `i`, its text
/// `size` across (its box 3 points more each side), centred at `at` beside its edge of
/// direction `along`; where its box meets an earlier one, slid along its edge by its own
/// extent along the edge and a gap, one way then the other, up to three times (it stays beside
/// its edge); where no place is clear, where it was.
fn apart_along_edges(labels: &[(Pos2, Vec2, Vec2)]) -> Vec<Pos2> {
    let mut boxes: Vec<Rect> = Vec::with_capacity(labels.len());
    let mut out = Vec::with_capacity(labels.len());
    for &(at, size, along) in labels {
        let boxed = |p: Pos2| Rect::from_center_size(p, size).expand(3.0);
        // A degenerate edge has no direction (`along` NaN): every place is NaN, so it stays.
        let step = along.x.abs() * (size.x + 6.0) + along.y.abs() * (size.y + 6.0) + 4.0;
        let place = [0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0]
            .into_iter()
            .map(|k| at + along * step * k)
            .find(|p| p.is_finite() && !boxes.iter().any(|b| b.intersects(boxed(*p))))
            .unwrap_or(at);
        boxes.push(boxed(place));
        out.push(place);
    }
    out
}

/// The inside test of the inspected pixel's owning triangle, on the pixel grid: its three edges
/// in the colours of `E_0`, `E_1`, `E_2` with their values at the pixel centre, each sample
/// filled when covered, ringed where it lies exactly on an edge (the fill rule decided).
pub(super) fn draw_edge_test(
    painter: &egui::Painter,
    view: &ImageViewport,
    record: &pipeline::capture::PixelRecord,
    lang: Lang,
) {
    let Some(f) = record
        .fragments
        .iter()
        .find(|f| f.visible)
        .or(record.fragments.last())
    else {
        return;
    };
    let e = &f.edges;
    const EDGE: [Color32; 3] = [
        Color32::from_rgb(255, 110, 110),
        Color32::from_rgb(110, 235, 110),
        Color32::from_rgb(120, 170, 255),
    ];
    let font = picture_font(painter.ctx(), 15.0);
    // The edges' labels, drawn last, over the samples.
    let mut labels = Vec::with_capacity(3);
    for (k, &edge_color) in EDGE.iter().enumerate() {
        let (a, b) = (e.corners[(k + 1) % 3], e.corners[(k + 2) % 3]);
        let (pa, pb) = (view.window_to_screen(a), view.window_to_screen(b));
        painter.line_segment([pa, pb], Stroke::new(2.5, edge_color));
        // The label sits on the inner side of the edge (towards the opposite corner), at the
        // foot of the perpendicular from the pixel centre; where the edge passes through the
        // pixel's marker, it slides along the edge until it clears the marker.
        let centre = view.window_to_screen(e.centre_position);
        let length = (pb - pa).length();
        let along = (pb - pa).normalized();
        let t = (centre - pa).dot(along).clamp(0.0, length);
        let foot = pa + along * t;
        let opposite = view.window_to_screen(e.corners[k]);
        let normal = Vec2::new(-along.y, along.x);
        let inward = if (opposite - foot).dot(normal) < 0.0 {
            -normal
        } else {
            normal
        };
        let tl = if e.top_left[k] {
            lang.t("draw-top-left")
        } else {
            ""
        };
        let text = format!("E{k} = {}{tl}", crate::vocabulary::num(e.centre[k] as f32));
        let size = painter
            .layout_no_wrap(text.clone(), font.clone(), edge_color)
            .size();
        let width = size.x;
        let near = (centre - foot).length() < 24.0 + view.zoom / 2.0;
        let slide = if near {
            let clear = width / 2.0 + view.zoom.max(16.0);
            // Towards the longer part of the edge.
            if t < length / 2.0 { clear } else { -clear }
        } else {
            0.0
        };
        // Off the edge by a gap plus the label's own half extent across it.
        let off = 6.0 + (inward.x.abs() * size.x + inward.y.abs() * size.y) / 2.0;
        let at = foot
            + along * slide
            + if inward.is_finite() {
                inward * off
            } else {
                Vec2::ZERO
            };
        labels.push((at, size, along, text, edge_color));
    }
    let places = apart_along_edges(&labels.iter().map(|l| (l.0, l.1, l.2)).collect::<Vec<_>>());
    let radius = (view.zoom / 10.0).clamp(3.0, 7.0);
    for s in &e.samples {
        let p = view.window_to_screen(s.position);
        if s.inside {
            painter.circle_filled(p, radius, Color32::WHITE);
        }
        painter.circle_stroke(p, radius, Stroke::new(1.5, Color32::BLACK));
        for &k in &s.on_edges {
            painter.circle_stroke(p, radius + 3.0, Stroke::new(2.0, EDGE[k]));
        }
    }
    for ((_, _, _, text, color), at) in labels.into_iter().zip(places) {
        crate::app::views::label_with_background(
            painter,
            at,
            egui::Align2::CENTER_CENTER,
            &text,
            &font,
            color,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::apart_along_edges;
    use egui::{pos2, vec2};

    /// Labels 80 × 20 (boxes 86 × 26): one on a horizontal edge slides along it by 86 + 4;
    /// one on a vertical edge clear of the others stays; one on a vertical edge over the first
    /// slides by 26 + 4 — one step down meets the vertical one's box (122–148 against
    /// 117–143), one up the first's (62–88 against 87–113), so two steps down, to 165. Worked
    /// by hand.
    #[test]
    fn edge_labels_slide_along_their_edges_until_clear() {
        let size = vec2(80.0, 20.0);
        let places = apart_along_edges(&[
            (pos2(100.0, 100.0), size, vec2(1.0, 0.0)),
            (pos2(110.0, 100.0), size, vec2(1.0, 0.0)),
            (pos2(100.0, 130.0), size, vec2(0.0, 1.0)),
            (pos2(100.0, 105.0), size, vec2(0.0, 1.0)),
        ]);
        assert_eq!(
            places,
            vec![
                pos2(100.0, 100.0),
                pos2(200.0, 100.0),
                pos2(100.0, 130.0),
                pos2(100.0, 165.0),
            ]
        );
    }
}
