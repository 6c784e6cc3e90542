//! `pipelens bench --peer-python`: pipelens and Mesa's llvmpipe (through the peer's `render.py`)
//! drawing the same OBJ meshes the same way, in alternating rounds, their medians side by side.

use glam::Vec3;
use pipeline::buffers::Capture;
use pipeline::camera::{Camera, Projection};
use pipeline::lighting::Frequency;
use pipeline::raster::Samples;
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;

use super::{BenchScene, measure, median};

/// Where the reference renderer is: Mesa's llvmpipe through `render.py` of
/// `../shared/peers/llvmpipe/` (see its README for the set-up).
#[derive(Clone, Debug)]
pub struct Peer {
    /// The Python that has moderngl (the peer's venv).
    pub python: std::path::PathBuf,
    /// `render.py`.
    pub script: std::path::PathBuf,
}

/// An OBJ scene as the peer draws it with `--fit`: the mesh centred and scaled into the unit
/// sphere, eye (0, 0, 3) looking at the origin, fovy 45°, near 0.1, far 50, a white point light
/// at (4, 4, 4) with no attenuation, Blinn-Phong per pixel with k_a 0.05, k_d 0.7 (or the texel,
/// bilinear), k_s 0.5, shininess 64.
///
/// # Errors
/// When the mesh or the texture cannot be loaded.
pub fn obj_scene(
    mesh: &std::path::Path,
    texture: Option<&std::path::Path>,
) -> anyhow::Result<BenchScene> {
    use pipeline::light::{Light, Material};
    use pipeline::scene::ColorSource;
    let mut m = pipeline::mesh::Mesh::load_obj(mesh)?;
    // As the peer's `--fit`: centred and scaled into the unit sphere.
    m.fit_unit_sphere();
    let name = mesh
        .file_name()
        .map_or_else(|| "mesh".to_owned(), |n| n.to_string_lossy().into_owned());
    let mut object = Object::new(&name, m);
    object.color = ColorSource::Uniform(Vec3::ONE);
    object.material = Material {
        ka: Vec3::splat(0.05),
        kd: Vec3::splat(0.7),
        ks: Vec3::splat(0.5),
        shininess: 64.0,
    };
    if let Some(t) = texture {
        object.texture = Some(std::sync::Arc::new(pipeline::texture::Texture::load(t)?));
    }
    Ok(BenchScene {
        name: format!(
            "{name}{}",
            if texture.is_some() { " + texture" } else { "" }
        ),
        scene: Scene {
            uniforms: Default::default(),
            objects: vec![object],
            camera: Camera {
                eye: Vec3::new(0.0, 0.0, 3.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::Perspective {
                fovy_deg: 45.0,
                aspect: None,
                near: 0.1,
                far: 50.0,
            },
            lights: vec![
                Light::Ambient {
                    intensity: Vec3::ONE,
                },
                Light::Point {
                    position: Vec3::splat(4.0),
                    intensity: Vec3::ONE,
                    attenuation: Vec3::X,
                },
            ],
            ..Scene::default()
        },
    })
}

/// What the peer is asked to draw: a mesh (with its texture), at a size, with samples, with
/// its own fragment shader or the GLSL file `fragment`.
struct PeerCase<'a> {
    mesh: &'a std::path::Path,
    texture: Option<&'a std::path::Path>,
    size: (u32, u32),
    samples: u32,
    fragment: Option<&'a std::path::Path>,
}

/// The peer's median frame time (ms) over `frames` of `case` on `threads`.
fn peer_frame_ms(
    peer: &Peer,
    case: &PeerCase<'_>,
    threads: usize,
    frames: usize,
) -> anyhow::Result<f64> {
    use anyhow::Context;
    let PeerCase {
        mesh,
        texture,
        size,
        samples,
        fragment,
    } = *case;
    let mut cmd = std::process::Command::new(&peer.python);
    cmd.arg(&peer.script)
        .arg(mesh)
        .args(["--fit", "--bench", &frames.to_string()])
        .args(["--size", &format!("{}x{}", size.0, size.1)])
        .args([
            "--samples",
            &if samples > 1 { samples } else { 0 }.to_string(),
        ])
        .env("LP_NUM_THREADS", threads.to_string());
    if let Some(t) = texture {
        cmd.arg("--texture").arg(t).args(["--filter", "linear"]);
    }
    if let Some(fs) = fragment {
        cmd.arg("--fs").arg(fs);
    }
    let out = cmd.output().context("running the llvmpipe peer")?;
    anyhow::ensure!(
        out.status.success(),
        "the peer failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text
        .lines()
        .rev()
        .find(|l| l.contains("median_ms"))
        .unwrap_or("");
    let v: serde_json::Value = serde_json::from_str(line).context("reading the peer's output")?;
    v["median_ms"]
        .as_f64()
        .context("the peer printed no median")
}

/// The student's Blinn-Phong row's fragment shader (pipelens' [`BUILTIN_FRAGMENT`], the GLSL
/// `pipelens bench --shaders` runs) as the peer can run it: its `main` word for word, renamed
/// `blinn_phong`, after the declarations the peer sets. The peer's `render.py` sets no array of
/// lights, so the lights the student's loop reads are filled from its uniforms before the call:
/// an ambient light of intensity 1 and the white point light at `light_pos` with no
/// attenuation, the scene both renderers draw ([`obj_scene`]); the surface colour a vertex
/// would give is white, as `obj_scene`'s object is. pipelens runs this same text.
///
/// [`BUILTIN_FRAGMENT`]: pipeline::shader::BUILTIN_FRAGMENT
///
/// # Errors
/// When the shipped shader no longer has a `void main()` to take.
pub fn student_fragment_for_peer() -> anyhow::Result<String> {
    let student = pipeline::shader::BUILTIN_FRAGMENT;
    let start = student
        .find("void main()")
        .ok_or_else(|| anyhow::anyhow!("blinn_phong.frag has no `void main()`"))?;
    let body = &student[start..].replacen("void main()", "void blinn_phong()", 1);
    Ok(format!(
        "#version 330 core
// The student's Blinn-Phong (pipelens' blinn_phong.frag), its main() word for word below as
// blinn_phong(), with the lights it loops over filled from the peer's uniforms.
{declarations}uniform vec3 eye;
uniform vec3 ka;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;
uniform bool use_tex;
uniform sampler2D tex;
uniform vec3 light_pos;
uniform vec3 light_color;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

const vec3 v_color = vec3(1.0);
Light lights[MAX_LIGHTS];
int light_count;

{body}
void main() {{
    lights[0] = Light(LIGHT_AMBIENT, vec3(0.0), vec3(0.0), vec3(1.0), vec3(1.0, 0.0, 0.0), 0.0, 0.0);
    lights[1] = Light(LIGHT_POINT, light_pos, vec3(0.0), light_color, vec3(1.0, 0.0, 0.0), 0.0, 0.0);
    light_count = 2;
    blinn_phong();
}}
",
        declarations = pipeline::shader::interface::light_declarations()
    ))
}

/// The bunny and the textured Spot under `data`, those that are present.
fn peer_meshes(
    data: &std::path::Path,
) -> anyhow::Result<Vec<(std::path::PathBuf, Option<std::path::PathBuf>)>> {
    let spot = data.join("models/spot");
    let meshes: Vec<_> = [
        (data.join("models/stanford-bunny.obj"), None),
        (
            spot.join("spot_triangulated_good.obj"),
            Some(spot.join("spot_texture.png")),
        ),
    ]
    .into_iter()
    .filter(|(m, _)| m.is_file())
    .collect();
    anyhow::ensure!(
        !meshes.is_empty(),
        "no bunny or Spot under {}",
        data.display()
    );
    Ok(meshes)
}

/// Runs pipelens and the peer on the shared data's meshes (when present), alternately, `rounds`
/// times each, and prints both medians and their ratio per scene, size, samples and threads.
///
/// # Errors
/// When a scene cannot be loaded or rendered, or the peer fails.
pub fn run_against_peer(
    peer: &Peer,
    data: &std::path::Path,
    quick: bool,
    out: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    let meshes = peer_meshes(data)?;
    let (frames, rounds) = if quick { (3, 1) } else { (15, 3) };
    writeln!(
        out,
        "\npipelens against llvmpipe — medians of {rounds} alternating rounds of {frames} frames; \
         pipelens with every buffer captured (all) and with the colour only (colour)\n"
    )?;
    writeln!(
        out,
        "{:<38} {:>10} {:>7} {:>7} {:>9} {:>9} {:>12} {:>9} {:>9}",
        "scene",
        "size",
        "samples",
        "threads",
        "all ms",
        "colour ms",
        "llvmpipe ms",
        "all ×",
        "colour ×"
    )?;
    let sizes: &[(u32, u32)] = if quick {
        &[(1280, 720)]
    } else {
        &[(960, 540), (1280, 720), (1920, 1080)]
    };
    for (mesh, texture) in &meshes {
        let bench = obj_scene(mesh, texture.as_deref())?;
        for &size in sizes {
            for samples in [Samples::X1, Samples::X4] {
                for threads in [1usize, 2] {
                    let settings = RenderSettings {
                        width: size.0,
                        height: size.1,
                        samples,
                        shading: Frequency::Phong,
                        sampler: pipeline::texture::Sampler {
                            mipmap: pipeline::texture::Mipmap::None,
                            ..pipeline::texture::Sampler::default()
                        },
                        ..RenderSettings::default()
                    };
                    let pool = super::pool(threads)?;
                    let colour = RenderSettings {
                        capture: Capture::COLOR,
                        ..settings
                    };
                    let (mut ours, mut shown, mut theirs) = (Vec::new(), Vec::new(), Vec::new());
                    for _ in 0..rounds {
                        let t = pool.install(|| measure(&bench.scene, &settings, frames))?;
                        ours.push(t.total().as_secs_f64() * 1e3);
                        let t = pool.install(|| measure(&bench.scene, &colour, frames))?;
                        shown.push(t.total().as_secs_f64() * 1e3);
                        let case = PeerCase {
                            mesh,
                            texture: texture.as_deref(),
                            size,
                            samples: samples.count() as u32,
                            fragment: None,
                        };
                        theirs.push(peer_frame_ms(peer, &case, threads, frames)?);
                    }
                    let (a, c, b) = (median(&mut ours), median(&mut shown), median(&mut theirs));
                    writeln!(
                        out,
                        "{:<38} {:>10} {:>7} {:>7} {:>9.2} {:>9.2} {:>12.2} {:>8.2}× {:>8.2}×",
                        bench.name,
                        format!("{}×{}", size.0, size.1),
                        samples.count(),
                        threads,
                        a,
                        c,
                        b,
                        a / b,
                        c / b
                    )?;
                }
            }
        }
    }
    student_shader_against_peer(peer, &meshes, (frames, rounds), out)
}

/// The student's Blinn-Phong GLSL ([`student_fragment_for_peer`]) run by pipelens' interpreter
/// and compiled by llvmpipe, on each mesh at 1280×720, one sample, 1 and 2 threads, the colour
/// kept, alternately `rounds` times: both medians, the ratio (target ≤ 3×), and pipelens'
/// built-in path beside them.
fn student_shader_against_peer(
    peer: &Peer,
    meshes: &[(std::path::PathBuf, Option<std::path::PathBuf>)],
    (frames, rounds): (usize, usize),
    out: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    use anyhow::Context;
    let source = student_fragment_for_peer()?;
    let fs = std::env::temp_dir().join(format!(
        "pipelens-student-blinn-phong-{}.frag",
        std::process::id()
    ));
    std::fs::write(&fs, &source).context("writing the peer's shader")?;
    let rows = student_rows(peer, meshes, (frames, rounds), &source, &fs, out);
    // The file is the run's own: gone whatever the rows did.
    let _ = std::fs::remove_file(&fs);
    rows
}

/// The rows of [`student_shader_against_peer`], the peer reading the shader from `fs`.
fn student_rows(
    peer: &Peer,
    meshes: &[(std::path::PathBuf, Option<std::path::PathBuf>)],
    (frames, rounds): (usize, usize),
    source: &str,
    fs: &std::path::Path,
    out: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    writeln!(
        out,
        "
the student's Blinn-Phong GLSL (blinn_phong.frag's main) in both: pipelens' \
         interpreter and llvmpipe's compiled code, the same source, 1280×720, 1 sample, the \
         colour kept; medians of {rounds} alternating rounds of {frames} frames\n"
    )?;
    writeln!(
        out,
        "{:<38} {:>7} {:>12} {:>14} {:>15} {:>15}",
        "scene", "threads", "built-in ms", "GLSL ms (ours)", "GLSL ms (llvm)", "GLSL × (≤ 3×)"
    )?;
    let size = (1280, 720);
    for (mesh, texture) in meshes {
        let bench = obj_scene(mesh, texture.as_deref())?;
        let glsl = super::with_shaders(&bench.scene, None, Some(source))?;
        let settings = RenderSettings {
            width: size.0,
            height: size.1,
            shading: Frequency::Phong,
            capture: Capture::COLOR,
            sampler: pipeline::texture::Sampler {
                mipmap: pipeline::texture::Mipmap::None,
                ..pipeline::texture::Sampler::default()
            },
            ..RenderSettings::default()
        };
        for threads in [1usize, 2] {
            let pool = super::pool(threads)?;
            let (mut builtin, mut ours, mut theirs) = (Vec::new(), Vec::new(), Vec::new());
            for _ in 0..rounds {
                let ms = |t: pipeline::StageTimes| t.total().as_secs_f64() * 1e3;
                builtin.push(ms(
                    pool.install(|| measure(&bench.scene, &settings, frames))?
                ));
                ours.push(ms(pool.install(|| measure(&glsl, &settings, frames))?));
                let case = PeerCase {
                    mesh,
                    texture: texture.as_deref(),
                    size,
                    samples: 1,
                    fragment: Some(fs),
                };
                theirs.push(peer_frame_ms(peer, &case, threads, frames)?);
            }
            let (b, a, c) = (median(&mut builtin), median(&mut ours), median(&mut theirs));
            writeln!(
                out,
                "{:<38} {:>7} {:>12.2} {:>14.2} {:>15.2} {:>14.2}×",
                bench.name,
                threads,
                b,
                a,
                c,
                a / c
            )?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The peer's copy keeps the student's `main` word for word and compiles in pipelens.
    #[test]
    fn the_peers_fragment_shader_is_the_students_main_and_compiles() {
        let fs = student_fragment_for_peer().expect("made");
        let student = pipeline::shader::BUILTIN_FRAGMENT;
        let main = &student[student.find("void main()").expect("main")..];
        let body = &main["void main()".len()..];
        assert!(fs.contains(&format!("void blinn_phong(){body}")));
        pipeline::shader::link(None, Some(&fs)).expect("pipelens compiles the peer's copy");
    }
}
