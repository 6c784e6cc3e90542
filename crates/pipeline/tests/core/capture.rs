//! What a capture keeps: a colour-only capture has the same picture, a capture written into
//! the storage of another is the same frame (what is drawn from one: `capture_views.rs`).

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::raster::Samples;
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;
use pipeline::texture::Texture;

use crate::support::render;
use crate::texture::quad_mesh;

/// A lit, textured quad under a point light (Phong shading), `size`² pixels.
pub(crate) fn lit_textured_quad(size: u32, samples: Samples) -> (Scene, RenderSettings) {
    let mut quad = Object::new("quad", quad_mesh());
    quad.rotate_deg = Vec3::new(-40.0, 10.0, 0.0);
    quad.texture = Some(std::sync::Arc::new(Texture::checkerboard(64, 8)));
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![quad],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, 3.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::default(),
        lights: vec![pipeline::light::Light::Point {
            position: Vec3::new(1.0, 2.0, 3.0),
            intensity: Vec3::ONE,
            attenuation: Vec3::X,
        }],
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: size,
        height: size,
        samples,
        shading: pipeline::lighting::Frequency::Phong,
        ..RenderSettings::default()
    };
    (scene, settings)
}

#[test]
fn a_colour_only_capture_has_the_same_picture_without_the_term_buffers() {
    use pipeline::buffers::Capture;
    let (scene, full) = lit_textured_quad(48, Samples::X4);
    let a = render(&scene, &full);
    let colour = RenderSettings {
        capture: Capture::COLOR,
        ..full
    };
    let b = render(&scene, &colour);
    assert_eq!(a.pixels.color, b.pixels.color);
    assert_eq!(a.pixels.coverage, b.pixels.coverage);
    assert_eq!(a.pixels.depth, b.pixels.depth);
    assert_eq!(a.pixels.primitive, b.pixels.primitive);
    assert_eq!(a.pixels.owner, b.pixels.owner);
    assert!(a.pixels.shading.is_some() && a.pixels.texturing.is_some());
    assert!(b.pixels.shading.is_none() && b.pixels.texturing.is_none());
    // The buffers hold exactly what the settings budget, for both selections.
    assert_eq!(a.buffer_bytes(), full.capture_bytes());
    assert_eq!(b.buffer_bytes(), colour.capture_bytes());
    // The barycentrics are derived from the owner, so both have them.
    assert!((0..48 * 48).any(|i| b.barycentrics(i).is_some()));
    assert_eq!(
        (0..48 * 48).map(|i| a.barycentrics(i)).collect::<Vec<_>>(),
        (0..48 * 48).map(|i| b.barycentrics(i)).collect::<Vec<_>>()
    );
    // What a view needs: the lighting buffers for n·l, nothing more for the colour.
    use pipeline::buffers::BufferKind;
    assert_eq!(Capture::showing([BufferKind::Color]), Capture::COLOR);
    assert_eq!(
        Capture::showing([BufferKind::Color, BufferKind::NDotL]),
        Capture {
            lighting: true,
            texturing: false,
            pixel: None,
            cost: false,
        }
    );
    assert!(b.buffers().contains(&BufferKind::BaryAffine));
    assert!(!b.buffers().contains(&BufferKind::NDotL));
}

#[test]
fn reusing_a_capture_s_storage_gives_the_same_frame() {
    use pipeline::buffers::Capture;
    // The spare capture differs in everything: size, samples, scene, selection. Its stale
    // contents must not leak into the new frame.
    let (scene, settings) = lit_textured_quad(40, Samples::X4);
    let fresh = render(&scene, &settings);
    let (other_scene, other) = lit_textured_quad(64, Samples::X8);
    let mut moved = other_scene.clone();
    moved.camera.eye = Vec3::new(0.5, 0.2, 2.0);
    let spare = render(&moved, &other);
    let reused = pipeline::render_reusing(&scene, &settings, Some(spare))
        .expect("renders")
        .0;
    assert_eq!(reused, fresh);
    // Smaller into larger storage, and a colour-only spare into a full frame.
    let small = render(
        &scene,
        &RenderSettings {
            width: 8,
            height: 8,
            capture: Capture::COLOR,
            ..settings
        },
    );
    let reused = pipeline::render_reusing(&scene, &settings, Some(small))
        .expect("renders")
        .0;
    assert_eq!(reused, fresh);
    // The same size and buffers, the camera moved: pixels covered before are background now
    // (their terms must be cleared) and the reverse; the background the frame before had too
    // is left as it is.
    let mut aside = scene.clone();
    aside.camera.eye = Vec3::new(1.5, 0.4, 2.5);
    let spare = render(&aside, &settings);
    let differs = |a: &pipeline::capture::FrameCapture| {
        a.pixels
            .coverage
            .iter()
            .zip(&fresh.pixels.coverage)
            .filter(|(a, b)| (**a == 0) != (**b == 0))
            .count()
    };
    assert!(differs(&spare) > 100, "the moved frame covers other pixels");
    let reused = pipeline::render_reusing(&scene, &settings, Some(spare))
        .expect("renders")
        .0;
    assert_eq!(reused, fresh);
    // The same size and buffers, another background colour, then another depth test (whose
    // samples are cleared to 0): the background the frame before left, which a frame with the
    // same background keeps, must not stay.
    for other in [
        RenderSettings {
            background: Vec3::new(0.9, 0.1, 0.3),
            ..settings
        },
        RenderSettings {
            depth_test: pipeline::raster::DepthTest::Greater,
            ..settings
        },
    ] {
        let spare = render(&scene, &other);
        let reused = pipeline::render_reusing(&scene, &settings, Some(spare))
            .expect("renders")
            .0;
        assert_eq!(reused, fresh);
    }
}

