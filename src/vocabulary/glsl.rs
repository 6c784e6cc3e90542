//! GLSL shown in the interface's language: the code stays GLSL, its `//` comments are put in
//! the reader's language — a lesson's own from its file (`[comments.zh]`, Chinese), pipelens'
//! shipped shaders' from the catalogs (a `glsl-…` message per comment line, its English the
//! line's words). A comment with no translation stays as written.

use std::collections::BTreeMap;

use pipeline::shader::lexeme::{Kind, lex};

use super::Lang;

/// `source` with its comments in `lang`: a comment's words found in the `lesson`'s table (in
/// Chinese) or in the catalogs are replaced (the code, the lines and each comment's indent
/// unchanged). English is the source as it is.
#[must_use]
pub fn localize(source: &str, lang: Lang, lesson: &BTreeMap<String, String>) -> String {
    if lang == Lang::EN {
        return source.to_owned();
    }
    pipeline::shader::lexeme::map_comments(source, |words| {
        let own = lesson.get(words).filter(|_| lang.is_chinese()).cloned();
        own.or_else(|| lang.from_english("glsl", words).map(str::to_owned))
    })
}

/// Whether a comment's `words` have their Chinese, in the lesson's table or the catalogs.
fn has_chinese(words: &str, lesson: &BTreeMap<String, String>) -> bool {
    lesson.contains_key(words) || Lang::ZH.from_english("glsl", words).is_some()
}

/// The words of `source`'s `//` comments that have no Chinese (neither in the `lesson`'s table
/// nor in the catalogs) and are not GLSL themselves (a declaration quoted in a comment).
#[must_use]
pub fn untranslated(source: &str, lesson: &BTreeMap<String, String>) -> Vec<String> {
    lex(source)
        .into_iter()
        .filter(|l| l.kind == Kind::Comment)
        .filter_map(|l| source[l.span].strip_prefix("//").map(str::trim))
        .filter(|words| !words.is_empty() && !is_code(words))
        .filter(|words| !has_chinese(words, lesson))
        .map(str::to_owned)
        .collect()
}

/// Whether a comment's words are GLSL quoted as it is (`struct Light { … };`,
/// `const int LIGHT_POINT = 1;`): they read the same in every language.
fn is_code(words: &str) -> bool {
    let first = words.split_whitespace().next().unwrap_or_default();
    words.ends_with(';')
        && matches!(
            first,
            "struct" | "const" | "uniform" | "float" | "int" | "vec2" | "vec3" | "vec4"
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every comment of every shipped shader has its Chinese, and the Chinese source is the
    /// same code with as many lines.
    #[test]
    fn the_shipped_shaders_read_in_chinese() {
        let none = BTreeMap::new();
        let shipped = pipeline::shader::SHIPPED_VERTEX
            .iter()
            .chain(&pipeline::shader::SHIPPED_FRAGMENT);
        for source in shipped {
            let missing = untranslated(source, &none);
            assert!(missing.is_empty(), "no Chinese for {missing:#?}");
            let zh = localize(source, Lang::ZH, &none);
            assert!(pipeline::shader::lexeme::same_code(source, &zh));
            assert_eq!(zh.lines().count(), source.lines().count());
            assert!(zh.contains('的'), "{zh}");
        }
    }

    /// Every `glsl-…` message is the words of a comment line of a shipped shader (none is left
    /// over from a shader that changed), and a language with no words of its own for them
    /// (French) keeps the comments in English.
    #[test]
    fn every_comment_message_is_a_shipped_line_and_french_keeps_english() {
        let shipped: Vec<&str> = pipeline::shader::SHIPPED_VERTEX
            .iter()
            .chain(&pipeline::shader::SHIPPED_FRAGMENT)
            .copied()
            .collect();
        let lines: std::collections::HashSet<&str> = shipped
            .iter()
            .flat_map(|source| {
                lex(source)
                    .into_iter()
                    .filter(|l| l.kind == Kind::Comment)
                    .filter_map(|l| source[l.span].strip_prefix("//").map(str::trim))
            })
            .collect();
        let ids = super::super::lang::english_ids();
        let left_over: Vec<&str> = ids
            .iter()
            .filter(|id| id.starts_with("glsl-"))
            .map(|id| Lang::EN.t(id))
            .filter(|words| !lines.contains(words))
            .collect();
        assert!(left_over.is_empty(), "no shipped line says {left_over:#?}");
        let none = BTreeMap::new();
        for source in &shipped {
            assert_eq!(localize(source, Lang::uncatalogued("fr"), &none), *source);
        }
    }
}
