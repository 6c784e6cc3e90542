//! Forms of GLSL that naga's front end refuses, rewritten into forms it reads before it reads
//! them. Assigning through a swizzle of an indexed value — a matrix column (`m[1].w = …`,
//! `to_light[3].xyz = -light;`) or an array element (`r[0].xy = …`) — is valid GLSL that the
//! course writes, and naga answers "Can't lookup field on this type". It becomes:
//!
//! - one component: `m[1].w = e;` → `m[1][3] = e;` (the component by its index);
//! - several: `a[i].xyz = e;` → `{ vec3 pl_swizzle = e; a[i][0] = pl_swizzle.x; … }`, each
//!   component stored by index from a temporary of the swizzle's size (a float vector: the
//!   columns of a matrix and the vectors the course indexes are float).
//!
//! Each rewrite is an [`Edit`], so that a message about the rewritten text maps back to the
//! student's (see [`super::dialect::Adapted::original_offset`]).
//!
//! GLSL 1.20's texture functions (`texture2D(s, uv)`, which drivers still take in `#version 330
//! core`) are renamed to GLSL 1.30's (`texture`), padded to the same length: naga would read
//! `texture2D(…)` as a constructor of its own `texture2D` type.
//!
//! A parameter's qualifiers naga refuses (`const in float v`, `in highp float v`) are blanked to
//! the form it reads (`const float v`), each byte kept in its place.

use std::ops::Range;

/// One rewrite: the student's bytes `old` became the bytes `new` of the rewritten text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edit {
    /// Where the rewrite is in the rewritten text.
    pub new: Range<usize>,
    /// What it replaced in the text before.
    pub old: Range<usize>,
}

/// The offset in the text before the edits that offset `at` of the rewritten text stands for:
/// inside an edit, the start of what it replaced; elsewhere, `at` shifted by the edits before.
#[must_use]
pub fn before_edits(edits: &[Edit], at: usize) -> usize {
    let mut shift: isize = 0;
    for e in edits {
        if at < e.new.start {
            break;
        }
        if at < e.new.end {
            return e.old.start;
        }
        shift = e.old.end as isize - e.new.end as isize;
    }
    (at as isize + shift).max(0) as usize
}

/// The components a swizzle letter stands for, in one of GLSL's three sets.
fn component(c: u8) -> Option<usize> {
    [b"xyzw", b"rgba", b"stpq"]
        .iter()
        .find_map(|set| set.iter().position(|&s| s == c))
}

/// Whether `c` may continue a name.
fn word(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// `text` with every store through a swizzle of an indexed value rewritten, and the edits.
#[must_use]
pub fn swizzle_stores(text: &str) -> (String, Vec<Edit>) {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut edits = Vec::new();
    let mut copied = 0;
    let mut i = 0;
    let mut depth = 0_i32; // parentheses
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                i = text[i..].find('\n').map_or(b.len(), |n| i + n);
                continue;
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                i = text[i + 2..].find("*/").map_or(b.len(), |n| i + 2 + n + 2);
                continue;
            }
            b'(' => depth += 1,
            b')' => depth -= 1,
            _ => {}
        }
        let Some(store) = (b[i] == b']')
            .then(|| swizzle_store(text, i, depth))
            .flatten()
        else {
            i += 1;
            continue;
        };
        out.push_str(&text[copied..store.replace.start]);
        let start = out.len();
        out.push_str(&store.with);
        edits.push(Edit {
            new: start..out.len(),
            old: store.replace.clone(),
        });
        copied = store.replace.end;
        i = store.replace.end;
    }
    out.push_str(&text[copied..]);
    (out, edits)
}

/// A store found: the bytes to replace and their replacement.
struct Store {
    replace: Range<usize>,
    with: String,
}

