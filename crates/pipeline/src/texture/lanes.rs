//! Bilinear lookups eight at a time: each lookup's four texels read by itself (a gather), the
//! weights `s`, `t` and the two blends of all eight in SIMD lanes — each colour what
//! [`Texture::read_level`] gives with bilinear filtering, bit for bit (the same operations in
//! the same order: `lerp(a, b, s) = a·(1 − s) + b·s`, as glam's).

use glam::{Vec2, Vec3};
use wide::f32x8;

use super::{Texture, Wrap};

/// Lookups read together (a run's fragments: the lighting's lanes, which `texture`, below
/// `lighting` in ARCHITECTURE.md's table, does not use).
pub const LANES: usize = 8;

impl Texture {
    /// Level `level[f]` read by bilinear filtering at `uv[f]`, for each lookup `f < n`: with
    /// `x = u·w − ½`, `y = v·h − ½` (the level's `w × h`), texels `(⌊x⌋ + {0, 1}, ⌊y⌋ + {0, 1})`
    /// (wrapped) blended by `s = x − ⌊x⌋` across and then `t = y − ⌊y⌋` up; lookups past `n`
    /// give zero. Level 0 is read from its 8-bit copy where it has one, as
    /// [`Texture::read_level`] reads it.
    #[must_use]
    pub(crate) fn bilinear_lanes(
        &self,
        level: &[usize; LANES],
        uv: &[Vec2; LANES],
        n: usize,
        wrap: Wrap,
    ) -> [Vec3; LANES] {
        // Each lookup's weights and its four texels (as `Level::bilinear_taps` places them),
        // [corner][channel] a lane a lookup: corners (i0, j0), (i1, j0), (i0, j1), (i1, j1).
        let (mut s_of, mut t_of) = ([0.0; LANES], [0.0; LANES]);
        let mut t = [[[0.0; LANES]; 3]; 4];
        for f in 0..n {
            let k = level[f];
            let taps = self.levels[k].bilinear_taps(uv[f], wrap);
            let ([i0, i1], [j0, j1]) = (taps.columns, taps.rows);
            (s_of[f], t_of[f]) = (taps.s, taps.t);
            for (c, (i, j)) in [(i0, j0), (i1, j0), (i0, j1), (i1, j1)]
                .into_iter()
                .enumerate()
            {
                [t[c][0][f], t[c][1][f], t[c][2][f]] = self.texel_of_level(k, i, j).to_array();
            }
        }
        let texels = t.map(|c| c.map(f32x8::new));
        let (s, tt) = (f32x8::new(s_of), f32x8::new(t_of));
        let (one_s, one_t) = (f32x8::ONE - s, f32x8::ONE - tt);
        let channel: [[f32; LANES]; 3] = std::array::from_fn(|ch| {
            let [t00, t10, t01, t11] = texels.map(|c| c[ch]);
            let bottom = t00 * one_s + t10 * s;
            let top = t01 * one_s + t11 * s;
            (bottom * one_t + top * tt).to_array()
        });
        std::array::from_fn(|f| Vec3::new(channel[0][f], channel[1][f], channel[2][f]))
    }
}

#[cfg(test)]
mod tests {
    use glam::{Vec2, Vec3};

    use super::LANES;
    use crate::texture::{Filter, Level, Texture, Wrap};

    /// A `w × h` texture whose texels are `value(i, j)`.
    fn texture(w: u32, h: u32, value: impl Fn(u32, u32) -> Vec3) -> Texture {
        let texels = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| value(i, j));
        Texture::from_level(
            "test",
            Level {
                width: w,
                height: h,
                texels: texels.collect(),
            },
        )
    }

    /// Each lane's colour equals, bit for bit, what [`Texture::read_level`] reads with bilinear
    /// filtering at the same level and place: on a texture of 8-bit texels (level 0 read from
    /// its tiled copy) and on one of any values (−0 among them), of odd sizes (levels whose
    /// last row and column join the box before), both wraps, at random places inside and far
    /// outside `[0, 1]`, on the texels' centres and edges, and at ±∞, NaN and past 2²³ texels;
    /// each lane at a level of its own, and runs of every length from 0 to 8.
    #[test]
    fn every_lane_reads_what_a_lookup_by_itself_reads() {
        let mut rng = fastrand::Rng::with_seed(59);
        let bytes = texture(37, 23, |i, j| {
            Vec3::new(
                ((i * 7 + j) % 256) as f32 / 255.0,
                ((i * j) % 256) as f32 / 255.0,
                ((200 + i + 3 * j) % 256) as f32 / 255.0,
            )
        });
        assert!(bytes.has_8_bit_level0());
        let any = texture(19, 40, |i, j| match (i + j) % 5 {
            0 => Vec3::new(-0.0, 0.0, -0.0),
            1 => Vec3::new(0.1 + i as f32 / 7.0, 1.0 / (1.0 + j as f32), 0.333),
            _ => Vec3::new((i as f32).sin(), (j as f32 * 0.37).cos(), 0.5),
        });
        assert!(!any.has_8_bit_level0());
        let special = [
            0.0,
            -0.0,
            1.0,
            0.5 / 37.0,
            1.5 / 23.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1.0e9,
            -3.0e7,
        ];
        for tex in [&bytes, &any] {
            for wrap in [Wrap::Repeat, Wrap::Clamp] {
                for round in 0..2000 {
                    let n = round % (LANES + 1);
                    let level: [usize; LANES] =
                        std::array::from_fn(|_| rng.usize(..tex.levels.len()));
                    let uv: [Vec2; LANES] = std::array::from_fn(|_| {
                        let mut c = || {
                            if rng.u8(..8) == 0 {
                                special[rng.usize(..special.len())]
                            } else {
                                (rng.f32() - 0.3) * 4.0
                            }
                        };
                        Vec2::new(c(), c())
                    });
                    let got = tex.bilinear_lanes(&level, &uv, n, wrap);
                    for f in 0..n {
                        let want = tex.read_level(level[f], uv[f], Filter::Bilinear, wrap);
                        assert_eq!(
                            got[f].to_array().map(f32::to_bits),
                            want.to_array().map(f32::to_bits),
                            "level {} at {:?}, {wrap:?}: {} against {}",
                            level[f],
                            uv[f],
                            got[f],
                            want
                        );
                    }
                }
            }
        }
    }
}
