//! `render`: the stages in order, each recording into the [`FrameCapture`].
//!
//! vertex stage → primitive assembly → clipping → perspective division and viewport →
//! triangle setup (culling) → rasterization with the depth test → resolve to pixels.
//!
//! The order and the vertex stage's call are here; primitive assembly, clipping, division,
//! viewport, setup and flat shading's face lighting in [`assembly`]; rasterization with the depth
//! test, pipelens' own or the student's, in [`rasterization`]; the resolve of samples to pixels
//! (colour, lighting terms, texture lookups) in [`resolve`](mod@resolve); the storage a frame is
//! written into, a capture no longer shown, in [`storage`].

mod assembly;
mod coarse;
#[cfg(test)]
mod fixtures;
mod inspected;
mod pixel_samples;
mod rasterization;
mod resolve;
mod runs;
mod storage;
mod student_geometry;
mod student_shaders;
pub use student_shaders::{ReplayError, WatchRun, trace_vertex, watch_fragment, watch_vertex};

use std::time::Duration;

use web_time::Instant;

use serde::Serialize;

use self::assembly::{assemble_and_clip, light_faces};
use self::rasterization::rasterize;
use self::resolve::{ResolveContext, resolve};
use self::storage::Storage;
use crate::capture::{FrameCapture, Matrices, ObjectSummary};
use crate::lighting::{Frequency, ShadeTerms};
use crate::scene::{Object, Scene};
use crate::settings::RenderSettings;
use crate::transform::{self, NamedMatrix};
use crate::vertex::{self, VertexMatrices, VertexRecord};

/// Why a frame cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The scene or the settings are invalid: each problem.
    #[error("the scene cannot be drawn: {}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("; "))]
    Invalid(Vec<crate::scene::SceneProblem>),
    /// The student's `shadow_matrix(light)` returned a matrix with a NaN or infinite entry.
    #[error(
        "the scene cannot be drawn: shadow_matrix(vec3({}, {}, {})) returned a matrix that is not finite (a division by zero?): {matrix}",
        light.x, light.y, light.z
    )]
    ShadowMatrix {
        /// The light relative to the plane it was called with.
        light: glam::Vec3,
        /// What it returned.
        matrix: glam::Mat4,
    },
    /// The student's code stopped while it ran on an object (an endless loop, an index out of
    /// range, …): which code, the object, and the message at its line (its complaint as data,
    /// for the interface to say in its language).
    #[error("the scene cannot be drawn: {} of {object}, {}{error}", part.name(), file.as_deref().map(|f| format!("{f}, ")).unwrap_or_default())]
    Code {
        /// Which code.
        part: CodePart,
        /// The object it ran on.
        object: String,
        /// What stopped it, where (boxed: a frame's `Result` stays small).
        error: Box<crate::shader::ShaderError>,
        /// The file the error's line and column are in, when the code stands in one (a shader
        /// file, or a lesson's inline GLSL: [`crate::shader::Origin`]).
        file: Option<String>,
    },
}

/// Which of the student's code a [`RenderError::Code`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CodePart {
    /// A vertex or fragment shader.
    Shader(crate::shader::Stage),
    /// A function the pipeline calls: the rasterizer's `inside()`, the depth test, a Bézier
    /// curve's or patch's point, the shadow matrix.
    Function(crate::shader::HookKind),
}

impl CodePart {
    /// Its name in English: `fragment shader`, `inside`, `de_casteljau`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Shader(crate::shader::Stage::Vertex) => "vertex shader",
            Self::Shader(crate::shader::Stage::Fragment) => "fragment shader",
            Self::Function(kind) => match kind {
                crate::shader::HookKind::Inside => "inside test",
                crate::shader::HookKind::DepthTest => "depth test",
                crate::shader::HookKind::Curve => "de_casteljau()",
                crate::shader::HookKind::ShadowMatrix => "shadow_matrix()",
                crate::shader::HookKind::Patch => "bezier_patch()",
            },
        }
    }
}

/// Wall-clock time spent in each stage of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StageTimes {
    /// Vertex stage (all transforms).
    pub vertex: Duration,
    /// Primitive assembly, clipping, division, viewport and triangle setup.
    pub clip_setup: Duration,
    /// Rasterization and the depth test. Where a frame is rasterized and resolved band by
    /// band, the two run together: this is their wall time less the resolve's share.
    pub raster: Duration,
    /// Resolve of samples to pixels (barycentrics, colour). Band by band, its share of the
    /// two's wall time: the bands' resolves timed, summed, divided by the cores.
    pub resolve: Duration,
}