/// A scene of `layout` runs of triangles, `(count, straddles)`: triangles behind the camera
/// (dropped whole by clipping) or big ones across the near and side planes (each clipped into a
/// fan of several raster triangles).
fn runs_of_triangles(layout: &[(usize, bool)]) -> Scene {
    let mut positions = Vec::new();
    for &(count, straddles) in layout {
        for i in 0..count {
            let dy = i as f32 * 1e-4;
            positions.extend(if straddles {
                [
                    Vec3::new(-30.0, -1.0 - dy, 10.0),
                    Vec3::new(30.0, -1.0 - dy, 10.0),
                    Vec3::new(0.0, -1.0 - dy, -60.0),
                ]
            } else {
                [
                    Vec3::new(-1.0, dy, 5.0),
                    Vec3::new(1.0, dy, 5.0),
                    Vec3::new(0.0, 1.0 + dy, 5.0),
                ]
            });
        }
    }
    let n = positions.len() as u32;
    let mesh = pipeline::mesh::Mesh {
        name: "runs".into(),
        normals: vec![Vec3::Y; n as usize],
        positions,
        uvs: Vec::new(),
        colors: Vec::new(),
        indices: (0..n / 3).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect(),
        labels: Vec::new(),
    };
    Scene {
        uniforms: Default::default(),
        objects: vec![Object::new("runs", mesh)],
        camera: Camera {
            eye: Vec3::ZERO,
            at: Vec3::NEG_Z,
            up: Vec3::Y,
        },
        projection: Projection::default(),
        ..Scene::default()
    }
}

#[test]
fn primitives_assembled_in_chunks_keep_their_raster_triangles_in_order() {
    // The assembly works on chunks of primitives in parallel, each writing its raster triangles
    // where its primitives' would go and setting aside what does not fit. Both ways of joining
    // them are exercised: a chunk with more triangles than primitives after chunks with fewer
    // (moved forward in place), and every chunk with more (the list rebuilt).
    let settings = RenderSettings {
        width: 64,
        height: 48,
        ..RenderSettings::default()
    };
    for layout in [
        vec![(3000, false), (600, true), (6000, false)],
        vec![(3000, true)],
    ] {
        let scene = runs_of_triangles(&layout);
        let frame = render(&scene, &settings);
        assert!(
            frame.triangles.len() > 2048,
            "clipping made fans: {} triangles",
            frame.triangles.len()
        );
        let mut next = 0;
        for (id, p) in frame.primitives.iter().enumerate() {
            assert_eq!(p.id as usize, id);
            assert_eq!(
                p.triangles[0],
                next,
                "primitive {id} begins where {} ended",
                id.max(1) - 1
            );
            next = p.triangles[1];
            assert!(
                frame.triangles[p.triangles[0] as usize..next as usize]
                    .iter()
                    .all(|t| t.primitive == p.id)
            );
        }
        assert_eq!(next as usize, frame.triangles.len());
        // Each primitive's triangles are those it has drawn alone.
        for id in (0..frame.primitives.len()).step_by(97) {
            let mut alone = scene.clone();
            let mesh = std::sync::Arc::make_mut(&mut alone.objects[0].mesh);
            mesh.indices = vec![mesh.indices[id]];
            let single = render(&alone, &settings);
            let p = &frame.primitives[id];
            assert_eq!(single.primitives[0].fate, p.fate, "primitive {id}");
            assert_eq!(single.primitives[0].clipped_polygon, p.clipped_polygon);
            let own: Vec<_> = frame.triangles[p.triangles[0] as usize..p.triangles[1] as usize]
                .iter()
                .map(|t| {
                    let mut t = *t;
                    t.primitive = 0;
                    t
                })
                .collect();
            assert_eq!(single.triangles, own, "primitive {id}");
        }
    }
}

