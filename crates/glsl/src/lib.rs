//! The GLSL engine of pipelens: shaders the student writes, the vertex and fragment stages as
//! *programs* (GAMES101, lecture 7: "Shader function executes once per fragment"; Angel: the
//! model-view matrix is passed "to the shader").
//!
//! A shader is GLSL as an OpenGL course writes it (`#version 330 core`, plain `uniform`s,
//! `uniform sampler2D tex;`, `in`/`out` without locations; GLSL 1.x's `attribute`, `varying`
//! and `gl_FragColor` too). [`compile()`] adapts it to the GLSL naga reads ([`dialect`]), has naga
//! parse and validate it, checks it against what pipelens provides ([`interface`]), and
//! translates naga's IR once into a register form (the `register_form` module). A [`Program`] then runs on the
//! CPU over batches of invocations ([`Machine`]), reading the textures its host binds
//! ([`Textures`]), and can record what one invocation did, statement by statement ([`Trace`]).
//!
//! Every message points at the student's own line and column.
//!
//! The pipeline (`pipeline::shader`) re-exports this crate and adds what is its own: the
//! uniforms' values for an object, the textures bound per slot, pipelens' shading modes as GLSL
//! and the pipeline functions the student writes.

mod builtins;
mod check;
pub mod complaint;
pub mod dialect;
mod evaluated_once;
pub mod glsl330;
pub mod interface;
mod lanes;
pub mod lexeme;
mod lowering;
mod machine;
mod modulo;
mod ops;
pub mod own_uniform;
pub mod power;
pub mod probe;
mod register_form;
mod stage;
pub mod stepping;
pub mod suggest;
mod trace;
mod translate;
mod type_layout;
mod watched;

mod batch;
mod compile;
mod error;
mod program;

pub use batch::{Batch, Ran, first_lanes};
pub use check::complain;
pub use compile::compile;
pub use complaint::Complaint;
pub use error::{Origin, ShaderError, error_at, line_column};
pub use machine::{DEFAULT_MAX_STEPS, Event, LANES, Machine, RunError, Texel, Textures};
pub use program::{Interpolate, Program, Stage, UniformValues, Varying};
pub use trace::{Step, Trace, TraceLine, Value, float_text, glsl_type};
