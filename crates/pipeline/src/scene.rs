//! What is drawn and how: objects (a mesh placed in the world), the camera, the projection and
//! the render settings. Plain data; [`Scene::validate`] says what is wrong with it in words.

use std::sync::Arc;

use glam::{Mat4, Vec3};
use serde::Serialize;

use crate::mesh::Mesh;
use crate::transform::{self, NamedMatrix, TransformError};

/// Where a fragment's colour comes from, before lighting exists.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ColorSource {
    /// The mesh's vertex colours, interpolated (meshes without colours use [`ColorSource::Normal`]).
    Vertex,
    /// The object-space normal shown as a colour, `(n + 1)/2`.
    Normal,
    /// One colour for the whole object.
    Uniform(Vec3),
}

/// A mesh placed in the world by its model transform `M = T·Rz·Ry·Rx·S`.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Name shown in the app and the capture.
    pub name: String,
    /// The mesh, shared (meshes can be large).
    pub mesh: Arc<Mesh>,
    /// Translation `T(tx, ty, tz)`.
    pub translate: Vec3,
    /// Rotation angles about x, y, z in degrees, applied x first: `Rz·Ry·Rx`.
    pub rotate_deg: Vec3,
    /// Scale `S(sx, sy, sz)`.
    pub scale: Vec3,
    /// The colour of its fragments.
    pub color: ColorSource,
    /// Its reflection coefficients (used by lighting).
    pub material: Material,
    /// Its texture: the surface colour where the mesh has texture coordinates.
    pub texture: Option<Arc<crate::texture::Texture>>,
    /// Bump or normal mapping (per-pixel lighting only).
    pub detail: Option<crate::texture::SurfaceDetail>,
    /// Displacement mapping: vertices moved along their normals.
    pub displacement: Option<crate::texture::Displacement>,
    /// Environment mapping: the surface mirrors a cube map.
    pub environment: Option<crate::texture::Environment>,
    /// A matrix applied after the object's own transform, `M = parent·T·Rz·Ry·Rx·S` (a shadow
    /// projection, a parent node's composite).
    pub parent: Option<NamedMatrix>,
    /// Whether lighting applies (shadow geometry is drawn in its flat colour).
    pub lit: bool,
    /// Whether it casts a planar shadow (when the scene has one).
    pub casts_shadow: bool,
    /// A rotation by an angle (degrees) about an arbitrary axis through the object's origin,
    /// applied after its Euler rotations: `M = T·R(n, θ)·Rz·Ry·Rx·S`, with `R(n, θ)` built as the
    /// notes do (`Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)`).
    pub axis_rotation: Option<(Vec3, f32)>,
    /// How the mesh was generated, when it is built in: lets a lesson change a parameter of the
    /// shape itself (a Bézier curve's `t`) and build it again.
    pub builtin: Option<crate::mesh::BuiltinMesh>,
}

impl Object {
    /// An object with the identity transform and its mesh's own colours.
    #[must_use]
    pub fn new(name: &str, mesh: Mesh) -> Self {
        Self {
            name: name.to_owned(),
            mesh: Arc::new(mesh),
            translate: Vec3::ZERO,
            rotate_deg: Vec3::ZERO,
            scale: Vec3::ONE,
            color: ColorSource::Vertex,
            material: Material::default(),
            texture: None,
            detail: None,
            displacement: None,
            environment: None,
            parent: None,
            lit: true,
            casts_shadow: true,
            axis_rotation: None,
            builtin: None,
        }
    }

