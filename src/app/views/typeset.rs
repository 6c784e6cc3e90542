//! Formulas typeset with egui: subscripts and superscripts raised, lowered and smaller, fractions
//! stacked over a bar, formulas inside wrapped paragraphs. The notation is read by
//! `vocabulary::notation`; this module only lays it out and paints it.

use std::sync::Arc;

use egui::{
    Align2, Color32, FontFamily, FontId, Galley, Painter, Pos2, Rect, Response, Sense, Stroke, Ui,
    Vec2,
};

use crate::vocabulary::line_breaks;
use crate::vocabulary::notation::{self, Node};

/// How text is drawn: its size and colours.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    /// The font size of the text (scripts and fractions are smaller).
    pub size: f32,
    /// Plain text.
    pub color: Color32,
    /// Formulas inside paragraphs.
    pub accent: Color32,
}

impl Style {
    /// The body text style of `ui`, formulas in the accent colour.
    #[must_use]
    pub fn body(ui: &Ui) -> Self {
        Self {
            size: ui.style().text_styles[&egui::TextStyle::Body].size,
            color: ui.visuals().text_color(),
            accent: accent(ui),
        }
    }

    /// The same at another size.
    #[must_use]
    pub fn sized(self, size: f32) -> Self {
        Self { size, ..self }
    }
}

/// The colour formulas are highlighted in.
#[must_use]
pub fn accent(ui: &Ui) -> Color32 {
    if ui.visuals().dark_mode {
        Color32::from_rgb(255, 214, 120)
    } else {
        Color32::from_rgb(150, 70, 0)
    }
}

/// One thing to paint, relative to the box's origin on its baseline.
enum Op {
    Text(Pos2, Arc<Galley>),
    Bar(Pos2, Pos2, f32),
}

/// A laid-out piece: what to paint, its width, and how far it reaches above and below the
/// baseline.
struct Boxed {
    ops: Vec<(Op, Color32)>,
    width: f32,
    ascent: f32,
    descent: f32,
}

impl Boxed {
    fn empty() -> Self {
        Self {
            ops: Vec::new(),
            width: 0.0,
            ascent: 0.0,
            descent: 0.0,
        }
    }

    /// Appends `other` to the right, on the same baseline, raised by `rise` (upwards positive).
    fn push(&mut self, other: Boxed, rise: f32) {
        let dx = self.width;
        for (op, c) in other.ops {
            self.ops.push((shift(op, Vec2::new(dx, -rise)), c));
        }
        self.width += other.width;
        self.ascent = self.ascent.max(other.ascent + rise);
        self.descent = self.descent.max(other.descent - rise);
    }
}

fn shift(op: Op, d: Vec2) -> Op {
    match op {
        Op::Text(p, g) => Op::Text(p + d, g),
        Op::Bar(a, b, w) => Op::Bar(a + d, b + d, w),
    }
}

/// The least size of a script or a fraction's terms (points), unless the formula's own is less:
/// on a touch screen 12 (at 0.7 of a phone's 14-point narration a subscript was under 10
/// points), elsewhere 7 (a desktop's narration shrunk to fit its card or band).
fn least(painter: &Painter) -> f32 {
    if crate::app::style::is_touch(painter.ctx()) {
        12.0
    } else {
        7.0
    }
}

/// A run of text at `size` (monospace for code).
fn text(painter: &Painter, s: &str, size: f32, color: Color32, mono: bool) -> Boxed {
    let family = if mono {
        FontFamily::Monospace
    } else {
        FontFamily::Proportional
    };
    let galley = painter.layout_no_wrap(s.to_owned(), FontId::new(size, family), color);
    let h = galley.size().y;
    let (ascent, descent) = (h * 0.78, h * 0.22);
    Boxed {
        width: galley.size().x,
        ascent,
        descent,
        ops: vec![(Op::Text(Pos2::new(0.0, -ascent), galley), color)],
    }
}

/// Lays out nodes on one baseline.
fn layout(painter: &Painter, nodes: &[Node], size: f32, color: Color32, style: &Style) -> Boxed {
    let mut out = Boxed::empty();
    for node in nodes {
        let b = match node {
            Node::Text(t) => text(painter, t, size, color, false),
            Node::Code(t) => text(painter, t, size * 0.92, color, true),
            Node::Formula(inner) => layout(painter, inner, size, style.accent, style),
            Node::Script { base, sub, sup } => {
                let mut b = layout(painter, base, size, color, style);
                let small = (size * 0.7).max(least(painter).min(size));
                let at = b.width;
                let mut widest = 0.0f32;
                for (script, rise) in [(sup, size * 0.42), (sub, -size * 0.2)] {
                    if let Some(s) = script {
                        let mut part = layout(painter, s, small, color, style);
                        part.width += size * 0.05;
                        widest = widest.max(part.width);
                        let mut placed = Boxed::empty();
                        placed.width = at;
                        placed.push(part, rise);
                        placed.width = 0.0;
                        for (op, c) in placed.ops {
                            b.ops.push((op, c));
                        }
                        b.ascent = b.ascent.max(placed.ascent);
                        b.descent = b.descent.max(placed.descent);
                    }
                }
                b.width = at + widest;
                b
            }
            Node::Frac { num, den } => {
                let small = (size * 0.82).max(least(painter).min(size));
                let n = layout(painter, num, small, color, style);
                let d = layout(painter, den, small, color, style);
                let pad = size * 0.12;
                let width = n.width.max(d.width) + 2.0 * pad;
                let axis = size * 0.3;
                let gap = size * 0.1;
                let mut b = Boxed::empty();
                b.width = width;
                let mut place = |part: Boxed, baseline_rise: f32| {
                    let dx = (width - part.width) / 2.0;
                    for (op, c) in part.ops {
                        b.ops.push((shift(op, Vec2::new(dx, -baseline_rise)), c));
                    }
                    b.ascent = b.ascent.max(part.ascent + baseline_rise);
                    b.descent = b.descent.max(part.descent - baseline_rise);
                };
                place(n, axis + gap + 0.0 + (small * 0.22));
                place(d, axis - gap - (small * 0.78));
                b.ops.push((
                    Op::Bar(
                        Pos2::new(pad * 0.5, -axis),
                        Pos2::new(width - pad * 0.5, -axis),
                        (size / 16.0).max(1.0),
                    ),
                    color,
                ));
                b
            }
        };
        out.push(b, 0.0);
    }
    out
}