impl StageTimes {
    /// The whole frame.
    #[must_use]
    pub fn total(&self) -> Duration {
        self.vertex + self.clip_setup + self.raster + self.resolve
    }
}

/// Renders one frame and records every stage. A pure function of its inputs.
///
/// # Errors
/// [`RenderError::Invalid`] listing every problem with the scene or the settings.
pub fn render(scene: &Scene, settings: &RenderSettings) -> Result<FrameCapture, RenderError> {
    render_timed(scene, settings).map(|(c, _)| c)
}

/// [`render`], also returning how long each stage took.
///
/// # Errors
/// As [`render`].
pub fn render_timed(
    scene: &Scene,
    settings: &RenderSettings,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    render_reusing(scene, settings, None)
}

/// [`render_timed`], writing the per-pixel and per-sample buffers into the storage of `spare`,
/// a capture no longer needed (the frame before). A full capture is tens to hundreds of
/// megabytes; memory fresh from the system costs a page fault and a zeroing every 4 KiB before
/// the pipeline writes a byte of it, which reusing storage avoids. The result is the same.
///
/// # Errors
/// As [`render`].
pub fn render_reusing(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<FrameCapture>,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    render_by(scene, settings, spare, Path::Fast)
}

/// [`render`] with every pixel resolved by the reference path alone: each pixel by itself,
/// its fragments shaded one by one ([`ResolveContext::pixel`]) — no background spans, no runs
/// of fragments lit together in lanes, no coarse runs (coarse shading's 2×2 blocks are still
/// shared: they are what it draws). The fast paths give the same bits in every buffer the
/// frame keeps; this is what tests compare them with.
///
/// # Errors
/// As [`render`].
pub fn render_reference(
    scene: &Scene,
    settings: &RenderSettings,
) -> Result<FrameCapture, RenderError> {
    render_by(scene, settings, None, Path::Reference).map(|(c, _)| c)
}

/// Which way the resolve takes (see [`render_reference`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Path {
    /// Background spans, runs lit in lanes, coarse runs: what a frame is drawn with.
    Fast,
    /// Every pixel by itself.
    Reference,
}

/// [`render_reusing`] with the resolve taking `path`.
fn render_by(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<FrameCapture>,
    path: Path,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    let problems = scene.problems(settings);
    if !problems.is_empty() {
        return Err(RenderError::Invalid(problems));
    }
    if let Some(drawn) = student_geometry::with_student_curves(scene, settings.max_steps)? {
        return render_by(&drawn, settings, spare, path);
    }
    if let Some(drawn) = student_geometry::with_student_shadow(scene, settings.max_steps)? {
        return render_by(&drawn, settings, spare, path);
    }
    if let Some((expanded, steps)) = scene.expanded() {
        return render_stages(&expanded, settings, spare, path).map(|(mut c, t)| {
            c.hierarchy = steps;
            (c, t)
        });
    }
    render_stages(scene, settings, spare, path)
}

