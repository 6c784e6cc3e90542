//! The coordinate spaces a vertex passes through (model, world, eye, clip, NDC, window): where
//! a vertex is in each, the view volume in each, how a space is named, and the sphere that frames
//! what is shown. The app's geometry views and the exported pictures of geometry steps both draw
//! from these.

use glam::{Vec3, Vec4};
use pipeline::capture::FrameCapture;

use crate::vocabulary::{Lang, Space};

/// The position of vertex row `v` in a space; `None` where it has none (NDC and window
/// coordinates of a vertex with `w ≤ 0`).
pub fn position(v: &pipeline::vertex::VertexRecord, space: Space) -> Option<Vec3> {
    match space {
        Space::Model => Some(v.object_pos.truncate()),
        // A projective model matrix (the shadow matrix) leaves w ≠ 1: show the point it means.
        Space::World => (v.world.w > 0.0).then(|| v.world.truncate() / v.world.w),
        Space::Eye => (v.eye.w > 0.0).then(|| v.eye.truncate() / v.eye.w),
        Space::Clip => Some(v.clip.truncate()),
        Space::Ndc => v.ndc,
        Space::Window => v.window,
    }
}

/// A point on its way from `from` to `to` at `t ∈ [0, 1]`. Clip → NDC divides gradually:
/// `(x, y, z) / (1 + t·(w − 1))`, so the frustum is seen squeezing into the cube.
pub fn between(v: &pipeline::vertex::VertexRecord, from: Space, to: Space, t: f32) -> Option<Vec3> {
    if t >= 1.0 {
        return position(v, to);
    }
    if from == Space::Clip && to == Space::Ndc {
        let d = 1.0 + t * (v.clip.w - 1.0);
        return (v.clip.w > 0.0 && d > 1e-6).then(|| v.clip.truncate() / d);
    }
    Some(position(v, from)?.lerp(position(v, to)?, t))
}

/// What a space is called over its picture.
#[must_use]
pub fn space_name(space: Space, l: Lang) -> &'static str {
    match space {
        Space::Model => l.t("spaces-object-coordinates"),
        Space::World => l.t("spaces-world-coordinates"),
        Space::Eye => l.t("spaces-eye-coordinates-camera-at-the"),
        Space::Clip => l.t("spaces-clip-coordinates-x-y-z"),
        Space::Ndc => l.t("spaces-normalized-device-coordinates-the-canonical"),
        Space::Window => l.t("spaces-window-coordinates-0-w-0"),
    }
}

/// The view volume in a space (world, eye, clip, NDC, window); `None` in model space.
pub fn volume(capture: &FrameCapture, space: Space) -> Option<[Vec3; 8]> {
    let eye = capture.projection.corners_eye(capture.settings.aspect());
    let m = &capture.matrices;
    let through = |mat: glam::Mat4, divide: bool| {
        eye.map(|p| {
            let c: Vec4 = mat * p.extend(1.0);
            if divide {
                c.truncate() / c.w
            } else {
                c.truncate()
            }
        })
    };
    match space {
        Space::Model => None,
        Space::World => Some(through(m.view.matrix.inverse(), false)),
        Space::Eye => Some(eye),
        Space::Clip => Some(through(m.projection.matrix, false)),
        Space::Ndc => Some(through(m.projection.matrix, true)),
        Space::Window => Some(through(m.viewport.matrix * m.projection.matrix, true)),
    }
}

/// World coordinates into a space, for what is drawn besides the vertices (the lights); `None`
/// where it would mean nothing (model space, and past the projection).
pub fn world_into(capture: &FrameCapture, space: Space) -> Option<glam::Mat4> {
    match space {
        Space::World => Some(glam::Mat4::IDENTITY),
        Space::Eye => Some(capture.matrices.view.matrix),
        _ => None,
    }
}

/// The sphere to frame, `(centre, radius)`: around the view volume in NDC and window
/// coordinates (a vertex just in front of the eye has enormous NDC coordinates, and would shrink
/// the cube to a dot), around the subject's vertices elsewhere; centred on their box, just
/// reaching the farthest.
pub fn bounds(capture: &FrameCapture, spaces: [Space; 2], subject: &[bool]) -> Option<(Vec3, f32)> {
    sphere_around(&framed_points(capture, spaces, subject))
}

/// The sphere [`bounds`] frames around `points`: centred on their box, just reaching the
/// farthest; `None` for no points.
#[must_use]
pub fn sphere_around(points: &[Vec3]) -> Option<(Vec3, f32)> {
    let lo = points.iter().copied().reduce(Vec3::min)?;
    let hi = points.iter().copied().reduce(Vec3::max)?;
    let centre = (lo + hi) / 2.0;
    let radius = points
        .iter()
        .map(|p| (*p - centre).length())
        .fold(0.0f32, f32::max);
    Some((centre, radius))
}

