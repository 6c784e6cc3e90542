//! The pixel under the mouse: its values in a tooltip, what the status line says there, and a
//! click that inspects it.

use egui::{Color32, Rect, RichText, Ui};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;

use super::viewport::ImageViewport;
use crate::app::command::SelectionCommand;
use crate::app::session::Command;
use crate::vocabulary::{Lang, num};

/// The values of one pixel, for the hover tooltip.
fn pixel_tooltip(ui: &mut Ui, capture: &FrameCapture, x: u32, y: u32, lang: Lang) {
    let i = capture.grid().index(x, y);
    let px = &capture.pixels;
    ui.label(RichText::new(format!("{} ({x}, {y})", lang.t("hover-pixel"))).strong());
    ui.label(format!(
        "{}: {}/{}",
        lang.t("hover-coverage"),
        px.coverage[i],
        capture.settings.samples.count()
    ));
    ui.label(format!(
        "{} z_w: {} ({} {})",
        lang.t("hover-depth"),
        num(px.depth[i]),
        lang.t("hover-eye-distance"),
        num(capture.eye_depth(px.depth[i]))
    ));
    if let Some(bary) = capture.barycentrics(i) {
        let (b, a) = (bary.perspective, bary.affine);
        ui.label(format!(
            "{}: {}",
            lang.t("hover-primitive"),
            px.primitive[i]
        ));
        ui.label(format!(
            "b ({}) = ({}, {}, {})",
            lang.t("hover-perspective-correct"),
            num(b[0]),
            num(b[1]),
            num(b[2])
        ));
        ui.label(format!(
            "λ ({}) = ({}, {}, {})",
            lang.t("hover-affine"),
            num(a[0]),
            num(a[1]),
            num(a[2])
        ));
    }
    let c = px.color[i];
    ui.label(format!(
        "RGB = ({}, {}, {})",
        num(c[0]),
        num(c[1]),
        num(c[2])
    ));
    // The debugger's watch over the frame, read at this pixel (y up, as the pixel's own).
    if let Some(w) = capture.shaders.as_ref().and_then(|r| r.watch.as_ref())
        && let Some(kind) = w.kind
    {
        let said = match w.at(x, y) {
            Some(v) => crate::app::views::watch_picture::value_words(kind, v),
            None => lang.t("hover-the-line-did-not-run").to_owned(),
        };
        let at = lang.t_with("hover-after-line", &[("line", &w.line)]);
        ui.label(RichText::new(format!("{} ({at}): {said}", w.expression)).monospace());
    }
    ui.label(RichText::new(lang.t("hover-click-to-inspect")).weak());
}

/// Why the image shows nothing (no texture in the scene), or that the buffer is on its way.
pub(super) fn status_message(
    painter: &egui::Painter,
    rect: Rect,
    capture: &FrameCapture,
    buffer: BufferKind,
    offered: bool,
    lang: Lang,
) {
    let text = if !offered {
        lang.t("hover-no-object-of-this-scene")
    } else if !capture.settings.capture.keeps(buffer) {
        // The capture shown kept only what the previous view needed; the render that keeps
        // this buffer is under way.
        lang.t("hover-rendering-this-buffer")
    } else {
        return;
    };
    crate::app::views::label_with_background(
        painter,
        rect.center(),
        egui::Align2::CENTER_CENTER,
        text,
        &crate::app::views::picture_font(painter.ctx(), 18.0),
        Color32::from_gray(235),
    );
}

/// Hover: the values of the pixel under the cursor; click: inspect it (only it: a vertex is
/// picked in a geometry view or the vertex table, not by a pixel's click, whose label would
/// stand beside the pixel's own).
pub(super) fn hover_and_click(
    response: &egui::Response,
    view: &ImageViewport,
    capture: &FrameCapture,
    lang: Lang,
) -> Vec<Command> {
    let mut cmds = Vec::new();
    let Some(pos) = response.hover_pos() else {
        return cmds;
    };
    let Some((c, y)) = view.window_pixel(pos, capture) else {
        return cmds;
    };
    response
        .clone()
        .on_hover_ui_at_pointer(|ui| pixel_tooltip(ui, capture, c, y, lang));
    if response.clicked() {
        cmds.push(Command::Selection(SelectionCommand::SelectPixel(Some((
            c, y,
        )))));
    }
    cmds
}
