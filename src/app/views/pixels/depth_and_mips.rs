//! What the pixel view shows beside some buffers: under the depth buffer, the curve of window
//! depth `z_w` against eye distance (it moves with near and far), with the depths present in the
//! image marked; under a texturing buffer, the mip pyramid, every level at once, the level read at
//! the inspected pixel framed and its footprint drawn there.

use crate::app::views::picture_font;
use std::collections::HashMap;

use egui::{Align2, Color32, Pos2, Rect, Stroke, TextureOptions, Ui, Vec2};
use egui_plot::{Line, Plot, VLine};
use pipeline::capture::{FrameCapture, PixelRecord};

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
    ui.painter().rect_filled(rect, 4.0, Color32::from_gray(14));
    let inner = crate::app::views::plot_axes::plot_rect(ui, rect);
    ui.scope_builder(egui::UiBuilder::new().max_rect(inner), |ui| {
        let (x_axes, y_axes) = crate::app::views::plot_axes::axes(
            lang.t("depth-and-mips-eye-distance-d-near-far"),
            lang.t("depth-and-mips-window-depth-z-w"),
            36.0,
        );
        let (curve_colour, depths_colour, ramp_colour) = (
            Color32::from_rgb(255, 214, 120),
            Color32::from_rgb(120, 200, 255),
            Color32::from_gray(200),
        );
        let curve_name = lang.t_with(
            "depth-and-mips-curve-legend",
            &[("near", &num(near)), ("far", &num(far))],
        );
        let depths = capture.depth_range();
        let mut entries = vec![(curve_name.as_str(), curve_colour)];
        if depths.is_some() {
            entries.push((lang.t("depth-and-mips-depths-in-the-image"), depths_colour));
        }
        if range.is_some() {
            entries.push((lang.t("depth-and-mips-grey-ramp-black-white"), ramp_colour));
        }
        let shown = crate::app::views::plot_legend::legend(ui, "depth-curve", &entries);
        let shown = |name: &str| {
            entries
                .iter()
                .zip(&shown)
                .any(|((n, _), s)| *n == name && *s)
        };
        let plot = Plot::new("depth-curve")
            .custom_x_axes(x_axes)
            .custom_y_axes(y_axes)
            .include_y(0.0)
            .include_y(1.0)
            .allow_scroll(false)
            .allow_axis_zoom_drag(false)
            .show(ui, |plot| {
                if shown(&curve_name) {
                    plot.line(Line::new(&curve_name, curve).color(curve_colour).width(2.5));
                }
                if let Some([a, b]) = depths
                    && shown(lang.t("depth-and-mips-depths-in-the-image"))
                {
                    let (da, db) = (capture.eye_depth(a), capture.eye_depth(b));
                    let name = lang.t("depth-and-mips-depths-in-the-image");
                    plot.vline(VLine::new(name, f64::from(da)).color(depths_colour));
                    plot.vline(VLine::new(name, f64::from(db)).color(depths_colour));
                }
                if let Some([lo, hi]) = range
                    && shown(lang.t("depth-and-mips-grey-ramp-black-white"))
                {
                    let name = lang.t("depth-and-mips-grey-ramp-black-white");
                    plot.hline(egui_plot::HLine::new(name, f64::from(lo)).color(ramp_colour));
                    plot.hline(egui_plot::HLine::new(name, f64::from(hi)).color(ramp_colour));
                }
            })
            .response;
        crate::app::views::alt::name_image(&plot, || {
            lang.t_with(
                "depth-and-mips-curve-alt",
                &[("near", &num(near)), ("far", &num(far))],
            )
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
        // The title on its own rows at the top (wrapped to the panel), the levels below it.
        let title = painter.layout(
            format!(
                "{} · {}",
                lang.t("depth-and-mips-mip-pyramid"),
                lang.t("depth-and-mips-framed-the-level-read-at")
            ),
            picture_font(painter.ctx(), 13.0),
            Color32::WHITE,
            rect.width() - 12.0,
        );
        let below = rect.top() + title.size().y + 10.0;
        painter.galley(rect.left_top() + Vec2::splat(6.0), title, Color32::WHITE);
        let sizes: Vec<Vec2> = texture
            .levels
            .iter()
            .map(|l| Vec2::new(l.width as f32, l.height as f32))
            .collect();
        let font = picture_font(painter.ctx(), 13.0);
        let label_h = painter.ctx().fonts_mut(|f| f.row_height(&font)) + 2.0;
        let rects = level_rects(
            &sizes,
            Rect::from_min_max(Pos2::new(rect.left(), below), rect.max),
            label_h,
        );
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
            level_label(&painter, (r, label_h), (k, level), &font, chosen);
            if let (Some(t), Some((l, _))) = (read, level_read)
                && l == k
            {
                draw_footprint(&painter, r, t, k, level.width);
            }
        }
    }
}

/// Level `k`'s label above its picture `r` (`label_h` high): its number and size, or where
/// that would run into the next level's label, its number only; yellow for a level read.
fn level_label(
    painter: &egui::Painter,
    (r, label_h): (Rect, f32),
    (k, level): (usize, &pipeline::texture::Level),
    font: &egui::FontId,
    chosen: bool,
) {
    let full = format!("{k}: {}×{}", level.width, level.height);
    let width = painter
        .layout_no_wrap(full.clone(), font.clone(), Color32::WHITE)
        .size()
        .x;
    let label = if width <= r.width() + LEVEL_GAP - 4.0 {
        full
    } else {
        k.to_string()
    };
    painter.text(
        Pos2::new(r.left(), r.top() - label_h),
        Align2::LEFT_TOP,
        label,
        font.clone(),
        if chosen {
            Color32::YELLOW
        } else {
            Color32::from_gray(220)
        },
    );
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

/// The gap between a level and the next in a row.
const LEVEL_GAP: f32 = 16.0;

/// Where each mip level goes in `rect`, in the arrangement that shows level 0 largest: in a row
/// (level 0, then each smaller level right of the one before), or, in a tall panel, level 0 on
/// top and the smaller levels in a row under it. Every level has its label's height `label_h`
/// above it and a gap before the next; the levels that would be under 2 points are left out.
fn level_rects(sizes: &[Vec2], rect: Rect, label_h: f32) -> Vec<Rect> {
    let pad = 8.0;
    let gap = LEVEL_GAP;
    let Some(&first) = sizes.first() else {
        return Vec::new();
    };
    let rest_w: f32 = sizes[1..].iter().map(|s| s.x).sum();
    let rest_h = sizes.get(1).map_or(0.0, |s| s.y);
    let gaps = gap * (sizes.len() - 1) as f32;
    let (w, h) = (rect.width() - 2.0 * pad, rect.height() - 2.0 * pad);
    // In a row: (first.x + rest_w)·s + gaps ≤ w, first.y·s + label ≤ h.
    let row = ((w - gaps) / (first.x + rest_w)).min((h - label_h) / first.y);
    // Stacked: level 0 over the row of the rest.
    let stacked = (w / first.x)
        .min((w - gaps + gap) / rest_w.max(1.0))
        .min((h - 2.0 * label_h - pad) / (first.y + rest_h));
    let scale = row.max(stacked).max(0.0);
    let origin = rect.left_top() + Vec2::splat(pad);
    let mut at = origin;
    let mut out = Vec::new();
    for (k, size) in sizes.iter().enumerate() {
        let size = *size * scale;
        if size.x < 2.0 || size.y < 2.0 {
            break;
        }
        let r = Rect::from_min_size(at + Vec2::new(0.0, label_h), size);
        out.push(r);
        at = if k == 0 && stacked > row {
            Pos2::new(origin.x, r.bottom() + pad)
        } else {
            Pos2::new(r.right() + gap, at.y)
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pyramid(n: u32) -> Vec<Vec2> {
        (0..n)
            .map(|k| Vec2::splat((1u32 << (n - 1 - k)) as f32))
            .collect()
    }

    /// A label's height in normal type (13 points' rows and 2).
    const LABEL_H: f32 = 18.0;

    /// Every level shown lies inside the panel with its label, none overlaps another.
    fn laid_out(rects: &[Rect], panel: Rect, label_h: f32) {
        for (i, r) in rects.iter().enumerate() {
            let labelled = Rect::from_min_max(r.min - Vec2::new(0.0, label_h), r.max);
            assert!(
                panel.contains_rect(labelled),
                "level {i} {labelled:?} outside {panel:?}"
            );
            for s in &rects[i + 1..] {
                assert!(!labelled.intersects(*s), "level {i} overlaps another");
            }
        }
    }

    #[test]
    fn a_wide_panel_shows_the_levels_in_a_row() {
        // 1366×768 with the pyramid under the image: a band about 1000 × 180.
        let panel = Rect::from_min_size(Pos2::ZERO, Vec2::new(1000.0, 180.0));
        let rects = level_rects(&pyramid(9), panel, LABEL_H);
        laid_out(&rects, panel, LABEL_H);
        assert!(rects.len() >= 7, "only {} levels", rects.len());
        assert!(rects.windows(2).all(|w| w[1].left() > w[0].right()));
    }

    #[test]
    fn a_tall_panel_puts_the_smaller_levels_under_level_zero() {
        // The column beside a wide image: 300 × 600.
        let panel = Rect::from_min_size(Pos2::ZERO, Vec2::new(300.0, 600.0));
        let rects = level_rects(&pyramid(9), panel, LABEL_H);
        laid_out(&rects, panel, LABEL_H);
        assert!(rects.len() >= 6, "only {} levels", rects.len());
        assert!(rects[1].top() > rects[0].bottom());
        // Level 0 over half the panel's width (the row under it, with its gaps, limits it).
        assert!(rects[0].width() > 150.0);
    }

    /// Classroom type's taller labels (24-point type, rows of 30) keep clear of the levels.
    #[test]
    fn classroom_labels_keep_their_room() {
        let panel = Rect::from_min_size(Pos2::ZERO, Vec2::new(1000.0, 180.0));
        let rects = level_rects(&pyramid(9), panel, 30.0);
        laid_out(&rects, panel, 30.0);
        assert!(rects.len() >= 6, "only {} levels", rects.len());
    }
}
