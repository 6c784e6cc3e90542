//! The pipelens core: a software implementation of the real-time graphics pipeline that records
//! what every stage does, so that it can be shown, exported and tested.
//!
//! Data flows one way: a [`Scene`](scene::Scene) and [`RenderSettings`](scene::RenderSettings)
//! go into [`render`], which returns a [`FrameCapture`](capture::FrameCapture). The modules follow
//! the stages in the order data flows through them:
//!
//! | module | stage |
//! |---|---|
//! | [`transform`] | every matrix of the course, with its formula |
//! | [`mesh`], [`scene`], [`hierarchy`] | what is drawn: meshes, objects, figures, camera, projection, settings |
//! | [`vertex`] | model → world → eye → clip → NDC → window, per vertex |
//! | [`clip`] | clipping in homogeneous clip space |
//! | [`raster`] | edge functions, top-left rule, multisampling, depth test, barycentrics |
//! | [`shade`] | Phong / Blinn-Phong terms, lights, attenuation, shading frequencies |
//! | [`texture`] | samplers, mipmaps, level of detail, trilinear and anisotropic filtering |
//! | [`capture`] | the record of a frame and its images |
//! | [`overlay`] | 2-D shapes over the images |

pub mod bezier;
pub mod capture;
pub mod clip;
pub mod hierarchy;
pub mod mesh;
pub mod overlay;
pub mod raster;
mod render;
pub mod scene;
pub mod shade;
pub mod texture;
pub mod transform;
pub mod vertex;

pub use render::{RenderError, StageTimes, render, render_reusing, render_timed};
