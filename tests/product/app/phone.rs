//! A phone's layout (issue "Every student's device"): at 390×844 (portrait) and 844×390
//! (landscape) the bar is one row, the narration a sheet under the picture, the picture at least
//! half of the screen on every step of a lesson, and a swipe across the sheet moves the steps.

use egui::{Event, Modifiers, PointerButton, Pos2, Rect};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use pipelens::app::PipelensApp;
use pipelens::app::command::LessonCommand;
use pipelens::app::session::Command;

/// A finger pressed at `from`, moved to `to` and lifted.
fn swipe(h: &mut Harness<'_, PipelensApp>, from: Pos2, to: Pos2) {
    let press = |pos, pressed| Event::PointerButton {
        pos,
        button: PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    h.input_mut().events.push(Event::PointerMoved(from));
    h.input_mut().events.push(press(from, true));
    h.run_steps(1);
    for k in 1..=5 {
        let t = k as f32 / 5.0;
        h.input_mut()
            .events
            .push(Event::PointerMoved(from + (to - from) * t));
        h.run_steps(1);
    }
    h.input_mut().events.push(press(to, false));
    h.run_steps(3);
}

/// On a phone (and an upright tablet, touched: the phone's layout), every step of the tour and
/// of lesson 07 gives the picture at least half of the screen upright (the narration under it;
/// 40 % on a 360×640 phone, whose bar and sheet take half) and a third on its side (the
/// narration beside it),
/// or as much as its shape allows: a wide image on an upright phone, whose subject spans it, is
/// as wide as the screen (its height is then the width over its aspect, a quarter of the
/// screen for the tour's 640×400 buffer); on its side, a picture as tall as the view.
#[test]
fn on_a_phone_the_picture_takes_half_the_screen_or_more() {
    for (size, least) in [
        ([390.0, 844.0], 0.5),
        // The bar and the sheet leave a 360×640 phone's view half the screen: its pictures
        // fill most of it.
        ([360.0, 640.0], 0.4),
        ([844.0, 390.0], 0.33),
        ([768.0, 1024.0], 0.5),
    ] {
        let screen = egui::Rect::from_min_size(Pos2::ZERO, egui::vec2(size[0], size[1]));
        let mut short = Vec::new();
        for name in ["00-tour", "07-rasterization"] {
            let path = crate::support::repo().join(format!("lessons/{name}.toml"));
            let mut h = super::sized_lesson_harness(&path, size);
            // A phone is touched: its controls a finger's size.
            super::touch(&mut h, Pos2::new(2.0, 2.0));
            let n = super::lesson_of(&h).steps.len();
            for k in 0..n {
                h.state_mut()
                    .session
                    .apply(Command::Lesson(LessonCommand::GoToStep(k)));
                h.run_steps(6);
                assert!(h.state().panels.narration, "the narration is shown");
                let share = h.state().picture_share(screen);
                let spans = h
                    .state()
                    .picture
                    .iter()
                    .fold(egui::Rect::NOTHING, |a, r| a.union(*r));
                // As wide as the screen upright, as tall as the view on its side.
                let as_shape_allows = if size[0] < size[1] {
                    spans.width() >= 0.9 * size[0]
                } else {
                    spans.height() >= 0.75 * size[1]
                };
                if share < least && !(as_shape_allows && share >= 0.2) {
                    short.push(format!(
                        "{name} step {}: {:.0} % ({:.0}×{:.0})",
                        k + 1,
                        share * 100.0,
                        spans.width(),
                        spans.height()
                    ));
                }
            }
        }
        assert!(short.is_empty(), "at {}×{}: {short:?}", size[0], size[1]);
    }
}

/// A swipe leftwards across the narration sheet goes to the next step, rightwards back; a
/// short or mostly vertical drag (scrolling the sheet) does not; on a tablet too.
#[test]
fn a_swipe_across_the_narration_moves_the_steps() {
    let path = crate::support::repo().join("lessons/00-tour.toml");
    let mut h = super::sized_lesson_harness(&path, [390.0, 844.0]);
    h.run_steps(4);
    assert_eq!(super::step_of(&h), 0);
    swipe(&mut h, Pos2::new(320.0, 760.0), Pos2::new(80.0, 770.0));
    assert_eq!(super::step_of(&h), 1, "leftwards: the next step");
    swipe(&mut h, Pos2::new(320.0, 760.0), Pos2::new(80.0, 770.0));
    assert_eq!(super::step_of(&h), 2);
    swipe(&mut h, Pos2::new(80.0, 760.0), Pos2::new(320.0, 760.0));
    assert_eq!(super::step_of(&h), 1, "rightwards: the step before");
    swipe(&mut h, Pos2::new(200.0, 800.0), Pos2::new(180.0, 700.0));
    assert_eq!(super::step_of(&h), 1, "a scroll is not a swipe");
    // Over the picture a drag is the view's (pan, orbit), not a step.
    swipe(&mut h, Pos2::new(320.0, 300.0), Pos2::new(80.0, 300.0));
    assert_eq!(super::step_of(&h), 1, "the picture keeps its drags");
    // An upright tablet, touched, has the phone's sheet and its swipe.
    let mut h = super::sized_lesson_harness(&path, [768.0, 1024.0]);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    h.run_steps(4);
    swipe(&mut h, Pos2::new(600.0, 940.0), Pos2::new(150.0, 950.0));
    assert_eq!(super::step_of(&h), 1, "a tablet's swipe: the next step");
}

/// The tour's first step is written for a keyboard and a mouse ("Press → …", "Click any pixel
/// to see, in the inspector on the right, …"). With a mouse the phone-sized window keeps those
/// words; once a finger touches the screen it says the gesture and the buttons a phone has
/// instead, the sentences as written by hand from the lesson's.
#[test]
fn on_a_touch_screen_the_narration_speaks_of_taps_and_swipes() {
    let path = crate::support::repo().join("lessons/00-tour.toml");
    let mut h = super::sized_lesson_harness(&path, [390.0, 844.0]);
    h.run_steps(4);
    assert!(
        h.query_by_label_contains("Click any pixel to see")
            .is_some()
    );
    assert!(!h.state().session.touch);
    super::touch(&mut h, Pos2::new(200.0, 780.0));
    h.run_steps(3);
    assert!(h.state().session.touch, "a touch makes it a touch screen");
    assert!(
        h.query_by_label_contains("Swipe the narration left (or tap ▶ at the top) to follow")
            .is_some(),
        "the step's arrow key becomes a swipe"
    );
    assert!(
        h.query_by_label_contains(
            "Tap any pixel to see, in the inspector (Menu → Show → Inspector), every fragment"
        )
        .is_some(),
        "a click becomes a tap, the inspector is found through the menu"
    );
    assert!(h.query_by_label_contains("Click any pixel").is_none());
    assert!(h.query_by_label_contains("Press →").is_none());
}

/// A dropped file's message on a 360-point phone is wrapped to the screen: its heading and the
/// reader's error (as long as a real one) are whole, no line running past the edge.
#[test]
fn a_dropped_file_s_message_fits_a_phone() {
    let path = crate::support::repo().join("lessons/00-tour.toml");
    let mut h = super::sized_lesson_harness(&path, [360.0, 640.0]);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    h.state_mut().session.dropped_error = Some(
        "truncated.obj could not be opened; what was open keeps running:\n\
         truncated.obj:1:3: a mesh becomes a new lesson in the lesson editor on the desktop; \
         the page opens lessons, scenes and shaders"
            .to_owned(),
    );
    h.run_steps(3);
    let message = h.get_by_label_contains("truncated.obj could not be opened");
    let rect = message.rect();
    assert!(
        rect.max.x <= 360.0 && rect.height() > 60.0,
        "the message wraps inside the screen: {rect:?}"
    );
}

/// On a phone no word or number is under 12 points (WCAG's reading size, and the floor
/// for a phone held at arm's length): every text the frame paints, on every step of the tour
/// and of the perspective lesson (the matrix card's digits were the view's width ÷ 36, 10
/// points on a 390-point phone), upright and on its side, touched.
#[test]
fn on_a_phone_no_text_is_under_12_points() {
    let mut small = Vec::new();
    for size in [[390.0, 844.0], [844.0, 390.0]] {
        for name in ["00-tour", "05-perspective"] {
            let path = crate::support::repo().join(format!("lessons/{name}.toml"));
            let mut h = super::sized_lesson_harness(&path, size);
            super::touch(&mut h, Pos2::new(2.0, 2.0));
            for k in 0..super::lesson_of(&h).steps.len() {
                super::go_to_step(&mut h, k);
                // The app's own measure, which a page reports for the browser test.
                let own = h.state().least.text;
                if own < 12.0 {
                    small.push(format!(
                        "{name} step {} at {size:?}: the app measures {own:.1} pt",
                        k + 1
                    ));
                }
                for (_, least, text) in super::framing::texts(&h) {
                    if least < 12.0 {
                        small.push(format!(
                            "{name} step {} at {size:?}: {least:.1} pt {:?}",
                            k + 1,
                            text.chars().take(30).collect::<String>()
                        ));
                    }
                }
            }
        }
    }
    small.dedup();
    assert!(
        small.is_empty(),
        "{} texts under 12 points:\n{}",
        small.len(),
        small.join("\n")
    );
}

/// Lesson 05's clip step (its third) in a window of `size`, touched: a phone's.
fn clip_step_touched(size: [f32; 2]) -> Harness<'static, PipelensApp> {
    let path = crate::support::repo().join("lessons/05-perspective.toml");
    let mut h = super::sized_lesson_harness(&path, size);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    super::go_to_step(&mut h, 2);
    h.run_steps(6);
    assert_eq!(
        h.state().session.selection.stage,
        pipelens::vocabulary::Stage::Clip,
        "lesson 05's third step is on the clip stage"
    );
    h
}

