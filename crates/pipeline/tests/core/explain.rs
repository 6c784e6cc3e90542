//! "Explain this pixel": the edge functions, weights and colour of a small triangle, against
//! values worked out by hand.

use glam::{Vec2, Vec3};
use pipeline::capture::{Remark, Section};
use pipeline::scene::ColorSource;

use crate::support::{pixel_scene, render};

/// The triangle (0, 0), (4, 0), (0, 4) in window pixels, its corners red, green and blue.
fn rgb_triangle(offset: f32) -> pipeline::capture::FrameCapture {
    let o = Vec2::splat(offset);
    let (mut scene, settings) = pixel_scene(
        8,
        8,
        &[[o, o + Vec2::new(4.0, 0.0), o + Vec2::new(0.0, 4.0)]],
    );
    let object = &mut scene.objects[0];
    let mut mesh = (*object.mesh).clone();
    mesh.colors = vec![Vec3::X, Vec3::Y, Vec3::Z];
    object.mesh = std::sync::Arc::new(mesh);
    object.color = ColorSource::Vertex;
    render(&scene, &settings)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn the_edge_functions_and_weights_of_a_small_triangle_are_the_hand_computed_ones() {
    let capture = rgb_triangle(0.0);
    // Pixel (1, 1), centre p = (1.5, 1.5). With a = (0, 0), b = (4, 0), c = (0, 4):
    // E_0 = (c − b) × (p − b) = (−4)(1.5) − (4)(1.5 − 4) = −6 + 10 = 4,
    // E_1 = (a − c) × (p − c) = 0·(1.5 − 4) − (−4)(1.5) = 6,
    // E_2 = (b − a) × (p − a) = 4·1.5 − 0 = 6; their sum 16 is twice the area 8;
    // λ = (4, 6, 6)/16 = (0.25, 0.375, 0.375), and the colour is λ·(red, green, blue).
    let e = capture.explain(1, 1).expect("the pixel is covered");
    for (k, expected) in [4.0, 6.0, 6.0].into_iter().enumerate() {
        assert!(
            close(e.edges.centre[k], expected),
            "E_{k} = {}",
            e.edges.centre[k]
        );
    }
    assert!(close(e.edges.area2, 16.0));
    for (k, l) in [0.25, 0.375, 0.375].into_iter().enumerate() {
        assert!(close(e.edges.lambda[k], l));
        // An orthographic projection has w = 1: perspective-correct weights are the affine ones.
        assert!((e.bary_perspective[k] - l as f32).abs() < 1e-6);
    }
    assert_eq!(e.corner_vertex, [Some(0), Some(1), Some(2)]);
    assert!(
        (e.color - Vec3::new(0.25, 0.375, 0.375))
            .abs()
            .max_element()
            < 1e-6
    );
    assert_eq!(e.edges.samples.len(), 1);
    assert!(e.edges.samples[0].inside && e.edges.samples[0].on_edges.is_empty());
    // The derivation has every part and ends with the 8-bit colour.
    for section in [
        Section::Vertices,
        Section::Rasterization,
        Section::Interpolation,
        Section::Colour,
    ] {
        assert!(e.lines.iter().any(|l| l.section == section), "{section:?}");
    }
    let last = e.lines.last().expect("lines");
    assert_eq!(last.result, "(64, 96, 96)");
    // The E_0 line substitutes the numbers of the formula.
    let e0 = e
        .lines
        .iter()
        .find(|l| l.formula.starts_with("E_0"))
        .expect("E_0");
    assert_eq!(e0.result, "4");
    // The pixel record carries it, and each fragment its own test.
    let record = capture.pixel_record(1, 1).expect("inside the viewport");
    assert_eq!(record.explanation.as_ref(), Some(&e));
    assert!(close(record.fragments[0].edges.centre[1], 6.0));
    // Nothing drawn, nothing to explain.
    assert!(capture.explain(7, 7).is_none());
}

#[test]
fn the_fill_rule_decides_samples_on_an_edge() {
    // Moved by half a pixel, the corners sit on pixel centres: (0.5, 0.5), (4.5, 0.5), (0.5, 4.5).
    // The edge c → a (x = 0.5, going down) is a left edge, a → b (y = 0.5, the triangle above
    // it) a bottom edge.
    let capture = rgb_triangle(0.5);
    // Pixel (0, 1), centre (0.5, 1.5): E_0 = (−4)(1.5 − 0.5) − (4)(0.5 − 4.5) = 12,
    // E_1 = 0 on the left edge: covered; E_2 = 4·1 = 4.
    let left = capture
        .explain(0, 1)
        .expect("a sample on a left edge is covered");
    let s = &left.edges.samples[0];
    assert_eq!(s.e, [12.0, 0.0, 4.0]);
    assert_eq!(s.on_edges, vec![1]);
    assert!(s.inside);
    assert_eq!(left.edges.top_left, [false, true, false]);
    assert!(
        left.lines
            .iter()
            .any(|l| l.remarks.contains(&Remark::OnEdge {
                edge: 1,
                top_left: true
            }))
    );
    // Pixel (1, 0), centre (1.5, 0.5): E_2 = 0 on the bottom edge: not covered, nothing drawn.
    assert!(capture.explain(1, 0).is_none());
    let record = capture.pixel_record(1, 0).expect("inside the viewport");
    assert!(record.fragments.is_empty());
}

#[test]
fn the_derivation_arrives_at_the_colour_the_render_made() {
    use pipeline::light::Light;
    use pipeline::lighting::Frequency;
    use pipeline::raster::Samples;
    let (mut scene, base) = crate::capture::lit_textured_quad(48, Samples::X1);
    scene.lights.insert(
        0,
        Light::Ambient {
            intensity: Vec3::splat(0.3),
        },
    );
    // Pixels brighter than white (this light's highlight) say that the buffer clamps them.
    let mut clamped = 0;
    for textured in [true, false] {
        if !textured {
            scene.objects[0].texture = None;
        }
        for shading in [
            Frequency::Unlit,
            Frequency::Flat,
            Frequency::Gouraud,
            Frequency::Phong,
        ] {
            let settings = pipeline::settings::RenderSettings { shading, ..base };
            let capture = render(&scene, &settings);
            let mut explained = 0;
            for y in (0..48).step_by(5) {
                for x in (0..48).step_by(5) {
                    let Some(e) = capture.explain(x, y) else {
                        continue;
                    };
                    if e.coverage[0] < e.coverage[1] {
                        continue;
                    }
                    explained += 1;
                    // The derivation recomputes with the render's own functions from the
                    // capture; it lands on the stored colour, clamped to [0, 1] as the colour
                    // buffer keeps it (the normal it starts from is interpolated at 32 bits,
                    // the render's too).
                    let stored = e.shaded.clamp(Vec3::ZERO, Vec3::ONE);
                    assert!(
                        (stored - e.color).abs().max_element() < 1e-4,
                        "{shading:?} textured {textured} at ({x}, {y}): {} vs {}",
                        e.shaded,
                        e.color
                    );
                    let says_clamped = e.lines.iter().any(|l| l.formula == "c_s = clamp(c, 0, 1)");
                    assert_eq!(says_clamped, stored != e.shaded, "at ({x}, {y})");
                    clamped += usize::from(says_clamped);
                    assert_eq!(e.texture.is_some(), textured);
                    assert_eq!(e.lighting.is_some(), shading != Frequency::Unlit);
                }
            }
            assert!(explained > 20, "{shading:?}: {explained} pixels explained");
        }
    }
    assert!(clamped > 0, "no explained pixel passes white");
}
