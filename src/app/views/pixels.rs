//! A pixel buffer as an image: zoom and pan, crisp pixels, the pixel grid, sample points and
//! overlays when zoomed in, values under the cursor, a click to inspect a pixel.

use egui::{Color32, Pos2, Rect, RichText, Sense, Stroke, TextureOptions, Ui, Vec2};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::overlay::{OverlayKind, Shape};
use pipeline::raster::{NONE, sample_offsets_image};

use super::palette;
use crate::app::session::{Command, Selection, Session};
use crate::vocabulary::{Lang, buffer_name, num};

/// Zoom and pan of the pixel view, and its texture cache.
#[derive(Default)]
pub struct PixelView {
    /// Screen points per image pixel; `None` fits the image to the panel.
    zoom: Option<f32>,
    /// The image point at the centre of the view.
    centre: Option<Vec2>,
    /// The texture of the buffer shown, with the generation and kind it was made from.
    texture: super::BufferTexture,
}

fn overlay_name(kind: OverlayKind, l: Lang) -> &'static str {
    match kind {
        OverlayKind::TriangleEdges => l.tr("Triangle edges", "三角形边"),
        OverlayKind::BoundingBoxes => l.tr("Bounding boxes", "包围盒"),
    }
}

/// The most overlay shapes drawn at once (a million-triangle mesh would stall the UI).
const MAX_SHAPES: usize = 20_000;

impl PixelView {
    /// The toolbar: buffer, overlays, samples, zoom reset.
    pub fn toolbar(
        &mut self,
        ui: &mut Ui,
        sel: &Selection,
        available: &[BufferKind],
        lang: Lang,
    ) -> Vec<Command> {
        let mut cmds = Vec::new();
        ui.horizontal_wrapped(|ui| {
            egui::ComboBox::new("buffer", lang.tr("buffer", "缓冲"))
                .selected_text(buffer_name(sel.buffer, lang))
                .show_ui(ui, |ui| {
                    for kind in available.iter().copied() {
                        if ui
                            .selectable_label(sel.buffer == kind, buffer_name(kind, lang))
                            .on_hover_text(kind.mapping())
                            .clicked()
                        {
                            cmds.push(Command::SelectBuffer(kind));
                        }
                    }
                });
            for kind in OverlayKind::ALL {
                let mut on = sel.overlays.contains(&kind);
                if ui.checkbox(&mut on, overlay_name(kind, lang)).changed() {
                    cmds.push(Command::ToggleOverlay(kind));
                }
            }
            let mut samples = sel.show_samples;
            if ui
                .checkbox(&mut samples, lang.tr("Sample points", "采样点"))
                .on_hover_text(lang.tr(
                    "Zoom in to see each pixel's sample positions: filled when covered.",
                    "放大后显示每个像素的采样位置：被覆盖时为实心。",
                ))
                .changed()
            {
                cmds.push(Command::ToggleSamples);
            }
            if ui
                .button(lang.tr("Fit", "适应窗口"))
                .on_hover_text(lang.tr(
                    "Zoom to fit (double-click the image)",
                    "缩放以适应（双击图像）",
                ))
                .clicked()
            {
                self.zoom = None;
                self.centre = None;
            }
        });
        cmds
    }

