//! Shader source printed in a handout: numbered lines, GLSL's keywords, types, numbers,
//! directives and comments coloured, and a line too long for the page wrapped under its own
//! indent (a comment's words under the comment's words), so a listing reads as the shader
//! panel shows it.

use std::fmt::Write as _;

use pipeline::shader::lexeme::{Kind, lex};

/// GLSL's keywords a listing colours as such (qualifiers, control flow, literals).
const KEYWORDS: [&str; 33] = [
    "attribute",
    "const",
    "uniform",
    "varying",
    "layout",
    "centroid",
    "flat",
    "smooth",
    "noperspective",
    "in",
    "out",
    "inout",
    "invariant",
    "precision",
    "highp",
    "mediump",
    "lowp",
    "struct",
    "break",
    "continue",
    "do",
    "for",
    "while",
    "switch",
    "case",
    "default",
    "if",
    "else",
    "discard",
    "return",
    "true",
    "false",
    "subroutine",
];

/// Whether `word` names a GLSL type: `void`, the scalars, `vecN` and its `b`/`i`/`u`/`d`
/// kinds, `matN` and `matNxM`, and the samplers.
fn is_type(word: &str) -> bool {
    let vector = |w: &str| {
        let w = w.trim_start_matches(['b', 'i', 'u', 'd']);
        matches!(w, "vec2" | "vec3" | "vec4")
    };
    let matrix = |w: &str| {
        let w = w.strip_prefix('d').unwrap_or(w);
        w.strip_prefix("mat").is_some_and(|dims| {
            matches!(
                dims,
                "2" | "3"
                    | "4"
                    | "2x2"
                    | "2x3"
                    | "2x4"
                    | "3x2"
                    | "3x3"
                    | "3x4"
                    | "4x2"
                    | "4x3"
                    | "4x4"
            )
        })
    };
    matches!(word, "void" | "bool" | "int" | "uint" | "float" | "double")
        || vector(word)
        || matrix(word)
        || word.trim_start_matches(['i', 'u']).starts_with("sampler")
}

/// The class a lexeme is coloured with, if any.
fn class(kind: Kind, text: &str) -> Option<&'static str> {
    match kind {
        Kind::Comment => Some("c"),
        Kind::Directive => Some("d"),
        Kind::Number => Some("n"),
        Kind::Word if KEYWORDS.contains(&text) => Some("k"),
        Kind::Word if is_type(text) => Some("t"),
        _ => None,
    }
}

