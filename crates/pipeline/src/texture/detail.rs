//! What a texture adds to a surface beyond its colour: bump and normal mapping (a perturbed
//! normal in the tangent frame), displacement mapping (vertices moved along their normals) and
//! environment mapping (a cube map seen in the mirror direction).

use glam::{Vec2, Vec3};

use super::{Filter, Level, Mipmap, Sampler, Texture, Wrap};

/// Detail a texture adds to a surface's normal (used where lighting is per pixel).
#[derive(Clone, Debug, PartialEq)]
pub enum SurfaceDetail {
    /// Bump mapping from a height map `h(u, v)` (its texels' luminance), GAMES101's way: in the
    /// tangent frame, `dU = k_h·k_n·(h(u + 1/w, v) − h(u, v))`, `dV = k_h·k_n·(h(u, v + 1/h) −
    /// h(u, v))` (the notes write the first as dp/dv: it is dp/du), the perturbed normal is
    /// `normalize(TBN·(−dU, −dV, 1))`.
    Bump {
        /// The height map.
        height: std::sync::Arc<Texture>,
        /// `k_h·k_n`: how strongly height changes tilt the normal.
        strength: f32,
    },
    /// Normal mapping: the texel is a tangent-space normal, `n_t = 2·c − 1`, and the normal is
    /// `normalize(TBN·n_t)`.
    Normal(std::sync::Arc<Texture>),
}

/// The tangent and bitangent of a triangle from its positions and texture coordinates, the
/// directions in which `u` and `v` grow:
/// `T = (Δp₁·Δv₂ − Δp₂·Δv₁)/det`, `B = (Δp₂·Δu₁ − Δp₁·Δu₂)/det`, `det = Δu₁·Δv₂ − Δu₂·Δv₁`.
/// `None` when the uvs are degenerate.
#[must_use]
pub fn tangent_frame(p: [Vec3; 3], uv: [Vec2; 3]) -> Option<(Vec3, Vec3)> {
    let (dp1, dp2) = (p[1] - p[0], p[2] - p[0]);
    let (d1, d2) = (uv[1] - uv[0], uv[2] - uv[0]);
    let det = d1.x * d2.y - d2.x * d1.y;
    if det.abs() < 1e-12 {
        return None;
    }
    Some((
        (dp1 * d2.y - dp2 * d1.y) / det,
        (dp2 * d1.x - dp1 * d2.x) / det,
    ))
}

impl SurfaceDetail {
    /// How a bump or normal map is read (here and, as `uniform sampler2D detail;`, by the
    /// student's shaders): bilinear, repeating, level 0.
    pub const MAP_SAMPLER: Sampler = Sampler {
        wrap: Wrap::Repeat,
        filter: Filter::Bilinear,
        mipmap: Mipmap::None,
        anisotropy: 1,
        lod_bias: 0.0,
    };

    /// The normal at `uv` perturbed from the unit normal `n` in the tangent frame `(t, b)`
    /// (made orthonormal to `n` first: `T' = normalize(t − n(n·t))`, `B' = ±n × T'`).
    #[must_use]
    pub fn perturb(&self, n: Vec3, t: Vec3, b: Vec3, uv: Vec2) -> Vec3 {
        let n = n.normalize_or_zero();
        let t1 = (t - n * n.dot(t)).normalize_or_zero();
        let handed = if n.cross(t1).dot(b) < 0.0 { -1.0 } else { 1.0 };
        let b1 = n.cross(t1) * handed;
        let local = match self {
            Self::Bump { height, strength } => {
                let l = &height.levels[0];
                let h = |uv: Vec2| {
                    let c = l.bilinear(uv, Wrap::Repeat);
                    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
                };
                let here = h(uv);
                let du = strength * (h(uv + Vec2::new(1.0 / l.width as f32, 0.0)) - here);
                let dv = strength * (h(uv + Vec2::new(0.0, 1.0 / l.height as f32)) - here);
                Vec3::new(-du, -dv, 1.0)
            }
            Self::Normal(map) => map.levels[0].bilinear(uv, Wrap::Repeat) * 2.0 - Vec3::ONE,
        };
        (t1 * local.x + b1 * local.y + n * local.z).normalize_or_zero()
    }
}

