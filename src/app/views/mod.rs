//! The panels. Each reads the session (and the capture) and returns the commands it wants;
//! none of them computes pipeline results — those come from the `FrameCapture`.

pub mod alt;
pub mod answer;
pub mod breakpoints;
mod buffer_texture;
pub mod card_placement;
pub mod compare;
pub mod debugger;
pub mod exercise;
pub mod geometry;
pub mod glsl_keys;
pub use glsl_keys::KEYS as GLSL_KEYS;
pub mod inspector;
pub mod lesson;
mod matrix;
pub mod navigator;
pub mod observer;
pub mod overlays;
pub mod own_uniforms;
pub mod palette;
pub mod params;
pub mod picture_keys;
pub mod pixels;
pub mod plot_axes;
pub mod plot_legend;
mod projector;
pub mod shader;
mod shader_source;
mod shader_tabs;
pub mod typeset;
pub mod watch_list;
pub mod watch_picture;
mod words;

pub use buffer_texture::{BufferTexture, TermGain};
pub use matrix::{matrix, matrix_grid};
pub use palette::{FATES, fate_color, fate_index};
pub use projector::{Projector, draw_lights};
pub use words::{
    boxed_galley, clear_corner, draw_gain_note, fit_rect, label_with_background, moved_inside,
    picture_font, picture_mono, picture_scale, place_label, wrapped_label,
};
