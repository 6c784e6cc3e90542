//! The colours that carry a meaning stay apart to colour-blind eyes (issue "Every student can
//! use it"): in every set of meanings a picture shows together, every pair and each meaning
//! against its ground keep `vision::APART` in CIELAB, for normal vision and as Machado et al.'s
//! protanope, deuteranope and tritanope see them; and a lighting term's picture is bright
//! enough to read on a projector.

use pipelens::palette::vision::{APART, Vision, closest};
use pipelens::palette::{Rgb, SETS};

/// Asserts that `meanings` on `grounds` read apart for every way of seeing.
fn assert_apart(set: &str, meanings: &[(&'static str, Rgb)], grounds: &[Rgb]) {
    for vision in Vision::ALL {
        for (d, a, b) in closest(vision, meanings, grounds) {
            assert!(
                d >= APART,
                "{set}, {}: {a} and {b} are {d:.1} apart (at least {APART} asked)",
                vision.name()
            );
        }
    }
}

#[test]
fn every_set_of_meanings_reads_apart_to_colour_blind_eyes() {
    for set in &SETS {
        assert_apart(set.name, set.meanings, set.grounds);
    }
    // The difference picture: its four meanings and the coverage's stripe, a colour difference
    // at its brightest and at its dimmest, over every grey a matching pixel can have.
    let [colour, coverage, depth, owner] = pipeline::capture::DIFFERENCE_COLOURS;
    let greys: Vec<Rgb> = (0..=pipeline::capture::MATCH_GREY_MAX)
        .map(|v| [v; 3])
        .collect();
    let dimmest = [
        (f32::from(colour[0]) * pipeline::capture::DIFFERENCE_DIMMEST) as u8,
        colour[1],
        colour[2],
    ];
    for red in [colour, dimmest] {
        assert_apart(
            "the difference picture",
            &[
                ("colour", red),
                ("coverage", coverage),
                ("coverage's stripe", pipeline::capture::COVERAGE_STRIPE),
                ("depth", depth),
                ("another triangle", owner),
            ],
            &greys,
        );
    }
}

/// The difference picture draws a pixel whose colour differs by the smallest step it reports
/// with the dimmest red, the same red the test above keeps apart from the matching greys.
#[test]
fn a_small_colour_difference_is_drawn_in_the_dimmest_red() {
    use pipeline::capture::{Criteria, DIFFERENCE_COLOURS, DIFFERENCE_DIMMEST};
    let spec = crate::support::lesson("25-lab-model-projection").spec_at(0);
    let frame = pipeline::render(&spec.scene, &spec.settings).expect("renders");
    let mut other = frame.clone();
    // One covered pixel, its red one 8-bit step brighter (or darker at the top).
    let i = (0..other.pixels.color.len())
        .find(|&i| other.pixels.coverage[i] > 0)
        .expect("a covered pixel");
    let r = &mut other.pixels.color[i][0];
    *r = if *r < 0.5 {
        *r + 1.5 / 255.0
    } else {
        *r - 1.5 / 255.0
    };
    let picture = other.difference_image(&frame, Criteria::colour(0.0));
    let w = frame.width() as usize;
    let pixel = picture.get_pixel((i % w) as u32, (i / w) as u32).0;
    let red = DIFFERENCE_COLOURS[0];
    assert_eq!(
        pixel,
        [
            (f32::from(red[0]) * DIFFERENCE_DIMMEST) as u8,
            red[1],
            red[2],
            255
        ]
    );
}

/// A step that shows a lighting term shows it bright enough for a projector: at every moment
/// of its animation (five, from start to end) its brightest covered channel is drawn at two
/// thirds of full brightness or more (the term shown brighter by the factor its note states).
/// Lesson 10's diffuse term peaks at 0.54 (RGB 137, 60, 43 on screen): a gain by powers of
/// two left it as it is; ×1.5 draws it at 0.81.
#[test]
fn a_lighting_term_is_shown_at_two_thirds_of_full_brightness_or_more() {
    use pipeline::buffers::BufferKind;
    let mut checked = 0;
    for path in crate::support::lesson_files() {
        let pipelens::lesson::Document::Lesson(lesson) =
            pipelens::lesson::load_file(&path).unwrap_or_else(|e| panic!("{e}"))
        else {
            continue;
        };
        for (k, step) in lesson.steps.iter().enumerate() {
            let kind = lesson.buffer_at(k);
            if !matches!(
                kind,
                BufferKind::Ambient | BufferKind::Diffuse | BufferKind::Specular
            ) {
                continue;
            }
            let seconds = step.animate.iter().map(|a| a.seconds).fold(0.0, f32::max);
            for i in 0..5 {
                let t = seconds * i as f32 / 4.0;
                let mut spec = lesson.spec_playing(k, t);
                spec.settings.width = spec.settings.width.min(320);
                spec.settings.height = spec.settings.height.min(200);
                let c = pipeline::render(&spec.scene, &spec.settings)
                    .unwrap_or_else(|e| panic!("{} step {k}: {e}", lesson.id));
                let gain = c.term_gain(kind);
                let image = c.image_gained(kind, gain);
                let brightest = image
                    .pixels()
                    .zip(&c.pixels.primitive)
                    .filter(|(_, p)| **p != pipeline::raster::NONE)
                    .flat_map(|(px, _)| px.0[..3].to_vec())
                    .max()
                    .unwrap_or(0);
                checked += 1;
                assert!(
                    brightest >= 170,
                    "{} step {} at {t} s: {kind:?} shown ×{gain}, brightest {brightest} of 255",
                    lesson.id,
                    k + 1
                );
            }
        }
    }
    assert!(checked >= 30, "only {checked} moments were checked");
}
