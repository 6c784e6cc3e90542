//! A geometry stage: the vertex data *in that space*, drawn as a wireframe with the space's axes,
//! its view volume and the lights, seen by an orbiting camera that frames the step's subject (the
//! objects it names, every object by default) and zooms toward the cursor. Moving on to the next
//! stage animates the vertices from one space to the next (for clip → NDC, a gradual division by
//! w). A card shows the matrix the stage applies.

mod cards;

use egui::{Align2, Color32, FontId, Pos2, Rect, Sense, Stroke, Ui, Vec2};
use glam::{Vec3, Vec4};
use pipeline::capture::FrameCapture;
use pipeline::transform::{self};

use super::{
    FATES, Projector, draw_lights, fate_color, fate_index, palette, picture_font, wrapped_label,
};
use crate::app::session::{Command, Session};
use crate::vocabulary::{Lang, Space};

/// The orbiting camera of the geometry views, and the picture's zoom and pan.
pub struct GeometryView {
    yaw: f32,
    pitch: f32,
    /// Magnification about the view's centre (screen space).
    zoom: f32,
    /// Shift after the magnification, in points.
    pan: Vec2,
    /// The step the view was last reset for.
    reset_for: Option<u64>,
    /// Where the picture was drawn this frame.
    pub picture: Option<Rect>,
}

