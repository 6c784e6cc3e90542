//! naga's IR translated into the register form of [`super::register_form`]: registers laid out
//! expression by expression, pointers followed to their places, constants evaluated, and every
//! operation checked to be one the machine runs.

mod statements;
mod texture;
mod translator;

pub use translator::{FLOAT_MODULO, Translator};
