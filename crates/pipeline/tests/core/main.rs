//! Tests of the core pipeline against independent references: the OpenGL reference pages, glam,
//! the course notes' formulas and values computed by hand.

mod bezier;
mod builtin_list;
mod camera;
mod capture;
mod capture_views;
mod clip;
mod colour_buffer;
mod detail;
mod explain;
mod frame;
mod glsl_rules;
mod hierarchy;
mod hooks;
mod implicit;
mod lighting;
mod normals;
mod own_uniforms;
mod parameters;
mod projection;
mod properties;
mod raster;
mod ripmap_sat_ewa;
mod sampling;
mod shader;
mod shader_errors;
mod shader_frame;
mod shader_frame_trace;
mod shader_replay;
mod shader_watch;
mod support;
mod texture;
mod texture_calls;
mod transform;
