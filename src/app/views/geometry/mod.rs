//! A geometry stage: the vertex data *in that space*, drawn as a wireframe with the space's axes,
//! its view volume and the lights, seen by an orbiting camera that frames the step's subject (the
//! objects it names, every object by default) and zooms toward the cursor. Moving on to the next
//! stage animates the vertices from one space to the next (for clip → NDC, a gradual division by
//! w). A card shows the matrix the stage applies.

mod cards;
mod framing;
mod legend;

use egui::{Align2, Color32, FontId, Pos2, Rect, Stroke, Ui, Vec2};
use glam::Vec3;
use pipeline::capture::FrameCapture;

use super::{Projector, draw_lights, fate_color, fate_index, palette, picture_font, wrapped_label};
use crate::app::command::{SelectionCommand, ViewCommand};
use crate::app::session::{Command, Session};
use crate::spaces::{between, space_name, volume, world_into};
use crate::vocabulary::Space;
use framing::{SubjectBox, clear_of_cards};

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
    /// Where the step's focused objects were drawn this frame (none without a focus).
    pub subject: Option<Rect>,
    /// The cards drawn over the picture this frame (until the next one is framed clear of
    /// them): the header, the matrix card, the legend.
    pub cards: Vec<Rect>,
    /// The subject's box as the framing camera has seen it since the step, the space or the
    /// orbit last changed (see [`SubjectBox`]).
    seen: Option<SubjectBox>,
    /// The square the framing camera's picture filled last frame: zooming toward the cursor
    /// keeps the point under it where it is.
    square: Option<Rect>,
    /// Whether the legend, folded into a chip on a small screen, was opened.
    legend_open: bool,
}

impl Default for GeometryView {
    fn default() -> Self {
        Self {
            yaw: crate::spaces::YAW,
            pitch: crate::spaces::PITCH,
            zoom: 1.0,
            pan: Vec2::ZERO,
            reset_for: None,
            picture: None,
            subject: None,
            cards: Vec::new(),
            seen: None,
            square: None,
            legend_open: false,
        }
    }
}

/// Which vertex rows are the subject (see [`crate::spaces::subject`]).
fn subject(capture: &FrameCapture, session: &Session, space: Space) -> Vec<bool> {
    let focus = session.selection.focus.as_deref().unwrap_or_default();
    crate::spaces::subject(capture, focus, session.selection.vertex, space)
}

/// The axes x, y, z of the space through its origin.
/// Each drawn vertex's world normal as a short line from the vertex, `length` long: the normals
/// the lighting uses (an OBJ's, a built-in's exact ones, or the average of the faces' around
/// each vertex position, as the scene says).
fn draw_normals(
    painter: &egui::Painter,
    cam: &Projector,
    capture: &FrameCapture,
    points: &[Option<Vec3>],
    length: f32,
) {
    let stroke = egui::Stroke::new(1.5, Color32::from_rgb(90, 210, 230));
    for (v, p) in capture.vertices.iter().zip(points) {
        let Some(p) = p else { continue };
        let tip = *p + v.normal_world * length;
        if let (Some(a), Some(b)) = (cam.project(*p), cam.project(tip)) {
            painter.line_segment([a, b], stroke);
        }
    }
}

