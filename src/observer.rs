//! The observer: the scene seen from outside, by a camera orbiting it, rendered by the same
//! pipeline, with the viewing camera's frustum drawn over it. The app's observer view and the
//! exported `observer.png` both come from here.

use glam::Vec3;
use pipeline::buffers::{BufferKind, Capture};
use pipeline::camera::{Camera, Projection};
use pipeline::capture::FrameCapture;
use pipeline::raster::Samples;
use pipeline::scene::Scene;
use pipeline::settings::RenderSettings;

use crate::lesson::SceneSpec;
use crate::vocabulary::Lang;

/// Where the observer's camera is: an orbit around the scene's centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// Angle around the vertical axis, degrees.
    pub yaw: f32,
    /// Angle above the horizon, degrees.
    pub pitch: f32,
    /// Distance from the centre.
    pub distance: f32,
    /// The point orbited.
    pub centre: Vec3,
}

impl Orbit {
    /// The camera on this orbit, looking at the centre.
    #[must_use]
    pub fn camera(&self) -> Camera {
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        let dir = Vec3::new(
            pitch.cos() * yaw.sin(),
            pitch.sin(),
            pitch.cos() * yaw.cos(),
        );
        Camera {
            eye: self.centre + dir * self.distance,
            at: self.centre,
            up: Vec3::Y,
        }
    }
}

/// The direction an observer looks from unless a step names its own (`orbit = [yaw, pitch]`):
/// 60° round from the viewing camera's usual +z side and 30° above the horizon, where a
/// frustum looking down −z shows its length and its four sides at once.
pub const DEFAULT_DIRECTION: [f32; 2] = [60.0, 30.0];

/// The orbit that frames the whole scene with the viewing camera ([`orbit_for`] without a
/// focus, from [`DEFAULT_DIRECTION`], for the lesson image's shape).
pub fn default_orbit(spec: &SceneSpec) -> Orbit {
    orbit_for(spec, &[], None, None)
}

/// The orbit a step's observer starts from, for a picture of `aspect` (width/height; the
/// lesson image's when `None`), from `direction` = `[yaw, pitch]` in degrees (the step's
/// `orbit`; [`DEFAULT_DIRECTION`] when `None`). It frames a box: with a `focus`,
/// the world-space box of the objects it names ([`crate::spaces::named_in`]) — the viewing
/// camera and its frustum are then context around the subject, unless the focus also names
/// the [`crate::spaces::CAMERA`], whose eye and frame are then framed with them; without one
/// (or when it names nothing drawn), every drawn object's box, the lights with a place and the
/// viewing camera with its frame, so that the objects are as large as the camera beside them allows (lesson
/// 25's cube was 0.7 % of the window, framed from twice the eye's distance). The orbit looks
/// at the middle of what it frames, from the distance where every point lies inside the
/// middle 85 % of the picture ([`fitting_distance`]).
pub fn orbit_for(
    spec: &SceneSpec,
    focus: &[String],
    direction: Option<[f32; 2]>,
    aspect: Option<f32>,
) -> Orbit {
    orbit_for_poses(std::slice::from_ref(spec), focus, direction, aspect)
}

/// [`orbit_for`] framing what each of `poses` shows (a step's scene at moments of its
/// animation), so that nothing framed leaves the picture while it plays; the picture's shape
/// defaults to the first pose's image.
pub fn orbit_for_poses(
    poses: &[SceneSpec],
    focus: &[String],
    direction: Option<[f32; 2]>,
    aspect: Option<f32>,
) -> Orbit {
    let points: Vec<Vec3> = poses.iter().flat_map(|s| framed(s, focus)).collect();
    let aspect = aspect
        .filter(|a| a.is_finite() && *a > 0.0)
        .unwrap_or_else(|| {
            poses.first().map_or(1.0, |s| {
                s.settings.width as f32 / s.settings.height.max(1) as f32
            })
        });
    around(&points, direction, aspect)
}

