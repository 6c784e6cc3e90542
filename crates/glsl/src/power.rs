//! The power `x^y` of the specular term `max(n·h, 0)^β`, a spotlight's `(cos φ)^e` and the
//! student's shaders' `pow`, eight lanes at a time.
//!
//! `x^y = e^(y·ln x)`, evaluated as `wide`'s `powf_simd` does it (Agner Fog's vector class
//! library): `x = m·2^k` with `m ∈ [√½, √2)`, `ln m` by a degree-8 polynomial in `m − 1`, the
//! product `y·ln x` carried with its rounding error, and `e^r` by a degree-7 Taylor polynomial
//! after taking out whole powers of two (`r ∈ [−ln2/2, ln2/2]`). No libm call: WebAssembly has no
//! `pow` instruction, and libm's software `powf` was a fifth of a frame in the page.
//!
//! **Error**, measured by the tests against `f64::powf` rounded to `f32`, for `x ∈ [2⁻²⁰, 2²⁰]` and
//! `|y| ≤ 1024` where the result is a normal `f32`: at most [`ULP_FACTOR`]`·(1 + |y·ln x|)` units in
//! the last place. It grows with the exponent `y·ln x` because without a fused multiply-add (x86-64's
//! baseline, WebAssembly) the product `y·ln x` keeps one rounding. A highlight that reaches an 8-bit
//! colour (`x ∈ [0, 1]`, `x^β ≥ 2⁻¹²`, so `|y·ln x| ≤ 8.4`) is within 12 ulps (measured: a relative 10⁻⁶) —
//! four orders below the 1/255 of a colour channel. `x^0 = 1` (also `0^0`), `1^y = 1`,
//! `0^y = 0` for `y > 0` and `+∞` for `y < 0`, exactly; a negative `x` gives NaN unless `y` is an
//! integer (GLSL leaves `pow` undefined there).
//!
//! The scalar [`pow`] is lane 0 of [`pow_lanes`], so the per-pixel path and the lanes agree bit
//! for bit: each lane's result depends on that lane's inputs only.

use wide::f32x8;

/// The measured bound of [`pow`]'s error: at most `ULP_FACTOR·(1 + |y·ln x|)` units in the last
/// place where the result is a normal `f32` (see the module's notes).
pub const ULP_FACTOR: f64 = 1.25;

/// `x^y` lane by lane.
#[inline]
#[must_use]
pub fn pow_lanes(x: f32x8, y: f32x8) -> f32x8 {
    x.powf_simd(y)
}

/// `x^y` for one value: lane 0 of [`pow_lanes`].
#[inline]
#[must_use]
pub fn pow(x: f32, y: f32) -> f32 {
    pow_lanes(f32x8::splat(x), f32x8::splat(y)).as_array()[0]
}