/// The points [`bounds`] frames: the view volume's corners in NDC and window coordinates, the
/// subject's finite vertex positions elsewhere, in each of `spaces`.
#[must_use]
pub fn framed_points(capture: &FrameCapture, spaces: [Space; 2], subject: &[bool]) -> Vec<Vec3> {
    let mut points = Vec::new();
    let mut add = |p: Vec3| {
        if p.is_finite() {
            points.push(p);
        }
    };
    for space in spaces {
        match (space, volume(capture, space)) {
            (Space::Ndc | Space::Window, Some(corners)) => corners.into_iter().for_each(&mut add),
            _ => capture
                .vertices
                .iter()
                .filter(|v| subject.get(v.object as usize).copied().unwrap_or(false))
                .filter_map(|v| position(v, space))
                .for_each(&mut add),
        }
    }
    points
}

/// The orbit a geometry picture is first seen from: degrees about y, and above the horizon.
pub const YAW: f32 = 35.0;
/// See [`YAW`].
pub const PITCH: f32 = 22.0;

/// The camera that frames the sphere (`centre`, `radius`) from direction (`yaw`, `pitch`) in
/// degrees, through a 40° lens on a picture of `aspect` (width/height): projection times view.
/// Far enough back that the sphere just fits the narrower side: it subtends a half-angle
/// asin(r/d), the half field of view is atan(tan 20°·min(aspect, 1)).
#[must_use]
pub fn framing(centre: Vec3, radius: f32, yaw: f32, pitch: f32, aspect: f32) -> Option<glam::Mat4> {
    let (yaw, pitch) = (yaw.to_radians(), pitch.to_radians());
    let dir = Vec3::new(
        pitch.cos() * yaw.sin(),
        pitch.sin(),
        pitch.cos() * yaw.cos(),
    );
    let half = (20f32.to_radians().tan() * aspect.min(1.0)).atan();
    let distance = radius * 1.06 / half.sin();
    let up = if pitch.cos().abs() < 1e-3 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let view = pipeline::transform::look_at(centre + dir * distance, centre, up).ok()?;
    let proj = pipeline::transform::perspective(
        40.0,
        aspect,
        distance * 0.01,
        distance * 10.0 + radius * 4.0,
    );
    Some(proj.matrix * view)
}

/// The fates a triangle can meet, in the legend's order: colour and the message of its name.
pub const FATES: [([u8; 3], &str); 6] = [
    (crate::palette::DRAWN, "spaces-fate-drawn"),
    (crate::palette::CLIPPED, "spaces-fate-clipped"),
    (crate::palette::OUTSIDE, "spaces-fate-outside"),
    (crate::palette::CULLED, "spaces-fate-culled"),
    (crate::palette::DEGENERATE, "spaces-fate-degenerate"),
    (crate::palette::NOT_FINITE, "spaces-fate-not-finite"),
];

/// How each fate's edges are drawn beside their colour, so that no fate is told by hue alone
/// (WCAG 1.4.1): dash and gap lengths in points, alternating, in [`FATES`]' order; empty for a
/// solid line. Drawn: solid; clipped: dashes; outside: dots; culled: dash and dot;
/// degenerate: a long dash and two dots; not finite: short dashes.
pub const FATE_DASHES: [&[f32]; FATES.len()] = [
    &[],
    &[7.0, 3.0],
    &[1.5, 3.0],
    &[8.0, 3.0, 1.5, 3.0],
    &[10.0, 2.5, 1.5, 2.5, 1.5, 2.5],
    &[3.0, 2.0],
];

/// The message of what each fate's line is called (for a legend in words).
pub const FATE_LINES: [&str; FATES.len()] = [
    "spaces-solid",
    "spaces-dashed",
    "spaces-dotted",
    "spaces-dash-dot",
    "spaces-dash-dot-dot",
    "spaces-short-dashes",
];

/// How many of every `stride`-th of `capture`'s triangles met each fate, in [`FATES`]' order.
#[must_use]
pub fn fates_met(capture: &pipeline::capture::FrameCapture, stride: usize) -> [usize; FATES.len()] {
    let mut met = [0; FATES.len()];
    for prim in capture.primitives.iter().step_by(stride.max(1)) {
        met[fate_index(&prim.fate)] += 1;
    }
    met
}

/// The fates that `capture`'s triangles met, each with its line in words, in [`FATES`]'
/// order: "clipped: dashed · outside: dotted" — the key a picture drawn without a legend of
/// its own leaves to the page.
#[must_use]
pub fn fates_in_words(capture: &pipeline::capture::FrameCapture, lang: Lang) -> String {
    let met = fates_met(capture, 1);
    (0..FATES.len())
        .filter(|&k| met[k] > 0)
        .map(|k| {
            lang.t_with(
                "spaces-fate-and-line",
                &[
                    ("fate", &lang.t(FATES[k].1)),
                    ("line", &lang.t(FATE_LINES[k])),
                ],
            )
        })
        .collect::<Vec<_>>()
        .join(" · ")
}

