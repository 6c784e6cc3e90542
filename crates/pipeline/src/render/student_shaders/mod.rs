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

use glam::Vec3;
use rayon::prelude::*;

mod discard;
mod fragment;
mod replay;

pub(in crate::render) use discard::{Peeled, peel_discarded};
pub(in crate::render) use fragment::fragment_shaders;
pub use replay::{ReplayError, WatchRun, watch_fragment, watch_vertex};

use super::RenderError;
use crate::capture::{
    FrameCapture, Matrices, ShaderRecord, VertexResults, VertexTrace, WatchPicture,
};
use crate::render::resolve::ResolveContext;
use crate::scene::{Object, Scene};
use crate::settings::RenderSettings;
use crate::shader::interface::TextureSlot;
use crate::shader::{self, Batch, Bindings, LANES, Programs, Uniforms};
use crate::vertex::{self, VertexRecord};

/// The fragment stage over a resolved frame: the shaders' colours written into `color`, and
/// the record of what the shaders did (`None` when no object has shaders). `peeled` fragments
/// were discarded before the resolve: the inspected pixel's runs list theirs first, nearest
/// first, each ending at its `discard`.
///
/// # Errors
/// A run-time error of a fragment shader.
pub(in crate::render) fn record(
    ctx: &ResolveContext<'_>,
    matrices: &Matrices,
    vertex_results: Option<Vec<Option<VertexResults>>>,
    color: &mut [[f32; 3]],
    peeled: Peeled,
) -> Result<Option<ShaderRecord>, RenderError> {
    let Some(results) = vertex_results else {
        return Ok(None);
    };
    let counts = fragment_shaders(ctx, matrices, &results, color)?;
    let mut pixel = peeled.traces;
    pixel.extend(counts.pixel);
    let watch = watch_picture(ctx, counts.watch, color.len());
    let cost = ctx.settings.capture.cost.then(|| {
        let mut values = vec![None; color.len()];
        for (i, steps) in counts.cost {
            values[i] = Some([steps as f32, 0.0, 0.0, 0.0]);
        }
        WatchPicture {
            line: 0,
            from_vertex: false,
            expression: "steps run".to_owned(),
            kind: Some(shader::probe::WatchKind::Int),
            values,
            width: ctx.settings.width,
        }
    });
    Ok(Some(ShaderRecord {
        vertex_results: results,
        fragments: counts.fragments,
        discarded: counts.discarded + peeled.fragments,
        not_finite: counts.not_finite,
        pixel,
        watch,
        cost,
    }))
}

/// The picture of what the watch saw (`None` when no object's shader watches).
fn watch_picture(
    ctx: &ResolveContext<'_>,
    seen: Vec<(usize, shader::probe::Watched)>,
    pixels: usize,
) -> Option<WatchPicture> {
    let (places, from_vertex) = ctx.scene.objects.iter().find_map(|o| {
        let programs = &o.code.shader.as_ref()?.programs;
        programs
            .fragment
            .watch
            .clone()
            .map(|w| (w, false))
            .or_else(|| programs.vertex.watch.clone().map(|w| (w, true)))
    })?;
    let mut values = vec![None; pixels];
    let mut kind = None;
    for (i, w) in seen {
        kind.get_or_insert(w.kind);
        values[i] = Some(w.value);
    }
    Some(WatchPicture {
        line: places.line,
        from_vertex,
        expression: places.expression,
        kind,
        values,
        width: ctx.settings.width,
    })
}

/// What the fragment stage reads of a frame drawn so far.
pub(in crate::render) struct Frame<'a> {
    pub(in crate::render) scene: &'a Scene,
    pub(in crate::render) settings: &'a RenderSettings,
    pub(in crate::render) matrices: &'a Matrices,
    pub(in crate::render) triangles: &'a [crate::raster::RasterTriangle],
    pub(in crate::render) primitives: &'a [crate::capture::PrimitiveRecord],
    pub(in crate::render) vertices: &'a [VertexRecord],
    pub(in crate::render) vertex_shading: &'a [crate::lighting::ShadeTerms],
    pub(in crate::render) face_shading: &'a [crate::lighting::ShadeTerms],
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
        at_up: [scene.camera.at, scene.camera.up],
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
        displacement_scale: match &o.displacement {
            Some(d) if !o.mesh.uvs.is_empty() => d.scale,
            _ => 0.0,
        },
        reflectivity: o.environment.as_ref().map_or(0.0, |e| e.reflectivity),
        time,
        resolution: glam::Vec2::new(settings.width as f32, settings.height as f32),
        lens: lens(&scene.projection, settings),
        rotation: o.rotate_deg,
        axis_angle: o.axis_rotation.unwrap_or((glam::Vec3::ZERO, 0.0)),
        scale: o.scale,
        own: own_uniforms(scene, o),
    }
}