/// The store through a swizzle whose indexed value ends with the `]` at `close`, if one
/// follows it (`].xyz = …;`, `].w += …;`). Several components are rewritten only where the
/// statement stands on its own (not inside parentheses).
fn swizzle_store(text: &str, close: usize, depth: i32) -> Option<Store> {
    let b = text.as_bytes();
    if b.get(close + 1) != Some(&b'.') {
        return None;
    }
    let swz_start = close + 2;
    let swz_end = (swz_start..b.len())
        .find(|&k| !word(b[k]))
        .unwrap_or(b.len());
    let swizzle = &b[swz_start..swz_end];
    let components: Vec<usize> = swizzle
        .iter()
        .map(|&c| component(c))
        .collect::<Option<_>>()?;
    if components.is_empty() || components.len() > 4 {
        return None;
    }
    // The assignment operator after it.
    let mut k = swz_end;
    while k < b.len() && b[k].is_ascii_whitespace() {
        k += 1;
    }
    let op_len = match (b.get(k), b.get(k + 1)) {
        (Some(b'='), Some(b'=')) => return None,
        (Some(b'='), _) => 1,
        (Some(b'+' | b'-' | b'*' | b'/'), Some(b'=')) => 2,
        _ => return None,
    };
    let op = &text[k..k + op_len];
    if components.len() == 1 {
        return Some(Store {
            replace: close + 1..swz_end,
            with: format!("[{}]", components[0]),
        });
    }
    if depth != 0 {
        return None;
    }
    let lhs_start = indexed_start(b, close)?;
    // The value: to the `;` that ends the statement, outside any parentheses or brackets.
    let value_start = k + op_len;
    let mut nest = 0_i32;
    let end = (value_start..b.len()).find(|&j| {
        match b[j] {
            b'(' | b'[' | b'{' => nest += 1,
            b')' | b']' | b'}' => nest -= 1,
            _ => {}
        }
        b[j] == b';' && nest == 0
    })?;
    let lhs = &text[lhs_start..=close];
    let value = text[value_start..end].trim();
    let names = [b'x', b'y', b'z', b'w'];
    let mut with = format!("{{ vec{} pl_swizzle = {value};", components.len());
    for (n, c) in components.iter().enumerate() {
        with.push_str(&format!(
            " {lhs}[{c}] {op} pl_swizzle.{};",
            names[n] as char
        ));
    }
    with.push_str(" }");
    Some(Store {
        replace: lhs_start..end + 1,
        with,
    })
}

