//! What the TOML reader's messages mean for a teacher writing a lesson.
//!
//! The reader reports where it gave up, in its own words ("missing comma between key-value
//! pairs", "duplicate key", "expected struct RawText"). [`explain`] turns that into the place
//! the mistake was made and what to write instead: the `{` that is never closed, the first
//! place a duplicated key was given, a text that needs both languages.

use pipeline::shader::suggest::{Quote, did_you_mean};
use std::ops::Range;

use super::Diagnostic;

/// The diagnostic for the reader's `message` at byte `span` of `text`.
pub(super) fn explain(text: &str, file: &str, span: Range<usize>, message: &str) -> Diagnostic {
    let marks = Marks::scan(text);
    if let Some(open) = marks.unclosed_brace().filter(|&o| o < span.start.max(1)) {
        return Diagnostic::at(
            file,
            text,
            open..open + 1,
            format!(
                "this `{{` is never closed: a table written inline, `{{ … }}`, ends with `}}` \
                 (the reader went on to line {} and stopped there: {})",
                line_of(text, span.start),
                plain_words(message)
            ),
        );
    }
    if message.starts_with("duplicate key") {
        let key = key_at(text, span.clone());
        let first = marks
            .first_definition(text, &key, span.start)
            .map_or_else(String::new, |at| {
                let (line, column) = line_column(text, at);
                format!(": it was first given on line {line}, column {column}")
            });
        return Diagnostic::at(
            file,
            text,
            span,
            format!("`{key}` is given twice in the same table{first}; give each key once"),
        );
    }
    if let Some(field) = missing_language(message) {
        let owner = key_before(text, span.start);
        let what = owner.map_or_else(|| "this text".to_owned(), |k| format!("`{k}`"));
        return Diagnostic::at(
            file,
            text,
            span,
            format!(
                "{what} needs both languages, {{ en = \"…\", zh = \"…\" }}: `{field}` is missing"
            ),
        );
    }
    Diagnostic::at(file, text, span, with_suggestion(&plain_words(message)))
}

/// `en` or `zh` when the message is serde's "missing field `en`" / "missing field `zh`".
fn missing_language(message: &str) -> Option<&'static str> {
    ["en", "zh"]
        .into_iter()
        .find(|l| message == format!("missing field `{l}`"))
}

/// Serde's names for the kinds of value, in the words of the file's reader.
const KINDS: [(&str, &str); 6] = [
    ("expected f64", "expected a number"),
    ("expected i64", "expected a whole number"),
    ("expected a boolean", "expected true or false"),
    ("expected a sequence", "expected an array [ … ]"),
    (
        "expected an array of length 3",
        "expected an array of three numbers [x, y, z]",
    ),
    ("expected a map", "expected a table { … }"),
];

fn plain_words(message: &str) -> String {
    KINDS
        .iter()
        .fold(message.to_owned(), |m, (from, to)| m.replace(from, to))
}

/// Adds "did you mean `x`?" to serde's "unknown field `y`, expected one of `a`, `b`" messages.
fn with_suggestion(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return message.to_owned();
    };
    let Some((unknown, expected)) = rest.split_once('`') else {
        return message.to_owned();
    };
    let candidates = expected.split('`').skip(1).step_by(2);
    format!(
        "{message}{}",
        did_you_mean(unknown, candidates, Quote::Code)
    )
}

/// The key written at `span`, without quotes.
fn key_at(text: &str, span: Range<usize>) -> String {
    text.get(span)
        .unwrap_or_default()
        .trim()
        .trim_matches(|c| c == '"' || c == '\'')
        .to_owned()
}

/// The key whose value starts at `value_start` (`narration` in `narration = { en = "…" }`).
fn key_before(text: &str, value_start: usize) -> Option<String> {
    let before = text.get(..value_start)?.trim_end().strip_suffix('=')?;
    let key: String = before
        .trim_end()
        .chars()
        .rev()
        .take_while(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.' | '"'))
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect();
    let key = key.trim_matches('"').to_owned();
    (!key.is_empty()).then_some(key)
}

fn line_of(text: &str, at: usize) -> usize {
    line_column(text, at).0
}

/// 1-based line and column (in characters) of byte `at`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let d = Diagnostic::at("", text, at..at, "");
    (d.line, d.column)
}

/// The places that give a TOML file its structure, found outside strings and comments.
struct Marks {
    /// Byte offsets of `{`, each with the offset of its `}` if it has one.
    braces: Vec<(usize, Option<usize>)>,
    /// Byte offsets of the lines that start a table (`[name]` or `[[name]]`).
    headers: Vec<usize>,
}

