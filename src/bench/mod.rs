//! `pipelens bench`: frame times per stage for standard scenes (against Mesa's llvmpipe on the
//! same meshes in `peer.rs`). It measures; it asserts nothing.

mod debugger;
pub mod grade;
pub mod handouts;
pub mod peer;
pub mod scaling;
mod shaders;
pub mod steps;

pub use peer::{Peer, run_against_peer};
pub use shaders::with_shaders;

use std::time::Duration;

use glam::Vec3;
use pipeline::buffers::Capture;
use pipeline::camera::{Camera, Projection};
use pipeline::lighting::Frequency;
use pipeline::mesh::BuiltinMesh;
use pipeline::raster::Samples;
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;
use pipeline::{StageTimes, render_reusing, render_timed};

/// A rayon pool of `n` threads for one measurement (every table's rows at 1, 2, … threads).
///
/// # Errors
/// When the threads cannot be started.
pub fn pool(n: usize) -> anyhow::Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .map_err(|e| anyhow::anyhow!("cannot start {n} threads: {e}"))
}

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
            uniforms: Default::default(),
            objects: vec![Object::new("sphere", mesh)],
            camera: Camera {
                eye: Vec3::new(0.0, 0.0, 3.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::default(),
            ..Scene::default()
        },
    }
}

/// The uv sphere over a floor with a checkerboard texture, lit per pixel (Blinn-Phong, a point
/// and an ambient light), trilinear filtering: the textured, lit scene of the benchmark.
#[must_use]
pub fn lit_textured_scene() -> BenchScene {
    use pipeline::light::Light;
    use pipeline::scene::ColorSource;
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
            uniforms: Default::default(),
            objects: vec![floor, ball],
            camera: Camera {
                eye: Vec3::new(0.0, 1.0, 4.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::default(),
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
            ..Scene::default()
        },
    }
}

