//! The text pipelens puts before the student's: `#version 450 core`, pipelens' `Light` type,
//! and each declaration the student wrote, declared again in the form naga reads (a texture and
//! its sampler with a binding, an `in` or `out` with a location), each piece with the student's
//! text it stands for.

use std::ops::Range;

use super::declaration::{Declaration, Storage};
use super::names::{SAMPLER_PREFIX, TEXTURE_PREFIX};
use super::scan::Token;
use crate::stage::Stage;

/// The preamble as it is built, with what each of its pieces stands for.
pub(super) struct Preamble {
    pub(super) text: String,
    pub(super) pieces: Vec<(Range<usize>, Range<usize>)>,
    textures: u32,
    /// The next location of a varying or output.
    next_location: u32,
}

impl Preamble {
    pub(super) fn new() -> Self {
        let mut p = Self {
            text: String::new(),
            pieces: Vec::new(),
            textures: 0,
            next_location: 0,
        };
        p.push_generated("#version 450 core\n", 0..0);
        p.push_generated(crate::interface::light_declarations(), 0..0);
        p
    }

    pub(super) fn push_generated(&mut self, text: &str, stands_for: Range<usize>) {
        let start = self.text.len();
        self.text.push_str(text);
        self.pieces.push((start..self.text.len(), stands_for));
    }

    /// `uniform sampler2D name;` (or `samplerCube`) as a texture, a sampler and the define that
    /// joins them.
    pub(super) fn texture(
        &mut self,
        kind: (&str, &str),
        name: &Token,
        span: &Range<usize>,
    ) -> Declaration {
        let (b, n, (sampler, texture)) = (2 * self.textures, &name.text, kind);
        self.textures += 1;
        self.push_generated(
            &format!(
                "layout(set = 1, binding = {b}) uniform {texture} {TEXTURE_PREFIX}{n};\n\
                 layout(set = 1, binding = {}) uniform sampler {SAMPLER_PREFIX}{n};\n\
                 #define {n} {sampler}({TEXTURE_PREFIX}{n}, {SAMPLER_PREFIX}{n})\n",
                b + 1
            ),
            span.clone(),
        );
        Declaration {
            storage: Storage::Texture,
            name: n.clone(),
            type_name: sampler.to_owned(),
            span: span.clone(),
            name_span: name.span.clone(),
        }
    }

    /// An `in` or `out`, declared again with a location. Vertex attributes take their fixed
    /// locations; anything else the next free one.
    pub(super) fn interface(
        &mut self,
        storage: Storage,
        qualifiers: &[&Token],
        ty: &Token,
        name: &Token,
        span: &Range<usize>,
        stage: Stage,
    ) -> Declaration {
        let attribute = (stage == Stage::Vertex && storage == Storage::Input)
            .then(|| super::super::interface::attribute_location(&name.text))
            .flatten();
        let location = attribute.unwrap_or_else(|| {
            let l = self.next_location
                + if stage == Stage::Vertex && storage == Storage::Input {
                    8
                } else {
                    0
                };
            self.next_location += 1;
            l
        });
        let q: Vec<&str> = qualifiers
            .iter()
            .map(|t| t.text.as_str())
            .filter(|q| !q.ends_with('p'))
            .collect();
        let keyword = if storage == Storage::Input {
            "in"
        } else {
            "out"
        };
        self.push_generated(
            &format!(
                "layout(location = {location}) {} {keyword} {} {};\n",
                q.join(" "),
                ty.text,
                name.text
            ),
            name.span.clone(),
        );
        Declaration {
            storage,
            name: name.text.clone(),
            type_name: ty.text.clone(),
            span: span.clone(),
            name_span: name.span.clone(),
        }
    }
}