fn paint(painter: &Painter, b: &Boxed, origin: Pos2) {
    for (op, color) in &b.ops {
        match op {
            Op::Text(p, g) => painter.galley(origin + p.to_vec2(), g.clone(), *color),
            Op::Bar(a, c, w) => {
                painter.line_segment(
                    [origin + a.to_vec2(), origin + c.to_vec2()],
                    Stroke::new(*w, *color),
                );
            }
        }
    }
}

/// Paints a formula with its top-left at `anchor` aligned by `align`; returns the rect it took.
pub fn paint_formula(
    painter: &Painter,
    at: Pos2,
    align: Align2,
    formula: &str,
    style: &Style,
) -> Rect {
    let nodes = notation::parse(formula, true);
    let b = layout(painter, &nodes, style.size, style.color, style);
    let size = Vec2::new(b.width, b.ascent + b.descent);
    let rect = align.anchor_size(at, size);
    paint(painter, &b, Pos2::new(rect.left(), rect.top() + b.ascent));
    rect
}

/// The size a formula takes when painted ([`paint_formula`]).
pub fn formula_size(painter: &Painter, formula: &str, style: &Style) -> Vec2 {
    let nodes = notation::parse(formula, true);
    let b = layout(painter, &nodes, style.size, style.color, style);
    Vec2::new(b.width, b.ascent + b.descent)
}

/// A formula on one line, as a widget.
pub fn formula(ui: &mut Ui, formula: &str, style: &Style) -> Response {
    let nodes = notation::parse(formula, true);
    let painter = ui.painter().clone();
    let b = layout(&painter, &nodes, style.size, style.color, style);
    let (rect, response) =
        ui.allocate_exact_size(Vec2::new(b.width, b.ascent + b.descent), Sense::hover());
    paint(&painter, &b, Pos2::new(rect.left(), rect.top() + b.ascent));
    let plain = notation::plain_text(&nodes);
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, &plain));
    response
}

/// A paragraph of narration (`**formulas**`, scripts, `` `code` ``), wrapped to the width
/// available.
pub fn paragraph(ui: &mut Ui, text: &str, style: &Style) -> Response {
    let nodes = notation::parse_paragraph(text);
    let painter = ui.painter().clone();
    let width = ui.available_width().max(40.0);
    let shown = line_breaks::pieces(&nodes);
    let boxes: Vec<Boxed> = shown
        .iter()
        .map(|p| layout(&painter, p, style.size, style.color, style))
        .collect();
    let widths: Vec<(f32, f32)> = boxes.iter().map(|b| (b.width, b.width)).collect();
    let lines = line_breaks::lines(&widths, &line_breaks::keeps_with_next(&shown), width);
    let spacing = style.size * 0.25;
    let metrics: Vec<(f32, f32)> = lines
        .iter()
        .map(|l| {
            let a = l
                .iter()
                .map(|&k| boxes[k].ascent)
                .fold(style.size * 0.8, f32::max);
            let d = l
                .iter()
                .map(|&k| boxes[k].descent)
                .fold(style.size * 0.25, f32::max);
            (a, d)
        })
        .collect();
    let height: f32 = metrics.iter().map(|(a, d)| a + d + spacing).sum::<f32>() - spacing;
    let (rect, response) =
        ui.allocate_exact_size(Vec2::new(width, height.max(0.0)), Sense::hover());
    let mut y = rect.top();
    for (line, (a, d)) in lines.iter().zip(metrics) {
        let mut x = rect.left();
        for &k in line {
            paint(&painter, &boxes[k], Pos2::new(x, y + a));
            x += boxes[k].width;
        }
        y += a + d + spacing;
    }
    let plain = notation::plain_text(&nodes);
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, &plain));
    response
}

/// A note in smaller type, legible (not greyed out).
pub fn note(ui: &mut Ui, text: &str) {
    let style = Style::body(ui);
    paragraph(ui, text, &style.sized(style.size * 0.9));
}