/// The world-space corners of the boxes of the objects `named` that `spec` draws (finite ones).
fn corners(spec: &SceneSpec, named: &dyn Fn(&str) -> bool) -> Vec<Vec3> {
    let (objects, _) = spec.scene.drawn_objects();
    objects
        .iter()
        .filter(|o| named(&o.name))
        .filter_map(|o| {
            let (lo, hi) = o.mesh.bounds()?;
            let m = o.model_matrix().matrix;
            Some((0..8).map(move |k| {
                let pick = |bit: usize, a: f32, b: f32| if k >> bit & 1 == 1 { b } else { a };
                m.transform_point3(Vec3::new(
                    pick(0, lo.x, hi.x),
                    pick(1, lo.y, hi.y),
                    pick(2, lo.z, hi.z),
                ))
            }))
        })
        .flatten()
        .filter(|p| p.is_finite())
        .collect()
}

/// Where a step's subject reaches while its animation plays: the world-space box corners of
/// the objects `focus` names (every object when it names none drawn) in each of `poses`. A
/// geometry view frames these from the step's first frame, so that a swinging limb neither
/// leaves the picture nor makes it breathe.
#[must_use]
pub fn reached(poses: &[SceneSpec], focus: &[String]) -> Vec<Vec3> {
    let named = |name: &str| crate::spaces::named_in(focus, name);
    poses
        .iter()
        .flat_map(|spec| {
            let points = corners(spec, &named);
            if points.is_empty() {
                corners(spec, &|_| true)
            } else {
                points
            }
        })
        .collect()
}

/// The points [`orbit_for`] frames in `spec`: the named objects' box corners (with the
/// viewing camera's when the focus names it), or everything.
fn framed(spec: &SceneSpec, focus: &[String]) -> Vec<Vec3> {
    let corners = |named: &dyn Fn(&str) -> bool| corners(spec, named);
    // The viewing camera's eye with its frame's axes u, v, n (a quarter of the way to what it
    // looks at, labelled a little beyond).
    let camera = || {
        let c = &spec.scene.camera;
        let reach = (c.at - c.eye).length() * 0.3;
        let n = (c.eye - c.at).normalize_or(Vec3::Z);
        let u = c.up.cross(n).normalize_or(Vec3::X);
        [
            c.eye,
            c.eye + u * reach,
            c.eye + n.cross(u) * reach,
            c.eye + n * reach,
        ]
    };
    let mut points = corners(&|name| crate::spaces::named_in(focus, name));
    if !points.is_empty() && focus.iter().any(|f| f == crate::spaces::CAMERA) {
        points.extend(camera());
    }
    if focus.is_empty() || points.is_empty() {
        // Every object, the lights with a place, and the viewing camera with its frame.
        points = corners(&|_| true);
        points.extend(camera());
        points.extend(spec.scene.lights.iter().filter_map(|l| match l {
            pipeline::light::Light::Point { position, .. }
            | pipeline::light::Light::Spot { position, .. } => Some(*position),
            _ => None,
        }));
        points.retain(|p| p.is_finite());
    }
    points
}

/// The orbit from `direction` (`[yaw, pitch]`, [`DEFAULT_DIRECTION`] when `None`) that looks at
/// the middle of `points` from where they all lie inside the middle 85 % of a picture of
/// `aspect`.
fn around(points: &[Vec3], direction: Option<[f32; 2]>, aspect: f32) -> Orbit {
    let (lo, hi) = points.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let centre = if lo.cmple(hi).all() {
        (lo + hi) / 2.0
    } else {
        Vec3::ZERO
    };
    let [yaw, pitch] = direction.unwrap_or(DEFAULT_DIRECTION);
    let mut orbit = Orbit {
        yaw,
        pitch,
        centre,
        distance: 1.0,
    };
    orbit.distance = fitting_distance(&orbit, points, aspect);
    // Centred on what it shows: the centre moved across the picture toward the middle of the
    // points' extent there, half the way each time (a whole step overshoots: the points
    // nearer the observer move more than the centre), eight times.
    for _ in 0..8 {
        let (r, u, d) = axes(&orbit);
        let seen = |p: &Vec3| {
            let q = *p - orbit.centre;
            let depth = (orbit.distance - q.dot(d)).max(1e-3);
            (q.dot(r) / depth, q.dot(u) / depth)
        };
        let (mut x, mut y) = (
            [f32::INFINITY, f32::NEG_INFINITY],
            [f32::INFINITY, f32::NEG_INFINITY],
        );
        for (a, b) in points.iter().map(seen) {
            x = [x[0].min(a), x[1].max(a)];
            y = [y[0].min(b), y[1].max(b)];
        }
        if !(x[0] <= x[1] && y[0] <= y[1]) {
            break;
        }
        orbit.centre += (r * (x[0] + x[1]) + u * (y[0] + y[1])) / 4.0 * orbit.distance;
        orbit.distance = fitting_distance(&orbit, points, aspect);
    }
    orbit
}

