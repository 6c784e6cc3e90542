//! Lighting eight points at once: [`super::shade`]'s formulas in structure-of-arrays lanes
//! (`wide::f32x8`: SSE on x86-64), for the pixels of a row that one triangle covers: every term
//! ([`shade_lanes`]) or the colour alone ([`shade_lanes_color`]).
//!
//! Every lane performs the scalar path's operations in the same order — `v·w = (x·x' + y·y') +
//! z·z'`, `normalize(v) = v·(1/√(v·v))` or zero, `f_att = 1/((a + b·d) + c·d·d)` — and IEEE
//! addition, multiplication, division and square root are correctly rounded in a SIMD lane as in a
//! scalar register, so each lane equals what [`super::shade`] gives for its point, bit for bit.
//! The powers (`max(n·h, 0)^β`, a spotlight's `(cos φ)^e`) are [`power::pow_lanes`], whose lane
//! is the scalar path's [`power::pow`]. The tests hold the two paths to that equality.

use glam::Vec3;
use wide::f32x8;

use super::{Reflection, ShadeTerms, power};
use crate::light::{Light, Material};

/// How many points one call lights.
pub const LANES: usize = 8;

/// Eight 3-vectors, one per lane, as three vectors of eight components.
#[derive(Clone, Copy)]
struct V3 {
    x: f32x8,
    y: f32x8,
    z: f32x8,
}

impl V3 {
    const ZERO: Self = Self::splat(Vec3::ZERO);

    const fn splat(v: Vec3) -> Self {
        Self {
            x: f32x8::splat(v.x),
            y: f32x8::splat(v.y),
            z: f32x8::splat(v.z),
        }
    }

    /// The lanes of `v` (at most [`LANES`]); lanes past its end are zero.
    fn gather(v: &[Vec3]) -> Self {
        let mut c = [[0.0f32; LANES]; 3];
        for (k, p) in v.iter().enumerate().take(LANES) {
            (c[0][k], c[1][k], c[2][k]) = (p.x, p.y, p.z);
        }
        Self {
            x: f32x8::new(c[0]),
            y: f32x8::new(c[1]),
            z: f32x8::new(c[2]),
        }
    }

