//! `pipelens bench`: frame times per stage for standard scenes. It measures; it asserts nothing.

use std::time::Duration;

use glam::Vec3;
use pipeline::mesh::BuiltinMesh;
use pipeline::scene::{Camera, Object, Projection, RenderSettings, Samples, Scene};
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
            lights: Vec::new(),
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
    for (triangles, default_frames) in [(10_000, 9), (1_000_000, 3)] {
        let bench = sphere_scene(triangles);
        for samples in [Samples::X1, Samples::X4] {
            let settings = RenderSettings {
                width: 1280,
                height: 720,
                samples,
                ..RenderSettings::default()
            };
            let n = frames.unwrap_or(if quick { 1 } else { default_frames });
            let t = measure(&bench.scene, &settings, n)?;
            writeln!(
                out,
                "{:<26} {:>10} {:>7} {:>8.2} {:>11.2} {:>8.2} {:>8.2} {:>8.2}",
                bench.name,
                "1280×720",
                samples.count(),
                ms(t.vertex),
                ms(t.clip_setup),
                ms(t.raster),
                ms(t.resolve),
                ms(t.total())
            )?;
        }
    }
    Ok(())
}