/// The orbit camera's right r̂, up û and direction d̂ (from the centre toward the camera).
fn axes(orbit: &Orbit) -> (Vec3, Vec3, Vec3) {
    let cam = orbit.camera();
    let d = (cam.eye - cam.at).normalize_or(Vec3::Z);
    let r = Vec3::Y.cross(d).normalize_or(Vec3::X);
    (r, d.cross(r), d)
}

/// The distance from `orbit`'s centre at which every one of `points` lies inside the middle
/// 85 % of a picture of `aspect` through the observer's lens ([`observer_fovy`]). Along the
/// orbit's direction d̂ with the picture's right r̂ and up û, a point at offset q from the
/// centre is at depth `D − q·d̂` from a camera at distance D and shows at `(q·r̂, q·û)/(D − q·d̂)`
/// of the focal length; inside means `|q·r̂| ≤ 0.85·tan α_h·(D − q·d̂)` and likewise for û
/// with α_v, so `D = max(q·d̂ + |q·r̂|/(0.85·tan α_h), q·d̂ + |q·û|/(0.85·tan α_v))` over the
/// points — exact for the box's corners, where a bounding sphere would frame a flat floor
/// from far too far.
fn fitting_distance(orbit: &Orbit, points: &[Vec3], aspect: f32) -> f32 {
    let (r, u, d) = axes(orbit);
    let vertical = 0.85 * (observer_fovy(aspect).to_radians() / 2.0).tan();
    let horizontal = vertical * aspect;
    let far_enough = points
        .iter()
        .map(|p| {
            let q = *p - orbit.centre;
            let depth = q.dot(d);
            (depth + q.dot(r).abs() / horizontal).max(depth + q.dot(u).abs() / vertical)
        })
        .fold(0.0f32, f32::max);
    far_enough.max(1e-2)
}

/// The observer's lens: 50° vertically for a picture at least 1.6 times as wide as high; a
/// narrower picture gets a taller angle that keeps the same horizontal one,
/// `fovy = 2·atan(tan(25°)·1.6/aspect)` (at most 120°), so that a tall panel still shows the
/// scene and the viewing camera beside it.
#[must_use]
pub fn observer_fovy(aspect: f32) -> f32 {
    const WIDE: f32 = 1.6;
    let half = 25f32.to_radians();
    if !(aspect.is_finite() && aspect > 0.0) || aspect >= WIDE {
        return 50.0;
    }
    (2.0 * (half.tan() * WIDE / aspect).atan())
        .to_degrees()
        .min(120.0)
}

