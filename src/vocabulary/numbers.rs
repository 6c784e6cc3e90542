//! How numbers are written in tables, tooltips, handouts: the same everywhere.

use glam::{Vec3, Vec4};

/// Formats a number for tables: 3 decimals, or scientific when huge or tiny; below 1e-6 in
/// magnitude it is shown as 0 (round-off such as 2.4e-7 in a rotation matrix says nothing).
#[must_use]
pub fn num(v: f32) -> String {
    if v.abs() < 1e-6 {
        "0".to_owned()
    } else if v.abs() >= 1e5 || v.abs() < 1e-3 {
        format!("{v:.2e}")
    } else {
        format!("{v:.3}")
    }
}

/// `(x, y, z)`.
#[must_use]
pub fn vec3(v: Vec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// `(x, y, z, w)`.
#[must_use]
pub fn vec4(v: Vec4) -> String {
    format!("({}, {}, {}, {})", num(v.x), num(v.y), num(v.z), num(v.w))
}

/// A number with at most `decimals` decimals and no trailing zeros (`45`, `43.1`, `-0.27`), as
/// captions and messages show a value.
#[must_use]
pub fn short(v: f32, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

#[cfg(test)]
mod short_tests {
    #[test]
    fn trailing_zeros_go() {
        assert_eq!(super::short(40.0, 3), "40");
        assert_eq!(super::short(43.125, 1), "43.1");
        assert_eq!(super::short(-0.0001, 3), "0");
        assert_eq!(super::short(-0.2673, 3), "-0.267");
        assert_eq!(super::short(100.0, 0), "100");
    }
}
