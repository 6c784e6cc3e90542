//! A student's own uniforms: a `uniform` whose name pipelens does not set becomes a control the
//! student drives (a slider for a `float` or an `int`, a checkbox for a `bool`, two numbers for
//! a `vec2`, a colour or three numbers for a `vec3`, a colour with its alpha or four numbers for
//! a `vec4`), its range and first value written in a comment after it on its line:
//!
//! ```glsl
//! uniform float bands;      // 1..8 = 4
//! uniform vec3 tint;        // = 1, 0.5, 0
//! uniform vec4 glaze;       // = 1, 1, 1, 0.5
//! uniform vec2 offset;      // -1..1 = 0.25, 0
//! uniform bool outline;     // = true
//! ```
//!
//! The comment reads `MIN..MAX = VALUE`, either half alone; a vector's value is its components
//! or one number for all of them. Without a value the uniform starts at 0 (GLSL's value for a
//! uniform never set), moved into the range; a `vec3` or `vec4` without a range (or with
//! `0..1`) is a colour, its components in [0, 1].

use crate::dialect::{Declaration, Storage};
use crate::program::Program;

/// The types a uniform of the student's own can have: what a control can set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OwnKind {
    /// `float`: a slider.
    Float,
    /// `int`: a slider in whole steps.
    Int,
    /// `bool`: a checkbox.
    Bool,
    /// `vec2`: two numbers.
    Vec2,
    /// `vec3`: a colour, or three numbers when it has a range other than [0, 1].
    Vec3,
    /// `vec4`: a colour with its alpha, or four numbers when it has a range other than [0, 1].
    Vec4,
}

impl OwnKind {
    /// The kind for a GLSL type, when a control can set it.
    #[must_use]
    pub fn of(glsl: &str) -> Option<Self> {
        match glsl {
            "float" => Some(Self::Float),
            "int" => Some(Self::Int),
            "bool" => Some(Self::Bool),
            "vec2" => Some(Self::Vec2),
            "vec3" => Some(Self::Vec3),
            "vec4" => Some(Self::Vec4),
            _ => None,
        }
    }

    /// Its GLSL type.
    #[must_use]
    pub fn glsl(self) -> &'static str {
        match self {
            Self::Float => "float",
            Self::Int => "int",
            Self::Bool => "bool",
            Self::Vec2 => "vec2",
            Self::Vec3 => "vec3",
            Self::Vec4 => "vec4",
        }
    }

    /// How many numbers its value has.
    #[must_use]
    pub fn components(self) -> usize {
        match self {
            Self::Float | Self::Int | Self::Bool => 1,
            Self::Vec2 => 2,
            Self::Vec3 => 3,
            Self::Vec4 => 4,
        }
    }

    /// Whether it is a vector (`vec2`, `vec3`, `vec4`): its value may be written as one number
    /// for every component.
    #[must_use]
    pub fn vector(self) -> bool {
        self.components() > 1
    }

    /// Whether a value of it can be a colour (`vec3`, `vec4`: RGB, RGBA).
    #[must_use]
    pub fn colour_kind(self) -> bool {
        matches!(self, Self::Vec3 | Self::Vec4)
    }

    /// Its value as the machine's 32-bit words: a float's bits, an int's, a bool's 0 or 1.
    #[must_use]
    pub fn words(self, value: &[f32]) -> Vec<u32> {
        value
            .iter()
            .take(self.components())
            .map(|&x| match self {
                Self::Float | Self::Vec2 | Self::Vec3 | Self::Vec4 => x.to_bits(),
                #[allow(clippy::cast_possible_truncation)]
                Self::Int => (x.round() as i32).cast_unsigned(),
                Self::Bool => u32::from(x != 0.0),
            })
            .collect()
    }
}

/// A uniform of the student's own, as its declaration and comment give it.
#[derive(Clone, Debug, PartialEq)]
pub struct OwnUniform {
    /// Its name.
    pub name: String,
    /// Its type.
    pub kind: OwnKind,
    /// The control's range (a vector's for each component).
    pub range: (f32, f32),
    /// Its first value (a bool's 0 or 1), inside the range.
    pub value: Vec<f32>,
    /// Whether a `vec3` or `vec4` is a colour (RGB, RGBA).
    pub colour: bool,
    /// The line it is declared on, from 1.
    pub line: usize,
}

/// What a control comment says: its range and its value, either left out.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Control {
    /// `MIN..MAX`.
    pub range: Option<(f32, f32)>,
    /// `= VALUE` (a vector's numbers; a bool's `true` as 1).
    pub value: Option<Vec<f32>>,
}

