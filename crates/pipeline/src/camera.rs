//! The camera and the projection: `LookAt(eye, at, up)` and the view volume of
//! `Perspective(fovy, aspect, near, far)`, `Frustum(l, r, b, t, near, far)` or
//! `Ortho(l, r, b, t, near, far)`, in Angel's / OpenGL's terms, with the same volume in
//! GAMES101's terms beside it.

use glam::Vec3;
use serde::Serialize;

use crate::transform::{self, NamedMatrix};

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

/// The three kinds of projection the course names, as a lesson file spells them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProjectionKind {
    /// `Perspective(fovy, aspect, near, far)`.
    Perspective,
    /// `Frustum(l, r, b, t, near, far)`.
    Frustum,
    /// `Ortho(l, r, b, t, near, far)`.
    Ortho,
}

impl ProjectionKind {
    /// Every kind, in the order the interface lists them.
    pub const ALL: [Self; 3] = [Self::Perspective, Self::Frustum, Self::Ortho];

    /// The word a lesson file writes for it (`projection.kind = "ortho"`).
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::Perspective => "perspective",
            Self::Frustum => "frustum",
            Self::Ortho => "ortho",
        }
    }
}

impl Projection {
    /// Its kind.
    #[must_use]
    pub fn kind(&self) -> ProjectionKind {
        match self {
            Self::Perspective { .. } => ProjectionKind::Perspective,
            Self::Frustum { .. } => ProjectionKind::Frustum,
            Self::Ortho { .. } => ProjectionKind::Ortho,
        }
    }

    /// The projection of `kind` whose view volume is this one's, as near as `kind` can make it
    /// — what switching the kind in the panel or with a lesson's `projection.kind` does.
    ///
    /// - The same kind: unchanged.
    /// - Perspective ↔ frustum: the near rectangle `[l, r] × [b, t]` at `near` is kept. A
    ///   frustum keeps it exactly; a perspective is centred, so it takes the rectangle's size:
    ///   `fovy = 2·atan((t − b) / (2·near))`, `aspect = (r − l) / (t − b)` (left unset when it
    ///   is the viewport's, so it goes on following the window).
    /// - To or from ortho: the box is the frustum's cross-section at the distance `focus` of
    ///   what the camera looks at (`|eye − at|`), so that plane keeps its size on screen: box =
    ///   rectangle · focus / near, and back, rectangle = box · near / focus. An ortho box whose
    ///   near face is at or behind the eye becomes a perspective with `near = focus / 10`.
    #[must_use]
    pub fn with_kind(&self, kind: ProjectionKind, viewport_aspect: f32, focus: f32) -> Self {
        if kind == self.kind() {
            return *self;
        }
        let [l, r, b, t, near, far] = self.bounds(viewport_aspect);
        let focus = if focus > 0.0 && focus.is_finite() {
            focus
        } else {
            near.abs().max(1.0)
        };
        // The near rectangle of a perspective or frustum, at `near`.
        let (rect, near) = match self.kind() {
            ProjectionKind::Ortho => {
                let near = if near > 0.0 { near } else { focus / 10.0 };
                ([l, r, b, t].map(|v| v * near / focus), near)
            }
            _ => ([l, r, b, t], near),
        };
        let [left, right, bottom, top] = rect;
        match kind {
            ProjectionKind::Perspective => {
                let aspect = (right - left) / (top - bottom);
                Self::Perspective {
                    fovy_deg: (2.0 * ((top - bottom) / (2.0 * near)).atan()).to_degrees(),
                    aspect: ((aspect - viewport_aspect).abs() > 1e-5 * viewport_aspect)
                        .then_some(aspect),
                    near,
                    far,
                }
            }
            ProjectionKind::Frustum => Self::Frustum {
                left,
                right,
                bottom,
                top,
                near,
                far,
            },
            ProjectionKind::Ortho => {
                let [left, right, bottom, top] = rect.map(|v| v * focus / near);
                Self::Ortho {
                    left,
                    right,
                    bottom,
                    top,
                    near,
                    far,
                }
            }
        }
    }

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

