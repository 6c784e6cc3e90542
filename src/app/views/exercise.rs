//! An exercise step's pictures beside the student's: pipelens' own frame (the reference) above,
//! the difference below (matching pixels dim, differing ones red, coverage differences yellow),
//! with the count of matching pixels; a click on either inspects that pixel in the student's
//! frame. And the card's part: the task, the verdict, and the first wrong pixel to inspect.

use std::sync::Arc;

use egui::text::LayoutJob;
use egui::{Color32, Pos2, Rect, RichText, Sense, TextureOptions, Ui, Vec2};
use pipeline::buffers::{BufferKind, Capture};
use pipeline::capture::{DIFFERENCE_COLOURS, FrameCapture};

use super::typeset::{self, Style};
use super::{BufferTexture, boxed_galley, fit_rect, picture_font};
use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};
use crate::lab::words;
use crate::lesson::answer::Exercise;

/// Green for passed, amber for not yet.
const PASSED: Color32 = Color32::from_rgb(120, 220, 120);
const NOT_YET: Color32 = Color32::from_rgb(255, 170, 90);

/// The reference and difference pictures, cached per pair of frames.
#[derive(Default)]
pub struct ExerciseView {
    reference: BufferTexture,
    difference: Option<((usize, usize), egui::TextureHandle)>,
    /// Where the pictures were drawn this frame (for the share of the window they take).
    pub picture: Vec<Rect>,
    /// The boxes of their captions this frame (words that must not cover a picture).
    pub captions: Vec<Rect>,
}

/// A frame's identity for the caches: its address (a new render is a new frame).
fn key(c: &Arc<FrameCapture>) -> usize {
    Arc::as_ptr(c) as usize
}

impl ExerciseView {
    /// Draws the reference above and the difference below in `rect`; a click inspects a pixel.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        session: &Session,
        capture: &Arc<FrameCapture>,
        rect: Rect,
    ) -> Vec<Command> {
        let lang = session.lang;
        let mut cmds = Vec::new();
        self.picture.clear();
        self.captions.clear();
        let Some(reference) = &session.exercise.reference else {
            ui.put(
                rect,
                egui::Label::new(lang.t("exercise-drawing-pipelens-own-frame")),
            );
            return cmds;
        };
        let tolerance = session.current_exercise().map_or(1.0, |e| e.tolerance);
        let aspect = capture.width() as f32 / capture.height() as f32;
        let kind = reference_kind(session);
        let gain = capture.term_gain(kind);
        let depth = session.selection.depth_view;
        let reference_texture = self.reference.get_with(
            ui.ctx(),
            "exercise-reference",
            (
                key(reference) as u64,
                kind,
                u64::from(gain.to_bits()) ^ u64::from(depth.linear),
            ),
            TextureOptions::NEAREST,
            || match kind {
                BufferKind::Depth => reference.depth_image(depth.linear, depth.range),
                kind => reference.image_shown(kind, gain),
            },
        );
        let pair = (key(capture), key(reference));
        if self.difference.as_ref().is_none_or(|(k, _)| *k != pair) {
            let criteria = session.exercise.findings.difference.as_ref().map_or_else(
                || crate::lab::criteria(&session.spec.scene, tolerance),
                |d| d.criteria,
            );
            let img = capture.difference_image(reference, criteria);
            let image = egui::ColorImage::from_rgba_unmultiplied(
                [img.width() as usize, img.height() as usize],
                img.as_raw(),
            );
            let t = ui
                .ctx()
                .load_texture("exercise-difference", image, TextureOptions::NEAREST);
            self.difference = Some((pair, t));
        }
        let difference_texture = self.difference.as_ref().map(|(_, t)| t.clone());
        let captions = captions(kind, lang, &picture_font(ui.ctx(), 14.0));
        let height = caption_height(ui.ctx(), session);
        let pair = crate::app::layout::lab_pair(rect, aspect, &height);
        let wrapped_captions: [_; 2] = std::array::from_fn(|i| {
            ui.painter()
                .layout_job(wrapped(&captions[i], pair[i].space.width()))
        });
        // Side by side, both pictures leave the room of the higher caption (the difference's
        // key wraps to three lines on a phone), so that they stand at one size and one top;
        // one over the other, each its own caption's (a landscape phone's view is short).
        let beside = (pair[0].space.top() - pair[1].space.top()).abs() < 0.5;
        let highest = wrapped_captions
            .iter()
            .map(|c| c.size().y + 6.0)
            .fold(0.0, f32::max);
        for ((i, texture), caption) in [Some(reference_texture), difference_texture]
            .into_iter()
            .enumerate()
            .zip(wrapped_captions)
        {
            let Some(texture) = texture else { continue };
            let space = pair[i].space;
            let room = if beside {
                highest
            } else {
                caption.size().y + 6.0
            };
            let (at, above) = captioned(space, aspect, room);
            report_uncovered(ui.ctx(), at);
            self.picture.push(at);
            let (pick, boxed) = picture(
                ui,
                (space, at, i, &texture),
                (caption, above),
                session,
                capture,
            );
            cmds.extend(pick);
            self.captions.push(boxed);
        }
        cmds
    }
}

