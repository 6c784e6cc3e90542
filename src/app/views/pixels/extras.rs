//! What the pixel view shows beside some buffers: under the depth buffer, the curve of window
//! depth `z_w` against eye distance (it moves with near and far), with the depths present in the
//! image marked; under a texturing buffer, the mip pyramid, every level at once, the level read at
//! the inspected pixel framed and its footprint drawn there.

use crate::app::views::picture_font;
use std::collections::HashMap;

use egui::{Align2, Color32, Pos2, Rect, Stroke, TextureOptions, Ui, Vec2};
use egui_plot::{Legend, Line, Plot, VLine};
use pipeline::capture::{FrameCapture, PixelRecord};

use crate::app::views::label_with_background;
use crate::vocabulary::{Lang, num};

/// The curve `z_w(d)` from near to far, and where the image's depths lie on it.
pub(super) fn depth_curve(
    ui: &mut Ui,
    rect: Rect,
    capture: &FrameCapture,
    range: Option<[f32; 2]>,
    lang: Lang,
) {
    let p = &capture.projection;
    let [.., near, far] = p.bounds(capture.settings.aspect());
    let n = 256;
    let curve: Vec<[f64; 2]> = (0..=n)
        .map(|k| {
            let d = near + (far - near) * k as f32 / n as f32;
            [f64::from(d), f64::from(p.window_depth(d))]
        })
        .collect();
    ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
        ui.painter().rect_filled(rect, 4.0, Color32::from_gray(14));
        Plot::new("depth-curve")
            .legend(Legend::default().follow_insertion_order(true))
            .x_axis_label(lang.tr("eye distance d (near → far)", "到视点的距离 d（近 → 远）"))
            .y_axis_label(lang.tr("window depth z_w", "窗口深度 z_w"))
            .y_axis_min_width(36.0)
            .include_y(0.0)
            .include_y(1.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                plot.line(
                    Line::new(
                        format!("z_w(d), near {}, far {}", num(near), num(far)),
                        curve,
                    )
                    .color(Color32::from_rgb(255, 214, 120))
                    .width(2.5),
                );
                if let Some([a, b]) = capture.depth_range() {
                    let (da, db) = (capture.eye_depth(a), capture.eye_depth(b));
                    let name = lang.tr("depths in the image", "图像中的深度");
                    plot.vline(
                        VLine::new(name, f64::from(da)).color(Color32::from_rgb(120, 200, 255)),
                    );
                    plot.vline(
                        VLine::new(name, f64::from(db)).color(Color32::from_rgb(120, 200, 255)),
                    );
                }
                if let Some([lo, hi]) = range {
                    let name = lang.tr("grey ramp: black → white", "灰度范围：黑 → 白");
                    plot.hline(
                        egui_plot::HLine::new(name, f64::from(lo)).color(Color32::from_gray(200)),
                    );
                    plot.hline(
                        egui_plot::HLine::new(name, f64::from(hi)).color(Color32::from_gray(200)),
                    );
                }
            });
    });
}

/// The egui textures of the mip levels shown, by texture and level.
#[derive(Default)]
pub(super) struct Pyramid {
    textures: HashMap<(String, usize), egui::TextureHandle>,
}

