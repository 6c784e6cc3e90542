//! How formulas are written in lessons, tooltips and the inspector, and read for typesetting:
//! plain text with three marks, as on a blackboard.
//!
//! - `x_i`, `z_ndc`, `M_{persp→ortho}`: a subscript — the run of letters and digits after `_`, or
//!   the group `{…}` / `(…)` (whose brackets are dropped). Only after a symbol of one or two
//!   letters (or a closing bracket): `depth_test` stays a word.
//! - `x^2`, `(n·h)^β`, `M^{-1}`, `2^(−11)`: a superscript, the same way.
//! - `a/b`, `(f+n)/(f−n)`, `2fn/((f−n)·d)`: in formulas only, a fraction of the atoms on either
//!   side — a run of letters and digits, a bracketed group (brackets dropped) or `|…|`.
//! - `` `code` ``: as written, in monospace.
//!
//! Narration marks its formulas with `**…**`; a whole tooltip or inspector line is a formula. The
//! parse is shared: the app lays it out with egui, the handout writes it as HTML.

/// A piece of a formula or a paragraph.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Node {
    /// Text as it is.
    Text(String),
    /// A base with a subscript and/or a superscript.
    Script {
        /// What carries the scripts.
        base: Vec<Node>,
        /// Below.
        sub: Option<Vec<Node>>,
        /// Above.
        sup: Option<Vec<Node>>,
    },
    /// A fraction.
    Frac {
        /// Above the bar.
        num: Vec<Node>,
        /// Below the bar.
        den: Vec<Node>,
    },
    /// Code, in monospace, not typeset.
    Code(String),
    /// A formula inside a paragraph (narration's `**…**`): shown highlighted.
    Formula(Vec<Node>),
}

/// Whether `c` is part of a symbol's name (letters, digits, Greek, primes).
fn word_char(c: char) -> bool {
    c.is_alphanumeric() && !is_cjk(c) || matches!(c, '′' | '\'' | '.')
}

/// Whether `c` is a Chinese character or CJK punctuation (each is its own word for line breaks).
#[must_use]
pub fn is_cjk(c: char) -> bool {
    matches!(c as u32, 0x2E80..=0x9FFF | 0xF900..=0xFAFF | 0xFF00..=0xFFEF)
}

/// Whether `c` may not begin a line (Chinese line-breaking rules): closing punctuation stays
/// with what it follows — `，。、；：！？` and closing brackets and quotes.
#[must_use]
pub fn closes(c: char) -> bool {
    matches!(
        c,
        '，' | '。'
            | '、'
            | '；'
            | '：'
            | '！'
            | '？'
            | '）'
            | '」'
            | '』'
            | '》'
            | '】'
            | '〉'
            | '”'
            | '’'
            | '…'
            | '—'
    )
}

/// Whether `c` may not end a line: opening brackets and quotes stay with what follows.
#[must_use]
pub fn opens(c: char) -> bool {
    matches!(c, '（' | '「' | '『' | '《' | '【' | '〈' | '“' | '‘')
}

/// An atom before the scripts and fractions are attached.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Atom {
    /// A run of letters and digits.
    Word(String),
    /// `(…)`, `{…}`, `[…]` or `|…|` with its inside.
    Group(char, Vec<Atom>, char),
    /// Any other character.
    Char(char),
    /// `` `code` ``.
    Code(String),
}

/// Where the bracket `open` at `start` closes, if it does.
fn matching(chars: &[char], start: usize, open: char, close: char) -> Option<usize> {
    let mut depth = 0usize;
    for (k, &c) in chars.iter().enumerate().skip(start) {
        if c == open {
            depth += 1;
        } else if c == close {
            depth -= 1;
            if depth == 0 {
                return Some(k);
            }
        }
    }
    None
}