/// Reads a control comment's text (after `//`). `Ok(None)`: an ordinary comment (it does not
/// start like a control: a digit, a sign, `.` or `=`).
///
/// # Errors
/// A comment that starts like a control but is not one, in words.
pub fn control(comment: &str) -> Result<Option<Control>, String> {
    let text = comment.trim();
    if !text.starts_with(|c: char| c.is_ascii_digit() || "+-.=".contains(c)) {
        return Ok(None);
    }
    let (range, value) = match text.split_once('=') {
        Some((r, v)) => (r.trim(), Some(v.trim())),
        None => (text, None),
    };
    let number = |s: &str| {
        s.trim()
            .parse::<f32>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("`{}` is not a number", s.trim()))
    };
    let range = if range.is_empty() {
        None
    } else {
        let (lo, hi) = range
            .split_once("..")
            .ok_or_else(|| format!("`{range}` is not a range MIN..MAX"))?;
        let (lo, hi) = (number(lo)?, number(hi)?);
        if lo >= hi {
            return Err(format!(
                "the range {lo}..{hi} is empty: MIN must be below MAX"
            ));
        }
        Some((lo, hi))
    };
    let value = match value {
        None => None,
        Some("true") => Some(vec![1.0]),
        Some("false") => Some(vec![0.0]),
        Some(v) => Some(
            v.trim_start_matches(['(', '['])
                .trim_end_matches([')', ']'])
                .split(',')
                .map(number)
                .collect::<Result<Vec<f32>, String>>()?,
        ),
    };
    Ok(Some(Control { range, value }))
}

/// The comment after position `end` on its line (`//` to the line's end), if any.
#[must_use]
pub fn comment_after(source: &str, end: usize) -> Option<&str> {
    let rest = source.get(end..)?;
    let line = rest.split('\n').next().unwrap_or_default();
    line.find("//").map(|at| &line[at + 2..])
}

/// The uniform of `kind` declared by `d` in `source`, with its control.
///
/// # Errors
/// Its comment starts like a control and is not one, or gives a value of the wrong length.
pub fn own_uniform(source: &str, d: &Declaration, kind: OwnKind) -> Result<OwnUniform, String> {
    let control = match comment_after(source, d.span.end) {
        Some(c) => control(c)?.unwrap_or_default(),
        None => Control::default(),
    };
    let n = kind.components();
    if let Some(v) = &control.value
        && v.len() != n
        && !(kind.vector() && v.len() == 1)
    {
        return Err(format!(
            "a {} takes {n} number{}, the comment gives {}",
            kind.glsl(),
            if n == 1 { "" } else { "s" },
            v.len()
        ));
    }
    let colour = kind.colour_kind() && control.range.is_none_or(|r| r == (0.0, 1.0));
    let range = control.range.unwrap_or(match kind {
        OwnKind::Int => (0.0, 10.0),
        _ => (0.0, 1.0),
    });
    let mut value = control.value.unwrap_or_else(|| vec![0.0; n]);
    if value.len() < n {
        value = vec![value[0]; n];
    }
    for x in &mut value {
        *x = x.clamp(range.0, range.1);
    }
    Ok(OwnUniform {
        name: d.name.clone(),
        kind,
        range,
        value,
        colour,
        line: crate::error::line_column(source, d.span.start).0,
    })
}

impl Program {
    /// The uniforms of the student's own this program declares, each with its control (a
    /// program that compiled has none whose comment is not a control).
    #[must_use]
    pub fn own_uniforms(&self) -> Vec<OwnUniform> {
        self.declarations
            .iter()
            .filter(|d| {
                d.storage == Storage::Uniform && crate::interface::uniform(&d.name).is_none()
            })
            .filter_map(|d| {
                let kind = OwnKind::of(&d.type_name)?;
                own_uniform(&self.source, d, kind).ok()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_control_comment_gives_range_and_value() {
        assert_eq!(
            control(" 0..4 = 1.5"),
            Ok(Some(Control {
                range: Some((0.0, 4.0)),
                value: Some(vec![1.5])
            }))
        );
        assert_eq!(
            control("= 1, 0.5, 0"),
            Ok(Some(Control {
                range: None,
                value: Some(vec![1.0, 0.5, 0.0])
            }))
        );
        assert_eq!(
            control("-1..1"),
            Ok(Some(Control {
                range: Some((-1.0, 1.0)),
                value: None
            }))
        );
        assert_eq!(
            control("= true"),
            Ok(Some(Control {
                range: None,
                value: Some(vec![1.0])
            }))
        );
        assert_eq!(control(" the tint of the toon bands"), Ok(None));
        assert!(control("4..1").is_err());
        assert!(control("0..x = 1").is_err());
        assert!(control("0.. = 1").is_err());
    }

    #[test]
    fn a_vector_takes_its_components_or_one_number_for_all() {
        assert_eq!(OwnKind::of("vec2"), Some(OwnKind::Vec2));
        assert_eq!(OwnKind::of("vec4"), Some(OwnKind::Vec4));
        assert_eq!(OwnKind::of("mat3"), None);
        assert_eq!(OwnKind::Vec4.components(), 4);
        // 0.5 is 0x3F000000, 1 is 0x3F800000.
        assert_eq!(
            OwnKind::Vec4.words(&[1.0, 0.5, 0.0, 1.0]),
            vec![0x3F80_0000, 0x3F00_0000, 0, 0x3F80_0000]
        );
        assert_eq!(OwnKind::Vec2.words(&[0.5, 0.5]), vec![0x3F00_0000; 2]);
    }

    #[test]
    fn the_comment_is_the_one_on_the_declarations_line() {
        let src = "uniform float k; // 0..2 = 1\nuniform float j;\n// = 3\n";
        assert_eq!(comment_after(src, 16), Some(" 0..2 = 1"));
        assert_eq!(comment_after(src, 45), None);
    }
}