/// The values of the student's own uniforms `object`'s shaders declare: the scene's, or where
/// it has none, the comment's (`shader::own_uniform`).
fn own_uniforms(scene: &Scene, object: &Object) -> Vec<(String, Vec<u32>)> {
    let Some(sh) = &object.code.shader else {
        return Vec::new();
    };
    let mut own = sh.programs.vertex.own_uniforms();
    own.extend(sh.programs.fragment.own_uniforms());
    own.into_iter()
        .map(|u| {
            let value = scene.uniforms.get(&u.name).unwrap_or(&u.value);
            (u.name.clone(), u.kind.words(value))
        })
        .collect()
}

/// `[fovy (degrees), aspect, near, far]` of the view volume: `fovy = 2·atan((t − b)/(2·near))`,
/// `aspect = (r − l)/(t − b)` (for an off-centre or parallel volume, those of its extent).
fn lens(projection: &crate::camera::Projection, settings: &RenderSettings) -> [f32; 4] {
    let [l, r, b, t, near, far] =
        projection.bounds(settings.width as f32 / settings.height.max(1) as f32);
    let fovy = 2.0 * ((t - b) / (2.0 * near)).atan().to_degrees();
    [fovy, (r - l) / (t - b), near, far]
}

/// The textures a program's samplers read and how each is sampled: the object's texture with
/// `surface` (the settings' sampler), its bump or normal map as the built-in bump mapping reads
/// it and its displacement map as the built-in displacement does (both bilinear, repeating,
/// level 0) — nothing of those without texture coordinates — and the cube map it mirrors.
fn textures<'a>(
    program: &shader::Program,
    object: &'a Object,
    surface: crate::texture::Sampler,
) -> Vec<Option<shader::Bound<'a>>> {
    use crate::texture::SurfaceDetail;
    use shader::Bound;
    let has_uvs = !object.mesh.uvs.is_empty();
    program
        .textures
        .iter()
        .map(|name| match shader::interface::texture_slot(name)? {
            TextureSlot::Environment => Some(Bound::Cube(&object.environment.as_ref()?.cube)),
            _ if !has_uvs => None,
            TextureSlot::Surface => Some(Bound::Image(object.texture.as_deref()?, surface)),
            TextureSlot::Detail => match object.detail.as_ref()? {
                SurfaceDetail::Bump { height: t, .. } | SurfaceDetail::Normal(t) => {
                    Some(Bound::Image(t, SurfaceDetail::MAP_SAMPLER))
                }
            },
            TextureSlot::Displacement => object
                .displacement
                .as_ref()
                .map(|d| Bound::Image(&d.height, SurfaceDetail::MAP_SAMPLER)),
        })
        .collect()
}

/// `program`'s run-time error `e` on `object`, at its place — in the file the source stands in,
/// named, when it stands in one.
fn shader_error(program: &shader::Program, object: &Object, e: &shader::RunError) -> RenderError {
    RenderError::Code {
        part: super::CodePart::Shader(program.stage),
        object: object.name.clone(),
        error: Box::new(program.run_error(e)),
        file: program.origin.as_ref().map(|o| o.file.clone()),
    }
}

/// Runs each object's vertex shader over its mesh's vertices, 64 a batch, from the mesh's own
/// attributes. Returns each object's outputs (its `gl_Position` becomes the clip position of
/// its rows when the vertex table is written), or `None` when no object has shaders. `spare`
/// holds the output buffers of the frame before, written over in place.
///
/// # Errors
/// A run-time error of a vertex shader, or a `gl_Position` that is not finite.
pub(super) fn vertex_shaders(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    mut spare: Vec<Vec<f32>>,
) -> Result<Option<Vec<Option<VertexResults>>>, RenderError> {
    if !scene.has_shaders() {
        return Ok(None);
    }
    let mut out = Vec::with_capacity(scene.objects.len());
    let mut first = 0usize;
    for (i, object) in scene.objects.iter().enumerate() {
        let start = first;
        first += object.mesh.positions.len();
        let Some(sh) = &object.code.shader else {
            out.push(None);
            continue;
        };
        let u = uniforms(scene, settings, matrices, i, sh.time);
        let values = spare.pop().unwrap_or_default();
        out.push(Some(run_vertex_shader(
            &sh.programs,
            object,
            settings.max_steps,
            &u,
            start,
            values,
        )?));
    }
    Ok(Some(out))
}

