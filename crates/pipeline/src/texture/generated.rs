//! Textures made in code, so that pipelens ships no image: a checkerboard, a uv grid, and a
//! texture whose mip levels have distinct colours, with those colours.

use glam::Vec3;

use super::{Level, Texture};

impl Texture {
    /// A checkerboard of `squares × squares` black and white squares, `size` texels a side.
    #[must_use]
    pub fn checkerboard(size: u32, squares: u32) -> Self {
        let cell = (size / squares.max(1)).max(1);
        Self::checker_cells("checkerboard", (size, size), cell)
    }

    /// A `width × height` checkerboard of black and white squares `cell` texels a side: wider
    /// than high, it tells `u·w` from `u·h` (the level-of-detail lab).
    #[must_use]
    pub fn checker_cells(name: &str, size: (u32, u32), cell: u32) -> Self {
        let cell = cell.max(1);
        Self::from_fn_sized(name, size, |i, j| {
            if ((i / cell) + (j / cell)).is_multiple_of(2) {
                Vec3::splat(0.95)
            } else {
                Vec3::splat(0.1)
            }
        })
    }

    /// A uv grid: red grows with u, green with v, with white grid lines every 1/8 and a darker
    /// cell pattern, so orientation and distortion are visible.
    #[must_use]
    pub fn uv_grid(size: u32) -> Self {
        let line = (size / 8).max(1);
        Self::from_fn("uv_grid", size, |i, j| {
            let (u, v) = (
                (i as f32 + 0.5) / size as f32,
                (j as f32 + 0.5) / size as f32,
            );
            if i.is_multiple_of(line) || j.is_multiple_of(line) {
                Vec3::ONE
            } else if ((i / line) + (j / line)).is_multiple_of(2) {
                Vec3::new(u, v, 0.35)
            } else {
                Vec3::new(u, v, 0.35) * 0.7
            }
        })
    }

    /// A texture whose mip levels have distinct colours (level 0 a checkerboard): what is seen
    /// shows which level was read.
    #[must_use]
    pub fn mip_levels(size: u32) -> Self {
        let mut t = Self::checkerboard(size, 8);
        t.name = "mip_levels".to_owned();
        for (k, level) in t.levels.iter_mut().enumerate().skip(1) {
            let c = level_color(k as u32);
            level.texels.iter_mut().for_each(|x| *x = c);
        }
        t
    }

    pub(super) fn from_fn(name: &str, size: u32, f: impl Fn(u32, u32) -> Vec3) -> Self {
        Self::from_fn_sized(name, (size, size), f)
    }

    /// A `width × height` texture whose texel `(i, j)` (j up) is `f(i, j)`.
    pub(super) fn from_fn_sized(
        name: &str,
        (width, height): (u32, u32),
        f: impl Fn(u32, u32) -> Vec3,
    ) -> Self {
        let (width, height) = (width.max(1), height.max(1));
        let texels = (0..height)
            .flat_map(|j| (0..width).map(move |i| (i, j)))
            .map(|(i, j)| f(i, j))
            .collect();
        Self::from_level(
            name,
            Level {
                width,
                height,
                texels,
            },
        )
    }
}

/// A distinct colour for mip level `k`, used by the mip-level texture and the level legend.
#[must_use]
pub fn level_color(k: u32) -> Vec3 {
    const COLORS: [[f32; 3]; 8] = [
        [0.95, 0.95, 0.95],
        [0.90, 0.25, 0.25],
        [0.95, 0.60, 0.15],
        [0.95, 0.90, 0.20],
        [0.30, 0.80, 0.30],
        [0.20, 0.75, 0.85],
        [0.30, 0.40, 0.95],
        [0.70, 0.35, 0.90],
    ];
    Vec3::from(COLORS[(k as usize).min(COLORS.len() - 1)])
}
