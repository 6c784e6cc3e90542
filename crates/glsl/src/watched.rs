//! What a watch saw, as data: the type of the watched expression, where a watched program keeps
//! its value among the invocations' globals, and each invocation's value read from there (the
//! watch itself is made in `crate::probe`).

use crate::lanes::LANES;
use crate::register_form::Reg;

/// The global the watch stores its value into (its store is kept out of the trace).
pub(crate) const WATCH: &str = "pipelens_watch";

/// The type of a watched value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WatchKind {
    /// `float`.
    Float,
    /// `vec2`.
    Vec2,
    /// `vec3`.
    Vec3,
    /// `vec4`.
    Vec4,
    /// `int` (or `uint`).
    Int,
    /// `bool`: a mask.
    Bool,
}

impl WatchKind {
    /// Its code in the watch's globals, as the overload for it stores it (from 1; 0: the line
    /// never ran).
    const ALL: [Self; 6] = [
        Self::Float,
        Self::Vec2,
        Self::Vec3,
        Self::Vec4,
        Self::Int,
        Self::Bool,
    ];

    /// How many of the `vec4`'s components hold the value.
    #[must_use]
    pub fn components(self) -> usize {
        match self {
            Self::Float | Self::Int | Self::Bool => 1,
            Self::Vec2 => 2,
            Self::Vec3 => 3,
            Self::Vec4 => 4,
        }
    }

    /// Its GLSL type.
    #[must_use]
    pub fn glsl(self) -> &'static str {
        match self {
            Self::Float => "float",
            Self::Vec2 => "vec2",
            Self::Vec3 => "vec3",
            Self::Vec4 => "vec4",
            Self::Int => "int",
            Self::Bool => "bool",
        }
    }
}

/// Where a watched program keeps what it saw: the value and its type's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WatchPlaces {
    value: Reg,
    kind: Reg,
    /// The line watched, from 1.
    pub line: usize,
    /// The expression watched, as typed.
    pub expression: String,
}

/// What one invocation's watch saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Watched {
    /// The value's type.
    pub kind: WatchKind,
    /// The value (its first [`WatchKind::components`] components; a bool is 0 or 1).
    pub value: [f32; 4],
}

impl WatchPlaces {
    /// The places of a program watching `expression` after `line`.
    pub(crate) fn new(value: Reg, kind: Reg, line: usize, expression: &str) -> Self {
        Self {
            value,
            kind,
            line,
            expression: expression.to_owned(),
        }
    }

    /// What lane `lane` saw, read from the invocations' globals (`LANES` values a component):
    /// `None` when it never ran the line.
    #[must_use]
    pub(crate) fn read(&self, privates: &[u32], lane: usize) -> Option<Watched> {
        let at = |reg: &Reg, c: u32| {
            privates
                .get((reg.first + c) as usize * LANES + lane)
                .map_or(0.0, |b| f32::from_bits(*b))
        };
        let code = at(&self.kind, 0);
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let kind = *WatchKind::ALL.get((code as usize).checked_sub(1)?)?;
        Some(Watched {
            kind,
            value: std::array::from_fn(|c| at(&self.value, c as u32)),
        })
    }
}