/// Reads atoms until `close` (or the end).
fn atoms(chars: &[char], i: &mut usize, close: Option<char>) -> Vec<Atom> {
    let mut out = Vec::new();
    while *i < chars.len() {
        let c = chars[*i];
        if Some(c) == close {
            *i += 1;
            return out;
        }
        match c {
            '`' => {
                let start = *i + 1;
                let end = chars[start..]
                    .iter()
                    .position(|&x| x == '`')
                    .map_or(chars.len(), |p| start + p);
                out.push(Atom::Code(chars[start..end].iter().collect()));
                *i = (end + 1).min(chars.len());
            }
            '(' | '{' | '[' => {
                let close = match c {
                    '(' => ')',
                    '{' => '}',
                    _ => ']',
                };
                if matching(chars, *i, c, close).is_some() {
                    *i += 1;
                    let inner = atoms(chars, i, Some(close));
                    out.push(Atom::Group(c, inner, close));
                } else {
                    // An unclosed bracket is a character like any other.
                    out.push(Atom::Char(c));
                    *i += 1;
                }
            }
            '|' if close != Some('|') && chars[*i + 1..].contains(&'|') => {
                *i += 1;
                let inner = atoms(chars, i, Some('|'));
                out.push(Atom::Group('|', inner, '|'));
            }
            c if word_char(c) && c != '.' && c != '\'' => {
                let start = *i;
                while *i < chars.len() && word_char(chars[*i]) {
                    // A full stop ends a sentence unless a digit follows (3.5).
                    if chars[*i] == '.' && !chars.get(*i + 1).is_some_and(char::is_ascii_digit) {
                        break;
                    }
                    *i += 1;
                }
                out.push(Atom::Word(chars[start..*i].iter().collect()));
            }
            c => {
                out.push(Atom::Char(c));
                *i += 1;
            }
        }
    }
    out
}

/// Parses `text`: scripts everywhere, fractions only when `formula`.
#[must_use]
pub fn parse(text: &str, formula: bool) -> Vec<Node> {
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    build(&atoms(&chars, &mut i, None), formula)
}

/// Parses a narration paragraph: `**…**` spans are formulas (fractions and highlighting),
/// scripts are typeset everywhere, `` `code` `` stays as written.
#[must_use]
pub fn parse_paragraph(text: &str) -> Vec<Node> {
    let mut out = Vec::new();
    for (k, part) in text.split("**").enumerate() {
        if part.is_empty() {
            continue;
        }
        if k % 2 == 1 {
            out.push(Node::Formula(parse(part, true)));
        } else {
            out.extend(parse(part, false));
        }
    }
    out
}

/// The nodes of an atom as written (a group keeps its brackets).
fn plain(atom: &Atom, formula: bool) -> Vec<Node> {
    match atom {
        Atom::Word(w) => vec![Node::Text(w.clone())],
        Atom::Char(c) => vec![Node::Text(c.to_string())],
        Atom::Code(c) => vec![Node::Code(c.clone())],
        Atom::Group(open, inner, close) => {
            let mut v = vec![Node::Text(open.to_string())];
            v.extend(build(inner, formula));
            v.push(Node::Text(close.to_string()));
            merge(v)
        }
    }
}

/// The nodes of an atom used as a script or a fraction's part: a group loses its brackets
/// (except `|…|`, which are part of the mathematics).
fn operand(atom: &Atom, formula: bool) -> Vec<Node> {
    match atom {
        // A tuple keeps its brackets: (x, y, z)/w divides each.
        Atom::Group(open, inner, _) if *open != '|' && !inner.contains(&Atom::Char(',')) => {
            build(inner, formula)
        }
        other => plain(other, formula),
    }
}

/// Whether an atom can carry a subscript: a symbol of one or two letters, or a group.
fn takes_subscript(atom: &Atom) -> bool {
    match atom {
        Atom::Word(w) => w.chars().count() <= 2 || w.chars().all(|c| !c.is_ascii()),
        Atom::Group(..) => true,
        _ => false,
    }
}

/// Whether an atom can be a script or a fraction's part.
fn is_operand(atom: Option<&Atom>) -> bool {
    matches!(atom, Some(Atom::Word(_) | Atom::Group(..)))
}

