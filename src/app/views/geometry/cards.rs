//! What the geometry view draws over the wireframe: the card with the stage's matrix, the
//! selected vertex with its coordinates (the legend is `legend.rs`).

use crate::app::views::{picture_mono, picture_scale};
use egui::{Align2, Color32, FontId, Pos2, Rect, Stroke, Vec2};
use glam::Vec3;
use pipeline::capture::FrameCapture;
use pipeline::transform::{self, NamedMatrix};

use crate::app::session::{Session, Teaching};
use crate::app::views::{Projector, palette, place_label, typeset};
use crate::spaces::position;
use crate::vocabulary::{Space, num, vec3, vec4};

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
