//! The light scan of a student's source that the adaptation reads: its tokens with comments
//! left out, its top-level statements, and its `#version` line.

use std::ops::Range;

/// A top-level statement's tokens, with the offset just after its `;`.
pub(super) type Statement = (Vec<Token>, usize);

/// A token of the light scan: a word, or one character of punctuation.
#[derive(Clone, Debug)]
pub(super) struct Token {
    pub(super) text: String,
    pub(super) span: Range<usize>,
}

/// The `#version` directive's place in `src`, from its `#` to the end of its line, as the
/// adaptation finds it (a directive in a comment is none).
pub(crate) fn version_directive(src: &str) -> Option<Range<usize>> {
    top_level(src).1
}

/// Splits `src` into tokens, leaving out comments, and into top-level statements. Returns the
/// top-level declarations (token lists ending before their `;`, with the offset just after
/// it), and the `#version` line.
pub(super) fn top_level(src: &str) -> (Vec<Statement>, Option<Range<usize>>) {
    let bytes = src.as_bytes();
    let mut statements = Vec::new();
    let mut current: Vec<Token> = Vec::new();
    let mut version = None;
    let (mut depth, mut i, mut at_line_start) = (0usize, 0usize, true);
    // Whether the current top-level statement opened a body (a function, a struct, a block).
    let mut opened_body = false;
    while i < bytes.len() {
        let c = bytes[i];
        if c == b'\n' {
            at_line_start = true;
            i += 1;
            continue;
        }
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        if src[i..].starts_with("//") {
            i = src[i..].find('\n').map_or(bytes.len(), |n| i + n);
            continue;
        }
        if src[i..].starts_with("/*") {
            i = src[i + 2..]
                .find("*/")
                .map_or(bytes.len(), |n| i + 2 + n + 2);
            continue;
        }
        if c == b'#' && at_line_start {
            // A preprocessor line, with its `\` continuations.
            let start = i;
            while i < bytes.len() && !(bytes[i] == b'\n' && bytes[i - 1] != b'\\') {
                i += 1;
            }
            let line = src[start..i].trim_end_matches('\r');
            if line
                .trim_start_matches('#')
                .trim_start()
                .starts_with("version")
            {
                version = Some(start..start + line.len());
            }
            continue;
        }
        at_line_start = false;
        if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' {
            let start = i;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || matches!(bytes[i], b'_' | b'.'))
            {
                i += 1;
            }
            if depth == 0 && !opened_body {
                current.push(Token {
                    text: src[start..i].to_owned(),
                    span: start..i,
                });
            }
            continue;
        }
        let ch = src[i..].chars().next().map_or(1, char::len_utf8);
        match c {
            b'{' => {
                if depth == 0 && !opened_body {
                    current.push(Token {
                        text: "{".to_owned(),
                        span: i..i + 1,
                    });
                    opened_body = true;
                }
                depth += 1;
            }
            b'}' => {
                depth = depth.saturating_sub(1);
                // A function's body ends its statement; a struct's or block's ends at `;`.
                if depth == 0 && current.iter().any(|t| t.text == "(") {
                    current.clear();
                    opened_body = false;
                }
            }
            b';' if depth == 0 => {
                // A struct's or block's body was skipped: its tokens end at its `{`.
                statements.push((std::mem::take(&mut current), i + 1));
                opened_body = false;
            }
            _ if depth == 0 && !opened_body => {
                current.push(Token {
                    text: src[i..i + ch].to_owned(),
                    span: i..i + ch,
                });
            }
            _ => {}
        }
        i += ch;
    }
    (statements, version)
}
