//! The panels. Each reads the session (and the capture) and returns the commands it wants;
//! none of them computes pipeline results — those come from the `FrameCapture`.

pub mod answer;
pub mod compare;
pub mod exercise;
pub mod geometry;
pub mod inspector;
pub mod lesson;
pub mod navigator;
pub mod observer;
pub mod params;
pub mod pixels;
pub mod room;
pub mod shader;
pub mod typeset;

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
    /// Lights.
    pub const LIGHT: Color32 = Color32::from_rgb(255, 240, 120);
}

/// A camera for drawing 3-D lines with egui: points go through `m = P·V` and the viewport of
/// `rect`. It draws; it is not part of the pipeline being taught.
pub struct Projector {
    /// Projection times view.
    pub m: Mat4,
    /// Where on screen.
    pub rect: Rect,
    /// Magnification about the rect's centre, then a shift (screen points): zooming and
    /// panning the picture as a photograph.
    pub zoom: f32,
    /// The shift after the magnification.
    pub pan: egui::Vec2,
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
        let q = Pos2::new(
            self.rect.left() + (n.x + 1.0) / 2.0 * self.rect.width(),
            self.rect.top() + (1.0 - n.y) / 2.0 * self.rect.height(),
        );
        Some(self.rect.center() + (q - self.rect.center()) * self.zoom + self.pan)
    }

    /// Draws a 3-D segment.
    pub fn line(&self, painter: &egui::Painter, a: Vec3, b: Vec3, stroke: egui::Stroke) {
        if let (Some(pa), Some(pb)) = (self.project(a), self.project(b)) {
            painter.line_segment([pa, pb], stroke);
        }
    }
}

/// The lights of a capture drawn where they are (see `Light::gizmo`), through `to_view` (world
/// coordinates into the space drawn), in a scene centred at `centre` of about `size`; each with its
/// label; returns whether it drew any.
pub fn draw_lights(
    painter: &egui::Painter,
    cam: &Projector,
    lights: &[pipeline::light::Light],
    to_view: &dyn Fn(Vec3) -> Vec3,
    (centre, size): (Vec3, f32),
    lang: Lang,
) -> bool {
    use pipeline::light::Light;
    let font = picture_font(painter.ctx(), 14.0);
    let mut drew = false;
    for (k, light) in lights.iter().enumerate() {
        let Some(g) = light.gizmo(centre, size) else {
            continue;
        };
        drew = true;
        let stroke = egui::Stroke::new(2.0, palette::LIGHT);
        for [a, b] in &g.segments {
            cam.line(painter, to_view(*a), to_view(*b), stroke);
        }
        if let Some(p) = cam.project(to_view(g.label_at)) {
            let name = match light {
                Light::Point { .. } => lang.tr("point light", "点光源"),
                Light::Spot { .. } => lang.tr("spotlight", "聚光灯"),
                Light::Directional { .. } => lang.tr("directional light", "平行光"),
                Light::Ambient { .. } => "",
            };
            label_with_background(
                painter,
                p,
                egui::Align2::CENTER_BOTTOM,
                &format!("{name} {k}"),
                &font,
                palette::LIGHT,
            );
        }
    }
    drew
}

/// How much larger the words drawn over pictures (labels, legends, cards) are than normal: 1,
/// or 1.6 in classroom mode — the body text's size over its normal 15 points.
#[must_use]
pub fn picture_scale(ctx: &egui::Context) -> f32 {
    ctx.global_style()
        .text_styles
        .get(&egui::TextStyle::Body)
        .map_or(1.0, |f| f.size / 15.0)
}

/// A proportional font of `size` normal points for words drawn over a picture.
#[must_use]
pub fn picture_font(ctx: &egui::Context, size: f32) -> egui::FontId {
    egui::FontId::proportional(size * picture_scale(ctx))
}

