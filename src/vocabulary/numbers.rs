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
