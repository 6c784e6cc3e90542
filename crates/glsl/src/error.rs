//! A message about a shader, at the student's line and column, with its mistake as data
//! ([`Complaint`]); where a source stands in a file ([`Origin`]).

use std::fmt;
use std::ops::Range;

use crate::complaint::Complaint;

/// A message about a shader, at its place in the student's source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderError {
    /// Line, from 1.
    pub line: usize,
    /// Column, from 1 (in characters).
    pub column: usize,
    /// The bytes it concerns in the student's source.
    pub span: Range<usize>,
    /// What is wrong, as a sentence (English).
    pub message: String,
    /// The mistake as data, for the interface to say in its language; [`Complaint::Other`]
    /// where only `message` says it.
    pub complaint: Complaint,
}

impl fmt::Display for ShaderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {}, column {}: {}",
            self.line, self.column, self.message
        )
    }
}

/// Where a shader's source stands in a file: a shader file (from its first line and column), or
/// a lesson whose text holds the GLSL (`fragment = """…"""`), from the line and column of the
/// source's first character there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Origin {
    /// The file's name as the lesson's messages write it.
    pub file: String,
    /// The line of the source's first character in the file, from 1.
    pub line: usize,
    /// Its column, from 1 (in characters).
    pub column: usize,
}

impl Origin {
    /// `e`, its line and column moved from the source's own to the file's: the source's line 1
    /// starts at this column, its later lines at the file's column 1. (The file's name goes
    /// with it where the error is said: the pipeline's `RenderError::Code`'s `file`.)
    #[must_use]
    pub fn place(&self, mut e: ShaderError) -> ShaderError {
        if e.line == 1 {
            e.column += self.column - 1;
        }
        e.line += self.line - 1;
        e
    }
}

/// Line and column (from 1, the column in characters) of byte `at` of `src`.
#[must_use]
pub fn line_column(src: &str, at: usize) -> (usize, usize) {
    let at = at.min(src.len());
    let at = (0..=at)
        .rev()
        .find(|&i| src.is_char_boundary(i))
        .unwrap_or(0);
    let before = &src[..at];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// A [`ShaderError`] at `span` of `src`, its line and column worked out.
#[must_use]
pub fn error_at(src: &str, span: Range<usize>, message: impl Into<String>) -> ShaderError {
    let (line, column) = line_column(src, span.start);
    ShaderError {
        line,
        column,
        span,
        message: message.into(),
        complaint: Complaint::Other,
    }
}

/// Where `void main` is, for messages about the whole shader.
pub(crate) fn main_span(source: &str) -> Range<usize> {
    source.find("main").map_or(0..0, |i| i..i + 4)
}
