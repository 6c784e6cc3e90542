//! A geometry stage: the vertex data *in that space*, drawn as a wireframe with the space's axes
//! and its view volume, seen by an orbiting camera. Moving on to the next stage animates the
//! vertices from one space to the next (for clip → NDC, a gradual division by w).

use egui::{Align2, Color32, FontId, Pos2, Sense, Stroke, Ui, Vec2};
use glam::{Vec3, Vec4};
use pipeline::capture::FrameCapture;
use pipeline::transform;

use super::{Projector, fate_color, palette};
use crate::app::session::{Command, Session};
use crate::vocabulary::{Lang, Space, vec3, vec4};

/// The orbiting camera of the geometry views.
pub struct GeometryView {
    yaw: f32,
    pitch: f32,
    zoom: f32,
}

impl Default for GeometryView {
    fn default() -> Self {
        Self {
            yaw: 35.0,
            pitch: 22.0,
            zoom: 1.0,
        }
    }
}

/// The most triangles drawn as wireframe (every k-th beyond that).
const MAX_TRIANGLES: usize = 30_000;

/// The position of vertex row `v` in a space; `None` where it has none (NDC and window
/// coordinates of a vertex with `w ≤ 0`).
fn position(v: &pipeline::vertex::VertexRecord, space: Space) -> Option<Vec3> {
    match space {
        Space::Model => Some(v.object_pos.truncate()),
        // A projective model matrix (the shadow matrix) leaves w ≠ 1: show the point it means.
        Space::World => (v.world.w > 0.0).then(|| v.world.truncate() / v.world.w),
        Space::Eye => (v.eye.w > 0.0).then(|| v.eye.truncate() / v.eye.w),
        Space::Clip => Some(v.clip.truncate()),
        Space::Ndc => v.ndc,
        Space::Window => v.window,
    }
}

/// A point on its way from `from` to `to` at `t ∈ [0, 1]`. Clip → NDC divides gradually:
/// `(x, y, z) / (1 + t·(w − 1))`, so the frustum is seen squeezing into the cube.
fn between(v: &pipeline::vertex::VertexRecord, from: Space, to: Space, t: f32) -> Option<Vec3> {
    if t >= 1.0 {
        return position(v, to);
    }
    if from == Space::Clip && to == Space::Ndc {
        let d = 1.0 + t * (v.clip.w - 1.0);
        return (v.clip.w > 0.0 && d > 1e-6).then(|| v.clip.truncate() / d);
    }
    Some(position(v, from)?.lerp(position(v, to)?, t))
}

fn space_name(space: Space, l: Lang) -> &'static str {
    match space {
        Space::Model => l.tr("object coordinates", "模型坐标"),
        Space::World => l.tr("world coordinates", "世界坐标"),
        Space::Eye => l.tr(
            "eye coordinates: camera at the origin, looking down −z",
            "相机坐标：相机在原点，朝向 −z",
        ),
        Space::Clip => l.tr(
            "clip coordinates (x, y, z of the homogeneous point)",
            "裁剪坐标（齐次点的 x, y, z）",
        ),
        Space::Ndc => l.tr(
            "normalized device coordinates: the canonical cube [−1, 1]³",
            "规范化设备坐标：规范立方体 [−1, 1]³",
        ),
        Space::Window => l.tr(
            "window coordinates: [0, W] × [0, H] × [0, 1]",
            "屏幕坐标：[0, W] × [0, H] × [0, 1]",
        ),
    }
}

/// The view volume in a space (world, eye, clip, NDC, window); `None` in model space.
fn volume(capture: &FrameCapture, space: Space) -> Option<[Vec3; 8]> {
    let eye = capture.projection.corners_eye(capture.settings.aspect());
    let m = &capture.matrices;
    let through = |mat: glam::Mat4, divide: bool| {
        eye.map(|p| {
            let c: Vec4 = mat * p.extend(1.0);
            if divide {
                c.truncate() / c.w
            } else {
                c.truncate()
            }
        })
    };
    match space {
        Space::Model => None,
        Space::World => Some(through(m.view.matrix.inverse(), false)),
        Space::Eye => Some(eye),
        Space::Clip => Some(through(m.projection.matrix, false)),
        Space::Ndc => Some(through(m.projection.matrix, true)),
        Space::Window => Some(through(m.viewport.matrix * m.projection.matrix, true)),
    }
}

/// The box to frame for the given spaces: the view volume in NDC and window coordinates (a
/// vertex just in front of the eye has enormous NDC coordinates, and would shrink the cube to a
/// dot), every finite vertex position elsewhere.
fn bounds(capture: &FrameCapture, spaces: [Space; 2], only: Option<u32>) -> Option<(Vec3, Vec3)> {
    let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    let mut add = |p: Vec3| {
        if p.is_finite() {
            lo = lo.min(p);
            hi = hi.max(p);
        }
    };
    for space in spaces {
        match (space, volume(capture, space)) {
            (Space::Ndc | Space::Window, Some(corners)) => corners.into_iter().for_each(&mut add),
            _ => capture
                .vertices
                .iter()
                .filter(|v| only.is_none_or(|o| v.object == o))
                .filter_map(|v| position(v, space))
                .for_each(&mut add),
        }
    }
    lo.is_finite().then_some((lo, hi))
}

