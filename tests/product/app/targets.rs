//! Every control is big enough to hit (issue 60): at least 24 × 24 points with a mouse (WCAG
//! 2.2's target size, 2.5.8) and 44 × 44 under a finger (a fingertip), on a desktop's windows,
//! a phone's and a tablet's, with every panel open; and a phone's bar fits its screen.

use accesskit_consumer::{FilterResult, NodeRef};
use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable, by};
use pipelens::app::PipelensApp;

fn include(_: &NodeRef) -> FilterResult {
    FilterResult::Include
}

/// Each control one can act on (click, focus) narrower or lower than `least`: its role, name
/// and size. Left out: labels (their text is selectable, not a control), egui's scroll bars
/// (which show only while scrolling), and the pictures and plots, areas one points into
/// whose size the layout's tests hold (`phone.rs`, `framing.rs`), not a control's.
fn too_small(h: &Harness<'_, PipelensApp>, least: f32) -> Vec<String> {
    h.query_all(by().predicate(|n: &NodeRef| {
        (n.is_clickable(&include) || n.is_focusable(&include))
            && !n.is_hidden()
            && !matches!(
                n.role(),
                accesskit::Role::Label | accesskit::Role::ScrollBar | accesskit::Role::Image
            )
            // A plot's area (egui_plot names it no role).
            && !(n.role() == accesskit::Role::Unknown && n.label().is_none())
    }))
    .filter_map(|n| {
        let r = n.rect();
        let a = n.accesskit_node();
        (r.width() < least || r.height() < least).then(|| {
            format!(
                "{:?} {:?} {:.0}×{:.0}",
                a.role(),
                a.label().unwrap_or_default(),
                r.width(),
                r.height()
            )
        })
    })
    .collect()
}

/// Lesson 10 (its parameters, its lab's code) and the tour, every panel open and the keys'
/// help shown, on the first and the last step: with a mouse at 1366×768 and 1920×1080 every
/// control is 24 points or more each way; under a finger on phones (360×640, 390×844) and a
/// tablet (768×1024), 44 or more.
#[test]
fn every_control_is_big_enough_to_hit() {
    let sizes = [
        ([1366.0, 768.0], false),
        ([1920.0, 1080.0], false),
        ([360.0, 640.0], true),
        ([390.0, 844.0], true),
        ([768.0, 1024.0], true),
    ];
    let mut small = Vec::new();
    for (size, touch) in sizes {
        let least = pipelens::app::target_size(touch);
        assert_eq!(least, if touch { 44.0 } else { 24.0 });
        for name in ["10-blinn-phong", "00-tour"] {
            let path = crate::support::repo().join(format!("lessons/{name}.toml"));
            let mut h = super::sized_lesson_harness(&path, size);
            h.run_steps(2);
            if touch {
                super::touch(&mut h, Pos2::new(2.0, 2.0));
            }
            let last = super::lesson_of(&h).steps.len() - 1;
            for step in [0, last] {
                h.state_mut()
                    .session
                    .apply(pipelens::app::session::Command::Lesson(
                        pipelens::app::command::LessonCommand::GoToStep(step),
                    ));
                let app = h.state_mut();
                app.panels.parameters = true;
                app.panels.inspector = true;
                app.panels.shader = true;
                app.panels.keys = true;
                h.run_steps(4);
                small.extend(
                    too_small(&h, least)
                        .into_iter()
                        .map(|s| format!("{size:?} {name} step {}: {s}", step + 1)),
                );
                // What a page reports of the frame for the browser test, measured by the app
                // from egui's widgets (a page has no AccessKit tree), agrees.
                let own = h.state().least;
                if own.target < least || !own.target.is_finite() {
                    small.push(format!(
                        "{size:?} {name} step {}: the app's own measure, {:.1} at {:?}",
                        step + 1,
                        own.target,
                        own.target_rect
                    ));
                }
            }
        }
    }
    assert!(
        small.is_empty(),
        "{} too small:\n{}",
        small.len(),
        small.join("\n")
    );
}

/// On a phone under a finger the bar is one row inside the screen: Menu, the step's arrows and
/// number, the stage (at 360 points wide the stage's drop-down was cut off).
#[test]
fn a_phone_s_bar_fits_its_screen() {
    let path = crate::support::repo().join("lessons/00-tour.toml");
    for size in [[360.0, 640.0], [390.0, 844.0]] {
        let mut h = super::sized_lesson_harness(&path, size);
        h.run_steps(2);
        super::touch(&mut h, Pos2::new(2.0, 2.0));
        h.run_steps(2);
        let bar: Vec<(String, egui::Rect)> = h
            .query_all(by().predicate(|n: &NodeRef| {
                n.is_clickable(&include) && !n.is_hidden() && n.role() != accesskit::Role::Label
            }))
            .filter(|n| n.rect().max.y <= 60.0)
            .map(|n| (n.accesskit_node().label().unwrap_or_default(), n.rect()))
            .collect();
        let names: Vec<&str> = bar.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            ["Menu", "Previous step", "Step 1 / 10", "Next step", "Stage"],
            "{size:?}"
        );
        for (name, rect) in &bar {
            assert!(
                rect.max.x <= size[0] && rect.height() >= 44.0,
                "{size:?}: {name} at {rect:?}"
            );
        }
    }
}
