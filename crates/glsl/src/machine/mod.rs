//! Runs a program in register form ([`super::register_form`]) over a batch of up to [`LANES`]
//! invocations at once, as a GPU runs a warp: every expression is evaluated for all lanes, and
//! a *mask* (one bit a lane) says which lanes a statement applies to. An `if` runs its two
//! branches with the lanes whose condition holds and the others; a loop runs until every lane
//! has left it; `break`, `continue`, `return` and `discard` take their lanes out of the mask.
//!
//! Fragments come in 2×2 quads (lanes `4q` … `4q + 3`: top-left, top-right, bottom-left,
//! bottom-right), so `dFdx(v) = v(x+1, y) − v(x, y)` is a difference within the quad, and
//! `texture()` takes its level of detail from the quad's differences of the coordinates.
//!
//! A step budget stops endless loops: each lane may run at most [`Machine::budget`] loop
//! iterations in one invocation.

mod call;
mod eval;
mod events;
mod run;
mod statements;
mod texture;
mod textures;

pub use crate::lanes::LANES;
pub use events::{Event, RunError};
pub use run::{DEFAULT_MAX_STEPS, Machine};
pub use textures::{Texel, Textures};