/// A monospace font of `size` normal points for numbers drawn over a picture.
#[must_use]
pub fn picture_mono(ctx: &egui::Context, size: f32) -> egui::FontId {
    egui::FontId::monospace(size * picture_scale(ctx))
}

/// Says over a picture that a dim lighting term is drawn `gain` times brighter than its values
/// (`vocabulary::gain_note`), in the accent colour at `at`; nothing when it is drawn as it is.
pub fn draw_gain_note(
    painter: &egui::Painter,
    (at, align): (Pos2, egui::Align2),
    kind: pipeline::buffers::BufferKind,
    gain: f32,
    lang: crate::vocabulary::Lang,
) {
    if let Some(note) = crate::vocabulary::gain_note(kind, gain, lang) {
        label_with_background(
            painter,
            at,
            align,
            &note,
            &picture_font(painter.ctx(), 15.0),
            egui::Color32::from_rgb(255, 214, 120),
        );
    }
}

/// Text on a dark translucent box, legible over any picture; returns its rect.
pub fn label_with_background(
    painter: &egui::Painter,
    at: Pos2,
    align: egui::Align2,
    text: &str,
    font: &egui::FontId,
    color: Color32,
) -> Rect {
    wrapped_label(painter, at, align, text, font, color, f32::INFINITY)
}

/// [`label_with_background`] wrapped to lines at most `width` wide.
pub fn wrapped_label(
    painter: &egui::Painter,
    at: Pos2,
    align: egui::Align2,
    text: &str,
    font: &egui::FontId,
    color: Color32,
    width: f32,
) -> Rect {
    let galley = painter.layout(text.to_owned(), font.clone(), color, width);
    let rect = align.anchor_size(at, galley.size()).expand(3.0);
    painter.rect_filled(rect, 3.0, Color32::from_black_alpha(170));
    painter.galley(rect.min + egui::vec2(3.0, 3.0), galley, color);
    rect
}

/// Where to put a label of `size` pointing at `anchor` so that it covers nothing in `avoid`
/// (first the subject on screen, then the cards and legends over the picture) and stays inside
/// `view`: the first place around the anchor, a little farther each round, that does neither;
/// else the first such place that covers the subject but no card (the label has its own dark
/// box: a label far from its point, with a leader line across the picture, reads worse); else
/// the view's corner farthest from the subject that covers nothing else; else the corner
/// farthest from the subject.
#[must_use]
pub fn place_label(anchor: Pos2, size: egui::Vec2, avoid: &[Rect], view: Rect) -> Rect {
    let around = |avoid: &[Rect]| {
        let clear = |r: &Rect| avoid.iter().all(|a| !r.intersects(*a));
        for step in 1..=8 {
            let d = 12.0 * step as f32;
            for dir in [
                egui::vec2(1.0, -1.0),
                egui::vec2(1.0, 1.0),
                egui::vec2(-1.0, -1.0),
                egui::vec2(-1.0, 1.0),
                egui::vec2(0.0, -1.0),
                egui::vec2(0.0, 1.0),
            ] {
                let r = Rect::from_center_size(anchor + dir * (d + size.length() / 2.0), size);
                if view.contains_rect(r) && clear(&r) {
                    return Some(r);
                }
            }
        }
        None
    };
    if let Some(r) = around(avoid).or_else(|| around(avoid.get(1..).unwrap_or_default())) {
        return r;
    }
    let subject = avoid.first().map_or(view.center(), Rect::center);
    let mut corners: Vec<Rect> = [
        view.left_top(),
        view.right_top(),
        view.left_bottom(),
        view.right_bottom(),
    ]
    .into_iter()
    .map(|corner| {
        let r = Rect::from_center_size(corner, size);
        r.translate(egui::vec2(
            (view.left() - r.left()).max(0.0) - (r.right() - view.right()).max(0.0),
            (view.top() - r.top()).max(0.0) - (r.bottom() - view.bottom()).max(0.0),
        ))
    })
    .collect();
    corners.sort_by(|a, b| {
        b.center()
            .distance(subject)
            .total_cmp(&a.center().distance(subject))
    });
    corners
        .iter()
        .find(|r| avoid.iter().skip(1).all(|a| !r.intersects(*a)))
        .or(corners.first())
        .copied()
        .unwrap_or(view)
}