/// Displacement mapping: every vertex moves along its normal by `scale·h(u, v)`, `h` the
/// height map's luminance (bilinear, level 0). It changes geometry, so it needs a finely
/// subdivided mesh; the normals are left as they were (add bump mapping with the same map to
/// light the new relief).
#[derive(Clone, Debug, PartialEq)]
pub struct Displacement {
    /// The height map.
    pub height: std::sync::Arc<Texture>,
    /// The largest displacement, in object units.
    pub scale: f32,
}

impl Displacement {
    /// `scale·h(u, v)`.
    #[must_use]
    pub fn offset(&self, uv: Vec2) -> f32 {
        let c = self.height.levels[0].bilinear(uv, Wrap::Repeat);
        self.scale * (0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z)
    }
}

/// A cube map: six square faces around the origin, looked up by direction (environment mapping).
/// Faces in the order +x, −x, +y, −y, +z, −z; on each, `(s, t)` run as in OpenGL's cube map table
/// (major axis `m`, `s = (sc/|m| + 1)/2`, `t = (tc/|m| + 1)/2`):
/// +x: `sc = −z, tc = y`; −x: `sc = z, tc = y`; +y: `sc = x, tc = −z`; −y: `sc = x, tc = z`;
/// +z: `sc = x, tc = y`; −z: `sc = −x, tc = y` — with `t` growing upwards (our texel rows count
/// from the bottom), so each face reads as seen from the centre with +y up.
#[derive(Clone, Debug, PartialEq)]
pub struct CubeMap {
    /// The faces +x, −x, +y, −y, +z, −z.
    pub faces: [Level; 6],
}

impl CubeMap {
    /// The faces' names, in order.
    pub const FACES: [&'static str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];

    /// The face and `(s, t)` a direction falls on.
    #[must_use]
    pub fn face_coords(d: Vec3) -> (usize, Vec2) {
        let a = d.abs();
        let (face, sc, tc, m) = if a.x >= a.y && a.x >= a.z {
            if d.x > 0.0 {
                (0, -d.z, d.y, a.x)
            } else {
                (1, d.z, d.y, a.x)
            }
        } else if a.y >= a.z {
            if d.y > 0.0 {
                (2, d.x, -d.z, a.y)
            } else {
                (3, d.x, d.z, a.y)
            }
        } else if d.z > 0.0 {
            (4, d.x, d.y, a.z)
        } else {
            (5, -d.x, d.y, a.z)
        };
        let m = m.max(1e-12);
        (face, Vec2::new((sc / m + 1.0) / 2.0, (tc / m + 1.0) / 2.0))
    }

    /// The colour seen in direction `d` (bilinear within the face, edges clamped).
    #[must_use]
    pub fn sample(&self, d: Vec3) -> Vec3 {
        let (face, st) = Self::face_coords(d);
        self.faces[face].bilinear(st, Wrap::Clamp)
    }

    /// A procedural room: a sky gradient above, a checkered floor below, four walls each in its
    /// own colour with a grid, so a reflection shows which way it looks.
    #[must_use]
    pub fn room(size: u32) -> Self {
        let size = size.max(2);
        let face = |f: &dyn Fn(f32, f32) -> Vec3| {
            let texels = (0..size)
                .flat_map(|j| (0..size).map(move |i| (i, j)))
                .map(|(i, j)| {
                    f(
                        (i as f32 + 0.5) / size as f32,
                        (j as f32 + 0.5) / size as f32,
                    )
                })
                .collect();
            Level {
                width: size,
                height: size,
                texels,
            }
        };
        let wall = |c: Vec3| {
            move |s: f32, t: f32| {
                let grid = ((s * 8.0).fract() < 0.06) || ((t * 8.0).fract() < 0.06);
                let shade = 0.55 + 0.45 * t;
                if grid { Vec3::splat(0.95) } else { c * shade }
            }
        };
        let sky = |s: f32, t: f32| {
            let r = ((s - 0.5).powi(2) + (t - 0.5).powi(2)).sqrt();
            Vec3::new(0.45, 0.65, 0.95)
                .lerp(Vec3::new(1.0, 0.97, 0.85), (1.0 - r * 3.0).clamp(0.0, 1.0))
        };
        let floor = |s: f32, t: f32| {
            if ((s * 8.0) as u32 + (t * 8.0) as u32).is_multiple_of(2) {
                Vec3::splat(0.8)
            } else {
                Vec3::splat(0.25)
            }
        };
        Self {
            faces: [
                face(&wall(Vec3::new(0.9, 0.3, 0.3))),
                face(&wall(Vec3::new(0.3, 0.8, 0.4))),
                face(&sky),
                face(&floor),
                face(&wall(Vec3::new(0.3, 0.45, 0.9))),
                face(&wall(Vec3::new(0.9, 0.8, 0.3))),
            ],
        }
    }
}

/// Environment mapping: the surface mirrors the cube map in direction `r = 2(n·v)n − v`,
/// mixed into its lit colour by `reflectivity` (per-pixel lighting only).
#[derive(Clone, Debug, PartialEq)]
pub struct Environment {
    /// What the surface reflects.
    pub cube: std::sync::Arc<CubeMap>,
    /// 0: no reflection, 1: a perfect mirror.
    pub reflectivity: f32,
}

/// The built-in height and normal maps the lessons' surface detail uses.
impl Texture {
    /// A height map of round bumps on a grid (`count × count` of them), for bump mapping.
    #[must_use]
    pub fn bumps(size: u32, count: u32) -> Self {
        let mut t = Self::from_fn("bumps", size, |i, j| {
            let cell = size as f32 / count.max(1) as f32;
            let (x, y) = (
                (i as f32 + 0.5) % cell / cell - 0.5,
                (j as f32 + 0.5) % cell / cell - 0.5,
            );
            let r2 = (x * x + y * y) * 4.0;
            Vec3::splat((1.0 - r2).max(0.0).sqrt())
        });
        t.name = "bumps".to_owned();
        t
    }

