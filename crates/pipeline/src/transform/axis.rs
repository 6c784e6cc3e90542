//! Rotation about an arbitrary axis: the notes' construction `Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)`,
//! Rodrigues' formula, and unit quaternions.

use glam::{Mat3, Mat4, Vec3};
use serde::Serialize;

use super::{NamedMatrix, TransformError, rotate_x, rotate_y, rotate_z, rows};

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

impl Quaternion {
    /// The 4-D dot product `q·r = w_q·w_r + v_q·v_r`: the cosine of the angle `Ω` between the
    /// two unit quaternions on the unit sphere in 4-D.
    #[must_use]
    pub fn dot(&self, other: &Self) -> f32 {
        self.w * other.w + self.v.dot(other.v)
    }

    /// `(w, v) → (−w, −v)`: the same rotation, from the other side of the sphere.
    #[must_use]
    pub fn negated(&self) -> Self {
        Self {
            w: -self.w,
            v: -self.v,
        }
    }

    /// Spherical linear interpolation from `self` (`t = 0`) to `to` (`t = 1`) along the shorter
    /// great arc:
    ///
    /// `slerp(q₀, q₁, t) = sin((1 − t)·Ω)/sin Ω · q₀ + sin(t·Ω)/sin Ω · q₁`, `cos Ω = q₀·q₁`,
    ///
    /// with `q₁` replaced by `−q₁` when `q₀·q₁ < 0` (the same rotation, the shorter way round).
    /// The result turns at a constant angular speed, by `2Ω` in all. When the two nearly coincide
    /// (`sin Ω → 0`) it falls back to the normalized linear blend, which is the same to first order.
    #[must_use]
    pub fn slerp(&self, to: &Self, t: f32) -> Self {
        let arc = self.arc_to(to);
        let (a, b) = arc.weights(t);
        let (w, v) = (a * self.w + b * arc.end.w, a * self.v + b * arc.end.v);
        let length = (w * w + v.length_squared()).sqrt();
        Self {
            w: w / length,
            v: v / length,
        }
    }

    /// The shorter great arc from `self` to `to` (see [`Self::slerp`]).
    #[must_use]
    pub fn arc_to(&self, to: &Self) -> GreatArc {
        let d = self.dot(to);
        let (end, flipped) = if d < 0.0 {
            (to.negated(), true)
        } else {
            (*to, false)
        };
        GreatArc {
            omega: d.abs().min(1.0).acos(),
            end,
            flipped,
        }
    }

    /// The rotation as an axis (unit length; `+x` for no rotation) and an angle in `[0, 2π]`:
    /// `θ = 2·acos w`, `n = v / sin(θ/2)`.
    #[must_use]
    pub fn axis_angle(&self) -> (Vec3, f32) {
        let theta = 2.0 * self.w.clamp(-1.0, 1.0).acos();
        (self.v.try_normalize().unwrap_or(Vec3::X), theta)
    }
}

/// The shorter great arc between two unit quaternions, as slerp travels it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct GreatArc {
    /// `Ω = acos |q₀·q₁|`, radians: half the angle of the rotation from one orientation to the other.
    pub omega: f32,
    /// `q₁`, or `−q₁` when that is nearer `q₀`.
    pub end: Quaternion,
    /// Whether `q₁` was negated.
    pub flipped: bool,
}

impl GreatArc {
    /// slerp's weights of `q₀` and of the arc's end at `t`: `sin((1 − t)Ω)/sin Ω` and `sin(tΩ)/sin Ω`
    /// (`1 − t` and `t` when `sin Ω` is too small to divide by).
    #[must_use]
    pub fn weights(&self, t: f32) -> (f32, f32) {
        let s = self.omega.sin();
        if s < 1e-4 {
            (1.0 - t, t)
        } else {
            (
                ((1.0 - t) * self.omega).sin() / s,
                (t * self.omega).sin() / s,
            )
        }
    }
}

/// An object's orientation moving by slerp from its rotation about an axis (`q₀`) to a second
/// rotation about an axis (`q₁`): the rotation at `t` is `slerp(q₀, q₁, t)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SlerpTo {
    /// The second orientation's axis (any length but zero).
    pub axis: Vec3,
    /// The second orientation's angle about it, degrees.
    pub angle_deg: f32,
    /// How far along the arc, `0` (the first orientation) to `1` (the second).
    pub t: f32,
}

impl SlerpTo {
    /// The quaternions of the two orientations, the first being the rotation by `from_deg` about
    /// `from_axis`.
    ///
    /// # Errors
    /// [`TransformError::ZeroAxis`] when either axis has no length.
    pub fn ends(
        &self,
        from_axis: Vec3,
        from_deg: f32,
    ) -> Result<(Quaternion, Quaternion), TransformError> {
        Ok((
            Quaternion::from_axis_angle(from_axis, from_deg.to_radians())?,
            Quaternion::from_axis_angle(self.axis, self.angle_deg.to_radians())?,
        ))
    }

    /// The rotation `R(slerp(q₀, q₁, t))` as a named matrix.
    ///
    /// # Errors
    /// [`TransformError::ZeroAxis`] when either axis has no length.
    pub fn matrix(&self, from_axis: Vec3, from_deg: f32) -> Result<NamedMatrix, TransformError> {
        let (q0, q1) = self.ends(from_axis, from_deg)?;
        Ok(NamedMatrix::new(
            "R(slerp(q₀, q₁, t))",
            "the rotation part way from the first orientation to the second, along the shorter arc",
            q0.slerp(&q1, self.t).to_matrix(),
        ))
    }
}
