//! `pipelens bench`: frame times per stage for standard scenes. It measures; it asserts nothing.

use std::time::Duration;

use glam::Vec3;
use pipeline::mesh::BuiltinMesh;
use pipeline::scene::{Camera, Object, Projection, RenderSettings, Samples, Scene};
use pipeline::shade::Frequency;
use pipeline::{StageTimes, render_timed};

/// One benchmark scene.
pub struct BenchScene {
    /// Shown in the table.
    pub name: String,
    /// What is drawn.
    pub scene: Scene,
}

/// The uv sphere with about `triangles` triangles, filling the middle of the view.
#[must_use]
pub fn sphere_scene(triangles: u32) -> BenchScene {
    // A uv sphere has segments·(2·rings − 2) triangles; take rings = segments/2 + 1.
    let segments = ((f64::from(triangles)).sqrt().round() as u32).max(4);
    let rings = segments / 2 + 1;
    let mesh = BuiltinMesh::UvSphere { segments, rings }.build();
    let name = format!("uv_sphere {} tris", mesh.indices.len());
    BenchScene {
        name,
        scene: Scene {
            objects: vec![Object::new("sphere", mesh)],
            camera: Camera {
                eye: Vec3::new(0.0, 0.0, 3.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::default(),
            figures: Vec::new(),
            shadow: None,
            lights: Vec::new(),
        },
    }
}

/// The uv sphere over a floor with a checkerboard texture, lit per pixel (Blinn-Phong, a point
/// and an ambient light), trilinear filtering: the textured, lit scene of the benchmark.
#[must_use]
pub fn lit_textured_scene() -> BenchScene {
    use pipeline::scene::{ColorSource, Light};
    let mut floor = Object::new(
        "floor",
        BuiltinMesh::Plane {
            divisions: 16,
            repeat: 12.0,
        }
        .build(),
    );
    floor.scale = Vec3::splat(8.0);
    floor.translate = Vec3::new(0.0, -1.0, 0.0);
    floor.texture = Some(std::sync::Arc::new(
        pipeline::texture::Texture::checkerboard(512, 16),
    ));
    let mut ball = sphere_scene(10_000).scene.objects.remove(0);
    ball.color = ColorSource::Uniform(Vec3::new(0.85, 0.3, 0.25));
    BenchScene {
        name: "lit textured floor+sphere".to_owned(),
        scene: Scene {
            objects: vec![floor, ball],
            camera: Camera {
                eye: Vec3::new(0.0, 1.0, 4.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::default(),
            figures: Vec::new(),
            shadow: None,
            lights: vec![
                Light::Ambient {
                    intensity: Vec3::splat(0.2),
                },
                Light::Point {
                    position: Vec3::new(2.0, 4.0, 3.0),
                    intensity: Vec3::ONE,
                    attenuation: Vec3::new(1.0, 0.0, 0.01),
                },
            ],
        },
    }
}

/// The median of each stage over `frames` renders (after one warm-up).
///
/// # Errors
/// When the scene cannot be rendered.
pub fn measure(
    scene: &Scene,
    settings: &RenderSettings,
    frames: usize,
) -> anyhow::Result<StageTimes> {
    render_timed(scene, settings)?;
    let mut runs = Vec::with_capacity(frames);
    for _ in 0..frames.max(1) {
        runs.push(render_timed(scene, settings)?.1);
    }
    let median = |f: fn(&StageTimes) -> Duration| {
        let mut v: Vec<Duration> = runs.iter().map(f).collect();
        v.sort();
        v[v.len() / 2]
    };
    Ok(StageTimes {
        vertex: median(|t| t.vertex),
        clip_setup: median(|t| t.clip_setup),
        raster: median(|t| t.raster),
        resolve: median(|t| t.resolve),
    })
}

/// Runs the standard benchmark and prints a table; `quick` uses fewer frames.
///
/// # Errors
/// When a scene cannot be rendered.
pub fn run(quick: bool, frames: Option<usize>, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    writeln!(
        out,
        "pipelens bench — medians in ms, {} thread(s) available\n",
        std::thread::available_parallelism().map_or(1, usize::from)
    )?;
    writeln!(
        out,
        "{:<26} {:>10} {:>7} {:>8} {:>11} {:>8} {:>8} {:>8}",
        "scene", "size", "samples", "vertex", "clip+setup", "raster", "resolve", "frame"
    )?;
    let cases = [
        (sphere_scene(10_000), 9, Frequency::Unlit),
        (sphere_scene(1_000_000), 3, Frequency::Unlit),
        (lit_textured_scene(), 5, Frequency::Phong),
    ];
    let mut rows = Vec::new();
    for (bench, default_frames, shading) in cases {
        for samples in [Samples::X1, Samples::X4] {
            let settings = RenderSettings {
                width: 1280,
                height: 720,
                samples,
                shading,
                ..RenderSettings::default()
            };
            rows.push((
                bench.name.clone(),
                bench.scene.clone(),
                settings,
                default_frames,
            ));
        }
    }
    // What a slider drag waits for in the app: the built-in lesson's first scene at 960×540
    // with its own settings (4 samples, Phong, shadows).
    let tour = crate::lesson::default_lesson().map_err(|d| anyhow::anyhow!("{d}"))?;
    let spec = tour.spec_at(0);
    rows.push((
        "tour lesson (slider drag)".to_owned(),
        spec.scene,
        RenderSettings {
            width: 960,
            height: 540,
            ..spec.settings
        },
        9,
    ));
    for (name, scene, settings, default_frames) in rows {
        let n = frames.unwrap_or(if quick { 1 } else { default_frames });
        let t = measure(&scene, &settings, n)?;
        writeln!(
            out,
            "{:<26} {:>10} {:>7} {:>8.2} {:>11.2} {:>8.2} {:>8.2} {:>8.2}",
            name,
            format!("{}×{}", settings.width, settings.height),
            settings.samples.count(),
            ms(t.vertex),
            ms(t.clip_setup),
            ms(t.raster),
            ms(t.resolve),
            ms(t.total())
        )?;
    }
    Ok(())
}
