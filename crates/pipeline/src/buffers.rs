//! The per-pixel buffers a frame can show ([`BufferKind`], with each one's colour mapping) and
//! which of them a frame keeps ([`Capture`]), with what each costs in memory. The render settings
//! refer to it; the capture holds the buffers.

use serde::Serialize;

/// Which image of a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BufferKind {
    /// The final colour, 8 bits per channel = round(255·c), no gamma conversion.
    Color,
    /// Window depth as grey, stretched from the nearest (black) to the farthest (white) depth
    /// present; background white.
    Depth,
    /// Covered samples / samples per pixel as grey (black: none, white: all).
    Coverage,
    /// Each primitive id in its own hue (golden-ratio hue steps); background black.
    PrimitiveId,
    /// Perspective-correct barycentrics `(b0, b1, b2)` as `(R, G, B)`; background black.
    BaryPerspective,
    /// Affine barycentrics `(λ0, λ1, λ2)` as `(R, G, B)`; background black.
    BaryAffine,
    /// The ambient term, 8 bits per channel; background black.
    Ambient,
    /// The diffuse term.
    Diffuse,
    /// The specular term.
    Specular,
    /// The normal used for lighting, `(n + 1)/2` as RGB.
    Normal,
    /// `max(n·l, 0)` of the key light as grey.
    NDotL,
    /// `max(n·h, 0)` (or `r·v`) of the key light as grey.
    NDotH,
    /// Texture coordinates `(fract u, fract v)` as red and green.
    Uv,
    /// The mip level read, each level in its own colour (blended for trilinear).
    MipLevel,
    /// The filtered texel colour.
    Texel,
    /// The footprint of the pixel in the texture: hue the direction of its long axis,
    /// saturation its anisotropy.
    Footprint,
    /// The environment map's reflected term.
    Reflected,
}

impl BufferKind {
    /// Every 8-bit image kind, in the order of the stages.
    pub const ALL: [BufferKind; 17] = [
        Self::Coverage,
        Self::PrimitiveId,
        Self::Depth,
        Self::BaryPerspective,
        Self::BaryAffine,
        Self::Normal,
        Self::NDotL,
        Self::NDotH,
        Self::Uv,
        Self::MipLevel,
        Self::Footprint,
        Self::Texel,
        Self::Ambient,
        Self::Diffuse,
        Self::Specular,
        Self::Reflected,
        Self::Color,
    ];

    /// Whether the buffer holds a lighting term (present only when lighting is on).
    #[must_use]
    pub fn is_lighting(self) -> bool {
        matches!(
            self,
            Self::Ambient
                | Self::Diffuse
                | Self::Specular
                | Self::Normal
                | Self::NDotL
                | Self::NDotH
                | Self::Reflected
        )
    }

    /// Whether the buffer holds a texture lookup (present only when an object is textured).
    #[must_use]
    pub fn is_texturing(self) -> bool {
        matches!(
            self,
            Self::Uv | Self::MipLevel | Self::Texel | Self::Footprint
        )
    }

    /// A file-name friendly name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Color => "color",
            Self::Depth => "depth",
            Self::Coverage => "coverage",
            Self::PrimitiveId => "primitive_id",
            Self::BaryPerspective => "bary_perspective",
            Self::BaryAffine => "bary_affine",
            Self::Ambient => "ambient",
            Self::Diffuse => "diffuse",
            Self::Specular => "specular",
            Self::Normal => "normal",
            Self::NDotL => "n_dot_l",
            Self::NDotH => "n_dot_h",
            Self::Uv => "uv",
            Self::MipLevel => "mip_level",
            Self::Texel => "texel",
            Self::Footprint => "footprint",
            Self::Reflected => "reflected",
        }
    }

    /// How the buffer's values become colours (for documentation and the capture's JSON).
    #[must_use]
    pub fn mapping(self) -> &'static str {
        match self {
            Self::Color => "RGB = round(255·colour), no gamma conversion",
            Self::Depth => {
                "grey = 255·(z_w − z_min)/(z_max − z_min) over covered pixels (depth_range); \
                 background white"
            }
            Self::Coverage => "grey = 255·covered samples/samples per pixel",
            Self::PrimitiveId => {
                "hue = fract(id·0.618034), full saturation and value; background black"
            }
            Self::BaryPerspective => {
                "RGB = 255·(b0, b1, b2), perspective-correct; background black"
            }
            Self::BaryAffine => "RGB = 255·(λ0, λ1, λ2), screen-space; background black",
            Self::Ambient => "RGB = round(255·Σ k_a·I_a), clamped; background black",
            Self::Diffuse => {
                "RGB = round(255·Σ f_att·k_d·I_d·max(l·n, 0)), clamped; background black"
            }
            Self::Specular => {
                "RGB = round(255·Σ f_att·k_s·I_s·max(n·h, 0)^β) (or (r·v)^α), clamped; background black"
            }
            Self::Normal => "RGB = 255·(n + 1)/2 of the unit world-space normal; background black",
            Self::NDotL => "grey = 255·max(n·l, 0) of the key light; background black",
            Self::NDotH => {
                "grey = 255·max(n·h, 0) (Blinn-Phong) or max(r·v, 0) (Phong); background black"
            }
            Self::Uv => {
                "RGB = 255·(fract u, fract v, 0); untextured surfaces dark grey (48, 48, 56); background black"
            }
            Self::MipLevel => {
                "level k in colour k (0 white, 1 red, 2 orange, 3 yellow, 4 green, 5 cyan, 6 blue, \
                 7+ violet), trilinear blends the two; untextured surfaces dark grey; background black"
            }
            Self::Texel => {
                "RGB = round(255·filtered texel); untextured surfaces dark grey (48, 48, 56); background black"
            }
            Self::Footprint => {
                "hue = direction of the footprint's long axis in the texture (0°–180°: red along s, \
                 cyan along t), saturation = min(log₂(major/minor)/3, 1): white isotropic, \
                 saturated ≥ 8:1; untextured surfaces dark grey; background black"
            }
            Self::Reflected => {
                "RGB = round(255·k·C_env(r)), r = 2(n·v)n − v, for mirror objects; black elsewhere"
            }
        }
    }
}

