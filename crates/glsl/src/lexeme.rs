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

/// Whether `a` and `b` are the same code: the same lexemes but for comments and spacing (a
/// starter shown with its comments in another language is still the starter).
#[must_use]
pub fn same_code(a: &str, b: &str) -> bool {
    fn code(src: &str) -> impl Iterator<Item = &str> {
        lex(src)
            .into_iter()
            .filter(|l| !matches!(l.kind, Kind::Comment | Kind::Space))
            .map(move |l| &src[l.span])
    }
    code(a).eq(code(b))
}

/// The words of `src` that are called: each followed, past spaces and comments, by `(` (a
/// function's name at its call or definition, a constructor's type).
#[must_use]
pub fn calls(src: &str) -> Vec<Lexeme> {
    let lexemes = lex(src);
    lexemes
        .iter()
        .enumerate()
        .filter(|(k, l)| {
            l.kind == Kind::Word
                && lexemes[k + 1..]
                    .iter()
                    .find(|n| !matches!(n.kind, Kind::Space | Kind::Comment))
                    .is_some_and(|n| &src[n.span.clone()] == "(")
        })
        .map(|(_, l)| l.clone())
        .collect()
}

/// Where `src` defines (or declares) the function `name` at its top level: the offset of the
/// name in `T name(`, a type word before it, outside every brace.
#[must_use]
pub fn definition(src: &str, name: &str) -> Option<usize> {
    let code: Vec<Lexeme> = lex(src)
        .into_iter()
        .filter(|l| !matches!(l.kind, Kind::Comment | Kind::Space))
        .collect();
    let text = |l: &Lexeme| &src[l.span.clone()];
    let mut depth = 0i32;
    for (k, l) in code.iter().enumerate() {
        match text(l) {
            "{" => depth += 1,
            "}" => depth -= 1,
            word if depth == 0 && word == name && l.kind == Kind::Word => {
                let typed = k > 0
                    && code[k - 1].kind == Kind::Word
                    && !matches!(text(&code[k - 1]), "return" | "else");
                if typed && code.get(k + 1).is_some_and(|n| text(n) == "(") {
                    return Some(l.span.start);
                }
            }
            _ => {}
        }
    }
    None
}

/// The function whose body holds offset `at` of `src`: the name before the parameter list
/// that the body's `{` follows, at the top level.
#[must_use]
pub fn enclosing_function(src: &str, at: usize) -> Option<&str> {
    let code: Vec<Lexeme> = lex(src)
        .into_iter()
        .filter(|l| !matches!(l.kind, Kind::Comment | Kind::Space))
        .collect();
    let (mut depth, mut named, mut current) = (0i32, None, None);
    for (k, l) in code.iter().enumerate() {
        if l.span.start >= at {
            return current.filter(|_| depth > 0);
        }
        match &src[l.span.clone()] {
            "(" if depth == 0 && k > 0 && code[k - 1].kind == Kind::Word => {
                named = Some(&src[code[k - 1].span.clone()]);
            }
            "{" => {
                if depth == 0 {
                    current = named;
                }
                depth += 1;
            }
            "}" => depth -= 1,
            _ => {}
        }
    }
    None
}

/// The parameter list of the function whose name is at offset `name` of `src`, from `(` to
/// `)`, its spaces and line breaks each one space.
#[must_use]
pub fn parameter_list(src: &str, name: usize) -> String {
    let open = src[name..].find('(').map_or(src.len(), |o| name + o);
    let close = src[open..].find(')').map_or(src.len(), |c| open + c + 1);
    src[open..close]
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// `src` with each `//` comment whose words `words` gives other words for rewritten: the
/// comment's words are its text after `//` and its leading spaces, trimmed; the spaces stay, so
/// a comment's indent under the one above it is kept. The code and the line count are unchanged.
#[must_use]
pub fn map_comments(src: &str, words: impl Fn(&str) -> Option<String>) -> String {
    let mut out = String::with_capacity(src.len());
    for l in lex(src) {
        let text = &src[l.span];
        let body = text.strip_prefix("//").filter(|_| l.kind == Kind::Comment);
        let other = body.and_then(|b| {
            let trimmed = b.trim();
            let lead = &b[..b.len() - b.trim_start().len()];
            words(trimmed)
                .filter(|w| !w.contains('\n'))
                .map(|w| format!("//{lead}{w}"))
        });
        out.push_str(other.as_deref().unwrap_or(text));
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

    /// A comment's words are replaced where another text is given, its indent kept; the code
    /// is untouched and the same code is recognised under either comments.
    #[test]
    fn comments_are_rewritten_and_the_code_is_the_same() {
        let src = "// one\n//   two, indented\nfloat x = 1.0; // three\n// four\n";
        let other = map_comments(src, |w| match w {
            "one" => Some("一".to_owned()),
            "two, indented" => Some("二".to_owned()),
            "three" => Some("三".to_owned()),
            _ => None,
        });
        assert_eq!(other, "// 一\n//   二\nfloat x = 1.0; // 三\n// four\n");
        assert!(same_code(src, &other));
        assert!(!same_code(src, "float x = 2.0;"));
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
