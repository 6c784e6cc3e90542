//! GLSL's built-in functions on rows of lanes (GLSL 4.50 specification, chapter 8): those the
//! machine runs, in `math`, and the list of naga's math functions it does not run yet, which
//! `crates/pipeline/tests/core/builtin_list.rs` checks against `math` name by name.

use glam::{Mat2, Mat3, Mat4};
use naga::MathFunction as M;

use crate::lanes::LANES;
use crate::ops::{f, map, zipf};
use crate::power;
use crate::register_form::{Kind, Reg};

/// Whether the machine runs `fun`.
#[must_use]
pub fn supported(fun: M) -> bool {
    !matches!(
        fun,
        M::Modf
            | M::Frexp
            | M::Ldexp
            | M::QuantizeToF16
            | M::CountTrailingZeros
            | M::CountLeadingZeros
            | M::CountOneBits
            | M::ReverseBits
            | M::ExtractBits
            | M::InsertBits
            | M::FirstTrailingBit
            | M::FirstLeadingBit
            | M::Pack4x8snorm
            | M::Pack4x8unorm
            | M::Pack2x16snorm
            | M::Pack2x16unorm
            | M::Pack2x16float
            | M::Pack4xI8
            | M::Pack4xU8
            | M::Pack4xI8Clamp
            | M::Pack4xU8Clamp
            | M::Unpack4x8snorm
            | M::Unpack4x8unorm
            | M::Unpack2x16snorm
            | M::Unpack2x16unorm
            | M::Unpack2x16float
            | M::Unpack4xI8
            | M::Unpack4xU8
            | M::Dot4I8Packed
            | M::Dot4U8Packed
    )
}

/// The component rows of a vector argument, at most four, on the stack.
type Vec4Rows<'a> = arrayvec::ArrayVec<&'a [u32], 4>;

/// `Σ_c a_c·b_c` at lane `l`, summed over the components in order.
fn dot_lane(a: &[&[u32]], b: &[&[u32]], l: usize) -> f32 {
    let mut sum = -0.0f32;
    for (x, y) in a.iter().zip(b) {
        sum += f(x[l]) * f(y[l]);
    }
    sum
}

/// `out[l] = Σ_c g(a_c[l], b_c[l])` for the first `n` lanes, the terms added over the
/// components in order from −0, as [`dot_lane`] adds them, a component row at a time.
fn sums_into(a: &[&[u32]], b: &[&[u32]], n: usize, g: impl Fn(f32, f32) -> f32, out: &mut [u32]) {
    let mut sum = [-0.0f32; LANES];
    for (x, y) in a.iter().zip(b) {
        for ((s, &x), &y) in sum[..n].iter_mut().zip(&x[..n]).zip(&y[..n]) {
            *s += g(f(x), f(y));
        }
    }
    for (o, s) in out.iter_mut().zip(&sum[..n]) {
        *o = s.to_bits();
    }
}

/// `x[l] = g(x[l])` for every lane of `x`, a float's bits in place.
fn map_in_place(x: &mut [u32], g: impl Fn(f32) -> f32) {
    for v in x {
        *v = g(f(*v)).to_bits();
    }
}