/// Where the indexed value ending with the `]` at `close` starts: back over `[…]` groups, a
/// name, and `.`-joined members (`lights[i].m[2]`).
fn indexed_start(b: &[u8], close: usize) -> Option<usize> {
    let mut at = close + 1;
    loop {
        // `[…]` groups.
        while at > 0 && b[at - 1] == b']' {
            let mut nest = 0;
            let mut j = at - 1;
            loop {
                match b[j] {
                    b']' => nest += 1,
                    b'[' => {
                        nest -= 1;
                        if nest == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                j = j.checked_sub(1)?;
            }
            at = j;
        }
        // A name.
        let end = at;
        while at > 0 && word(b[at - 1]) {
            at -= 1;
        }
        if at == end || b[at].is_ascii_digit() {
            return None;
        }
        if at > 0 && b[at - 1] == b'.' {
            at -= 1;
            continue;
        }
        return Some(at);
    }
}

/// GLSL 1.20's texture functions, which GLSL 1.30 renamed (OpenGL drivers still take the old
/// names), and the names naga reads: `texture2D(s, uv)` is `texture(s, uv)`.
const LEGACY_TEXTURE: [(&str, &str); 6] = [
    ("texture2D", "texture"),
    ("texture2DLod", "textureLod"),
    ("texture2DProj", "textureProj"),
    ("texture2DProjLod", "textureProjLod"),
    ("textureCube", "texture"),
    ("textureCubeLod", "textureLod"),
];

/// `src` with each call of a GLSL 1.20 texture function renamed to its GLSL 1.30 name, padded
/// with spaces to the old name's length so that every byte keeps its offset (naga would read
/// `texture2D(…)` as a constructor of its `texture2D` type).
pub(super) fn legacy_texture_calls(src: &str) -> String {
    let mut out = src.to_owned();
    for l in super::lexeme::calls(src) {
        if let Some(&(old, new)) = LEGACY_TEXTURE
            .iter()
            .find(|(old, _)| src[l.span.clone()] == **old)
        {
            out.replace_range(l.span, &format!("{new:<width$}", width = old.len()));
        }
    }
    out
}

/// The words blanked in a function's parameter list, which naga's front end refuses there:
/// GLSL's precision qualifiers (no effect in desktop GLSL 3.30, §4.5.2).
const PRECISION: [&str; 3] = ["highp", "mediump", "lowp"];

/// `src` with the parameter qualifiers naga refuses blanked, each byte kept in its place:
/// `const in float v` and `in const float v` become `const float v` (the same read-only `in`
/// parameter, GLSL 3.30 §6.1.1), and a precision qualifier (`in highp float v`) is dropped. A
/// parameter list is a parenthesis outside every brace: a function's header.
pub(super) fn parameter_qualifiers(src: &str) -> String {
    use super::lexeme::{Kind, lex};
    let code: Vec<_> = lex(src)
        .into_iter()
        .filter(|l| !matches!(l.kind, Kind::Comment | Kind::Space))
        .collect();
    let text = |k: usize| code.get(k).map_or("", |l| &src[l.span.clone()]);
    let mut out = src.to_owned();
    let (mut braces, mut parens) = (0i32, 0i32);
    for (k, l) in code.iter().enumerate() {
        match text(k) {
            "{" => braces += 1,
            "}" => braces -= 1,
            "(" => parens += 1,
            ")" => parens -= 1,
            word if braces == 0 && parens > 0 && l.kind == Kind::Word => {
                let blank = PRECISION.contains(&word)
                    || (word == "in"
                        && (text(k + 1) == "const" || text(k.wrapping_sub(1)) == "const"));
                if blank {
                    out.replace_range(l.span.clone(), &" ".repeat(l.span.len()));
                }
            }
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stores_through_a_swizzle_of_an_indexed_value_are_rewritten() {
        let (text, edits) = swizzle_stores("    m[1].w = -1.0 / l.y;\n");
        assert_eq!(text, "    m[1][3] = -1.0 / l.y;\n");
        assert_eq!(edits.len(), 1);
        let (text, _) = swizzle_stores("t[3].xyz = -light;");
        assert_eq!(
            text,
            "{ vec3 pl_swizzle = -light; t[3][0] = pl_swizzle.x; t[3][1] = pl_swizzle.y; t[3][2] = pl_swizzle.z; }"
        );
        let (text, _) = swizzle_stores("s.r[i + 1].gb += f(a, b);");
        assert_eq!(
            text,
            "{ vec2 pl_swizzle = f(a, b); s.r[i + 1][1] += pl_swizzle.x; s.r[i + 1][2] += pl_swizzle.y; }"
        );
        // Reading, comparing, and comments are left alone.
        for same in [
            "x = m[1].xyz;",
            "if (v[0].x == 1.0) {}",
            "// m[1].xy = v;",
            "a.xy = v;",
        ] {
            assert_eq!(swizzle_stores(same).0, same);
        }
    }

    /// Offsets after an edit shift by what it added; inside it, they stand for its start.
    #[test]
    fn offsets_map_back_through_the_edits() {
        let src = "m[1].w = 1.0; bad";
        let (text, edits) = swizzle_stores(src);
        let bad = text.find("bad").expect("bad");
        assert_eq!(before_edits(&edits, bad), src.find("bad").expect("bad"));
        assert_eq!(before_edits(&edits, 2), 2);
        assert_eq!(before_edits(&edits, 5), 4);
    }
}
