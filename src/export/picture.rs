//! A step's picture as the app shows it, for handouts and slides: the stage's buffer with the
//! step's overlays (edges, bounding boxes, sample points), the inspected pixel framed with its
//! lighting vectors, the selected vertex, the profile line and its chart; settings compared side
//! by side with their names; the observer view where the step's stage is a space or its layout
//! shows it. The shapes are the core's (`overlay::Shape`, `FrameCapture::lighting_arrows`), the
//! ones the app draws.

use anyhow::Result;
use image::{Rgba, RgbaImage, imageops};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::overlay::{OverlayKind, Shape};

use super::composing::{above, beside, bottom_note, centred_label, darken};
use super::palette::Palette;
use super::text;
use crate::lesson::script::{Layout, Overlay};
use crate::lesson::{Lesson, SceneSpec};
use crate::spaces;
use crate::vocabulary::{Lang, Space, lighting_legend, profile, variant_label};
use glam::Vec3;

/// What one step rendered: its scene, its capture and the compared settings' captures.
pub struct Rendered<'a> {
    /// The scene as the step (at this moment of its animation) sets it.
    pub spec: &'a SceneSpec,
    /// The capture of the step's settings.
    pub capture: &'a FrameCapture,
    /// The compared settings, by name, when the step compares.
    pub variants: &'a [(String, FrameCapture)],
}

/// The yellow of the selection (the app's `palette::SELECTED`).
const SELECTED: [u8; 4] = [255, 215, 0, 255];
/// The most overlay shapes drawn (as in the app).
const MAX_SHAPES: usize = 20_000;
/// The width a buffer is magnified towards (by a whole factor, so pixels stay square).
const TARGET_WIDTH: u32 = 640;

/// Step `k`'s picture, its drawings in `palette`.
///
/// # Errors
/// When the chart cannot be drawn.
pub fn step_picture(
    lesson: &Lesson,
    k: usize,
    r: &Rendered<'_>,
    (lang, palette): (Lang, Palette),
) -> Result<RgbaImage> {
    let step = &lesson.steps[k];
    let stage = lesson.stage_at(k);
    let buffer = lesson.buffer_at(k);
    // The scene from outside, at least as wide as a magnified buffer (a 24×16 lesson image
    // would give a 24×16 observer view).
    let focus = step.focus.as_deref().unwrap_or_default();
    let observer = || {
        let mut big = r.spec.clone();
        let z = zoom_for(big.settings.width);
        big.settings.width *= z;
        big.settings.height *= z;
        crate::observer::observer_image(&big, r.capture, focus, step.orbit)
    };
    if let Some(space) = stage.space() {
        let normals = step
            .overlays
            .as_deref()
            .is_some_and(|o| o.contains(&Overlay::Normals));
        let own = space_picture(
            r.capture,
            space,
            focus,
            (step.vertex, normals),
            (lang, palette),
        );
        return Ok(match (own, step.layout, observer()) {
            (Some(a), Layout::Observer, Some(o)) => beside(&a, &o),
            (Some(a), ..) => a,
            (None, _, Some(o)) => o,
            (None, _, None) => r.capture.image(BufferKind::Color),
        });
    }
    let line = step.profile_line(r.capture.width(), r.capture.height());
    let picture = if step.compare.is_some() && !r.variants.is_empty() {
        side_by_side(r.variants, buffer, line, lang)
    } else {
        let (w, h) = (r.capture.width(), r.capture.height());
        let shapes = Shapes {
            overlays: step.overlays.as_deref().unwrap_or_default(),
            // A pixel outside an image exported at another size is not drawn.
            pixel: step.pixel.filter(|&(x, y)| x < w && y < h),
            vertex: step.vertex,
            line,
            depth_range: step.depth_range,
        };
        let gain = r.capture.term_gain(buffer);
        let mut img = buffer_with_shapes(r.capture, (buffer, gain), &shapes, lang);
        // The objects a step compares, named above them as the app names them.
        let z = zoom_for(r.capture.width()) as f32;
        let points = r.capture.object_label_points();
        for ([x, y], name) in r.spec.object_labels(r.capture, &points, lang) {
            centred_label(&mut img, x * z, y * z - 18.0, &name);
        }
        if let Some(note) = crate::vocabulary::gain_note(buffer, gain, lang) {
            bottom_note(&mut img, &note);
        }
        let img = match watched(r.capture, zoom_for(w), lang) {
            Some(w) => beside(&img, &w),
            None => img,
        };
        match (step.layout, observer()) {
            (Layout::Observer, Some(o)) => beside(&img, &o),
            _ => img,
        }
    };
    let Some(line) = line else {
        return Ok(picture);
    };
    let curves: Vec<(String, Vec<[f64; 2]>)> = if r.variants.is_empty() {
        let name = crate::vocabulary::buffer_name(buffer, lang).to_owned();
        vec![(name, profile::points(r.capture, line))]
    } else {
        r.variants
            .iter()
            .map(|(n, c)| (variant_label(n, lang), profile::points(c, line)))
            .collect()
    };
    let chart_h = (picture.width() * 2 / 5).clamp(240, 760);
    let chart = super::chart::profile_chart(&curves, (lang, palette), picture.width(), chart_h)?;
    Ok(above(&picture, &chart))
}