/// The median of each stage over `frames` renders (after one warm-up), each written into the
/// storage of the one before, as the app renders.
///
/// # Errors
/// When the scene cannot be rendered.
pub fn measure(
    scene: &Scene,
    settings: &RenderSettings,
    frames: usize,
) -> anyhow::Result<StageTimes> {
    let mut spare = Some(render_timed(scene, settings)?.0);
    let mut runs = Vec::with_capacity(frames);
    for _ in 0..frames.max(1) {
        let (capture, times) = render_reusing(scene, settings, spare.take())?;
        spare = Some(capture);
        runs.push(times);
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

/// The instruction sets this build was compiled for, as a run should state them: the native
/// build takes those of the processor it was built on (`.cargo/config.toml`), one built with
/// `RUSTFLAGS=` its architecture's baseline.
fn compiled_for() -> String {
    let wider: Vec<&str> = [
        ("AVX-512", cfg!(target_feature = "avx512f")),
        ("AVX2", cfg!(target_feature = "avx2")),
        ("FMA", cfg!(target_feature = "fma")),
    ]
    .into_iter()
    .filter_map(|(name, on)| on.then_some(name))
    .collect();
    if wider.is_empty() {
        format!("{}'s baseline", std::env::consts::ARCH)
    } else {
        format!("{} with {}", std::env::consts::ARCH, wider.join(", "))
    }
}

/// Runs the standard benchmark and prints a table; `quick` uses fewer frames.
///
/// # Errors
/// When a scene cannot be rendered.
pub fn run(quick: bool, frames: Option<usize>, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    writeln!(
        out,
        "pipelens bench — medians in ms, {} thread(s) available, compiled for {}; stages with \
         every buffer captured, then the frame keeping the colour only (what the Output view \
         keeps)\n",
        rayon::current_num_threads(),
        compiled_for()
    )?;
    writeln!(
        out,
        "{:<26} {:>10} {:>7} {:>8} {:>11} {:>8} {:>8} {:>8} {:>8}",
        "scene", "size", "samples", "vertex", "clip+setup", "raster", "resolve", "frame", "colour"
    )?;
    let cases = [
        (sphere_scene(10_000), 9, Frequency::Unlit),
        (sphere_scene(1_000_000), 3, Frequency::Unlit),
        (lit_textured_scene(), 5, Frequency::Phong),
    ];
    for (bench, default_frames, shading) in cases {
        for samples in [Samples::X1, Samples::X4] {
            let settings = RenderSettings {
                width: 1280,
                height: 720,
                samples,
                shading,
                ..RenderSettings::default()
            };
            let n = frames.unwrap_or(if quick { 1 } else { default_frames });
            let t = measure(&bench.scene, &settings, n)?;
            let colour = RenderSettings {
                capture: Capture::COLOR,
                ..settings
            };
            let c = measure(&bench.scene, &colour, n)?;
            writeln!(
                out,
                "{:<26} {:>10} {:>7} {:>8.2} {:>11.2} {:>8.2} {:>8.2} {:>8.2} {:>8.2}",
                bench.name,
                format!("{}×{}", settings.width, settings.height),
                settings.samples.count(),
                ms(t.vertex),
                ms(t.clip_setup),
                ms(t.raster),
                ms(t.resolve),
                ms(t.total()),
                ms(c.total())
            )?;
        }
    }
    writeln!(
        out,
        "(these frames are rasterized and resolved band by band, the two at once: the frame is \
         timed whole; resolve is the bands' resolve times summed and divided by the threads, \
         raster the rest)"
    )?;
    shader_rows(frames.unwrap_or(if quick { 1 } else { 5 }), out)?;
    slider_drag(frames.unwrap_or(if quick { 1 } else { 15 }), out)?;
    memory(out)
}

/// The rows of the student's shaders: GLSL beside the built-in path, then the debugger's
/// timings on lesson 24 (`pipelens bench --shaders`), `frames` runs each.
///
/// # Errors
/// When a shader does not compile or a frame cannot be drawn.
pub fn shader_rows(frames: usize, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    shaders::rows(frames, out)?;
    debugger::rows(frames, out)
}

/// The memory of a full capture of the lit, textured scene at 1920×1080 with 4 samples:
/// measured from the capture's own buffers and records.
fn memory(out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    let settings = RenderSettings {
        width: 1920,
        height: 1080,
        samples: Samples::X4,
        shading: Frequency::Phong,
        ..RenderSettings::default()
    };
    let c = pipeline::render(&lit_textured_scene().scene, &settings)?;
    let mb = |b: u64| b as f64 / 1e6;
    writeln!(
        out,
        "\nmemory of a full capture, lit textured scene, 1920×1080, 4 samples: {:.1} MB \
         (buffers {:.1} MB = {} bytes a pixel + {} a sample; records {:.1} MB)",
        mb(c.memory_bytes()),
        mb(c.buffer_bytes()),
        settings.capture.bytes_per_pixel(),
        pipeline::buffers::CAPTURE_BYTES_PER_SAMPLE,
        mb(c.memory_bytes() - c.buffer_bytes())
    )?;
    Ok(())
}

/// What a slider drag waits for in the app: the built-in lesson's first step at 960×540, the
/// render the app's worker does for it (the view's capture keeping what it shows, and the
/// observer), and what inspecting a pixel adds (every buffer kept by a full frame, its own
/// terms by a draft).
fn slider_drag(frames: usize, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    use crate::app::session::Session;
    let tour = crate::lesson::default_lesson().map_err(|d| anyhow::anyhow!("{d}"))?;
    let doc = crate::lesson::Document::Lesson(Box::new(tour));
    let mut session = Session::with_document(doc, "bench", None);
    session.spec.settings.width = 960;
    session.spec.settings.height = 540;
    writeln!(
        out,
        "\nslider drag on the tour lesson at 960×540, {} samples, as the app renders it \
         (view + observer; medians of {frames}):",
        session.spec.settings.samples.count()
    )?;
    // Drafts are what is on screen during a drag (target ≤ 16 ms), the full frame what follows
    // the release (target ≤ 100 ms).
    for (label, pixel, drafting) in [
        ("released: full frame", None, false),
        ("released: full frame", Some((480, 270)), false),
        ("dragging: draft", None, true),
        ("dragging: draft", Some((480, 270)), true),
    ] {
        session.selection.pixel = pixel;
        session.drafting = drafting;
        let job = session.job();
        let mut times: Vec<_> = job_frames(&job, frames)?
            .into_iter()
            .map(|(_, wall)| wall)
            .collect();
        times.sort();
        writeln!(
            out,
            "  {:<20} {:<18} {:<19} stage {:<10} keeps {:<28} {:>8.2} ms",
            label,
            match (
                job.spec.settings.samples.count(),
                job.spec.settings.coarse_shading
            ) {
                (1, true) => "1 sample, 2×2 rate".to_string(),
                (1, false) => "1 sample".to_string(),
                (n, _) => format!("{n} samples"),
            },
            if pixel.is_some() {
                "a pixel inspected"
            } else {
                "nothing inspected"
            },
            session.selection.stage.name(crate::vocabulary::Lang::EN),
            match job.spec.settings.capture {
                Capture::FULL => "every buffer",
                Capture::COLOR => "the colour only",
                c if c.with_pixel(None) == Capture::COLOR => "the colour + 1 pixel's terms",
                _ => "some buffers",
            },
            times[times.len() / 2].as_secs_f64() * 1e3
        )?;
    }
    Ok(())
}

/// Renders `job` once to warm up and then `frames` times (at least once), each frame written
/// into the storage of the one before, as the app's render worker does: each frame's stage
/// times and the job's wall time.
///
/// # Errors
/// When the job's scene cannot be rendered.
pub fn job_frames(
    job: &crate::app::worker::Job,
    frames: usize,
) -> anyhow::Result<Vec<(pipeline::StageTimes, std::time::Duration)>> {
    let mut spares = crate::app::worker::RecycledCaptures::default();
    let mut measured = Vec::with_capacity(frames.max(1));
    for i in 0..=frames.max(1) {
        let start = std::time::Instant::now();
        let done = job.clone().run(&mut spares);
        let wall = start.elapsed();
        let rendered = done.result.map_err(|e| anyhow::anyhow!(e))?;
        if i > 0 {
            measured.push((rendered.times, wall));
        }
        spares.reuse(rendered);
    }
    Ok(measured)
}

/// The middle value of `v`.
pub(super) fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}