impl Default for GeometryView {
    fn default() -> Self {
        Self {
            yaw: 35.0,
            pitch: 22.0,
            zoom: 1.0,
            pan: Vec2::ZERO,
            reset_for: None,
            picture: None,
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

/// World coordinates into a space, for what is drawn besides the vertices (the lights); `None`
/// where it would mean nothing (model space, and past the projection).
fn world_into(capture: &FrameCapture, space: Space) -> Option<glam::Mat4> {
    match space {
        Space::World => Some(glam::Mat4::IDENTITY),
        Space::Eye => Some(capture.matrices.view.matrix),
        _ => None,
    }
}

/// Which vertex rows are the subject: the objects named by `focus` (a figure by its parts), every
/// object without it; in model space, one object (its own origin): the focused one, the selected
/// vertex's, or the first.
fn subject(capture: &FrameCapture, session: &Session, space: Space) -> Vec<bool> {
    let focus = session.selection.focus.as_deref().unwrap_or_default();
    let named = |name: &str| {
        focus.iter().any(|f| {
            name == f
                || name
                    .strip_prefix(f.as_str())
                    .is_some_and(|r| r.starts_with(": "))
        })
    };
    let mut objects: Vec<bool> = capture
        .objects
        .iter()
        .map(|o| focus.is_empty() || named(&o.name))
        .collect();
    if objects.iter().all(|o| !o) {
        objects.iter_mut().for_each(|o| *o = true);
    }
    if space == Space::Model {
        let by_vertex = session
            .selection
            .vertex
            .and_then(|i| capture.vertices.get(i as usize))
            .map(|v| v.object as usize);
        let one = by_vertex
            .or_else(|| objects.iter().position(|o| *o))
            .unwrap_or(0);
        objects = (0..capture.objects.len()).map(|k| k == one).collect();
    }
    objects
}

/// The sphere to frame, `(centre, radius)`: around the view volume in NDC and window
/// coordinates (a vertex just in front of the eye has enormous NDC coordinates, and would shrink
/// the cube to a dot), around the subject's vertices elsewhere; centred on their box, just
/// reaching the farthest.
fn bounds(capture: &FrameCapture, spaces: [Space; 2], subject: &[bool]) -> Option<(Vec3, f32)> {
    let mut points = Vec::new();
    let mut add = |p: Vec3| {
        if p.is_finite() {
            points.push(p);
        }
    };
    for space in spaces {
        match (space, volume(capture, space)) {
            (Space::Ndc | Space::Window, Some(corners)) => corners.into_iter().for_each(&mut add),
            _ => capture
                .vertices
                .iter()
                .filter(|v| subject.get(v.object as usize).copied().unwrap_or(false))
                .filter_map(|v| position(v, space))
                .for_each(&mut add),
        }
    }
    let lo = points.iter().copied().reduce(Vec3::min)?;
    let hi = points.iter().copied().reduce(Vec3::max)?;
    let centre = (lo + hi) / 2.0;
    let radius = points
        .iter()
        .map(|p| (*p - centre).length())
        .fold(0.0f32, f32::max);
    Some((centre, radius))
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
                picture_font(painter.ctx(), 16.0),
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

/// Every triangle as three segments, coloured by its fate (the subject brighter); returns the
/// stride used, the screen box of the subject and which fates (by [`fate_index`]) were drawn.
fn draw_triangles(
    painter: &egui::Painter,
    cam: &Projector,
    capture: &FrameCapture,
    points: &[Option<Vec3>],
    subject: &[bool],
) -> (usize, Rect, [bool; FATES.len()]) {
    let stride = capture.primitives.len().div_ceil(MAX_TRIANGLES).max(1);
    let mut seen = Rect::NOTHING;
    let mut fates = [false; FATES.len()];
    for prim in capture.primitives.iter().step_by(stride) {
        let focused = subject.get(prim.object as usize).copied().unwrap_or(false);
        let color = fate_color(&prim.fate);
        let stroke = Stroke::new(
            if focused { 1.3 } else { 0.8 },
            if focused {
                color
            } else {
                color.gamma_multiply(0.3)
            },
        );
        let p = prim
            .vertices
            .map(|r| points[r as usize].and_then(|p| cam.project(p)));
        if let [Some(a), Some(b), Some(c)] = p {
            // Separate segments: a joined outline of a sliver gets miter spikes.
            painter.line_segment([a, b], stroke);
            painter.line_segment([b, c], stroke);
            painter.line_segment([c, a], stroke);
            fates[fate_index(&prim.fate)] = true;
            if focused {
                seen = seen.union(Rect::from_points(&[a, b, c]));
            }
        }
    }
    (stride, seen, fates)
}

/// What the header over the picture says and where it may reach.
struct Header<'a> {
    /// The picture's rect.
    rect: Rect,
    space: Space,
    subject: &'a [bool],
    /// Whether the vertices move from one space into this one (the replay button).
    animated: bool,
    /// The header stays left of this x (the matrix card's left side).
    right: f32,
}

impl GeometryView {
    /// Draws the geometry of `space`, animated from `from` at progress `t`, with the stage's
    /// matrix in a card when `card`.
    #[allow(clippy::too_many_arguments)]
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        session: &Session,
        capture: &FrameCapture,
        space: Space,
        from: Option<Space>,
        t: f32,
        card: bool,
    ) -> Vec<Command> {
        let lang = session.lang;
        if self.reset_for != Some(session.step_entered) {
            // A new step frames its own subject.
            (self.zoom, self.pan) = (1.0, Vec2::ZERO);
            self.reset_for = Some(session.step_entered);
        }
        let mut cmds = Vec::new();
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        self.picture = Some(rect);
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(18));
        self.navigate(ui, &response, rect);
        let subject = subject(capture, session, space);
        let eased = t * t * (3.0 - 2.0 * t);
        let from = from.unwrap_or(space);
        let points: Vec<Option<Vec3>> = capture
            .vertices
            .iter()
            .map(|v| {
                if space == Space::Model && !subject[v.object as usize] {
                    None
                } else {
                    between(v, from, space, eased)
                }
            })
            .collect();
        let Some((cam, radius, centre)) =
            bounds(capture, [space, from], &subject).and_then(|b| self.camera(rect, b))
        else {
            painter.text(
                rect.center(),
                Align2::CENTER_CENTER,
                lang.tr("nothing to show in this space", "此空间中没有可显示的顶点"),
                picture_font(painter.ctx(), 18.0),
                Color32::GRAY,
            );
            return cmds;
        };
        draw_axes(&painter, &cam, radius * 0.6);
        let view_volume = volume(capture, space).filter(|_| t >= 1.0);
        if let Some(v) = &view_volume {
            draw_volume(&painter, &cam, v);
        }
        let (stride, seen, fates) = draw_triangles(&painter, &cam, capture, &points, &subject);
        let mut lights = false;
        if let Some(m) = world_into(capture, space) {
            let to_view = |p: Vec3| m.transform_point3(p);
            let world_centre = m.inverse().transform_point3(centre);
            lights = draw_lights(
                &painter,
                &cam,
                &capture.lights,
                &to_view,
                (world_centre, radius * 2.0),
                lang,
            );
        }
        let card = card
            .then(|| cards::matrix_card(&painter, rect, session, capture, space))
            .flatten();
        let header = Header {
            rect,
            space,
            subject: &subject,
            animated: from != space,
            right: card.map_or(rect.right(), |c| c.left()),
        };
        let title = self.header(ui, &painter, &header, session, capture, &mut cmds);
        let shown = cards::Shown {
            fates,
            volume: view_volume.is_some(),
            lights,
        };
        let top = card.map_or(rect.top(), |c| c.bottom()) + 8.0;
        let legend = cards::legend(&painter, rect, top, lang, stride, &shown);
        let avoid = [seen, card.unwrap_or(Rect::NOTHING), legend, title];
        cards::draw_selected(
            &painter, &cam, session, capture, space, &points, &avoid, rect,
        );
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            cmds.push(pick(&cam, &points, pos));
        }
        cmds
    }

