//! The GLSL a student of an OpenGL course writes, adapted to the GLSL naga reads.
//!
//! A student writes `#version 330 core`, plain `uniform vec3 eye;`, `uniform sampler2D tex;`,
//! and `in`/`out` without locations (or GLSL 1.x's `attribute`, `varying` and `gl_FragColor`).
//! naga's GLSL front end reads Vulkan-flavoured GLSL 4.50: uniforms only inside blocks with a
//! binding, textures and samplers apart, every `in` and `out` with a location. This module
//! rewrites the first into the second without moving the student's text:
//!
//! - `#version …` becomes blanks; the adapted source starts with `#version 450 core` and a
//!   *preamble* (pipelens' `Light` type and constants, then what the student declared).
//! - `uniform T name;` keeps its place with `uniform` (and any `layout(…)`) blanked: a plain
//!   global that the host fills before each run, by name ([`crate::Program::set_uniforms`]).
//! - `uniform sampler2D name;` (or `samplerCube`) is blanked and declared in the preamble as a
//!   texture and a sampler, with `#define name sampler2D(texture, sampler)` so that
//!   `texture(name, uv)` reads.
//! - `in`/`out`/`attribute`/`varying` declarations are blanked and declared again in the
//!   preamble with a location (vertex attributes at their fixed locations, see
//!   [`super::interface`]).
//!
//! Blanks keep every byte of the student's text at its offset plus the preamble's length, so a
//! message of naga's maps back to the student's line and column ([`Adapted::original_offset`]);
//! a message about a declaration that moved into the preamble maps to that declaration.

use std::ops::Range;

mod declaration;
mod names;
mod preamble;
mod sampler_arguments;
mod scan;

pub use declaration::{Declaration, Storage};
pub use names::{FRAG_COLOR, SAMPLER_PREFIX, TEXTURE_PREFIX};
pub(crate) use scan::version_directive;

use crate::stage::Stage;
use names::sampler_kind;
use preamble::Preamble;
use scan::{Token, top_level};

/// The student's source adapted for naga, with the map back to the student's text.
#[derive(Clone, Debug)]
pub struct Adapted {
    /// What naga reads: the preamble, then the student's text with declarations blanked.
    pub text: String,
    /// Length in bytes of the preamble: student byte `b` is at `preamble_len + b`, but for the
    /// forms rewritten for naga (the `lowering` module).
    pub preamble_len: usize,
    /// The rewrites of the student's text after the preamble, pass by pass in the order they
    /// were made (each pass's edits in the text the pass before it wrote).
    edits: Vec<Vec<super::lowering::Edit>>,
    /// The insertions made after naga first read the text ([`super::modulo`]), in the text
    /// after the preamble, applied after [`Self::edits`].
    pub(super) splats: Vec<super::lowering::Edit>,
    /// For each piece of the preamble, the student's text it stands for.
    pieces: Vec<(Range<usize>, Range<usize>)>,
    /// The declarations the student wrote, in order.
    pub declarations: Vec<Declaration>,
}

/// A mistake in the student's declarations found before naga reads the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DialectError {
    /// Where, in the student's text (bytes).
    pub span: Range<usize>,
    /// What is wrong, as a sentence.
    pub message: String,
}

impl Adapted {
    /// The student's byte offset that naga's offset `at` (in [`Self::text`]) stands for.
    #[must_use]
    pub fn original_offset(&self, at: usize) -> usize {
        if at >= self.preamble_len {
            let at = super::lowering::before_edits(&self.splats, at - self.preamble_len);
            return self
                .edits
                .iter()
                .rev()
                .fold(at, |at, pass| super::lowering::before_edits(pass, at));
        }
        self.pieces
            .iter()
            .find(|(adapted, _)| adapted.contains(&at))
            .map_or(0, |(_, original)| original.start)
    }

    /// The student's range that naga's span `span` stands for.
    #[must_use]
    pub fn original_range(&self, span: Range<usize>) -> Range<usize> {
        let start = self.original_offset(span.start);
        if span.start < self.preamble_len {
            let piece = self.pieces.iter().find(|(a, _)| a.contains(&span.start));
            return piece.map_or(start..start, |(_, o)| o.clone());
        }
        start..self.original_offset(span.end.max(span.start)).max(start)
    }
}

/// The types an `in` or `out` may have.
const VARYING_TYPES: [&str; 15] = [
    "float", "int", "uint", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3",
    "uvec4", "mat2", "mat3", "mat4",
];

