//! A run the frame kept, run again with a program compiled with a watch
//! (`shader::probe::watch`) in place of its object's own: the debugger's watch list reads an
//! expression after a line in the very run it steps through — the inspected fragment with its
//! quad's inputs as the frame interpolated them, or the selected vertex with its attributes,
//! each with its object's uniforms and textures. The watched program runs the same statements
//! (the watch only stores), so the steps of its trace are those of the run the debugger shows.

use super::{
    Batch, Bindings, RenderError, Scene, as_drawn, row_vertex, run_one_vertex, shader_error,
};
use super::{textures, uniforms};
use crate::capture::{FragmentTrace, FrameCapture};
use crate::shader::Program;

/// Why a run could not be run again with a watch.
#[derive(Debug)]
pub enum ReplayError {
    /// The frame kept no way to run it again (nothing is inspected there, or the run is not a
    /// shader's of the student's).
    NotKept,
    /// The expression reads an input the shader does not declare (and so the frame did not
    /// interpolate): its name.
    Input(String),
    /// The run stopped (an endless loop, an index out of range).
    Run(RenderError),
}

impl std::fmt::Display for ReplayError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NotKept => write!(f, "the frame kept no run to read the watch in"),
            Self::Input(name) => write!(
                f,
                "it reads `{name}`, which the shader does not declare: the frame did not interpolate it"
            ),
            Self::Run(e) => write!(f, "{e}"),
        }
    }
}

/// Each value `program` (the fragment shader of `trace`'s object compiled with a watch) stores,
/// when the fragment of `trace` runs again with it: the number of steps of the run before the
/// store, and the value's components (see `Program::watched_values`). `scene` is the scene
/// `capture` was drawn from.
///
/// # Errors
/// No run kept, an input the frame did not interpolate, or the run stopped.
pub fn watch_fragment(
    scene: &Scene,
    capture: &FrameCapture,
    trace: &FragmentTrace,
    program: &Program,
) -> Result<Vec<(usize, [f32; 4])>, ReplayError> {
    let replay = trace.replay.as_ref().ok_or(ReplayError::NotKept)?;
    let drawn = as_drawn(scene);
    let scene = drawn.as_ref();
    let object = scene
        .objects
        .get(replay.object)
        .ok_or(ReplayError::NotKept)?;
    let sh = object.code.shader.as_ref().ok_or(ReplayError::NotKept)?;
    let kept = &replay.batch;
    let mut batch = Batch::new(program);
    batch.start(kept.lanes());
    for lane in 0..kept.lanes() {
        if kept.live() & (1 << lane) == 0 {
            batch.helper(lane);
        }
    }
    for (input, rows) in program.inputs.iter().zip(batch.rows_mut()) {
        let from = replay
            .inputs
            .iter()
            .position(|v| v.name == input.name && v.builtin == input.builtin)
            .ok_or_else(|| {
                ReplayError::Input(match input.builtin {
                    // The fragment stage's position is GLSL's gl_FragCoord.
                    Some(naga::BuiltIn::Position { .. }) => "gl_FragCoord".to_owned(),
                    _ => input.name.clone(),
                })
            })?;
        rows.clone_from(&kept.rows()[from]);
    }
    let u = uniforms(
        scene,
        &capture.settings,
        &capture.matrices,
        replay.object,
        sh.time,
    );
    let mut m = program.machine();
    m.budget = capture.settings.max_steps;
    program.set_uniforms(&mut m, &u);
    let tex = textures(program, object, capture.settings.sampler);
    let bindings = Bindings { textures: &tex };
    m.trace_lane(Some(replay.lane));
    m.run_batch(&batch, &bindings)
        .map_err(|e| ReplayError::Run(shader_error(program, object, &e)))?;
    Ok(program.watched_values(&m.take_trace()))
}

/// [`watch_fragment`] for the vertex of row `row` of the vertex table: each value `program`
/// (its object's vertex shader compiled with a watch) stores when the vertex runs again.
///
/// # Errors
/// No such row or no shader of the student's there, or the run stopped.
pub fn watch_vertex(
    scene: &Scene,
    capture: &FrameCapture,
    row: usize,
    program: &Program,
) -> Result<Vec<(usize, [f32; 4])>, ReplayError> {
    let drawn = as_drawn(scene);
    let scene = drawn.as_ref();
    let (i, index) = row_vertex(scene, capture, row).ok_or(ReplayError::NotKept)?;
    if scene.objects[i].code.shader.is_none() {
        return Err(ReplayError::NotKept);
    }
    let run = run_one_vertex(scene, capture, i, index, program).map_err(ReplayError::Run)?;
    Ok(program.watched_values(&run.events))
}