/// The variable picture a frame drawn with a watch kept (`ShaderRecord::watch`), magnified `z`
/// times as the buffer beside it is, its expression and line written at its top.
fn watched(capture: &FrameCapture, z: u32, lang: Lang) -> Option<RgbaImage> {
    let picture = capture.shaders.as_ref()?.watch.as_ref()?;
    let drawn = picture.drawn(pipeline::capture::WatchView::Value);
    let mut img = image::imageops::resize(
        &drawn.image,
        drawn.image.width() * z,
        drawn.image.height() * z,
        image::imageops::FilterType::Nearest,
    );
    let title = lang.t_with(
        "picture-watch-title",
        &[("expression", &picture.expression), ("line", &picture.line)],
    );
    let middle = img.width() as f32 / 2.0;
    centred_label(&mut img, middle, 18.0, &title);
    Some(img)
}

/// The legend of step `k`'s drawings that its picture leaves to the page or slide around it
/// (drawn there at their own size, clear of the subject): the lighting vectors' names, when
/// the step's inspected pixel draws them; the variable picture's colours, when it draws one;
/// the triangles' fates and their lines, on a geometry stage.
#[must_use]
pub fn legend(lesson: &Lesson, k: usize, capture: &FrameCapture, lang: Lang) -> Vec<String> {
    let (w, h) = (capture.width(), capture.height());
    let mut lines: Vec<String> = lesson.steps[k]
        .pixel
        .filter(|&(x, y)| x < w && y < h && !capture.lighting_arrows(x, y).is_empty())
        .map(|_| lighting_legend(lang).map(str::to_owned).to_vec())
        .unwrap_or_default();
    if let Some(picture) = capture.shaders.as_ref().and_then(|s| s.watch.as_ref()) {
        lines.push(watch_legend(picture, lang));
    }
    // A geometry stage's triangles, dashed by their fates: the key to the lines.
    if lesson.steps[k]
        .stage
        .and_then(crate::vocabulary::Stage::space)
        .is_some()
    {
        lines.push(spaces::fates_in_words(capture, lang));
    }
    lines
}

