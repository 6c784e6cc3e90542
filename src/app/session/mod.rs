//! The app's state with no egui: the session itself, the predictable step rule and the render
//! jobs (`state.rs`); the commands panels return, applied kind by kind (`apply.rs`); what the
//! current step teaches (`teaching.rs`); an exercise step's reference render and the code kept
//! (`exercise.rs`), that reference and its findings (`reference.rs`); the finer render the
//! session asks of its view (`view_resolution.rs`).

mod apply;
mod exercise;
mod reference;
mod state;
mod teaching;
mod view_resolution;

pub use crate::app::command::{
    Command, EditorCommand, LessonCommand, SceneCommand, SelectionCommand, ViewCommand,
};
pub use crate::app::player::LessonPlayer;
pub use crate::app::selection::{DepthView, Selection};
pub use reference::Comparison;
pub use state::{Session, source_name};
pub use teaching::Teaching;
