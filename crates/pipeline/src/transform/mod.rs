//! Every matrix of the course, as a named function whose doc comment carries its formula.
//!
//! Conventions (both courses agree on these):
//! - column vectors, `p' = M·p`, so `M = C·B·A` applies `A` first;
//! - right-handed coordinates; the camera looks down `−z` with `+y` up;
//! - angles are in radians unless a name says `_deg`.
//!
//! Matrices are written here row by row, as on the slides, with [`rows`]; glam stores them
//! column-major, which is an implementation detail nobody outside this module needs to know.
//!
//! The two courses name the depth range differently:
//! - Angel / OpenGL (`ortho`, `frustum`, `perspective`): `near`, `far` are positive *distances*;
//!   the near plane `z = −near` goes to NDC `z = −1`, the far plane to `+1`.
//! - GAMES101 (`ortho_games101`, `persp_to_ortho`): `n`, `f` are *z coordinates*, negative, `n > f`;
//!   `M_ortho` maps `[f, n]` to `[−1, 1]`, so the near plane goes to NDC `z = +1`.
//!
//! With `n = −near`, `f = −far` the two describe the same frustum:
//! `M_ortho·M_persp→ortho = −Z·P_GL` where `Z = diag(1, 1, −1, 1)` (see [`games101_relation`]).
//! The factor `−1` does not move any point (homogeneous coordinates), `Z` mirrors NDC depth.
//!
//! The matrices are grouped as the course teaches them: modelling transforms here, rotation
//! about an arbitrary axis in [`axis`], the camera in [`viewing`], projections, the viewport and
//! the shadow projection in [`projection`]; all are re-exported here.

mod axis;
mod projection;
mod viewing;

pub use axis::*;
pub use projection::*;
pub use viewing::*;

use glam::{Mat4, Vec3, Vec4};
use serde::Serialize;

/// Builds a matrix from its rows, written as on the slides.
#[must_use]
pub fn rows(r: [[f32; 4]; 4]) -> Mat4 {
    Mat4::from_cols_array_2d(&r).transpose()
}

/// The rows of a matrix, as on the slides (row-major), for display and export.
#[must_use]
pub fn to_rows(m: &Mat4) -> [[f32; 4]; 4] {
    m.transpose().to_cols_array_2d()
}

/// A matrix with the name and formula it is taught under, as recorded in a capture.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NamedMatrix {
    /// Short name in the course's notation, e.g. `P = N·S·H`.
    pub name: String,
    /// The formula, written in the notes' notation as plain text.
    pub formula: String,
    /// The matrix, row-major (`rows[i][j]` is row `i`, column `j`).
    #[serde(serialize_with = "serialize_rows")]
    pub matrix: Mat4,
    /// Factors whose product (left to right) equals `matrix`; empty when it is elementary.
    pub factors: Vec<NamedMatrix>,
}

impl NamedMatrix {
    /// A matrix with no factors.
    #[must_use]
    pub fn new(name: &str, formula: &str, matrix: Mat4) -> Self {
        Self {
            name: name.to_owned(),
            formula: formula.to_owned(),
            matrix,
            factors: Vec::new(),
        }
    }

    /// Attaches the factors whose left-to-right product is this matrix.
    #[must_use]
    pub fn with_factors(mut self, factors: Vec<NamedMatrix>) -> Self {
        self.factors = factors;
        self
    }
}

fn serialize_rows<S: serde::Serializer>(m: &Mat4, s: S) -> Result<S::Ok, S::Error> {
    to_rows(m).serialize(s)
}