    /// The depth buffer's drawing: linear or not, and its range.
    pub fn depth_controls(
        ui: &mut Ui,
        sel: &Selection,
        capture: &FrameCapture,
        lang: Lang,
    ) -> Option<Command> {
        let mut view = sel.depth_view;
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut view.linear, lang.tr("linear: eye distance", "线性：相机距离"))
                .on_hover_text(lang.tr(
                    "z_w is not linear in distance: d = 2fn/((f+n) − z_ndc·(f−n)). Most of [0, 1] goes to the near part of the frustum.",
                    "z_w 与距离不成线性：d = 2fn/((f+n) − z_ndc·(f−n))。[0, 1] 的大部分分给了视锥体的近处。",
                ));
            let value = |z: f32| if view.linear { capture.eye_depth(z) } else { z };
            let auto = capture.depth_range().map_or([0.0, 1.0], |[a, b]| [value(a), value(b)]);
            let mut range = view.range.unwrap_or(auto);
            let speed = ((range[1] - range[0]).abs() / 200.0).max(1e-5);
            let a = ui.add(egui::DragValue::new(&mut range[0]).speed(speed).max_decimals(5).prefix(lang.tr("black at ", "黑：")));
            let b = ui.add(egui::DragValue::new(&mut range[1]).speed(speed).max_decimals(5).prefix(lang.tr("white at ", "白：")));
            if a.changed() || b.changed() {
                view.range = Some(range);
            }
            if ui.button(lang.tr("auto range", "自动范围")).clicked() {
                view.range = None;
            }
            if view.linear != sel.depth_view.linear {
                view.range = None;
            }
        });
        (view != sel.depth_view).then_some(Command::SetDepthView(view))
    }

    /// The image view itself.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session, capture: &FrameCapture) -> Vec<Command> {
        let sel = &session.selection;
        let lang = session.lang;
        let mut cmds = Vec::new();
        let depth = sel.depth_view;
        let variant = if sel.buffer == BufferKind::Depth {
            let [a, b] = depth.range.unwrap_or([f32::NAN; 2]);
            (u64::from(a.to_bits()) << 32 | u64::from(b.to_bits())) ^ u64::from(depth.linear)
        } else {
            0
        };
        let texture = self.texture.get_with(
            ui.ctx(),
            "pixel-view",
            (session.shown_generation, sel.buffer, variant),
            TextureOptions::NEAREST,
            || match sel.buffer {
                BufferKind::Depth => capture.depth_image(depth.linear, depth.range),
                kind => capture.image(kind),
            },
        );
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        response.widget_info(|| {
            egui::WidgetInfo::labeled(egui::Role::Image, true, lang.tr("pixel view", "像素视图"))
        });
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(24));
        if response.double_clicked() {
            self.zoom = None;
            self.centre = None;
            return cmds;
        }
        let view = self.navigate(ui, &response, rect, capture);
        painter.image(
            texture.id(),
            Rect::from_min_max(
                view.to_screen([0.0, 0.0]),
                view.to_screen([view.size.x, view.size.y]),
            ),
            Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
            Color32::WHITE,
        );
        if view.zoom >= 6.0 {
            draw_grid(&painter, &view);
        }
        if view.zoom >= 14.0 && sel.show_samples {
            draw_samples(&painter, &view, capture);
        }
        draw_overlays(&painter, &view, capture, &sel.overlays, lang);
        draw_selection(&painter, &view, capture, sel);
        if sel.buffer.is_lighting() || sel.buffer == BufferKind::Color {
            draw_light_vectors(&painter, &view, capture, sel, lang);
        }
        if sel.buffer == BufferKind::MipLevel {
            draw_mip_legend(&painter, rect, lang);
        }
        if !capture.settings.capture.keeps(sel.buffer) {
            // The capture shown kept only what the previous view needed; the render that keeps
            // this buffer is under way.
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                lang.tr("rendering this buffer…", "正在渲染此缓冲…"),
                egui::FontId::proportional(18.0),
                Color32::from_gray(220),
            );
        }
        // Hover: the values of the pixel under the cursor; click: inspect it.
        if let Some(pos) = response.hover_pos()
            && let Some((c, y)) = view.window_pixel(pos, capture)
        {
            response
                .clone()
                .on_hover_ui_at_pointer(|ui| pixel_tooltip(ui, capture, c, y, lang));
            if response.clicked() {
                cmds.push(Command::SelectPixel(Some((c, y))));
                // Clicking a triangle selects its vertex nearest the click (its vertex-table row).
                let i = ((capture.height() - 1 - y) * capture.width() + c) as usize;
                if let Some(prim) = capture.primitives.get(capture.pixels.primitive[i] as usize) {
                    let click = view.to_image(pos);
                    let nearest = prim.vertices.iter().copied().min_by(|a, b| {
                        let d = |r: u32| {
                            capture.vertices[r as usize]
                                .window
                                .map_or(f32::INFINITY, |w| {
                                    let p = capture.window_to_image(w);
                                    (Vec2::new(p[0], p[1]) - click).length()
                                })
                        };
                        d(*a).total_cmp(&d(*b))
                    });
                    cmds.push(Command::SelectVertex(nearest));
                }
            }
        }
        cmds
    }

    /// Applies wheel zoom (about the cursor) and drag pan; returns the mapping to use.
    fn navigate(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        rect: Rect,
        capture: &FrameCapture,
    ) -> ImageViewport {
        let size = Vec2::new(capture.width() as f32, capture.height() as f32);
        let fit = (rect.width() / size.x).min(rect.height() / size.y);
        let range = (fit.min(1.0) * 0.5, 256.0);
        let mut zoom = self.zoom.unwrap_or(fit).clamp(range.0, range.1);
        let mut centre = self.centre.unwrap_or(size / 2.0);
        if let Some(pointer) = response.hover_pos() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y + i.zoom_delta().ln() * 200.0);
            if scroll != 0.0 {
                let new_zoom = (zoom * (scroll / 200.0).exp()).clamp(range.0, range.1);
                let under = centre + (pointer - rect.center()) / zoom;
                centre = under - (pointer - rect.center()) / new_zoom;
                zoom = new_zoom;
                self.zoom = Some(zoom);
            }
        }
        if response.dragged() {
            centre -= response.drag_delta() / zoom;
        }
        self.centre = Some(centre);
        ImageViewport {
            rect,
            centre,
            zoom,
            size,
        }
    }
}

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
        Shape::Dot {
            center,
            radius,
            color: c,
        } => {
            painter.circle_filled(to_screen(*center), *radius, color(*c));
        }
    }
}