/// What the variable picture's colours stand for, in words.
fn watch_legend(picture: &pipeline::capture::WatchPicture, lang: Lang) -> String {
    use pipeline::shader::probe::WatchKind;
    let range = picture.range(0);
    let said = match (picture.kind, range) {
        (Some(WatchKind::Bool), _) => lang.t("picture-watch-holds").to_owned(),
        (Some(WatchKind::Float | WatchKind::Int), Some((lo, hi))) => lang.t_with(
            "picture-watch-range",
            &[
                ("lo", &crate::vocabulary::num(lo)),
                ("hi", &crate::vocabulary::num(hi)),
            ],
        ),
        _ => lang.t("picture-watch-vector").to_owned(),
    };
    lang.t_with(
        if picture.from_vertex {
            "picture-watch-legend-vertex"
        } else {
            "picture-watch-legend-fragment"
        },
        &[
            ("expression", &picture.expression),
            ("line", &picture.line),
            ("said", &said),
        ],
    )
}

/// The polylines of the segment `a`–`b` (picture pixels) in a pen's colour and width, solid
/// with no dashes, else in them (`spaces::dashed`, as the app dashes a fate's edges).
fn pen_segments(
    a: [f32; 2],
    b: [f32; 2],
    (color, width, dashes): ([u8; 4], f32, &[f32]),
) -> impl Iterator<Item = Shape> {
    spaces::dashed(a, b, dashes, 1.0)
        .into_iter()
        .map(move |[p, q]| Shape::Polyline {
            points: vec![p, q],
            closed: false,
            color,
            width,
        })
}

/// The size of a geometry stage's picture.
const SPACE_PICTURE: (u32, u32) = (800, 600);

/// A geometry stage as the app draws it: the vertices in `space` as a wireframe coloured by
/// each triangle's fate (the subject bright, the rest dim), the space's axes and its view
/// volume, from the app's first orbit, framing the subject; the space named at the top.
/// `(vertex, normals)`: the selected vertex, and whether the world view draws the vertex normals.
fn space_picture(
    capture: &FrameCapture,
    space: Space,
    focus: &[String],
    (vertex, normals): (Option<u32>, bool),
    (lang, palette): (Lang, Palette),
) -> Option<RgbaImage> {
    let print = palette == Palette::Print;
    let ink = |rgb: [u8; 3], a: u8| palette.ink(rgb, a);
    let subject = spaces::subject(capture, focus, vertex, space);
    let (centre, radius) = spaces::bounds(capture, [space, space], &subject)?;
    let (w, h) = SPACE_PICTURE;
    let m = spaces::framing(
        centre,
        radius.max(1e-3),
        spaces::YAW,
        spaces::PITCH,
        w as f32 / h as f32,
    )?;
    let project = |p: Vec3| -> Option<[f32; 2]> {
        let c = m * p.extend(1.0);
        (c.w > 1e-6 && c.is_finite()).then(|| {
            let n = c.truncate() / c.w;
            [(n.x + 1.0) / 2.0 * w as f32, (1.0 - n.y) / 2.0 * h as f32]
        })
    };
    let mut shapes = Vec::new();
    // A segment in world coordinates, drawn with a pen (colour, width, dashes).
    let mut segment = |a: Vec3, b: Vec3, pen: ([u8; 4], f32, &[f32])| {
        if let (Some(a), Some(b)) = (project(a), project(b)) {
            shapes.extend(pen_segments(a, b, pen));
        }
    };
    if let Some(v) = spaces::volume(capture, space) {
        let (near, far) = (
            ink(crate::palette::NEAR, 255),
            ink(crate::palette::FAR, 255),
        );
        for i in 0..4 {
            segment(v[i], v[(i + 1) % 4], (near, 1.5, &[]));
            segment(v[4 + i], v[4 + (i + 1) % 4], (far, 1.2, &[]));
            segment(v[i], v[4 + i], (far, 1.2, &[]));
        }
    }
    let points: Vec<Option<Vec3>> = capture
        .vertices
        .iter()
        .map(|v| {
            let shown = space != Space::Model || subject[v.object as usize];
            shown.then(|| spaces::position(v, space)).flatten()
        })
        .collect();
    let stride = capture.primitives.len().div_ceil(30_000).max(1);
    for prim in capture.primitives.iter().step_by(stride) {
        let focused = subject.get(prim.object as usize).copied().unwrap_or(false);
        let fate = spaces::fate_index(&prim.fate);
        // The drawn triangles are white on screen: black ink on paper.
        let rgb = match (print, fate) {
            (true, 0) => [40, 40, 40],
            _ => spaces::FATES[fate].0,
        };
        let (color, width) = if focused {
            (ink(rgb, 255), 1.3)
        } else {
            (ink(rgb, 80), 0.8)
        };
        if let [Some(a), Some(b), Some(c)] = prim.vertices.map(|i| points[i as usize]) {
            for [p, q] in [[a, b], [b, c], [c, a]] {
                segment(p, q, (color, width, spaces::FATE_DASHES[fate]));
            }
        }
    }
    if normals && space == Space::World {
        for (v, p) in capture.vertices.iter().zip(&points) {
            if let Some(p) = p {
                let tip = *p + v.normal_world * (radius * 0.12);
                segment(*p, tip, (ink([90, 210, 230], 255), 1.5, &[]));
            }
        }
    }
    let axes = [
        (Vec3::X, crate::palette::X, "x"),
        (Vec3::Y, crate::palette::Y, "y"),
        (Vec3::Z, crate::palette::Z, "z"),
    ];
    let length = radius * 0.6;
    for (axis, rgb, _) in axes {
        segment(Vec3::ZERO, axis * length, (ink(rgb, 255), 2.0, &[]));
    }
    let labels: Vec<([f32; 2], [u8; 3], &str)> = axes
        .iter()
        .filter_map(|&(axis, rgb, name)| {
            let [r, g, b, _] = ink(rgb, 255);
            Some((project(axis * length * 1.08)?, [r, g, b], name))
        })
        .collect();
    paint(
        (w, h),
        &shapes,
        &labels,
        spaces::space_name(space, lang),
        palette,
    )
}

