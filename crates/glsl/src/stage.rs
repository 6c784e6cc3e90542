//! The two programmable stages a student writes.

/// Which programmable stage a shader is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Runs once per vertex: writes `gl_Position` and the varyings.
    Vertex,
    /// Runs once per fragment: writes the colour, or discards.
    Fragment,
}

impl Stage {
    /// "vertex" or "fragment".
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Vertex => "vertex",
            Self::Fragment => "fragment",
        }
    }
}
