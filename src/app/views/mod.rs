//! The panels. Each reads the session (and the capture) and returns the commands it wants;
//! none of them computes pipeline results — those come from the `FrameCapture`.

pub mod compare;
pub mod geometry;
pub mod inspector;
pub mod lesson;
pub mod navigator;
pub mod observer;
pub mod params;
pub mod pixels;

use egui::{Color32, Pos2, Rect, RichText, Ui};
use glam::{Mat4, Vec3, Vec4};
use pipeline::transform::{NamedMatrix, to_rows};

use crate::vocabulary::{Lang, num};

/// Colours used across views, chosen to read on a projector.
pub mod palette {
    use egui::Color32;
    /// The x axis.
    pub const X: Color32 = Color32::from_rgb(235, 80, 80);
    /// The y axis.
    pub const Y: Color32 = Color32::from_rgb(90, 210, 90);
    /// The z axis.
    pub const Z: Color32 = Color32::from_rgb(90, 140, 255);
    /// Selection highlight.
    pub const SELECTED: Color32 = Color32::from_rgb(255, 215, 0);
    /// The viewing frustum's near plane.
    pub const NEAR: Color32 = Color32::from_rgb(255, 200, 60);
    /// The viewing frustum's far plane and sides.
    pub const FAR: Color32 = Color32::from_rgb(255, 140, 40);
    /// Clipped geometry.
    pub const CLIPPED: Color32 = Color32::from_rgb(255, 120, 200);
}

/// A camera for drawing 3-D lines with egui: points go through `m = P·V` and the viewport of
/// `rect`. It draws; it is not part of the pipeline being taught.
pub struct Projector {
    /// Projection times view.
    pub m: Mat4,
    /// Where on screen.
    pub rect: Rect,
}

impl Projector {
    /// The screen position of `p`, if it is in front of the camera.
    #[must_use]
    pub fn project(&self, p: Vec3) -> Option<Pos2> {
        let c: Vec4 = self.m * p.extend(1.0);
        if c.w <= 1e-6 || !c.is_finite() {
            return None;
        }
        let n = c.truncate() / c.w;
        Some(Pos2::new(
            self.rect.left() + (n.x + 1.0) / 2.0 * self.rect.width(),
            self.rect.top() + (1.0 - n.y) / 2.0 * self.rect.height(),
        ))
    }

    /// Draws a 3-D segment.
    pub fn line(&self, painter: &egui::Painter, a: Vec3, b: Vec3, stroke: egui::Stroke) {
        if let (Some(pa), Some(pb)) = (self.project(a), self.project(b)) {
            painter.line_segment([pa, pb], stroke);
        }
    }
}

/// A matrix with its name, formula and numbers, and its factors folded below it.
pub fn matrix(ui: &mut Ui, m: &NamedMatrix, lang: Lang, id: &str) {
    ui.label(RichText::new(&m.name).strong());
    ui.label(RichText::new(lang.formula(&m.formula)).italics().weak());
    matrix_grid(ui, &m.matrix, id);
    if !m.factors.is_empty() {
        egui::CollapsingHeader::new(lang.tr("Factors", "分解"))
            .id_salt(format!("{id}-factors"))
            .show(ui, |ui| {
                for (i, f) in m.factors.iter().enumerate() {
                    matrix(ui, f, lang, &format!("{id}-{i}"));
                }
            });
    }
}

/// The 4×4 numbers, in monospace, right-aligned.
pub fn matrix_grid(ui: &mut Ui, m: &Mat4, id: &str) {
    egui::Frame::group(ui.style()).show(ui, |ui| {
        egui::Grid::new(id).spacing([10.0, 2.0]).show(ui, |ui| {
            for row in to_rows(m) {
                for v in row {
                    ui.label(RichText::new(format!("{:>9}", num(v))).monospace());
                }
                ui.end_row();
            }
        });
    });
}

/// The largest rectangle of `aspect` (width/height) centred in `outer`.
#[must_use]
pub fn fit_rect(outer: Rect, aspect: f32) -> Rect {
    let (w, h) = (outer.width(), outer.height());
    let size = if w / h > aspect {
        egui::vec2(h * aspect, h)
    } else {
        egui::vec2(w, w / aspect)
    };
    Rect::from_center_size(outer.center(), size)
}

/// The colour of a primitive's fate, for wireframes.
#[must_use]
pub fn fate_color(f: &pipeline::capture::Fate) -> Color32 {
    use pipeline::capture::Fate;
    match f {
        Fate::Drawn => Color32::from_gray(220),
        Fate::Clipped => palette::CLIPPED,
        Fate::Outside { .. } => Color32::from_gray(90),
        Fate::Culled { .. } => Color32::from_rgb(70, 90, 150),
        Fate::Degenerate => Color32::RED,
    }
}

/// A capture's buffer uploaded as an egui texture, uploaded again only when the capture (its
/// generation), the buffer or the way it is drawn (`variant`) changes.
#[derive(Default)]
pub struct BufferTexture(
    Option<(
        (u64, pipeline::buffers::BufferKind, u64),
        egui::TextureHandle,
    )>,
);

impl BufferTexture {
    /// The texture of `kind` from `capture` (generation `generation`), drawn by `capture.image`.
    pub fn get(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        generation: u64,
        kind: pipeline::buffers::BufferKind,
        capture: &pipeline::capture::FrameCapture,
        options: egui::TextureOptions,
    ) -> egui::TextureHandle {
        self.get_with(ctx, name, (generation, kind, 0), options, || {
            capture.image(kind)
        })
    }

    /// The texture for `key`, made by `make` when the key changed.
    pub fn get_with(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        key: (u64, pipeline::buffers::BufferKind, u64),
        options: egui::TextureOptions,
        make: impl FnOnce() -> image::RgbaImage,
    ) -> egui::TextureHandle {
        if let Some((k, t)) = &self.0
            && *k == key
        {
            return t.clone();
        }
        let img = make();
        let size = [img.width() as usize, img.height() as usize];
        let color = egui::ColorImage::from_rgba_unmultiplied(size, img.as_raw());
        let t = ctx.load_texture(name, color, options);
        self.0 = Some((key, t.clone()));
        t
    }
}