/// Reports how much of a companion picture at `at` the narration card in its corner leaves
/// uncovered (the card of the last frame), so that a card over it becomes a band or a column
/// ([`super::card_placement::shape`]): the two are drawn whole, not framed around the card as
/// the student's frame is.
fn report_uncovered(ctx: &egui::Context, at: Rect) {
    let Some(card) = super::card_placement::narration_card(ctx) else {
        return;
    };
    let hidden = at.intersect(card);
    if hidden.is_positive() && at.is_positive() {
        super::card_placement::report_kept(ctx, 1.0 - hidden.area() / at.area());
    }
}

/// The buffer pipelens' own picture shows: the one the student's frame is shown in (with its
/// gain, its depth ramp), as the buffer menu names it, where the reference kept it; colour
/// otherwise.
fn reference_kind(session: &Session) -> BufferKind {
    let shown = session.selection.buffer;
    let kept = session
        .exercise
        .reference
        .as_ref()
        .is_some_and(|r| r.settings.capture.covers(Capture::showing([shown])));
    if kept { shown } else { BufferKind::Color }
}

/// How high the two companion pictures' captions are, wrapped to a space `width` wide: the
/// higher of the two with its margin, as [`ExerciseView::ui`] lays them out.
pub fn caption_height(ctx: &egui::Context, session: &Session) -> impl Fn(f32) -> f32 + use<> {
    let captions = captions(
        reference_kind(session),
        session.lang,
        &picture_font(ctx, 14.0),
    );
    let ctx = ctx.clone();
    move |width: f32| {
        captions
            .iter()
            .map(|c| ctx.fonts_mut(|f| f.layout_job(wrapped(c, width))).size().y + 6.0)
            .fold(0.0, f32::max)
    }
}

/// A caption wrapped to a space `width` wide (less its box's margins).
fn wrapped(caption: &LayoutJob, width: f32) -> LayoutJob {
    let mut job = caption.clone();
    job.wrap.max_width = width - 6.0;
    job
}

/// The captions of pipelens' own picture (showing the buffer `kind`) and of the difference,
/// whose key names each meaning in its colour in the picture (red: colour, yellow: coverage,
/// blue: depth, pink: another triangle).
fn captions(
    kind: BufferKind,
    lang: crate::vocabulary::Lang,
    font: &egui::FontId,
) -> [LayoutJob; 2] {
    let format = |color: Color32| egui::TextFormat::simple(font.clone(), color);
    let mut own = LayoutJob::default();
    own.append(
        &format!(
            "{} · {}",
            lang.t("exercise-pipelens-own"),
            crate::vocabulary::buffer_name(kind, lang)
        ),
        0.0,
        format(Color32::WHITE),
    );
    let mut difference = LayoutJob::default();
    difference.append(lang.t("exercise-difference"), 0.0, format(Color32::WHITE));
    let names = [
        lang.t("exercise-colour"),
        lang.t("exercise-coverage"),
        lang.t("exercise-depth"),
        lang.t("exercise-another-triangle"),
    ];
    let separator = lang.t("list-separator");
    for (k, (name, [r, g, b])) in names.into_iter().zip(DIFFERENCE_COLOURS).enumerate() {
        difference.append(name, 0.0, format(Color32::from_rgb(r, g, b)));
        if k + 1 < names.len() {
            difference.append(separator, 0.0, format(Color32::WHITE));
        }
    }
    [own, difference]
}

/// A picture of `aspect` fitted in `half` with its caption of height `caption`: above it where
/// the half has the room (the picture moved down as far as that needs, or made smaller by up to
/// a third to leave that room; `true`), else over its top-left corner (a very low space).
fn captioned(half: Rect, aspect: f32, caption: f32) -> (Rect, bool) {
    let at = fit_rect(half, aspect);
    if half.height() - at.height() < caption {
        let below = Rect::from_min_max(half.min + Vec2::new(0.0, caption), half.max);
        let smaller = fit_rect(below, aspect);
        if below.height() <= 0.0 || smaller.width() < at.width() * 2.0 / 3.0 {
            return (at, false);
        }
        return (smaller, true);
    }
    let down = (half.top() + caption - at.top()).max(0.0);
    (at.translate(Vec2::new(0.0, down)), true)
}

