//! The desktop app (eframe + egui): a stage navigator, the selected stage in the main view, the
//! observer view, the parameters and the inspector. It reads `FrameCapture`s and never computes
//! pipeline results itself.

mod chrome;
pub mod command;
mod compact;
mod editor;
mod export_task;
mod latency;
mod layout;
mod library;
pub mod platform;
mod player;
pub mod progress;
pub mod record;
mod reload;
pub mod selection;
pub mod session;
pub mod shortcuts;
pub mod sizes;
mod start;
mod step_panels;
mod style;
mod toolbar;
pub mod view_resolution;
pub mod views;
mod watched;
mod window;
mod window_size;
pub mod worker;

#[cfg(not(target_arch = "wasm32"))]
pub use start::run;
#[cfg(target_arch = "wasm32")]
pub use start::start;
pub use start::{Start, create, initial_lang};
pub use style::{apply_style, cjk_font, install_fonts, setup_context, target_size};
pub use window::{Panels, PipelensApp};
