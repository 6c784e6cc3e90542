//! `pipelens bench`'s rows for the student's shaders: GLSL run by pipelens' interpreter beside
//! the built-in path on the same scene.

use std::time::Duration;

use pipeline::buffers::Capture;
use pipeline::lighting::Frequency;
use pipeline::scene::Scene;
use pipeline::settings::RenderSettings;

use super::{lit_textured_scene, measure, sphere_scene};

/// A vertex shader that only transforms: `gl_Position = mvp·p`.
const PASS_THROUGH_VERTEX: &str = "#version 330 core
uniform mat4 mvp;
in vec3 position;
void main() { gl_Position = mvp * vec4(position, 1.0); }
";
/// A fragment shader that writes one colour (the pass-through row measures the vertex stage).
const ONE_COLOUR_FRAGMENT: &str = "#version 330 core
out vec4 color;
void main() { color = vec4(0.8, 0.8, 0.8, 1.0); }
";

/// `scene` with every object running the shaders `vertex` and `fragment` (pipelens' own GLSL
/// for a stage left out).
///
/// # Errors
/// When the shaders do not compile or link.
pub fn with_shaders(
    scene: &Scene,
    vertex: Option<&str>,
    fragment: Option<&str>,
) -> anyhow::Result<Scene> {
    let programs = pipeline::shader::link(vertex, fragment).map_err(|e| {
        anyhow::anyhow!(
            "{}",
            e.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        )
    })?;
    let mut scene = scene.clone();
    scene.set_shaders(&pipeline::scene::ObjectShader {
        programs: std::sync::Arc::new(programs),
        time: 0.0,
    });
    Ok(scene)
}

/// Shaders the student writes beside the built-in path on the same scene, 1280×720, one
/// sample, the colour kept: pipelens' Blinn-Phong as GLSL on the lit textured scene (target:
/// the frame ≤ 3× the built-in one, issue 32; ≤ 2.5× on one thread, issue 59) and a
/// pass-through vertex shader on the 1M-triangle sphere
/// (target: the vertex stage ≤ 2× the built-in one).
pub fn rows(frames: usize, out: &mut dyn std::io::Write) -> anyhow::Result<()> {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    writeln!(
        out,
        "
shaders the student writes (GLSL, run by pipelens' interpreter) against the built-in \
         path, 1280×720, 1 sample, the colour kept; medians of {frames}:"
    )?;
    writeln!(
        out,
        "  {:<44} {:>8} {:>8} {:>8} {:>10} {:>7}",
        "scene and shader", "vertex", "resolve", "frame", "built-in", "ratio"
    )?;
    let lit = lit_textured_scene();
    let sphere = sphere_scene(1_000_000);
    let cases = [
        (
            "lit textured, Blinn-Phong fragment shader",
            &lit,
            Frequency::Phong,
            with_shaders(&lit.scene, None, Some(pipeline::shader::BUILTIN_FRAGMENT))?,
            false,
        ),
        (
            "1M sphere, pass-through vertex shader",
            &sphere,
            Frequency::Unlit,
            with_shaders(
                &sphere.scene,
                Some(PASS_THROUGH_VERTEX),
                Some(ONE_COLOUR_FRAGMENT),
            )?,
            true,
        ),
    ];
    for (label, bench, shading, glsl, vertex_only) in cases {
        let settings = RenderSettings {
            width: 1280,
            height: 720,
            shading,
            capture: Capture::COLOR,
            ..RenderSettings::default()
        };
        let builtin = measure(&bench.scene, &settings, frames)?;
        let t = measure(&glsl, &settings, frames)?;
        let (mine, theirs, what) = if vertex_only {
            (t.vertex, builtin.vertex, "vertex stage, target ≤ 2×")
        } else {
            (
                t.total(),
                builtin.total(),
                "frame, target ≤ 3×, on one thread ≤ 2.5×",
            )
        };
        writeln!(
            out,
            "  {:<44} {:>8.2} {:>8.2} {:>8.2} {:>10.2} {:>6.2}× ({what})",
            label,
            ms(t.vertex),
            ms(t.resolve),
            ms(t.total()),
            ms(theirs),
            mine.as_secs_f64() / theirs.as_secs_f64().max(1e-9)
        )?;
    }
    Ok(())
}