/// One picture beside the student's, captioned (above it, or over it: `above`), the inspected
/// pixel marked; a click on it inspects that pixel. Returns that command and the caption's box.
fn picture(
    ui: &mut Ui,
    (space, at, i, texture): (Rect, Rect, usize, &egui::TextureHandle),
    (caption, above): (Arc<egui::Galley>, bool),
    session: &Session,
    capture: &FrameCapture,
) -> (Option<Command>, Rect) {
    let response = ui.interact(at, ui.scope_id().with(("exercise", i)), Sense::click());
    let name = caption.text().to_owned();
    super::alt::name_image(&response, || name.clone());
    let painter = ui.painter_at(at);
    painter.image(
        texture.id(),
        at,
        Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
        Color32::WHITE,
    );
    // Above the picture, or over its top-left corner, wrapped to its space (a square picture
    // is narrower than its caption in classroom type).
    let corner = if above {
        Pos2::new(space.left(), at.top() - caption.size().y - 3.0)
    } else {
        at.left_top() + Vec2::splat(6.0)
    };
    let boxed = boxed_galley(
        &ui.painter_at(space),
        corner,
        egui::Align2::LEFT_TOP,
        caption,
        Color32::WHITE,
    )
    .intersect(space);
    let (w, h) = (capture.width(), capture.height());
    let grid = capture.grid();
    let s = at.width() / w as f32;
    if let Some((x, y)) = session.selection.pixel {
        let p = at.min + Vec2::new(x as f32 * s, grid.row(y.min(h - 1)) as f32 * s);
        painter.rect_stroke(
            Rect::from_min_size(p, Vec2::splat(s.max(3.0))).expand(2.0),
            0.0,
            egui::Stroke::new(2.0, Color32::from_rgb(0, 200, 255)),
            egui::StrokeKind::Outside,
        );
    }
    let clicked = response
        .clicked()
        .then(|| response.interact_pointer_pos())
        .flatten();
    let pick = clicked.and_then(|p| {
        let (x, row) = ((p.x - at.left()) / s, (p.y - at.top()) / s);
        (x >= 0.0 && row >= 0.0 && (x as u32) < w && (row as u32) < h)
            .then(|| (x as u32, grid.row(row as u32)))
    });
    // With the keyboard's focus (Tab, or V for the first), the arrows move the inspected pixel
    // as in the student's own frame; the first press inspects the middle.
    let place = (i == 0).then_some(super::picture_keys::Place::Beside);
    let keys = super::picture_keys::take(ui, &response, place);
    super::picture_keys::ring(ui, at, keys);
    let from = session.selection.pixel;
    let moved = super::picture_keys::arrowed_pixel(keys, from, (w, h), || (w / 2, h / 2));
    let pick = pick
        .or(moved)
        .map(|p| Command::Selection(SelectionCommand::SelectPixel(Some(p))));
    (pick, boxed)
}

/// What else the check found, each as a line: the inside or depth test sample by sample at the
/// first wrong pixel, a function's matrix (the shadow's) compared without a vertex shader, the
/// lab's quantity (uv, λ, texel) against pipelens' at the inspected pixel, the first value where
/// the student's run parts from pipelens' (at the inspected pixel, or at a vertex of the first
/// wrong pixel's triangle).
fn findings_lines(ui: &mut Ui, session: &Session, style: &Style) {
    let (f, lang) = (&session.exercise.findings, session.lang);
    if let Some(s) = &f.sample {
        not_yet(ui, s.words(lang), style);
    }
    if f.vertex.is_none()
        && let Some(m) = &f.matrix
    {
        not_yet(ui, words::matrix_words(m, lang), style);
    }
    if let Some(q) = &f.quantity {
        not_yet(ui, q.words(lang), style);
    }
    if let Some(m) = &f.mismatch
        && (m.vertex.is_some() || session.selection.pixel.is_some())
    {
        not_yet(ui, words::mismatch_words(m, lang), style);
    }
}

/// A line of what is not yet right, in the card's colour for it.
fn not_yet(ui: &mut Ui, text: String, style: &Style) -> egui::Response {
    ui.label(RichText::new(text).size(style.size * 0.9).color(NOT_YET))
}