/// A `w`×`h` drawing: `shapes` on the palette's ground, the axes' `labels` and the `title`
/// (light on a dark box on screen, dark ink in print).
fn paint(
    (w, h): (u32, u32),
    shapes: &[Shape],
    labels: &[([f32; 2], [u8; 3], &str)],
    title: &str,
    palette: Palette,
) -> Option<RgbaImage> {
    let print = palette == Palette::Print;
    let mut pixmap = tiny_skia::Pixmap::new(w, h)?;
    let ground = if print { 255 } else { 18 };
    pixmap.fill(tiny_skia::Color::from_rgba8(ground, ground, ground, 255));
    pipeline::overlay::draw(&mut pixmap, shapes, 1.0);
    let mut img = RgbaImage::from_raw(w, h, pixmap.take())?;
    for &([x, y], rgb, name) in labels {
        text::draw(&mut img, x - 5.0, y + 7.0, 20.0, rgb, name);
    }
    if print {
        text::draw(&mut img, 18.0, 34.0, 22.0, [30, 30, 30], title);
    } else {
        darken(&mut img, 8, 8, text::width(title, 22.0) as u32 + 20, 36);
        text::draw(&mut img, 18.0, 34.0, 22.0, [235, 235, 235], title);
    }
    Some(img)
}

/// What is drawn over a buffer.
struct Shapes<'a> {
    overlays: &'a [Overlay],
    pixel: Option<(u32, u32)>,
    vertex: Option<u32>,
    line: Option<[f32; 4]>,
    /// The depth buffer's grey ramp (`depth_range`); `None`: the image's own.
    depth_range: Option<[f32; 2]>,
}

/// The whole factor that brings `width` nearest to the target width (at least 1, at most 32).
fn zoom_for(width: u32) -> u32 {
    (TARGET_WIDTH / width.max(1)).clamp(1, 32)
}

