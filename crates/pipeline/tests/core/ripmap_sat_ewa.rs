//! Minification beyond the mipmap: ripmaps, summed-area tables and EWA (lesson 23).

use glam::{Vec2, Vec3};
use pipeline::texture::{Level, Texture, Wrap};

/// A 16×16 texture whose texel (i, j) is (i, j, i·j) — easy sums.
fn ramp() -> Texture {
    let texels = (0..16)
        .flat_map(|j| (0..16).map(move |i| Vec3::new(i as f32, j as f32, (i * j) as f32)))
        .collect();
    Texture::from_level(
        "ramp",
        Level {
            width: 16,
            height: 16,
            texels,
        },
    )
}

/// The summed-area table's mean over a box is the brute-force mean, inside the texture, across
/// its edge when repeating, and cut to it when clamping.
#[test]
fn the_summed_area_table_averages_the_footprints_box_exactly() {
    let t = ramp();
    let texel = Vec2::splat(1.0 / 16.0);
    let mean = |x0: i64, x1: i64, y0: i64, y1: i64| {
        let mut s = Vec3::ZERO;
        for y in y0..y1 {
            for x in x0..x1 {
                s += t.levels[0].texel(x, y, Wrap::Repeat);
            }
        }
        s / ((x1 - x0) * (y1 - y0)) as f32
    };
    // A 4×2-texel footprint centred on texel corner (6, 8): columns 4..8, rows 7..9.
    let got = t.sample_summed_area(
        Vec2::new(6.0, 8.0) * texel,
        Vec2::new(4.0, 0.0) * texel,
        Vec2::new(0.0, 2.0) * texel,
        Wrap::Repeat,
    );
    assert!((got - mean(4, 8, 7, 9)).length() < 1e-4, "{got}");
    // Across the right edge, repeating: columns 14..18 are 14, 15, 0, 1.
    let got = t.sample_summed_area(
        Vec2::new(16.0, 8.0) * texel,
        Vec2::new(4.0, 0.0) * texel,
        Vec2::new(0.0, 2.0) * texel,
        Wrap::Repeat,
    );
    assert!((got - mean(14, 18, 7, 9)).length() < 1e-4, "{got}");
    // A diagonal footprint's box: |∂u/∂x| + |∂u/∂y| = 4 texels wide, 4 high.
    let got = t.sample_summed_area(
        Vec2::new(8.0, 8.0) * texel,
        Vec2::new(2.0, 2.0) * texel,
        Vec2::new(-2.0, 2.0) * texel,
        Wrap::Repeat,
    );
    assert!((got - mean(6, 10, 6, 10)).length() < 1e-4, "{got}");
}

/// The ripmap reads the level halved i times in u and j in v for a footprint 2^i by 2^j texels:
/// a footprint 8 texels long in u and 1 in v reads level (3, 0), which is 2×16.
#[test]
fn the_ripmap_halves_each_axis_by_its_own_extent() {
    let t = ramp();
    let texel = 1.0 / 16.0;
    let (color, [i, j]) = t.sample_ripmap(
        Vec2::new(0.25, 0.53),
        Vec2::new(8.0 * texel, 0.0),
        Vec2::new(0.0, texel),
        Wrap::Repeat,
    );
    assert_eq!([i, j], [3, 0]);
    // Level (3, 0) is 2×16: its column 0 averages columns 0..8 (red 3.5), and u = 0.25 is that
    // column's centre; v = 0.53 is 8.48 rows up, 7.98 from row centres: green 7.98.
    assert!((color.x - 3.5).abs() < 1e-4, "{color}");
    assert!((color.y - 7.98).abs() < 1e-3, "{color}");
    let (_, [i, j]) = t.sample_ripmap(
        Vec2::splat(0.5),
        Vec2::new(texel, 0.0),
        Vec2::new(0.0, 4.0 * texel),
        Wrap::Repeat,
    );
    assert_eq!([i, j], [0, 2]);
}

/// EWA on a constant texture returns the constant; on the ramp, the weighted mean of a symmetric
/// ellipse centred on a texel is that texel's value (the ramp is linear); a long footprint reads
/// more texels than a short one, on a coarser level when it is wide.
#[test]
fn ewa_is_a_normalised_weighted_mean_over_the_ellipse() {
    let flat = Texture::from_level(
        "flat",
        Level {
            width: 16,
            height: 16,
            texels: vec![Vec3::new(0.25, 0.5, 0.75); 256],
        },
    );
    let texel = 1.0 / 16.0;
    let (c, _, _) = flat.sample_ewa(
        Vec2::splat(0.5),
        Vec2::new(3.0 * texel, 0.0),
        Vec2::new(0.0, texel),
        Wrap::Repeat,
    );
    assert!((c - Vec3::new(0.25, 0.5, 0.75)).length() < 1e-5);
    let t = ramp();
    let centre = Vec2::new(7.5, 6.5) * texel; // the centre of texel (7, 6)
    let (c, level, short) = t.sample_ewa(
        centre,
        Vec2::new(texel, 0.0),
        Vec2::new(0.0, texel),
        Wrap::Clamp,
    );
    assert_eq!(level, 0);
    assert!((c.x - 7.0).abs() < 1e-3 && (c.y - 6.0).abs() < 1e-3, "{c}");
    let (_, _, long) = t.sample_ewa(
        centre,
        Vec2::new(4.0 * texel, 4.0 * texel),
        Vec2::new(-texel, texel),
        Wrap::Clamp,
    );
    assert!(long > short, "{long} texels against {short}");
}