/// The scene from the observer's camera: the same pipeline, one sample, a perspective lens
/// wide enough for the viewing frustum ([`observer_fovy`]), as many pixels as the viewing
/// camera's image but shaped `aspect` (width/height; the observer fills the panel it is shown
/// in); only its colour is kept (into `spare`'s storage, if given).
pub fn render_observer(
    spec: &SceneSpec,
    camera: Camera,
    aspect: Option<f32>,
    spare: Option<FrameCapture>,
) -> Option<FrameCapture> {
    let distance = (camera.eye - camera.at).length();
    let scene = Scene {
        uniforms: Default::default(),
        objects: spec.scene.objects.clone(),
        camera,
        projection: Projection::Perspective {
            fovy_deg: observer_fovy(
                aspect.unwrap_or(spec.settings.width as f32 / spec.settings.height.max(1) as f32),
            ),
            aspect: None,
            near: (distance * 0.02).max(1e-3),
            far: distance * 20.0,
        },
        figures: spec.scene.figures.clone(),
        shadow: spec.scene.shadow,
        lights: spec.scene.lights.clone(),
    };
    let (mut width, mut height) = (spec.settings.width, spec.settings.height);
    if let Some(a) = aspect.filter(|a| a.is_finite() && *a > 0.05 && *a < 20.0) {
        let pixels = f64::from(width) * f64::from(height);
        width = ((pixels * f64::from(a)).sqrt().round() as u32).clamp(16, 4096);
        height = ((f64::from(width) / f64::from(a)).round() as u32).clamp(16, 4096);
    }
    let settings = RenderSettings {
        width,
        height,
        samples: Samples::X1,
        capture: Capture::COLOR,
        ..spec.settings
    };
    pipeline::render_reusing(&scene, &settings, spare)
        .ok()
        .map(|(c, _)| c)
}

/// Which parts of the viewing camera the observer draws, and in which colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parts {
    /// The camera frame u, v, n at the eye.
    pub axes: bool,
    /// The near plane's rectangle.
    pub near: bool,
    /// The far plane's rectangle.
    pub far: bool,
    /// The frustum's side edges (and the rays from the eye to the near corners).
    pub sides: bool,
    /// The polygons that clipping produced.
    pub clipped: bool,
    /// The lights.
    pub lights: bool,
    /// The near plane's colour.
    pub near_color: [u8; 4],
    /// The far plane's and the sides' colour.
    pub far_color: [u8; 4],
}

impl Default for Parts {
    fn default() -> Self {
        Self {
            axes: true,
            near: true,
            far: true,
            sides: true,
            clipped: true,
            lights: true,
            near_color: opaque(crate::palette::NEAR),
            far_color: opaque(crate::palette::FAR),
        }
    }
}

/// A segment in world coordinates, with its colour and width.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mark {
    /// One end.
    pub a: Vec3,
    /// The other.
    pub b: Vec3,
    /// Straight-alpha sRGB.
    pub color: [u8; 4],
    /// In screen points (pixels of an export).
    pub width: f32,
}

/// A word written at a world point.
#[derive(Clone, Debug, PartialEq)]
pub struct Tag {
    /// Where.
    pub at: Vec3,
    /// What.
    pub text: String,
    /// Straight-alpha sRGB.
    pub color: [u8; 4],
}