/// Where object `i`'s vertex shader put each vertex's `gl_Position` (`None` when pipelens' own
/// vertex stage transforms it).
pub(super) fn shader_clip<'a>(
    scene: &'a Scene,
    results: Option<&'a [Option<VertexResults>]>,
    i: usize,
) -> Option<vertex::ShaderClip<'a>> {
    let r = results?.get(i)?.as_ref()?;
    let programs = &scene.objects[i].code.shader.as_ref()?.programs;
    Some(vertex::ShaderClip {
        values: &r.values,
        stride: r.stride as usize,
        position: programs.position as usize,
    })
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
    let drawn = as_drawn(scene);
    let scene = drawn.as_ref();
    let Some((i, index)) = row_vertex(scene, capture, row) else {
        return Ok(None);
    };
    let object = &scene.objects[i];
    let Some(sh) = &object.code.shader else {
        return Ok(None);
    };
    let vs = &sh.programs.vertex;
    let run = run_one_vertex(scene, capture, i, index, vs)?;
    let mut at = 0usize;
    let outputs = vs
        .outputs
        .iter()
        .map(|o| {
            let n = o.components as usize;
            let value = lane_value(&run.outputs[at * LANES..], n, 0);
            at += n;
            (o.name.clone(), value)
        })
        .collect();
    Ok(Some(VertexTrace {
        row: row as u32,
        object: object.name.clone(),
        inputs: lane_values(&vs.inputs, run.batch.rows(), 0),
        trace: vs.describe(&run.events),
        outputs,
    }))
}

/// `scene` as the render draws it: its figures and shadows expanded.
fn as_drawn(scene: &Scene) -> std::borrow::Cow<'_, Scene> {
    match scene.expanded() {
        Some((s, _)) => std::borrow::Cow::Owned(s),
        None => std::borrow::Cow::Borrowed(scene),
    }
}

/// Where row `row` of the vertex table comes from in `scene` (expanded): its object, and the
/// vertex's index in that object's mesh.
fn row_vertex(scene: &Scene, capture: &FrameCapture, row: usize) -> Option<(usize, usize)> {
    if row >= capture.vertices.len() {
        return None;
    }
    let mut first = 0usize;
    let (i, object) = scene.objects.iter().enumerate().find(|(_, o)| {
        first += o.mesh.positions.len();
        row < first
    })?;
    Some((i, row - (first - object.mesh.positions.len())))
}

/// One vertex's run, traced: its inputs, its outputs (the batch's rows), what it did, and
/// what its watch last saw (a program compiled with one).
struct VertexRun {
    batch: Batch,
    outputs: Vec<u32>,
    events: Vec<shader::Event>,
    watched: Option<shader::probe::Watched>,
}

/// Vertex `index` of object `i` through `program` (the object's vertex shader, or it compiled
/// with a watch), alone in lane 0, traced.
fn run_one_vertex(
    scene: &Scene,
    capture: &FrameCapture,
    i: usize,
    index: usize,
    program: &shader::Program,
) -> Result<VertexRun, RenderError> {
    let object = &scene.objects[i];
    let time = object.code.shader.as_ref().map_or(0.0, |sh| sh.time);
    let u = uniforms(scene, &capture.settings, &capture.matrices, i, time);
    let mut m = program.machine();
    m.budget = capture.settings.max_steps;
    program.set_uniforms(&mut m, &u);
    let mut batch = Batch::new(program);
    batch.start(1);
    for (input, rows) in program.inputs.iter().zip(batch.rows_mut()) {
        let location = shader::interface::attribute_location(&input.name);
        write_inputs(rows, input, location, object, index, 1);
    }
    let tex = textures(program, object, crate::texture::Sampler::default());
    let bindings = Bindings { textures: &tex };
    m.trace_lane(Some(0));
    let ran = m
        .run_batch(&batch, &bindings)
        .map_err(|e| shader_error(program, object, &e))?;
    let outputs = ran.rows().to_vec();
    let watched = program.watch.as_ref().and_then(|w| ran.watched(w, 0));
    let events = m.take_trace();
    Ok(VertexRun {
        batch,
        outputs,
        events,
        watched,
    })
}

/// Lane `lane`'s value of a varying of `components` floats, rows `LANES` apart, as GLSL writes
/// it: `0.500` or `vec3(0.000, 0.707, 0.707)`.
pub(super) fn lane_value(rows: &[u32], components: usize, lane: usize) -> String {
    let v: Vec<String> = (0..components)
        .map(|c| shader::float_text(f32::from_bits(rows[c * LANES + lane])))
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
        .map(|(v, r)| {
            let value = match v.builtin {
                Some(naga::BuiltIn::FrontFacing) => (r[lane] != 0).to_string(),
                Some(naga::BuiltIn::VertexIndex | naga::BuiltIn::InstanceIndex) => {
                    r[lane].to_string()
                }
                _ => lane_value(r, v.components as usize, lane),
            };
            (v.name.clone(), value)
        })
        .collect()
}

