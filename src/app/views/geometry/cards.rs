//! What the geometry view draws over the wireframe: the legend, the card with the stage's
//! matrix, the selected vertex with its coordinates.

use crate::app::views::{picture_font, picture_mono, picture_scale};
use egui::{Align2, Color32, FontId, Pos2, Rect, Stroke, Vec2};
use glam::Vec3;
use pipeline::capture::FrameCapture;
use pipeline::transform::{self, NamedMatrix};

use crate::app::session::{Session, Teaching};
use crate::app::views::{FATES, Projector, label_with_background, palette, place_label, typeset};
use crate::spaces::position;
use crate::vocabulary::{Lang, Space, num, vec3, vec4};

/// The least size of the matrix card's digits (points): a phone's view is 340–380 points
/// wide, and its reader holds it at arm's length.
pub(super) const MATRIX_LEAST: f32 = 12.0;

/// The matrix card's type size in a view `width` points wide: in classroom mode the
/// narration's size, the room reads its digits (the subject is framed clear of the card);
/// otherwise as the view's width allows, 13 to 24 points, and never under 12 (a phone's view,
/// 360 points wide, would make its digits 10 points).
fn card_type(ctx: &egui::Context, width: f32) -> f32 {
    let scale = picture_scale(ctx);
    if scale > 1.0 {
        15.0 * scale
    } else {
        (width / 42.0)
            .clamp(13.0, 24.0)
            .min(width / 36.0)
            .max(MATRIX_LEAST)
    }
}

/// What the picture shows, so that the legend names only that.
pub(super) struct Shown {
    /// Which fates (by `fate_index`) some drawn triangle met.
    pub fates: [bool; FATES.len()],
    /// Every how many triangles one is drawn.
    pub stride: usize,
    /// Whether the triangles are dashed by their fate (few enough of them to be).
    pub dashed: bool,
    /// Whether the view volume's edges are drawn.
    pub volume: bool,
    /// Whether a light is drawn.
    pub lights: bool,
}