/// On a phone the geometry view's own buttons (Front view, Reset view) are in the View menu,
/// not a row of finger-sized buttons over the picture: on its side (844×390), lesson 05's
/// clip step left the subject a corner under the matrix card, the header's two rows and the
/// legend. Over the picture only the space's name stays; the View menu has both buttons.
#[test]
fn on_a_phone_the_geometry_view_s_buttons_are_in_the_view_menu() {
    for size in [[844.0, 390.0], [390.0, 844.0]] {
        let mut h = clip_step_touched(size);
        assert!(
            h.query_by_label("Front view").is_none() && h.query_by_label("Reset view").is_none(),
            "{size:?}: no view buttons over the picture"
        );
        h.get_by_label("View ▾").click();
        h.run_steps(3);
        assert!(
            h.query_by_label("Reset view").is_some(),
            "{size:?}: the View menu has Reset view"
        );
        h.get_by_label("Front view").click();
        h.run_steps(4);
        // The view's header is one card: the space's name, a row or two of words.
        let header = h
            .state()
            .overlays
            .first()
            .copied()
            .unwrap_or(egui::Rect::NOTHING);
        assert!(
            header.is_positive() && header.height() < 60.0,
            "{size:?}: the header over the picture is the space's name alone: {header:?}"
        );
    }
}

