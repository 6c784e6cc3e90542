//! Formulas typeset with egui: subscripts and superscripts raised, lowered and smaller, fractions
//! stacked over a bar, formulas inside wrapped paragraphs. The notation is read by
//! `vocabulary::notation`; this module only lays it out and paints it.

use std::sync::Arc;

use egui::{
    Align2, Color32, FontFamily, FontId, Galley, Painter, Pos2, Rect, Response, Sense, Stroke, Ui,
    Vec2,
};

use crate::vocabulary::notation::{self, Node, is_cjk};

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
                let small = (size * 0.7).max(7.0);
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
                let small = (size * 0.82).max(7.0);
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

/// The pieces a paragraph may break between. A line breaks only where a reader allows it:
/// after a space, or beside a Chinese character — never inside a word or a formula's atom (a
/// name and its scripts, `k_d·c·I`; a function and its argument list, `max(n·h, 0)`, whose
/// spaces inside brackets do not count), never before punctuation that follows a word
/// (", run"), nor at a leading space. By the Chinese line-breaking rules closing punctuation
/// joins the piece before it and opening punctuation the piece after it, so no line begins
/// with "，" or ends with "（". Each formula's parts keep the accent colour.
fn pieces(nodes: &[Node]) -> Vec<Vec<Node>> {
    let mut out = Vec::new();
    let mut glue = false;
    split(nodes, &mut out, &mut glue, None);
    out
}

/// Adds the pieces of `nodes` to `out`; `glue` says the last piece ends with opening
/// punctuation (the next one joins it). Inside a formula `depth` counts the brackets open, and
/// a space inside them ends no word.
fn split(nodes: &[Node], out: &mut Vec<Vec<Node>>, glue: &mut bool, mut depth: Option<&mut i32>) {
    let bracketed = |d: &Option<&mut i32>| d.as_deref().is_some_and(|d| *d > 0);
    for n in nodes {
        match n {
            Node::Text(t) => {
                let mut word = String::new();
                for c in t.chars() {
                    if is_cjk(c) {
                        let held = bracketed(&depth);
                        if !word.is_empty() {
                            add(out, Node::Text(std::mem::take(&mut word)), glue, held);
                        }
                        add(out, Node::Text(c.to_string()), glue, held);
                        continue;
                    }
                    word.push(c);
                    if let Some(d) = depth.as_deref_mut() {
                        match c {
                            '(' | '[' | '{' => *d += 1,
                            ')' | ']' | '}' => *d -= 1,
                            _ => {}
                        }
                    }
                    if c == ' ' && !bracketed(&depth) {
                        add(out, Node::Text(std::mem::take(&mut word)), glue, false);
                    }
                }
                if !word.is_empty() {
                    let held = bracketed(&depth);
                    add(out, Node::Text(word), glue, held);
                }
            }
            Node::Formula(inner) => {
                // A long formula may break at its spaces outside brackets.
                let mut parts = Vec::new();
                split(inner, &mut parts, &mut false, Some(&mut 0));
                for p in parts {
                    add(out, Node::Formula(p), glue, false);
                }
            }
            other => {
                let held = bracketed(&depth);
                add(out, other.clone(), glue, held);
            }
        }
    }
}

/// The first (or with `last`, the last) character `nodes` show: a script or a fraction
/// counts as a letter (it is never a place to break).
fn edge(nodes: &[Node], last: bool) -> Option<char> {
    let n = if last { nodes.last() } else { nodes.first() }?;
    match n {
        Node::Text(t) | Node::Code(t) if last => t.chars().last(),
        Node::Text(t) | Node::Code(t) => t.chars().next(),
        Node::Formula(inner) => edge(inner, last),
        Node::Script { base, .. } if !last => edge(base, false),
        Node::Script { .. } | Node::Frac { .. } => Some('x'),
    }
}

