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

use glam::{Mat3, Mat4, Vec3, Vec4};
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

/// The angles of the notes' construction of a rotation about an arbitrary axis `u = (a, b, c)`
/// (unit length), with `d = √(b² + c²)`:
/// - `θx` turns `u` about x into the xz plane: `cos θx = c/d`, `sin θx = b/d` (`θx = 0` when `d = 0`);
/// - `θy` then turns it about y onto the z axis: `cos θy = d`, `sin θy = −a`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AxisAlignment {
    /// `θx` in radians.
    pub theta_x: f32,
    /// `θy` in radians.
    pub theta_y: f32,
}

/// The alignment angles `θx`, `θy` that carry the unit axis `u` onto `+z` (see [`AxisAlignment`]).
///
/// # Errors
/// [`TransformError::ZeroAxis`] when `axis` has no length.
pub fn align_axis_with_z(axis: Vec3) -> Result<AxisAlignment, TransformError> {
    let u = axis.try_normalize().ok_or(TransformError::ZeroAxis)?;
    let d = (u.y * u.y + u.z * u.z).sqrt();
    let theta_x = if d > 0.0 { u.y.atan2(u.z) } else { 0.0 };
    let theta_y = (-u.x).atan2(d);
    Ok(AxisAlignment { theta_x, theta_y })
}

/// Rotation by `θ` about an arbitrary axis through the origin, built the notes' way:
/// align the axis with z, rotate about z, undo the alignment:
///
/// `R = Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)`
///
/// The factors are returned in that order, so their product is `R`.
///
/// # Errors
/// [`TransformError::ZeroAxis`] when `axis` has no length.
pub fn rotate_axis_aligned(axis: Vec3, theta: f32) -> Result<NamedMatrix, TransformError> {
    let AxisAlignment { theta_x, theta_y } = align_axis_with_z(axis)?;
    let factors = vec![
        NamedMatrix::new(
            "Rx(−θx)",
            "undo the turn into the xz plane",
            rotate_x(-theta_x),
        ),
        NamedMatrix::new("Ry(−θy)", "undo the turn onto z", rotate_y(-theta_y)),
        NamedMatrix::new("Rz(θ)", "the rotation itself, about z", rotate_z(theta)),
        NamedMatrix::new("Ry(θy)", "cos θy = d, sin θy = −a", rotate_y(theta_y)),
        NamedMatrix::new("Rx(θx)", "cos θx = c/d, sin θx = b/d", rotate_x(theta_x)),
    ];
    let matrix = factors.iter().fold(Mat4::IDENTITY, |m, f| m * f.matrix);
    Ok(NamedMatrix::new(
        "R = Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)",
        "rotation about an arbitrary axis, by aligning it with z",
        matrix,
    )
    .with_factors(factors))
}

/// Rodrigues' rotation formula, rotation by `α` about the unit axis `n`:
///
/// `R(n, α) = cos α · I + (1 − cos α) · n·nᵀ + sin α · N`, where `N` is the cross-product matrix
///
/// ```text
///     |  0  −nz  ny |
/// N = |  nz  0  −nx |
///     | −ny  nx  0  |
/// ```
///
/// # Errors
/// [`TransformError::ZeroAxis`] when `axis` has no length.
pub fn rotate_axis_rodrigues(axis: Vec3, alpha: f32) -> Result<Mat4, TransformError> {
    let n = axis.try_normalize().ok_or(TransformError::ZeroAxis)?;
    let (s, c) = alpha.sin_cos();
    let outer = Mat3::from_cols(n * n.x, n * n.y, n * n.z);
    let cross = Mat3::from_cols(
        Vec3::new(0.0, n.z, -n.y),
        Vec3::new(-n.z, 0.0, n.x),
        Vec3::new(n.y, -n.x, 0.0),
    );
    let r = Mat3::IDENTITY * c + outer * (1.0 - c) + cross * s;
    Ok(Mat4::from_mat3(r))
}

/// A unit quaternion `q = (w, x, y, z) = (cos(θ/2), sin(θ/2)·n)` for rotation by `θ` about `n`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Quaternion {
    /// Scalar part `cos(θ/2)`.
    pub w: f32,
    /// Vector part `sin(θ/2)·n`.
    pub v: Vec3,
}

