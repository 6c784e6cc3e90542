//! The app's state with no egui (`state.rs`: the predictable step rule, the render jobs, the
//! commands applied), what the current step teaches (`teaching.rs`), an exercise step's
//! reference render and its code kept (`exercise.rs`), its reference and findings
//! (`reference.rs`), and the finer render it asks of its view
//! (`fine.rs`).

mod exercise;
mod fine;
mod reference;
mod state;
mod teaching;

pub use crate::app::player::LessonPlayer;
pub use crate::app::selection::{Command, DepthView, Selection};
pub use reference::Comparison;
pub use state::{Session, source_name};
pub use teaching::Teaching;
