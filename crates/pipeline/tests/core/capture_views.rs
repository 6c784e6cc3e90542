//! What is drawn from a capture: a dim lighting term shown brighter by a stated factor with its
//! values kept, the overlays (hidden triangles left out, the focus stressed), the box that holds
//! every covered pixel, and the first wrong pixel and the difference picture, upright.

use glam::Vec3;
use pipeline::raster::Samples;
use pipeline::scene::Scene;

use crate::capture::lit_textured_quad;
use crate::support::render;

/// A dim lighting term is shown brighter by the largest of 1, 1.5, 2, 3, 4, 6, 8, 12, 16 with
/// `g·max ≤ 1`, and the buffer's values stay as they are: ambient `k_a·I_a·c = 1 · 0.2 · 0.8 =
/// 0.16` is shown ×6 (0.96; ×8 would pass 1); `1 · 0.7 · 0.8 = 0.56` ×1.5 (0.84; ×2 would pass
/// 1), which a gain by powers of two left as it is, dim on a projector; `1 · 0.9 · 0.8 = 0.72`
/// as it is (×1.5 would pass 1).
#[test]
fn a_dim_term_is_shown_brighter_and_its_values_stay() {
    use pipeline::buffers::BufferKind;
    use pipeline::light::{Light, Material};
    use pipeline::scene::ColorSource;
    let (mut scene, settings) = lit_textured_quad(16, Samples::X1);
    let quad = &mut scene.objects[0];
    quad.texture = None;
    quad.color = ColorSource::Uniform(Vec3::splat(0.8));
    quad.material = Material {
        ka: Vec3::ONE,
        ..Material::default()
    };
    scene.lights = vec![Light::Ambient {
        intensity: Vec3::splat(0.2),
    }];
    let c = render(&scene, &settings);
    assert_eq!(c.term_gain(BufferKind::Ambient), 6.0);
    // Nothing lit but the ambient: no diffuse or specular, nothing to brighten.
    assert_eq!(c.term_gain(BufferKind::Diffuse), 1.0);
    assert_eq!(c.term_gain(BufferKind::Color), 1.0);
    let centre = (8, 8);
    let raw = c.image(BufferKind::Ambient).get_pixel(centre.0, centre.1).0;
    let shown = c
        .image_gained(BufferKind::Ambient, 6.0)
        .get_pixel(centre.0, centre.1)
        .0;
    assert_eq!(raw[0], (0.16_f32 * 255.0).round() as u8);
    assert_eq!(shown[0], (0.96_f32 * 255.0).round() as u8);
    for (intensity, gain) in [(0.7, 1.5), (0.9, 1.0)] {
        scene.lights = vec![Light::Ambient {
            intensity: Vec3::splat(intensity),
        }];
        assert_eq!(
            render(&scene, &settings).term_gain(BufferKind::Ambient),
            gain,
            "ambient {intensity}"
        );
    }
}