    /// The model matrix `M = T·Rz(θz)·Ry(θy)·Rx(θx)·S` with its factors.
    #[must_use]
    pub fn model_matrix(&self) -> NamedMatrix {
        let r = self.rotate_deg * (std::f32::consts::PI / 180.0);
        let mut factors: Vec<NamedMatrix> = self.parent.iter().cloned().collect();
        factors.push(NamedMatrix::new(
            "T",
            "T(tx, ty, tz)",
            transform::translate(self.translate),
        ));
        let about_axis = self
            .axis_rotation
            .and_then(|(axis, deg)| transform::rotate_axis_aligned(axis, deg.to_radians()).ok());
        factors.extend(about_axis);
        factors.extend([
            NamedMatrix::new("Rz", "Rz(θz)", transform::rotate_z(r.z)),
            NamedMatrix::new("Ry", "Ry(θy)", transform::rotate_y(r.y)),
            NamedMatrix::new("Rx", "Rx(θx)", transform::rotate_x(r.x)),
            NamedMatrix::new("S", "S(sx, sy, sz)", transform::scale(self.scale)),
        ]);
        let m = factors.iter().fold(Mat4::IDENTITY, |m, f| m * f.matrix);
        let formula = match (self.parent.is_some(), self.axis_rotation.is_some()) {
            (true, _) => "M = parent·T·Rz·Ry·Rx·S: the object's own transform, then its parent's",
            (false, false) => "M = T·Rz·Ry·Rx·S: scale, rotate about x, y, z, then translate",
            (false, true) => {
                "M = T·R(n, θ)·Rz·Ry·Rx·S: scale, rotate about x, y, z, then about the axis n, then translate"
            }
        };
        NamedMatrix::new(&format!("M_model({})", self.name), formula, m).with_factors(factors)
    }
}

/// The camera: `LookAt(eye, at, up)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Camera {
    /// The eye point (centre of projection).
    pub eye: Vec3,
    /// The point looked at.
    pub at: Vec3,
    /// The up vector `v_up` (need not be perpendicular to the view direction).
    pub up: Vec3,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            eye: Vec3::new(0.0, 0.0, 3.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        }
    }
}

/// The projection, in Angel's / OpenGL's terms (`near`, `far` positive distances).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Projection {
    /// `Perspective(fovy, aspect, near, far)`; `aspect` `None` takes the viewport's width/height.
    Perspective {
        /// Vertical field of view in degrees, in (0, 180).
        fovy_deg: f32,
        /// Width / height of the view volume; `None`: the viewport's.
        aspect: Option<f32>,
        /// Distance to the near plane (> 0).
        near: f32,
        /// Distance to the far plane (> near).
        far: f32,
    },
    /// `Frustum(left, right, bottom, top, near, far)`, possibly asymmetric.
    Frustum {
        /// The near rectangle `[l, r] × [b, t]` at `z = −near`.
        #[allow(missing_docs)]
        left: f32,
        #[allow(missing_docs)]
        right: f32,
        #[allow(missing_docs)]
        bottom: f32,
        #[allow(missing_docs)]
        top: f32,
        /// Distance to the near plane (> 0).
        near: f32,
        /// Distance to the far plane (> near).
        far: f32,
    },
    /// `Ortho(left, right, bottom, top, near, far)`.
    Ortho {
        /// The box `[l, r] × [b, t] × [−far, −near]`.
        #[allow(missing_docs)]
        left: f32,
        #[allow(missing_docs)]
        right: f32,
        #[allow(missing_docs)]
        bottom: f32,
        #[allow(missing_docs)]
        top: f32,
        /// `z = −near` is the near face (may be negative: behind the eye).
        near: f32,
        /// `z = −far` is the far face (> near).
        far: f32,
    },
}

impl Default for Projection {
    fn default() -> Self {
        Self::Perspective {
            fovy_deg: 45.0,
            aspect: None,
            near: 0.1,
            far: 50.0,
        }
    }
}

impl Projection {
    /// The view volume `[l, r, b, t, near, far]` for a viewport of the given aspect ratio.
    #[must_use]
    pub fn bounds(&self, viewport_aspect: f32) -> [f32; 6] {
        match *self {
            Self::Perspective {
                fovy_deg,
                aspect,
                near,
                far,
            } => {
                let [l, r, b, t] = transform::perspective_bounds(
                    fovy_deg,
                    aspect.unwrap_or(viewport_aspect),
                    near,
                );
                [l, r, b, t, near, far]
            }
            Self::Frustum {
                left,
                right,
                bottom,
                top,
                near,
                far,
            }
            | Self::Ortho {
                left,
                right,
                bottom,
                top,
                near,
                far,
            } => [left, right, bottom, top, near, far],
        }
    }

