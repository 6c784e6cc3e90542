//! The resolve's fast paths — background spans, runs of fragments lit together in lanes, the
//! colour-only lighting, coarse runs — give the same bits as the reference path, which
//! resolves every pixel by itself (`pipeline::render_reference`), on every step of every
//! lesson: the frame the step shows, the settings it compares side by side, and the draft
//! drawn while a slider is dragged; every buffer kept, and the colour alone.

use pipelens::lesson::{Document, load_file};
use pipeline::buffers::Capture;
use pipeline::capture::{FrameCapture, PixelBuffers};
use pipeline::settings::RenderSettings;

use crate::support::lesson_files;

/// Where two frames' pixel buffers first differ: the buffer's name and the pixel, or `None`
/// when every buffer holds the same bits.
fn first_difference(fast: &PixelBuffers, reference: &PixelBuffers) -> Option<(String, usize)> {
    fn at<T>(
        name: &str,
        a: &[T],
        b: &[T],
        same: impl Fn(&T, &T) -> bool,
    ) -> Option<(String, usize)> {
        if a.len() != b.len() {
            return Some((
                format!("{name} (length {} against {})", a.len(), b.len()),
                0,
            ));
        }
        a.iter()
            .zip(b)
            .position(|(a, b)| !same(a, b))
            .map(|i| (name.to_owned(), i))
    }
    let bits3 = |a: &[f32; 3], b: &[f32; 3]| a.map(f32::to_bits) == b.map(f32::to_bits);
    at(
        "coverage",
        &fast.coverage,
        &reference.coverage,
        PartialEq::eq,
    )
    .or_else(|| {
        at("depth", &fast.depth, &reference.depth, |a, b| {
            a.to_bits() == b.to_bits()
        })
    })
    .or_else(|| {
        at(
            "primitive",
            &fast.primitive,
            &reference.primitive,
            PartialEq::eq,
        )
    })
    .or_else(|| at("owner", &fast.owner, &reference.owner, PartialEq::eq))
    .or_else(|| at("colour", &fast.color, &reference.color, bits3))
    .or_else(|| {
        kept(
            "lighting terms",
            (fast.shading.as_ref(), reference.shading.as_ref()),
            |b| b.n_dot_l.len(),
            |b, i| format!("{:?}", b.at(i)),
        )
    })
    .or_else(|| {
        kept(
            "texture lookups",
            (fast.texturing.as_ref(), reference.texturing.as_ref()),
            |b| b.uv.len(),
            |b, i| format!("{:?}", b.at(i)),
        )
    })
}

/// Where buffers `name` that a frame may keep or not first differ: kept by one frame only, or
/// at the first of their `len` pixels whose values differ (`at`: every value printed, which
/// tells apart any two bit patterns but NaNs).
fn kept<B>(
    name: &str,
    (fast, reference): (Option<&B>, Option<&B>),
    len: impl Fn(&B) -> usize,
    at: impl Fn(&B, usize) -> String,
) -> Option<(String, usize)> {
    match (fast, reference) {
        (Some(a), Some(b)) => (0..len(a))
            .find(|&i| at(a, i) != at(b, i))
            .map(|i| (name.to_owned(), i)),
        (None, None) => None,
        _ => Some((format!("{name} (kept by one only)"), 0)),
    }
}

/// Renders `scene` with `settings` by the fast paths and by the reference path and panics,
/// naming `what` and the pixel, where a buffer differs. Returns the fast frame.
fn assert_same_bits(
    scene: &pipeline::scene::Scene,
    settings: &RenderSettings,
    what: &str,
) -> FrameCapture {
    let fast = pipeline::render(scene, settings).unwrap_or_else(|e| panic!("{what}: {e}"));
    let reference =
        pipeline::render_reference(scene, settings).unwrap_or_else(|e| panic!("{what}: {e}"));
    if let Some((buffer, i)) = first_difference(&fast.pixels, &reference.pixels) {
        let w = settings.width as usize;
        panic!(
            "{what}: the {buffer} of pixel ({}, {}) (image column, row) differ between the fast \
             paths and the reference path",
            i % w,
            i / w
        );
    }
    fast
}

#[test]
fn every_lesson_step_resolves_to_the_same_bits_by_the_fast_paths_and_the_reference_path() {
    let files = lesson_files();
    assert!(!files.is_empty());
    let (mut frames, mut covered) = (0usize, 0usize);
    for path in files {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            continue;
        };
        let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
        for k in 0..lesson.steps.len() {
            // The step as it opens, and part-way through its animation.
            for t in [0.0, 1.7] {
                let mut spec = lesson.spec_playing(k, t);
                // Small (the aspect kept), so that the whole set renders quickly; runs,
                // spans and edges are there at any size.
                let (w, h) = (spec.settings.width, spec.settings.height);
                spec.settings.width = w.min(200);
                spec.settings.height = (u64::from(h) * u64::from(spec.settings.width)
                    / u64::from(w.max(1)))
                .clamp(1, 128) as u32;
                let mut cases = vec![("the step".to_owned(), spec.settings)];
                if let Some(c) = lesson.steps[k].compare {
                    cases.extend(c.variants(&spec.settings));
                }
                // The draft shown while a slider is dragged: one sample, 2×2 coarse shading.
                cases.push((
                    "the draft".to_owned(),
                    RenderSettings {
                        samples: pipeline::raster::Samples::X1,
                        coarse_shading: true,
                        ..spec.settings
                    },
                ));
                for (label, settings) in cases {
                    for capture in [Capture::FULL, Capture::COLOR] {
                        let settings = RenderSettings {
                            capture,
                            ..settings
                        };
                        let what = format!(
                            "{name} step {} at t = {t}, {label}, {}",
                            k + 1,
                            if capture == Capture::FULL {
                                "every buffer"
                            } else {
                                "the colour only"
                            }
                        );
                        let frame = assert_same_bits(&spec.scene, &settings, &what);
                        frames += 1;
                        covered += frame.pixels.coverage.iter().filter(|&&c| c > 0).count();
                    }
                }
            }
        }
    }
    // Every lesson's steps, so hundreds of frames, and most of them draw something.
    assert!(frames > 500, "only {frames} frames compared");
    assert!(
        covered > 1_000_000,
        "only {covered} covered pixels compared"
    );
}