    /// A relief for the labs: round bumps `cell` texels across on a `width × height` map that
    /// is not square, with channels that differ — `(h, h², 1 − h)` for the bump's height `h` —
    /// so that a bump map stepping by 1/h where it should step by 1/w, or a displacement reading
    /// one channel where it should read the luminance, draws another picture.
    #[must_use]
    pub fn relief(width: u32, height: u32, cell: u32) -> Self {
        let cell = cell.max(1) as f32;
        let mut t = Self::from_fn_sized("relief", (width, height), |i, j| {
            let (x, y) = (
                (i as f32 + 0.5) % cell / cell - 0.5,
                (j as f32 + 0.5) % cell / cell - 0.5,
            );
            let h = (1.0 - (x * x + y * y) * 4.0).max(0.0).sqrt();
            Vec3::new(h, h * h, 1.0 - h)
        });
        t.name = "relief".to_owned();
        t
    }

    /// The tangent-space normal map of the same bumps: from the height's central differences
    /// `∂h/∂u, ∂h/∂v` (per texel, times `strength`), `n = normalize(−∂h/∂u, −∂h/∂v, 1)` stored
    /// as `(n + 1)/2` — what a normal map holds, so that normal mapping reproduces bump mapping.
    #[must_use]
    pub fn bump_normals(size: u32, count: u32, strength: f32) -> Self {
        Self::normals_of(&Self::bumps(size, count), strength, "bump_normals")
    }

    /// The tangent-space normal map of [`Self::relief`]'s heights (their luminance), as
    /// [`Self::bump_normals`] is of the bumps: normal mapping with it reproduces bump mapping
    /// with the relief.
    #[must_use]
    pub fn relief_normals(width: u32, height: u32, cell: u32, strength: f32) -> Self {
        Self::normals_of(
            &Self::relief(width, height, cell),
            strength,
            "relief_normals",
        )
    }

    /// The normal map of a height map (its texels' luminance): central differences per texel,
    /// times `strength`, `n = normalize(−∂h/∂u, −∂h/∂v, 1)` stored as `(n + 1)/2`.
    fn normals_of(height: &Self, strength: f32, name: &str) -> Self {
        let l = &height.levels[0];
        let luminance = Vec3::new(0.2126, 0.7152, 0.0722);
        let h = |i: i64, j: i64| l.texel(i, j, Wrap::Repeat).dot(luminance);
        let mut t = Self::from_fn_sized(name, (l.width, l.height), |i, j| {
            let (i, j) = (i64::from(i), i64::from(j));
            let du = (h(i + 1, j) - h(i - 1, j)) / 2.0 * strength;
            let dv = (h(i, j + 1) - h(i, j - 1)) / 2.0 * strength;
            (Vec3::new(-du, -dv, 1.0).normalize() + Vec3::ONE) / 2.0
        });
        t.name = name.to_owned();
        t
    }
}