/// What the observer draws over its picture, in world coordinates: the viewing camera's frame
/// u, v, n at the eye, its frustum (near and far planes, edges, rays from the eye), the polygons
/// clipping produced (from clip space back to the world: `(P·V)⁻¹` applied to their clip
/// coordinates), and the lights where they are. One description, drawn by egui in the app and by
/// tiny-skia in exported images.
#[must_use]
pub fn viewing_camera(
    main: &FrameCapture,
    parts: &Parts,
    scene: (Vec3, f32),
    lang: Lang,
) -> (Vec<Mark>, Vec<Tag>) {
    let (mut marks, mut tags) = (Vec::new(), Vec::new());
    let c = main.camera;
    let mut mark =
        |a: Vec3, b: Vec3, color: [u8; 4], width: f32| marks.push(Mark { a, b, color, width });
    if let Ok(frame) = pipeline::transform::camera_frame(c.eye, c.at, c.up) {
        let [.., n, _] = main.projection.bounds(main.settings.aspect());
        let scale = (c.at - c.eye).length().max(n) * 0.25;
        if parts.axes {
            for (axis, color, label) in [
                (frame.u, opaque(crate::palette::X), "u"),
                (frame.v, opaque(crate::palette::Y), "v"),
                (frame.n, opaque(crate::palette::Z), "n"),
            ] {
                mark(c.eye, c.eye + axis * scale, color, 2.5);
                tags.push(Tag {
                    at: c.eye + axis * scale * 1.15,
                    text: label.to_owned(),
                    color,
                });
            }
        }
    }
    tags.push(Tag {
        at: c.eye,
        text: lang.t("observer-eye").to_owned(),
        color: [255, 255, 255, 255],
    });
    // Eye-space corners to world: the inverse of the view matrix the capture used.
    let to_world = main.matrices.view.matrix.inverse();
    let corners = main
        .projection
        .corners_eye(main.settings.aspect())
        .map(|p| to_world.transform_point3(p));
    let (near, far) = (&corners[..4], &corners[4..]);
    let dim = |c: [u8; 4]| [c[0], c[1], c[2], c[3] / 2];
    for i in 0..4 {
        let j = (i + 1) % 4;
        if parts.near {
            mark(near[i], near[j], parts.near_color, 2.0);
        }
        if parts.far {
            mark(far[i], far[j], parts.far_color, 1.5);
        }
        if parts.sides {
            mark(near[i], far[i], parts.far_color, 1.0);
            if main.projection.is_perspective() {
                mark(c.eye, near[i], dim(parts.near_color), 1.0);
            }
        }
    }
    if parts.clipped {
        let clip_to_world = (main.matrices.projection.matrix * main.matrices.view.matrix).inverse();
        for poly in main
            .primitives
            .iter()
            .filter_map(|p| p.clipped_polygon.as_ref())
            .take(2000)
        {
            let pts: Vec<Vec3> = poly
                .iter()
                .map(|v| {
                    let q = clip_to_world * v.clip;
                    q.truncate() / q.w
                })
                .collect();
            for k in 0..pts.len() {
                mark(
                    pts[k],
                    pts[(k + 1) % pts.len()],
                    opaque(crate::palette::CLIPPED),
                    1.5,
                );
            }
        }
    }
    if parts.lights {
        for (k, light) in main.lights.iter().enumerate() {
            let Some(g) = light.gizmo(scene.0, scene.1) else {
                continue;
            };
            for [a, b] in g.segments {
                mark(a, b, opaque(crate::palette::LIGHT), 2.0);
            }
            tags.push(Tag {
                at: g.label_at,
                text: crate::vocabulary::light_name(light, k, lang),
                color: opaque(crate::palette::LIGHT),
            });
        }
    }
    (marks, tags)
}

/// The centre and size of what the scene draws, for placing the lights' marks: the orbit's
/// centre and the distance from it to the viewing camera.
#[must_use]
pub fn scene_extent(spec: &SceneSpec) -> (Vec3, f32) {
    let o = default_orbit(spec);
    (
        o.centre,
        (spec.scene.camera.eye - o.centre).length().max(1.0),
    )
}

/// The scene seen from outside (the app's observer view): rendered from the default orbit, with
/// the viewing camera's frame, frustum, clipped polygons and lights drawn over it.
pub fn observer_image(
    spec: &SceneSpec,
    main: &FrameCapture,
    focus: &[String],
    direction: Option<[f32; 2]>,
) -> Option<image::RgbaImage> {
    use pipeline::overlay::Shape;
    let orbit = orbit_for(spec, focus, direction, None);
    let outside = render_observer(spec, orbit.camera(), None, None)?;
    let (marks, _) = viewing_camera(main, &Parts::default(), scene_extent(spec), Lang::EN);
    let mut shapes: Vec<Shape> = marks
        .iter()
        .filter_map(|m| {
            let [p, q] = outside.world_segment_to_image(m.a, m.b)?;
            Some(Shape::Polyline {
                points: vec![p, q],
                closed: false,
                color: m.color,
                width: m.width,
            })
        })
        .collect();
    if let Some(center) = outside.world_to_image(main.camera.eye) {
        shapes.push(Shape::Dot {
            center,
            radius: 4.0,
            color: [255, 255, 255, 255],
        });
    }
    Some(outside.image_with_shapes(BufferKind::Color, 1.0, &shapes, 1))
}

/// A palette colour, opaque.
fn opaque([r, g, b]: crate::palette::Rgb) -> [u8; 4] {
    [r, g, b, 255]
}