    /// The window depth `z_w ∈ [0, 1]` of a point at eye distance `d` (along −z):
    /// perspective `z_ndc = (f+n)/(f−n) − 2·f·n/((f−n)·d)`, parallel
    /// `z_ndc = 2·(d − n)/(f − n) − 1`, then `z_w = (z_ndc + 1)/2` (`n`, `f` the near and far
    /// distances). The perspective curve rises steeply near `n`: most of `[0, 1]` goes to the
    /// near part of the frustum.
    #[must_use]
    pub fn window_depth(&self, d: f32) -> f32 {
        let [.., n, f] = self.bounds(1.0);
        let z_ndc = if self.is_perspective() {
            (f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)
        } else {
            2.0 * (d - n) / (f - n) - 1.0
        };
        (z_ndc + 1.0) / 2.0
    }

    /// The eye distance (along −z) of window depth `z_w`, undoing [`Self::window_depth`]:
    /// perspective `d = 2·f·n / ((f + n) − z_ndc·(f − n))` with `z_ndc = 2·z_w − 1`; parallel
    /// `d = n + z_w·(f − n)`.
    #[must_use]
    pub fn eye_distance(&self, z_w: f32) -> f32 {
        let [.., n, f] = self.bounds(1.0);
        if self.is_perspective() {
            let z_ndc = 2.0 * z_w - 1.0;
            2.0 * f * n / ((f + n) - z_ndc * (f - n))
        } else {
            n + z_w * (f - n)
        }
    }

    /// What is wrong with these parameters, if anything.
    #[must_use]
    pub fn problems(&self) -> Vec<ProjectionProblem> {
        let mut out = Vec::new();
        let [l, r, b, t, near, far] = self.bounds(1.0);
        if let Self::Perspective {
            fovy_deg, aspect, ..
        } = *self
        {
            if !(fovy_deg > 0.0 && fovy_deg < 180.0) {
                out.push(ProjectionProblem::Fovy(fovy_deg));
            }
            if let Some(a) = aspect
                && !(a > 0.0 && a.is_finite())
            {
                out.push(ProjectionProblem::Aspect(a));
            }
        } else {
            if !(l < r) {
                out.push(ProjectionProblem::LeftRight { left: l, right: r });
            }
            if !(b < t) {
                out.push(ProjectionProblem::BottomTop { bottom: b, top: t });
            }
        }
        if self.is_perspective() && !(near > 0.0) {
            out.push(ProjectionProblem::Near(near));
        }
        if !(far > near) {
            out.push(ProjectionProblem::FarNear { near, far });
        }
        if [l, r, b, t, near, far].iter().any(|v| !v.is_finite()) {
            out.push(ProjectionProblem::NotFinite);
        }
        out
    }
}

/// What is wrong with a projection's parameters, as data for the interface to say in its
/// language; its English sentence is its `Display`.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum ProjectionProblem {
    /// `fovy` outside (0°, 180°).
    #[error("fovy must be between 0° and 180° (exclusive), got {0}")]
    Fovy(f32),
    /// An `aspect` that is not a positive number.
    #[error("aspect must be a positive number, got {0}")]
    Aspect(f32),
    /// `left ≥ right` (a frustum or ortho box).
    #[error("left must be less than right, got left = {left}, right = {right}")]
    LeftRight {
        /// `left`.
        left: f32,
        /// `right`.
        right: f32,
    },
    /// `bottom ≥ top`.
    #[error("bottom must be less than top, got bottom = {bottom}, top = {top}")]
    BottomTop {
        /// `bottom`.
        bottom: f32,
        /// `top`.
        top: f32,
    },
    /// A perspective projection's `near ≤ 0`.
    #[error(
        "near must be positive for a perspective projection (it is a distance in front of the eye), got {0}"
    )]
    Near(f32),
    /// `far ≤ near`.
    #[error("far must be greater than near, got near = {near}, far = {far}")]
    FarNear {
        /// `near`.
        near: f32,
        /// `far`.
        far: f32,
    },
    /// A parameter that is NaN or infinite.
    #[error("every projection parameter must be a finite number")]
    NotFinite,
}
