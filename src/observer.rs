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

/// An orbit that frames the scene: centred on the mean of the objects' positions, far enough
/// back to see the viewing camera too.
pub fn default_orbit(spec: &SceneSpec) -> Orbit {
    let n = spec.scene.objects.len().max(1) as f32;
    let centre = spec.scene.objects.iter().map(|o| o.translate).sum::<Vec3>() / n;
    let reach = (spec.scene.camera.eye - centre).length().max(1.0);
    Orbit {
        yaw: 60.0,
        pitch: 30.0,
        distance: reach * 2.2,
        centre,
    }
}

/// The scene from the observer's camera: the same pipeline, one sample, no culling (so the
/// outside of everything is seen), a perspective lens wide enough for the viewing frustum;
/// only its colour is kept (into `spare`'s storage, if given).
pub fn render_observer(
    spec: &SceneSpec,
    camera: Camera,
    spare: Option<FrameCapture>,
) -> Option<FrameCapture> {
    let distance = (camera.eye - camera.at).length();
    let scene = Scene {
        objects: spec.scene.objects.clone(),
        camera,
        projection: Projection::Perspective {
            fovy_deg: 50.0,
            aspect: None,
            near: (distance * 0.02).max(1e-3),
            far: distance * 20.0,
        },
        figures: spec.scene.figures.clone(),
        shadow: spec.scene.shadow,
        lights: spec.scene.lights.clone(),
    };
    let settings = RenderSettings {
        samples: Samples::X1,
        capture: Capture::COLOR,
        ..spec.settings
    };
    pipeline::render_reusing(&scene, &settings, spare)
        .ok()
        .map(|(c, _)| c)
}

/// The scene seen from outside (the app's observer view): rendered from the default orbit, with
/// the viewing camera's frustum drawn over it and a dot at its eye.
pub fn observer_image(spec: &SceneSpec, main: &FrameCapture) -> Option<image::RgbaImage> {
    use pipeline::overlay::Shape;
    let orbit = default_orbit(spec);
    let outside = render_observer(spec, orbit.camera(), None)?;
    let to_world = main.matrices.view.matrix.inverse();
    let corners: Vec<glam::Vec3> = main
        .projection
        .corners_eye(main.settings.aspect())
        .iter()
        .map(|p| to_world.transform_point3(*p))
        .collect();
    let (near, far) = (&corners[..4], &corners[4..]);
    let mut shapes = Vec::new();
    let mut line = |a: glam::Vec3, b: glam::Vec3, color: [u8; 4], width: f32| {
        if let Some([p, q]) = outside.world_segment_to_image(a, b) {
            shapes.push(Shape::Polyline {
                points: vec![p, q],
                closed: false,
                color,
                width,
            });
        }
    };
    let (yellow, orange) = ([255, 214, 90, 255], [255, 140, 40, 255]);
    for i in 0..4 {
        let j = (i + 1) % 4;
        line(near[i], near[j], yellow, 2.5);
        line(far[i], far[j], orange, 2.0);
        line(near[i], far[i], orange, 1.2);
        if main.projection.is_perspective() {
            line(main.camera.eye, near[i], yellow, 1.0);
        }
    }
    if let Some(center) = outside.world_to_image(main.camera.eye) {
        shapes.push(Shape::Dot {
            center,
            radius: 4.0,
            color: [255, 255, 255, 255],
        });
    }
    Some(outside.image_with_shapes(BufferKind::Color, &shapes, 1))
}