impl Pyramid {
    /// Every level of the texture of the inspected pixel's object (or the first texture),
    /// smaller and smaller from left to right; the level read framed, the footprint drawn on it.
    pub(super) fn ui(
        &mut self,
        ui: &mut Ui,
        rect: Rect,
        capture: &FrameCapture,
        record: Option<&PixelRecord>,
        lang: Lang,
    ) {
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 4.0, Color32::from_gray(14));
        let owner = record
            .and_then(|r| r.explanation.as_ref())
            .map(|e| e.object.clone());
        let Some((_, texture)) = capture
            .textures
            .iter()
            .find(|(o, _)| Some(o) == owner.as_ref())
            .or(capture.textures.first())
        else {
            return;
        };
        let read = record.and_then(|r| r.texture.as_ref());
        let level_read = read.map(|t| (t.level.floor().max(0.0) as usize, t.level.fract()));
        let rects = level_rects(texture, rect);
        for (k, (level, r)) in texture.levels.iter().zip(rects).enumerate() {
            let key = (texture.name.clone(), k);
            let handle = self.textures.entry(key).or_insert_with(|| {
                let img = texture.level_image(k);
                let color = egui::ColorImage::from_rgba_unmultiplied(
                    [img.width() as usize, img.height() as usize],
                    img.as_raw(),
                );
                ui.ctx().load_texture(
                    format!("mip-{}-{k}", texture.name),
                    color,
                    TextureOptions::NEAREST,
                )
            });
            painter.image(
                handle.id(),
                r,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
            let chosen = level_read.is_some_and(|(l, t)| l == k || (l + 1 == k && t > 0.0));
            painter.rect_stroke(
                r.expand(2.0),
                0.0,
                Stroke::new(
                    if chosen { 3.0 } else { 1.0 },
                    if chosen {
                        Color32::YELLOW
                    } else {
                        Color32::from_gray(90)
                    },
                ),
                egui::StrokeKind::Outside,
            );
            painter.text(
                Pos2::new(r.left(), r.top() - LABEL_H),
                Align2::LEFT_TOP,
                format!("{k}: {}×{}", level.width, level.height),
                picture_font(painter.ctx(), 13.0),
                if chosen {
                    Color32::YELLOW
                } else {
                    Color32::from_gray(220)
                },
            );
            if let (Some(t), Some((l, _))) = (read, level_read)
                && l == k
            {
                draw_footprint(&painter, r, t, k, level.width);
            }
        }
        label_with_background(
            &painter,
            rect.right_top() + Vec2::new(-6.0, 6.0),
            Align2::RIGHT_TOP,
            &format!(
                "{} · {}",
                lang.tr("mip pyramid", "mipmap 金字塔"),
                lang.tr(
                    "framed: the level read at the inspected pixel, its footprint in cyan",
                    "框出：所检查像素读取的层级，青色为其覆盖区域"
                )
            ),
            &picture_font(painter.ctx(), 13.0),
            Color32::WHITE,
        );
    }
}

/// The inspected pixel's footprint on mip level `k` shown in `r` (`width` texels wide): its
/// axes, given in level-0 texels, divided by 2^k, around the point uv.
fn draw_footprint(
    painter: &egui::Painter,
    r: Rect,
    t: &pipeline::capture::PixelTexture,
    k: usize,
    width: u32,
) {
    let per_texel = r.width() / width as f32;
    let centre = Pos2::new(
        r.left() + t.uv[0].rem_euclid(1.0) * r.width(),
        r.top() + (1.0 - t.uv[1].rem_euclid(1.0)) * r.height(),
    );
    let k2 = 2f32.powi(k as i32);
    let ax = Vec2::new(t.footprint[0], -t.footprint[1]) / k2 * per_texel;
    let ay = Vec2::new(t.footprint[2], -t.footprint[3]) / k2 * per_texel;
    let corners = [
        centre - (ax + ay) / 2.0,
        centre + (ax - ay) / 2.0,
        centre + (ax + ay) / 2.0,
        centre + (ay - ax) / 2.0,
    ];
    let stroke = Stroke::new(2.0, Color32::from_rgb(0, 255, 255));
    for i in 0..4 {
        painter.line_segment([corners[i], corners[(i + 1) % 4]], stroke);
    }
}

/// The height of a level's label.
const LABEL_H: f32 = 18.0;

/// Where each mip level goes in `rect`: side by side, halving (one under the other in a tall
/// panel), level 0 taking about half the length; as many levels as fit.
fn level_rects(texture: &pipeline::texture::Texture, rect: Rect) -> Vec<Rect> {
    let pad = 8.0;
    let vertical = rect.height() > rect.width();
    let (w0, h0) = (
        texture.levels[0].width as f32,
        texture.levels[0].height as f32,
    );
    let scale = if vertical {
        ((rect.width() - 2.0 * pad) / w0).min((rect.height() - 2.0 * pad) / (2.0 * (h0 + LABEL_H)))
    } else {
        ((rect.height() - 2.0 * pad - LABEL_H) / h0).min((rect.width() - 2.0 * pad) / (2.2 * w0))
    };
    let mut at = rect.left_top() + Vec2::splat(pad);
    let mut out = Vec::new();
    for level in &texture.levels {
        let size = Vec2::new(level.width as f32, level.height as f32) * scale;
        let r = Rect::from_min_size(at + Vec2::new(0.0, LABEL_H), size);
        if size.x < 2.0 || size.y < 2.0 || !rect.contains_rect(r.shrink(0.5)) {
            break;
        }
        out.push(r);
        at = if vertical {
            Pos2::new(at.x, r.bottom() + pad)
        } else {
            Pos2::new(r.right() + pad * 1.5, at.y)
        };
    }
    out
}
