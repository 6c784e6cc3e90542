//! The stages of the pipeline, in the order data flows through them, and the coordinate spaces
//! of the geometry stages: their names in both languages and what each does, with its formula.

use pipeline::buffers::BufferKind;

use super::Lang;

/// The stages of the pipeline, in the order data flows through them. The default, where the
/// app opens and a lesson starts when no step names a stage, is the world.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Object (model) coordinates.
    Model,
    /// World coordinates, after the model matrix.
    #[default]
    World,
    /// Eye (camera) coordinates, after the view matrix.
    View,
    /// Clip coordinates, after the projection.
    Clip,
    /// Normalized device coordinates, after the perspective division.
    Ndc,
    /// Window coordinates, after the viewport transform.
    Screen,
    /// Rasterization: coverage, primitive ids, barycentrics.
    Raster,
    /// The depth buffer.
    Depth,
    /// Lighting: ambient, diffuse and specular terms, normals.
    Shading,
    /// Texture lookups: uv, level of detail, texel colour.
    Texturing,
    /// The final image.
    Output,
}

impl Stage {
    /// The stage named (in English, any case), for the command line.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|s| s.name(Lang::EN).eq_ignore_ascii_case(name))
    }

    /// Every stage, in order.
    pub const ALL: [Stage; 11] = [
        Self::Model,
        Self::World,
        Self::View,
        Self::Clip,
        Self::Ndc,
        Self::Screen,
        Self::Raster,
        Self::Depth,
        Self::Shading,
        Self::Texturing,
        Self::Output,
    ];

    /// Its name.
    #[must_use]
    pub fn name(self, l: Lang) -> &'static str {
        match self {
            Self::Model => l.t("stage-model"),
            Self::World => l.t("stage-world"),
            Self::View => l.t("stage-view"),
            Self::Clip => l.t("stage-clip"),
            Self::Ndc => l.t("stage-ndc"),
            Self::Screen => l.t("stage-viewport"),
            Self::Raster => l.t("stage-rasterization"),
            Self::Depth => l.t("stage-depth"),
            Self::Shading => l.t("stage-shading"),
            Self::Texturing => l.t("stage-texturing"),
            Self::Output => l.t("stage-output"),
        }
    }

    /// What happens to reach this stage, with its formula (the navigator's tooltip).
    #[must_use]
    pub fn explanation(self, l: Lang) -> &'static str {
        match self {
            Self::Model => l.t("stage-object-coordinates-the-mesh-as"),
            Self::World => l.t("stage-world-coordinates-m-p-with"),
            Self::View => l.t("stage-eye-coordinates-v-m-p"),
            Self::Clip => l.t("stage-clip-coordinates-p-v-m"),
            Self::Ndc => l.t("stage-normalized-device-coordinates-x-y"),
            Self::Screen => l.t("stage-window-coordinates-x-w-x"),
            Self::Raster => l.t("stage-which-samples-each-triangle-covers"),
            Self::Depth => l.t("stage-the-z-buffer-a-fragment"),
            Self::Shading => l.t("stage-lighting-i-k-a-i"),
            Self::Texturing => l.t("stage-texture-lookups-uv-interpolated-log"),
            Self::Output => l.t("stage-the-final-colour-each-pixel"),
        }
    }

    /// The coordinate space a geometry stage shows; `None` for the pixel stages.
    #[must_use]
    pub fn space(self) -> Option<Space> {
        match self {
            Self::Model => Some(Space::Model),
            Self::World => Some(Space::World),
            Self::View => Some(Space::Eye),
            Self::Clip => Some(Space::Clip),
            Self::Ndc => Some(Space::Ndc),
            Self::Screen => Some(Space::Window),
            Self::Raster | Self::Depth | Self::Shading | Self::Texturing | Self::Output => None,
        }
    }

    /// The buffer a pixel stage opens on.
    #[must_use]
    pub fn default_buffer(self) -> BufferKind {
        match self {
            Self::Raster => BufferKind::BaryPerspective,
            Self::Depth => BufferKind::Depth,
            Self::Shading => BufferKind::Diffuse,
            Self::Texturing => BufferKind::MipLevel,
            _ => BufferKind::Color,
        }
    }

    fn index(self) -> usize {
        Self::ALL.iter().position(|s| *s == self).unwrap_or(0)
    }

    /// The next stage (the last stays).
    #[must_use]
    pub fn next(self) -> Self {
        Self::ALL[(self.index() + 1).min(Self::ALL.len() - 1)]
    }

    /// The previous stage (the first stays).
    #[must_use]
    pub fn previous(self) -> Self {
        Self::ALL[self.index().saturating_sub(1)]
    }
}

/// A coordinate space of the vertex table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Space {
    /// Object coordinates.
    Model,
    /// World coordinates.
    World,
    /// Eye coordinates.
    Eye,
    /// Clip coordinates (x, y, z of the homogeneous point).
    Clip,
    /// Normalized device coordinates.
    Ndc,
    /// Window coordinates.
    Window,
}
