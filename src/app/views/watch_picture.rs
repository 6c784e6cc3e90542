//! The debugger's variable picture: a fragment-shader expression after a line, at every pixel
//! of the frame (`Selection::watch`, drawn by `WatchPicture::drawn`), with its legend; the
//! value under the mouse, a click inspecting that pixel, and for a condition the first pixel
//! where it holds, its run shown at that line. On the vertex shader's tab, the same for an
//! expression of the vertex shader, interpolated over each triangle as a varying is.

use egui::{RichText, Ui};
use pipeline::capture::{WatchPicture, WatchView};
use pipeline::shader::Stage;
use pipeline::shader::probe::{WatchKind, WatchSpec};

use crate::app::command::SelectionCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::{Lang, num};

/// What the watch's row keeps: the expression typed, its line, how the picture is drawn.
pub struct WatchPanel {
    /// The expression as typed.
    pub expression: String,
    /// The line after which it is read, from 1.
    pub line: usize,
    /// How a vector is drawn: as a colour, or one component on the ramp.
    pub view: WatchView,
    /// Why the last Show did nothing.
    pub error: Option<String>,
    /// The pixel view draws this picture (the window sets it each frame): the row keeps its
    /// legend and leaves the picture out, so that the code keeps its room.
    pub in_view: bool,
    /// The picture's texture, with the frame and view it shows.
    texture: Option<((usize, WatchView), egui::TextureHandle)>,
    /// The watch the row last showed: one set elsewhere (a lesson's step) is copied into it.
    synced: Option<WatchSpec>,
}

impl Default for WatchPanel {
    fn default() -> Self {
        Self {
            expression: String::new(),
            line: 1,
            view: WatchView::Value,
            error: None,
            in_view: false,
            texture: None,
            synced: None,
        }
    }
}

/// What the row asks for: a command, and, after "first where it holds", the line whose last
/// step the debugger should show in that pixel's run.
#[derive(Default)]
pub struct Asked {
    /// The command (a watch set or stopped, a pixel inspected).
    pub command: Option<Command>,
    /// The line to show in the run of the pixel just inspected.
    pub show_line: Option<usize>,
}

/// The watch's row and picture for the shader of `stage`. `step_line` is the line of the
/// debugger's step (the default line to watch after).
pub fn ui(
    ui: &mut Ui,
    panel: &mut WatchPanel,
    session: &Session,
    step_line: Option<usize>,
    stage: Stage,
) -> Asked {
    let lang = session.lang;
    let mut asked = Asked::default();
    // The selection's watch, when it is of this tab's shader (the row shows it); the picture
    // and its legend, which say whose line it is, show on either tab.
    let any = session.selection.watch.is_some();
    let watching = session.selection.watch.clone().filter(|w| w.stage == stage);
    if panel.synced != watching {
        if let Some(w) = &watching {
            panel.line = w.line;
            panel.expression.clone_from(&w.expression);
        }
        panel.synced.clone_from(&watching);
    }
    ui.horizontal_wrapped(|ui| {
        let label = ui
            .label(RichText::new(lang.t("watch-picture-watch-over-the-frame")).strong())
            .on_hover_text(match stage {
                Stage::Fragment => lang.t("watch-picture-any-expression-of-your-fragment"),
                Stage::Vertex => lang.t("watch-picture-any-expression-of-your-vertex"),
            });
        let field = ui
            .add(
                egui::TextEdit::singleline(&mut panel.expression)
                    .id_salt("watch expression")
                    .code_editor()
                    // One line: Tab moves on to the next control, as in every field (the
                    // code editor's lock would trap the keyboard here, WCAG 2.1.2).
                    .lock_focus(false)
                    .desired_width(220.0)
                    .hint_text(lang.t("watch-picture-e-g-dot-n-l")),
            )
            .labelled_by(label.id);
        let after = ui.label(lang.t("watch-picture-after-line"));
        ui.add(egui::DragValue::new(&mut panel.line).range(1..=9999))
            .labelled_by(after.id);
        if let Some(line) = step_line
            && ui
                .button(lang.t("watch-picture-the-step-s"))
                .on_hover_text(lang.t("watch-picture-watch-after-the-line-of"))
                .clicked()
        {
            panel.line = line;
        }
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if ui.button(lang.t("watch-picture-show")).clicked() || entered {
            asked.command = show(panel, session, stage);
        }
        if any && ui.button(lang.t("watch-picture-stop")).clicked() {
            asked.command = Some(Command::Selection(SelectionCommand::SetWatch(None)));
        }
    });
    if let Some(e) = panel.error.as_ref().or(session.watch_error.as_ref()) {
        ui.colored_label(ui.visuals().error_fg_color, e);
    }
    let picture = session.capture.as_ref().and_then(|c| {
        c.shaders
            .as_ref()
            .and_then(|r| r.watch.as_ref())
            .map(|w| (c, w))
    });
    if let Some((capture, picture)) = picture.filter(|_| any) {
        let key = (std::sync::Arc::as_ptr(capture) as usize, panel.view);
        shown(ui, panel, picture, key, lang, &mut asked);
    }
    asked
}