/// The style rules of a listing (a `<table class="src">`).
pub const STYLE: &str = "\
table.src{border-collapse:collapse;width:100%;background:#f6f6f1;font-family:'pipelens CJK','DejaVu Sans Mono',Menlo,Consolas,'Liberation Mono',monospace;font-size:8.5pt;line-height:1.35;margin:.3em 0}
table.src td{padding:0 .5em;vertical-align:top} table.src td.n{color:#666;text-align:right;width:2.5em;user-select:none;border-right:1px solid #ddd}
table.src td.l{white-space:pre-wrap;overflow-wrap:anywhere} table.src tr.m td{background:#fff1c7}
table.src .c{color:#5b6b5b;font-style:italic} table.src .k{color:#8a1f6d;font-weight:bold} table.src .t{color:#0b5f8a}
table.src .n{color:#9a5b00} table.src .d{color:#6d4aa6} .listing{font-size:.9em;color:#444;margin:.8em 0 0}
";

/// `source` as a listing: one row per line with its number, the lines in `marked` (from 1)
/// on a yellow ground. A wrapped line continues under its text: under the words of a comment
/// that starts the line, else four columns further in than the line's indent.
#[must_use]
pub fn html(source: &str, marked: &[usize]) -> String {
    let source = source.trim_end();
    let mut lines = vec![String::new()];
    for l in lex(source) {
        let text = &source[l.span];
        let class = class(l.kind, text);
        for (k, part) in text.split('\n').enumerate() {
            if k > 0 {
                lines.push(String::new());
            }
            let line = lines.last_mut().expect("a line");
            match class {
                Some(c) if !part.is_empty() => {
                    let _ = write!(
                        line,
                        "<span class=\"{c}\">{}</span>",
                        super::html::esc(part)
                    );
                }
                _ => line.push_str(&super::html::esc(part)),
            }
        }
    }
    let mut h = String::from("<table class=\"src\">");
    for (i, (line, raw)) in lines.iter().zip(source.split('\n')).enumerate() {
        let indent = raw.len() - raw.trim_start().len();
        let hang = indent
            + if raw.trim_start().starts_with("//") {
                3
            } else {
                4
            };
        let _ = write!(
            h,
            "<tr{}><td class=\"n\">{}</td><td class=\"l\" style=\"padding-left:{hang}ch;text-indent:-{hang}ch\">{line}</td></tr>",
            if marked.contains(&(i + 1)) {
                " class=\"m\""
            } else {
                ""
            },
            i + 1
        );
    }
    h.push_str("</table>");
    h
}

/// The files of `code` a listing prints, named as the shader panel's Save names them:
/// pipelens' own shipped shaders are not repeated.
pub(super) fn own_files(code: &pipeline::scene::StudentCode) -> Vec<(String, &str)> {
    let files = crate::lesson::forbid::sources(code);
    files.into_iter().filter(|(f, s)| !shipped(f, s)).collect()
}

/// Whether `source`, saved as `file`, is one of pipelens' own shipped shaders.
fn shipped(file: &str, source: &str) -> bool {
    use pipeline::shader::{SHIPPED_FRAGMENT, SHIPPED_VERTEX};
    match file {
        "shader.vert" => SHIPPED_VERTEX.contains(&source),
        "shader.frag" => SHIPPED_FRAGMENT.contains(&source),
        _ => false,
    }
}

/// The lines (from 1) of `source` whose code `before` does not have, blank lines aside: a
/// step's edit of the shader the step before ran. A line's code is its text before a `//`
/// comment (a comment alone on its line is its code), so a comment dropped from a line the
/// edit did not touch does not mark it.
pub(super) fn changed_lines(source: &str, before: &str) -> Vec<usize> {
    let code = |line: &str| {
        let line = line.trim();
        match line.split_once("//") {
            Some((code, _)) if !code.trim().is_empty() => code.trim().to_owned(),
            _ => line.to_owned(),
        }
    };
    let old: std::collections::HashSet<String> = before.lines().map(code).collect();
    source
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !old.contains(&code(l)))
        .map(|(i, _)| i + 1)
        .collect()
}

/// Step `k`'s own shaders (its `shader`: `code`), each with its file name and the lines it
/// changed from the shader of the same file the step before ran.
pub(super) fn step_edits<'a>(
    lesson: &crate::lesson::Lesson,
    k: usize,
    code: &'a pipeline::scene::StudentCode,
) -> Vec<(String, &'a str, Vec<usize>)> {
    let files = own_files(code);
    if files.is_empty() {
        return Vec::new();
    }
    let before = k.checked_sub(1).map(|j| lesson.spec_at(j).scene);
    // An edit is of the step before's own code: pipelens' shipped shaders are no edit's start.
    let before_files = before.as_ref().map_or_else(Vec::new, |scene| {
        let shader = scene.objects.iter().find_map(|o| o.code.shader.as_ref());
        let files = crate::lesson::forbid::files(shader, |kind| scene.hook(kind));
        files.into_iter().filter(|(f, s)| !shipped(f, s)).collect()
    });
    files
        .into_iter()
        .map(|(file, source)| {
            let marked = before_files
                .iter()
                .find(|(f, _)| *f == file)
                .map_or_else(Vec::new, |(_, old)| changed_lines(source, old));
            (file, source, marked)
        })
        .collect()
}

/// A lab's starter files (pipelens' own shipped shaders aside), each with its file name and
/// the lines that say TODO.
pub(super) fn starter_todos(
    starter: &pipeline::scene::StudentCode,
) -> Vec<(String, &str, Vec<usize>)> {
    own_files(starter)
        .into_iter()
        .map(|(file, source)| {
            let todo = source
                .lines()
                .enumerate()
                .filter(|(_, l)| l.contains("TODO"))
                .map(|(i, _)| i + 1)
                .collect();
            (file, source, todo)
        })
        .collect()
}

/// A row of a slide's code panel: the line's number (empty for a gap), its text, and whether
/// it is marked.
pub type Row = (String, String, bool);

/// The lines of `source` a slide shows: each marked line (from 1) with `context` lines around
/// it, at most `max` in all, as `(line, text, marked)`; a gap between two stretches is a row
/// with no number and `…`.
#[must_use]
pub(super) fn focus(
    source: &str,
    marked: &[usize],
    context: usize,
    max: usize,
) -> Vec<(String, String, bool)> {
    let lines: Vec<&str> = source.lines().collect();
    let shown = |i: usize| {
        marked
            .iter()
            .any(|&m| i + 1 + context >= m && i < m + context)
    };
    let mut out = Vec::new();
    let mut last: Option<usize> = None;
    for (i, text) in lines.iter().enumerate().filter(|(i, _)| shown(*i)) {
        if last.is_some_and(|l| i > l + 1) {
            out.push((String::new(), "…".to_owned(), false));
        }
        out.push((
            (i + 1).to_string(),
            (*text).to_owned(),
            marked.contains(&(i + 1)),
        ));
        last = Some(i);
    }
    out.truncate(max);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each line numbered, its lexemes coloured by kind, `<` escaped, a marked line marked, and
    /// a comment's continuation indented under its words (4 spaces and `// `: 7 columns).
    #[test]
    fn a_listing_numbers_colours_and_hangs_its_lines() {
        let h = html(
            "#version 330 core\nuniform vec3 eye;\nvoid main() {\n    // if a < b\n    float x = 1.5;\n}\n",
            &[5],
        );
        assert_eq!(h.matches("<tr").count(), 6, "{h}");
        assert!(h.contains("<span class=\"d\">#version 330 core</span>"));
        assert!(h.contains("<span class=\"k\">uniform</span> <span class=\"t\">vec3</span> eye;"));
        assert!(h.contains("<span class=\"c\">// if a &lt; b</span>"));
        assert!(h.contains("padding-left:7ch;text-indent:-7ch\">    <span class=\"c\">"));
        assert!(h.contains(
            "<tr class=\"m\"><td class=\"n\">5</td><td class=\"l\" style=\"padding-left:8ch;text-indent:-8ch\">    <span class=\"t\">float</span> x = <span class=\"n\">1.5</span>;"
        ));
        assert!(!h.contains("<tr class=\"m\"><td class=\"n\">4<"));
    }

    #[test]
    fn types_are_told_from_other_words() {
        for t in [
            "vec3",
            "ivec2",
            "mat4",
            "mat3x2",
            "dmat4",
            "sampler2D",
            "usampler2D",
            "void",
        ] {
            assert!(is_type(t), "{t}");
        }
        for w in ["vector", "mat5", "material", "eye", "bvec", "vec5"] {
            assert!(!is_type(w), "{w}");
        }
    }
}
