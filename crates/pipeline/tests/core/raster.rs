//! The rasterization rules, proved on the cases where they matter.

use glam::Vec2;
use pipeline::capture::Fate;
use pipeline::raster::NONE;
use pipeline::raster::Samples;

use crate::support::{cover_counts, pixel_scene, render, sample_position};

/// Point-in-convex-polygon with a margin: `Some(true)` clearly inside, `Some(false)` clearly
/// outside, `None` within `margin` of the boundary (where the fill rule decides).
pub(crate) fn inside_convex(poly: &[Vec2], p: Vec2, margin: f32) -> Option<bool> {
    let mut min_d = f32::INFINITY;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let d = (b - a).perp_dot(p - a) / (b - a).length();
        min_d = min_d.min(d);
    }
    if min_d > margin {
        Some(true)
    } else if min_d < -margin {
        Some(false)
    } else {
        None
    }
}

#[test]
fn a_fan_of_random_triangles_covers_every_sample_exactly_once() {
    for samples in [Samples::X1, Samples::X4] {
        for seed in 0..40 {
            let mut rng = fastrand::Rng::with_seed(seed);
            let (w, h) = (64, 48);
            let centre = Vec2::new(20.0 + rng.f32() * 24.0, 15.0 + rng.f32() * 18.0);
            // A convex polygon: points on an ellipse at increasing random angles.
            // Angles (i + jitter)·2π/n with n ≥ 4: consecutive gaps stay below π, so the centre
            // is inside and the fan does not fold over itself.
            let n = 4 + rng.usize(..12);
            let angles: Vec<f32> = (0..n)
                .map(|i| (i as f32 + rng.f32() * 0.8) * std::f32::consts::TAU / n as f32)
                .collect();
            let ring: Vec<Vec2> = angles
                .iter()
                .map(|a| centre + Vec2::new(a.cos() * 18.0, a.sin() * 13.0))
                .collect();
            let tris: Vec<[Vec2; 3]> = (0..n)
                .map(|i| [centre, ring[i], ring[(i + 1) % n]])
                .collect();
            let (scene, mut settings) = pixel_scene(w, h, &tris);
            settings.samples = samples;
            let capture = render(&scene, &settings);
            let (sum, distinct) = cover_counts(&capture);
            assert_eq!(sum, distinct, "seed {seed}: some sample was covered twice");
            // No gaps: every sample clearly inside the polygon (the fan's union when the centre
            // is inside it) is covered.
            for y in 0..h {
                for x in 0..w {
                    for s in 0..samples.count() {
                        let p = sample_position(samples, x, y, s);
                        let covered =
                            capture.samples.triangle[capture.samples.index(x, y, s)] != NONE;
                        // Snapping moves vertices by up to 1/512 pixel: decide only beyond that.
                        match inside_convex(&ring, p, 0.01) {
                            Some(true) => assert!(covered, "seed {seed}: gap at {p}"),
                            Some(false) => assert!(!covered, "seed {seed}: spill at {p}"),
                            None => {}
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn a_jittered_grid_of_triangles_is_watertight() {
    for seed in 0..30 {
        let mut rng = fastrand::Rng::with_seed(1000 + seed);
        let (w, h) = (60u32, 40u32);
        let (nx, ny) = (7usize, 5usize);
        // Grid points over [2, 58] × [2, 38]; inner points jittered, boundary kept straight.
        let mut pts = vec![Vec2::ZERO; (nx + 1) * (ny + 1)];
        for j in 0..=ny {
            for i in 0..=nx {
                let mut p = Vec2::new(
                    2.0 + 56.0 * i as f32 / nx as f32,
                    2.0 + 36.0 * j as f32 / ny as f32,
                );
                if i > 0 && i < nx && j > 0 && j < ny {
                    p += Vec2::new(rng.f32() - 0.5, rng.f32() - 0.5) * 5.0;
                    // Some points exactly on pixel centres and pixel corners.
                    if rng.bool() {
                        p = (p * 2.0).round() / 2.0;
                    }
                }
                pts[j * (nx + 1) + i] = p;
            }
        }
        let mut tris = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let at = |a: usize, b: usize| pts[b * (nx + 1) + a];
                let (p00, p10, p11, p01) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                if rng.bool() {
                    tris.push([p00, p10, p11]);
                    tris.push([p00, p11, p01]);
                } else {
                    // Mixed orientation: clockwise triangles must follow the same rule.
                    tris.push([p00, p01, p10]);
                    tris.push([p10, p01, p11]);
                }
            }
        }
        let (scene, settings) = pixel_scene(w, h, &tris);
        let capture = render(&scene, &settings);
        let (sum, distinct) = cover_counts(&capture);
        assert_eq!(sum, distinct, "seed {seed}: double cover");
        // Every pixel centre inside the outer rectangle (2, 38) is covered; the rectangle's own
        // boundary lies on pixel borders, so centres are strictly inside or outside.
        let expected: u64 = (2..58).count() as u64 * (2..38).count() as u64;
        assert_eq!(distinct, expected, "seed {seed}: gaps");
    }
}

#[test]
fn top_left_rule_on_edges_through_pixel_centres() {
    // The square [1.5, 5.5]², split along a diagonal: every edge passes through pixel centres.
    let (a, b, c, d) = (
        Vec2::new(1.5, 1.5),
        Vec2::new(5.5, 1.5),
        Vec2::new(5.5, 5.5),
        Vec2::new(1.5, 5.5),
    );
    let (scene, settings) = pixel_scene(16, 16, &[[a, b, c], [a, c, d]]);
    let capture = render(&scene, &settings);
    let (sum, distinct) = cover_counts(&capture);
    assert_eq!(
        sum, distinct,
        "the diagonal's centres go to one triangle only"
    );
    // Left edge x = 1.5 and top edge y = 5.5 are in; right x = 5.5 and bottom y = 1.5 are out:
    // columns 1..=4, window rows 2..=5.
    for y in 0..16 {
        for x in 0..16 {
            let covered = capture.samples.triangle[capture.samples.index(x, y, 0)] != NONE;
            let expected = (1..=4).contains(&x) && (2..=5).contains(&y);
            assert_eq!(covered, expected, "pixel ({x}, {y})");
        }
    }
    // On the diagonal (centres (k+.5, k+.5)), the lower-right triangle a,b,c has it as its
    // top-left edge ("left": the edge c→a goes down): it owns them.
    for k in 2..=4 {
        let t = capture.samples.triangle[capture.samples.index(k, k, 0)];
        assert_eq!(
            capture.triangles[t as usize].primitive, 0,
            "diagonal pixel {k}"
        );
    }
    // A lone triangle with a horizontal top edge through centres: its top row is in.
    let (scene, settings) = pixel_scene(
        16,
        16,
        &[[
            Vec2::new(2.5, 8.5),
            Vec2::new(8.5, 2.5),
            Vec2::new(8.5, 8.5),
        ]],
    );
    let capture = render(&scene, &settings);
    let row = |y: u32| {
        (0..16)
            .filter(|&x| capture.samples.triangle[capture.samples.index(x, y, 0)] != NONE)
            .count()
    };
    // Top edge y = 8.5 is in (centres x = 2.5..=7.5, the right edge x = 8.5 is out): 6 pixels.
    assert_eq!(row(8), 6);
    // The hypotenuse (8.5,2.5)…(2.5,8.5) is a left edge (the triangle lies to its right): at
    // y = 3.5 the only centre inside is x = 7.5, exactly on it, and it is in.
    assert_eq!(row(3), 1, "row 3: {}", row(3));
    assert_eq!(
        row(2),
        0,
        "the bottom vertex's row has only the corner centre, on two edges"
    );
}

#[test]
fn degenerate_and_sliver_triangles() {
    let collinear = [
        Vec2::new(1.0, 1.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(9.0, 5.0),
    ];
    let point = [Vec2::new(4.5, 4.5); 3];
    let sliver = [
        Vec2::new(0.5, 0.5),
        Vec2::new(15.5, 0.6),
        Vec2::new(0.5, 0.52),
    ];
    let (scene, settings) = pixel_scene(16, 16, &[collinear, point, sliver]);
    let capture = render(&scene, &settings);
    assert_eq!(capture.primitives[0].fate, Fate::Degenerate);
    assert_eq!(capture.primitives[1].fate, Fate::Degenerate);
    assert_eq!(
        capture.primitives[0].counts.covered + capture.primitives[1].counts.covered,
        0
    );
    // The sliver is drawn; the only centre it could hold is (0.5, 0.5), its corner, which lies
    // on its bottom edge (not a top or left edge), so it covers at most that one.
    assert_eq!(capture.primitives[2].fate, Fate::Drawn);
    assert!(capture.primitives[2].counts.covered <= 1);
    let any_nan = capture
        .pixels
        .color
        .iter()
        .flatten()
        .any(|v| !v.is_finite());
    assert!(!any_nan, "no NaN anywhere");
}

#[test]
fn coverage_of_a_triangle_is_the_sum_over_a_split() {
    let mut rng = fastrand::Rng::with_seed(99);
    for _ in 0..200 {
        let mut p = || Vec2::new(rng.f32() * 40.0, rng.f32() * 30.0);
        let (a, b, c) = (p(), p(), p());
        // Split through a: m on b–c.
        let t = rng.f32();
        let m = b + (c - b) * t;
        let whole = pixel_scene(40, 30, &[[a, b, c]]);
        let split = pixel_scene(40, 30, &[[a, b, m], [a, m, c]]);
        for samples in [Samples::X1, Samples::X4] {
            let mut s1 = whole.1;
            s1.samples = samples;
            let mut s2 = split.1;
            s2.samples = samples;
            let (cw, cs) = (render(&whole.0, &s1), render(&split.0, &s2));
            let (sum_w, distinct_w) = cover_counts(&cw);
            let (sum_s, distinct_s) = cover_counts(&cs);
            assert_eq!(sum_s, distinct_s, "halves overlap");
            // m is not on the snapping grid, so the halves can differ from the whole only in
            // samples within 1/256 pixel of the line b–c; allow none for clear cases.
            let diff = sum_w.abs_diff(sum_s);
            assert!(diff <= 2, "whole {sum_w} ({distinct_w}) vs halves {sum_s}");
        }
    }
}

/// Snapping rounds to the nearest 1/256 pixel with ties to even, as the processor's default
/// rounding and Mesa's llvmpipe do: a vertex at exactly k + ½ sub-pixel units goes to the even
/// neighbour (864.142578125 = 221220.5/256 snaps to 221220, not 221221; the bunny at 1280×720
/// has such a vertex, and rounding it away from zero changed a pixel's coverage against llvmpipe).
#[test]
fn snapping_rounds_ties_to_even() {
    use pipeline::raster::snap;
    assert_eq!(snap(221_220.5 / 256.0), 221_220);
    assert_eq!(snap(221_221.5 / 256.0), 221_222);
    assert_eq!(snap(-2.5 / 256.0), -2);
    assert_eq!(snap(-3.5 / 256.0), -4);
    assert_eq!(snap(10.0 + 0.6 / 256.0), 2561);
}

/// `snap` rounds with an added constant rather than `round_ties_even`; on every kind of value
/// (ties, near-ties, negative, huge, infinite, NaN) the two agree.
#[test]
fn snapping_agrees_with_round_ties_even_everywhere() {
    use pipeline::raster::snap;
    let reference = |v: f32| (f64::from(v) * 256.0).round_ties_even() as i64;
    let mut values = vec![
        0.0,
        -0.0,
        f32::MAX,
        f32::MIN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        8.0e12,
        -8.0e12,
        9.0e12,
        -9.0e12,
    ];
    let mut next = crate::support::xorshift(0x2545_f491);
    for k in 0..200_000 {
        // Random bits: spread over all magnitudes, and ties k + ½ sub-pixel units.
        let bits = next();
        values.push(f32::from_bits(bits));
        values.push((k as f32 - 100_000.0 + 0.5) / 256.0);
        values.push(((bits % 4_000_000) as f32 - 2_000_000.0) / 512.0);
    }
    for v in values {
        assert_eq!(snap(v), reference(v), "snap({v:e})");
    }
}

/// Depth is the plane through the window positions as computed, not through the snapped ones:
/// on a steep triangle whose corners lie off the 1/256 grid, the plane through the snapped
/// corners is off by about 1e-4 at the pixel centre, the triangle's own plane (computed here
/// in f64 from the same three points) agrees to f32 rounding. Coverage still uses the snapped
/// corners.
#[test]
fn depth_is_the_plane_of_the_unsnapped_triangle() {
    use glam::{DVec3, I64Vec2, Vec3};
    use pipeline::raster::{CullMode, ONE, RasterTriangle};
    let third = 1.0 / 768.0; // a third of a sub-pixel step: as far off the grid as it gets
    let window = [
        Vec3::new(10.0 + third, 10.0 - third, 0.05),
        Vec3::new(16.0 - third, 11.0 + third, 0.95),
        Vec3::new(11.0 + third, 16.0 + third, 0.50),
    ];
    let tri = RasterTriangle::setup(
        0,
        window,
        [1.0; 3],
        pipeline::raster::Corners::ORIGINAL,
        CullMode::None,
        (40, 40),
    )
    .expect("a proper triangle");
    let p = window.map(|w| DVec3::new(w.x.into(), w.y.into(), w.z.into()));
    let exact = |x: f64, y: f64| {
        let (d1, d2) = (p[1] - p[0], p[2] - p[0]);
        let det = d1.x * d2.y - d2.x * d1.y;
        let a = (d1.z * d2.y - d2.z * d1.y) / det;
        let b = (d1.x * d2.z - d2.x * d1.z) / det;
        p[0].z + a * (x - p[0].x) + b * (y - p[0].y)
    };
    for (x, y) in [(12u32, 12u32), (13, 12), (11, 13)] {
        let centre = I64Vec2::new(i64::from(x) * ONE + ONE / 2, i64::from(y) * ONE + ONE / 2);
        assert!(tri.covers(centre), "pixel ({x}, {y}) is inside");
        let want = exact(f64::from(x) + 0.5, f64::from(y) + 0.5);
        let got = f64::from(tri.depth_at(centre));
        assert!(
            (got - want).abs() < 1e-7,
            "pixel ({x}, {y}): {got} against the triangle's own plane {want}"
        );
        // The screen-space weights of the snapped triangle give a visibly different depth:
        // the test would not notice a plane through the snapped corners otherwise.
        let l = tri.lambda(centre);
        let snapped = f64::from(l.x * window[0].z + l.y * window[1].z + l.z * window[2].z);
        assert!(
            (snapped - want).abs() > 1e-5,
            "pixel ({x}, {y}): the snapped plane differs ({snapped} vs {want})"
        );
    }
}

/// The edge coefficients are kept in 32 bits: a corner beyond the fixed-point range that keeps
/// them exact is refused at setup (a clipped triangle never has one), and one at the edge of the
/// range is rasterized exactly as the edge functions in 64 bits say.
#[test]
fn corners_beyond_the_fixed_point_range_are_refused_at_setup() {
    use glam::{I64Vec2, Vec3};
    use pipeline::raster::{CullMode, MAX_FIXED, ONE, RasterTriangle, SetupRejection};
    let setup = |far: f32| {
        RasterTriangle::setup(
            0,
            [
                Vec3::new(0.5, 0.5, 0.5),
                Vec3::new(far, 0.5, 0.5),
                Vec3::new(0.5, far, 0.5),
            ],
            [1.0; 3],
            pipeline::raster::Corners::ORIGINAL,
            CullMode::None,
            (8, 8),
        )
    };
    let limit = (MAX_FIXED / ONE) as f32; // 4 194 303 pixels, exactly representable
    assert_eq!(setup(limit * 2.0).err(), Some(SetupRejection::OutOfRange));
    assert_eq!(setup(-limit * 2.0).err(), Some(SetupRejection::OutOfRange));
    let tri = setup(limit).expect("within the range");
    // The three edge values at a point add up to twice the area (in 64 bits), and the
    // triangle covers the first pixels and not a point beyond its hypotenuse.
    let p = I64Vec2::new(3 * ONE + ONE / 2, 5 * ONE + ONE / 2);
    assert_eq!(tri.edge_values(p).iter().sum::<i64>(), tri.area2());
    assert!(tri.covers(p));
    let beyond = I64Vec2::new(MAX_FIXED, MAX_FIXED);
    assert!(!tri.covers(beyond));
    // What the rasterizer's records cost: a million of them are a frame's memory traffic
    // (written, moved together and read): two cache lines, the corners' weights kept as indices.
    assert!(std::mem::size_of::<RasterTriangle>() <= 128);
}

/// The fast rasterizer bins its triangles in parallel runs of 65 536: with more triangles than
/// that, overlapping across the runs' boundaries, the result is still the reference's, drawing
/// them one after another.
#[test]
fn binning_in_runs_keeps_the_drawing_order() {
    use glam::Vec3;
    use pipeline::raster::{CullMode, DepthTest, RasterTriangle, SampleBuffers, Samples};
    let (w, h) = (48u32, 32u32);
    let mut next = crate::support::uniform(0x2545_f491_u32);
    let tris: Vec<RasterTriangle> = (0..150_000u32)
        .filter_map(|k| {
            let (x, y) = (next() * w as f32, next() * h as f32);
            let z = next();
            let corner = |dx: f32, dy: f32| Vec3::new(x + dx, y + dy, z);
            RasterTriangle::setup(
                k,
                [
                    corner(0.0, 0.0),
                    corner(3.0 * next(), 0.3),
                    corner(0.2, 3.0 * next()),
                ],
                [1.0; 3],
                pipeline::raster::Corners::ORIGINAL,
                CullMode::None,
                (w, h),
            )
            .ok()
        })
        .collect();
    assert!(tris.len() > 2 * 65_536, "{} triangles", tris.len());
    // Always: the last triangle drawn over a sample wins, so the order is all that decides.
    // The second draw goes into the first's storage, whose lists hold three runs of triangles
    // to its two.
    let mut spare: Option<SampleBuffers> = None;
    for (test, drawn) in [
        (DepthTest::Always, &tris[..]),
        (DepthTest::Less, &tris[..100_000]),
    ] {
        let clear = test.clear_value();
        let mut fast = match spare.take() {
            Some(s) => s.cleared(w, h, Samples::X4, clear),
            None => SampleBuffers::new(w, h, Samples::X4, clear),
        };
        let counts = fast.rasterize_all(drawn, test).to_vec();
        assert_eq!(counts.len(), drawn.len());
        let mut reference = SampleBuffers::new(w, h, Samples::X4, clear);
        for (i, t) in drawn.iter().enumerate() {
            assert_eq!(reference.rasterize_reference(t, i as u32, test), counts[i]);
        }
        assert_eq!(fast.triangle, reference.triangle);
        assert_eq!(fast.depth, reference.depth);
        spare = Some(fast);
    }
}

/// Whether a triangle's box holds a sample, as the binning asks it (from what setup kept),
/// is whether some sample position of a pixel of the viewport lies in the box of its snapped
/// corners: for small and large triangles, inside, across and wholly outside the viewport, at
/// every sample count.
#[test]
fn a_box_holds_a_sample_where_a_pixel_s_sample_lies_in_the_snapped_corners_box() {
    use glam::{I64Vec2, Vec3};
    use pipeline::raster::{CullMode, ONE, RasterTriangle, Samples, sample_offsets_fixed, snap_xy};
    let (w, h) = (8u32, 6u32);
    let mut next = crate::support::uniform(0x6c07_8965_u32);
    let (mut holds, mut empty, mut outside) = (0, 0, 0);
    for k in 0..20_000 {
        // Corners anywhere from three pixels before the viewport to three past it; a tenth of
        // the triangles slivers under a pixel wide.
        let size = if k % 10 == 0 { 0.6 } else { 6.0 };
        let (x, y) = (next() * 14.0 - 3.0, next() * 12.0 - 3.0);
        let corner = |dx: f32, dy: f32| Vec3::new(x + dx * size, y + dy * size, 0.5);
        let window = [
            corner(0.0, 0.0),
            corner(next(), next() * 0.2),
            corner(next() * 0.2, next()),
        ];
        let Ok(tri) = RasterTriangle::setup(
            0,
            window,
            [1.0; 3],
            pipeline::raster::Corners::ORIGINAL,
            CullMode::None,
            (w, h),
        ) else {
            continue;
        };
        let fixed = window.map(snap_xy);
        let lo = fixed[0].min(fixed[1]).min(fixed[2]);
        let hi = fixed[0].max(fixed[1]).max(fixed[2]);
        outside += usize::from(hi.x < 0 || lo.x >= i64::from(w) * ONE);
        for samples in [Samples::X1, Samples::X4, Samples::X8, Samples::X16] {
            let offsets = sample_offsets_fixed(samples);
            let want = (0..w).any(|px| {
                (0..h).any(|py| {
                    offsets.iter().any(|o| {
                        let p = I64Vec2::new(i64::from(px) * ONE, i64::from(py) * ONE) + *o;
                        p.cmpge(lo).all() && p.cmple(hi).all()
                    })
                })
            });
            assert_eq!(
                tri.box_holds_a_sample(&offsets),
                want,
                "{window:?}, {samples:?}"
            );
            (holds, empty) = (holds + usize::from(want), empty + usize::from(!want));
        }
    }
    assert!(
        holds > 10_000 && empty > 5_000,
        "{holds} hold a sample, {empty} none"
    );
    assert!(
        outside > 500,
        "only {outside} boxes wholly beside the viewport"
    );
}