fn draw_axes(painter: &egui::Painter, cam: &Projector, length: f32) {
    for (axis, color, label) in [
        (Vec3::X, palette::X, "x"),
        (Vec3::Y, palette::Y, "y"),
        (Vec3::Z, palette::Z, "z"),
    ] {
        cam.line(painter, Vec3::ZERO, axis * length, Stroke::new(2.0, color));
        // On a dark box: an axis often ends on a line of the view volume (the viewport's x
        // runs along the near rectangle's edge).
        if let Some(p) = cam.project(axis * length * 1.08) {
            crate::app::views::label_with_background(
                painter,
                p,
                Align2::CENTER_CENTER,
                label,
                &picture_font(painter.ctx(), 16.0),
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

/// Every `stride`-th triangle (as `shown` says) as three segments, coloured by its fate (the
/// subject brighter) and dashed by it where `shown` is; returns the screen box of the subject.
fn draw_triangles(
    painter: &egui::Painter,
    cam: &Projector,
    capture: &FrameCapture,
    points: &[Option<Vec3>],
    (subject, shown): (&[bool], &legend::Shown),
) -> Rect {
    let (stride, dashed) = (shown.stride, shown.dashed);
    let mut seen = Rect::NOTHING;
    let scale = super::picture_scale(painter.ctx());
    for prim in capture.primitives.iter().step_by(stride) {
        let focused = subject.get(prim.object as usize).copied().unwrap_or(false);
        let color = fate_color(&prim.fate);
        let fate = (dashed.then(|| fate_index(&prim.fate)), scale);
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
            for ends in [[a, b], [b, c], [c, a]] {
                palette::fate_segment(painter, ends, stroke, fate);
            }
            if focused {
                seen = seen.union(Rect::from_points(&[a, b, c]));
            }
        }
    }
    seen
}

/// The camera a geometry view draws through, with the framed sphere's radius and centre.
type Framed = (Projector, f32, Vec3);

/// Said in the middle of a view with nothing in it to frame.
fn nothing_to_show(painter: &egui::Painter, rect: Rect, lang: crate::vocabulary::Lang) {
    painter.text(
        rect.center(),
        Align2::CENTER_CENTER,
        lang.t("geometry-nothing-to-show-in-this"),
        picture_font(painter.ctx(), 18.0),
        Color32::GRAY,
    );
}

/// `]` and `[` of a focused view: the next or previous vertex selected.
fn vertex_keys(
    keys: super::picture_keys::Keys,
    session: &Session,
    capture: &FrameCapture,
) -> Option<Command> {
    (keys.vertex != 0).then(|| {
        let count = capture.vertices.len();
        let vertex =
            super::picture_keys::stepped_vertex(session.selection.vertex, keys.vertex, count);
        Command::Selection(SelectionCommand::SelectVertex(vertex))
    })
}

/// Degrees an arrow key turns a focused geometry view or the observer.
pub const ORBIT_STEP: f32 = 5.0;

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
        let (rect, response) = super::picture_keys::allocate_rest(ui, "geometry view");
        let view = lang.t("geometry-geometry-view");
        super::alt::name_picture(&response, view, (session, capture, session.selection.stage));
        self.picture = Some(rect);
        self.subject = None;
        // Framed clear of where the cards were last frame; a move asks for one more frame.
        let own = std::mem::take(&mut self.cards);
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, palette::GROUND);
        let subject = subject(capture, session, space);
        let eased = t * t * (3.0 - 2.0 * t);
        let from = from.unwrap_or(space);
        let points = positions(capture, (from, space, eased), &subject);
        let framed_points = crate::spaces::framed_points(capture, [space, from], &subject);
        let sphere = crate::spaces::sphere_around(&framed_points);
        let view_volume = volume(capture, space).filter(|_| t >= 1.0);
        let shown = legend::shown(capture, space, sphere, view_volume.is_some());
        let legend = legend::Legend::for_view(ui, &painter, &shown, (self.legend_open, lang));
        let keys = self.navigate(ui, &response, self.square.unwrap_or(rect));
        let mut cmds: Vec<Command> = vertex_keys(keys, session, capture).into_iter().collect();
        let in_view = (rect, own.as_slice(), &legend);
        let scene = (session, capture);
        let (framed, legend_at) = self.frame(ui.ctx(), scene, space, framed_points, in_view);
        let Some((cam, radius, centre)) = framed else {
            nothing_to_show(&painter, rect, lang);
            return cmds;
        };
        draw_axes(&painter, &cam, radius * 0.6);
        if let Some(v) = &view_volume {
            draw_volume(&painter, &cam, v);
        }
        let seen = draw_triangles(&painter, &cam, capture, &points, (&subject, &shown));
        let focused = session
            .selection
            .focus
            .as_ref()
            .is_some_and(|f| !f.is_empty());
        self.subject = Some(seen.intersect(rect)).filter(|r| focused && r.is_positive());
        if space == Space::World && from == space && session.selection.show_normals {
            draw_normals(&painter, &cam, capture, &points, radius * 0.12);
        }
        if shown.lights
            && let Some(m) = world_into(capture, space)
        {
            let to_view = |p: Vec3| m.transform_point3(p);
            let world_centre = m.inverse().transform_point3(centre);
            draw_lights(
                &painter,
                &cam,
                &capture.lights,
                &to_view,
                (world_centre, radius * 2.0),
                (&own, rect),
                lang,
            );
        }
        let card = card
            .then(|| cards::matrix_card(&painter, rect, session, capture, space))
            .flatten();
        let header = self.header_beside(ui, rect, card);
        let header = Header {
            rect: header,
            space,
            subject: &subject,
            animated: from != space,
            right: header.right(),
        };
        let title = self.header(ui, &painter, &header, session, capture, &mut cmds);
        let chip = legend.chip_at(legend_at.0);
        let legend = legend.paint(&painter, legend_at.0, legend_at.1);
        if legend::chip(ui, chip, lang) {
            self.legend_open = !self.legend_open;
        }
        self.cards = vec![title, card.unwrap_or(Rect::NOTHING), legend];
        let moved = |a: &Rect, b: &Rect| (a.min - b.min).length() + (a.max - b.max).length() > 0.5;
        if own.len() != self.cards.len() || own.iter().zip(&self.cards).any(|(a, b)| moved(a, b)) {
            ui.ctx().request_repaint();
        }
        let narration = super::card_placement::narration_card(ui.ctx()).unwrap_or(Rect::NOTHING);
        let avoid = [
            seen,
            card.unwrap_or(Rect::NOTHING),
            legend,
            title,
            narration,
        ];
        cards::draw_selected(
            &painter, &cam, session, capture, space, &points, &avoid, rect,
        );
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            cmds.push(pick(&cam, &points, pos));
        }
        super::picture_keys::ring(ui, rect, keys);
        cmds
    }

    /// The camera that frames the subject in `space` (`points`, what
    /// [`crate::spaces::framed_points`] frames on the way into it, and in world and eye
    /// coordinates where the step's animation takes it) in the room of its shape that the
    /// cards (`own`, last frame's, and the narration card) leave in `rect`, with the sphere's
    /// radius and centre; and where the legend goes.
    fn frame(
        &mut self,
        ctx: &egui::Context,
        (session, capture): (&Session, &FrameCapture),
        space: Space,
        mut points: Vec<Vec3>,
        (rect, own, legend): (Rect, &[Rect], &legend::Legend),
    ) -> (Option<Framed>, (Rect, usize)) {
        let key = (
            session.step_entered,
            space,
            self.yaw.to_bits(),
            self.pitch.to_bits(),
        );
        if let Some(m) = world_into(capture, space)
            && session.subject_reach.0 == session.step_entered
        {
            let reach = &session.subject_reach.1;
            points.extend(reach.iter().map(|p| m.transform_point3(*p)));
        }
        let framed = SubjectBox::framing(&points, self.seen, key);
        self.seen = framed.map(|f| f.1);
        let aspect = framed.map_or(1.0, |f| f.1.aspect());
        let (frame, legend_at) = clear_of_cards(ctx, rect, own, legend, aspect);
        let cam = framed.map(|(m, seen)| {
            let (centre, radius) = seen.sphere();
            let square = seen.square_for(frame);
            self.square = Some(square);
            let cam = Projector {
                m,
                rect: square,
                zoom: self.zoom,
                pan: self.pan,
            };
            (cam, radius, centre)
        });
        (cam, legend_at)
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
        // On a small screen the view's buttons are in the View menu (`view_buttons`): a row of
        // finger-sized buttons over a phone's picture covered its subject.
        let small = crate::app::window_size::is_compact(ui.ctx());
        if small && !animated {
            return label;
        }
        // Left of the matrix card, wrapped onto more rows when they do not fit.
        let buttons = Rect::from_min_size(
            Pos2::new(rect.left() + 8.0, label.bottom() + 6.0),
            Vec2::new((right - rect.left() - 16.0).max(size * 8.0), size * 6.0),
        );
        let row = ui.scope_builder(egui::UiBuilder::new().max_rect(buttons), |ui| {
            ui.horizontal_wrapped(|ui| {
                if !small {
                    cmds.extend(self.view_buttons(ui, session, space));
                }
                if animated
                    && ui
                        .button(lang.t("geometry-replay-transition"))
                        .on_hover_text(lang.t("geometry-space"))
                        .clicked()
                {
                    cmds.push(Command::View(ViewCommand::PlayTransition));
                }
            })
            .response
            .rect
        });
        label.union(row.inner)
    }

    /// The view's own buttons: Front view, Reset view, and in world space the normals. Over
    /// the picture on a large screen (`header`); in the View menu on a small one.
    pub fn view_buttons(&mut self, ui: &mut Ui, session: &Session, space: Space) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        if ui.button(lang.t("geometry-front-view")).clicked() {
            (self.yaw, self.pitch) = (0.0, 0.0);
        }
        if ui
            .button(lang.t("geometry-reset-view"))
            .on_hover_text(lang.t("geometry-or-double-click-the-picture"))
            .clicked()
        {
            *self = Self {
                reset_for: self.reset_for,
                legend_open: self.legend_open,
                ..Self::default()
            };
        }
        if space == Space::World {
            let mut on = session.selection.show_normals;
            if ui
                .checkbox(&mut on, lang.t("geometry-normals"))
                .on_hover_text(lang.t("geometry-each-vertex-s-normal-n"))
                .changed()
            {
                cmds.push(Command::View(ViewCommand::ToggleNormals));
            }
        }
        cmds
    }

    /// Drag to orbit, scroll to zoom toward the cursor, drag with the right button (or
    /// Shift) to pan, double-click to reset; with the keyboard's focus, the arrows orbit as a
    /// drag that way would ([`ORBIT_STEP`] a press, Shift ten) and `+`/`−` zoom about the
    /// middle. Returns the keys it read (the vertex keys are the caller's).
    fn navigate(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        rect: Rect,
    ) -> super::picture_keys::Keys {
        let keys = super::picture_keys::take(ui, response, Some(super::picture_keys::Place::Main));
        self.yaw -= keys.arrows.x * ORBIT_STEP;
        self.pitch = (self.pitch - keys.arrows.y * ORBIT_STEP).clamp(-89.0, 89.0);
        if keys.zoom != 0 {
            let zoom = super::picture_keys::zoomed(self.zoom, keys.zoom, (0.05, 80.0));
            self.pan *= zoom / self.zoom;
            self.zoom = zoom;
        }
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
        keys
    }

    /// Where the header (the space's name, the view's buttons) goes: the top-left, left of the
    /// matrix card, or below the card across the view when the card leaves it less than nine
    /// words' room.
    fn header_beside(&self, ui: &Ui, rect: Rect, card: Option<Rect>) -> Rect {
        let size = ui.style().text_styles[&egui::TextStyle::Body].size;
        match card {
            Some(c) if c.left() - rect.left() >= size * 9.0 => {
                Rect::from_min_max(rect.min, Pos2::new(c.left(), rect.bottom()))
            }
            Some(c) => Rect::from_min_max(Pos2::new(rect.left(), c.bottom() + 2.0), rect.max),
            None => rect,
        }
    }
}

/// Each vertex row's position on the way from space `from` to `to` at eased progress `t`; in
/// model space, only the subject's (each object has its own origin there).
fn positions(
    capture: &FrameCapture,
    (from, to, t): (Space, Space, f32),
    subject: &[bool],
) -> Vec<Option<Vec3>> {
    capture
        .vertices
        .iter()
        .map(|v| {
            if to == Space::Model && !subject[v.object as usize] {
                None
            } else {
                between(v, from, to, t)
            }
        })
        .collect()
}

/// The vertex nearest a click (within 12 points), or none.
fn pick(cam: &Projector, points: &[Option<Vec3>], pos: Pos2) -> Command {
    let nearest = points
        .iter()
        .enumerate()
        .filter_map(|(i, p)| p.and_then(|p| cam.project(p)).map(|s| (i, s.distance(pos))))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    Command::Selection(SelectionCommand::SelectVertex(
        nearest.filter(|(_, d)| *d < 12.0).map(|(i, _)| i as u32),
    ))
}