impl Marks {
    fn scan(text: &str) -> Self {
        let bytes = text.as_bytes();
        let mut braces = Vec::new();
        let mut open: Vec<usize> = Vec::new();
        let mut headers = Vec::new();
        let mut brackets = 0usize;
        let mut line_start = true;
        let mut i = 0;
        while i < bytes.len() {
            let b = bytes[i];
            match b {
                b'\n' => line_start = true,
                b' ' | b'\t' | b'\r' => {}
                b'#' => {
                    i = text[i..].find('\n').map_or(bytes.len(), |n| i + n);
                    continue;
                }
                b'"' | b'\'' => {
                    i = string_end(bytes, i);
                    line_start = false;
                    continue;
                }
                _ => {
                    match b {
                        b'[' if line_start && brackets == 0 && open.is_empty() => headers.push(i),
                        b'[' => brackets += 1,
                        b']' => brackets = brackets.saturating_sub(1),
                        b'{' => {
                            open.push(braces.len());
                            braces.push((i, None));
                        }
                        b'}' => {
                            if let Some(k) = open.pop() {
                                braces[k].1 = Some(i);
                            }
                        }
                        _ => {}
                    }
                    line_start = false;
                }
            }
            i += 1;
        }
        Self { braces, headers }
    }

    /// The first `{` that no `}` closes.
    fn unclosed_brace(&self) -> Option<usize> {
        self.braces
            .iter()
            .find(|(_, close)| close.is_none())
            .map(|(o, _)| *o)
    }

    /// Where `key` is first given in the table that holds byte `at`: the innermost inline
    /// table around `at`, else the section from the last `[header]` before it.
    fn first_definition(&self, text: &str, key: &str, at: usize) -> Option<usize> {
        let inline = self
            .braces
            .iter()
            .filter(|(o, c)| *o < at && c.is_none_or(|c| c > at))
            .map(|(o, _)| o + 1)
            .next_back();
        let start = inline.unwrap_or_else(|| {
            self.headers
                .iter()
                .copied()
                .take_while(|&h| h < at)
                .last()
                .unwrap_or(0)
        });
        let region = text.get(start..at)?;
        let quoted = format!("\"{key}\"");
        [key, quoted.as_str()]
            .iter()
            .flat_map(|k| region.match_indices(k).map(move |(i, _)| (i, k.len())))
            .filter(|&(i, len)| {
                let before = region[..i].chars().next_back();
                let after = region[i + len..].trim_start_matches([' ', '\t']);
                before.is_none_or(|c| c.is_whitespace() || c == '{' || c == ',')
                    && after.starts_with('=')
            })
            .map(|(i, _)| start + i)
            .min()
    }
}

/// The byte after the string that starts at `i` (basic or literal, one line or three quotes).
fn string_end(bytes: &[u8], i: usize) -> usize {
    let q = bytes[i];
    let triple = bytes.get(i..i + 3) == Some(&[q, q, q][..]);
    let mut j = if triple { i + 3 } else { i + 1 };
    while j < bytes.len() {
        let b = bytes[j];
        if b == b'\\' && q == b'"' {
            j += 2;
            continue;
        }
        if !triple && b == b'\n' {
            return j;
        }
        if b == q && (!triple || bytes.get(j..j + 3) == Some(&[q, q, q][..])) {
            return j + if triple { 3 } else { 1 };
        }
        j += 1;
    }
    bytes.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn braces_in_strings_and_comments_do_not_count() {
        let m = Marks::scan("a = \"{\" # {\nb = '''{\n'''\nc = { d = 1 }\n");
        assert_eq!(m.braces.len(), 1);
        assert_eq!(m.unclosed_brace(), None);
        let m = Marks::scan("[x]\na = { b = 1\n[[y]]\n");
        assert_eq!(m.unclosed_brace(), Some(8));
    }

    #[test]
    fn the_first_definition_is_found_in_its_own_table() {
        let text = "[a]\nk = 1\n[b]\nk = 2\nj = { k = 3, k = 4 }\nk = 5\n";
        let m = Marks::scan(text);
        let second_inline = text.rfind("k = 4").expect("k");
        assert_eq!(
            m.first_definition(text, "k", second_inline),
            text.find("k = 3")
        );
        let last = text.rfind("k = 5").expect("k");
        assert_eq!(m.first_definition(text, "k", last), text.find("k = 2"));
    }
}