/// The cost view's row: a checkbox, and when it is on the picture of the steps the fragment
/// shader ran at each pixel (`ShaderRecord::cost`: loops and branches show as brighter areas),
/// its legend and hover, a click inspecting the pixel.
pub fn cost(ui: &mut Ui, panel: &mut WatchPanel, session: &Session) -> Option<Command> {
    let lang = session.lang;
    let mut on = session.selection.cost;
    let mut asked = Asked::default();
    if ui
        .checkbox(
            &mut on,
            RichText::new(lang.t("watch-picture-cost-the-steps-each-fragment")).strong(),
        )
        .on_hover_text(lang.t("watch-picture-at-each-pixel-how-many"))
        .changed()
    {
        asked.command = Some(Command::Selection(SelectionCommand::SetCost(on)));
    }
    let picture = session.capture.as_ref().and_then(|c| {
        c.shaders
            .as_ref()
            .and_then(|r| r.cost.as_ref())
            .map(|w| (c, w))
    });
    if let Some((capture, picture)) = picture.filter(|_| on) {
        let key = (std::sync::Arc::as_ptr(capture) as usize, WatchView::Value);
        shown(ui, panel, picture, key, lang, &mut asked);
    }
    asked.command
}

/// Checks the watch of `stage`'s shader against the scene (it compiles there) and asks for it.
fn show(panel: &mut WatchPanel, session: &Session, stage: Stage) -> Option<Command> {
    let lang = session.lang;
    let watch = WatchSpec {
        stage,
        line: panel.line,
        expression: panel.expression.trim().to_owned(),
    };
    match session.spec.scene.watching(&watch) {
        Ok(_) => {
            panel.error = None;
            panel.view = WatchView::Value;
            Some(Command::Selection(SelectionCommand::SetWatch(Some(watch))))
        }
        Err(e) => {
            panel.error = Some(format!("{} {e}", lang.t("watch-picture-cannot-watch")));
            None
        }
    }
}

/// The picture with its legend; hovering says the value, a click inspects the pixel.
fn shown(
    ui: &mut Ui,
    panel: &mut WatchPanel,
    picture: &WatchPicture,
    key: (usize, WatchView),
    lang: Lang,
    asked: &mut Asked,
) {
    let Some(kind) = picture.kind else {
        ui.label(if picture.from_vertex {
            lang.t("watch-picture-no-triangle-of-this-frame")
        } else {
            lang.t("watch-picture-no-fragment-of-this-frame")
        });
        return;
    };
    let drawn = picture.drawn(panel.view);
    legend(ui, panel, picture, kind, drawn.range, lang, asked);
    if panel.in_view {
        return;
    }
    let texture = match &panel.texture {
        Some((k, t)) if *k == key => t.clone(),
        _ => {
            let size = [drawn.image.width() as usize, drawn.image.height() as usize];
            let image = egui::ColorImage::from_rgba_unmultiplied(size, drawn.image.as_raw());
            let t = ui
                .ctx()
                .load_texture("watch picture", image, egui::TextureOptions::NEAREST);
            panel.texture = Some((key, t.clone()));
            t
        }
    };
    let (w, h) = (picture.width as f32, picture.height() as f32);
    let scale = (ui.available_width() / w).min(240.0 / h).max(0.1);
    let response = ui.add(
        egui::Image::new(&texture)
            .fit_to_exact_size(egui::vec2(w * scale, h * scale))
            .sense(egui::Sense::click()),
    );
    let Some(pos) = response.hover_pos() else {
        return;
    };
    let local = (pos - response.rect.min) / scale;
    let (x, row) = (local.x.floor() as u32, local.y.floor() as u32);
    let y = picture.height().saturating_sub(row + 1);
    let cost = picture.line == 0;
    let said = match picture.at(x, y) {
        Some(v) if cost => format!("{} {}", num(v[0]), lang.t("watch-picture-steps")),
        Some(v) => value_words(kind, v),
        None if cost => lang.t("watch-picture-no-fragment-of-yours-here").to_owned(),
        None if picture.from_vertex => lang.t("watch-picture-a-corner-of-the-triangle").to_owned(),
        None => lang.t("watch-picture-the-line-did-not-run").to_owned(),
    };
    let response = response.on_hover_text(format!(
        "{} ({x}, {y}): {said}",
        lang.t("watch-picture-pixel")
    ));
    if response.clicked() {
        asked.command = Some(Command::Selection(SelectionCommand::SelectPixel(Some((
            x, y,
        )))));
    }
}