/// The values of one pixel, for the hover tooltip.
fn pixel_tooltip(ui: &mut Ui, capture: &FrameCapture, x: u32, y: u32, lang: Lang) {
    let i = ((capture.height() - 1 - y) * capture.width() + x) as usize;
    let px = &capture.pixels;
    ui.label(RichText::new(format!("{} ({x}, {y})", lang.tr("pixel", "像素"))).strong());
    ui.label(format!(
        "{}: {}/{}",
        lang.tr("coverage", "覆盖"),
        px.coverage[i],
        capture.settings.samples.count()
    ));
    ui.label(format!(
        "{} z_w: {} ({} {})",
        lang.tr("depth", "深度"),
        num(px.depth[i]),
        lang.tr("eye distance", "相机距离"),
        num(capture.eye_depth(px.depth[i]))
    ));
    if let Some(bary) = capture.barycentrics(i) {
        let (b, a) = (bary.perspective, bary.affine);
        ui.label(format!(
            "{}: {}",
            lang.tr("primitive", "图元"),
            px.primitive[i]
        ));
        ui.label(format!(
            "b (persp.) = ({}, {}, {})",
            num(b[0]),
            num(b[1]),
            num(b[2])
        ));
        ui.label(format!(
            "λ (affine) = ({}, {}, {})",
            num(a[0]),
            num(a[1]),
            num(a[2])
        ));
    }
    let c = px.color[i];
    ui.label(format!(
        "RGB = ({}, {}, {})",
        num(c[0]),
        num(c[1]),
        num(c[2])
    ));
    ui.label(RichText::new(lang.tr("click to inspect", "单击查看详情")).weak());
}

/// Where the image is on screen: `centre` (image pixels) at the middle of `rect`, `zoom` screen
/// points per image pixel.
struct ImageViewport {
    rect: Rect,
    centre: Vec2,
    zoom: f32,
    size: Vec2,
}

impl ImageViewport {
    fn to_screen(&self, p: [f32; 2]) -> Pos2 {
        self.rect.center() + (Vec2::new(p[0], p[1]) - self.centre) * self.zoom
    }

    fn to_image(&self, s: Pos2) -> Vec2 {
        self.centre + (s - self.rect.center()) / self.zoom
    }

    /// The visible image pixels: columns `c0..c1`, rows `r0..r1`.
    fn visible(&self) -> (u32, u32, u32, u32) {
        let (a, b) = (self.to_image(self.rect.min), self.to_image(self.rect.max));
        (
            a.x.floor().clamp(0.0, self.size.x) as u32,
            a.y.floor().clamp(0.0, self.size.y) as u32,
            b.x.ceil().clamp(0.0, self.size.x) as u32,
            b.y.ceil().clamp(0.0, self.size.y) as u32,
        )
    }

    /// The window pixel (x, y up) under a screen point, if it is on the image.
    fn window_pixel(&self, pos: Pos2, capture: &FrameCapture) -> Option<(u32, u32)> {
        let ip = self.to_image(pos);
        (ip.x >= 0.0 && ip.y >= 0.0 && ip.x < self.size.x && ip.y < self.size.y)
            .then(|| (ip.x as u32, capture.height() - 1 - ip.y as u32))
    }
}

