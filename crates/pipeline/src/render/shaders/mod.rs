//! The student's shaders in the pipeline. The vertex shader runs for every vertex of an object
//! that has one, 64 vertices a batch, and its `gl_Position` takes the place of `P·V·M·p` in the
//! vertex table (clipping, the division and the viewport follow from it as before). The
//! fragment shader runs after rasterization for every triangle that covers a pixel, in 2×2
//! quads as a GPU runs it (so `dFdx`, `dFdy` and `texture()`'s level of detail are differences
//! within the quad), sixteen quads a batch, and its colour replaces the built-in shading.
//!
//! Each fragment input is interpolated from the vertex outputs of the same name at the pixel
//! centre: perspective-correct by default, `(Σ λ_i·a_i/w_i)/(Σ λ_i/w_i)`; `noperspective`
//! affinely in the window, `Σ λ_i·a_i`; `flat` from the provoking (last) vertex.
//!
//! The depth test runs before the fragment shader (early z); a fragment the shader discards is
//! taken out of the test afterwards and the pixel rasterized again without it, so what lies
//! behind it shows (see `discard`).

use glam::{Vec3, Vec4};
use rayon::prelude::*;

mod discard;
mod fragment;

pub(in crate::render) use discard::peel_discarded;
pub(in crate::render) use fragment::fragment_shaders;

use super::RenderError;
use crate::capture::{FrameCapture, Matrices, ShaderRecord, VertexResults, VertexTrace};
use crate::render::resolve::ResolveContext;
use crate::scene::{Object, Scene};
use crate::settings::RenderSettings;
use crate::shader::interface::TextureSlot;
use crate::shader::{self, Bindings, LANES, Programs, Uniforms};
use crate::vertex::{self, VertexRecord};

/// The fragment stage over a resolved frame: the shaders' colours written into `color`, and
/// the record of what the shaders did (`None` when no object has shaders). `peeled` fragments
/// were discarded before the resolve.
///
/// # Errors
/// A run-time error of a fragment shader.
pub(in crate::render) fn record(
    ctx: &ResolveContext<'_>,
    matrices: &Matrices,
    vertex_results: Option<Vec<Option<VertexResults>>>,
    color: &mut [[f32; 3]],
    peeled: u64,
) -> Result<Option<ShaderRecord>, RenderError> {
    let Some(results) = vertex_results else {
        return Ok(None);
    };
    let counts = fragment_shaders(ctx, matrices, &results, color)?;
    Ok(Some(ShaderRecord {
        vertex_results: results,
        fragments: counts.fragments,
        discarded: counts.discarded + peeled,
        not_finite: counts.not_finite,
        pixel: counts.pixel,
    }))
}

/// What the fragment stage reads of a frame drawn so far.
pub(in crate::render) struct Frame<'a> {
    pub(in crate::render) scene: &'a Scene,
    pub(in crate::render) settings: &'a RenderSettings,
    pub(in crate::render) matrices: &'a Matrices,
    pub(in crate::render) triangles: &'a [crate::raster::RasterTriangle],
    pub(in crate::render) primitives: &'a [crate::capture::PrimitiveRecord],
    pub(in crate::render) vertices: &'a [VertexRecord],
    pub(in crate::render) vertex_shading: &'a [crate::shade::ShadeTerms],
    pub(in crate::render) face_shading: &'a [crate::shade::ShadeTerms],
}

/// The uniforms object `i` of `scene` is drawn with.
fn uniforms(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    i: usize,
    time: f32,
) -> Uniforms {
    let o = &scene.objects[i];
    Uniforms {
        model: matrices.models[i].matrix,
        view: matrices.view.matrix,
        projection: matrices.projection.matrix,
        eye: scene.camera.eye,
        lights: scene.lights.clone(),
        material: o.material,
        has_texture: o.texture.is_some() && !o.mesh.uvs.is_empty(),
        detail_kind: match &o.detail {
            _ if o.mesh.uvs.is_empty() => 0,
            None => 0,
            Some(crate::texture::SurfaceDetail::Bump { .. }) => 1,
            Some(crate::texture::SurfaceDetail::Normal(_)) => 2,
        },
        bump_strength: match &o.detail {
            Some(crate::texture::SurfaceDetail::Bump { strength, .. }) => *strength,
            _ => 0.0,
        },
        time,
        resolution: glam::Vec2::new(settings.width as f32, settings.height as f32),
    }
}

/// The textures a program's `sampler2D`s read and how each is sampled: the object's texture
/// with `surface` (the settings' sampler), its bump or normal map as the built-in bump mapping
/// reads it (bilinear, repeating, level 0). Nothing without texture coordinates.
fn textures<'a>(
    program: &shader::Program,
    object: &'a Object,
    surface: crate::texture::Sampler,
) -> Vec<Option<(&'a crate::texture::Texture, crate::texture::Sampler)>> {
    use crate::texture::{Filter, Mipmap, Sampler, SurfaceDetail, Wrap};
    let detail = Sampler {
        wrap: Wrap::Repeat,
        filter: Filter::Bilinear,
        mipmap: Mipmap::None,
        anisotropy: 1,
        lod_bias: 0.0,
    };
    let has_uvs = !object.mesh.uvs.is_empty();
    program
        .textures
        .iter()
        .map(|name| match shader::interface::texture_slot(name)? {
            TextureSlot::Surface => Some((object.texture.as_deref()?, surface)),
            TextureSlot::Detail => match object.detail.as_ref()? {
                SurfaceDetail::Bump { height: t, .. } | SurfaceDetail::Normal(t) => {
                    Some((&**t, detail))
                }
            },
        })
        .map(|bound| bound.filter(|_| has_uvs))
        .collect()
}