impl Quaternion {
    /// The rotation by `theta` about `axis`.
    ///
    /// # Errors
    /// [`TransformError::ZeroAxis`] when `axis` has no length.
    pub fn from_axis_angle(axis: Vec3, theta: f32) -> Result<Self, TransformError> {
        let n = axis.try_normalize().ok_or(TransformError::ZeroAxis)?;
        let (s, c) = (theta / 2.0).sin_cos();
        Ok(Self { w: c, v: n * s })
    }

    /// Rotates `p` as `q·(0, p)·q*`.
    #[must_use]
    pub fn rotate(&self, p: Vec3) -> Vec3 {
        // q·p·q* expanded: p + 2w(v × p) + 2 v × (v × p)
        let t = 2.0 * self.v.cross(p);
        p + self.w * t + self.v.cross(t)
    }

    /// The rotation matrix of a unit quaternion:
    ///
    /// ```text
    /// | 1−2(y²+z²)  2(xy−wz)    2(xz+wy)   |
    /// | 2(xy+wz)    1−2(x²+z²)  2(yz−wx)   |
    /// | 2(xz−wy)    2(yz+wx)    1−2(x²+y²) |
    /// ```
    #[must_use]
    pub fn to_matrix(&self) -> Mat4 {
        let (w, x, y, z) = (self.w, self.v.x, self.v.y, self.v.z);
        rows([
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
                0.0,
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
                0.0,
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
                0.0,
            ],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }
}

/// The camera frame `u, v, n` of Angel's LookAt: `n = (eye − at)/|eye − at|`,
/// `u = (v_up × n)/|v_up × n|`, `v = n × u`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CameraFrame {
    /// The camera's x axis (to the right).
    pub u: Vec3,
    /// The camera's y axis (up).
    pub v: Vec3,
    /// The camera's z axis (pointing back, from `at` to `eye`).
    pub n: Vec3,
    /// The eye point.
    pub eye: Vec3,
}

/// The camera frame of `LookAt(eye, at, v_up)`.
///
/// # Errors
/// When `eye == at`, or `v_up` is parallel to the view direction (so `u` would be zero).
pub fn camera_frame(eye: Vec3, at: Vec3, up: Vec3) -> Result<CameraFrame, TransformError> {
    let n = (eye - at)
        .try_normalize()
        .ok_or(TransformError::EyeAtCoincide(eye))?;
    let u = up
        .cross(n)
        .try_normalize()
        .filter(|_| up.cross(n).length() > 1e-6 * up.length())
        .ok_or(TransformError::UpParallelToView { up, dir: at - eye })?;
    let v = n.cross(u);
    Ok(CameraFrame { u, v, n, eye })
}