/// GLSL's `smoothstep`: `t = clamp((x − e0)/(e1 − e0), 0, 1)`, `t²(3 − 2t)`.
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A built-in function. `row(reg, c)` reads component `c` of a register; a scalar argument
/// repeats for every component. `rows` is the first argument's vector or column size.
///
/// # Errors
/// A function the machine does not run.
#[allow(clippy::too_many_lines, clippy::too_many_arguments)]
pub fn math<'a>(
    fun: M,
    kind: Kind,
    args: &[Reg],
    rows: u32,
    row: &dyn Fn(u32, u32) -> &'a [u32],
    out: &mut [u32],
    width: u32,
    n: usize,
) -> Result<(), String> {
    let arg = |i: usize, c: u32| {
        let r = args[i];
        row(r.first, if r.len == 1 { 0 } else { c })
    };
    let a0 = args[0];
    let stride = crate::lanes::LANES;
    // Component by component, floats: `g` is a generic parameter, so each function's loop is
    // compiled with it inlined (called through a `dyn Fn`, every lane paid an indirect call).
    fn each1<'r>(
        out: &mut [u32],
        x: impl Fn(usize, u32) -> &'r [u32],
        width: u32,
        n: usize,
        g: impl Fn(f32) -> f32,
    ) {
        for c in 0..width {
            map(x(0, c), &mut out[c as usize * LANES..][..n], |v| {
                g(f(v)).to_bits()
            });
        }
    }
    fn each2<'r>(
        out: &mut [u32],
        x: impl Fn(usize, u32) -> &'r [u32],
        width: u32,
        n: usize,
        g: impl Fn(f32, f32) -> f32,
    ) {
        for c in 0..width {
            zipf(x(0, c), x(1, c), &mut out[c as usize * LANES..][..n], &g);
        }
    }
    fn each3<'r>(
        out: &mut [u32],
        x: impl Fn(usize, u32) -> &'r [u32],
        width: u32,
        n: usize,
        g: impl Fn(f32, f32, f32) -> f32,
    ) {
        for c in 0..width {
            let (a, b, d) = (x(0, c), x(1, c), x(2, c));
            for (l, o) in out[c as usize * LANES..][..n].iter_mut().enumerate() {
                *o = g(f(a[l]), f(b[l]), f(d[l])).to_bits();
            }
        }
    }
    // An argument's component rows (a vector has at most four).
    let rows_of = |i: usize| -> Vec4Rows<'a> {
        let mut r = Vec4Rows::new();
        for c in 0..args[i].len {
            r.push(arg(i, c));
        }
        r
    };
    // Per lane, whole vectors: dot products and the like.
    let vec = |i: usize, l: usize| -> Vec<f32> {
        (0..args[i].len)
            .map(|c| f(row(args[i].first, c)[l]))
            .collect()
    };
    let dot = |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f32>();
    let per_lane = |out: &mut [u32], g: &dyn Fn(usize) -> Vec<f32>| {
        for l in 0..n {
            for (c, v) in g(l).into_iter().enumerate() {
                out[c * stride + l] = v.to_bits();
            }
        }
    };
    match (fun, kind) {
        (M::Abs, Kind::Int) => {
            for c in 0..width {
                map(arg(0, c), &mut out[c as usize * stride..][..n], |v| {
                    (v as i32).wrapping_abs() as u32
                });
            }
        }
        (M::Min | M::Max | M::Clamp, Kind::Int | Kind::Uint) => {
            for c in 0..width {
                for l in 0..n {
                    let g = |i: usize| arg(i, c)[l];
                    let (x, y) = (g(0), g(1));
                    let v = if kind == Kind::Int {
                        let (x, y) = (x as i32, y as i32);
                        (match fun {
                            M::Min => x.min(y),
                            M::Max => x.max(y),
                            _ => x.max(y).min(g(2) as i32),
                        }) as u32
                    } else {
                        match fun {
                            M::Min => x.min(y),
                            M::Max => x.max(y),
                            _ => x.max(y).min(g(2)),
                        }
                    };
                    out[c as usize * stride + l] = v;
                }
            }
        }
        (M::Sign, Kind::Int) => {
            for c in 0..width {
                map(arg(0, c), &mut out[c as usize * stride..][..n], |v| {
                    (v as i32).signum() as u32
                });
            }
        }
        (M::Abs, _) => each1(out, arg, width, n, f32::abs),
        (M::Min, _) => each2(out, arg, width, n, f32::min),
        (M::Max, _) => each2(out, arg, width, n, f32::max),
        (M::Clamp, _) => each3(out, arg, width, n, |x, lo, hi| x.max(lo).min(hi)),
        (M::Saturate, _) => each1(out, arg, width, n, |x| x.clamp(0.0, 1.0)),
        (M::Cos, _) => each1(out, arg, width, n, f32::cos),
        (M::Cosh, _) => each1(out, arg, width, n, f32::cosh),
        (M::Sin, _) => each1(out, arg, width, n, f32::sin),
        (M::Sinh, _) => each1(out, arg, width, n, f32::sinh),
        (M::Tan, _) => each1(out, arg, width, n, f32::tan),
        (M::Tanh, _) => each1(out, arg, width, n, f32::tanh),
        (M::Acos, _) => each1(out, arg, width, n, f32::acos),
        (M::Asin, _) => each1(out, arg, width, n, f32::asin),
        (M::Atan, _) => each1(out, arg, width, n, f32::atan),
        (M::Atan2, _) => each2(out, arg, width, n, f32::atan2),
        (M::Asinh, _) => each1(out, arg, width, n, f32::asinh),
        (M::Acosh, _) => each1(out, arg, width, n, f32::acosh),
        (M::Atanh, _) => each1(out, arg, width, n, f32::atanh),
        (M::Radians, _) => each1(out, arg, width, n, f32::to_radians),
        (M::Degrees, _) => each1(out, arg, width, n, f32::to_degrees),
        (M::Ceil, _) => each1(out, arg, width, n, f32::ceil),
        (M::Floor, _) => each1(out, arg, width, n, f32::floor),
        (M::Round, _) => each1(out, arg, width, n, f32::round_ties_even),
        (M::Fract, _) => each1(out, arg, width, n, |x| x - x.floor()),
        (M::Trunc, _) => each1(out, arg, width, n, f32::trunc),
        (M::Exp, _) => each1(out, arg, width, n, f32::exp),
        (M::Exp2, _) => each1(out, arg, width, n, f32::exp2),
        (M::Log, _) => each1(out, arg, width, n, f32::ln),
        (M::Log2, _) => each1(out, arg, width, n, f32::log2),
        // The lighting's polynomial power (its error is stated in `power.rs`), eight lanes
        // at a time.
        (M::Pow, _) => {
            for c in 0..width {
                power::pow_bits(arg(0, c), arg(1, c), &mut out[c as usize * stride..][..n]);
            }
        }
        (M::Sqrt, _) => each1(out, arg, width, n, f32::sqrt),
        (M::InverseSqrt, _) => each1(out, arg, width, n, |x| 1.0 / x.sqrt()),
        (M::Sign, _) => each1(out, arg, width, n, |x| {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }),
        (M::Fma, _) => each3(out, arg, width, n, |a, b, c| a.mul_add(b, c)),
        (M::Mix, _) => each3(out, arg, width, n, |a, b, t| a * (1.0 - t) + b * t),
        (M::Step, _) => each2(
            out,
            arg,
            width,
            n,
            |edge, x| if x < edge { 0.0 } else { 1.0 },
        ),
        (M::SmoothStep, _) => each3(out, arg, width, n, smoothstep),
        // The geometric functions: their sums row by row over every lane at once, each
        // lane's terms added over the components in order from −0 (`dot_lane`'s order, so the
        // same bits), then the square root and the division row by row.
        (M::Dot, _) => {
            let (a, b) = (rows_of(0), rows_of(1));
            sums_into(&a, &b, n, |x, y| x * y, &mut out[..n]);
        }
        (M::Length, _) => {
            let a = rows_of(0);
            sums_into(&a, &a, n, |x, y| x * y, &mut out[..n]);
            map_in_place(&mut out[..n], f32::sqrt);
        }
        (M::Distance, _) => {
            let (a, b) = (rows_of(0), rows_of(1));
            sums_into(
                &a,
                &b,
                n,
                |x, y| {
                    let d = x - y;
                    d * d
                },
                &mut out[..n],
            );
            map_in_place(&mut out[..n], f32::sqrt);
        }
        (M::Normalize, _) => {
            let a = rows_of(0);
            let mut len = [0u32; LANES];
            sums_into(&a, &a, n, |x, y| x * y, &mut len[..n]);
            map_in_place(&mut len[..n], f32::sqrt);
            for (c, x) in a.iter().enumerate() {
                zipf(&x[..n], &len[..n], &mut out[c * stride..][..n], |v, l| {
                    v / l
                });
            }
        }
        (M::Cross, _) => {
            let (a, b) = (rows_of(0), rows_of(1));
            for l in 0..n {
                let a = |c: usize| f(a[c][l]);
                let b = |c: usize| f(b[c][l]);
                let v = [
                    a(1) * b(2) - a(2) * b(1),
                    a(2) * b(0) - a(0) * b(2),
                    a(0) * b(1) - a(1) * b(0),
                ];
                for (c, x) in v.iter().enumerate() {
                    out[c * stride + l] = x.to_bits();
                }
            }
        }
        // outerProduct(c, r) = c·rᵀ: column j is c·r_j.
        (M::Outer, _) => {
            let (c, r) = (rows_of(0), rows_of(1));
            for l in 0..n {
                for (j, rj) in r.iter().enumerate() {
                    for (i, ci) in c.iter().enumerate() {
                        out[(j * c.len() + i) * stride + l] = (f(ci[l]) * f(rj[l])).to_bits();
                    }
                }
            }
        }
        // reflect(I, N) = I − 2·(N·I)·N
        (M::Reflect, _) => {
            let (i, nn) = (rows_of(0), rows_of(1));
            for l in 0..n {
                let d = dot_lane(&nn, &i, l);
                for (c, (x, y)) in i.iter().zip(&nn).enumerate() {
                    out[c * stride + l] = (f(x[l]) - 2.0 * d * f(y[l])).to_bits();
                }
            }
        }
        // faceforward(N, I, Nref) = N if Nref·I < 0, else −N
        (M::FaceForward, _) => {
            let (nn, i, nref) = (rows_of(0), rows_of(1), rows_of(2));
            for l in 0..n {
                let s = if dot_lane(&nref, &i, l) < 0.0 {
                    1.0
                } else {
                    -1.0
                };
                for (c, x) in nn.iter().enumerate() {
                    out[c * stride + l] = (s * f(x[l])).to_bits();
                }
            }
        }
        // refract(I, N, η): k = 1 − η²(1 − (N·I)²); 0 if k < 0, else η·I − (η·(N·I) + √k)·N
        (M::Refract, _) => per_lane(out, &|l| {
            let (i, nn) = (vec(0, l), vec(1, l));
            let eta = f(row(args[2].first, 0)[l]);
            let d = dot(&nn, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            if k < 0.0 {
                vec![0.0; i.len()]
            } else {
                i.iter()
                    .zip(&nn)
                    .map(|(a, b)| eta * a - (eta * d + k.sqrt()) * b)
                    .collect()
            }
        }),
        (M::Transpose, _) => {
            let (r, c) = (rows, a0.len / rows);
            for j in 0..c {
                for i in 0..r {
                    out[(i * c + j) as usize * stride..][..n]
                        .copy_from_slice(row(a0.first, j * r + i));
                }
            }
        }
        (M::Determinant | M::Inverse, _) => per_lane(out, &|l| {
            let m = vec(0, l);
            let inverse = fun == M::Inverse;
            match rows {
                2 => {
                    let m = Mat2::from_cols_slice(&m);
                    if inverse {
                        m.inverse().to_cols_array().to_vec()
                    } else {
                        vec![m.determinant()]
                    }
                }
                3 => {
                    let m = Mat3::from_cols_slice(&m);
                    if inverse {
                        m.inverse().to_cols_array().to_vec()
                    } else {
                        vec![m.determinant()]
                    }
                }
                _ => {
                    let m = Mat4::from_cols_slice(&m);
                    if inverse {
                        m.inverse().to_cols_array().to_vec()
                    } else {
                        vec![m.determinant()]
                    }
                }
            }
        }),
        (other, _) => return Err(format!("`{other:?}` is not run by pipelens yet")),
    }
    Ok(())
}

