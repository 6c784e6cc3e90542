//! Text put inside HTML: its markup characters written as entities; the app's notation typeset
//! as HTML (scripts, fractions, formulas) and a narration's simple markdown.

use std::fmt::Write as _;

use crate::vocabulary::notation::{self, Node};

/// Escapes text for HTML.
pub(super) fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Typeset notation ([`notation`]) as HTML, as the app lays it out: scripts as `<sub>` and
/// `<sup>`, a fraction's parts stacked over a bar, code in monospace, a narration's formula
/// highlighted.
pub(super) fn typeset(nodes: &[Node]) -> String {
    let mut s = String::new();
    for n in nodes {
        match n {
            Node::Text(t) => s.push_str(&esc(t)),
            Node::Code(t) => {
                let _ = write!(s, "<code>{}</code>", esc(t));
            }
            Node::Script { base, sub, sup } => {
                s.push_str(&typeset(base));
                if let Some(x) = sub {
                    let _ = write!(s, "<sub>{}</sub>", typeset(x));
                }
                if let Some(x) = sup {
                    let _ = write!(s, "<sup>{}</sup>", typeset(x));
                }
            }
            Node::Frac { num, den } => {
                let _ = write!(
                    s,
                    "<span class=\"frac\"><span>{}</span><span>{}</span></span>",
                    typeset(num),
                    typeset(den)
                );
            }
            Node::Formula(inner) => {
                let _ = write!(s, "<strong>{}</strong>", typeset(inner));
            }
        }
    }
    s
}

/// The narration's simple markdown as HTML: paragraphs, `- ` bullets, `**formulas**`, each
/// line typeset ([`notation::parse_paragraph`]).
pub(super) fn markdown(text: &str) -> String {
    let mut out = String::new();
    for paragraph in text.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
        let lines: Vec<&str> = paragraph.lines().map(str::trim).collect();
        let inline = |l: &str| typeset(&notation::parse_paragraph(l));
        if lines.iter().all(|l| l.starts_with("- ")) {
            out.push_str("<ul>");
            for l in lines {
                let _ = write!(out, "<li>{}</li>", inline(&l[2..]));
            }
            out.push_str("</ul>\n");
        } else {
            let _ = writeln!(out, "<p>{}</p>", inline(&lines.join(" ")));
        }
    }
    out
}