/// Angel's `LookAt(eye, at, v_up)` in the u, v, n form. With `p = eye`:
///
/// ```text
/// | ux uy uz −p·u |
/// | vx vy vz −p·v |
/// | nx ny nz −p·n |
/// | 0  0  0   1   |
/// ```
///
/// It is `(Mᵀ)⁻¹` for `Mᵀ = [u, v, n, p]`, the frame of the camera written in world coordinates:
/// `[R t; 0 1]⁻¹ = [Rᵀ −Rᵀt; 0 1]` because `R` is orthogonal.
///
/// # Errors
/// See [`camera_frame`].
pub fn look_at(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, TransformError> {
    let CameraFrame { u, v, n, eye: p } = camera_frame(eye, at, up)?;
    Ok(rows([
        [u.x, u.y, u.z, -p.dot(u)],
        [v.x, v.y, v.z, -p.dot(v)],
        [n.x, n.y, n.z, -p.dot(n)],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}

/// GAMES101's view transform from the eye position `e`, gaze direction `g` and up direction `t`:
/// `M_view = R_view·T_view`, translate `e` to the origin, then rotate `g` to `−z`, `t` to `y`,
/// `g × t` to `x`:
///
/// ```text
///          | 1 0 0 −xe |           | x(g×t) y(g×t) z(g×t) 0 |
/// T_view = | 0 1 0 −ye |  R_view = |  xt     yt     zt    0 |
///          | 0 0 1 −ze |           | x(−g)  y(−g)  z(−g)  0 |
///          | 0 0 0  1  |           |  0      0      0     1 |
/// ```
///
/// `R_view` is the transpose of its easy inverse (x → g×t, y → t, z → −g).
/// `g` and `t` need not be unit or perpendicular: `t` is made perpendicular to `g` first
/// (the notes assume it is), which gives exactly Angel's LookAt with `g = at − eye`.
///
/// # Errors
/// See [`camera_frame`].
pub fn look_at_gt(e: Vec3, g: Vec3, t: Vec3) -> Result<NamedMatrix, TransformError> {
    let frame = camera_frame(e, e + g, t)?;
    let (g_hat, t_hat) = (-frame.n, frame.v);
    let gxt = g_hat.cross(t_hat);
    let t_view = translate(-e);
    let r_view = rows([
        [gxt.x, gxt.y, gxt.z, 0.0],
        [t_hat.x, t_hat.y, t_hat.z, 0.0],
        [-g_hat.x, -g_hat.y, -g_hat.z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    Ok(NamedMatrix::new(
        "M_view = R_view·T_view",
        "translate e to the origin, then rotate g to −z, t to y, g×t to x",
        r_view * t_view,
    )
    .with_factors(vec![
        NamedMatrix::new("R_view", "rows: g×t, t, −g", r_view),
        NamedMatrix::new("T_view", "T(−e)", t_view),
    ]))
}

/// Angel's / OpenGL's `Ortho(left, right, bottom, top, near, far)` (`glOrtho`): the box
/// `[l, r]×[b, t]×[−far, −near]` to the canonical cube, `−near → −1`, `−far → +1`.
/// It is `S·T` with `T(−(l+r)/2, −(b+t)/2, (near+far)/2)` and `S(2/(r−l), 2/(t−b), −2/(far−near))`:
///
/// ```text
/// | 2/(r−l)    0        0          −(r+l)/(r−l)   |
/// |   0      2/(t−b)    0          −(t+b)/(t−b)   |
/// |   0        0     −2/(f−n)      −(f+n)/(f−n)   |
/// |   0        0        0               1         |
/// ```
#[must_use]
pub fn ortho(l: f32, r: f32, b: f32, t: f32, near: f32, far: f32) -> NamedMatrix {
    let t_center = translate(Vec3::new(
        -(l + r) / 2.0,
        -(b + t) / 2.0,
        (near + far) / 2.0,
    ));
    let s_unit = scale(Vec3::new(2.0 / (r - l), 2.0 / (t - b), -2.0 / (far - near)));
    let m = rows([
        [2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
        [0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b)],
        [0.0, 0.0, -2.0 / (far - near), -(far + near) / (far - near)],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    NamedMatrix::new(
        "Ortho = S·T",
        "centre the view volume at the origin, then scale it to the cube [−1,1]³",
        m,
    )
    .with_factors(vec![
        NamedMatrix::new("S", "S(2/(r−l), 2/(t−b), −2/(far−near))", s_unit),
        NamedMatrix::new("T", "T(−(l+r)/2, −(b+t)/2, (near+far)/2)", t_center),
    ])
}

/// Angel's / OpenGL's `Frustum(left, right, bottom, top, near, far)` (`glFrustum`), with its
/// factors `P = N·S·H`:
/// - `H = H(θ, φ)`, the shear that makes the frustum symmetric about the −z axis:
///   `x' = x + (l+r)/(2·near)·z`, `y' = y + (t+b)/(2·near)·z`;
/// - `S = S(2·near/(r−l), 2·near/(t−b), 1)`, making the sides the planes `x = ±z`, `y = ±z`;
/// - `N`, the perspective normalization, with `α = −(far+near)/(far−near)`,
///   `β = −2·far·near/(far−near)`:
///
/// ```text
///     | 1 0 0 0 |           | 2n/(r−l)    0      (r+l)/(r−l)      0        |
/// N = | 0 1 0 0 |   N·S·H = |    0     2n/(t−b)  (t+b)/(t−b)      0        |
///     | 0 0 α β |           |    0        0     −(f+n)/(f−n)  −2fn/(f−n)   |
///     | 0 0 −1 0|           |    0        0          −1           0        |
/// ```
#[must_use]
pub fn frustum(l: f32, r: f32, b: f32, t: f32, near: f32, far: f32) -> NamedMatrix {
    let h = shear(Shear {
        xz: (l + r) / (2.0 * near),
        yz: (t + b) / (2.0 * near),
        ..Shear::default()
    });
    let s = scale(Vec3::new(2.0 * near / (r - l), 2.0 * near / (t - b), 1.0));
    let alpha = -(far + near) / (far - near);
    let beta = -2.0 * far * near / (far - near);
    let n = rows([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, alpha, beta],
        [0.0, 0.0, -1.0, 0.0],
    ]);
    let p = rows([
        [2.0 * near / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2.0 * near / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, alpha, beta],
        [0.0, 0.0, -1.0, 0.0],
    ]);
    NamedMatrix::new(
        "P = N·S·H",
        "Frustum(l, r, b, t, near, far): shear, scale, then perspective normalization",
        p,
    )
    .with_factors(vec![
        NamedMatrix::new(
            "N",
            "perspective normalization: α = −(far+near)/(far−near), β = −2·far·near/(far−near)",
            n,
        ),
        NamedMatrix::new("S", "S(2·near/(r−l), 2·near/(t−b), 1)", s),
        NamedMatrix::new(
            "H",
            "shear H(θ, φ): cot θ = (l+r)/(2·near), cot φ = (t+b)/(2·near)",
            h,
        ),
    ])
}

/// The symmetric view volume of `Perspective(fovy, aspect, near, far)` (`gluPerspective`):
/// `top = near·tan(fovy/2)`, `right = top·aspect`, `left = −right`, `bottom = −top`.
///
/// (Erratum: the review slides write `top = near·tan(fovy)`; the half angle is right, since fovy
/// is the whole vertical angle and `top` is half the height of the near plane.)
#[must_use]
pub fn perspective_bounds(fovy_deg: f32, aspect: f32, near: f32) -> [f32; 4] {
    let top = near * (fovy_deg.to_radians() / 2.0).tan();
    let right = top * aspect;
    [-right, right, -top, top]
}

/// Angel's / OpenGL's `Perspective(fovy, aspect, near, far)` (`gluPerspective`): `Frustum` of the
/// symmetric volume of [`perspective_bounds`], which simplifies to
///
/// ```text
/// | near/right     0          0              0        |
/// |     0      near/top       0              0        |
/// |     0          0    −(f+n)/(f−n)   −2fn/(f−n)     |
/// |     0          0         −1              0        |
/// ```
///
/// with `near/top = cot(fovy/2)`. `fovy` is in degrees.
#[must_use]
pub fn perspective(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> NamedMatrix {
    let [l, r, b, t] = perspective_bounds(fovy_deg, aspect, near);
    let mut m = frustum(l, r, b, t, near, far);
    m.name = "P = Perspective(fovy, aspect, near, far)".to_owned();
    m.formula = "Frustum(−right, right, −top, top, near, far) with top = near·tan(fovy/2), \
                 right = top·aspect"
        .to_owned();
    m
}

/// GAMES101's "squish" `M_persp→ortho` for `n`, `f` given as z coordinates (negative, `n > f`):
/// it keeps the near plane fixed, keeps the z of the far plane's points, and squeezes the frustum
/// into the box `[l,r]×[b,t]×[f,n]` (`x' = n·x/z`, `y' = n·y/z`):
///
/// ```text
/// | n 0  0    0  |
/// | 0 n  0    0  |
/// | 0 0 n+f −n·f |
/// | 0 0  1    0  |
/// ```
#[must_use]
pub fn persp_to_ortho(n: f32, f: f32) -> Mat4 {
    rows([
        [n, 0.0, 0.0, 0.0],
        [0.0, n, 0.0, 0.0],
        [0.0, 0.0, n + f, -n * f],
        [0.0, 0.0, 1.0, 0.0],
    ])
}

/// GAMES101's `M_ortho` of the box `[l,r]×[b,t]×[f,n]` (`n`, `f` z coordinates, `n > f`): translate
/// the centre to the origin, then scale each side to length 2; the near plane goes to `z = +1`:
///
/// ```text
///           | 2/(r−l)    0       0     0 |   | 1 0 0 −(r+l)/2 |
/// M_ortho = |   0     2/(t−b)    0     0 | · | 0 1 0 −(t+b)/2 |
///           |   0        0    2/(n−f)  0 |   | 0 0 1 −(n+f)/2 |
///           |   0        0       0     1 |   | 0 0 0    1     |
/// ```
#[must_use]
pub fn ortho_games101(l: f32, r: f32, b: f32, t: f32, f: f32, n: f32) -> NamedMatrix {
    let s = scale(Vec3::new(2.0 / (r - l), 2.0 / (t - b), 2.0 / (n - f)));
    let tr = translate(Vec3::new(-(r + l) / 2.0, -(t + b) / 2.0, -(n + f) / 2.0));
    NamedMatrix::new(
        "M_ortho",
        "[l,r]×[b,t]×[f,n] → [−1,1]³: translate the centre to the origin, then scale",
        s * tr,
    )
    .with_factors(vec![
        NamedMatrix::new("scale", "S(2/(r−l), 2/(t−b), 2/(n−f))", s),
        NamedMatrix::new("translate", "T(−(r+l)/2, −(t+b)/2, −(n+f)/2)", tr),
    ])
}

/// GAMES101's perspective projection `M_persp = M_ortho·M_persp→ortho` of the frustum whose near
/// rectangle is `[l,r]×[b,t]` at `z = n`, far plane at `z = f` (`n > f`, both negative).
#[must_use]
pub fn perspective_games101(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> NamedMatrix {
    let squish = persp_to_ortho(n, f);
    let orth = ortho_games101(l, r, b, t, f, n);
    NamedMatrix::new(
        "M_persp = M_ortho·M_persp→ortho",
        "squish the frustum into a box (n and f fixed), then the orthographic projection",
        orth.matrix * squish,
    )
    .with_factors(vec![
        NamedMatrix::new("M_ortho", &orth.formula, orth.matrix),
        NamedMatrix::new(
            "M_persp→ortho",
            "x' = n·x/z, y' = n·y/z; z of the near and far planes kept",
            squish,
        ),
    ])
}

/// `Z = diag(1, 1, −1, 1)`, the mirror of NDC depth that relates the two courses' projections:
/// `M_persp(GAMES101; n = −near, f = −far) = −Z·Perspective_GL(near, far)` and
/// `M_ortho(GAMES101; n = −near, f = −far) = Z·Ortho_GL(near, far)`.
/// Both put every point at the same NDC x and y; GAMES101's NDC z is the negated GL one
/// (near plane at `+1` instead of `−1`), and the factor `−1` on the whole homogeneous vector
/// (`w = z` instead of `w = −z`) changes no point.
#[must_use]
pub fn games101_relation() -> Mat4 {
    scale(Vec3::new(1.0, 1.0, -1.0))
}

/// The viewport transform from NDC to window coordinates for a `width × height` window with its
/// origin at the bottom-left corner (OpenGL's `glViewport(0, 0, w, h)` with `glDepthRange(0, 1)`):
/// `x_w = (x+1)·w/2`, `y_w = (y+1)·h/2`, `z_w = (z+1)/2`:
///
/// ```text
/// | w/2  0   0   w/2 |
/// |  0  h/2  0   h/2 |
/// |  0   0  1/2  1/2 |
/// |  0   0   0    1  |
/// ```
///
/// GAMES101's `M_viewport` is the same in x and y and leaves z unchanged (its notes mislabel it
/// `M_persp→ortho`); pipelens stores depth as OpenGL does, in `[0, 1]`.
#[must_use]
pub fn viewport(width: f32, height: f32) -> Mat4 {
    rows([
        [width / 2.0, 0.0, 0.0, width / 2.0],
        [0.0, height / 2.0, 0.0, height / 2.0],
        [0.0, 0.0, 0.5, 0.5],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// The projective shadow matrix for a point light at `(xl, yl, zl)` onto the plane `y = 0`:
/// move the light to the origin, project onto `y = −yl` (a perspective projection whose last row
/// is `(0, 1/(−yl), 0, 0)`), move back: `M = T(xl, yl, zl)·M_p·T(−xl, −yl, −zl)`, so that after the
/// perspective division
/// `x_p = xl − (x − xl)·yl/(y − yl)`, `y_p = 0`, `z_p = zl − (z − zl)·yl/(y − yl)`.
#[must_use]
pub fn planar_shadow(light: Vec3) -> NamedMatrix {
    let m_p = rows([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, -1.0 / light.y, 0.0, 0.0],
    ]);
    let (to, back) = (translate(-light), translate(light));
    NamedMatrix::new(
        "M_shadow = T(l)·M_p·T(−l)",
        "project from the light onto the plane y = 0",
        back * m_p * to,
    )
    .with_factors(vec![
        NamedMatrix::new("T(l)", "move the light back to (xl, yl, zl)", back),
        NamedMatrix::new("M_p", "perspective projection onto y = −yl", m_p),
        NamedMatrix::new("T(−l)", "move the light to the origin", to),
    ])
}

/// Applies a homogeneous matrix to a point `(x, y, z, 1)`.
#[must_use]
pub fn apply_point(m: &Mat4, p: Vec3) -> Vec4 {
    *m * p.extend(1.0)
}