/// Attaches scripts and (in formulas) fractions, and merges plain text.
fn build(atoms: &[Atom], formula: bool) -> Vec<Node> {
    let mut out: Vec<Node> = Vec::new();
    let mut k = 0;
    // The last operand pushed, as nodes, so that a following `_`, `^` or `/` can take it.
    let mut last: Option<Vec<Node>> = None;
    let mut last_atom: Option<&Atom> = None;
    let flush = |out: &mut Vec<Node>, last: &mut Option<Vec<Node>>| {
        if let Some(nodes) = last.take() {
            out.extend(nodes);
        }
    };
    while k < atoms.len() {
        let a = &atoms[k];
        let script = match a {
            Atom::Char('_') if last_atom.is_some_and(takes_subscript) => Some(true),
            Atom::Char('^') if last.is_some() => Some(false),
            _ => None,
        };
        if let Some(is_sub) = script {
            // A sign may lead an exponent: M^-1.
            let (signed, next) = match (atoms.get(k + 1), atoms.get(k + 2)) {
                (Some(Atom::Char(s @ ('-' | '−' | '+'))), n) if is_operand(n) => (Some(*s), n),
                (n, _) => (None, n),
            };
            if is_operand(next) {
                let mut script_nodes = Vec::new();
                if let Some(s) = signed {
                    script_nodes.push(Node::Text(s.to_string()));
                }
                script_nodes.extend(operand(next.expect("an operand"), formula));
                let base = last.take().unwrap_or_default();
                // A second script on the same base joins the first: x_i^2.
                let (base, mut sub, mut sup) = match base.as_slice() {
                    [Node::Script { base, sub, sup }]
                        if (is_sub && sub.is_none()) || (!is_sub && sup.is_none()) =>
                    {
                        (base.clone(), sub.clone(), sup.clone())
                    }
                    _ => (base, None, None),
                };
                if is_sub {
                    sub = Some(script_nodes);
                } else {
                    sup = Some(script_nodes);
                }
                let node = Node::Script { base, sub, sup };
                last = Some(vec![node]);
                k += if signed.is_some() { 3 } else { 2 };
                continue;
            }
        }
        if formula && matches!(a, Atom::Char('/')) && last.is_some() && is_operand(atoms.get(k + 1))
        {
            let num = last.take().unwrap_or_default();
            let num = match (last_atom, num.as_slice()) {
                // The brackets of a group numerator are dropped (not a tuple's).
                (Some(g @ Atom::Group(..)), _) => operand(g, formula),
                _ => num,
            };
            // Scripts bind tighter than the fraction: x_c/w_c is x_c over w_c.
            let mut end = k + 2;
            while matches!(atoms.get(end), Some(Atom::Char('_' | '^')))
                && is_operand(atoms.get(end + 1))
            {
                end += 2;
            }
            let den = if end == k + 2 {
                operand(&atoms[k + 1], formula)
            } else {
                build(&atoms[k + 1..end], formula)
            };
            last = Some(vec![Node::Frac { num, den }]);
            last_atom = None;
            k = end;
            continue;
        }
        flush(&mut out, &mut last);
        match a {
            Atom::Word(_) | Atom::Group(..) => {
                last = Some(plain(a, formula));
                last_atom = Some(a);
            }
            other => {
                out.extend(plain(other, formula));
                last_atom = None;
            }
        }
        k += 1;
    }
    flush(&mut out, &mut last);
    merge(out)
}

/// Joins neighbouring text nodes.
fn merge(nodes: Vec<Node>) -> Vec<Node> {
    let mut out: Vec<Node> = Vec::with_capacity(nodes.len());
    for n in nodes {
        match (out.last_mut(), n) {
            (Some(Node::Text(a)), Node::Text(b)) => a.push_str(&b),
            (_, n) => out.push(n),
        }
    }
    out
}

/// Whether a fraction's part needs brackets when the fraction is written on one line: it is
/// more than one atom (`E0 + E1 + E2`, `z+1`, `n·l`), so `a/b` would read otherwise than the
/// fraction bar does. A name or number (`w`, `2fn`, `x_c`) and a norm `|l + v|` need none.
#[must_use]
pub fn needs_brackets(part: &[Node]) -> bool {
    let plain = plain_text(part);
    let norm = plain.len() > 1
        && plain.starts_with('|')
        && plain.ends_with('|')
        && plain.matches('|').count() == 2;
    !norm && !plain.chars().all(char::is_alphanumeric)
}