/// `kind` of `capture`, magnified, with the shapes drawn and the lighting vectors named.
fn buffer_with_shapes(
    capture: &FrameCapture,
    (kind, gain): (BufferKind, f32),
    s: &Shapes<'_>,
    lang: Lang,
) -> RgbaImage {
    let zoom = zoom_for(capture.width());
    let z = zoom as f32;
    let mut shapes: Vec<Shape> = Vec::new();
    // As the app draws them: the triangles in sight, the inspected pixel's strongly.
    let visible = capture.visible_triangles();
    let focus = s.pixel.and_then(|(x, y)| capture.primitive_at(x, y));
    for o in s.overlays {
        let kind = match o {
            Overlay::Edges => OverlayKind::TriangleEdges,
            Overlay::BoundingBoxes => OverlayKind::BoundingBoxes,
            Overlay::Samples | Overlay::Normals => continue,
        };
        let focused = capture.overlay_shapes_focused(kind, visible.as_deref(), focus);
        shapes.extend(focused.take(MAX_SHAPES));
    }
    if s.overlays.contains(&Overlay::Samples) && zoom >= 6 {
        shapes.extend(sample_dots(capture, z));
    }
    if let Some(line) = s.line {
        shapes.push(Shape::Polyline {
            points: vec![[line[0], line[1]], [line[2], line[3]]],
            closed: false,
            color: [255, 220, 0, 255],
            width: 2.0,
        });
    }
    if let Some(v) = s.vertex.and_then(|i| capture.vertices.get(i as usize))
        && let Some(win) = v.window
    {
        let [x, y] = capture.window_to_image(win);
        let r = 7.0 / z;
        shapes.push(Shape::Rect {
            min: [x - r, y - r],
            max: [x + r, y + r],
            color: SELECTED,
            width: 2.5,
        });
    }
    let arrows = s
        .pixel
        .map(|(x, y)| capture.lighting_arrows(x, y))
        .unwrap_or_default();
    if let Some((x, y)) = s.pixel {
        let r = capture.grid().row(y.min(capture.height() - 1)) as f32;
        let pad = 1.5 / z;
        shapes.push(Shape::Rect {
            min: [x as f32 - pad, r - pad],
            max: [x as f32 + 1.0 + pad, r + 1.0 + pad],
            color: SELECTED,
            width: 2.0,
        });
    }
    shapes.extend(arrows.iter().map(|a| Shape::Arrow {
        from: a.from,
        to: a.to,
        color: a.color,
        width: 2.5,
    }));
    let mut img = if kind == BufferKind::Depth {
        capture.depth_image_with_shapes(s.depth_range, &shapes, zoom)
    } else {
        capture.image_with_shapes(kind, gain, &shapes, zoom)
    };
    // Each letter beyond its arrow's head, clear of the others (as the app places them).
    let ends: Vec<([f32; 2], [f32; 2])> = arrows
        .iter()
        .map(|a| (a.from.map(|v| v * z), a.to.map(|v| v * z)))
        .collect();
    let places = pipeline::overlay::spread_labels(&ends, [14.0, 20.0], 12.0, &[]);
    for (a, at) in arrows.iter().zip(places) {
        let [r, g, b, _] = a.color;
        text::draw(&mut img, at[0] - 5.0, at[1] + 7.0, 20.0, [r, g, b], a.name);
    }
    for l in &capture.labels {
        centred_label(&mut img, l.image[0] * z, l.image[1] * z, &l.text);
    }
    if kind == BufferKind::MipLevel {
        mip_legend(&mut img, lang);
    }
    img
}