fn shader_error(stage: shader::Stage, object: &Object, e: &shader::ShaderError) -> RenderError {
    RenderError::Invalid(vec![format!(
        "{} shader of {}, {e}",
        stage.name(),
        object.name
    )])
}

/// Runs each object's vertex shader over its rows of the vertex table (`vertices`, objects in
/// order), writing `gl_Position` as the clip position (and the NDC and window positions that
/// follow from it). Returns each object's results, or `None` when no object has shaders.
///
/// # Errors
/// A run-time error of a vertex shader, or a `gl_Position` that is not finite.
pub(super) fn vertex_shaders(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    vertices: &mut [VertexRecord],
) -> Result<Option<Vec<Option<VertexResults>>>, RenderError> {
    if !scene.has_shaders() {
        return Ok(None);
    }
    let mut out = Vec::with_capacity(scene.objects.len());
    let mut first = 0usize;
    for (i, object) in scene.objects.iter().enumerate() {
        let n = object.mesh.positions.len();
        let rows = first..first + n;
        first += n;
        let Some(sh) = &object.shader else {
            out.push(None);
            continue;
        };
        let u = uniforms(scene, settings, matrices, i, sh.time);
        out.push(Some(run_vertex_shader(
            &sh.programs,
            object,
            &u,
            &matrices.viewport.matrix,
            &mut vertices[rows.clone()],
            rows.start,
        )?));
    }
    Ok(Some(out))
}

/// Row `row` of the vertex table through its object's vertex shader, traced: the attributes it
/// received, each statement with the values it wrote, and its outputs. `scene` is the scene
/// `capture` was drawn from (its figures and shadow expanded as the render expands them).
/// `None` when the row is not in the table or its object runs pipelens' own vertex stage.
///
/// # Errors
/// A run-time error of the vertex shader.
pub fn trace_vertex(
    scene: &Scene,
    capture: &FrameCapture,
    row: usize,
) -> Result<Option<VertexTrace>, RenderError> {
    // The inspector asks every frame a vertex is selected: no shader, no work (no expansion).
    if !scene.has_shaders() {
        return Ok(None);
    }
    let expanded;
    let scene = if scene.shadow.is_some() || !scene.figures.is_empty() {
        expanded = Scene {
            objects: scene.drawn_objects().0,
            shadow: None,
            figures: Vec::new(),
            ..scene.clone()
        };
        &expanded
    } else {
        scene
    };
    let Some(record) = capture.vertices.get(row) else {
        return Ok(None);
    };
    let mut first = 0usize;
    let Some((i, object)) = scene.objects.iter().enumerate().find(|(_, o)| {
        let n = o.mesh.positions.len();
        first += n;
        row < first
    }) else {
        return Ok(None);
    };
    let Some(sh) = &object.shader else {
        return Ok(None);
    };
    let index = row - (first - object.mesh.positions.len());
    let vs = &sh.programs.vertex;
    let u = uniforms(scene, &capture.settings, &capture.matrices, i, sh.time);
    let mut m = vs.machine();
    vs.set_uniforms(&mut m, &u);
    let inputs: Vec<Vec<u32>> = vs
        .inputs
        .iter()
        .map(|input| {
            let mut rows = vec![0u32; input.components as usize * LANES];
            let location = shader::interface::attribute_location(&input.name);
            write_input(&mut rows, 0, input, location, object, record, index);
            rows
        })
        .collect();
    let refs: Vec<&[u32]> = inputs.iter().map(Vec::as_slice).collect();
    let tex = textures(vs, object, crate::texture::Sampler::default());
    let bindings = Bindings { textures: &tex };
    m.trace_lane(Some(0));
    m.run(&refs, 1, 1, &bindings)
        .map_err(|e| shader_error(shader::Stage::Vertex, object, &vs.run_error(&e)))?;
    let events = m.take_trace();
    let result = m.result();
    let mut at = 0usize;
    let outputs = vs
        .outputs
        .iter()
        .map(|o| {
            let n = o.components as usize;
            let value = lane_value(&result[at * LANES..], n, 0);
            at += n;
            (o.name.clone(), value)
        })
        .collect();
    Ok(Some(VertexTrace {
        row: row as u32,
        object: object.name.clone(),
        inputs: lane_values(&vs.inputs, &inputs, 0),
        trace: vs.describe(&events),
        outputs,
    }))
}

