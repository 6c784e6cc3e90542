//! GLSL source cut into lexemes, each with its kind, its place and its line: what a printed
//! listing colours, and what a check of names reads (comments are lexemes too, so a reader
//! skips them by kind). Every byte of the source belongs to exactly one lexeme, so the lexemes
//! written one after another give the source back.

use std::ops::Range;

/// What a lexeme is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `// …` to the end of its line, or `/* … */`.
    Comment,
    /// A preprocessor line (`#version 330 core`), with its `\` continuations.
    Directive,
    /// An identifier or a keyword: a letter or `_`, then letters, digits and `_`.
    Word,
    /// A number: `1`, `0.5`, `.5`, `1e-3`, `2.0f`, `0x1F`, `3u`.
    Number,
    /// One character of anything else (`(`, `;`, `*`, …).
    Punctuation,
    /// Spaces, tabs and line breaks.
    Space,
}

/// One lexeme of a source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lexeme {
    /// Its kind.
    pub kind: Kind,
    /// Its bytes in the source.
    pub span: Range<usize>,
    /// The line it starts on (from 1).
    pub line: usize,
}

/// `src` cut into lexemes, in order; together they cover every byte of it.
#[must_use]
pub fn lex(src: &str) -> Vec<Lexeme> {
    let bytes = src.as_bytes();
    let mut out = Vec::new();
    let (mut i, mut line, mut line_start) = (0, 1, true);
    while i < bytes.len() {
        let c = bytes[i];
        let rest = &src[i..];
        let (end, kind) = if c.is_ascii_whitespace() {
            let n = rest.find(|ch: char| !ch.is_ascii_whitespace());
            (i + n.unwrap_or(rest.len()), Kind::Space)
        } else if rest.starts_with("//") {
            (i + rest.find('\n').unwrap_or(rest.len()), Kind::Comment)
        } else if let Some(body) = rest.strip_prefix("/*") {
            let n = body.find("*/");
            (n.map_or(bytes.len(), |n| i + 2 + n + 2), Kind::Comment)
        } else if c == b'#' && line_start {
            // To the end of the line, past each `\` that continues it.
            let mut j = i;
            while j < bytes.len() && !(bytes[j] == b'\n' && bytes[j - 1] != b'\\') {
                j += 1;
            }
            (j, Kind::Directive)
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let n = rest.find(|ch: char| !(ch.is_ascii_alphanumeric() || ch == '_'));
            (i + n.unwrap_or(rest.len()), Kind::Word)
        } else if c.is_ascii_digit()
            || (c == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            (number_end(bytes, i), Kind::Number)
        } else {
            let n = rest.chars().next().map_or(1, char::len_utf8);
            (i + n, Kind::Punctuation)
        };
        out.push(Lexeme {
            kind,
            span: i..end,
            line,
        });
        let text = &src[i..end];
        line += text.matches('\n').count();
        line_start = kind == Kind::Space && (line_start || text.contains('\n'));
        i = end;
    }
    out
}

/// Where the number starting at `i` ends: digits, a point, letters (a suffix, hex digits, an
/// exponent's `e`) and an exponent's sign.
fn number_end(bytes: &[u8], mut i: usize) -> usize {
    let start = i;
    while i < bytes.len() {
        let c = bytes[i];
        let exponent_sign = matches!(c, b'+' | b'-')
            && i > start
            && matches!(bytes[i - 1], b'e' | b'E')
            && !bytes[start..i].starts_with(b"0x");
        if c.is_ascii_alphanumeric() || c == b'.' || exponent_sign {
            i += 1;
        } else {
            break;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A shader's lexemes, each with its text, kind and line, read by hand from the source.
    #[test]
    fn a_shader_is_cut_into_its_lexemes_and_they_give_it_back() {
        let src = "#version 330 core\n// a comment, x = 1\nfloat f = 1.5e-3 * .5; /* two\nlines */ int i;\n";
        let lexemes = lex(src);
        let joined: String = lexemes.iter().map(|l| &src[l.span.clone()]).collect();
        assert_eq!(joined, src);
        let seen: Vec<(&str, Kind, usize)> = lexemes
            .iter()
            .filter(|l| l.kind != Kind::Space)
            .map(|l| (&src[l.span.clone()], l.kind, l.line))
            .collect();
        assert_eq!(
            seen,
            [
                ("#version 330 core", Kind::Directive, 1),
                ("// a comment, x = 1", Kind::Comment, 2),
                ("float", Kind::Word, 3),
                ("f", Kind::Word, 3),
                ("=", Kind::Punctuation, 3),
                ("1.5e-3", Kind::Number, 3),
                ("*", Kind::Punctuation, 3),
                (".5", Kind::Number, 3),
                (";", Kind::Punctuation, 3),
                ("/* two\nlines */", Kind::Comment, 3),
                ("int", Kind::Word, 4),
                ("i", Kind::Word, 4),
                (";", Kind::Punctuation, 4),
            ]
        );
    }

    /// `#` is a directive only at the start of a line; `a.x` is a word, a point and a word;
    /// `x-1` a subtraction, not an exponent; a character outside ASCII is one lexeme.
    #[test]
    fn directives_swizzles_and_signs_are_told_apart() {
        let src = "v.x-1e+2 # n·l\n  #define N 3";
        let seen: Vec<(&str, Kind)> = lex(src)
            .iter()
            .filter(|l| l.kind != Kind::Space)
            .map(|l| (&src[l.span.clone()], l.kind))
            .collect();
        assert_eq!(
            seen,
            [
                ("v", Kind::Word),
                (".", Kind::Punctuation),
                ("x", Kind::Word),
                ("-", Kind::Punctuation),
                ("1e+2", Kind::Number),
                ("#", Kind::Punctuation),
                ("n", Kind::Word),
                ("·", Kind::Punctuation),
                ("l", Kind::Word),
                ("#define N 3", Kind::Directive),
            ]
        );
    }
}