/// The overlays of a picture of the rasterizer draw the triangles in sight: one drawn over
/// entirely by a later one (depth test `always`) owns no sample and is left out; the focus
/// primitive's box and edges are strong, the rest faint.
#[test]
fn overlays_leave_out_hidden_triangles_and_stress_the_focus() {
    use glam::Vec2;
    use pipeline::overlay::{OverlayKind, Shape};
    let t = [
        Vec2::new(2.0, 2.0),
        Vec2::new(14.0, 2.0),
        Vec2::new(2.0, 14.0),
    ];
    let other = [
        Vec2::new(20.0, 2.0),
        Vec2::new(30.0, 2.0),
        Vec2::new(20.0, 12.0),
    ];
    let (scene, settings) = crate::support::pixel_scene(32, 16, &[t, t, other]);
    let c = crate::support::render(&scene, &settings);
    assert_eq!(c.visible_triangles(), Some(vec![false, true, true]));
    let visible = c.visible_triangles();
    let focus = c.primitive_at(22, 4);
    assert_eq!(focus, Some(2));
    let edges: Vec<Shape> = c
        .overlay_shapes_focused(OverlayKind::TriangleEdges, visible.as_deref(), focus)
        .collect();
    let styles: Vec<(u8, f32)> = edges
        .iter()
        .map(|s| match s {
            Shape::Polyline { color, width, .. } => (color[3], *width),
            other => panic!("an edge overlay draws polylines, not {other:?}"),
        })
        .collect();
    assert_eq!(
        styles,
        vec![(66, 1.0), (220, 2.5)],
        "triangle 1 faint, 2 strong"
    );
    // Without a focus every triangle in sight is faint; all three without visibility data.
    let faint = c.overlay_shapes_focused(OverlayKind::BoundingBoxes, visible.as_deref(), None);
    assert!(
        faint
            .map(|s| match s {
                Shape::Rect { color, .. } => color[3],
                _ => 0,
            })
            .all(|a| a == 60)
    );
    assert_eq!(
        c.overlay_shapes_focused(OverlayKind::BoundingBoxes, None, None)
            .count(),
        3
    );
}

/// The covered box is that of the covered pixels, rows counted from the top: a triangle with
/// its legs on x = 2 and y = 2 (window coordinates, y up) and its hypotenuse on x + y = 16
/// covers the pixels whose centres (x + ½, y + ½) are inside. The centres on the hypotenuse
/// (a right edge: not owned, by the top-left rule) are out, so the columns are 2..13 and the
/// window rows 2..13, image rows 16 − 13..16 − 2.
#[test]
fn the_covered_box_holds_every_covered_pixel() {
    use glam::Vec2;
    let t = [
        Vec2::new(2.0, 2.0),
        Vec2::new(14.0, 2.0),
        Vec2::new(2.0, 14.0),
    ];
    let (scene, settings) = crate::support::pixel_scene(32, 16, &[t]);
    let c = crate::support::render(&scene, &settings);
    assert_eq!(c.covered_box(), Some([2, 3, 13, 14]));
    let other = [
        Vec2::new(20.0, 2.0),
        Vec2::new(30.0, 2.0),
        Vec2::new(20.0, 12.0),
    ];
    let (scene, settings) = crate::support::pixel_scene(32, 16, &[t, other]);
    let c = crate::support::render(&scene, &settings);
    assert_eq!(c.covered_box(), Some([2, 3, 29, 14]));
    let (scene, settings) = crate::support::pixel_scene(32, 16, &[]);
    assert_eq!(
        crate::support::render(&scene, &settings).covered_box(),
        None
    );
}