/// The pieces of the segment `a`–`b` that `pattern` draws (dash and gap lengths as in
/// [`FATE_DASHES`], × `scale`, repeated from `a`; the last dash cut at `b`): the whole segment
/// for an empty pattern, a point-like one, or one so long that its dashes would be past
/// counting. The app and the exported pictures dash by this one rule.
#[must_use]
pub fn dashed(a: [f32; 2], b: [f32; 2], pattern: &[f32], scale: f32) -> Vec<[[f32; 2]; 2]> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let length = dx.hypot(dy);
    let period = pattern.iter().sum::<f32>() * scale;
    if pattern.is_empty() || !(period > 0.0) || !(length > 0.0) || length / period > 1e4 {
        return vec![[a, b]];
    }
    let at = |t: f32| [a[0] + dx * t / length, a[1] + dy * t / length];
    let mut pieces = Vec::new();
    let mut t = 0.0;
    for (k, len) in pattern.iter().enumerate().cycle() {
        let end = (t + len * scale).min(length);
        if k % 2 == 0 {
            pieces.push([at(t), at(end)]);
        }
        t = end;
        if t >= length {
            break;
        }
    }
    pieces
}

/// Where a fate stands in [`FATES`].
#[must_use]
pub fn fate_index(f: &pipeline::capture::Fate) -> usize {
    use pipeline::capture::Fate;
    match f {
        Fate::Drawn => 0,
        Fate::Clipped => 1,
        Fate::Outside { .. } => 2,
        Fate::Culled { .. } => 3,
        Fate::Degenerate => 4,
        Fate::NotFinite => 5,
    }
}

/// The name a step's `focus` gives the viewing camera (`focus = ["cube", "camera"]`): the
/// observer then frames the objects named with the camera's eye and its frame u, v, n, and
/// leaves the lights out.
pub const CAMERA: &str = "camera";

/// Whether `focus` names the object `name`: by its own name, or a figure's part by the
/// figure's name (`arm` names `arm: base`).
#[must_use]
pub fn named_in(focus: &[String], name: &str) -> bool {
    focus.iter().any(|f| {
        name == f
            || name
                .strip_prefix(f.as_str())
                .is_some_and(|r| r.starts_with(": "))
    })
}

/// Which vertex rows are the subject: the objects named by `focus` (a figure by its parts), every
/// object without it; in model space, one object (its own origin): the focused one, the selected
/// vertex's, or the first.
#[must_use]
pub fn subject(
    capture: &FrameCapture,
    focus: &[String],
    vertex: Option<u32>,
    space: Space,
) -> Vec<bool> {
    let named = |name: &str| named_in(focus, name);
    let mut objects: Vec<bool> = capture
        .objects
        .iter()
        .map(|o| focus.is_empty() || named(&o.name))
        .collect();
    if objects.iter().all(|o| !o) {
        objects.iter_mut().for_each(|o| *o = true);
    }
    if space == Space::Model {
        let by_vertex = vertex
            .and_then(|i| capture.vertices.get(i as usize))
            .map(|v| v.object as usize);
        let one = by_vertex
            .or_else(|| objects.iter().position(|o| *o))
            .unwrap_or(0);
        objects = (0..capture.objects.len()).map(|k| k == one).collect();
    }
    objects
}

#[cfg(test)]
mod tests {
    use super::dashed;

    /// 7 on, 3 off from the start: a 20-long segment is lit on [0, 7] and [10, 17]; a 12-long
    /// one's second dash is cut at its end; no pattern, or no length, is the whole segment.
    #[test]
    fn a_dashed_segment_is_lit_where_its_pattern_says() {
        let along = |x: f32| [x, 0.0];
        assert_eq!(
            dashed(along(0.0), along(20.0), &[7.0, 3.0], 1.0),
            vec![[along(0.0), along(7.0)], [along(10.0), along(17.0)]]
        );
        assert_eq!(
            dashed(along(0.0), along(12.0), &[7.0, 3.0], 1.0),
            vec![[along(0.0), along(7.0)], [along(10.0), along(12.0)]]
        );
        // Twice the scale: one dash of 14 fills a 12-long segment.
        assert_eq!(
            dashed(along(0.0), along(12.0), &[7.0, 3.0], 2.0),
            vec![[along(0.0), along(12.0)]]
        );
        assert_eq!(
            dashed(along(0.0), along(5.0), &[], 1.0),
            vec![[along(0.0), along(5.0)]]
        );
        assert_eq!(dashed(along(3.0), along(3.0), &[1.0, 1.0], 1.0).len(), 1);
        // Down a diagonal: 3-4-5, so the first dash of 5 ends at (3, 4).
        assert_eq!(
            dashed([0.0, 0.0], [6.0, 8.0], &[5.0, 5.0], 1.0),
            vec![[[0.0, 0.0], [3.0, 4.0]]]
        );
    }
}