/// A capture that keeps no term buffer but one pixel's terms (a draft's inspected pixel) has
/// that pixel's terms and lookup as the full capture has them, λ and the footprint included
/// when the sampler reads one level only (the colour then needs no derivatives).
#[test]
fn the_inspected_pixel_keeps_its_terms_without_the_term_buffers() {
    use pipeline::buffers::Capture;
    use pipeline::texture::{Mipmap, Sampler};
    let (scene, settings) = lit_textured_quad(32, Samples::X4);
    for mipmap in [Mipmap::None, Mipmap::Linear] {
        let settings = RenderSettings {
            sampler: Sampler {
                mipmap,
                ..settings.sampler
            },
            ..settings
        };
        let full = render(&scene, &settings);
        let at = (13, 17);
        let kept = render(
            &scene,
            &RenderSettings {
                capture: Capture::COLOR.with_pixel(Some(at)),
                ..settings
            },
        );
        assert_eq!(full.pixels.color, kept.pixels.color);
        assert!(kept.pixels.shading.is_none() && kept.pixels.texturing.is_none());
        let (a, b) = (full.pixel_record(at.0, at.1), kept.pixel_record(at.0, at.1));
        let (a, b) = (a.expect("a record"), b.expect("a record"));
        let lookup = a.texture.clone().expect("a lookup");
        assert!(lookup.lod.abs() > 0.0 && lookup.footprint != [0.0; 4]);
        assert_eq!((a.lighting, a.texture), (b.lighting, b.texture));
        // Outside the viewport: nothing kept, nothing panics.
        let outside = render(
            &scene,
            &RenderSettings {
                capture: Capture::COLOR.with_pixel(Some((32, 0))),
                ..settings
            },
        );
        assert!(outside.pixels.inspected.is_none());
    }
}

#[test]
fn coarse_shading_shades_a_2x2_block_once_per_triangle_and_edges_as_usual() {
    use pipeline::buffers::Capture;
    use pipeline::raster::NONE;
    let (scene, settings) = lit_textured_quad(48, Samples::X1);
    let full = render(&scene, &settings);
    let (w, h) = (settings.width as usize, settings.height as usize);
    // Also with an exact pixel (an inspected one, window coordinates): the second of its block,
    // which would otherwise take the first's shading.
    for exact in [None, Some((25, 29))] {
        let coarse = render(
            &scene,
            &RenderSettings {
                coarse_shading: true,
                capture: Capture::COLOR.with_pixel(exact),
                ..settings
            },
        );
        let px = (&full.pixels, &coarse.pixels);
        assert_eq!(px.0.coverage, px.1.coverage);
        assert_eq!(px.0.depth, px.1.depth);
        assert_eq!(px.0.owner, px.1.owner);
        let exact_index = exact.map(|(x, y)| (h - 1 - y as usize) * w + x as usize);
        let interior = |i: usize| px.0.coverage[i] == 1 && px.0.owner[i] != NONE;
        let mut reused = 0;
        for i in 0..px.0.color.len() {
            let (row, col) = (i / w, i % w);
            // The block's first pixel inside one triangle (top row first; the exact pixel
            // aside) is shaded; the block's other pixels inside that triangle take its shading.
            let first = [(0, 0), (0, 1), (1, 0), (1, 1)]
                .into_iter()
                .map(|(r, c)| ((row & !1) + r, (col & !1) + c))
                .filter(|&(r, c)| c < w && r < h)
                .map(|(r, c)| r * w + c)
                .find(|&j| interior(j) && Some(j) != exact_index);
            let expected = match first {
                Some(j) if interior(i) && px.0.owner[j] == px.0.owner[i] => j,
                _ => i,
            };
            let expected = if Some(i) == exact_index { i } else { expected };
            reused += usize::from(expected != i);
            assert_eq!(px.1.color[i], px.0.color[expected], "pixel {col}, {row}");
        }
        // The quad fills most of the image: most pixels take another's shading.
        assert!(
            reused > px.0.color.len() / 3,
            "{reused} pixels reused a shading"
        );
        if let (Some(i), Some((x, y))) = (exact_index, exact) {
            assert!(
                interior(i) && interior(i - 1),
                "the exact pixel is inside the quad"
            );
            assert_ne!(
                px.0.color[i],
                px.0.color[i - 1],
                "and differs from its neighbour"
            );
            assert_eq!(px.1.color[i], px.0.color[i]);
            // Its explanation, derived from its own records, lands on its colour.
            let e = coarse.explain(x, y).expect("explained");
            assert!((e.shaded - e.color).abs().max_element() < 1e-4);
            // No term buffer is kept, but its terms and lookup are, as the full frame's.
            assert!(coarse.pixels.shading.is_none() && coarse.pixels.texturing.is_none());
            let (a, b) = (full.pixel_record(x, y), coarse.pixel_record(x, y));
            let (a, b) = (a.expect("a record"), b.expect("a record"));
            assert!(a.lighting.is_some() && a.texture.is_some());
            assert_eq!((a.lighting, a.texture), (b.lighting, b.texture));
            assert_eq!(full.pixel_vectors(x, y), coarse.pixel_vectors(x, y));
            // Its neighbour has none kept.
            let n = coarse.pixel_record(x - 1, y).expect("a record");
            assert!(n.lighting.is_none() && n.texture.is_none());
        }
    }
}