/// The legend, measured before the picture is framed so that the subject can be framed clear
/// of it: what each colour drawn means, one item a row (a column) or as many a row as the
/// view's width holds (a strip along the foot).
pub(super) struct Legend {
    /// Each item's colour, words, and the fate whose dashes its line shows (by `fate_index`).
    items: Vec<(Color32, &'static str, Option<usize>)>,
    /// Each item's width (the widest's), its line and words.
    item_w: f32,
    row: f32,
    /// "showing triangles 1/n" when only every n-th triangle is drawn.
    note: Option<String>,
}

impl Legend {
    /// The legend of what `shown` says is drawn.
    pub(super) fn new(painter: &egui::Painter, shown: &Shown, lang: Lang) -> Self {
        let stride = shown.stride;
        let mut items: Vec<(Color32, &'static str, Option<usize>)> = FATES
            .iter()
            .zip(shown.fates)
            .enumerate()
            .filter(|(_, (_, drawn))| *drawn)
            .map(|(k, ((color, name), _))| (*color, lang.t(name), shown.dashed.then_some(k)))
            .collect();
        if shown.volume {
            items.push((palette::NEAR, lang.t("cards-near-plane"), None));
            items.push((palette::FAR, lang.t("cards-far-plane"), None));
        }
        if shown.lights {
            items.push((palette::LIGHT, lang.t("cards-light"), None));
        }
        let font = picture_font(painter.ctx(), 14.0);
        let item_w = items
            .iter()
            .map(|(_, text, _)| {
                let g = painter.layout_no_wrap((*text).to_owned(), font.clone(), Color32::WHITE);
                g.size().x
            })
            .fold(0.0f32, f32::max)
            + 40.0 * picture_scale(painter.ctx());
        let note = (stride > 1 && !items.is_empty())
            .then(|| format!("{} 1/{stride}", lang.t("cards-showing-triangles")));
        Self {
            items,
            item_w,
            row: font.size * 1.3,
            note,
        }
    }

    /// How many items a row holds in a strip `width` wide (at least one).
    pub(super) fn per_row(&self, width: f32) -> usize {
        ((width - 8.0) / self.item_w).floor().max(1.0) as usize
    }

    /// The legend's size with `per_row` items a row, its note below included; zero when it
    /// has nothing to say.
    pub(super) fn size(&self, per_row: usize) -> Vec2 {
        if self.items.is_empty() {
            return Vec2::ZERO;
        }
        let per_row = per_row.clamp(1, self.items.len());
        let rows = self.items.len().div_ceil(per_row);
        let note = if self.note.is_some() {
            self.row + 6.0
        } else {
            0.0
        };
        Vec2::new(
            self.item_w * per_row as f32 + 4.0,
            self.row * rows as f32 + 8.0 + note,
        )
    }

    /// Draws the legend in `at` (from [`Self::size`] with `per_row`); returns where it is.
    pub(super) fn paint(&self, painter: &egui::Painter, at: Rect, per_row: usize) -> Rect {
        if self.items.is_empty() {
            return Rect::NOTHING;
        }
        let per_row = per_row.clamp(1, self.items.len());
        let scale = picture_scale(painter.ctx());
        let note = if self.note.is_some() {
            self.row + 6.0
        } else {
            0.0
        };
        let back = Rect::from_min_max(at.min, at.max - Vec2::new(0.0, note));
        painter.rect_filled(back, 4.0, Color32::from_black_alpha(150));
        for (k, (color, text, fate)) in self.items.iter().enumerate() {
            let (r, c) = (k / per_row, k % per_row);
            let p = Pos2::new(
                back.left() + 8.0 + self.item_w * c as f32,
                back.top() + 4.0 + self.row * (r as f32 + 0.5),
            );
            // The line as the picture draws it: a fate's in its dashes, a little longer so
            // that the pattern shows.
            let ends = [p, p + Vec2::new(18.0 * scale, 0.0)];
            palette::fate_segment(
                painter,
                ends,
                Stroke::new(3.0, *color),
                (*fate, scale * 0.8),
            );
            painter.text(
                p + Vec2::new(24.0 * scale, 0.0),
                Align2::LEFT_CENTER,
                *text,
                picture_font(painter.ctx(), 14.0),
                Color32::from_gray(230),
            );
        }
        match &self.note {
            Some(note) => back.union(label_with_background(
                painter,
                back.left_bottom() + Vec2::new(0.0, 6.0),
                Align2::LEFT_TOP,
                note,
                &picture_font(painter.ctx(), 13.0),
                Color32::YELLOW,
            )),
            None => back,
        }
    }
}

/// The matrix the stage applies, big, in a card at the top-right: the object's model matrix, V,
/// P, the division by w, the viewport. Returns where the card is, if there is one.
pub(super) fn matrix_card(
    painter: &egui::Painter,
    rect: Rect,
    session: &Session,
    capture: &FrameCapture,
    space: Space,
) -> Option<Rect> {
    let m = &capture.matrices;
    let lang = session.lang;
    let (title, matrix): (String, Option<&NamedMatrix>) = match (space, session.teaching()) {
        (Space::World, Teaching::Model(k)) => match (m.models.get(k), capture.objects.get(k)) {
            (Some(model), Some(o)) => (
                format!("{} · {}", model.name, session.spec.label(&o.name, lang)),
                Some(model),
            ),
            _ => return None,
        },
        (Space::World, Teaching::Stack) => {
            // The root of the figure the step is about (the first figure when it names none).
            let figures = &session.spec.scene.figures;
            let focus = session.selection.focus.as_deref().unwrap_or_default();
            let figure = focus
                .iter()
                .find(|f| figures.iter().any(|g| &g.name == *f))
                .map(String::as_str);
            let (node, c) = pipeline::hierarchy::root_composite(&capture.hierarchy, figure)?;
            let part = crate::vocabulary::part_name(node, lang);
            let title = match figure {
                Some(f) => format!("M({part}) · {}", session.spec.label(f, lang)),
                None => format!("M({part})"),
            };
            (title, Some(c))
        }
        (Space::Eye, _) => (m.view.name.clone(), Some(&m.view)),
        (Space::Clip, _) => (m.projection.name.clone(), Some(&m.projection)),
        (Space::Ndc, _) => (
            "(x_ndc, y_ndc, z_ndc) = (x_c, y_c, z_c)/w_c".to_owned(),
            None,
        ),
        (Space::Window, _) => (m.viewport.name.clone(), Some(&m.viewport)),
        _ => return None,
    };
    let size = card_type(painter.ctx(), rect.width());
    let style = typeset::Style {
        size,
        color: Color32::WHITE,
        accent: Color32::from_rgb(255, 214, 120),
    };
    let mono = FontId::monospace(size);
    let rows = matrix.map(|mat| transform::to_rows(&mat.matrix));
    let cells: Vec<Vec<std::sync::Arc<egui::Galley>>> = rows
        .iter()
        .flatten()
        .map(|r| {
            r.iter()
                .map(|v| painter.layout_no_wrap(num(*v), mono.clone(), Color32::WHITE))
                .collect()
        })
        .collect();
    let col_w = cells
        .iter()
        .flatten()
        .map(|g| g.size().x)
        .fold(0.0f32, f32::max)
        + size * 0.8;
    let row_h = size * 1.3;
    let title_galley_w = {
        let probe =
            painter.layout_no_wrap(title.clone(), FontId::proportional(size), Color32::WHITE);
        probe.size().x
    };
    let width = (col_w * 4.0).max(title_galley_w) + size;
    let height = size * 1.8 + if rows.is_some() { row_h * 4.0 } else { 0.0 } + size * 0.5;
    let card = Rect::from_min_size(
        Pos2::new(rect.right() - width - 10.0, rect.top() + 10.0),
        Vec2::new(width, height),
    );
    painter.rect_filled(card, 6.0, Color32::from_black_alpha(190));
    typeset::paint_formula(
        painter,
        card.left_top() + Vec2::new(size * 0.5, size * 0.4),
        Align2::LEFT_TOP,
        &title,
        &style,
    );
    for (r, row) in cells.iter().enumerate() {
        for (c, g) in row.iter().enumerate() {
            let right = card.left() + size * 0.5 + col_w * (c as f32 + 1.0) - size * 0.4;
            let y = card.top() + size * 1.8 + row_h * r as f32;
            painter.galley(Pos2::new(right - g.size().x, y), g.clone(), Color32::WHITE);
        }
    }
    // The bracket of the matrix.
    if rows.is_some() {
        let top = card.top() + size * 1.7;
        let bottom = top + row_h * 4.0;
        let stroke = Stroke::new(1.5, Color32::from_gray(200));
        for x in [card.left() + size * 0.35, card.right() - size * 0.35] {
            painter.line_segment([Pos2::new(x, top), Pos2::new(x, bottom)], stroke);
        }
    }
    Some(card)
}

/// The selected vertex with its coordinates in this space, the label placed off the subject
/// and the cards (`avoid`, the subject first).
#[allow(clippy::too_many_arguments)]
pub(super) fn draw_selected(
    painter: &egui::Painter,
    cam: &Projector,
    session: &Session,
    capture: &FrameCapture,
    space: Space,
    points: &[Option<Vec3>],
    avoid: &[Rect],
    view: Rect,
) {
    let Some(i) = session.selection.vertex else {
        return;
    };
    let (Some(v), Some(Some(p))) = (
        capture.vertices.get(i as usize),
        points
            .get(i as usize)
            .map(|p| p.and_then(|p| cam.project(p))),
    ) else {
        return;
    };
    painter.circle_filled(p, 6.0, palette::SELECTED);
    let text = if space == Space::Clip {
        vec4(v.clip)
    } else {
        position(v, space).map_or_else(String::new, vec3)
    };
    let font = picture_mono(painter.ctx(), 15.0);
    let galley = painter.layout_no_wrap(format!("v{i} {text}"), font, palette::SELECTED);
    let place = place_label(p, galley.size() + Vec2::splat(6.0), avoid, view.shrink(4.0));
    painter.line_segment(
        [p, place.center()],
        Stroke::new(1.0, palette::SELECTED.gamma_multiply(0.7)),
    );
    painter.rect_filled(place, 3.0, Color32::from_black_alpha(180));
    painter.galley(place.min + Vec2::splat(3.0), galley, palette::SELECTED);
}