/// The stages, in order, over a scene whose figures and shadows are already plain objects.
fn render_stages(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<FrameCapture>,
    path: Path,
) -> Result<(FrameCapture, StageTimes), RenderError> {
    let mut storage = Storage::of(spare);
    let matrices = frame_matrices(scene, settings)?;
    let mut times = StageTimes::default();

    let t = Instant::now();
    let (mut vertices, mut vertex_shading) = (storage.vertices, storage.vertex_shading);
    // The student's vertex shaders first: the table's rows take their gl_Position.
    let vertex_results =
        student_shaders::vertex_shaders(scene, settings, &matrices, storage.shader_outputs)?;
    vertex_stage(
        scene,
        settings,
        &matrices,
        vertex_results.as_deref(),
        &mut vertices,
        &mut vertex_shading,
    );
    times.vertex = t.elapsed();

    let t = Instant::now();
    let (mut primitives, mut triangles) = (storage.primitives, storage.triangles);
    assemble_and_clip(
        scene,
        settings,
        &matrices,
        &vertices,
        &mut primitives,
        &mut triangles,
    );
    let mut face_shading = storage.face_shading;
    if settings.shading == Frequency::Flat {
        light_faces(scene, settings, &vertices, &primitives, &mut face_shading);
    }
    times.clip_setup = t.elapsed();

    let in_bands = drawn_in_bands(scene, path, vertex_results.is_some());
    let spare = (storage.samples.take(), storage.pixels);
    let frame = student_shaders::Frame {
        scene,
        settings,
        matrices: &matrices,
        triangles: &triangles,
        primitives: &primitives,
        vertices: &vertices,
        vertex_shading: &vertex_shading,
        face_shading: &face_shading,
    };
    let (mut samples, pixels, covered, shaders, hooked) = if in_bands {
        let (samples, pixels, covered) = draw_in_bands(&frame, spare, &mut times);
        (samples, pixels, covered, None, None)
    } else {
        let t = Instant::now();
        let (mut samples, hooked) = rasterize(scene, settings, spare.0, &triangles, &primitives)?;
        times.raster = t.elapsed();
        // Fragments a shader discards are taken out of the depth test, layer by layer.
        let mut peeled = student_shaders::Peeled::default();
        if let Some(results) = &vertex_results {
            peeled = student_shaders::peel_discarded(&frame, results, &mut samples)?;
        }
        let t = Instant::now();
        let ctx = frame.context(path, samples.rows());
        let (mut pixels, covered) = resolve(&ctx, spare.1);
        let shaders =
            student_shaders::record(&ctx, &matrices, vertex_results, &mut pixels.color, peeled)?;
        times.resolve = t.elapsed();
        (samples, pixels, covered, shaders, hooked)
    };
    // Each primitive's counts, from its raster triangles', written once the resolve (which
    // reads the records) is done with them.
    let t = Instant::now();
    rasterization::record_counts(
        &mut primitives,
        hooked.as_deref().unwrap_or(samples.drawn()),
    );
    times.raster += t.elapsed();
    // The next frame drawn into this storage clears only what this one covered.
    samples.covered.0 = Some(covered);

    let labels = matrices.screen_labels(&scene.objects, settings.width, settings.height);
    let capture = FrameCapture {
        settings: *settings,
        camera: scene.camera,
        projection: scene.projection,
        lights: scene.lights.clone(),
        objects: object_summaries(scene),
        matrices,
        vertices,
        vertex_shading,
        face_shading,
        hierarchy: Vec::new(),
        textures: by_object(scene, |o| o.texture.clone()),
        cubes: by_object(scene, |o| o.environment.as_ref().map(|e| e.cube.clone())),
        primitives,
        triangles,
        samples,
        pixels,
        labels,
        shaders,
    };
    Ok((capture, times))
}

/// Whether a frame is rasterized and resolved band by band, shading right after coverage
/// ([`draw_in_bands`]): wherever nothing between the two reads or changes the whole image's
/// samples — no student's inside or depth test (drawn triangle after triangle), no student's
/// shader (whose discards are peeled from the whole image before the resolve) — on the fast
/// paths (the reference path is what the bands are checked against).
fn drawn_in_bands(scene: &Scene, path: Path, shaders: bool) -> bool {
    path == Path::Fast && !shaders && !rasterization::has_hooks(scene)
}

/// Rasterization with the depth test and the resolve, band by band
/// ([`resolve::rasterize_and_resolve`]), into `spare`'s storage; the inspected pixel's terms
/// and lookup after them (they read every row). What each triangle drew is left in the
/// samples ([`crate::raster::SampleBuffers::drawn`]).
fn draw_in_bands(
    frame: &student_shaders::Frame<'_>,
    spare: (
        Option<crate::raster::SampleBuffers>,
        crate::capture::PixelBuffers,
    ),
    times: &mut StageTimes,
) -> (
    crate::raster::SampleBuffers,
    crate::capture::PixelBuffers,
    crate::raster::CoveredRows,
) {
    let (settings, path) = (frame.settings, Path::Fast);
    let t = Instant::now();
    let mut samples = rasterization::cleared_samples(settings, spare.0);
    let cleared = t.elapsed();
    let ctx = frame.context(path, crate::raster::SampleRows::default());
    let (mut pixels, covered, [raster, resolving]) =
        resolve::rasterize_and_resolve(&ctx, &mut samples, spare.1);
    let t = Instant::now();
    pixels.inspected = resolve::inspected(&frame.context(path, samples.rows()), &pixels);
    times.raster = cleared + raster;
    times.resolve = resolving + t.elapsed();
    (samples, pixels, covered)
}