/// Pixel borders, when pixels are big enough to see them.
fn draw_grid(painter: &egui::Painter, view: &ImageViewport) {
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
fn draw_samples(painter: &egui::Painter, view: &ImageViewport, capture: &FrameCapture) {
    let (c0, r0, c1, r1) = view.visible();
    let offsets = sample_offsets_image(capture.settings.samples);
    let radius = (view.zoom / 14.0).clamp(1.5, 5.0);
    for r in r0..r1 {
        let y = capture.height() - 1 - r;
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

/// The selected overlays, from the capture's own shape descriptions.
fn draw_overlays(
    painter: &egui::Painter,
    view: &ImageViewport,
    capture: &FrameCapture,
    overlays: &[OverlayKind],
    lang: Lang,
) {
    let mut drawn = 0;
    for &kind in overlays {
        for shape in capture.overlay_shapes(kind).take(MAX_SHAPES - drawn) {
            drawn += 1;
            draw_shape(painter, &shape, &|p| view.to_screen(p));
        }
    }
    if drawn >= MAX_SHAPES {
        painter.text(
            view.rect.left_bottom() + Vec2::new(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            lang.tr(
                "overlays: first 20 000 shapes only",
                "叠加层：只显示前 20000 个图形",
            ),
            egui::FontId::proportional(13.0),
            Color32::YELLOW,
        );
    }
}

/// At the inspected pixel of a lit image, the vectors of the lighting drawn from the surface
/// point: the normal n, the light vector l, the view vector v and the half vector h (the capture
/// computes them; here they are only projected and drawn).
fn draw_light_vectors(
    painter: &egui::Painter,
    view: &ImageViewport,
    capture: &FrameCapture,
    sel: &Selection,
    lang: Lang,
) {
    let Some(v) = sel.pixel.and_then(|(x, y)| capture.pixel_vectors(x, y)) else {
        return;
    };
    let length = 0.15 * (capture.camera.eye - v.position).length();
    for (vector, name, color) in [
        (v.normal, "n", Color32::WHITE),
        (v.light, "l", Color32::from_rgb(255, 210, 60)),
        (v.view, "v", Color32::from_gray(150)),
        (v.half, "h", Color32::from_rgb(90, 220, 255)),
    ] {
        let Some([a, b]) = capture.world_segment_to_image(v.position, v.position + vector * length)
        else {
            continue;
        };
        let (a, b) = (view.to_screen(a), view.to_screen(b));
        painter.arrow(a, b - a, Stroke::new(2.5, color));
        painter.text(
            b + (b - a).normalized() * 10.0,
            egui::Align2::CENTER_CENTER,
            name,
            egui::FontId::proportional(18.0),
            color,
        );
    }
    // The legend, wrapped to the view's width (it may be half the panel beside the observer).
    let galley = painter.layout(
        lang.tr(
            "at the inspected pixel: n normal, l to the light, v to the eye, h = (l + v)/|l + v|",
            "在所检查的像素处：n 法线，l 指向光源，v 指向视点，h = (l + v)/|l + v|",
        )
        .to_owned(),
        egui::FontId::proportional(14.0),
        Color32::WHITE,
        view.rect.width() - 16.0,
    );
    painter.galley(
        view.rect.left_top() + Vec2::new(8.0, 8.0),
        galley,
        Color32::WHITE,
    );
}

/// The colours of the mip levels, with their numbers.
fn draw_mip_legend(painter: &egui::Painter, rect: Rect, lang: Lang) {
    let origin = rect.right_top() + Vec2::new(-230.0, 10.0);
    painter.rect_filled(
        Rect::from_min_size(origin, Vec2::new(220.0, 54.0)),
        4.0,
        Color32::from_black_alpha(190),
    );
    painter.text(
        origin + Vec2::new(8.0, 6.0),
        egui::Align2::LEFT_TOP,
        lang.tr("mip level", "mipmap 层级"),
        egui::FontId::proportional(13.0),
        Color32::WHITE,
    );
    for k in 0..8u32 {
        let c = pipeline::texture::level_color(k)
            .to_array()
            .map(|v| (v.clamp(0.0, 1.0) * 255.0) as u8);
        let at = origin + Vec2::new(8.0 + k as f32 * 26.0, 26.0);
        painter.rect_filled(
            Rect::from_min_size(at, Vec2::new(22.0, 22.0)),
            2.0,
            Color32::from_rgb(c[0], c[1], c[2]),
        );
        let label = if k == 7 {
            "7+".to_owned()
        } else {
            k.to_string()
        };
        painter.text(
            at + Vec2::new(11.0, 11.0),
            egui::Align2::CENTER_CENTER,
            label,
            egui::FontId::proportional(12.0),
            if k == 0 || k == 3 {
                Color32::BLACK
            } else {
                Color32::WHITE
            },
        );
    }
}

/// The selected vertex (a ring at its window position) and the inspected pixel (a frame).
fn draw_selection(
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
    }
    if let Some((x, y)) = sel.pixel {
        let r = (capture.height() - 1 - y) as f32;
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