    /// The eight corners of the view volume in eye coordinates: the near rectangle at
    /// `z = −near`, then the far rectangle at `z = −far` (scaled by `far/near` for a perspective
    /// projection), each bottom-left, bottom-right, top-right, top-left.
    #[must_use]
    pub fn corners_eye(&self, viewport_aspect: f32) -> [Vec3; 8] {
        let [l, r, b, t, n, f] = self.bounds(viewport_aspect);
        let k = if self.is_perspective() { f / n } else { 1.0 };
        let near = [
            Vec3::new(l, b, -n),
            Vec3::new(r, b, -n),
            Vec3::new(r, t, -n),
            Vec3::new(l, t, -n),
        ];
        let far = near.map(|p| Vec3::new(p.x * k, p.y * k, -f));
        [
            near[0], near[1], near[2], near[3], far[0], far[1], far[2], far[3],
        ]
    }

    /// Whether this is a perspective (rather than parallel) projection.
    #[must_use]
    pub fn is_perspective(&self) -> bool {
        !matches!(self, Self::Ortho { .. })
    }

    /// The OpenGL projection matrix with its factors (`N·S·H` for a frustum, `S·T` for ortho).
    #[must_use]
    pub fn matrix(&self, viewport_aspect: f32) -> NamedMatrix {
        let [l, r, b, t, n, f] = self.bounds(viewport_aspect);
        match *self {
            Self::Perspective {
                fovy_deg, aspect, ..
            } => transform::perspective(fovy_deg, aspect.unwrap_or(viewport_aspect), n, f),
            Self::Frustum { .. } => transform::frustum(l, r, b, t, n, f),
            Self::Ortho { .. } => transform::ortho(l, r, b, t, n, f),
        }
    }

    /// The same projection in GAMES101's terms (`n = −near`, `f = −far`):
    /// `M_ortho·M_persp→ortho` for perspective, `M_ortho` for parallel projection.
    #[must_use]
    pub fn matrix_games101(&self, viewport_aspect: f32) -> NamedMatrix {
        let [l, r, b, t, near, far] = self.bounds(viewport_aspect);
        if self.is_perspective() {
            transform::perspective_games101(l, r, b, t, -near, -far)
        } else {
            transform::ortho_games101(l, r, b, t, -far, -near)
        }
    }

    /// What is wrong with these parameters, if anything (each as a sentence).
    #[must_use]
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        let [l, r, b, t, near, far] = self.bounds(1.0);
        if let Self::Perspective {
            fovy_deg, aspect, ..
        } = *self
        {
            if !(fovy_deg > 0.0 && fovy_deg < 180.0) {
                out.push(format!(
                    "fovy must be between 0° and 180° (exclusive), got {fovy_deg}"
                ));
            }
            if let Some(a) = aspect
                && !(a > 0.0 && a.is_finite())
            {
                out.push(format!("aspect must be a positive number, got {a}"));
            }
        } else {
            if !(l < r) {
                out.push(format!(
                    "left must be less than right, got left = {l}, right = {r}"
                ));
            }
            if !(b < t) {
                out.push(format!(
                    "bottom must be less than top, got bottom = {b}, top = {t}"
                ));
            }
        }
        if self.is_perspective() && !(near > 0.0) {
            out.push(format!(
                "near must be positive for a perspective projection (it is a distance in front of \
                 the eye), got {near}"
            ));
        }
        if !(far > near) {
            out.push(format!(
                "far must be greater than near, got near = {near}, far = {far}"
            ));
        }
        if [l, r, b, t, near, far].iter().any(|v| !v.is_finite()) {
            out.push("every projection parameter must be a finite number".to_owned());
        }
        out
    }
}

