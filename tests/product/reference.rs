//! Reference images of the course's assignments, when `../shared/data` is beside the checkout.

use crate::support::{repo, shared_data};

#[test]
fn games101_assignment_2_without_antialiasing_matches_pixel_for_pixel() {
    let Some(data) = shared_data() else {
        eprintln!("skipped: ../shared/data is not present");
        return;
    };
    let reference =
        image::open(data.join("reference/games101_danieldfy/a2_output_with_no_anti_aliasing.png"))
            .expect("reference decodes")
            .to_rgb8();
    let spec = pipelens::lesson::load_scene_file(&repo().join("assets/scenes/games101_a2.toml"))
        .expect("scene");
    let capture = pipeline::render(&spec.scene, &spec.settings).expect("renders");
    let ours = capture.image(pipeline::capture::BufferKind::Color);
    assert_eq!((ours.width(), ours.height()), reference.dimensions());
    let differing = ours
        .pixels()
        .zip(reference.pixels())
        .filter(|(a, b)| a.0[..3] != b.0[..])
        .count();
    assert_eq!(
        differing, 0,
        "{differing} pixels differ from the assignment's image"
    );
}
