//! A step recorded from what is on screen ("Add step", issue 36): the stage, the buffer, the
//! layout and comparison, the overlays, the inspected pixel and selected vertex, the framed
//! objects, the observer's direction, the profile line, the depth ramp, and — as `set` entries — every parameter that
//! differs from the scene the lesson's current step leaves (`set` entries are kept by the steps
//! after theirs). Its title names the stage in both languages until the teacher words it; it has
//! no narration yet. `lesson::record::append_step` writes it into the lesson file.

use crate::app::session::Session;
use crate::lesson::Step;
use crate::lesson::script::{Layout, Overlay};
use crate::vocabulary::{Lang, Text};
use pipeline::overlay::OverlayKind;

/// The step on screen, to come after the lesson's current one; `None` without a lesson.
#[must_use]
pub fn recorded_step(session: &Session) -> Option<Step> {
    let player = session.lesson.as_ref()?;
    let sel = &session.selection;
    // The scene the step shows by itself (its animations at the time they are at): what the
    // teacher changed is what differs from it.
    let before = player.lesson.spec_playing(player.step, player.time);
    let mut overlays: Vec<Overlay> = sel
        .overlays
        .iter()
        .map(|o| match o {
            OverlayKind::TriangleEdges => Overlay::Edges,
            OverlayKind::BoundingBoxes => Overlay::BoundingBoxes,
        })
        .collect();
    if sel.show_samples {
        overlays.push(Overlay::Samples);
    }
    if sel.show_normals {
        overlays.push(Overlay::Normals);
    }
    let layout = match (sel.comparison, sel.show_observer) {
        (Some(_), _) => Layout::Compare,
        (None, true) => Layout::Observer,
        (None, false) => Layout::Single,
    };
    Some(Step {
        title: Text::new(sel.stage.name(Lang::EN), sel.stage.name(Lang::ZH)),
        narration: Text::default(),
        stage: Some(sel.stage),
        layout,
        compare: sel.comparison,
        buffer: Some(sel.buffer),
        // None named is none shown: an empty list would say nothing more.
        overlays: (!overlays.is_empty()).then_some(overlays),
        set: crate::lesson::param::differences(&before, &session.spec),
        animate: Vec::new(),
        pixel: sel.pixel,
        vertex: sel.vertex,
        // The profile plot is drawn under compared images only.
        profile: sel.profile.filter(|_| sel.comparison.is_some()),
        focus: sel.focus.clone(),
        orbit: sel.show_observer.then(|| direction(session)).flatten(),
        depth_range: sel.depth_view.range,
        watch: sel.watch.clone(),
        // Authored, not on screen: "Update step" keeps the file's own.
        shader_lines: None,
        panels: Vec::new(),
        shader: None,
        question: None,
        expect: None,
        exercise: None,
        answer: None,
    })
}

/// The direction the teacher turned the observer to, `[yaw, pitch]` to a tenth of a degree;
/// `None` where it is the one every observer starts from
/// ([`crate::observer::DEFAULT_DIRECTION`]), which a step need not name.
fn direction(session: &Session) -> Option<[f32; 2]> {
    let tenth = |x: f32| (x * 10.0).round() / 10.0;
    // A drag turns the yaw without bound: the same direction, written in (−180°, 180°].
    let yaw = tenth(session.orbit.yaw).rem_euclid(360.0);
    let yaw = if yaw > 180.0 { yaw - 360.0 } else { yaw };
    let now = [yaw, tenth(session.orbit.pitch)];
    (now != crate::observer::DEFAULT_DIRECTION).then_some(now)
}
