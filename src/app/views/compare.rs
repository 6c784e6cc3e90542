//! Settings side by side — flat | Gouraud | Phong (the Mach band comparison), affine |
//! perspective-correct, 1× | 4× — with an intensity profile along a line the user drags across
//! any of the images, plotted for all of them.

use egui::{Color32, Pos2, Rect, RichText, Sense, Stroke, TextureOptions, Ui, Vec2};
use egui_plot::{Legend, Line, Plot};

use super::fit_rect;
use crate::app::session::{Command, Session};
use crate::vocabulary::variant_label;

/// Textures of the compared images and the line being dragged.
#[derive(Default)]
pub struct CompareView {
    textures: Vec<super::BufferTexture>,
    drag_start: Option<[f32; 2]>,
}

/// Colours of the compared settings' curves.
const CURVES: [Color32; 4] = [
    Color32::from_rgb(255, 170, 60),
    Color32::from_rgb(90, 200, 255),
    Color32::from_rgb(150, 255, 120),
    Color32::from_rgb(230, 120, 255),
];

impl CompareView {
    /// Draws the images in a row and the profile plot below them.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        let variants = &session.variants;
        if variants.is_empty() {
            ui.label(lang.tr("Rendering the comparison…", "正在渲染对比…"));
            return cmds;
        }
        ui.label(
            RichText::new(lang.tr(
                "Drag across any image to draw a profile line; the plot shows the intensity along it for each.",
                "在任一图像上拖动以画出剖面线；下方曲线显示每幅图像沿该线的亮度。",
            ))
            .weak(),
        );
        let area = ui.available_rect_before_wrap();
        let images_h = area.height() * 0.62;
        let gap = 6.0;
        let w = (area.width() - gap * (variants.len() as f32 - 1.0)) / variants.len() as f32;
        for (i, (name, capture)) in variants.iter().enumerate() {
            let cell = Rect::from_min_size(
                area.min + Vec2::new(i as f32 * (w + gap), 0.0),
                Vec2::new(w, images_h),
            );
            if self.textures.len() <= i {
                self.textures.resize_with(i + 1, Default::default);
            }
            let texture = self.textures[i].get(
                ui.ctx(),
                &format!("compare-{i}"),
                session.shown_generation,
                session.selection.buffer,
                capture,
                TextureOptions::NEAREST,
            );
            let title_h = 22.0;
            let image = fit_rect(
                Rect::from_min_max(cell.min + Vec2::new(0.0, title_h), cell.max),
                capture.width() as f32 / capture.height() as f32,
            );
            let response = ui.interact(image, ui.scope_id().with(("compare", i)), Sense::drag());
            let accessible = format!(
                "{}: {}",
                lang.tr("compared image", "对比图像"),
                variant_label(name, lang)
            );
            response
                .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &accessible));
            let painter = ui.painter_at(cell);
            painter.text(
                cell.min,
                egui::Align2::LEFT_TOP,
                variant_label(name, lang),
                egui::FontId::proportional(16.0),
                CURVES[i % CURVES.len()],
            );
            painter.image(
                texture.id(),
                image,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
            let scale = capture.width() as f32 / image.width();
            let to_image = |p: Pos2| [(p.x - image.min.x) * scale, (p.y - image.min.y) * scale];
            let to_screen = |p: [f32; 2]| image.min + Vec2::new(p[0], p[1]) / scale;
            if response.drag_started()
                && let Some(p) = response.interact_pointer_pos()
            {
                self.drag_start = Some(to_image(p));
            }
            if response.dragged()
                && let (Some(a), Some(p)) = (self.drag_start, response.interact_pointer_pos())
            {
                let b = to_image(p);
                cmds.push(Command::SetProfile(Some([a[0], a[1], b[0], b[1]])));
            }
            if let Some(l) = session.selection.profile {
                painter.line_segment(
                    [to_screen([l[0], l[1]]), to_screen([l[2], l[3]])],
                    Stroke::new(2.0, Color32::YELLOW),
                );
            }
        }
        ui.advance_cursor_after_rect(Rect::from_min_size(
            area.min,
            Vec2::new(area.width(), images_h + gap),
        ));
        self.plot(ui, session);
        cmds
    }

    fn plot(&self, ui: &mut Ui, session: &Session) {
        let lang = session.lang;
        let Some(line) = session.selection.profile else {
            return;
        };
        Plot::new("profile")
            .legend(Legend::default())
            .x_axis_label(lang.tr("position along the line (pixels)", "沿线位置（像素）"))
            .y_axis_label(lang.tr("intensity (Rec. 709 luminance)", "亮度（Rec. 709 亮度）"))
            .show(ui, |plot| {
                for (i, (name, capture)) in session.variants.iter().enumerate() {
                    let samples = capture.profile([line[0], line[1]], [line[2], line[3]]);
                    let length = (line[2] - line[0]).hypot(line[3] - line[1]);
                    let points: Vec<[f64; 2]> = samples
                        .iter()
                        .map(|s| [f64::from(s.t * length), f64::from(s.intensity)])
                        .collect();
                    plot.line(
                        Line::new(variant_label(name, lang), points)
                            .color(CURVES[i % CURVES.len()])
                            .width(2.0),
                    );
                }
            });
    }
}
