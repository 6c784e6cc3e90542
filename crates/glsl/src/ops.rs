//! The arithmetic of the shader machine on rows of lanes: GLSL's operators (GLSL 4.50
//! specification, chapter 5), the conversions between kinds and the screen-space derivatives,
//! one component at a time over every lane; the built-in functions are in `builtins.rs`.
//! Values are 32-bit patterns; each operation reads them as the kind its operands have.

use naga::{BinaryOperator as B, DerivativeAxis};

use super::register_form::Kind;

pub(crate) fn f(x: u32) -> f32 {
    f32::from_bits(x)
}

/// `y[l] = g(x[l])` for every lane.
pub fn map(x: &[u32], y: &mut [u32], g: impl Fn(u32) -> u32) {
    for (o, &v) in y.iter_mut().zip(x) {
        *o = g(v);
    }
}

pub(crate) fn zip(x: &[u32], y: &[u32], out: &mut [u32], g: impl Fn(u32, u32) -> u32) {
    for ((o, &a), &b) in out.iter_mut().zip(x).zip(y) {
        *o = g(a, b);
    }
}

pub(crate) fn zipf(x: &[u32], y: &[u32], out: &mut [u32], g: impl Fn(f32, f32) -> f32) {
    zip(x, y, out, |a, b| g(f(a), f(b)).to_bits());
}

/// An integer division (`remainder`: `%`) by zero in a live lane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DivisionByZero {
    /// Whether it was `%`.
    pub remainder: bool,
}

impl DivisionByZero {
    /// The sentence (English).
    #[must_use]
    pub fn message(self) -> &'static str {
        if self.remainder {
            "integer remainder (%) by zero"
        } else {
            "integer division by zero"
        }
    }
}

/// A binary operator on one component row; `live` lanes report integer division by zero.
///
/// # Errors
/// An integer division or remainder by zero in a live lane.
pub fn binary(
    op: B,
    kind: Kind,
    x: &[u32],
    y: &[u32],
    out: &mut [u32],
    live: u64,
) -> Result<(), DivisionByZero> {
    let cmp = |out: &mut [u32], o: fn(std::cmp::Ordering) -> bool| match kind {
        Kind::Float => zip(x, y, out, |a, b| {
            u32::from(f(a).partial_cmp(&f(b)).is_some_and(o))
        }),
        Kind::Int => zip(x, y, out, |a, b| u32::from(o((a as i32).cmp(&(b as i32))))),
        Kind::Uint | Kind::Bool => zip(x, y, out, |a, b| u32::from(o(a.cmp(&b)))),
    };
    if matches!((op, kind), (B::Divide | B::Modulo, Kind::Int | Kind::Uint))
        && y.iter()
            .enumerate()
            .any(|(l, &b)| b == 0 && live & (1 << l) != 0)
    {
        return Err(DivisionByZero {
            remainder: op == B::Modulo,
        });
    }
    match (op, kind) {
        (B::Add, Kind::Float) => zipf(x, y, out, |a, b| a + b),
        (B::Subtract, Kind::Float) => zipf(x, y, out, |a, b| a - b),
        (B::Multiply, Kind::Float) => zipf(x, y, out, |a, b| a * b),
        (B::Divide, Kind::Float) => zipf(x, y, out, |a, b| a / b),
        // naga's float `%` is the truncated remainder, `x − y·trunc(x/y)`.
        (B::Modulo, Kind::Float) => zipf(x, y, out, |a, b| a % b),
        (B::Add, _) => zip(x, y, out, u32::wrapping_add),
        (B::Subtract, _) => zip(x, y, out, u32::wrapping_sub),
        (B::Multiply, _) => zip(x, y, out, u32::wrapping_mul),
        (B::Divide, Kind::Int) => zip(x, y, out, |a, b| {
            if b == 0 {
                0
            } else {
                (a as i32).wrapping_div(b as i32) as u32
            }
        }),
        (B::Divide, _) => zip(x, y, out, |a, b| a.checked_div(b).unwrap_or(0)),
        (B::Modulo, Kind::Int) => zip(x, y, out, |a, b| {
            if b == 0 {
                0
            } else {
                (a as i32).wrapping_rem(b as i32) as u32
            }
        }),
        (B::Modulo, _) => zip(x, y, out, |a, b| a.checked_rem(b).unwrap_or(0)),
        (B::Equal, _) => cmp(out, |o| o.is_eq()),
        (B::NotEqual, Kind::Float) => zip(x, y, out, |a, b| u32::from(f(a) != f(b))),
        (B::NotEqual, _) => cmp(out, |o| o.is_ne()),
        (B::Less, _) => cmp(out, |o| o.is_lt()),
        (B::LessEqual, _) => cmp(out, |o| o.is_le()),
        (B::Greater, _) => cmp(out, |o| o.is_gt()),
        (B::GreaterEqual, _) => cmp(out, |o| o.is_ge()),
        (B::And | B::LogicalAnd, _) => zip(x, y, out, |a, b| a & b),
        (B::InclusiveOr | B::LogicalOr, _) => zip(x, y, out, |a, b| a | b),
        (B::ExclusiveOr, _) => zip(x, y, out, |a, b| a ^ b),
        (B::ShiftLeft, _) => zip(x, y, out, |a, b| a.wrapping_shl(b)),
        (B::ShiftRight, Kind::Int) => zip(x, y, out, |a, b| (a as i32).wrapping_shr(b) as u32),
        (B::ShiftRight, _) => zip(x, y, out, u32::wrapping_shr),
    }
    Ok(())
}

