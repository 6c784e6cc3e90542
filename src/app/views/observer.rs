//! The observer view: the scene from outside, rendered by the same pipeline from an orbiting
//! camera, with the viewing camera's frame (u, v, n), its frustum and the clipped geometry drawn
//! over it.

use egui::{Align2, Color32, FontId, Rect, Sense, Stroke, TextureOptions, Ui, Vec2};
use glam::{Mat4, Vec3, Vec4};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::transform;

use super::{Projector, fit_rect, palette};
use crate::app::session::{Command, Session};
use crate::observer::Orbit;
use crate::vocabulary::Lang;

/// The texture of the observer image.
#[derive(Default)]
pub struct ObserverView {
    texture: super::BufferTexture,
    parts: Parts,
}

/// Which parts of the viewing camera the observer view draws, and in which colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parts {
    /// The camera frame u, v, n at the eye.
    pub axes: bool,
    /// The near plane's rectangle.
    pub near: bool,
    /// The far plane's rectangle.
    pub far: bool,
    /// The frustum's side edges (and the rays from the eye to the near corners).
    pub sides: bool,
    /// The polygons that clipping produced.
    pub clipped: bool,
    /// The near plane's colour.
    pub near_color: Color32,
    /// The far plane's and the sides' colour.
    pub far_color: Color32,
}

impl Default for Parts {
    fn default() -> Self {
        Self {
            axes: true,
            near: true,
            far: true,
            sides: true,
            clipped: true,
            near_color: palette::NEAR,
            far_color: palette::FAR,
        }
    }
}

impl ObserverView {
    /// Draws the observer's image and the viewing camera over it.
    pub fn ui(&mut self, ui: &mut Ui, session: &Session, main: &FrameCapture) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        ui.label(
            egui::RichText::new(lang.tr(
                "Observer: the scene from outside (drag to orbit, scroll to zoom)",
                "观察者视图：从外部看场景（拖动旋转，滚轮缩放）",
            ))
            .strong(),
        );
        ui.menu_button(lang.tr("Show…", "显示…"), |ui| {
            let p = &mut self.parts;
            ui.checkbox(
                &mut p.axes,
                lang.tr("camera frame u, v, n", "相机标架 u, v, n"),
            );
            ui.checkbox(
                &mut p.clipped,
                lang.tr("clipped polygons", "裁剪后的多边形"),
            );
            ui.checkbox(&mut p.sides, lang.tr("frustum sides", "视锥侧棱"));
            ui.horizontal(|ui| {
                ui.checkbox(&mut p.near, lang.tr("near plane", "近平面"));
                ui.color_edit_button_srgba(&mut p.near_color);
            });
            ui.horizontal(|ui| {
                ui.checkbox(&mut p.far, lang.tr("far plane", "远平面"));
                ui.color_edit_button_srgba(&mut p.far_color);
            });
        });
        let Some(obs) = &session.observer else {
            ui.label(lang.tr("(no observer image)", "（无观察者图像）"));
            return cmds;
        };
        let (outer, response) =
            ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        let rect = fit_rect(outer, obs.width() as f32 / obs.height() as f32);
        let painter = ui.painter_at(outer);
        let texture = self.texture.get(
            ui.ctx(),
            "observer",
            session.shown_generation,
            BufferKind::Color,
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
            cmds.push(Command::SetOrbit(orbit));
        }
        // The observer's own matrices, as its capture recorded them.
        let cam = Projector {
            m: obs.matrices.projection.matrix * obs.matrices.view.matrix,
            rect,
        };
        draw_viewing_camera(&painter, &cam, main, &self.parts, lang);
        cmds
    }
}

/// The viewing camera in world coordinates: its u, v, n axes at the eye, its frustum (near
/// plane, far plane, edges), and the polygons clipping produced.
fn draw_viewing_camera(
    painter: &egui::Painter,
    cam: &Projector,
    main: &FrameCapture,
    parts: &Parts,
    lang: Lang,
) {
    let c = main.camera;
    let Ok(frame) = transform::camera_frame(c.eye, c.at, c.up) else {
        return;
    };
    let [.., n, _] = main.projection.bounds(main.settings.aspect());
    let scale = (c.at - c.eye).length().max(n) * 0.25;
    if parts.axes {
        for (axis, color, label) in [
            (frame.u, palette::X, "u"),
            (frame.v, palette::Y, "v"),
            (frame.n, palette::Z, "n"),
        ] {
            cam.line(
                painter,
                c.eye,
                c.eye + axis * scale,
                Stroke::new(2.5, color),
            );
            if let Some(p) = cam.project(c.eye + axis * scale * 1.15) {
                painter.text(
                    p,
                    Align2::CENTER_CENTER,
                    label,
                    FontId::proportional(16.0),
                    color,
                );
            }
        }
    }
    if let Some(p) = cam.project(c.eye) {
        painter.circle_filled(p, 4.0, Color32::WHITE);
        painter.text(
            p + Vec2::new(6.0, 6.0),
            Align2::LEFT_TOP,
            lang.tr("eye", "视点"),
            FontId::proportional(14.0),
            Color32::WHITE,
        );
    }
    // Eye-space corners to world: the inverse of the view matrix the capture used.
    let to_world = main.matrices.view.matrix.inverse();
    let corners = main.projection.corners_eye(main.settings.aspect());
    let (near, far) = (&corners[..4], &corners[4..]);
    let w = |p: Vec3| to_world.transform_point3(p);
    for i in 0..4 {
        let j = (i + 1) % 4;
        if parts.near {
            cam.line(
                painter,
                w(near[i]),
                w(near[j]),
                Stroke::new(2.0, parts.near_color),
            );
        }
        if parts.far {
            cam.line(
                painter,
                w(far[i]),
                w(far[j]),
                Stroke::new(1.5, parts.far_color),
            );
        }
        if parts.sides {
            cam.line(
                painter,
                w(near[i]),
                w(far[i]),
                Stroke::new(1.0, parts.far_color),
            );
            if main.projection.is_perspective() {
                cam.line(
                    painter,
                    c.eye,
                    w(near[i]),
                    Stroke::new(1.0, parts.near_color.gamma_multiply(0.5)),
                );
            }
        }
    }
    if parts.clipped {
        draw_clipped(painter, cam, main);
    }
}

/// Clipped polygons, from clip space back to world: (P·V)⁻¹ applied to their clip coordinates.
fn draw_clipped(painter: &egui::Painter, cam: &Projector, main: &FrameCapture) {
    let clip_to_world: Mat4 =
        (main.matrices.projection.matrix * main.matrices.view.matrix).inverse();
    for prim in main
        .primitives
        .iter()
        .filter_map(|p| p.clipped_polygon.as_ref())
        .take(2000)
    {
        let pts: Vec<egui::Pos2> = prim
            .iter()
            .filter_map(|v| {
                let q: Vec4 = clip_to_world * v.clip;
                cam.project(q.truncate() / q.w)
            })
            .collect();
        for k in 0..pts.len() {
            painter.line_segment(
                [pts[k], pts[(k + 1) % pts.len()]],
                Stroke::new(1.5, palette::CLIPPED),
            );
        }
    }
}