/// A mistake in the type of an `in` or `out`: one it cannot have (a misspelt type, which naga
/// would only call "not implemented").
fn varying_type_error(ty: &Token, storage: Storage) -> Option<DialectError> {
    if VARYING_TYPES.contains(&ty.text.as_str()) {
        return None;
    }
    let keyword = if storage == Storage::Input {
        "in"
    } else {
        "out"
    };
    Some(DialectError {
        span: ty.span.clone(),
        message: format!(
            "`{}` is not a type an `{keyword}` can have: float, int, uint, vec2–4, ivec2–4, uvec2–4, mat2–4{}",
            ty.text,
            crate::suggest::did_you_mean(&ty.text, VARYING_TYPES, crate::suggest::Quote::Code)
        ),
    })
}

/// Qualifiers that may stand before the type of an `in` or `out`.
const INTERPOLATION: [&str; 6] = [
    "flat",
    "noperspective",
    "smooth",
    "centroid",
    "highp",
    "mediump",
];

/// Adapts the student's `src` for naga (see the module's documentation).
///
/// # Errors
/// Adapts `src` for naga; `extra` is GLSL of pipelens' own put at the end of the preamble
/// (a watch's declarations, `crate::probe`), empty for the student's code as written.
///
/// # Errors
/// A declaration pipelens cannot adapt: a `uniform` block, an `in` or `out` it cannot read.
pub fn adapt(src: &str, stage: Stage, extra: &str) -> Result<Adapted, Vec<DialectError>> {
    let (statements, version) = top_level(src);
    let mut blanks: Vec<Range<usize>> = version.into_iter().collect();
    let mut declarations = Vec::new();
    let mut errors = Vec::new();
    let mut preamble = Preamble::new();
    for (tokens, end) in &statements {
        let Some(first) = tokens.first() else {
            continue;
        };
        let span = first.span.start..*end;
        // Layout qualifiers are pipelens' to choose: skip them.
        let (layout, rest) = split_layout(tokens);
        // `flat in vec3 c;`: interpolation qualifiers may come first.
        let q = rest
            .iter()
            .position(|t| !INTERPOLATION.contains(&t.text.as_str()))
            .unwrap_or(0);
        let (qualifiers, rest) = rest.split_at(q);
        let Some(keyword) = rest.first() else {
            continue;
        };
        let storage = match (keyword.text.as_str(), stage) {
            ("uniform", _) => Storage::Uniform,
            ("in" | "attribute", _) | ("varying", Stage::Fragment) => Storage::Input,
            ("out", _) | ("varying", Stage::Vertex) => Storage::Output,
            _ => continue,
        };
        let after = &rest[1..];
        if storage == Storage::Uniform {
            if after.iter().any(|t| t.text == "{") {
                errors.push(DialectError {
                    span: span.clone(),
                    message: "a uniform block: declare each uniform on its own, \
                              `uniform vec3 eye;` (pipelens sets them by name)"
                        .to_owned(),
                });
                continue;
            }
            let names = declared_names(after, &span, &mut errors);
            if let Some(kind) = names.first().and_then(|(ty, _)| sampler_kind(&ty.text)) {
                for (_, name) in &names {
                    declarations.push(preamble.texture(kind, name, &span));
                }
                blanks.push(span.clone());
            } else {
                // Keep the declaration where it is, as a plain global: blank `uniform` and layout.
                blanks.push(keyword.span.clone());
                if let Some(layout) = layout {
                    blanks.push(layout);
                }
                for (ty, name) in names {
                    declarations.push(Declaration {
                        storage,
                        name: name.text.clone(),
                        type_name: ty.text.clone(),
                        span: span.clone(),
                        name_span: name.span.clone(),
                    });
                }
            }
            continue;
        }
        let qualifiers: Vec<&Token> = qualifiers.iter().collect();
        for (ty, name) in declared_names(after, &span, &mut errors) {
            if let Some(e) = varying_type_error(ty, storage) {
                errors.push(e);
                continue;
            }
            declarations.push(preamble.interface(storage, &qualifiers, ty, name, &span, stage));
        }
        blanks.push(span);
    }
    if stage == Stage::Fragment
        && !declarations.iter().any(|d| d.storage == Storage::Output)
        && contains_word(src, "gl_FragColor")
    {
        preamble.push_generated(
            &format!(
                "layout(location = 0) out vec4 {FRAG_COLOR};\n#define gl_FragColor {FRAG_COLOR}\n"
            ),
            0..0,
        );
    }
    for glsl in super::glsl330::written_in_glsl(src) {
        preamble.push_generated(glsl, 0..0);
    }
    if sampler_arguments::any(src) {
        preamble.push_generated(
            &format!(
                "layout(set = 2, binding = 0) uniform sampler {};\n",
                sampler_arguments::PARAMETER_SAMPLER
            ),
            0..0,
        );
    }
    if !extra.is_empty() {
        preamble.push_generated(extra, 0..0);
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    Ok(assemble(src, &blanks, preamble, declarations))
}

/// What naga reads: the preamble, then the student's text with `blanks` blanked and the forms
/// naga refuses rewritten.
fn assemble(
    src: &str,
    blanks: &[Range<usize>],
    preamble: Preamble,
    declarations: Vec<Declaration>,
) -> Adapted {
    let mut student = src.as_bytes().to_vec();
    for r in blanks {
        for b in &mut student[r.clone()] {
            if *b != b'\n' {
                *b = b' ';
            }
        }
    }
    // Blanking replaces whole declarations and ASCII keywords, so the text stays UTF-8.
    let student = super::lowering::legacy_texture_calls(&String::from_utf8_lossy(&student));
    let student = super::lowering::parameter_qualifiers(&student);
    // Valid GLSL naga refuses, rewritten: samplers passed to functions, stores through a
    // swizzle of an indexed value.
    let textures: Vec<String> = declarations
        .iter()
        .filter(|d| d.storage == Storage::Texture)
        .map(|d| d.name.clone())
        .collect();
    let (student, passed) = sampler_arguments::rewrite(&student, &textures);
    let (student, swizzled) = super::lowering::swizzle_stores(&student);
    let preamble_len = preamble.text.len();
    Adapted {
        text: preamble.text + &student,
        preamble_len,
        edits: vec![passed, swizzled],
        splats: Vec::new(),
        pieces: preamble.pieces,
        declarations,
    }
}

/// Whether `word` stands in `src` as a whole word.
fn contains_word(src: &str, word: &str) -> bool {
    src.match_indices(word).any(|(i, _)| {
        let before = src[..i].chars().next_back();
        let after = src[i + word.len()..].chars().next();
        let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
        !ident(before) && !ident(after)
    })
}

/// Splits a leading `layout(…)` off a declaration's tokens: its span, and the rest.
fn split_layout(tokens: &[Token]) -> (Option<Range<usize>>, &[Token]) {
    if tokens.first().is_some_and(|t| t.text == "layout")
        && tokens.get(1).is_some_and(|t| t.text == "(")
        && let Some(close) = tokens.iter().position(|t| t.text == ")")
    {
        return (
            Some(tokens[0].span.start..tokens[close].span.end),
            &tokens[close + 1..],
        );
    }
    (None, tokens)
}

/// The type and the names of `T a, b[3], c;` (tokens after the storage keyword, precision words
/// skipped).
fn declared_names<'t>(
    tokens: &'t [Token],
    span: &Range<usize>,
    errors: &mut Vec<DialectError>,
) -> Vec<(&'t Token, &'t Token)> {
    let tokens: Vec<&Token> = tokens
        .iter()
        .filter(|t| !INTERPOLATION[4..].contains(&t.text.as_str()) && t.text != "lowp")
        .collect();
    let Some(ty) = tokens.first() else {
        errors.push(DialectError {
            span: span.clone(),
            message: "a declaration without a type and a name".to_owned(),
        });
        return Vec::new();
    };
    let mut names = Vec::new();
    let mut expect_name = true;
    let mut bracket = 0;
    for t in &tokens[1..] {
        match t.text.as_str() {
            "[" => bracket += 1,
            "]" => bracket -= 1,
            "," if bracket == 0 => expect_name = true,
            _ if expect_name && bracket == 0 => {
                if t.text
                    .starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
                {
                    names.push((*ty, *t));
                } else {
                    errors.push(DialectError {
                        span: t.span.clone(),
                        message: format!("expected a name after `{}`, found `{}`", ty.text, t.text),
                    });
                }
                expect_name = false;
            }
            _ => {}
        }
    }
    if names.is_empty() && errors.is_empty() {
        errors.push(DialectError {
            span: span.clone(),
            message: format!("`{}` declares no name", ty.text),
        });
    }
    names
}
