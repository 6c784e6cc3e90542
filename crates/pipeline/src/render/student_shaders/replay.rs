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
use crate::shader::probe::{self, WatchError, WatchKind};

/// What a watch saw in one run: the value's type (`None`: the run never ran the line) and each
/// store, after how many of the run's steps (the value stands from that step on) and the
/// value's components first.
#[derive(Clone, Debug, PartialEq)]
pub struct WatchRun {
    /// The value's type.
    pub kind: Option<WatchKind>,
    /// Each store: the steps before it, the value.
    pub stores: Vec<(usize, [f32; 4])>,
}

/// Why a run could not be run again with a watch.
#[derive(Debug)]
pub enum ReplayError {
    /// The frame kept no way to run it again (nothing is inspected there, or the run is not a
    /// shader's of the student's).
    NotKept,
    /// The expression reads an input the shader does not declare (and so the frame did not
    /// interpolate): its name.
    Input(String),
    /// The expression cannot be watched there (a name not in scope, a line that ends no
    /// statement).
    Watch(WatchError),
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
            Self::Watch(e) => write!(f, "{e}"),
            Self::Run(e) => write!(f, "{e}"),
        }
    }
}

/// What `expression` is just after `line` of the fragment shader of `trace`'s object, each
/// time the fragment of `trace` runs that line when it runs again with the shader compiled
/// with that watch. `scene` is the scene `capture` was drawn from.
///
/// # Errors
/// No run kept, an expression that cannot be watched there, an input the frame did not
/// interpolate, or the run stopped.
pub fn watch_fragment(
    scene: &Scene,
    capture: &FrameCapture,
    trace: &FragmentTrace,
    (line, expression): (usize, &str),
) -> Result<WatchRun, ReplayError> {
    let replay = trace.replay.as_ref().ok_or(ReplayError::NotKept)?;
    let drawn = as_drawn(scene);
    let scene = drawn.as_ref();
    let object = scene
        .objects
        .get(replay.object)
        .ok_or(ReplayError::NotKept)?;
    let sh = object.code.shader.as_ref().ok_or(ReplayError::NotKept)?;
    let program = &watched(&sh.programs.fragment, line, expression)?;
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
    let ran = m
        .run_batch(&batch, &bindings)
        .map_err(|e| ReplayError::Run(shader_error(program, object, &e)))?;
    let kind = program
        .watch
        .as_ref()
        .and_then(|w| ran.watched(w, replay.lane))
        .map(|w| w.kind);
    Ok(WatchRun {
        kind,
        stores: program.watched_values(&m.take_trace()),
    })
}

/// [`watch_fragment`] for the vertex of row `row` of the vertex table: each value `expression`
/// has just after `line` of its object's vertex shader when the vertex runs again.
///
/// # Errors
/// No such row or no shader of the student's there, an expression that cannot be watched
/// there, or the run stopped.
pub fn watch_vertex(
    scene: &Scene,
    capture: &FrameCapture,
    row: usize,
    (line, expression): (usize, &str),
) -> Result<WatchRun, ReplayError> {
    let drawn = as_drawn(scene);
    let scene = drawn.as_ref();
    let (i, index) = row_vertex(scene, capture, row).ok_or(ReplayError::NotKept)?;
    let sh = scene.objects[i]
        .code
        .shader
        .as_ref()
        .ok_or(ReplayError::NotKept)?;
    let program = &watched(&sh.programs.vertex, line, expression)?;
    let run = run_one_vertex(scene, capture, i, index, program).map_err(ReplayError::Run)?;
    Ok(WatchRun {
        kind: run.watched.map(|w| w.kind),
        stores: program.watched_values(&run.events),
    })
}

/// `program`'s source compiled with a watch of `expression` just after `line`, its errors
/// placed in the file it stands in.
fn watched(program: &Program, line: usize, expression: &str) -> Result<Program, ReplayError> {
    let mut watched = probe::watch(program.stage, &program.source, line, expression)
        .map_err(ReplayError::Watch)?;
    watched.origin.clone_from(&program.origin);
    Ok(watched)
}
