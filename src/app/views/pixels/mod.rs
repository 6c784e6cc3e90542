//! A pixel buffer as an image: zoom and pan, crisp pixels, the pixel grid, sample points and
//! overlays when zoomed in (see [`draw`]), values under the cursor, a click to inspect a pixel;
//! under the depth buffer the curve of window depth against distance, under a texturing buffer
//! the mip pyramid (see [`depth_and_mips`]); the pixel under the mouse — its values, the status
//! line, a click to inspect it — in [`hover`].

mod depth_and_mips;
mod draw;
mod hover;
mod texture;
mod viewport;

pub use draw::draw_shape;

use egui::{Color32, Pos2, Rect, Ui, Vec2};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::overlay::OverlayKind;

use crate::app::command::{SelectionCommand, ViewCommand};
use crate::app::session::{Command, Selection, Session};
use crate::app::views::picture_keys;
use crate::vocabulary::{Lang, buffer_name};
use viewport::{ImageViewport, layout};

/// Zoom and pan of the pixel view, its texture caches, and where it drew the picture.
pub struct PixelView {
    /// Screen points per image pixel; `None` fits the image to the panel.
    zoom: Option<f32>,
    /// The image point at the centre of the view.
    centre: Option<Vec2>,
    /// The textures of the buffer shown: the lesson's pixels, or finer.
    textures: texture::Textures,
    /// The mip levels' textures.
    pyramid: depth_and_mips::Pyramid,
    /// Show the mip pyramid under a texturing buffer.
    show_pyramid: bool,
    /// Draw the variable picture (the debugger's watch over the frame, or its cost view) in
    /// place of the buffer while there is one: the step's subject, big, on a phone too.
    show_watch: bool,
    /// Whether the image drew the variable picture this frame.
    pub drew_watch: bool,
    /// The inspected pixel's record, per capture and pixel.
    record: Option<(u64, (u32, u32), pipeline::capture::PixelRecord)>,
    /// Where the picture (the image, the depth curve, the pyramid) was drawn this frame.
    pub picture: Vec<Rect>,
    /// Where the step's subject in the image (the covered pixels, the inspected one) was
    /// drawn this frame, and the panel beside the image.
    pub subject: Vec<Rect>,
    /// The boxes of the words drawn over the picture this frame (the lighting vectors' legend,
    /// the mip levels' legend, the note on a term's gain): they must not cover the subject.
    pub words: Vec<Rect>,
    /// Which raster triangles own a sample, per capture shown (overlays leave out the rest).
    visible: Option<(u64, Option<Vec<bool>>)>,
    /// Where each object's name goes, per capture shown.
    label_points: Option<(u64, Vec<Option<[f32; 2]>>)>,
    /// The covered pixels' box (image pixels, y down), per capture shown: the subject the
    /// narration card must leave clear.
    covered: Option<(u64, Option<Rect>)>,
    /// The image's size on screen when fitted (points).
    fitted: Vec2,
}

impl Default for PixelView {
    fn default() -> Self {
        Self {
            zoom: None,
            centre: None,
            textures: texture::Textures::default(),
            pyramid: depth_and_mips::Pyramid::default(),
            show_pyramid: true,
            show_watch: true,
            drew_watch: false,
            record: None,
            picture: Vec::new(),
            subject: Vec::new(),
            words: Vec::new(),
            visible: None,
            label_points: None,
            covered: None,
            fitted: Vec2::ZERO,
        }
    }
}

/// The variable picture the selection asks for and the frame drew: the watch, or else the
/// cost view; `None` when neither, or when no fragment ran the watched line.
fn watched<'c>(
    session: &Session,
    capture: &'c FrameCapture,
) -> Option<&'c pipeline::capture::WatchPicture> {
    let sel = &session.selection;
    let record = capture.shaders.as_ref()?;
    let picture = match (&record.watch, &record.cost) {
        (Some(w), _) if sel.watch.is_some() => w,
        (_, Some(c)) if sel.cost => c,
        _ => return None,
    };
    (picture.kind.is_some() && picture.width == capture.width()).then_some(picture)
}