/// The axes x, y, z of the space through its origin.
fn draw_axes(painter: &egui::Painter, cam: &Projector, length: f32) {
    for (axis, color, label) in [
        (Vec3::X, palette::X, "x"),
        (Vec3::Y, palette::Y, "y"),
        (Vec3::Z, palette::Z, "z"),
    ] {
        cam.line(painter, Vec3::ZERO, axis * length, Stroke::new(2.0, color));
        if let Some(p) = cam.project(axis * length * 1.08) {
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

/// The view volume's twelve edges: near rectangle, far rectangle, and the four between.
fn draw_volume(painter: &egui::Painter, cam: &Projector, v: &[Vec3; 8]) {
    let near = Stroke::new(1.5, palette::NEAR);
    let far = Stroke::new(1.2, palette::FAR);
    for i in 0..4 {
        cam.line(painter, v[i], v[(i + 1) % 4], near);
        cam.line(painter, v[4 + i], v[4 + (i + 1) % 4], far);
        cam.line(painter, v[i], v[4 + i], far);
    }
}

/// Every triangle as three segments, coloured by its fate; returns the stride used.
fn draw_triangles(
    painter: &egui::Painter,
    cam: &Projector,
    capture: &FrameCapture,
    points: &[Option<Vec3>],
) -> usize {
    let stride = capture.primitives.len().div_ceil(MAX_TRIANGLES).max(1);
    for prim in capture.primitives.iter().step_by(stride) {
        let stroke = Stroke::new(1.0, fate_color(&prim.fate));
        let p = prim
            .vertices
            .map(|r| points[r as usize].and_then(|p| cam.project(p)));
        if let [Some(a), Some(b), Some(c)] = p {
            // Separate segments: a joined outline of a sliver gets miter spikes.
            painter.line_segment([a, b], stroke);
            painter.line_segment([b, c], stroke);
            painter.line_segment([c, a], stroke);
        }
    }
    stride
}

impl GeometryView {
    /// Draws the geometry of `space`, animated from `from` at progress `t`.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        session: &Session,
        capture: &FrameCapture,
        space: Space,
        from: Option<Space>,
        t: f32,
    ) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = self.header(ui, space, from.is_some(), lang);
        // Object coordinates overlap (every object has its own origin): show one object, the
        // one of the selected vertex.
        let only = (space == Space::Model).then(|| {
            session
                .selection
                .vertex
                .and_then(|i| capture.vertices.get(i as usize))
                .map_or(0, |v| v.object)
        });
        if let Some(o) = only.and_then(|o| capture.objects.get(o as usize)) {
            ui.label(format!("{}: {}", lang.tr("object", "物体"), o.name)).on_hover_text(lang.tr(
                "Each object has its own origin; select a vertex of another object (vertex table) to show it.",
                "每个物体有自己的原点；在顶点表中选择另一物体的顶点即可切换。",
            ));
        }
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(18));
        self.orbit(ui, &response);
        let eased = t * t * (3.0 - 2.0 * t);
        let from = from.unwrap_or(space);
        let points: Vec<Option<Vec3>> = capture
            .vertices
            .iter()
            .map(|v| {
                if only.is_some_and(|o| v.object != o) {
                    None
                } else {
                    between(v, from, space, eased)
                }
            })
            .collect();
        let Some(cam) = bounds(capture, [space, from], only).and_then(|b| self.camera(rect, b))
        else {
            painter.text(
                rect.center(),
                Align2::CENTER_CENTER,
                lang.tr("nothing to show in this space", "此空间中没有可显示的顶点"),
                FontId::proportional(18.0),
                Color32::GRAY,
            );
            return cmds;
        };
        draw_axes(&painter, &cam.0, cam.1 * 0.6);
        if let Some(v) = volume(capture, space).filter(|_| t >= 1.0) {
            draw_volume(&painter, &cam.0, &v);
        }
        let stride = draw_triangles(&painter, &cam.0, capture, &points);
        if stride > 1 {
            painter.text(
                rect.left_bottom() + Vec2::new(8.0, -8.0),
                Align2::LEFT_BOTTOM,
                format!("{} 1/{stride}", lang.tr("showing triangles", "显示三角形")),
                FontId::proportional(13.0),
                Color32::YELLOW,
            );
        }
        self.legend(&painter, rect, lang);
        draw_selected(&painter, &cam.0, session, capture, space, &points);
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            cmds.push(pick(&cam.0, &points, pos));
        }
        cmds
    }

    fn header(&mut self, ui: &mut Ui, space: Space, animated: bool, lang: Lang) -> Vec<Command> {
        let mut cmds = Vec::new();
        ui.label(egui::RichText::new(space_name(space, lang)).strong());
        ui.horizontal_wrapped(|ui| {
            if ui.button(lang.tr("Front view", "正视图")).clicked() {
                (self.yaw, self.pitch) = (0.0, 0.0);
            }
            if ui.button(lang.tr("Reset view", "重置视角")).clicked() {
                *self = Self::default();
            }
            if animated
                && ui
                    .button(lang.tr("▶ Replay transition", "▶ 重播变换"))
                    .on_hover_text(lang.tr("Space", "空格键"))
                    .clicked()
            {
                cmds.push(Command::PlayTransition);
            }
        });
        cmds
    }

    /// Drag to orbit, scroll to zoom.
    fn orbit(&mut self, ui: &Ui, response: &egui::Response) {
        if response.dragged() {
            let d = response.drag_delta();
            self.yaw -= d.x * 0.4;
            self.pitch = (self.pitch + d.y * 0.4).clamp(-89.0, 89.0);
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            self.zoom = (self.zoom * (scroll / 300.0).exp()).clamp(0.05, 50.0);
        }
    }

    /// The orbiting camera framing the box `(lo, hi)`, and the box's radius.
    fn camera(&self, rect: egui::Rect, (lo, hi): (Vec3, Vec3)) -> Option<(Projector, f32)> {
        let centre = (lo + hi) / 2.0;
        let radius = ((hi - lo).length() / 2.0).max(1e-3);
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        let dir = Vec3::new(
            pitch.cos() * yaw.sin(),
            pitch.sin(),
            pitch.cos() * yaw.cos(),
        );
        // Far enough back that the sphere around the box fits the narrower side of the view.
        let aspect = (rect.width() / rect.height()).min(1.0);
        let distance = radius * 1.1 / (20f32.to_radians().tan() * aspect) / self.zoom;
        let up = if pitch.cos().abs() < 1e-3 {
            Vec3::Z
        } else {
            Vec3::Y
        };
        let view = transform::look_at(centre + dir * distance, centre, up).ok()?;
        let proj = transform::perspective(
            40.0,
            rect.width() / rect.height(),
            distance * 0.01,
            distance * 10.0 + radius * 4.0,
        );
        Some((
            Projector {
                m: proj.matrix * view,
                rect,
            },
            radius,
        ))
    }

    fn legend(&self, painter: &egui::Painter, rect: egui::Rect, lang: Lang) {
        let items = [
            (Color32::from_gray(220), lang.tr("drawn", "绘制")),
            (palette::CLIPPED, lang.tr("clipped", "被裁剪")),
            (Color32::from_gray(90), lang.tr("outside", "在视见体外")),
            (Color32::from_rgb(70, 90, 150), lang.tr("culled", "被剔除")),
            (palette::NEAR, lang.tr("near plane", "近平面")),
            (palette::FAR, lang.tr("far plane", "远平面")),
        ];
        let mut y = rect.top() + 10.0;
        for (color, text) in items {
            let p = Pos2::new(rect.right() - 150.0, y);
            painter.line_segment([p, p + Vec2::new(20.0, 0.0)], Stroke::new(3.0, color));
            painter.text(
                p + Vec2::new(26.0, 0.0),
                Align2::LEFT_CENTER,
                text,
                FontId::proportional(14.0),
                Color32::LIGHT_GRAY,
            );
            y += 20.0;
        }
    }
}