/// `x[i]^y[i]` into `out[i]` for three slices of `f32` bits (the shader machine's registers),
/// eight at a time.
pub fn pow_bits(x: &[u32], y: &[u32], out: &mut [u32]) {
    let lanes = |v: &[u32]| {
        f32x8::new(std::array::from_fn(|k| {
            v.get(k).map_or(1.0, |b| f32::from_bits(*b))
        }))
    };
    for ((x, y), out) in x.chunks(8).zip(y.chunks(8)).zip(out.chunks_mut(8)) {
        let p = pow_lanes(lanes(x), lanes(y));
        for (o, v) in out.iter_mut().zip(p.as_array()) {
            *o = v.to_bits();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The distance between two finite `f32` of one sign, in units in the last place.
    fn ulps(a: f32, b: f32) -> u32 {
        a.to_bits().abs_diff(b.to_bits())
    }

    /// `x^y` in `f64`, rounded once to `f32`.
    fn exact(x: f32, y: f32) -> f32 {
        f64::from(x).powf(f64::from(y)) as f32
    }

    #[test]
    fn the_error_stays_within_the_stated_bound_over_the_shading_range_and_beyond() {
        // (ulps / (1 + |y·ln x|), x, y, ulps) at the worst point.
        let mut worst = (0.0, 0.0, 0.0, 0);
        // x from 2^-20 to 2^20 in 4 000 logarithmic steps (and every step's neighbour bits),
        // y over the shininess range and the shaders' range, negative too.
        let ys: Vec<f32> = (0..=400)
            .map(|i| i as f32 * 0.37)
            .chain([0.5, 1.0, 2.0, 5.0, 32.0, 128.0, 1000.0, 1024.0])
            .flat_map(|y| [y, -y])
            .collect();
        for i in 0..=4000 {
            let base = (f64::from(i) / 100.0 - 20.0).exp2() as f32;
            for x in [base, f32::from_bits(base.to_bits() + 1)] {
                for &y in &ys {
                    let want = exact(x, y);
                    if !want.is_normal() {
                        continue;
                    }
                    let e = ulps(pow(x, y), want);
                    let scaled = f64::from(e) / (1.0 + (f64::from(y) * f64::from(x).ln()).abs());
                    if scaled > worst.0 {
                        worst = (scaled, x, y, e);
                    }
                }
            }
        }
        assert!(
            worst.0 <= ULP_FACTOR,
            "{} ulps at {}^{}: {} ulps per unit of 1 + |y·ln x| (bound {ULP_FACTOR})",
            worst.3,
            worst.1,
            worst.2,
            worst.0
        );
    }

    #[test]
    fn a_highlight_is_within_a_millionth() {
        // The shading range: x ∈ [0, 1], β ≤ 256, results that reach an 8-bit colour (≥ 2^-12).
        for i in 1..=1000 {
            let x = i as f32 / 1000.0;
            for beta in [1.0, 5.0, 32.0, 100.0, 256.0] {
                let want = f64::from(x).powf(f64::from(beta));
                if want >= 2f64.powi(-12) {
                    let rel = (f64::from(pow(x, beta)) - want).abs() / want;
                    assert!(rel < 1e-6, "{x}^{beta}: relative error {rel:e}");
                }
            }
        }
    }

    #[test]
    fn the_exact_cases_are_exact() {
        for x in [0.0, 0.25, 1.0, 3.0, 1e6] {
            assert_eq!(pow(x, 0.0), 1.0, "{x}^0");
        }
        for y in [-3.0, 0.5, 1.0, 7.5, 200.0] {
            assert_eq!(pow(1.0, y), 1.0, "1^{y}");
        }
        for y in [0.5, 1.0, 64.0] {
            assert_eq!(pow(0.0, y), 0.0, "0^{y}");
        }
        assert_eq!(pow(0.0, -1.0), f32::INFINITY);
        assert_eq!(pow(2.0, 10.0), 1024.0);
        assert_eq!(pow(-2.0, 3.0), -8.0);
        assert!(pow(-2.0, 0.5).is_nan());
        assert!(pow(f32::NAN, 2.0).is_nan());
    }

    #[test]
    fn each_lane_is_the_scalar_power_whatever_its_neighbours() {
        // A negative, a zero and a NaN in other lanes change no lane's result.
        let x = [0.3, -2.0, 0.0, f32::NAN, 0.999, 17.0, 1e-5, 0.5];
        let y = [40.0, 3.0, 5.0, 1.0, 512.0, 0.5, 2.0, -3.0];
        let lanes = pow_lanes(f32x8::new(x), f32x8::new(y));
        for k in 0..8 {
            let (a, b) = (lanes.as_array()[k], pow(x[k], y[k]));
            assert!(a.to_bits() == b.to_bits(), "lane {k}: {a} against {b}");
        }
        let mut out = [0; 11];
        let bits = |v: &[f32]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
        let (xs, ys) = (
            [x.as_slice(), &[2.0, 9.0, 0.1]].concat(),
            [y.as_slice(), &[3.0, 0.5, 1.0]].concat(),
        );
        pow_bits(&bits(&xs), &bits(&ys), &mut out);
        for k in 0..11 {
            assert_eq!(out[k], pow(xs[k], ys[k]).to_bits(), "pow_bits lane {k}");
        }
    }
}