/// Appends `n` as a piece of its own where a line may break before it, or else (and always
/// when `held`, inside a formula's brackets) to the last piece (see [`pieces`]).
fn add(out: &mut Vec<Vec<Node>>, n: Node, glue: &mut bool, held: bool) {
    let first = edge(std::slice::from_ref(&n), false);
    // Closing punctuation, Chinese or ASCII, never begins a line (after a Chinese
    // character either: "漫反射)").
    let closing = first.is_some_and(|c| notation::closes(c) || ",.;:!?)]}".contains(c));
    let opening = edge(std::slice::from_ref(&n), true).is_some_and(notation::opens);
    match out.last_mut() {
        Some(last) => {
            let before = edge(last, true);
            let may_break = !*glue
                && !held
                && !closing
                && first.is_some_and(|c| !c.is_whitespace())
                && (before.is_some_and(|c| c.is_whitespace() || is_cjk(c))
                    || first.is_some_and(is_cjk));
            if may_break {
                out.push(vec![n]);
            } else {
                last.push(n);
            }
        }
        None => out.push(vec![n]),
    }
    *glue = opening;
}

/// For each piece, whether a line should not break after it where the line has room: it ends
/// with an operator (`= `, `+ `, `→ `) or the next piece begins with one, so that `n·l = 1`
/// and `64 → 8` stay together.
fn keeps_with_next(pieces: &[Vec<Node>]) -> Vec<bool> {
    const OPERATORS: &str = "=+−×·<>≤≥≈≠→";
    let shown: Vec<String> = pieces.iter().map(|p| notation::plain_text(p)).collect();
    (0..shown.len())
        .map(|k| {
            let ends = shown[k]
                .trim_end()
                .chars()
                .last()
                .is_some_and(|c| OPERATORS.contains(c));
            let next = shown
                .get(k + 1)
                .and_then(|n| n.chars().next())
                .is_some_and(|c| OPERATORS.contains(c));
            ends || next
        })
        .collect()
}