fn overlay_name(kind: OverlayKind, l: Lang) -> &'static str {
    match kind {
        OverlayKind::TriangleEdges => l.t("pixels-triangle-edges"),
        OverlayKind::BoundingBoxes => l.t("pixels-bounding-boxes"),
    }
}

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
            egui::ComboBox::new("buffer", lang.t("pixels-buffer"))
                .selected_text(buffer_name(sel.buffer, lang))
                .show_ui(ui, |ui| {
                    // The final colour first (the most used, and at the bottom of 17 it fell
                    // below the fold), then the buffers in the pipeline's order.
                    let colour = available
                        .iter()
                        .copied()
                        .filter(|&k| k == BufferKind::Color);
                    let rest = available
                        .iter()
                        .copied()
                        .filter(|&k| k != BufferKind::Color);
                    for (i, kind) in colour.chain(rest).enumerate() {
                        if i == 1 && available.contains(&BufferKind::Color) {
                            ui.separator();
                        }
                        if ui
                            .selectable_label(sel.buffer == kind, buffer_name(kind, lang))
                            .on_hover_text(kind.mapping())
                            .clicked()
                        {
                            cmds.push(Command::View(ViewCommand::SelectBuffer(kind)));
                        }
                    }
                });
            for kind in OverlayKind::ALL {
                let mut on = sel.overlays.contains(&kind);
                if ui.checkbox(&mut on, overlay_name(kind, lang)).changed() {
                    cmds.push(Command::View(ViewCommand::ToggleOverlay(kind)));
                }
            }
            let mut samples = sel.show_samples;
            if ui
                .checkbox(&mut samples, lang.t("pixels-sample-points"))
                .on_hover_text(lang.t("pixels-zoom-in-to-see-each"))
                .changed()
            {
                cmds.push(Command::View(ViewCommand::ToggleSamples));
            }
            if sel.buffer.is_texturing() {
                ui.checkbox(&mut self.show_pyramid, lang.t("pixels-mip-pyramid"))
                    .on_hover_text(lang.t("pixels-every-level-of-the-texture"));
            }
            if sel.watch.is_some() || sel.cost {
                ui.checkbox(&mut self.show_watch, lang.t("pixels-variable-picture"))
                    .on_hover_text(lang.t("pixels-the-shader-panel-s-watch"));
            }
            if ui
                .button(lang.t("pixels-fit"))
                .on_hover_text(lang.t("pixels-zoom-to-fit-double-click"))
                .clicked()
            {
                self.zoom = None;
                self.centre = None;
            }
        });
        cmds
    }

    /// The texture the image shows at magnification `zoom`, and its lighting term's gain: the
    /// variable picture while there is one and it is ticked, the buffer otherwise.
    fn texture(
        &mut self,
        ctx: &egui::Context,
        session: &Session,
        capture: &FrameCapture,
        zoom: f32,
    ) -> (egui::TextureHandle, f32) {
        let picture = self.show_watch.then(|| watched(session, capture)).flatten();
        self.drew_watch = picture.is_some();
        match picture {
            Some(picture) => (
                self.textures.watch(ctx, session.shown_generation, picture),
                1.0,
            ),
            None => self.textures.get(ctx, session, capture, zoom),
        }
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
            ui.checkbox(&mut view.linear, lang.t("pixels-linear-eye-distance"))
                .on_hover_text(lang.t("pixels-z-w-is-not-linear"));
            let value = |z: f32| if view.linear { capture.eye_depth(z) } else { z };
            let auto = capture
                .depth_range()
                .map_or([0.0, 1.0], |[a, b]| [value(a), value(b)]);
            let mut range = view.range.unwrap_or(auto);
            let speed = ((range[1] - range[0]).abs() / 200.0).max(1e-5);
            let a = ui.add(
                egui::DragValue::new(&mut range[0])
                    .speed(speed)
                    .max_decimals(5)
                    .prefix(lang.t("pixels-black-at")),
            );
            let b = ui.add(
                egui::DragValue::new(&mut range[1])
                    .speed(speed)
                    .max_decimals(5)
                    .prefix(lang.t("pixels-white-at")),
            );
            if a.changed() || b.changed() {
                view.range = Some(range);
            }
            if ui.button(lang.t("pixels-auto-range")).clicked() {
                view.range = None;
            }
            if view.linear != sel.depth_view.linear {
                view.range = None;
            }
        });
        (view != sel.depth_view).then_some(Command::View(ViewCommand::SetDepthView(view)))
    }

    /// The words over the picture, each kept in [`Self::words`]: the lighting vectors' legend,
    /// the mip levels' legend, why a buffer is not shown yet, and the note on a term's gain (at
    /// the top, clear of the narration card in the bottom-left).
    fn draw_words(
        &mut self,
        painter: &egui::Painter,
        (rect, view): (Rect, &ImageViewport),
        (session, capture): (&Session, &FrameCapture),
        (gain, offered): (f32, bool),
    ) {
        let (sel, lang) = (&session.selection, session.lang);
        if sel.buffer.is_lighting() || sel.buffer == BufferKind::Color {
            self.words.extend(draw::draw_light_vectors(
                painter,
                view,
                capture,
                sel,
                (&self.subject, lang),
            ));
        }
        if sel.buffer == BufferKind::MipLevel {
            let legend = draw::draw_mip_legend(painter, rect, (&self.subject, lang));
            self.words.push(legend);
        }
        hover::status_message(painter, rect, capture, sel.buffer, offered, lang);
        let top = (
            rect.center_top() + egui::Vec2::new(0.0, 8.0),
            egui::Align2::CENTER_TOP,
            rect.width() - 24.0,
        );
        self.words.extend(crate::app::views::draw_gain_note(
            painter, top, sel.buffer, gain, lang,
        ));
    }

    /// The image view itself.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session, capture: &FrameCapture) -> Vec<Command> {
        let sel = &session.selection;
        let lang = session.lang;
        let mut cmds = Vec::new();
        let card = crate::app::views::card_placement::narration_card(ui.ctx());
        let full = ui.available_rect_before_wrap();
        let offered = session.buffers.contains(&sel.buffer) || !sel.buffer.is_texturing();
        let wants_extra = sel.buffer == BufferKind::Depth
            || (sel.buffer.is_texturing() && self.show_pyramid && !capture.textures.is_empty());
        let (rect, extra) = layout(full, capture, wants_extra);
        let extra = extra.map(|e| crate::app::views::card_placement::right_of(e, card));
        let response = picture_keys::allocate(ui, rect, "pixel view");
        self.picture.clear();
        self.words.clear();
        crate::app::views::alt::name_picture(
            &response,
            lang.t("pixels-pixel-view"),
            (session, capture, sel.stage),
        );
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(24));
        if response.double_clicked() {
            self.zoom = None;
            self.centre = None;
            return cmds;
        }
        let keys = picture_keys::take(ui, &response, Some(picture_keys::Place::Main));
        let view = self.navigate(ui, (&response, session), (rect, keys), capture);
        cmds.extend(self.arrows(keys, &view, session, capture));
        // The physical pixels the fitted image covers: the finer render's size (`display`).
        let ppp = ui.ctx().pixels_per_point();
        let pixels = [
            (self.fitted.x * ppp).round() as u32,
            (self.fitted.y * ppp).round() as u32,
        ];
        if session.view_pixels != Some(pixels) {
            cmds.push(Command::View(ViewCommand::SetViewPixels(pixels)));
        }
        let (texture, gain) = self.texture(ui.ctx(), session, capture, view.zoom);
        let image = Rect::from_min_max(
            view.to_screen([0.0, 0.0]),
            view.to_screen([view.size.x, view.size.y]),
        );
        self.picture.push(image.intersect(rect));
        let subject = self.subject(session, capture);
        self.subject = vec![
            Rect::from_min_max(
                view.to_screen([subject.min.x, subject.min.y]),
                view.to_screen([subject.max.x, subject.max.y]),
            )
            .intersect(rect),
        ];
        painter.image(
            texture.id(),
            Rect::from_min_max(
                view.to_screen([0.0, 0.0]),
                view.to_screen([view.size.x, view.size.y]),
            ),
            Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
            Color32::WHITE,
        );
        if view.zoom >= texture::GRID_ZOOM {
            draw::draw_grid(&painter, &view);
        }
        if view.zoom >= 14.0 && sel.show_samples {
            draw::draw_samples(&painter, &view, capture);
        }
        self.annotate(&painter, (&view, &response), session, capture);
        let record = self.record(session, capture);
        if let Some(r) = &record
            && matches!(
                session.selection.stage,
                crate::vocabulary::Stage::Raster | crate::vocabulary::Stage::Depth
            )
            && view.zoom >= 10.0
        {
            draw::draw_edge_test(&painter, &view, r, lang);
        }
        self.draw_words(&painter, (rect, &view), (session, capture), (gain, offered));
        if let Some(below) = extra {
            self.picture.push(below);
            self.subject.push(below);
            if sel.buffer == BufferKind::Depth {
                depth_and_mips::depth_curve(
                    ui,
                    below,
                    capture,
                    sel.depth_view.range.filter(|_| !sel.depth_view.linear),
                    lang,
                );
            } else {
                self.pyramid.ui(ui, below, capture, record.as_ref(), lang);
            }
        }
        cmds.extend(hover::hover_and_click(&response, &view, capture, lang));
        picture_keys::ring(ui, rect, keys);
        cmds
    }

    /// The inspected pixel's record, computed once per capture and pixel (replaying the fragments
    /// walks every triangle).
    fn record(
        &mut self,
        session: &Session,
        capture: &FrameCapture,
    ) -> Option<pipeline::capture::PixelRecord> {
        let (x, y) = session.selection.pixel?;
        let key = (session.shown_generation, (x, y));
        if self.record.as_ref().is_none_or(|(g, p, _)| (*g, *p) != key) {
            self.record = capture.pixel_record(x, y).map(|r| (key.0, key.1, r));
        }
        self.record.as_ref().map(|(_, _, r)| r.clone())
    }

    /// What is drawn over the image: the overlays (the triangle under the pointer, else the
    /// inspected pixel's, strongly), the selection, the meshes' labels and the names of the
    /// objects a step compares.
    fn annotate(
        &mut self,
        painter: &egui::Painter,
        (view, response): (&ImageViewport, &egui::Response),
        session: &Session,
        capture: &FrameCapture,
    ) {
        let (sel, lang) = (&session.selection, session.lang);
        if !sel.overlays.is_empty() {
            let hovered = response
                .hover_pos()
                .and_then(|p| view.window_pixel(p, capture));
            let focus = hovered
                .or(sel.pixel)
                .and_then(|(x, y)| capture.primitive_at(x, y));
            let visible = self.visible(session, capture);
            draw::draw_overlays(
                painter,
                view,
                capture,
                (&sel.overlays, visible, focus),
                lang,
            );
        }
        draw::draw_selection(painter, view, capture, sel);
        draw::draw_labels(painter, view, capture);
        let generation = session.shown_generation;
        if self
            .label_points
            .as_ref()
            .is_none_or(|(g, _)| *g != generation)
        {
            self.label_points = Some((generation, capture.object_label_points()));
        }
        if let Some((_, points)) = &self.label_points {
            let names = session.spec.object_labels(capture, points, lang);
            draw::draw_object_labels(painter, view, &names);
        }
    }

    /// Which raster triangles own a sample in the frame shown (found once per frame).
    fn visible(&mut self, session: &Session, capture: &FrameCapture) -> Option<&[bool]> {
        let generation = session.shown_generation;
        if self.visible.as_ref().is_none_or(|(g, _)| *g != generation) {
            self.visible = Some((generation, capture.visible_triangles()));
        }
        self.visible.as_ref().and_then(|(_, v)| v.as_deref())
    }

    /// What the step is about in the image (pixels, y down): the covered pixels and the
    /// corners of the triangles in sight (a vertex lies outside the pixels it covers), and the
    /// inspected pixel; the whole image when nothing is covered.
    fn subject(&mut self, session: &Session, capture: &FrameCapture) -> Rect {
        let g = session.shown_generation;
        let (w, h) = (capture.width() as f32, capture.height() as f32);
        if self.covered.as_ref().is_none_or(|(k, _)| *k != g) {
            let image = Rect::from_min_size(Pos2::ZERO, Vec2::new(w, h));
            let covered = capture.covered_box().map(|[x0, y0, x1, y1]| {
                let pixels = Rect::from_min_max(
                    Pos2::new(x0 as f32, y0 as f32),
                    Pos2::new(x1 as f32, y1 as f32),
                );
                let visible = self.visible(session, capture).map(<[bool]>::to_vec);
                capture
                    .triangles
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| visible.as_ref().is_none_or(|v| v.get(*i) == Some(&true)))
                    .flat_map(|(_, t)| t.window)
                    .map(|p| Pos2::new(p.x, h - p.y))
                    .filter(|p| image.contains(*p))
                    .fold(pixels, |b, p| b.union(Rect::from_min_max(p, p)))
            });
            self.covered = Some((g, covered));
        }
        let mut subject = self
            .covered
            .as_ref()
            .and_then(|(_, b)| *b)
            .unwrap_or(Rect::from_min_size(Pos2::ZERO, Vec2::new(w, h)));
        if let Some((x, y)) = session
            .selection
            .pixel
            .filter(|&(x, y)| x < capture.width() && y < capture.height())
        {
            let row = h - 1.0 - y as f32;
            subject = subject.union(Rect::from_min_size(
                Pos2::new(x as f32, row),
                Vec2::splat(1.0),
            ));
        }
        subject
    }

    /// The arrows of a focused view: the inspected pixel moved (Shift: ten pixels), the first
    /// press inspecting the middle of the step's subject; the view panned to keep it in sight.
    fn arrows(
        &mut self,
        keys: picture_keys::Keys,
        view: &ImageViewport,
        session: &Session,
        capture: &FrameCapture,
    ) -> Option<Command> {
        let grid = capture.grid();
        let size = (capture.width(), capture.height());
        let to = picture_keys::arrowed_pixel(keys, session.selection.pixel, size, || {
            let c = self.subject(session, capture).center();
            let x = (c.x as u32).min(size.0.saturating_sub(1));
            (x, grid.row((c.y as u32).min(size.1.saturating_sub(1))))
        })?;
        // Its centre on screen, kept a pixel's width inside the view.
        let at = view.to_screen([to.0 as f32 + 0.5, grid.row(to.1) as f32 + 0.5]);
        let inside = view.rect.shrink(view.zoom.min(view.rect.width() / 4.0));
        if !inside.contains(at) {
            let shift = (at - inside.clamp(at)) / view.zoom;
            self.zoom = Some(view.zoom);
            self.centre = Some(view.centre + shift);
        }
        Some(Command::Selection(SelectionCommand::SelectPixel(Some(to))))
    }

    /// Applies wheel zoom (about the cursor), a focused view's `+`/`−` (about the inspected
    /// pixel, else the middle) and drag pan; returns the mapping to use.
    fn navigate(
        &mut self,
        ui: &Ui,
        (response, session): (&egui::Response, &Session),
        (rect, keys): (Rect, picture_keys::Keys),
        capture: &FrameCapture,
    ) -> ImageViewport {
        let size = Vec2::new(capture.width() as f32, capture.height() as f32);
        // Until the user zooms or drags: as large as the view allows with the covered pixels
        // and the inspected one clear of the narration card.
        let card = crate::app::views::card_placement::narration_card(ui.ctx());
        let subject = self.subject(session, capture);
        // A phone's view is narrow and tall: the picture covers it (the sides cropped, the
        // subject whole and in the middle; a pinch shows the rest).
        let placed = if crate::app::window_size::is_compact(ui.ctx()) {
            viewport::cover(rect, size, subject)
        } else {
            crate::app::views::card_placement::place(rect, size, subject, card)
        };
        let fit = placed.width() / size.x;
        self.fitted = placed.size();
        crate::app::views::card_placement::report_kept(
            ui.ctx(),
            placed.area() / crate::app::views::fit_rect(rect, size.x / size.y).area(),
        );
        let range = (fit.min(1.0) * 0.5, 256.0);
        let mut zoom = self.zoom.unwrap_or(fit).clamp(range.0, range.1);
        let mut centre = self
            .centre
            .unwrap_or(size / 2.0 - (placed.center() - rect.center()) / zoom);
        if let Some(pointer) = response.hover_pos() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y + i.zoom_delta().ln() * 200.0);
            if scroll != 0.0 {
                let new_zoom = (zoom * (scroll / 200.0).exp()).clamp(range.0, range.1);
                let under = centre + (pointer - rect.center()) / zoom;
                centre = under - (pointer - rect.center()) / new_zoom;
                zoom = new_zoom;
                self.zoom = Some(zoom);
                self.centre = Some(centre);
            }
        }
        if keys.zoom != 0 {
            let new_zoom = picture_keys::zoomed(zoom, keys.zoom, range);
            let held = session.selection.pixel.map_or(centre, |(x, y)| {
                Vec2::new(x as f32 + 0.5, capture.grid().row(y) as f32 + 0.5)
            });
            centre = held - (held - centre) * zoom / new_zoom;
            zoom = new_zoom;
            self.zoom = Some(zoom);
            self.centre = Some(centre);
        }
        if response.dragged() {
            centre -= response.drag_delta() / zoom;
            self.centre = Some(centre);
        }
        ImageViewport {
            rect,
            centre,
            zoom,
            size,
        }
    }
}
