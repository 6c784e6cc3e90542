//! How the image is produced: its size, the samples per pixel, culling, the depth test,
//! interpolation, the shading frequency and reflection model, the texture sampler, and which
//! buffers to keep; with the limits that keep a capture's memory bounded.

use glam::Vec3;
use serde::Serialize;

use crate::buffers::{CAPTURE_BYTES_PER_SAMPLE, Capture};
use crate::lighting::{Frequency, Reflection};
use crate::raster::{CullMode, DepthTest, Samples};
use crate::texture::Sampler;

/// How the image is produced: size, samples, culling, depth test, interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RenderSettings {
    /// Viewport width in pixels.
    pub width: u32,
    /// Viewport height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub samples: Samples,
    /// Face culling.
    pub cull: CullMode,
    /// Depth comparison.
    pub depth_test: DepthTest,
    /// Interpolate attributes perspective-correctly (`false`: affine in screen space, for comparison).
    pub perspective_correct: bool,
    /// Where lighting is evaluated (unlit: the surface colour as it is).
    pub shading: Frequency,
    /// The specular term: Phong or Blinn-Phong.
    pub reflection: Reflection,
    /// How textures are read.
    pub sampler: Sampler,
    /// Shade every sample at its own position (supersampling) instead of once per pixel and
    /// triangle at the pixel centre (multisampling).
    pub per_sample_shading: bool,
    /// Coarse shading, for drafts (what a GPU's variable-rate shading does at a 2×2 rate): in
    /// each 2×2 block of pixels (image rows 2k, 2k + 1, columns 2j, 2j + 1, resolved top row
    /// first, left to right) the first pixel wholly inside one triangle is shaded, and the
    /// block's other pixels wholly inside that triangle take its colour, lighting terms and
    /// texture lookup; every other pixel is shaded as usual, and the capture's pixel
    /// ([`Capture::pixel`]) by itself. Coverage, depth and owners are unchanged. About a
    /// quarter of the shading; the app's drafts use it while a slider is dragged.
    pub coarse_shading: bool,
    /// The clear colour, linear RGB in `[0, 1]`.
    pub background: Vec3,
    /// Which per-pixel buffers to keep ([`Capture::FULL`]: all of them).
    pub capture: Capture,
    /// The loop iterations one shader invocation may run before the run stops as an endless
    /// loop (`max_steps` of `[scene.render]`; [`DEFAULT_MAX_STEPS`] unless a lesson raises it).
    pub max_steps: u32,
}

/// The loop iterations a shader invocation may run unless the lesson says otherwise (the GLSL
/// engine's own default).
pub use pipelens_glsl::DEFAULT_MAX_STEPS;

/// The most `max_steps` a lesson may ask for: a run of that many iterations per pixel takes
/// minutes, not forever.
pub const MAX_MAX_STEPS: u32 = 1 << 24;

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
            samples: Samples::X1,
            cull: CullMode::None,
            depth_test: DepthTest::Less,
            perspective_correct: true,
            shading: Frequency::Unlit,
            reflection: Reflection::BlinnPhong,
            sampler: Sampler::default(),
            per_sample_shading: false,
            coarse_shading: false,
            background: Vec3::new(0.08, 0.09, 0.11),
            capture: Capture::FULL,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

/// The largest width or height of a viewport.
pub const MAX_VIEWPORT_SIDE: u32 = 16_384;

// A raster triangle's bounding box (`RasterTriangle::bbox`) is 16 bits a coordinate.
const _: () = assert!(MAX_VIEWPORT_SIDE <= 1 << 16);

/// The most memory one capture may take, by [`RenderSettings::capture_bytes`]: 2 GiB, so that
/// a mistaken size is refused with a message instead of exhausting the machine.
pub const MAX_CAPTURE_BYTES: u64 = 2 << 30;

impl RenderSettings {
    /// Width / height.
    #[must_use]
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height as f32
    }

    /// The memory the per-pixel and per-sample buffers of a capture at these settings take, at
    /// most: `W·H·B + W·H·S·8` bytes with `B` the selection's bytes a pixel (85 for a full
    /// capture, see [`CAPTURE_BYTES_PER_PIXEL`](crate::buffers::CAPTURE_BYTES_PER_PIXEL)).
    #[must_use]
    pub fn capture_bytes(&self) -> u64 {
        let pixels = u64::from(self.width) * u64::from(self.height);
        pixels * self.capture.bytes_per_pixel()
            + pixels * self.samples.count() as u64 * CAPTURE_BYTES_PER_SAMPLE
    }

    /// Why a capture at these settings would take too much memory, if it would.
    #[must_use]
    pub fn capture_problem(&self) -> Option<SettingsProblem> {
        let bytes = self.capture_bytes();
        (bytes > MAX_CAPTURE_BYTES).then_some(SettingsProblem::CaptureTooLarge {
            width: self.width,
            height: self.height,
            samples: self.samples.count() as u32,
            megabytes: bytes >> 20,
        })
    }

    /// What is wrong with these settings, if anything.
    #[must_use]
    pub fn problems(&self) -> Vec<SettingsProblem> {
        let mut out = Vec::new();
        for (height, v) in [(false, self.width), (true, self.height)] {
            if v == 0 || v > MAX_VIEWPORT_SIDE {
                out.push(SettingsProblem::ViewportSide { height, got: v });
            }
        }
        out.extend(self.capture_problem());
        if !self.background.is_finite() {
            out.push(SettingsProblem::Background);
        }
        out
    }
}

/// What is wrong with the render settings, as data for the interface to say in its language;
/// its English sentence is its `Display`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SettingsProblem {
    /// The viewport's width (or height) is 0 or past [`MAX_VIEWPORT_SIDE`].
    #[error(
        "the viewport {} must be between 1 and {MAX_VIEWPORT_SIDE} pixels, got {got}",
        if *height { "height" } else { "width" }
    )]
    ViewportSide {
        /// The height (`false`: the width).
        height: bool,
        /// The size asked for.
        got: u32,
    },
    /// A capture past [`MAX_CAPTURE_BYTES`].
    #[error(
        "{width}×{height} pixels × {samples} samples needs about {megabytes} MB for a capture, more than the {} MB allowed; lower the size or the sample count",
        MAX_CAPTURE_BYTES >> 20
    )]
    CaptureTooLarge {
        /// Viewport width.
        width: u32,
        /// Viewport height.
        height: u32,
        /// Samples per pixel.
        samples: u32,
        /// The capture's size in MiB.
        megabytes: u64,
    },
    /// A background colour that is NaN or infinite.
    #[error("the background colour must be finite")]
    Background,
}