/// On a small screen the geometry view's legend is a chip at the view's bottom-right that a
/// tap opens above itself and a second tap closes: on a landscape phone its five rows took a
/// fifth of lesson 05's clip view, for a key the student reads once.
#[test]
fn on_a_small_screen_the_legend_is_a_chip_that_a_tap_opens() {
    for size in [[844.0, 390.0], [390.0, 844.0]] {
        let mut h = clip_step_touched(size);
        let chip = h.get_by_label("Legend").rect();
        let picture = h
            .state()
            .picture
            .iter()
            .copied()
            .find(|p| p.contains_rect(chip))
            .expect("the chip is on a picture");
        assert!(
            chip.width() >= 44.0 && chip.height() >= 44.0,
            "{size:?}: the chip is a finger's target: {chip:?}"
        );
        assert!(
            picture.right() - chip.right() < 20.0 && picture.bottom() - chip.bottom() < 20.0,
            "{size:?}: the chip is at the view's bottom-right corner: {chip:?} in {picture:?}"
        );
        let legend = |h: &Harness<'_, PipelensApp>| {
            h.state().overlays.get(2).copied().unwrap_or(Rect::NOTHING)
        };
        assert!(
            legend(&h).area() < 1.2 * chip.area(),
            "{size:?}: folded, the legend is the chip alone: {:?}",
            legend(&h)
        );
        super::tap(&mut h, chip.center());
        h.run_steps(4);
        let open = legend(&h);
        // Lesson 05's clip step shows drawn, clipped and outside triangles, the near and the
        // far plane: five keys, one a row at least in a column, a few a row in a strip.
        assert!(
            open.contains_rect(h.get_by_label("Legend").rect()) && open.area() > 3.0 * chip.area(),
            "{size:?}: a tap opens the legend over its chip: {open:?}"
        );
        assert!(
            (h.get_by_label("Legend").rect().max - chip.max).length() < 1.0,
            "{size:?}: the chip stays where it was as the legend opens above it"
        );
        super::tap(&mut h, chip.center());
        h.run_steps(4);
        assert!(
            legend(&h).area() < 1.2 * chip.area(),
            "{size:?}: a second tap folds it again: {:?}",
            legend(&h)
        );
    }
    // A desktop's view has the room: its legend is open, with no chip.
    let path = crate::support::repo().join("lessons/05-perspective.toml");
    let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
    super::go_to_step(&mut h, 2);
    h.run_steps(6);
    assert!(h.query_by_label("Legend").is_none(), "no chip on a desktop");
    let legend = h.state().overlays.get(2).copied().unwrap_or(Rect::NOTHING);
    assert!(
        legend.height() > 60.0,
        "a desktop's legend shows its keys: {legend:?}"
    );
}