/// The text of nodes with the marks taken out (`x_i` → `xi`), a fraction on one line with its
/// parts bracketed where they need it (`λ_k = E_k/(E_0 + E_1 + E_2)`): for searching and for
/// what a screen reader says.
#[must_use]
pub fn plain_text(nodes: &[Node]) -> String {
    let mut s = String::new();
    for n in nodes {
        match n {
            Node::Text(t) | Node::Code(t) => s.push_str(t),
            Node::Script { base, sub, sup } => {
                s.push_str(&plain_text(base));
                if let Some(x) = sub {
                    s.push_str(&plain_text(x));
                }
                if let Some(x) = sup {
                    s.push('^');
                    s.push_str(&plain_text(x));
                }
            }
            Node::Frac { num, den } => {
                for (k, part) in [num, den].into_iter().enumerate() {
                    if k == 1 {
                        s.push('/');
                    }
                    if needs_brackets(part) {
                        s.push('(');
                        s.push_str(&plain_text(part));
                        s.push(')');
                    } else {
                        s.push_str(&plain_text(part));
                    }
                }
            }
            Node::Formula(inner) => s.push_str(&plain_text(inner)),
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::{Node, parse, parse_paragraph};

    fn t(s: &str) -> Node {
        Node::Text(s.to_owned())
    }

    /// A fraction said on one line reads as its bar does: each part of more than one atom in
    /// brackets (the inspector's λ, f_att, window z, read out by a screen reader), a name, a
    /// number or a norm without.
    #[test]
    fn a_fraction_on_one_line_keeps_its_parts_together() {
        let said = |f: &str| super::plain_text(&parse(f, true));
        assert_eq!(
            said("λ_k = E_k/(E_0 + E_1 + E_2)"),
            "λk = Ek/(E0 + E1 + E2)"
        );
        assert_eq!(
            said("f_att = 1/(a + b·d + c·d^2)"),
            "fatt = 1/(a + b·d + c·d^2)"
        );
        assert_eq!(said("z_w = (z+1)/2"), "zw = (z+1)/2");
        assert_eq!(said("h = (l + v)/|l + v|"), "h = (l + v)/|l + v|");
        assert_eq!(said("x_c/w_c"), "xc/wc");
    }

    #[test]
    fn subscripts_superscripts_and_fractions() {
        assert_eq!(
            parse("z_ndc", true),
            vec![Node::Script {
                base: vec![t("z")],
                sub: Some(vec![t("ndc")]),
                sup: None
            }]
        );
        // A long word keeps its underscore: it is a name, not a symbol.
        assert_eq!(parse("depth_test", true), vec![t("depth_test")]);
        assert_eq!(
            parse("d^2", true),
            vec![Node::Script {
                base: vec![t("d")],
                sub: None,
                sup: Some(vec![t("2")])
            }]
        );
        assert_eq!(
            parse("M^-1", true),
            vec![Node::Script {
                base: vec![t("M")],
                sub: None,
                sup: Some(vec![t("-"), t("1")])
            }]
        );
        // x_i^2: both scripts on one base.
        assert_eq!(
            parse("x_i^2", true),
            vec![Node::Script {
                base: vec![t("x")],
                sub: Some(vec![t("i")]),
                sup: Some(vec![t("2")])
            }]
        );
        assert_eq!(
            parse("(f+n)/(f−n)", true),
            vec![Node::Frac {
                num: vec![t("f+n")],
                den: vec![t("f−n")]
            }]
        );
        // In prose, a slash is a slash.
        assert_eq!(parse("near/far", false), vec![t("near/far")]);
        assert_eq!(
            parse("tan(fovy/2)", true),
            vec![
                t("tan("),
                Node::Frac {
                    num: vec![t("fovy")],
                    den: vec![t("2")]
                },
                t(")")
            ]
        );
        // |l + v| keeps its bars under a fraction bar.
        assert_eq!(
            parse("(l + v)/|l + v|", true),
            vec![Node::Frac {
                num: vec![t("l + v")],
                den: vec![t("|l + v|")]
            }]
        );
        assert_eq!(parse("3.5 and a.", true), vec![t("3.5 and a.")]);
        // An unclosed bracket stays a bracket, and nothing is added.
        assert_eq!(parse("by w (the ", false), vec![t("by w (the ")]);
        // Scripts bind tighter than the fraction bar.
        assert_eq!(
            parse("x_c/w_c", true),
            vec![Node::Frac {
                num: vec![Node::Script {
                    base: vec![t("x")],
                    sub: Some(vec![t("c")]),
                    sup: None
                }],
                den: vec![Node::Script {
                    base: vec![t("w")],
                    sub: Some(vec![t("c")]),
                    sup: None
                }]
            }]
        );
    }

    #[test]
    fn paragraphs_mark_formulas_and_code() {
        let p = parse_paragraph("the **top = near·tan(fovy/2)** of `uv_sphere`, k_a");
        assert!(
            matches!(&p[1], Node::Formula(inner) if inner.iter().any(|n| matches!(n, Node::Frac { .. })))
        );
        assert!(p.contains(&Node::Code("uv_sphere".into())));
        assert!(p.iter().any(|n| matches!(n, Node::Script { .. })));
    }
}