/// The selected vertex, with its coordinates in this space.
fn draw_selected(
    painter: &egui::Painter,
    cam: &Projector,
    session: &Session,
    capture: &FrameCapture,
    space: Space,
    points: &[Option<Vec3>],
) {
    let Some(i) = session.selection.vertex else {
        return;
    };
    let Some(v) = capture.vertices.get(i as usize) else {
        return;
    };
    let Some(p) = points[i as usize].and_then(|p| cam.project(p)) else {
        return;
    };
    painter.circle_filled(p, 6.0, palette::SELECTED);
    let text = if space == Space::Clip {
        vec4(v.clip)
    } else {
        position(v, space).map_or_else(String::new, vec3)
    };
    painter.text(
        p + Vec2::new(10.0, -10.0),
        Align2::LEFT_BOTTOM,
        format!("#{i} {text}"),
        FontId::monospace(14.0),
        palette::SELECTED,
    );
}

/// The vertex nearest a click (within 12 points), or none.
fn pick(cam: &Projector, points: &[Option<Vec3>], pos: Pos2) -> Command {
    let nearest = points
        .iter()
        .enumerate()
        .filter_map(|(i, p)| p.and_then(|p| cam.project(p)).map(|s| (i, s.distance(pos))))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    Command::SelectVertex(nearest.filter(|(_, d)| *d < 12.0).map(|(i, _)| i as u32))
}