/// Two frames that differ in a known place, worked out by hand: on an 8×6 window, a triangle
/// with corners at window (0, 0), (3.2, 0) and (0, 3.2) covers the pixels whose centre
/// `(x + ½, y + ½)` has `x + y + 1 < 3.2`, so `x + y ≤ 2`: rows y = 0 (x = 0, 1, 2), y = 1
/// (x = 0, 1) and y = 2 (x = 0), the bottom-left corner. Compared with the empty frame, the
/// first differing pixel reading from the top is window (0, 2) — image row 6 − 1 − 2 = 3 — and
/// the difference picture is yellow (coverage) at image rows 3, 4, 5 in the bottom-left, dim
/// everywhere else. The pixel reported is one where the frames differ.
#[test]
fn the_first_wrong_pixel_and_the_difference_picture_are_upright() {
    use glam::Vec2;
    let tri = [
        Vec2::new(0.0, 0.0),
        Vec2::new(3.2, 0.0),
        Vec2::new(0.0, 3.2),
    ];
    let (scene, settings) = crate::support::pixel_scene(8, 6, &[tri]);
    let drawn = render(&scene, &settings);
    let empty = render(
        &Scene {
            uniforms: Default::default(),
            objects: Vec::new(),
            ..scene.clone()
        },
        &settings,
    );
    let d = drawn.difference(&empty, 1.0).expect("same size");
    assert_eq!(d.coverage_differs, 6);
    assert_eq!(d.matching, 48 - 6);
    assert_eq!(
        d.first,
        Some((0, 2)),
        "window (0, 2): the top of the corner"
    );
    let (x, y) = d.first.expect("a difference");
    let (a, b) = (
        drawn.pixel_record(x, y).expect("in the window"),
        empty.pixel_record(x, y).expect("in the window"),
    );
    assert_ne!(a.coverage, b.coverage, "the reported pixel differs");
    let picture = drawn.difference_image(&empty, pipeline::capture::Criteria::colour(1.0));
    // Coverage that differs is striped: yellow where (col + row) / 2 is even, white where it
    // is odd — (0, 3): 3 / 2 = 1, white; (0, 4), (1, 4), (0, 5): 2, yellow; (1, 5), (2, 5): 3,
    // white.
    let (yellow, white) = (image::Rgba([255, 220, 0, 255]), image::Rgba([255; 4]));
    let covered: [((u32, u32), image::Rgba<u8>); 6] = [
        ((0, 3), white),
        ((0, 4), yellow),
        ((1, 4), yellow),
        ((0, 5), yellow),
        ((1, 5), white),
        ((2, 5), white),
    ];
    for row in 0..6 {
        for col in 0..8 {
            let p = *picture.get_pixel(col, row);
            match covered.iter().find(|(at, _)| *at == (col, row)) {
                Some((_, c)) => assert_eq!(p, *c, "image pixel ({col}, {row})"),
                None => assert!(
                    p != yellow && p != white,
                    "image pixel ({col}, {row}): {p:?}"
                ),
            }
        }
    }
}

/// A lighting term's picture keeps its object's outline: the covered pixels beside uncovered
/// ones are at least the faint `OUTLINE` where the term is darker, the inside and the outside
/// keep the term's values, and the exported buffer has no outline. The triangle (2, 2),
/// (14, 2), (2, 14) in window coordinates (y up, 16 rows): window pixel (2, 5), centre
/// (2.5, 5.5), is inside and its left neighbour's centre (1.5, 5.5) is not — image row
/// 16 − 1 − 5 = 10; window pixel (5, 5) and its four neighbours are inside (x + y < 16).
#[test]
fn a_lighting_terms_picture_keeps_its_objects_outline() {
    use pipeline::buffers::BufferKind;
    use pipeline::capture::OUTLINE;
    let t = [
        glam::Vec2::new(2.0, 2.0),
        glam::Vec2::new(14.0, 2.0),
        glam::Vec2::new(2.0, 14.0),
    ];
    let (scene, settings) = crate::support::pixel_scene(32, 16, &[t]);
    let c = render(&scene, &settings);
    let exported = c.image(BufferKind::Specular);
    let shown = c.image_shown(BufferKind::Specular, 1.0);
    let rim = (2, 10);
    let inside = (5, 10);
    let outside = (1, 10);
    let px = |img: &image::RgbaImage, (x, y): (u32, u32)| {
        let p = img.get_pixel(x, y).0;
        [p[0], p[1], p[2]]
    };
    for ((s, e), o) in px(&shown, rim).iter().zip(px(&exported, rim)).zip(OUTLINE) {
        assert!(*s >= o, "{:?}", px(&shown, rim));
        assert_eq!(*s, e.max(o));
    }
    assert_eq!(px(&shown, inside), px(&exported, inside));
    assert_eq!(px(&shown, outside), [0, 0, 0]);
    assert_ne!(
        px(&exported, rim),
        OUTLINE,
        "the exported buffer has no outline"
    );
    // The colour buffer is shown as it is.
    assert_eq!(
        c.image_shown(BufferKind::Color, 1.0).as_raw(),
        c.image(BufferKind::Color).as_raw()
    );
}
