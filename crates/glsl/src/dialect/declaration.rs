//! What a student's top-level declaration declares: its storage (uniform, texture, input,
//! output), its name and its type, with where they are in the student's text.

use std::ops::Range;

/// What a top-level declaration of the student's declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// `uniform` (not a sampler).
    Uniform,
    /// `uniform sampler2D` or `uniform samplerCube`.
    Texture,
    /// `in` (or `attribute`, or `varying` in a fragment shader).
    Input,
    /// `out` (or `varying` in a vertex shader).
    Output,
}

/// One name a student's declaration declares (`in vec3 a, b;` declares two).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Declaration {
    /// How it is stored.
    pub storage: Storage,
    /// The name as written.
    pub name: String,
    /// The type as written (`vec3`, `Light`), without array brackets.
    pub type_name: String,
    /// Where the whole declaration is in the student's text (bytes).
    pub span: Range<usize>,
    /// Where the name is in the student's text (bytes).
    pub name_span: Range<usize>,
}