/// `out = Σ a_k·b_k` over the pairs of rows (a row of a matrix times a column).
/// The terms are added in order, `((0 + a_0·b_0) + a_1·b_1) + …`, a term over all lanes at a
/// time (rows cut to the lanes, so the loop runs over plain arrays).
pub fn dot_rows(terms: &[(&[u32], &[u32])], out: &mut [u32]) {
    let n = out.len().min(crate::lanes::LANES);
    let mut sum = [0f32; crate::lanes::LANES];
    for (a, b) in terms {
        let (a, b) = (&a[..n], &b[..n]);
        for ((s, &x), &y) in sum[..n].iter_mut().zip(a).zip(b) {
            *s += f(x) * f(y);
        }
    }
    for (o, s) in out.iter_mut().zip(&sum[..n]) {
        *o = s.to_bits();
    }
}

/// A derivative within each 2×2 quad (lanes top-left, top-right, bottom-left, bottom-right).
/// Coarse: one value for the quad, from its top-left pixel (`dFdx = v_TR − v_TL`,
/// `dFdy = v_BL − v_TL`); fine: per row or column. `fwidth = |dFdx| + |dFdy|`.
pub fn derivative(axis: DerivativeAxis, fine: bool, x: &[u32], out: &mut [u32]) {
    for q in (0..x.len()).step_by(4) {
        if q + 3 >= x.len() {
            out[q..].fill(0f32.to_bits());
            break;
        }
        let v = |i: usize| f(x[q + i]);
        let dx = [v(1) - v(0), v(3) - v(2)];
        let dy = [v(2) - v(0), v(3) - v(1)];
        for i in 0..4 {
            let (row, col) = (i / 2, i % 2);
            let (ddx, ddy) = if fine {
                (dx[row], dy[col])
            } else {
                (dx[0], dy[0])
            };
            out[q + i] = match axis {
                DerivativeAxis::X => ddx,
                DerivativeAxis::Y => ddy,
                DerivativeAxis::Width => ddx.abs() + ddy.abs(),
            }
            .to_bits();
        }
    }
}

/// A numeric conversion of one row (`float(i)`, `int(x)`, `bool(x)`).
pub fn convert(from: Kind, to: Kind, x: &[u32], y: &mut [u32]) {
    match (from, to) {
        (Kind::Float, Kind::Int) => map(x, y, |v| f(v) as i32 as u32),
        (Kind::Float, Kind::Uint) => map(x, y, |v| f(v) as u32),
        (Kind::Float, Kind::Bool) => map(x, y, |v| u32::from(f(v) != 0.0)),
        (Kind::Int, Kind::Float) => map(x, y, |v| (v as i32 as f32).to_bits()),
        (Kind::Uint, Kind::Float) => map(x, y, |v| (v as f32).to_bits()),
        (Kind::Bool, Kind::Float) => map(x, y, |v| if v != 0 { 1f32.to_bits() } else { 0 }),
        (Kind::Int | Kind::Uint, Kind::Bool) => map(x, y, |v| u32::from(v != 0)),
        _ => y.copy_from_slice(x),
    }
}