/// The colours of the mip levels with their numbers, at the top-right (as the app shows them).
fn mip_legend(img: &mut RgbaImage, lang: Lang) {
    let (w, h) = (8 * 26 + 14, 62);
    let x0 = img.width().saturating_sub(w + 8);
    darken(img, x0, 8, w, h);
    let title = lang.t("picture-mip-level");
    text::draw(img, (x0 + 8) as f32, 26.0, 15.0, [255, 255, 255], title);
    for k in 0..8u32 {
        let c = pipeline::texture::level_color(k)
            .to_array()
            .map(|v| (v.clamp(0.0, 1.0) * 255.0) as u8);
        let x = x0 + 8 + k * 26;
        text::fill(img, x, 36, 22, 22, c);
        let label = if k == 7 {
            "7+".to_owned()
        } else {
            k.to_string()
        };
        let ink = if k == 0 || k == 3 {
            [0, 0, 0]
        } else {
            [255, 255, 255]
        };
        let lw = text::width(&label, 14.0);
        text::draw(img, x as f32 + 11.0 - lw / 2.0, 52.0, 14.0, ink, &label);
    }
}

/// Each pixel's samples: white where covered, dark grey where not (as the app draws them).
fn sample_dots(capture: &FrameCapture, zoom: f32) -> Vec<Shape> {
    let offsets = pipeline::raster::sample_offsets_image(capture.settings.samples);
    let radius = (zoom / 14.0).clamp(1.5, 5.0);
    let mut dots = Vec::new();
    for r in 0..capture.height() {
        let y = capture.grid().row(r);
        for c in 0..capture.width() {
            for (k, o) in offsets.iter().enumerate() {
                let covered = capture.samples.triangle[capture.samples.index(c, y, k)]
                    != pipeline::raster::NONE;
                dots.push(Shape::Dot {
                    center: [c as f32 + o[0], r as f32 + o[1]],
                    radius,
                    color: if covered {
                        [255, 255, 255, 255]
                    } else {
                        [70, 70, 70, 255]
                    },
                });
            }
        }
    }
    dots
}

/// The compared settings side by side (at most three in a row), each with its name in its
/// curve's colour and the profile line drawn across it.
fn side_by_side(
    variants: &[(String, FrameCapture)],
    kind: BufferKind,
    line: Option<[f32; 4]>,
    lang: Lang,
) -> RgbaImage {
    // Two, three in a row; four as 2×2.
    let columns = if variants.len() == 4 {
        2
    } else {
        variants.len().min(3) as u32
    };
    let rows = (variants.len() as u32).div_ceil(columns);
    let gain = FrameCapture::shared_term_gain(variants.iter().map(|(_, c)| c), kind);
    let tiles: Vec<RgbaImage> = variants
        .iter()
        .enumerate()
        .map(|(i, (name, cap))| {
            let shapes = Shapes {
                overlays: &[],
                pixel: None,
                vertex: None,
                line,
                depth_range: None,
            };
            let mut tile = buffer_with_shapes(cap, (kind, gain), &shapes, lang);
            let label = variant_label(name, lang);
            let [r, g, b] = profile::CURVE_COLORS[i % profile::CURVE_COLORS.len()];
            let size = (tile.width() as f32 / 16.0).clamp(20.0, 64.0);
            darken(
                &mut tile,
                0,
                0,
                (text::width(&label, size) + size) as u32,
                (size * 1.5) as u32,
            );
            text::draw(&mut tile, size / 2.0, size * 1.12, size, [r, g, b], &label);
            tile
        })
        .collect();
    let (tw, th) = (tiles[0].width(), tiles[0].height());
    let gap = 8;
    let mut out = RgbaImage::from_pixel(
        columns * tw + (columns - 1) * gap,
        rows * th + (rows - 1) * gap,
        Rgba([30, 30, 30, 255]),
    );
    for (i, t) in tiles.iter().enumerate() {
        let (c, r) = (i as u32 % columns, i as u32 / columns);
        imageops::overlay(
            &mut out,
            t,
            i64::from(c * (tw + gap)),
            i64::from(r * (th + gap)),
        );
    }
    if let Some(note) = crate::vocabulary::gain_note(kind, gain, lang) {
        bottom_note(&mut out, &note);
    }
    out
}
