//! Settings side by side — flat | Gouraud | Phong (the Mach band comparison), affine |
//! perspective-correct, 1× | 4× MSAA | 4× SSAA, the four texture filters — using the whole width:
//! the images in the grid that makes them largest, and under them the intensity profile along a
//! line the user drags across any of them, plotted for all of them in the images' order.

use egui::{Color32, Pos2, Rect, Sense, Stroke, TextureOptions, Ui, Vec2};
use egui_plot::{Line, Plot};

use super::fit_rect;
use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::{profile, variant_label};

/// Textures of the compared images, the line being dragged, where the picture was drawn.
#[derive(Default)]
pub struct CompareView {
    textures: Vec<super::BufferTexture>,
    /// The gain the compared lighting terms share.
    gain: super::TermGain,
    drag_start: Option<[f32; 2]>,
    /// The images' and the plot's rects this frame.
    pub picture: Vec<Rect>,
}

/// Colours of the compared settings' curves (and their captions).
pub const CURVES: [Color32; 4] = {
    let c = profile::CURVE_COLORS;
    [
        Color32::from_rgb(c[0][0], c[0][1], c[0][2]),
        Color32::from_rgb(c[1][0], c[1][1], c[1][2]),
        Color32::from_rgb(c[2][0], c[2][1], c[2][2]),
        Color32::from_rgb(c[3][0], c[3][1], c[3][2]),
    ]
};

/// The number of columns that makes `n` images of `aspect` largest in `area`.
fn best_columns(n: usize, aspect: f32, area: Vec2) -> usize {
    (1..=n)
        .max_by(|&a, &b| {
            let size = |cols: usize| {
                let rows = n.div_ceil(cols) as f32;
                let (w, h) = (area.x / cols as f32, area.y / rows);
                let h = h.min(w / aspect);
                h * h * aspect
            };
            size(a).total_cmp(&size(b))
        })
        .unwrap_or(1)
}

/// The images in the grid that makes them largest (in at most 70 % of the height when a
/// profile is plotted; the plot takes all the height they leave): `(n, aspect)` images, `gap`
/// between them. Returns the columns, a cell's size and the rectangle of all the images.
fn grid(area: Rect, (n, aspect): (usize, f32), with_plot: bool, gap: f32) -> (usize, Vec2, Rect) {
    let room = Vec2::new(
        area.width(),
        area.height() * if with_plot { 0.7 } else { 1.0 },
    );
    let cols = best_columns(n, aspect, room);
    let rows = n.div_ceil(cols);
    let cell_w = (area.width() - gap * (cols as f32 - 1.0)) / cols as f32;
    let cell_h = ((room.y - gap * (rows as f32 - 1.0)) / rows as f32).min(cell_w / aspect);
    let images = Rect::from_min_size(
        area.min,
        Vec2::new(
            area.width(),
            cell_h * rows as f32 + gap * (rows as f32 - 1.0),
        ),
    );
    (cols, Vec2::new(cell_w, cell_h), images)
}

/// Each image's cell in the grid `(cols, cell, images)` of `n` images, and the grid's rect.
fn cells((cols, cell, images): (usize, Vec2, Rect), n: usize, gap: f32) -> (Vec<Rect>, Rect) {
    let cells = (0..n)
        .map(|i| {
            let (c, r) = (i % cols, i / cols);
            Rect::from_min_size(
                images.min + Vec2::new(c as f32 * (cell.x + gap), r as f32 * (cell.y + gap)),
                cell,
            )
        })
        .collect();
    (cells, images)
}

/// The grid's cells framed clear of the narration card: in the whole area when the images miss
/// it, else right of it or above it, whichever makes them larger (reported to the card as the
/// share of their size they kept).
fn framed(
    ctx: &egui::Context,
    area: Rect,
    (n, aspect): (usize, f32),
    with_plot: bool,
    gap: f32,
) -> (Vec<Rect>, Rect) {
    let card = super::card_placement::narration_card(ctx);
    let (cells, images) = super::card_placement::candidates(area, card)
        .into_iter()
        .map(|r| cells(grid(r, (n, aspect), with_plot, gap), n, gap))
        .filter(|(cells, _)| {
            cells
                .iter()
                .all(|c| super::card_placement::misses(fit_rect(*c, aspect), card))
        })
        .max_by(|a, b| a.0[0].area().total_cmp(&b.0[0].area()))
        .unwrap_or_else(|| cells(grid(area, (n, aspect), with_plot, gap), n, gap));
    let unobstructed = grid(area, (n, aspect), with_plot, gap).1;
    super::card_placement::report_kept(ctx, cells[0].area() / (unobstructed.x * unobstructed.y));
    (cells, images)
}