/// A light source of the notes (Angel, chapter on lighting): each colour component is an
/// intensity, usually in `[0, 1]` (GAMES101's `I` may be larger, with `I/r²` falloff).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Light {
    /// Ambient light `I_a`: the same at every point, from every direction.
    Ambient {
        /// Intensity per RGB component.
        intensity: Vec3,
    },
    /// A point light at `position` radiating equally in all directions, attenuated by
    /// `1/(a + b·d + c·d²)` at distance `d`.
    Point {
        /// World position.
        position: Vec3,
        /// Intensity per RGB component.
        intensity: Vec3,
        /// `(a, b, c)` of the attenuation `1/(a + b·d + c·d²)`; `(1, 0, 0)` is none,
        /// `(0, 0, 1)` is GAMES101's `I/r²`.
        attenuation: Vec3,
    },
    /// A distant light: parallel rays travelling along `direction`, no attenuation.
    Directional {
        /// Direction the light travels (from the light towards the scene).
        direction: Vec3,
        /// Intensity per RGB component.
        intensity: Vec3,
    },
    /// A spotlight: a point light limited to the cone of half-angle `cutoff_deg` around
    /// `direction`, its intensity falling off as `cos^e φ` with the angle `φ` from the axis.
    Spot {
        /// World position (apex of the cone).
        position: Vec3,
        /// Axis of the cone.
        direction: Vec3,
        /// Half-angle of the cone in degrees.
        cutoff_deg: f32,
        /// Falloff exponent `e`.
        exponent: f32,
        /// Intensity per RGB component.
        intensity: Vec3,
        /// `(a, b, c)` of the distance attenuation.
        attenuation: Vec3,
    },
}

/// A material's reflection coefficients for the Phong and Blinn-Phong models:
/// `I = k_a·I_a + 1/(a + b·d + c·d²)·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(r·v, 0)^α)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Material {
    /// Ambient reflection `k_a` per RGB component.
    pub ka: Vec3,
    /// Diffuse reflection `k_d` per RGB component.
    pub kd: Vec3,
    /// Specular reflection `k_s` per RGB component.
    pub ks: Vec3,
    /// Shininess: `α` for Phong's `(r·v)^α`, `β` for Blinn-Phong's `(n·h)^β`.
    pub shininess: f32,
}

impl Default for Material {
    /// A plain grey plastic: `k_a = 0.1`, `k_d = 0.7`, `k_s = 0.5`, shininess 32.
    fn default() -> Self {
        Self {
            ka: Vec3::splat(0.1),
            kd: Vec3::splat(0.7),
            ks: Vec3::splat(0.5),
            shininess: 32.0,
        }
    }
}

/// The number of samples per pixel and where they lie.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum Samples {
    /// One sample at the pixel centre.
    #[default]
    X1,
    /// The standard rotated grid of four.
    X4,
    /// The standard pattern of eight.
    X8,
    /// The standard pattern of sixteen.
    X16,
}

impl Samples {
    /// The count, 1, 4, 8 or 16.
    #[must_use]
    pub fn count(self) -> usize {
        match self {
            Self::X1 => 1,
            Self::X4 => 4,
            Self::X8 => 8,
            Self::X16 => 16,
        }
    }

    /// The pattern for a count, if it is one of 1, 4, 8, 16.
    #[must_use]
    pub fn from_count(n: u32) -> Option<Self> {
        match n {
            1 => Some(Self::X1),
            4 => Some(Self::X4),
            8 => Some(Self::X8),
            16 => Some(Self::X16),
            _ => None,
        }
    }
}

/// Which faces are discarded before rasterization. Front faces are counter-clockwise in window
/// coordinates (OpenGL's default `glFrontFace(GL_CCW)`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CullMode {
    /// Draw both sides (OpenGL's default: culling disabled).
    #[default]
    None,
    /// Discard triangles seen from behind.
    Back,
    /// Discard triangles seen from the front.
    Front,
}

/// The depth test: a fragment is kept when `compare(fragment_depth, stored_depth)` holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DepthTest {
    /// `<` (OpenGL's default `GL_LESS`): nearer wins, the first of equals stays.
    #[default]
    Less,
    /// `≤`: nearer wins, the last of equals replaces.
    LessEqual,
    /// `>`: farther wins.
    Greater,
    /// `≥`.
    GreaterEqual,
    /// Always pass: the last fragment drawn wins (painter's order).
    Always,
}

