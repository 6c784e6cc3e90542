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
            .find(|s| s.name(Lang::En).eq_ignore_ascii_case(name))
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
            Self::Model => l.tr("Model", "模型"),
            Self::World => l.tr("World", "世界"),
            Self::View => l.tr("View", "相机"),
            Self::Clip => l.tr("Clip", "裁剪"),
            Self::Ndc => l.tr("NDC", "规范化设备"),
            Self::Screen => l.tr("Viewport", "视口"),
            Self::Raster => l.tr("Rasterization", "光栅化"),
            Self::Depth => l.tr("Depth", "深度"),
            Self::Shading => l.tr("Shading", "着色"),
            Self::Texturing => l.tr("Texturing", "纹理"),
            Self::Output => l.tr("Output", "输出"),
        }
    }

    /// What happens to reach this stage, with its formula (the navigator's tooltip).
    #[must_use]
    pub fn explanation(self, l: Lang) -> &'static str {
        match self {
            Self::Model => l.tr(
                "Object coordinates: the mesh as it was modelled, p = (x, y, z, 1).",
                "模型坐标系：物体建模时的坐标，p = (x, y, z, 1)。",
            ),
            Self::World => l.tr(
                "World coordinates: M·p, with M = T·Rz·Ry·Rx·S placing each object.",
                "世界坐标系：M·p，M = T·Rz·Ry·Rx·S 把每个物体放入场景。",
            ),
            Self::View => l.tr(
                "Eye coordinates: V·M·p, V = LookAt(eye, at, up); the camera at the origin looking down −z.",
                "相机坐标系：V·M·p，V = LookAt(eye, at, up)；相机位于原点，朝向 −z。",
            ),
            Self::Clip => l.tr(
                "Clip coordinates: P·V·M·p (homogeneous). Inside the view volume: −w ≤ x, y, z ≤ w.",
                "裁剪坐标系：P·V·M·p（齐次坐标）。视见体内：−w ≤ x, y, z ≤ w。",
            ),
            Self::Ndc => l.tr(
                "Normalized device coordinates: (x, y, z)/w, the canonical cube [−1, 1]³.",
                "规范化设备坐标：(x, y, z)/w，规范立方体 [−1, 1]³。",
            ),
            Self::Screen => l.tr(
                "Window coordinates: x_w = (x+1)·W/2, y_w = (y+1)·H/2, z_w = (z+1)/2.",
                "屏幕坐标：x_w = (x+1)·W/2，y_w = (y+1)·H/2，z_w = (z+1)/2。",
            ),
            Self::Raster => l.tr(
                "Which samples each triangle covers: edge functions, the top-left rule, barycentric weights.",
                "每个三角形覆盖哪些采样点：边函数、左上规则、重心坐标。",
            ),
            Self::Depth => l.tr(
                "The z-buffer: a fragment is kept if it is nearer than what the buffer holds.",
                "深度缓冲（z-buffer）：片元比缓冲中的值更近时保留。",
            ),
            Self::Shading => l.tr(
                "Lighting: I = k_a·I_a + f_att·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(n·h, 0)^β), evaluated per face, per vertex or per pixel.",
                "光照：I = k_a·I_a + f_att·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(n·h, 0)^β)，按面、按顶点或按像素计算。",
            ),
            Self::Texturing => l.tr(
                "Texture lookups: uv interpolated, λ = log₂(texels per pixel) picks the mip level; nearest, bilinear, trilinear, anisotropic.",
                "纹理查询：插值得到 uv，λ = log₂(每像素纹素数) 选择 mipmap 层级；最近邻、双线性、三线性、各向异性。",
            ),
            Self::Output => l.tr(
                "The final colour: each pixel the mean of its samples.",
                "最终颜色：每个像素为其采样点的平均。",
            ),
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
