//! Where a line of narration may break, for every place that sets it — the app's cards
//! (`app::views::typeset`) and the exported slides (`export::text`): the pieces a paragraph may
//! break between, which pieces an operator keeps together, and the greedy lines over their
//! widths. A line breaks only where a reader allows it: after a space or beside a Chinese
//! character; never before closing punctuation, after opening punctuation, nor inside a
//! formula's atom; an operator with its operands where the line has room.

use crate::vocabulary::notation::{self, Node, is_cjk};

/// The pieces a paragraph may break between. A line breaks only where a reader allows it:
/// after a space, or beside a Chinese character — never inside a word or a formula's atom (a
/// name and its scripts, `k_d·c·I`; a function and its argument list, `max(n·h, 0)`, whose
/// spaces inside brackets do not count), never before punctuation that follows a word
/// (", run"), nor at a leading space. By the Chinese line-breaking rules closing punctuation
/// joins the piece before it and opening punctuation the piece after it, so no line begins
/// with "，" or ends with "（". Each formula's parts keep the accent colour.
pub fn pieces(nodes: &[Node]) -> Vec<Vec<Node>> {
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
pub fn keeps_with_next(pieces: &[Vec<Node>]) -> Vec<bool> {
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

/// The greedy lines over pieces `widths` wide — each piece's advance, and its width without
/// the spaces it ends with, which may overhang the line's end — no line wider than `max`
/// unless one piece is: each line takes pieces while they fit, and a chain of pieces kept
/// together (`kept[k]`: piece k keeps with the next, [`keeps_with_next`]) that fits on a line
/// of its own starts a new line rather than break. Returns each line's pieces by index.
#[must_use]
pub fn lines(widths: &[(f32, f32)], kept: &[bool], max: f32) -> Vec<Vec<usize>> {
    let kept = |k: usize| kept.get(k).copied().unwrap_or(false);
    let mut lines: Vec<Vec<usize>> = vec![Vec::new()];
    let mut x = 0.0;
    for (k, &(advance, ink)) in widths.iter().enumerate() {
        // The width of this piece and those it keeps with (`n·l = 1`).
        let starts_chain = k == 0 || !kept(k - 1);
        let chain = if starts_chain {
            let end = (k..widths.len())
                .find(|&j| !kept(j))
                .unwrap_or(widths.len() - 1);
            widths[k..end].iter().map(|w| w.0).sum::<f32>() + widths[end].1
        } else {
            ink
        };
        let overflows = x + ink > max || (starts_chain && x + chain > max && chain <= max);
        if overflows && x > 0.0 {
            lines.push(Vec::new());
            x = 0.0;
        }
        lines.last_mut().expect("a line").push(k);
        x += advance;
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vocabulary::notation;

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
                for lang in [crate::vocabulary::Lang::EN, crate::vocabulary::Lang::ZH] {
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

#[cfg(test)]
mod line_tests {
    use super::lines;

    /// Pieces 30, 30, 30 wide in lines 70 wide: two on the first line, one on the next; a
    /// chain 30 + 30 kept together after a first piece of 30 moves whole to the next line.
    #[test]
    fn greedy_lines_keep_a_chain_whole() {
        let w = [(30.0, 30.0); 3];
        assert_eq!(lines(&w, &[false; 3], 70.0), [vec![0, 1], vec![2]]);
        assert_eq!(
            lines(&w, &[false, true, false], 70.0),
            [vec![0], vec![1, 2]]
        );
        // A piece wider than the line stays whole on a line of its own.
        let w = [(100.0, 100.0), (10.0, 10.0)];
        assert_eq!(lines(&w, &[false; 2], 70.0), [vec![0], vec![1]]);
        // A word's trailing space may overhang the line: 30 + 36 (its space 6) in 66.
        let w = [(30.0, 30.0), (42.0, 36.0)];
        assert_eq!(lines(&w, &[false; 2], 66.0), [vec![0, 1]]);
    }
}