impl DepthTest {
    /// Whether a fragment at `z` replaces the stored `stored`.
    #[must_use]
    #[inline]
    pub fn passes(self, z: f32, stored: f32) -> bool {
        match self {
            Self::Less => z < stored,
            Self::LessEqual => z <= stored,
            Self::Greater => z > stored,
            Self::GreaterEqual => z >= stored,
            Self::Always => true,
        }
    }

    /// The depth the buffer is cleared to: the far end for `<`/`≤`, the near end otherwise.
    #[must_use]
    pub fn clear_value(self) -> f32 {
        match self {
            Self::Greater | Self::GreaterEqual => 0.0,
            _ => 1.0,
        }
    }
}

/// How the image is produced: size, samples, culling, depth test, interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RenderSettings {
    /// Viewport width in pixels.
    pub width: u32,
    /// Viewport height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub samples: Samples,
    /// Face culling.
    pub cull: CullMode,
    /// Depth comparison.
    pub depth_test: DepthTest,
    /// Interpolate attributes perspective-correctly (`false`: affine in screen space, for comparison).
    pub perspective_correct: bool,
    /// Where lighting is evaluated (unlit: the surface colour as it is).
    pub shading: crate::shade::Frequency,
    /// The specular term: Phong or Blinn-Phong.
    pub reflection: crate::shade::Reflection,
    /// How textures are read.
    pub sampler: crate::texture::Sampler,
    /// Shade every sample at its own position (supersampling) instead of once per pixel and
    /// triangle at the pixel centre (multisampling).
    pub per_sample_shading: bool,
    /// The clear colour, linear RGB in `[0, 1]`.
    pub background: Vec3,
    /// Which per-pixel buffers to keep ([`Capture::FULL`]: all of them).
    pub capture: Capture,
}

/// Which per-pixel buffers a frame keeps. The colour, coverage, depth and owner of each pixel
/// (and from the owner its barycentrics) are always kept; the lighting terms and the texture
/// lookups are computed for the colour in any case but stored only when asked for, so a view
/// that shows only the final image does not pay for writing them (about 60 of a full capture's
/// 85 bytes a pixel).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Capture {
    /// Keep the lighting terms (ambient, diffuse, specular, normal, n·l, n·h, reflected), when
    /// lighting is on.
    pub lighting: bool,
    /// Keep the texture lookups (uv, λ, level, texel, footprint), when an object is textured.
    pub texturing: bool,
}

impl Capture {
    /// Every buffer: what exports write and the inspector reads.
    pub const FULL: Self = Self {
        lighting: true,
        texturing: true,
    };
    /// The colour, coverage, depth and owner only.
    pub const COLOR: Self = Self {
        lighting: false,
        texturing: false,
    };

    /// What showing `kinds` needs.
    #[must_use]
    pub fn showing(kinds: impl IntoIterator<Item = crate::capture::BufferKind>) -> Self {
        kinds.into_iter().fold(Self::COLOR, |c, k| Self {
            lighting: c.lighting || k.is_lighting(),
            texturing: c.texturing || k.is_texturing(),
        })
    }

    /// Whether this selection keeps everything `other` keeps.
    #[must_use]
    pub fn covers(self, other: Self) -> bool {
        (self.lighting || !other.lighting) && (self.texturing || !other.texturing)
    }

    /// Whether `kind` is kept.
    #[must_use]
    pub fn keeps(self, kind: crate::capture::BufferKind) -> bool {
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

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
            samples: Samples::X1,
            cull: CullMode::None,
            depth_test: DepthTest::Less,
            perspective_correct: true,
            shading: crate::shade::Frequency::Unlit,
            reflection: crate::shade::Reflection::BlinnPhong,
            sampler: crate::texture::Sampler::default(),
            per_sample_shading: false,
            background: Vec3::new(0.08, 0.09, 0.11),
            capture: Capture::FULL,
        }
    }
}