impl<'a> student_shaders::Frame<'a> {
    /// What the resolve reads of this frame: its records and `samples`, taking `path`.
    fn context(&self, path: Path, samples: crate::raster::SampleRows<'a>) -> ResolveContext<'a> {
        ResolveContext {
            path,
            derivatives: self.settings.capture.texturing || self.settings.sampler.uses_footprint(),
            scene: self.scene,
            settings: self.settings,
            samples,
            triangles: self.triangles,
            primitives: self.primitives,
            vertices: self.vertices,
            vertex_shading: self.vertex_shading,
            face_shading: self.face_shading,
        }
    }
}

/// What a sample of the colour buffer keeps of a fragment's colour: each channel clamped to
/// [0, 1], as a fixed-point colour buffer stores it (OpenGL 3.3 §4.1.8: colours are clamped
/// before they are written to a fixed-point buffer). Multisampling averages the samples *after*
/// this, so a pixel on an edge whose fragment is brighter than white resolves to
/// `covered/samples`·white, not more.
#[must_use]
pub(super) fn stored_color(c: glam::Vec3) -> glam::Vec3 {
    c.clamp(glam::Vec3::ZERO, glam::Vec3::ONE)
}

/// What `of` finds on each object that has it, with the object's name: the textures and the
/// cube maps a frame read.
fn by_object<T>(scene: &Scene, of: impl Fn(&Object) -> Option<T>) -> Vec<(String, T)> {
    scene
        .objects
        .iter()
        .filter_map(|o| of(o).map(|t| (o.name.clone(), t)))
        .collect()
}

/// What the capture says of each object: its name, mesh, size, material and surface.
fn object_summaries(scene: &Scene) -> Vec<ObjectSummary> {
    scene
        .objects
        .iter()
        .map(|o| ObjectSummary {
            name: o.name.clone(),
            mesh: o.mesh.name.clone(),
            vertices: o.mesh.positions.len(),
            triangles: o.mesh.indices.len(),
            material: o.material,
            lit: o.lit,
            texture: o
                .texture
                .as_ref()
                .filter(|_| !o.mesh.uvs.is_empty())
                .map(|t| t.name.clone()),
            detail: o.detail.is_some(),
            reflectivity: o.environment.as_ref().map(|e| e.reflectivity),
        })
        .collect()
}

/// The vertex stage: every vertex of every object through every space, in order, with its
/// lighting when shading is per vertex, appended to `vertices` and `vertex_shading`; an object
/// with a vertex shader takes its clip positions from `shader_results`.
fn vertex_stage(
    scene: &Scene,
    settings: &RenderSettings,
    matrices: &Matrices,
    shader_results: Option<&[Option<crate::capture::VertexResults>]>,
    vertices: &mut Vec<VertexRecord>,
    vertex_shading: &mut Vec<ShadeTerms>,
) {
    for (i, object) in scene.objects.iter().enumerate() {
        let m = VertexMatrices {
            model: matrices.models[i].matrix,
            view: matrices.view.matrix,
            projection: matrices.projection.matrix,
            viewport: matrices.viewport.matrix,
        };
        let lighting = vertex::VertexLighting {
            frequency: settings.shading,
            reflection: settings.reflection,
            lights: &scene.lights,
            eye: scene.camera.eye,
        };
        let shader = student_shaders::shader_clip(scene, shader_results, i);
        vertex::transform_object(
            object,
            i as u32,
            &m,
            &lighting,
            shader,
            vertices,
            vertex_shading,
        );
    }
}

/// The frame's matrices: models, view, both courses' projections, viewport.
fn frame_matrices(scene: &Scene, settings: &RenderSettings) -> Result<Matrices, RenderError> {
    let view = scene
        .view_matrix()
        .map_err(|e| RenderError::Invalid(vec![e.into()]))?;
    let aspect = settings.aspect();
    Ok(Matrices {
        models: scene.objects.iter().map(|o| o.model_matrix()).collect(),
        projection: scene.projection.matrix(aspect),
        projection_games101: scene.projection.matrix_games101(aspect),
        viewport: NamedMatrix::new(
            "M_viewport",
            "x_w = (x+1)·width/2, y_w = (y+1)·height/2, z_w = (z+1)/2",
            transform::viewport(settings.width as f32, settings.height as f32),
        ),
        view,
    })
}