/// Where the picture's expression is read: after which line of which shader.
fn place_words(picture: &WatchPicture, lang: Lang) -> String {
    if picture.from_vertex {
        lang.t_with(
            "watch-picture-after-vertex-line",
            &[("line", &picture.line)],
        )
    } else {
        format!("{} {}", lang.t("watch-picture-after-line-2"), picture.line)
    }
}

/// A watched value as GLSL writes it.
pub(super) fn value_words(kind: WatchKind, v: [f32; 4]) -> String {
    match kind {
        WatchKind::Bool => (v[0] != 0.0).to_string(),
        WatchKind::Float | WatchKind::Int => num(v[0]),
        _ => {
            let parts: Vec<String> = v.iter().take(kind.components()).map(|c| num(*c)).collect();
            format!("{}({})", kind.glsl(), parts.join(", "))
        }
    }
}

/// What the colours stand for: the ramp's two ends with their values, or a condition's two
/// colours with how many pixels each, or a vector's channels; a vector's view chosen here.
#[allow(clippy::too_many_arguments)]
fn legend(
    ui: &mut Ui,
    panel: &mut WatchPanel,
    picture: &WatchPicture,
    kind: WatchKind,
    range: Option<(f32, f32)>,
    lang: Lang,
    asked: &mut Asked,
) {
    let swatch = |ui: &mut Ui, c: [u8; 4]| {
        let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
        ui.painter()
            .rect_filled(rect, 2.0, egui::Color32::from_rgb(c[0], c[1], c[2]));
    };
    let ramp = pipeline::capture::watch_ramp;
    ui.horizontal_wrapped(|ui| {
        ui.label(
            RichText::new(format!(
                "`{}` {} · {}",
                picture.expression,
                place_words(picture, lang),
                kind.glsl()
            ))
            .monospace(),
        );
        if kind.components() > 1 {
            ui.selectable_value(
                &mut panel.view,
                WatchView::Value,
                lang.t("watch-picture-as-colour"),
            );
            for (c, name) in ["x", "y", "z", "w"]
                .iter()
                .enumerate()
                .take(kind.components())
            {
                ui.selectable_value(&mut panel.view, WatchView::Component(c), *name);
            }
        }
    });
    ui.horizontal_wrapped(|ui| {
        match (kind, range) {
            (WatchKind::Bool, _) => {
                let holds = picture
                    .values
                    .iter()
                    .flatten()
                    .filter(|v| v[0] != 0.0)
                    .count();
                swatch(ui, ramp(1.0));
                ui.label(format!("{} ({holds})", lang.t("watch-picture-true")));
                swatch(ui, ramp(0.0));
                ui.label(format!(
                    "{} ({})",
                    lang.t("watch-picture-false"),
                    picture.pixels_run() - holds
                ));
                if let Some(first) = picture.first_where()
                    && ui
                        .button(lang.t("watch-picture-first-where-it-holds"))
                        .on_hover_text(lang.t("watch-picture-inspects-the-first-pixel-where"))
                        .clicked()
                {
                    asked.command = Some(Command::Selection(SelectionCommand::SelectPixel(Some(
                        first,
                    ))));
                    // A fragment's run has no vertex line to show.
                    asked.show_line = (!picture.from_vertex).then_some(picture.line);
                }
            }
            (_, Some((lo, hi))) => {
                swatch(ui, ramp(0.0));
                ui.label(num(lo));
                for k in 1..8 {
                    swatch(ui, ramp(k as f32 / 8.0));
                }
                swatch(ui, ramp(1.0));
                ui.label(num(hi));
            }
            _ => {
                ui.label(lang.t("watch-picture-x-red-y-green-z"));
            }
        }
        swatch(ui, [68, 68, 68, 255]);
        ui.label(lang.t("watch-picture-not-run"));
    });
}