/// Why a transform cannot be built from the given parameters.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TransformError {
    /// LookAt needs a view direction: `eye` and `at` coincide.
    #[error("the eye and the point looked at coincide ({0:?}): there is no view direction")]
    EyeAtCoincide(Vec3),
    /// LookAt needs an up vector that is not parallel to the view direction.
    #[error(
        "the up vector {up:?} is parallel to the view direction {dir:?}: \
         u = v_up × n is zero, so the camera frame is undefined (choose another up vector)"
    )]
    UpParallelToView {
        /// The up vector given.
        up: Vec3,
        /// The view direction `at − eye`.
        dir: Vec3,
    },
    /// A rotation axis must have a length.
    #[error("the rotation axis is the zero vector")]
    ZeroAxis,
}

/// Translation `T(dx, dy, dz)`:
///
/// ```text
/// | 1 0 0 dx |
/// | 0 1 0 dy |
/// | 0 0 1 dz |
/// | 0 0 0 1  |
/// ```
#[must_use]
pub fn translate(d: Vec3) -> Mat4 {
    rows([
        [1.0, 0.0, 0.0, d.x],
        [0.0, 1.0, 0.0, d.y],
        [0.0, 0.0, 1.0, d.z],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// Scaling `S(sx, sy, sz)` about the origin (the fixed point): `diag(sx, sy, sz, 1)`.
#[must_use]
pub fn scale(s: Vec3) -> Mat4 {
    rows([
        [s.x, 0.0, 0.0, 0.0],
        [0.0, s.y, 0.0, 0.0],
        [0.0, 0.0, s.z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// Rotation about the x axis, `Rx(θ)`; x is unchanged:
///
/// ```text
/// | 1   0     0    0 |
/// | 0  cosθ −sinθ  0 |
/// | 0  sinθ  cosθ  0 |
/// | 0   0     0    1 |
/// ```
#[must_use]
pub fn rotate_x(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    rows([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, c, -s, 0.0],
        [0.0, s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// Rotation about the y axis, `Ry(θ)`; y is unchanged. Note the signs ("something strange
/// about Ry"): z × x = y, so the `sinθ` sits above the diagonal in the first row:
///
/// ```text
/// |  cosθ 0 sinθ 0 |
/// |   0   1  0   0 |
/// | −sinθ 0 cosθ 0 |
/// |   0   0  0   1 |
/// ```
#[must_use]
pub fn rotate_y(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    rows([
        [c, 0.0, s, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [-s, 0.0, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// Rotation about the z axis, `Rz(θ)`: `x' = x·cosθ − y·sinθ`, `y' = x·sinθ + y·cosθ`, `z' = z`.
///
/// ```text
/// | cosθ −sinθ 0 0 |
/// | sinθ  cosθ 0 0 |
/// |  0     0   1 0 |
/// |  0     0   0 1 |
/// ```
#[must_use]
pub fn rotate_z(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    rows([
        [c, -s, 0.0, 0.0],
        [s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// The general shear: each coordinate gains a multiple of the others,
/// `x' = x + xy·y + xz·z`, `y' = y + yx·x + yz·z`, `z' = z + zx·x + zy·y`:
///
/// ```text
/// | 1  xy xz 0 |
/// | yx 1  yz 0 |
/// | zx zy 1  0 |
/// | 0  0  0  1 |
/// ```
///
/// The shear `H(θ, φ)` of Frustum is `shear(Shear { xz: cot θ, yz: cot φ, ..})`.
#[must_use]
pub fn shear(h: Shear) -> Mat4 {
    rows([
        [1.0, h.xy, h.xz, 0.0],
        [h.yx, 1.0, h.yz, 0.0],
        [h.zx, h.zy, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// The six shear factors of [`shear`]; `xy` is how much of `y` is added to `x`, and so on.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[allow(missing_docs)]
pub struct Shear {
    pub xy: f32,
    pub xz: f32,
    pub yx: f32,
    pub yz: f32,
    pub zx: f32,
    pub zy: f32,
}

/// Applies a homogeneous matrix to a point `(x, y, z, 1)`.
#[must_use]
pub fn apply_point(m: &Mat4, p: Vec3) -> Vec4 {
    *m * p.extend(1.0)
}