/// Writes vertex shader input `input` of mesh vertices `first .. first + n` into lanes
/// `0 .. n` of its rows: `gl_VertexIndex` is the vertex's index, an attribute its value at
/// `location` (see [`shader::interface::ATTRIBUTES`]; a component the attribute lacks is 0, and
/// the fourth 1, as OpenGL fills a vec4 from a vec3).
fn write_inputs(
    rows: &mut [u32],
    input: &shader::Varying,
    location: Option<u32>,
    object: &Object,
    first: usize,
    n: usize,
) {
    let mesh = &object.mesh;
    let components = input.components as usize;
    let mut put = |l: usize, v: [f32; 3]| {
        for (c, x) in [v[0], v[1], v[2], 1.0]
            .into_iter()
            .enumerate()
            .take(components)
        {
            rows[c * LANES + l] = x.to_bits();
        }
    };
    if input.builtin == Some(naga::BuiltIn::VertexIndex) {
        for (l, r) in rows[..n].iter_mut().enumerate() {
            *r = (first + l) as u32;
        }
        return;
    }
    for l in 0..n {
        let i = first + l;
        let v = match location {
            // The mesh's own position: a vertex shader displaces it itself (pipelens.vert
            // does, with `displacement` and `displacement_scale`).
            Some(0) => mesh.positions[i].to_array(),
            Some(1) => mesh
                .normals
                .get(i)
                .copied()
                .unwrap_or(Vec3::ZERO)
                .to_array(),
            Some(2) => mesh.uvs.get(i).map_or([0.0; 3], |uv| [uv.x, uv.y, 0.0]),
            Some(3) => vertex::vertex_color(object, i).to_array(),
            _ => [0.0; 3],
        };
        put(l, v);
    }
}

/// One object's vertex shader over its mesh: every output of every vertex in `values` (a buffer
/// to reuse); a `gl_Position` that is not finite drops its primitives at assembly
/// ([`crate::capture::Fate::NotFinite`]). `first` is the object's first row in
/// the vertex table; a vertex's loops may run `max_steps` iterations.
fn run_vertex_shader(
    programs: &Programs,
    object: &Object,
    max_steps: u32,
    u: &Uniforms,
    first: usize,
    mut values: Vec<f32>,
) -> Result<VertexResults, RenderError> {
    let vs = &programs.vertex;
    let count = object.mesh.positions.len();
    let stride = vs.outputs.iter().map(|o| o.components).sum::<u32>() as usize;
    // Every value is written below: only new room needs filling.
    values.truncate(count * stride);
    values.resize(count * stride, 0.0);
    let tex = textures(vs, object, crate::texture::Sampler::default());
    let locations: Vec<Option<u32>> = vs
        .inputs
        .iter()
        .map(|i| shader::interface::attribute_location(&i.name))
        .collect();
    // Each batch's watch, when the shader watches (none kept otherwise).
    let watched: Vec<Vec<Option<shader::probe::Watched>>> = values
        .par_chunks_mut(LANES * stride.max(1))
        .enumerate()
        .map_init(
            || {
                let mut m = vs.machine();
                m.budget = max_steps;
                vs.set_uniforms(&mut m, u);
                (m, Batch::new(vs))
            },
            |(m, batch), (k, results)| {
                let start = k * LANES;
                let n = (count - start).min(LANES);
                batch.start(n);
                for ((input, rows), location) in
                    vs.inputs.iter().zip(batch.rows_mut()).zip(&locations)
                {
                    write_inputs(rows, input, *location, object, start, n);
                }
                let bindings = Bindings { textures: &tex };
                let ran = m
                    .run_batch(batch, &bindings)
                    .map_err(|e| shader_error(vs, object, &e))?;
                for (l, out) in results.chunks_exact_mut(stride).enumerate() {
                    for (c, v) in out.iter_mut().enumerate() {
                        *v = ran.output(c, l);
                    }
                }
                Ok(vs
                    .watch
                    .as_ref()
                    .map(|places| (0..n).map(|l| ran.watched(places, l)).collect())
                    .unwrap_or_default())
            },
        )
        .collect::<Result<_, RenderError>>()?;
    Ok(VertexResults {
        first: first as u32,
        stride: stride as u32,
        values,
        watch: watched.concat(),
    })
}
