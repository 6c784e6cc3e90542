//! The observer view: the scene from outside, rendered by the same pipeline from an orbiting
//! camera at the panel's shape, with the viewing camera's frame (u, v, n), its frustum, the
//! clipped geometry and the lights drawn over it (`observer::viewing_camera`, the description the
//! exported image draws too).

use crate::app::command::ViewCommand;
use crate::app::views::picture_font;
use egui::{Align2, Color32, Rect, Stroke, TextureOptions, Ui, Vec2};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;

use super::{Projector, boxed_galley, fit_rect};
use crate::app::session::{Command, Session};
use crate::observer::{Orbit, Parts, scene_extent, viewing_camera};

/// The texture of the observer image and what to draw over it.
#[derive(Default)]
pub struct ObserverView {
    texture: super::BufferTexture,
    parts: Parts,
    /// Where the picture was drawn this frame.
    pub picture: Option<Rect>,
}

fn color(c: [u8; 4]) -> Color32 {
    Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3])
}

impl ObserverView {
    /// Draws the observer's image and the viewing camera over it.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session, main: &FrameCapture) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        let (outer, response) = super::picture_keys::allocate_rest(ui, "observer");
        super::alt::name_image(&response, || {
            lang.t("observer-observer-the-scene-seen-from").to_owned()
        });
        if outer.height() > 0.0 {
            cmds.push(Command::View(ViewCommand::SetObserverAspect(
                outer.width() / outer.height(),
            )));
        }
        let painter = ui.painter_at(outer);
        painter.rect_filled(outer, 0.0, super::palette::GROUND);
        self.picture = None;
        let Some(obs) = &session.observer else {
            painter.text(
                outer.center(),
                Align2::CENTER_CENTER,
                lang.t("observer-rendering-the-observer"),
                picture_font(painter.ctx(), 16.0),
                Color32::GRAY,
            );
            return cmds;
        };
        let rect = fit_rect(outer, obs.width() as f32 / obs.height() as f32);
        self.picture = Some(rect);
        let texture = self.texture.get(
            ui.ctx(),
            "observer",
            (session.shown_generation, BufferKind::Color, 1.0),
            obs,
            TextureOptions::LINEAR,
        );
        painter.image(
            texture.id(),
            rect,
            Rect::from_min_max(egui::Pos2::ZERO, egui::Pos2::new(1.0, 1.0)),
            Color32::WHITE,
        );
        let mut orbit: Orbit = session.orbit;
        let keys =
            super::picture_keys::take(ui, &response, Some(super::picture_keys::Place::Beside));
        // The arrows turn it as a drag that way would; `+` comes closer.
        orbit.yaw -= keys.arrows.x * super::geometry::ORBIT_STEP;
        orbit.pitch =
            (orbit.pitch - keys.arrows.y * super::geometry::ORBIT_STEP).clamp(-85.0, 85.0);
        orbit.distance = super::picture_keys::zoomed(orbit.distance, -keys.zoom, (0.2, 1e4));
        if response.dragged() {
            let d = response.drag_delta();
            orbit.yaw -= d.x * 0.4;
            orbit.pitch = (orbit.pitch + d.y * 0.4).clamp(-85.0, 85.0);
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            orbit.distance = (orbit.distance * (-scroll / 400.0).exp()).clamp(0.2, 1e4);
        }
        if orbit != session.orbit {
            cmds.push(Command::View(ViewCommand::SetOrbit(orbit)));
        }
        // The observer's own matrices, as its capture recorded them.
        let cam = Projector {
            m: obs.matrices.projection.matrix * obs.matrices.view.matrix,
            rect,
            zoom: 1.0,
            pan: Vec2::ZERO,
        };
        let painter = ui.painter_at(rect);
        let (marks, tags) = viewing_camera(main, &self.parts, scene_extent(&session.spec), lang);
        for m in &marks {
            cam.line(&painter, m.a, m.b, Stroke::new(m.width, color(m.color)));
        }
        let font = picture_font(painter.ctx(), 14.0);
        // Each tag below-right of its point, moved inside the picture where it would run off
        // its edge; none for a point outside it.
        let view = painter.clip_rect().shrink(4.0);
        for t in &tags {
            if let Some(p) = cam.project(t.at).filter(|p| view.contains(*p)) {
                let galley = painter.layout_no_wrap(t.text.clone(), font.clone(), color(t.color));
                let size = galley.size() + Vec2::splat(6.0);
                let at = super::moved_inside(Rect::from_min_size(p + Vec2::splat(3.0), size), view);
                boxed_galley(
                    &painter,
                    at.center(),
                    Align2::CENTER_CENTER,
                    galley,
                    color(t.color),
                );
            }
        }
        self.controls(ui, rect, lang);
        super::picture_keys::ring(ui, rect, keys);
        cmds
    }

    /// The title and the choice of what to draw, over the top-left of the picture.
    fn controls(&mut self, ui: &mut Ui, rect: Rect, lang: crate::vocabulary::Lang) {
        let size = ui.style().text_styles[&egui::TextStyle::Body].size;
        let bar = Rect::from_min_size(
            rect.left_top() + Vec2::splat(6.0),
            Vec2::new(rect.width() - 12.0, size * 1.8),
        );
        ui.scope_builder(egui::UiBuilder::new().max_rect(bar), |ui| {
            ui.horizontal(|ui| {
                ui.menu_button(lang.t("observer-observer"), |ui| {
                    ui.label(lang.t("observer-the-scene-from-outside-drag"));
                    let p = &mut self.parts;
                    ui.checkbox(&mut p.axes, lang.t("observer-camera-frame-u-v-n"));
                    ui.checkbox(&mut p.clipped, lang.t("observer-clipped-polygons"));
                    ui.checkbox(&mut p.sides, lang.t("observer-frustum-sides"));
                    ui.checkbox(&mut p.near, lang.t("observer-near-plane"));
                    ui.checkbox(&mut p.far, lang.t("observer-far-plane"));
                    ui.checkbox(&mut p.lights, lang.t("observer-lights"));
                });
            });
        });
    }
}