/// The largest width or height of a viewport.
pub const MAX_VIEWPORT_SIDE: u32 = 16_384;
/// The most memory one capture may take, by [`RenderSettings::capture_bytes`]: 2 GiB, so that
/// a mistaken size is refused with a message instead of exhausting the machine.
pub const MAX_CAPTURE_BYTES: u64 = 2 << 30;

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

impl RenderSettings {
    /// Width / height.
    #[must_use]
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height as f32
    }

    /// The memory the per-pixel and per-sample buffers of a capture at these settings take, at
    /// most: `W·H·B + W·H·S·8` bytes with `B` the selection's bytes a pixel (85 for a full
    /// capture, see [`CAPTURE_BYTES_PER_PIXEL`]).
    #[must_use]
    pub fn capture_bytes(&self) -> u64 {
        let pixels = u64::from(self.width) * u64::from(self.height);
        pixels * self.capture.bytes_per_pixel()
            + pixels * self.samples.count() as u64 * CAPTURE_BYTES_PER_SAMPLE
    }

    /// Why a capture at these settings would take too much memory, if it would.
    #[must_use]
    pub fn capture_problem(&self) -> Option<String> {
        let bytes = self.capture_bytes();
        (bytes > MAX_CAPTURE_BYTES).then(|| {
            format!(
                "{}×{} pixels × {} samples needs about {} MB for a capture, more than the {} MB \
                 allowed; lower the size or the sample count",
                self.width,
                self.height,
                self.samples.count(),
                bytes >> 20,
                MAX_CAPTURE_BYTES >> 20
            )
        })
    }

    /// What is wrong with these settings, if anything.
    #[must_use]
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (name, v) in [("width", self.width), ("height", self.height)] {
            if v == 0 || v > MAX_VIEWPORT_SIDE {
                out.push(format!(
                    "the viewport {name} must be between 1 and {MAX_VIEWPORT_SIDE} pixels, got {v}"
                ));
            }
        }
        out.extend(self.capture_problem());
        if !self.background.is_finite() {
            out.push("the background colour must be finite".to_owned());
        }
        out
    }
}

/// A planar projected shadow (Angel's shadow matrix): every object that casts one is drawn a
/// second time, projected from the point light `light` onto the plane `y = plane_y`, in `color`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PlanarShadow {
    /// The light the shadow is cast from.
    pub light: Vec3,
    /// The height of the receiving plane.
    pub plane_y: f32,
    /// The shadow's colour.
    pub color: Vec3,
}

/// How far above its plane shadow geometry is lifted so that it wins the depth test against
/// the plane itself (the polygon offset of fixed-function OpenGL).
pub const SHADOW_LIFT: f32 = 2e-3;

impl PlanarShadow {
    /// `T(0, h + ε, 0)·M_shadow(l − (0, h, 0))·T(0, −h, 0)`: the notes' matrix for the plane
    /// `y = 0`, moved to `y = h` and lifted by [`SHADOW_LIFT`].
    #[must_use]
    pub fn matrix(&self) -> NamedMatrix {
        let h = Vec3::new(0.0, self.plane_y, 0.0);
        let m = transform::planar_shadow(self.light - h);
        let up = transform::translate(h + Vec3::new(0.0, SHADOW_LIFT, 0.0));
        let down = transform::translate(-h);
        NamedMatrix::new(
            "M_shadow",
            "T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0): project from the light onto y = h",
            up * m.matrix * down,
        )
        .with_factors(vec![
            NamedMatrix::new("T(0, h+ε, 0)", "back up to the plane, lifted by ε", up),
            m,
            NamedMatrix::new("T(0, −h, 0)", "the plane to y = 0", down),
        ])
    }
}

/// Everything that is drawn: objects, camera and projection.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Scene {
    /// The objects, drawn in this order (primitive ids count across them in this order).
    pub objects: Vec<Object>,
    /// The viewing camera.
    pub camera: Camera,
    /// The projection.
    pub projection: Projection,
    /// The lights (used by lighting).
    pub lights: Vec<Light>,
    /// A planar projected shadow, drawn as a second pass.
    pub shadow: Option<PlanarShadow>,
    /// Articulated figures (robot arm, humanoid), drawn part by part by a matrix-stack traversal.
    pub figures: Vec<crate::hierarchy::Figure>,
}

