//! The viewing transform: the camera frame `u, v, n` of Angel's `LookAt`, and GAMES101's
//! `M_view = R_view·T_view` from the gaze `g` and up `t`.

use glam::{Mat4, Vec3};
use serde::Serialize;

use super::{NamedMatrix, TransformError, rows, translate};

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