/// A paragraph of narration (`**formulas**`, scripts, `` `code` ``), wrapped to the width
/// available.
pub fn paragraph(ui: &mut Ui, text: &str, style: &Style) -> Response {
    let nodes = notation::parse_paragraph(text);
    let painter = ui.painter().clone();
    let width = ui.available_width().max(40.0);
    let shown = pieces(&nodes);
    let boxes: Vec<Boxed> = shown
        .iter()
        .map(|p| layout(&painter, p, style.size, style.color, style))
        .collect();
    // Greedy lines, keeping an operator with its operands where the line has room.
    let kept = keeps_with_next(&shown);
    let mut lines: Vec<Vec<usize>> = vec![Vec::new()];
    let mut x = 0.0;
    for (k, b) in boxes.iter().enumerate() {
        // The width of this piece and those it keeps with (`n·l = 1`).
        let starts_chain = k == 0 || !kept[k - 1];
        let chain: f32 = if starts_chain {
            let end = (k..boxes.len())
                .find(|&j| !kept[j])
                .unwrap_or(boxes.len() - 1);
            boxes[k..=end].iter().map(|b| b.width).sum()
        } else {
            b.width
        };
        let overflows =
            x + b.width > width || (starts_chain && x + chain > width && chain <= width);
        if overflows && x > 0.0 {
            lines.push(Vec::new());
            x = 0.0;
        }
        lines.last_mut().expect("a line").push(k);
        x += b.width;
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(p: &[Vec<Node>]) -> Vec<String> {
        p.iter()
            .map(|piece| {
                piece
                    .iter()
                    .map(|n| match n {
                        Node::Text(t) => t.clone(),
                        Node::Formula(_) => "F".to_owned(),
                        _ => "?".to_owned(),
                    })
                    .collect()
            })
            .collect()
    }

    /// The Chinese line-breaking rules: a line never begins with closing punctuation, after a
    /// character or after a formula, and never ends with opening punctuation.
    #[test]
    fn closing_punctuation_joins_the_piece_before_and_opening_the_piece_after() {
        let p = pieces(&notation::parse_paragraph("甲乙，丙（丁）。"));
        assert_eq!(texts(&p), ["甲", "乙，", "丙", "（丁）。"]);
        let p = pieces(&notation::parse_paragraph("是 **x = 1**，然后"));
        // The space joins the character before it; the formula breaks at its spaces (three
        // parts); the comma joins the last.
        assert_eq!(texts(&p), ["是 ", "F", "F", "F，", "然", "后"]);
    }

    /// Lines break only after a space (or beside a Chinese character): never before the
    /// punctuation after a formula or a word (", run", ": its inputs"), nor inside a formula's
    /// atom — a name and its subscript and what follows it (`k_d·c·I`), a function and its
    /// argument list (`max(n·h, 0)`), a subscript and the comma after it (`h_b, 0)`).
    #[test]
    fn no_break_inside_an_atom_or_before_punctuation() {
        let p = pieces(&notation::parse_paragraph(
            "then **k_d·c·I**, run **max(n·h, 0)**: its inputs **mix(h_a, h_b, 0)**.",
        ));
        assert_eq!(
            texts(&p),
            ["then ", "F, ", "run ", "F: ", "its ", "inputs ", "F."]
        );
        // Each formula stayed whole: one Formula node a piece.
        assert!(p.iter().all(|piece| {
            piece
                .iter()
                .filter(|n| matches!(n, Node::Formula(_)))
                .count()
                <= 1
        }));
    }

    /// Over every narration, question and answer of every built-in lesson in both languages:
    /// no piece a line may start with begins with punctuation or a space, none ends with an
    /// opening bracket, and every formula part keeps its brackets balanced (a function's
    /// argument list is never cut). Lines break only between pieces, so this holds at every
    /// width.
    #[test]
    fn every_lessons_words_break_only_where_a_reader_allows() {
        let mut bad = Vec::new();
        for (file, _) in crate::lesson::library::LESSONS {
            let lesson = crate::lesson::library::lesson(file).expect("a built-in lesson");
            for (k, step) in lesson.steps.iter().enumerate() {
                let texts = [
                    Some(&step.narration),
                    step.question.as_ref(),
                    step.answer.as_ref(),
                ];
                for lang in [crate::vocabulary::Lang::En, crate::vocabulary::Lang::Zh] {
                    for text in texts.iter().flatten() {
                        let nodes = notation::parse_paragraph(text.get(lang));
                        let p = pieces(&nodes);
                        for (j, piece) in p.iter().enumerate() {
                            let shown = notation::plain_text(piece);
                            let first = shown.chars().next().unwrap_or(' ');
                            let last = shown.trim_end().chars().last().unwrap_or(' ');
                            let starts_badly = j > 0
                                && (first.is_whitespace()
                                    || ",.;:!?)]}".contains(first)
                                    || notation::closes(first));
                            let depth: i32 = piece
                                .iter()
                                .filter_map(|n| match n {
                                    Node::Formula(f) => Some(notation::plain_text(f)),
                                    _ => None,
                                })
                                .flat_map(|f| f.chars().collect::<Vec<_>>())
                                .map(|c| match c {
                                    '(' | '[' => 1,
                                    ')' | ']' => -1,
                                    _ => 0,
                                })
                                .sum();
                            if starts_badly || notation::opens(last) || depth != 0 {
                                bad.push(format!("{file} step {} {lang:?}: {shown:?}", k + 1));
                            }
                        }
                    }
                }
            }
        }
        assert!(bad.is_empty(), "{} pieces: {bad:#?}", bad.len());
    }

    /// An operator keeps its operands on its line where the line has room: the pieces of
    /// `(n·l = 1) gets` keep "(n·l " with "= " and "= " with "1) ", not "1) " with "gets".
    #[test]
    fn an_operator_keeps_with_its_operands() {
        let p = pieces(&notation::parse_paragraph("light (n·l = 1) gets 64 → 8"));
        assert_eq!(
            texts(&p),
            ["light ", "(n·l ", "= ", "1) ", "gets ", "64 ", "→ ", "8"]
        );
        assert_eq!(
            keeps_with_next(&p),
            [false, true, true, false, false, true, true, false]
        );
    }
}