impl Scene {
    /// Whether a full capture of this scene at `settings` has buffer `kind` to show: the
    /// lighting buffers when lighting is on (the reflected term when an object mirrors its
    /// environment), the texturing buffers when an object is textured. Known before rendering,
    /// so that a view can offer a buffer that the capture it shows did not keep.
    #[must_use]
    pub fn offers(&self, settings: &RenderSettings, kind: crate::capture::BufferKind) -> bool {
        use crate::capture::BufferKind;
        let lit = settings.shading != crate::shade::Frequency::Unlit;
        if kind == BufferKind::Reflected {
            lit && self
                .objects
                .iter()
                .any(|o| o.lit && o.environment.is_some())
        } else if kind.is_lighting() {
            lit
        } else if kind.is_texturing() {
            self.objects
                .iter()
                .any(|o| o.texture.is_some() && !o.mesh.uvs.is_empty())
        } else {
            true
        }
    }

    /// The objects drawn and the figures' traversal: the scene's own objects, then every part
    /// of every figure (depth-first, with a matrix stack), then (with a planar shadow) the shadow
    /// pass, one unlit object `shadow of …` per object that casts one.
    #[must_use]
    pub fn drawn_objects(&self) -> (Vec<Object>, Vec<crate::hierarchy::Step>) {
        let mut out = self.objects.clone();
        let mut steps = Vec::new();
        for figure in &self.figures {
            steps.extend(crate::hierarchy::traverse(figure, &mut out));
        }
        if let Some(shadow) = &self.shadow {
            let m = shadow.matrix();
            let casting: Vec<Object> = out.iter().filter(|o| o.casts_shadow).cloned().collect();
            for o in casting {
                let mut s = o.clone();
                s.name = format!("shadow of {}", o.name);
                s.parent = Some(match &o.parent {
                    Some(p) => NamedMatrix::new("M_shadow·parent", &m.formula, m.matrix * p.matrix)
                        .with_factors(vec![m.clone(), p.clone()]),
                    None => m.clone(),
                });
                s.color = ColorSource::Uniform(shadow.color);
                s.texture = None;
                s.detail = None;
                s.environment = None;
                s.lit = false;
                s.casts_shadow = false;
                out.push(s);
            }
        }
        (out, steps)
    }

    /// The view matrix `LookAt(eye, at, up)`.
    ///
    /// # Errors
    /// When the camera is degenerate (see [`transform::camera_frame`]).
    pub fn view_matrix(&self) -> Result<NamedMatrix, TransformError> {
        let Camera { eye, at, up } = self.camera;
        let m = transform::look_at(eye, at, up)?;
        let gt = transform::look_at_gt(eye, at - eye, up)?;
        Ok(NamedMatrix::new(
            "V = LookAt(eye, at, up)",
            "rows u, v, n and −p·u, −p·v, −p·n with n = (eye−at)/|eye−at|, u = v_up×n/|v_up×n|, \
             v = n×u; equals GAMES101's R_view·T_view with g = at − eye, t = up",
            m,
        )
        .with_factors(gt.factors))
    }

    /// Every problem with the scene and settings, as sentences; empty when it can be drawn.
    #[must_use]
    pub fn problems(&self, settings: &RenderSettings) -> Vec<String> {
        let mut out = settings.problems();
        out.extend(self.projection.problems());
        let Camera { eye, at, up } = self.camera;
        if !(eye.is_finite() && at.is_finite() && up.is_finite()) {
            out.push("the camera's eye, at and up must be finite".to_owned());
        } else if let Err(e) = transform::camera_frame(eye, at, up) {
            out.push(e.to_string());
        }
        for o in &self.objects {
            if !(o.translate.is_finite() && o.rotate_deg.is_finite() && o.scale.is_finite()) {
                out.push(format!("object `{}`: its transform must be finite", o.name));
            }
            if let ColorSource::Uniform(c) = o.color
                && !c.is_finite()
            {
                out.push(format!("object `{}`: its colour must be finite", o.name));
            }
        }
        out
    }
}
