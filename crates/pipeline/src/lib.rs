//! The pipelens core: a software implementation of the real-time graphics pipeline that records
//! what every stage does, so that it can be shown, exported and tested.
//!
//! Data flows one way: a [`Scene`](scene::Scene) and [`RenderSettings`](settings::RenderSettings)
//! go into [`render()`], which returns a [`FrameCapture`](capture::FrameCapture). The modules are
//! listed in the order data flows through them; each uses only those above it:
//!
//! | module | stage |
//! |---|---|
//! | [`grid`] | window positions (y up) against image rows (top first), one way |
//! | [`transform`] | every matrix of the course, with its formula |
//! | [`bezier`], [`mesh`] | Bézier curves; meshes from OBJ files and built-in shapes |
//! | [`texture`] | textures and their mip pyramids, samplers, surface detail |
//! | [`camera`], [`light`] | the camera and projection; lights and materials |
//! | [`raster`] | edge functions, top-left rule, sample patterns, the z-buffer and depth test |
//! | [`lighting`] | Phong / Blinn-Phong terms, attenuation, shading frequencies |
//! | [`shader`] | the student's GLSL: the engine crate `pipelens-glsl` (adapted, parsed and validated by naga, run on the CPU), with the uniforms' values, the textures bound, pipelens' shading modes and the student's pipeline functions |
//! | [`buffers`], [`settings`] | which per-pixel buffers there are and are kept; the render settings |
//! | [`hierarchy`], [`scene`] | articulated figures; what is drawn |
//! | [`vertex`], [`clip`] | model → world → eye → clip → NDC → window per vertex; clipping |
//! | [`overlay`] | 2-D shapes over the images |
//! | [`capture`] | the record of a frame and its images |
//! | `render` | the stages in order ([`render()`]) |

pub mod bezier;
pub mod buffers;
pub mod camera;
pub mod capture;
pub mod clip;
pub mod grid;
pub mod hierarchy;
pub mod light;
pub mod lighting;
pub mod mesh;
pub mod overlay;
pub mod raster;
mod render;
pub mod scene;
pub mod settings;
pub mod shader;
pub mod texture;
pub mod transform;
pub mod vertex;

pub use render::{
    CodePart, RenderError, ReplayError, StageTimes, WatchRun, render, render_reference,
    render_reusing, render_timed, trace_vertex, watch_fragment, watch_vertex,
};