/// The card's part of an exercise step: the task, where to write, the verdict and the first
/// wrong pixel to inspect. Returns whether the Inspector should open (that pixel was chosen).
pub fn card_part(
    ui: &mut Ui,
    (exercise, session): (&Exercise, &Session),
    style: &Style,
    commands: &mut Vec<Command>,
) -> bool {
    let lang = session.lang;
    ui.add_space(6.0);
    ui.label(
        RichText::new(lang.t("exercise-exercise"))
            .strong()
            .color(Color32::WHITE),
    );
    let task = crate::vocabulary::touch::for_device(exercise.task.get(lang), session.touch);
    typeset::paragraph(ui, &task, style);
    let writes = |kind| exercise.starter.hooks.get(kind).is_some();
    let how = if writes(pipeline::shader::HookKind::Curve) {
        lang.t("exercise-write-your-code-in-the")
    } else if writes(pipeline::shader::HookKind::Patch) {
        lang.t("exercise-write-your-code-in-the-2")
    } else {
        lang.t("exercise-write-your-code-in-the-3")
    };
    let how = crate::vocabulary::touch::for_device(how, session.touch);
    ui.label(RichText::new(how).size(style.size * 0.85));
    let passed_before = passed_before(session);
    if let Some((verdict, color)) = verdict(session)
        && session.exercise.findings.difference.is_none()
    {
        // A shortcut taken, or a curve's or a surface's points: the verdict alone.
        let shown = ui.label(RichText::new(&verdict).size(style.size * 0.9).color(color));
        super::alt::announce(&shown, (super::alt::Part::Verdict, &verdict));
        return false;
    }
    match &session.exercise.findings.difference {
        Some(d) => {
            let (verdict, color) = verdict(session).unwrap_or_default();
            let shown = ui.label(RichText::new(&verdict).size(style.size * 0.9).color(color));
            super::alt::announce(&shown, (super::alt::Part::Verdict, &verdict));
            if !d.passed()
                && let Some((row, yours, theirs)) = session.exercise.findings.vertex
            {
                not_yet(ui, words::vertex_words(row, yours, theirs, lang), style);
                if let Some(m) = &session.exercise.findings.matrix {
                    not_yet(ui, words::matrix_words(m, lang), style);
                }
                if session.selection.vertex != Some(row)
                    && ui
                        .button(lang.t("exercise-inspect-the-first-wrong-vertex"))
                        .on_hover_text(lang.t("exercise-selects-its-row-of-the"))
                        .clicked()
                {
                    commands.push(Command::Selection(SelectionCommand::SelectVertex(Some(
                        row,
                    ))));
                    return true;
                }
            }
            if !d.passed() {
                findings_lines(ui, session, style);
            }
            if let Some(first) = d.first
                && session.selection.pixel != Some(first)
                && ui
                    .button(lang.t("exercise-inspect-the-first-wrong-pixel"))
                    .on_hover_text(lang.t("exercise-selects-it-the-inspector-shows"))
                    .clicked()
            {
                commands.push(Command::Selection(SelectionCommand::SelectPixel(Some(
                    first,
                ))));
                return true;
            }
        }
        None if passed_before => {
            ui.label(RichText::new(lang.t("exercise-passed-before")).color(PASSED));
        }
        None => {}
    }
    false
}

/// The lab's verdict in one line with its colour (green passed, amber not yet): a shortcut
/// taken, else a curve's or a surface's points against pipelens', else the frame against
/// pipelens' own; none before the first comparison.
#[must_use]
pub fn verdict(session: &Session) -> Option<(String, Color32)> {
    let lang = session.lang;
    let findings = &session.exercise.findings;
    let colour = |passed: bool| if passed { PASSED } else { NOT_YET };
    if let Some(s) = &findings.shortcut {
        return Some((s.words(lang), NOT_YET));
    }
    if let Some(c) = &findings.curve {
        return Some((words::curve_verdict(c, lang), colour(c.passed())));
    }
    let d = findings.difference.as_ref()?;
    Some((words::verdict(d, lang), colour(d.passed())))
}

/// Whether the student passed the lab on screen on an earlier visit (kept in the progress).
fn passed_before(session: &Session) -> bool {
    session
        .lesson
        .as_ref()
        .is_some_and(|p| session.progress.passed(&p.lesson, p.step))
}

/// The verdict as a strip over the code on a small screen's Code tab (`app::compact`), where
/// the narration is out of sight: the words, or "Passed before." when the lab was passed on an
/// earlier visit, or what it waits for.
pub fn strip(ui: &mut Ui, session: &Session) {
    let lang = session.lang;
    let passed_before = passed_before(session);
    let (text, color) = verdict(session).unwrap_or_else(|| {
        if passed_before {
            (lang.t("exercise-passed-before").to_owned(), PASSED)
        } else {
            (
                lang.t("exercise-drawing-pipelens-own-frame").to_owned(),
                ui.visuals().text_color(),
            )
        }
    });
    let shown = ui.add(egui::Label::new(RichText::new(&text).strong().color(color)).wrap());
    super::alt::announce(&shown, (super::alt::Part::Verdict, &text));
}