impl CompareView {
    /// Draws the images and the profile plot below them.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        self.picture.clear();
        let variants = &session.variants;
        if variants.is_empty() {
            ui.label(lang.t("compare-rendering-the-comparison"));
            return cmds;
        }
        let card = super::card_placement::narration_card(ui.ctx());
        let area = ui.available_rect_before_wrap();
        let with_plot = session.selection.profile.is_some();
        let aspect = variants[0].1.width() as f32 / variants[0].1.height() as f32;
        let caption_size = ui.style().text_styles[&egui::TextStyle::Body].size * 1.1;
        let gap = 6.0;
        let (cells, images) = framed(ui.ctx(), area, (variants.len(), aspect), with_plot, gap);
        let kind = session.selection.buffer;
        let gain = self.gain.get((session.shown_generation, kind), || {
            pipeline::capture::FrameCapture::shared_term_gain(
                variants.iter().map(|(_, c)| &**c),
                kind,
            )
        });
        for (i, ((name, capture), &cell)) in variants.iter().zip(&cells).enumerate() {
            if self.textures.len() <= i {
                self.textures.resize_with(i + 1, Default::default);
            }
            let texture = self.textures[i].get(
                ui.ctx(),
                &format!("compare-{i}"),
                (session.shown_generation, kind, gain),
                capture,
                TextureOptions::NEAREST,
            );
            let image = fit_rect(cell, capture.width() as f32 / capture.height() as f32);
            self.picture.push(image);
            let response = ui.interact(image, ui.scope_id().with(("compare", i)), Sense::drag());
            let caption = variant_label(name, lang);
            let accessible = lang.t_with("compare-compared-image", &[("caption", &caption)]);
            super::alt::name_image(&response, || accessible.clone());
            let painter = ui.painter_at(cell);
            painter.image(
                texture.id(),
                image,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
            // The caption over the image's top-left corner, in the colour of its curve.
            super::label_with_background(
                &painter,
                image.left_top() + Vec2::splat(6.0),
                egui::Align2::LEFT_TOP,
                &caption,
                &egui::FontId::proportional(caption_size),
                CURVES[i % CURVES.len()],
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
                // A click is not a line: a profile needs two image pixels' length (a shorter
                // one would plot an empty chart over half the window).
                if (b[0] - a[0]).hypot(b[1] - a[1]) >= 2.0 {
                    cmds.push(Command::Selection(SelectionCommand::SetProfile(Some([
                        a[0], a[1], b[0], b[1],
                    ]))));
                }
            }
            if let Some(l) = session.selection.profile {
                painter.line_segment(
                    [to_screen([l[0], l[1]]), to_screen([l[2], l[3]])],
                    Stroke::new(2.5, Color32::YELLOW),
                );
            }
        }
        let bottom = images.center_bottom() - Vec2::new(0.0, 8.0);
        let at = (bottom, egui::Align2::CENTER_BOTTOM, images.width() - 24.0);
        super::draw_gain_note(ui.painter(), at, kind, gain, lang);
        ui.advance_cursor_after_rect(images);
        if with_plot {
            // Below the images, right of the card when the card would cover its axes.
            let plot = super::card_placement::right_of(
                Rect::from_min_max(
                    Pos2::new(images.left(), images.bottom() + gap),
                    Pos2::new(images.right(), area.bottom()),
                ),
                card,
            );
            self.picture.push(plot);
            let inner = crate::app::views::plot_axes::plot_rect(ui, plot);
            ui.scope_builder(egui::UiBuilder::new().max_rect(inner), |ui| {
                self.plot(ui, session)
            });
        }
        cmds
    }

    fn plot(&self, ui: &mut Ui, session: &Session) {
        let lang = session.lang;
        let Some(line) = session.selection.profile else {
            return;
        };
        let (x_axes, y_axes) = crate::app::views::plot_axes::axes(
            profile::x_label(lang),
            profile::y_label(lang),
            40.0,
        );
        let names: Vec<String> = session
            .variants
            .iter()
            .map(|(name, _)| variant_label(name, lang))
            .collect();
        let entries: Vec<(&str, egui::Color32)> = names
            .iter()
            .enumerate()
            .map(|(i, n)| (n.as_str(), CURVES[i % CURVES.len()]))
            .collect();
        let shown = crate::app::views::plot_legend::legend(ui, "profile", &entries);
        Plot::new("profile")
            .custom_x_axes(x_axes)
            .custom_y_axes(y_axes)
            .include_y(0.0)
            .allow_scroll(false)
            .allow_axis_zoom_drag(false)
            .show(ui, |plot| {
                for (i, (name, capture)) in session.variants.iter().enumerate() {
                    if !shown[i] {
                        continue;
                    }
                    let points = profile::points(capture, line);
                    plot.line(
                        Line::new(variant_label(name, lang), points)
                            .color(CURVES[i % CURVES.len()])
                            .width(2.0),
                    );
                }
            });
    }
}
