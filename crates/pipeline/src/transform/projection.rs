//! Projections: Angel's / OpenGL's `Ortho`, `Frustum` (`N·S·H`) and `Perspective`, GAMES101's
//! `M_ortho·M_persp→ortho`, the relation between the two, the viewport transform, and the
//! projective shadow matrix.

use glam::{Mat4, Vec3};

use super::{NamedMatrix, Shear, rows, scale, shear, translate};

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