/// A math function as GLSL spells it: naga's `Modf` is `modf`, `Outer` `outerProduct`.
pub(super) fn glsl_name(fun: naga::MathFunction) -> String {
    use naga::MathFunction as M;
    match fun {
        M::Outer => "outerProduct".to_owned(),
        M::CountOneBits => "bitCount".to_owned(),
        M::ExtractBits => "bitfieldExtract".to_owned(),
        M::InsertBits => "bitfieldInsert".to_owned(),
        M::ReverseBits => "bitfieldReverse".to_owned(),
        M::FirstTrailingBit => "findLSB".to_owned(),
        M::FirstLeadingBit => "findMSB".to_owned(),
        M::Pack2x16float => "packHalf2x16".to_owned(),
        M::Unpack2x16float => "unpackHalf2x16".to_owned(),
        M::Pack2x16unorm => "packUnorm2x16".to_owned(),
        M::Unpack2x16unorm => "unpackUnorm2x16".to_owned(),
        M::Pack2x16snorm => "packSnorm2x16".to_owned(),
        M::Unpack2x16snorm => "unpackSnorm2x16".to_owned(),
        M::Pack4x8unorm => "packUnorm4x8".to_owned(),
        M::Unpack4x8unorm => "unpackUnorm4x8".to_owned(),
        M::Pack4x8snorm => "packSnorm4x8".to_owned(),
        M::Unpack4x8snorm => "unpackSnorm4x8".to_owned(),
        other => format!("{other:?}").to_lowercase(),
    }
}
