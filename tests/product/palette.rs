//! The colours that carry a meaning stay apart to colour-blind eyes (issue "Every student can
//! use it"): in every set of meanings a picture shows together, every pair and each meaning
//! against its ground keep `vision::APART` in CIELAB, for normal vision and as Machado et al.'s
//! protanope, deuteranope and tritanope see them.

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