/// Lane `lane`'s value of a varying of `components` floats, rows `LANES` apart, as GLSL writes
/// it: `0.500` or `vec3(0.000, 0.707, 0.707)`.
pub(super) fn lane_value(rows: &[u32], components: usize, lane: usize) -> String {
    let v: Vec<String> = (0..components)
        .map(|c| format!("{:.3}", f32::from_bits(rows[c * LANES + lane])))
        .collect();
    if v.len() == 1 {
        v[0].clone()
    } else {
        format!("vec{}({})", v.len(), v.join(", "))
    }
}

/// Each varying's name and lane `lane`'s value (see [`lane_value`]).
pub(super) fn lane_values(
    varyings: &[shader::Varying],
    rows: &[Vec<u32>],
    lane: usize,
) -> Vec<(String, String)> {
    varyings
        .iter()
        .zip(rows)
        .map(|(v, r)| (v.name.clone(), lane_value(r, v.components as usize, lane)))
        .collect()
}

/// Writes vertex shader input `input` of mesh vertex `i` (table row `record`) into lane `l` of
/// its rows: `gl_VertexIndex` is `i`, an attribute its value at `location`.
fn write_input(
    rows: &mut [u32],
    l: usize,
    input: &shader::Varying,
    location: Option<u32>,
    object: &Object,
    record: &VertexRecord,
    i: usize,
) {
    if input.builtin == Some(naga::BuiltIn::VertexIndex) {
        rows[l] = i as u32;
        return;
    }
    let a = attribute(object, record, location, i);
    for c in 0..input.components as usize {
        rows[c * LANES + l] = a[c].to_bits();
    }
}

/// One attribute's value for mesh vertex `i` (see [`shader::interface::ATTRIBUTES`]).
fn attribute(object: &Object, record: &VertexRecord, location: Option<u32>, i: usize) -> [f32; 4] {
    let mesh = &object.mesh;
    let v3 = |v: Vec3| [v.x, v.y, v.z, 0.0];
    match location {
        Some(0) => v3(record.object_pos.truncate()),
        Some(1) => v3(mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO)),
        Some(2) => mesh
            .uvs
            .get(i)
            .map_or([0.0; 4], |uv| [uv.x, uv.y, 0.0, 0.0]),
        Some(3) => v3(record.color),
        _ => [0.0; 4],
    }
}

fn run_vertex_shader(
    programs: &Programs,
    object: &Object,
    u: &Uniforms,
    viewport: &glam::Mat4,
    rows: &mut [VertexRecord],
    first: usize,
) -> Result<VertexResults, RenderError> {
    let vs = &programs.vertex;
    let stride: u32 = vs.outputs.iter().map(|o| o.components).sum();
    let mut values = vec![0f32; rows.len() * stride as usize];
    let tex = textures(vs, object, crate::texture::Sampler::default());
    let locations: Vec<Option<u32>> = vs
        .inputs
        .iter()
        .map(|i| shader::interface::attribute_location(&i.name))
        .collect();
    rows.par_chunks_mut(LANES)
        .zip(values.par_chunks_mut(LANES * stride as usize))
        .enumerate()
        .try_for_each_init(
            || {
                let mut m = vs.machine();
                vs.set_uniforms(&mut m, u);
                (m, Vec::<Vec<u32>>::new())
            },
            |(m, inputs), (k, (records, results))| {
                let n = records.len();
                inputs.resize(vs.inputs.len(), Vec::new());
                for ((input, rows_in), location) in vs.inputs.iter().zip(inputs.iter_mut()).zip(&locations) {
                    rows_in.clear();
                    rows_in.resize(input.components as usize * LANES, 0);
                    for (l, r) in records.iter().enumerate() {
                        write_input(rows_in, l, input, *location, object, r, k * LANES + l);
                    }
                }
                let refs: Vec<&[u32]> = inputs.iter().map(Vec::as_slice).collect();
                let bindings = Bindings { textures: &tex };
                let live = if n == LANES { u64::MAX } else { (1 << n) - 1 };
                m.run(&refs, n, live, &bindings)
                    .map_err(|e| shader_error(shader::Stage::Vertex, object, &vs.run_error(&e)))?;
                let result = m.result();
                for (l, r) in records.iter_mut().enumerate() {
                    for c in 0..stride as usize {
                        results[l * stride as usize + c] = f32::from_bits(result[c * LANES + l]);
                    }
                    let p = programs.position as usize;
                    let clip = Vec4::from_slice(&results[l * stride as usize + p..][..4]);
                    if !clip.is_finite() {
                        return Err(RenderError::Invalid(vec![format!(
                            "vertex shader of {}: vertex {} has gl_Position = {clip}, which is not finite",
                            object.name,
                            k * LANES + l
                        )]));
                    }
                    r.clip = clip;
                    (r.ndc, r.window) = if clip.w > 0.0 {
                        let (ndc, window, _) = vertex::to_window(clip, viewport);
                        (Some(ndc), Some(window))
                    } else {
                        (None, None)
                    };
                }
                Ok(())
            },
        )?;
    Ok(VertexResults {
        first: first as u32,
        stride,
        values,
    })
}