/// A matrix with its name and formula typeset, its numbers, and its factors below it (open
/// when `open`).
pub fn matrix(ui: &mut Ui, m: &NamedMatrix, lang: Lang, id: &str, open: bool) {
    let style = typeset::Style::body(ui);
    typeset::formula(ui, &m.name, &style.sized(style.size * 1.1));
    let formula = lang.formula(&m.formula);
    if !formula.is_empty() {
        let dim = typeset::Style {
            color: ui.visuals().text_color().gamma_multiply(0.85),
            ..style
        };
        typeset::paragraph(ui, &formula, &dim.sized(style.size * 0.9));
    }
    matrix_grid(ui, &m.matrix, id);
    if !m.factors.is_empty() {
        egui::CollapsingHeader::new(lang.tr("Factors", "分解"))
            .id_salt(format!("{id}-factors"))
            .default_open(open)
            .show(ui, |ui| {
                for (i, f) in m.factors.iter().enumerate() {
                    matrix(ui, f, lang, &format!("{id}-{i}"), false);
                }
            });
    }
}

/// The 4×4 numbers, in monospace at the body size, right-aligned.
pub fn matrix_grid(ui: &mut Ui, m: &Mat4, id: &str) {
    let size = ui.style().text_styles[&egui::TextStyle::Body].size;
    egui::Frame::group(ui.style()).show(ui, |ui| {
        egui::Grid::new(id)
            .spacing([size * 0.7, 2.0])
            .show(ui, |ui| {
                for row in to_rows(m) {
                    for v in row {
                        ui.label(
                            RichText::new(format!("{:>9}", num(v)))
                                .monospace()
                                .size(size),
                        );
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
    FATES[fate_index(f)].0
}

/// The fates a triangle can meet, in the legend's order: colour, English name, Chinese name
/// (`spaces::FATES`, the colours as egui's).
pub const FATES: [(Color32, &str, &str); crate::spaces::FATES.len()] = {
    const fn fate(k: usize) -> (Color32, &'static str, &'static str) {
        let f = crate::spaces::FATES[k];
        (Color32::from_rgb(f.0[0], f.0[1], f.0[2]), f.1, f.2)
    }
    [fate(0), fate(1), fate(2), fate(3), fate(4), fate(5)]
};

pub use crate::spaces::fate_index;

/// A lighting term's display gain (`FrameCapture::term_gain`, a scan of every pixel), found
/// again only when the capture (its generation) or the buffer changes, not on every UI frame.
#[derive(Default)]
pub struct TermGain(Option<((u64, pipeline::buffers::BufferKind), f32)>);

impl TermGain {
    /// The gain for `key`, from `find` when the key changed.
    pub fn get(
        &mut self,
        key: (u64, pipeline::buffers::BufferKind),
        find: impl FnOnce() -> f32,
    ) -> f32 {
        match self.0 {
            Some((k, gain)) if k == key => gain,
            _ => {
                let gain = find();
                self.0 = Some((key, gain));
                gain
            }
        }
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
    /// The texture of `kind` from `capture` (generation `generation`), its lighting terms drawn
    /// `gain` times brighter (`capture.image_gained`).
    pub fn get(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        (generation, kind, gain): (u64, pipeline::buffers::BufferKind, f32),
        capture: &pipeline::capture::FrameCapture,
        options: egui::TextureOptions,
    ) -> egui::TextureHandle {
        let key = (generation, kind, u64::from(gain.to_bits()));
        self.get_with(ctx, name, key, options, || capture.image_gained(kind, gain))
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