    /// Lane `k` as a `Vec3`.
    fn lane(&self, k: usize) -> Vec3 {
        Vec3::new(
            self.x.as_array()[k],
            self.y.as_array()[k],
            self.z.as_array()[k],
        )
    }

    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }

    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }

    /// Component by component.
    fn mul(self, o: Self) -> Self {
        Self {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }

    fn scale(self, s: f32x8) -> Self {
        Self {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    /// The lanes where `mask` is set, zero elsewhere.
    fn keep(self, mask: f32x8) -> Self {
        Self {
            x: mask.select(self.x, f32x8::ZERO),
            y: mask.select(self.y, f32x8::ZERO),
            z: mask.select(self.z, f32x8::ZERO),
        }
    }

    /// `(x·x' + y·y') + z·z'`, as glam's `Vec3::dot`.
    fn dot(self, o: Self) -> f32x8 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `v·(1/|v|)`, or zero where `1/|v|` is not finite and positive (glam's
    /// `normalize_or_zero`).
    fn normalize_or_zero(self) -> Self {
        let rcp = f32x8::ONE / self.dot(self).sqrt();
        let ok = rcp.simd_gt(f32x8::ZERO) & rcp.simd_lt(f32x8::INFINITY);
        self.scale(rcp).keep(ok)
    }
}

/// `max(a, 0)` as `f32::max` gives it (zero for NaN) — up to the sign of a zero, which the sums
/// it enters do not keep.
fn positive_part(a: f32x8) -> f32x8 {
    a.simd_gt(f32x8::ZERO).select(a, f32x8::ZERO)
}

/// What lights a run's points: the eye they are seen from, the lights, the material and the
/// reflection model.
#[derive(Clone, Copy)]
pub struct Lighting<'a> {
    /// The eye (world coordinates).
    pub eye: Vec3,
    /// The scene's lights.
    pub lights: &'a [Light],
    /// The object's material.
    pub material: &'a Material,
    /// Phong or Blinn-Phong.
    pub model: Reflection,
}

/// Lights the points `p` (world coordinates) with normals `n` (not yet unit) and surface
/// colours `c` — one point a lane, at most [`LANES`] — as `lighting` says: for each `k`,
/// `out[k]` becomes exactly `shade(p[k], n[k], eye, c[k], lights, material, model)`.
///
/// # Panics
/// If the slices' lengths differ or exceed [`LANES`].
pub fn shade_lanes(
    p: &[Vec3],
    n: &[Vec3],
    c: &[Vec3],
    lighting: &Lighting,
    out: &mut [ShadeTerms],
) {
    let lit = light_lanes(p, n, c, lighting, out.len());
    for (k, o) in out.iter_mut().enumerate() {
        let (light, half, n_dot_l, n_dot_h) =
            lit.key.map_or((Vec3::ZERO, Vec3::ZERO, 0.0, 0.0), |t| {
                (
                    t.0.lane(k),
                    t.1.lane(k),
                    t.2.as_array()[k],
                    t.3.as_array()[k],
                )
            });
        *o = ShadeTerms {
            ambient: lit.ambient.lane(k),
            diffuse: lit.diffuse.lane(k),
            specular: lit.specular.lane(k),
            reflected: Vec3::ZERO,
            normal: lit.normal.lane(k),
            light,
            half,
            n_dot_l,
            n_dot_h,
        };
    }
}

/// The colours alone of [`shade_lanes`]' points: `out[k]` becomes exactly
/// `shade(…).color()`, `((ambient + diffuse) + specular) + reflected` with nothing reflected,
/// without the terms a frame that keeps only its colour has no use for (their transposition
/// out of the lanes was a sixth of a textured run's shading).
///
/// # Panics
/// If the slices' lengths differ or exceed [`LANES`].
pub fn shade_lanes_color(
    p: &[Vec3],
    n: &[Vec3],
    c: &[Vec3],
    lighting: &Lighting,
    out: &mut [Vec3],
) {
    let lit = light_lanes(p, n, c, lighting, out.len());
    let color = lit.ambient.add(lit.diffuse).add(lit.specular).add(V3::ZERO);
    for (k, o) in out.iter_mut().enumerate() {
        *o = color.lane(k);
    }
}

/// What lighting eight points leaves in lanes: the three terms, the unit normal, and the first
/// directed light's `(l, h, n·l, n·h or r·v)` (the terms' key light), if there is one.
struct LitLanes {
    ambient: V3,
    diffuse: V3,
    specular: V3,
    normal: V3,
    key: Option<(V3, V3, f32x8, f32x8)>,
}

/// [`shade_lanes`]' lighting of `count` points, left in lanes.
///
/// # Panics
/// If the slices' lengths differ from `count` or `count` exceeds [`LANES`].
fn light_lanes(p: &[Vec3], n: &[Vec3], c: &[Vec3], lighting: &Lighting, count: usize) -> LitLanes {
    assert!(count <= LANES && p.len() == count && n.len() == count && c.len() == count);
    let &Lighting {
        eye,
        lights,
        material: m,
        model,
    } = lighting;
    let (p, c) = (V3::gather(p), V3::gather(c));
    let n = V3::gather(n).normalize_or_zero();
    let v = V3::splat(eye).sub(p).normalize_or_zero();
    let (mut ambient, mut diffuse, mut specular) = (V3::ZERO, V3::ZERO, V3::ZERO);
    let mut key: Option<(V3, V3, f32x8, f32x8)> = None;
    for light in lights {
        let (l, intensity, factor) = match *light {
            Light::Ambient { intensity } => {
                ambient = ambient.add(V3::splat(m.ka).mul(c).mul(V3::splat(intensity)));
                continue;
            }
            Light::Directional {
                direction,
                intensity,
            } => (
                V3::splat(-direction.normalize_or_zero()),
                intensity,
                f32x8::ONE,
            ),
            Light::Point {
                position,
                intensity,
                attenuation,
            } => {
                let to = V3::splat(position).sub(p);
                let f_att = attenuation_lanes(attenuation, to.dot(to).sqrt());
                // `factor = f_att·f_spot` with `f_spot = 1`.
                (to.normalize_or_zero(), intensity, f_att * f32x8::ONE)
            }
            Light::Spot {
                position,
                direction,
                cutoff_deg,
                exponent,
                intensity,
                attenuation,
            } => {
                let to = V3::splat(position).sub(p);
                let l = to.normalize_or_zero();
                let f_att = attenuation_lanes(attenuation, to.dot(to).sqrt());
                let spot = spot_factor_lanes(l, direction, cutoff_deg, exponent);
                (l, intensity, f_att * spot)
            }
        };
        let n_dot_l = n.dot(l);
        let h = l.add(v).normalize_or_zero();
        let spec_dot = match model {
            Reflection::Phong => {
                let r = n.scale(f32x8::splat(2.0) * n_dot_l).sub(l);
                r.dot(v)
            }
            Reflection::BlinnPhong => n.dot(h),
        };
        let lit = n_dot_l.simd_gt(f32x8::ZERO);
        let power = power::pow_lanes(spec_dot.max(f32x8::ZERO), f32x8::splat(m.shininess));
        let intensity = V3::splat(intensity);
        let spec = V3::splat(m.ks).scale(factor).mul(intensity).scale(power);
        specular = specular.add(spec.keep(lit));
        let diff = V3::splat(m.kd)
            .scale(factor)
            .mul(c)
            .mul(intensity)
            .scale(positive_part(n_dot_l));
        diffuse = diffuse.add(diff);
        key.get_or_insert((l, h, n_dot_l, spec_dot));
    }
    LitLanes {
        ambient,
        diffuse,
        specular,
        normal: n,
        key,
    }
}

/// [`super::spot_factor`] lane by lane: `(cos φ)^e` with `cos φ = (−l)·axis`, 0 where
/// `cos φ < cos θ`.
fn spot_factor_lanes(l: V3, axis: Vec3, cutoff_deg: f32, exponent: f32) -> f32x8 {
    // `−l` as the scalar path negates: multiplying by −1 flips the sign bit and nothing else.
    let cos_phi = l
        .scale(f32x8::splat(-1.0))
        .dot(V3::splat(axis.normalize_or_zero()));
    let outside = cos_phi.simd_lt(f32x8::splat(cutoff_deg.to_radians().cos()));
    let power = power::pow_lanes(cos_phi.max(f32x8::ZERO), f32x8::splat(exponent));
    outside.select(f32x8::ZERO, power)
}

/// [`super::attenuation`] lane by lane: `1/((a + b·d) + c·d·d)`, 1 where that denominator is
/// not positive.
fn attenuation_lanes(abc: Vec3, d: f32x8) -> f32x8 {
    let denom = f32x8::splat(abc.x) + f32x8::splat(abc.y) * d + f32x8::splat(abc.z) * d * d;
    denom
        .simd_gt(f32x8::ZERO)
        .select(f32x8::ONE / denom, f32x8::ONE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::shade;

    /// A small deterministic generator (xorshift).
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 40) as f32 / (1u64 << 24) as f32
        }

        fn vec(&mut self, scale: f32) -> Vec3 {
            Vec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * scale
        }
    }

    fn lights(r: &mut Rng) -> Vec<Light> {
        vec![
            Light::Ambient {
                intensity: r.vec(1.0).abs(),
            },
            Light::Point {
                position: r.vec(8.0),
                intensity: r.vec(2.0).abs(),
                attenuation: Vec3::new(1.0, r.next(), r.next() * 0.2),
            },
            Light::Directional {
                direction: r.vec(1.0),
                intensity: r.vec(1.0).abs(),
            },
            Light::Spot {
                position: r.vec(8.0),
                direction: r.vec(1.0),
                cutoff_deg: 10.0 + 60.0 * r.next(),
                exponent: 4.0 * r.next(),
                intensity: r.vec(2.0).abs(),
                attenuation: Vec3::new(1.0, 0.0, 0.0),
            },
            Light::Point {
                position: Vec3::ZERO,
                intensity: Vec3::ONE,
                attenuation: Vec3::new(0.0, 0.0, 1.0),
            },
        ]
    }

    #[test]
    fn every_lane_equals_the_scalar_shading_bit_for_bit() {
        let mut r = Rng(0x9e37_79b9_7f4a_7c15);
        for round in 0..400 {
            let lights = lights(&mut r);
            let m = Material {
                ka: r.vec(1.0).abs(),
                kd: r.vec(1.0).abs(),
                ks: r.vec(1.0).abs(),
                shininess: 1.0 + 100.0 * r.next(),
            };
            let eye = r.vec(10.0);
            let count = 1 + round % LANES;
            let mut p: Vec<Vec3> = (0..count).map(|_| r.vec(4.0)).collect();
            let mut n: Vec<Vec3> = (0..count).map(|_| r.vec(2.0)).collect();
            let c: Vec<Vec3> = (0..count).map(|_| r.vec(1.0).abs()).collect();
            // Degenerate lanes: a zero normal, a point at the eye, a point at a light.
            n[0] = if round % 3 == 0 { Vec3::ZERO } else { n[0] };
            if round % 5 == 1 {
                p[count - 1] = eye;
            }
            if round % 7 == 2 {
                p[0] = Vec3::ZERO;
            }
            for model in [Reflection::Phong, Reflection::BlinnPhong] {
                let lighting = Lighting {
                    eye,
                    lights: &lights,
                    material: &m,
                    model,
                };
                let mut out = vec![ShadeTerms::default(); count];
                shade_lanes(&p, &n, &c, &lighting, &mut out);
                let mut colors = vec![Vec3::NAN; count];
                shade_lanes_color(&p, &n, &c, &lighting, &mut colors);
                for k in 0..count {
                    let want = shade(p[k], n[k], eye, c[k], &lights, &m, model);
                    assert_eq!(out[k], want, "round {round}, lane {k}, {model:?}");
                    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
                    assert_eq!(
                        bits(colors[k]),
                        bits(want.color()),
                        "colour, round {round}, lane {k}, {model:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn without_lights_every_lane_is_unlit_but_keeps_its_normal() {
        let n = [Vec3::new(0.0, 3.0, 4.0)];
        let mut out = [ShadeTerms::default()];
        let lighting = Lighting {
            eye: Vec3::Z,
            lights: &[],
            material: &Material::default(),
            model: Reflection::BlinnPhong,
        };
        shade_lanes(&[Vec3::ZERO], &n, &[Vec3::ONE], &lighting, &mut out);
        assert_eq!(out[0].normal, Vec3::new(0.0, 0.6, 0.8));
        assert_eq!(out[0].color(), Vec3::ZERO);
    }
}
