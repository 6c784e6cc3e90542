//! Shaders the student writes, in the pipeline: the GLSL engine ([`pipelens_glsl`], re-exported
//! here whole) and what the pipeline adds to it — the uniforms' values for one object
//! ([`Uniforms`]), the textures bound per slot ([`Bindings`]), pipelens' own shading modes
//! shipped as GLSL and a vertex and a fragment shader linked by their varyings ([`link`](mod@link)), and
//! the functions the pipeline calls in place of its own, written by the student ([`hook`]).

mod bindings;
pub mod hook;
pub mod link;
mod uniforms;

pub use bindings::{Bindings, Bound};
pub use hook::{
    At, CURVE_SIGNATURE, CurveDifference, DEPTH_SIGNATURE, Hook, HookKind, Hooks, INSIDE_SIGNATURE,
    InsideTest, PATCH_SIGNATURE, compile_hook, compile_inside,
};
pub use link::{
    BUILTIN_FLAT_FRAGMENT, BUILTIN_FLAT_VERTEX, BUILTIN_FRAGMENT, BUILTIN_GOURAUD_FRAGMENT,
    BUILTIN_GOURAUD_VERTEX, BUILTIN_MIRROR_FRAGMENT, BUILTIN_NORMAL_MAPPED_FRAGMENT,
    BUILTIN_PHONG_FRAGMENT, BUILTIN_UNLIT_FRAGMENT, BUILTIN_VERTEX, Link, Programs,
    SHIPPED_FRAGMENT, SHIPPED_VERTEX, StageError, Surface, builtin_programs, builtin_sources, link,
};
pub use pipelens_glsl::*;
pub use uniforms::Uniforms;