    /// Space name and object at the top-left, wrapped left of the matrix card, the view buttons
    /// below it, drawn over the picture; returns where they are.
    fn header(
        &mut self,
        ui: &mut Ui,
        painter: &egui::Painter,
        header: &Header,
        session: &Session,
        capture: &FrameCapture,
        cmds: &mut Vec<Command>,
    ) -> Rect {
        let Header {
            rect,
            space,
            subject,
            animated,
            right,
        } = *header;
        let lang = session.lang;
        let size = ui.style().text_styles[&egui::TextStyle::Body].size;
        let mut title = space_name(space, lang).to_owned();
        if space == Space::Model
            && let Some(o) = subject
                .iter()
                .position(|s| *s)
                .and_then(|k| capture.objects.get(k))
        {
            title = format!("{title} · {}", session.spec.label(&o.name, lang));
        }
        let label = wrapped_label(
            painter,
            rect.left_top() + Vec2::new(8.0, 8.0),
            Align2::LEFT_TOP,
            &title,
            &FontId::proportional(size),
            Color32::WHITE,
            (right - rect.left() - 30.0).max(size * 6.0),
        );
        let buttons = Rect::from_min_size(
            Pos2::new(rect.left() + 8.0, label.bottom() + 6.0),
            Vec2::new(rect.width() * 0.5, size * 2.0),
        );
        let row = ui.scope_builder(egui::UiBuilder::new().max_rect(buttons), |ui| {
            ui.horizontal(|ui| {
                if ui.button(lang.tr("Front view", "正视图")).clicked() {
                    (self.yaw, self.pitch) = (0.0, 0.0);
                }
                if ui
                    .button(lang.tr("Reset view", "重置视角"))
                    .on_hover_text(lang.tr("Or double-click the picture.", "或双击画面。"))
                    .clicked()
                {
                    *self = Self {
                        reset_for: self.reset_for,
                        ..Self::default()
                    };
                }
                if animated
                    && ui
                        .button(lang.tr("▶ Replay transition", "▶ 重播变换"))
                        .on_hover_text(lang.tr("Space", "空格键"))
                        .clicked()
                {
                    cmds.push(Command::PlayTransition);
                }
            })
            .response
            .rect
        });
        label.union(row.inner)
    }

    /// Drag to orbit, scroll to zoom toward the cursor, drag with the right button (or
    /// Shift) to pan, double-click to reset.
    fn navigate(&mut self, ui: &Ui, response: &egui::Response, rect: Rect) {
        let shift = ui.input(|i| i.modifiers.shift);
        if response.double_clicked() {
            (self.zoom, self.pan) = (1.0, Vec2::ZERO);
        }
        if response.dragged_by(egui::PointerButton::Secondary) || (response.dragged() && shift) {
            self.pan += response.drag_delta();
        } else if response.dragged() {
            let d = response.drag_delta();
            self.yaw -= d.x * 0.4;
            self.pitch = (self.pitch + d.y * 0.4).clamp(-89.0, 89.0);
        }
        if let Some(pointer) = response.hover_pos() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y + i.zoom_delta().ln() * 300.0);
            if scroll != 0.0 {
                let zoom = (self.zoom * (scroll / 300.0).exp()).clamp(0.05, 80.0);
                // The point under the cursor stays where it is.
                let c = rect.center();
                let under = c + (pointer - c - self.pan) / self.zoom;
                self.pan = pointer - c - (under - c) * zoom;
                self.zoom = zoom;
            }
        }
    }

    /// The orbiting camera framing the sphere `(centre, radius)`.
    fn camera(&self, rect: Rect, (centre, radius): (Vec3, f32)) -> Option<(Projector, f32, Vec3)> {
        let radius = radius.max(1e-3);
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        let dir = Vec3::new(
            pitch.cos() * yaw.sin(),
            pitch.sin(),
            pitch.cos() * yaw.cos(),
        );
        // Far enough back that the sphere just fits the narrower side of a 40° lens: it subtends
        // a half-angle asin(r/d), the half field of view atan(tan 20°·min(aspect, 1)).
        let aspect = (rect.width() / rect.height()).min(1.0);
        let half = (20f32.to_radians().tan() * aspect).atan();
        let distance = radius * 1.06 / half.sin();
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
                zoom: self.zoom,
                pan: self.pan,
            },
            radius,
            centre,
        ))
    }
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
