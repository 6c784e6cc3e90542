//! Property tests (proptest) of the rasterization and clipping invariants, on random inputs:
//! watertight fans, coverage additive over a split, the depth test independent of drawing order
//! for opaque geometry, and clipping that never leaves the view volume.

use glam::{Vec2, Vec3, Vec4};
use pipeline::clip::{ClipOutcome, ClipVertex, clip_triangle};
use pipeline::mesh::Mesh;
use pipeline::raster::{DepthTest, Samples};
use pipeline::scene::{ColorSource, Object};
use proptest::prelude::*;

use crate::support::{cover_counts, pixel_scene, render};

/// A point on the 1/16-pixel grid inside a 48×32 window.
fn grid_point() -> impl Strategy<Value = Vec2> {
    (0u32..48 * 16, 0u32..32 * 16).prop_map(|(x, y)| Vec2::new(x as f32, y as f32) / 16.0)
}

fn samples() -> impl Strategy<Value = Samples> {
    prop_oneof![Just(Samples::X1), Just(Samples::X4), Just(Samples::X16)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// A triangle split at a point of one edge covers exactly the samples of the whole, each
    /// once. The split point is on the 1/256-pixel snapping grid, so the halves' shared edge is
    /// exactly the whole's cut.
    #[test]
    fn coverage_is_additive_over_a_split(a in grid_point(), b in grid_point(), c in grid_point(), k in 1u32..16, s in samples()) {
        let m = b + (c - b) * (k as f32 / 16.0);
        let (whole, mut settings) = pixel_scene(48, 32, &[[a, b, c]]);
        settings.samples = s;
        let (split, _) = pixel_scene(48, 32, &[[a, b, m], [a, m, c]]);
        let (sum_w, distinct_w) = cover_counts(&render(&whole, &settings));
        let (sum_s, distinct_s) = cover_counts(&render(&split, &settings));
        prop_assert_eq!(sum_w, distinct_w);
        prop_assert_eq!(sum_s, distinct_s, "the halves overlap");
        prop_assert_eq!(sum_w, sum_s, "the halves cover what the whole covers");
    }

    /// A convex polygon cut into a fan of triangles around an inner point: no sample is covered
    /// twice, and the fan covers exactly what the polygon's own fan from a vertex covers.
    #[test]
    fn fans_are_watertight(
        centre in (20.0f32..28.0, 12.0f32..20.0),
        jitter in proptest::collection::vec(0.0f32..0.8, 5..12),
        radius in 4.0f32..14.0,
        s in samples(),
    ) {
        let n = jitter.len();
        let centre = Vec2::new(centre.0, centre.1);
        let ring: Vec<Vec2> = (0..n)
            .map(|i| {
                let angle = (i as f32 + jitter[i]) / n as f32 * std::f32::consts::TAU;
                centre + Vec2::new(angle.cos(), angle.sin()) * radius
            })
            .collect();
        let around: Vec<[Vec2; 3]> = (0..n).map(|i| [centre, ring[i], ring[(i + 1) % n]]).collect();
        let from_vertex: Vec<[Vec2; 3]> = (1..n - 1).map(|i| [ring[0], ring[i], ring[i + 1]]).collect();
        let (a, mut settings) = pixel_scene(48, 32, &around);
        settings.samples = s;
        let (b, _) = pixel_scene(48, 32, &from_vertex);
        let (sum_a, distinct_a) = cover_counts(&render(&a, &settings));
        let (sum_b, distinct_b) = cover_counts(&render(&b, &settings));
        prop_assert_eq!(sum_a, distinct_a, "a sample covered twice");
        prop_assert_eq!(sum_b, distinct_b, "a sample covered twice");
        // The inner point is not on the snapping grid: the two fans' outlines are the same
        // polygon, so they cover the same samples.
        prop_assert_eq!(distinct_a, distinct_b);
    }

    /// Opaque triangles at distinct depths give the same image whatever order they are drawn in.
    #[test]
    fn the_depth_test_does_not_depend_on_the_order(
        tris in proptest::collection::vec((grid_point(), grid_point(), grid_point()), 2..8),
        order_seed in any::<u64>(),
    ) {
        let build = |order: &[usize]| {
            let mut mesh = Mesh { name: "depth".into(), ..Mesh::default() };
            for &k in order {
                let (a, b, c) = tris[k];
                // Each triangle flat at its own depth z = −0.1 − 0.2·k, its own colour.
                let z = -0.1 - 0.2 * k as f32;
                let base = mesh.positions.len() as u32;
                mesh.positions.extend([a, b, c].map(|p| p.extend(z)));
                mesh.colors.extend([Vec3::new(k as f32 / 8.0, 1.0 - k as f32 / 8.0, 0.5); 3]);
                mesh.normals.extend([Vec3::Z; 3]);
                mesh.indices.push([base, base + 1, base + 2]);
            }
            let (mut scene, mut settings) = pixel_scene(48, 32, &[]);
            let mut object = Object::new("depth", mesh);
            object.color = ColorSource::Vertex;
            scene.objects = vec![object];
            settings.depth_test = DepthTest::Less;
            settings.cull = pipeline::raster::CullMode::None;
            render(&scene, &settings)
        };
        let forward: Vec<usize> = (0..tris.len()).collect();
        let mut shuffled = forward.clone();
        fastrand::Rng::with_seed(order_seed).shuffle(&mut shuffled);
        let (x, y) = (build(&forward), build(&shuffled));
        prop_assert_eq!(&x.pixels.color, &y.pixels.color);
        prop_assert_eq!(&x.pixels.depth, &y.pixels.depth);
    }

    /// Every vertex clipping produces lies in the view volume −w ≤ x, y, z ≤ w with w > 0, and
    /// its barycentrics (relative to the input triangle) sum to 1 within [0, 1].
    #[test]
    fn clipping_stays_in_the_view_volume(
        p in proptest::collection::vec((-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0, -2.0f32..4.0), 3),
    ) {
        let v = |k: usize| Vec4::new(p[k].0, p[k].1, p[k].2, p[k].3);
        let corners = [Vec3::X, Vec3::Y, Vec3::Z];
        let tri = [0, 1, 2].map(|k| ClipVertex { clip: v(k), bary: corners[k] });
        if let ClipOutcome::Clipped(poly) = clip_triangle(tri) {
            prop_assert!(poly.len() >= 3);
            for q in poly {
                let c = q.clip;
                let slack = 1e-4 * c.w.abs().max(1.0);
                prop_assert!(c.w >= 1e-5 - slack, "w = {}", c.w);
                for x in [c.x, c.y, c.z] {
                    prop_assert!(x.abs() <= c.w + slack, "{c} outside");
                }
                prop_assert!((q.bary.x + q.bary.y + q.bary.z - 1.0).abs() < 1e-4);
                prop_assert!(q.bary.min_element() >= -1e-4 && q.bary.max_element() <= 1.0 + 1e-4);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// The fast rasterizer (bands in parallel, edge functions stepped) gives bit for bit the
    /// coverage, owners, depths and counts of the simple one (every sample tested on its own,
    /// one triangle after another), whatever the size, samples and depth test.
    #[test]
    fn the_fast_rasterizer_equals_the_reference(
        size in (1u32..70, 1u32..70),
        tris in proptest::collection::vec(
            (-10.0f32..80.0, -10.0f32..80.0, -10.0f32..80.0, -10.0f32..80.0, -10.0f32..80.0, -10.0f32..80.0, 0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0),
            1..24,
        ),
        s in prop_oneof![Just(Samples::X1), Just(Samples::X4), Just(Samples::X8), Just(Samples::X16)],
        test in prop_oneof![Just(DepthTest::Less), Just(DepthTest::LessEqual), Just(DepthTest::Greater), Just(DepthTest::Always)],
    ) {
        use pipeline::raster::RasterTriangle;
        let raster: Vec<RasterTriangle> = tris
            .iter()
            .enumerate()
            .filter_map(|(k, t)| {
                plain_triangle(
                    k,
                    [Vec3::new(t.0, t.1, t.6), Vec3::new(t.2, t.3, t.7), Vec3::new(t.4, t.5, t.8)],
                    size,
                )
            })
            .collect();
        fast_equals_reference(&raster, size, s, test)?;
    }

    /// Triangles smaller than a pixel or two, their corners on the 1/16-pixel grid so that
    /// their boxes' edges fall on sample positions: those whose box holds no sample are skipped
    /// by the fast rasterizer, and it must still equal the reference.
    #[test]
    fn slivers_between_the_samples_are_skipped_exactly(
        tris in proptest::collection::vec(
            (0i32..16 * 20, 0i32..16 * 12, -20i32..20, -20i32..20, -20i32..20, -20i32..20, 0.0f32..1.0),
            1..64,
        ),
        s in prop_oneof![Just(Samples::X1), Just(Samples::X4), Just(Samples::X8), Just(Samples::X16)],
        test in prop_oneof![Just(DepthTest::Less), Just(DepthTest::Always)],
    ) {
        use pipeline::raster::RasterTriangle;
        let size = (20, 12);
        let raster: Vec<RasterTriangle> = tris
            .iter()
            .enumerate()
            .filter_map(|(k, &(x, y, dx1, dy1, dx2, dy2, z))| {
                let at = |dx: i32, dy: i32| Vec3::new((x + dx) as f32 / 16.0, (y + dy) as f32 / 16.0, z);
                plain_triangle(k, [at(0, 0), at(dx1, dy1), at(dx2, dy2)], size)
            })
            .collect();
        fast_equals_reference(&raster, size, s, test)?;
    }
}

/// Raster triangle `k` with these window corners (`w = 1`, no clipping, no culling), or `None`
/// when it has no area.
fn plain_triangle(
    k: usize,
    window: [Vec3; 3],
    size: (u32, u32),
) -> Option<pipeline::raster::RasterTriangle> {
    pipeline::raster::RasterTriangle::setup(
        k as u32,
        window,
        [1.0; 3],
        pipeline::raster::Corners::ORIGINAL,
        pipeline::raster::CullMode::None,
        size,
    )
    .ok()
}

/// Draws `raster` with the fast rasterizer and with the reference one, and checks that the
/// counts, owners and depths agree bit for bit.
fn fast_equals_reference(
    raster: &[pipeline::raster::RasterTriangle],
    size: (u32, u32),
    s: Samples,
    test: DepthTest,
) -> Result<(), TestCaseError> {
    use pipeline::raster::SampleBuffers;
    let clear = test.clear_value();
    let mut fast = SampleBuffers::new(size.0, size.1, s, clear);
    let counts = fast.rasterize_all(raster, test).to_vec();
    let mut reference = SampleBuffers::new(size.0, size.1, s, clear);
    for (i, t) in raster.iter().enumerate() {
        let c = reference.rasterize_reference(t, i as u32, test);
        prop_assert_eq!(c, counts[i], "the counts of triangle {}", i);
    }
    prop_assert_eq!(&fast.triangle, &reference.triangle);
    prop_assert!(
        fast.depth
            .iter()
            .zip(&reference.depth)
            .all(|(a, b)| a.to_bits() == b.to_bits())
    );
    Ok(())
}