/// A lab's two companion pictures — pipelens' own and the difference — side by side stand at
/// one size and one top (one over the other, centred on one line): the difference's key ("colour,
/// coverage, depth, another triangle") wraps to three lines on a phone, and the difference was
/// drawn lower than pipelens' own beside it.
#[test]
fn a_lab_s_two_pictures_side_by_side_match_in_size_and_top() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut beside_seen = 0;
    for size in [
        [360.0, 640.0],
        [390.0, 844.0],
        [844.0, 390.0],
        [768.0, 1024.0],
        [1366.0, 768.0],
    ] {
        let mut h = super::sized_lesson_harness(&path, size);
        super::go_to_step_titled(&mut h, super::SPECULAR_LAB);
        h.run_steps(8);
        let pictures = &h.state().picture;
        let [.., own, difference] = pictures.as_slice() else {
            panic!("{size:?}: the lab's two pictures: {pictures:?}");
        };
        let (own, difference) = (*own, *difference);
        assert!(own.is_positive(), "{size:?}: {own:?}");
        if own.max.x <= difference.min.x + 0.5 {
            beside_seen += 1;
            assert!(
                (own.size() - difference.size()).length() < 0.5
                    && (own.top() - difference.top()).abs() < 0.5,
                "{size:?}: side by side at one size and one top: {own:?} and {difference:?}"
            );
        } else {
            assert!(
                own.max.y <= difference.min.y + 0.5
                    && (own.center().x - difference.center().x).abs() < 0.5,
                "{size:?}: one over the other, centred on one line: {own:?} and {difference:?}"
            );
        }
    }
    assert!(
        beside_seen >= 1,
        "the pair stands side by side on an upright phone"
    );
}

/// On a 360×640 phone the lab's view is about as high as wide: beside its two companions the
/// student's frame was a column half the screen wide, the sphere cropped at its sides. It stands
/// over the two, as wide as the screen but for the view's margins (322 points, where beside the
/// two its column was 196), cropped less; the companions keep their place under it.
#[test]
fn on_a_small_phone_the_lab_s_frame_stands_over_its_companions() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = super::sized_lesson_harness(&path, [360.0, 640.0]);
    super::touch(&mut h, Pos2::new(2.0, 2.0));
    super::go_to_step_titled(&mut h, super::SPECULAR_LAB);
    h.run_steps(8);
    let pictures = &h.state().picture;
    let [frame, .., own, difference] = pictures.as_slice() else {
        panic!("the lab's three pictures: {pictures:?}");
    };
    assert!(
        frame.width() >= 0.85 * 360.0,
        "as wide as the screen but for the margins: {frame:?}"
    );
    for companion in [own, difference] {
        assert!(
            frame.bottom() <= companion.top() + 0.5,
            "over its companions: {frame:?}, {companion:?}"
        );
    }
}