/// Which per-pixel buffers a frame keeps. The colour, coverage, depth and owner of each pixel
/// (and from the owner its barycentrics) are always kept; the lighting terms and the texture
/// lookups are computed for the colour in any case but stored only when asked for, so a view
/// that shows only the final image does not pay for writing them (about 60 of a full capture's
/// 85 bytes a pixel). One pixel's terms and lookup can be kept without their buffers: the
/// inspected pixel of a draft.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Capture {
    /// Keep the lighting terms (ambient, diffuse, specular, normal, n·l, n·h, reflected), when
    /// lighting is on.
    pub lighting: bool,
    /// Keep the texture lookups (uv, λ, level, texel, footprint), when an object is textured.
    pub texturing: bool,
    /// A window pixel `(x, y)` (y up) whose lighting terms and texture lookup are kept even
    /// where their buffers are not, and which coarse shading shades by itself (its shading no
    /// other pixel takes): the inspected pixel, whose explanation derives its colour from its
    /// own records and must land on it.
    pub pixel: Option<(u32, u32)>,
    /// Keep, at each pixel, the steps the student's fragment shader ran there (of the
    /// fragment covering the most of its samples): the debugger's cost view.
    pub cost: bool,
}

impl Capture {
    /// Every buffer: what exports write and the inspector reads.
    pub const FULL: Self = Self {
        lighting: true,
        texturing: true,
        pixel: None,
        cost: false,
    };
    /// The colour, coverage, depth and owner only.
    pub const COLOR: Self = Self {
        lighting: false,
        texturing: false,
        pixel: None,
        cost: false,
    };

    /// What showing `kinds` needs.
    #[must_use]
    pub fn showing(kinds: impl IntoIterator<Item = BufferKind>) -> Self {
        kinds.into_iter().fold(Self::COLOR, |c, k| Self {
            lighting: c.lighting || k.is_lighting(),
            texturing: c.texturing || k.is_texturing(),
            ..c
        })
    }

    /// This selection, keeping pixel `at`'s terms and lookup too.
    #[must_use]
    pub fn with_pixel(self, at: Option<(u32, u32)>) -> Self {
        Self { pixel: at, ..self }
    }

    /// Whether this selection keeps everything `other` keeps: its buffers, the cost view, and
    /// its pixel's terms (kept by every buffer or by the same pixel).
    #[must_use]
    pub fn covers(self, other: Self) -> bool {
        let pixel =
            other.pixel.is_none() || self.pixel == other.pixel || (self.lighting && self.texturing);
        (self.lighting || !other.lighting)
            && (self.texturing || !other.texturing)
            && (self.cost || !other.cost)
            && pixel
    }

    /// Whether `kind` is kept.
    #[must_use]
    pub fn keeps(self, kind: BufferKind) -> bool {
        (self.lighting || !kind.is_lighting()) && (self.texturing || !kind.is_texturing())
    }

    /// The bytes a pixel takes with this selection, at most (see [`CAPTURE_BYTES_PER_PIXEL`]).
    #[must_use]
    pub fn bytes_per_pixel(self) -> u64 {
        CORE_BYTES_PER_PIXEL
            + if self.lighting {
                LIGHTING_BYTES_PER_PIXEL
            } else {
                0
            }
            + if self.texturing {
                TEXTURING_BYTES_PER_PIXEL
            } else {
                0
            }
    }
}

impl Default for Capture {
    fn default() -> Self {
        Self::FULL
    }
}

/// Bytes per pixel of the buffers always kept: coverage 1, depth 4, primitive 4, owner 4 and
/// the colour 3·4 = 12 (32-bit floats); the barycentrics are derived from the owner.
pub const CORE_BYTES_PER_PIXEL: u64 = 25;
/// Bytes per pixel of the lighting buffers, kept as half floats (11 significant bits, as a
/// GPU's RGBA16F G-buffer): ambient, diffuse, specular, normal, reflected 5·3·2, n·l and n·h 2·2.
pub const LIGHTING_BYTES_PER_PIXEL: u64 = 34;
/// Bytes per pixel of the texturing buffers: uv 2·4 (32-bit: texel addresses need the bits),
/// λ 2, level 2, texel 3·2 and footprint 4·2 (half floats).
pub const TEXTURING_BYTES_PER_PIXEL: u64 = 26;
/// Bytes per pixel of a full capture: 25 + 34 + 26 = 85.
pub const CAPTURE_BYTES_PER_PIXEL: u64 =
    CORE_BYTES_PER_PIXEL + LIGHTING_BYTES_PER_PIXEL + TEXTURING_BYTES_PER_PIXEL;
/// Bytes per sample: its depth and its triangle (4 + 4).
pub const CAPTURE_BYTES_PER_SAMPLE: u64 = 8;
