//! The picture at the view's own resolution. On the stages whose subject is the shading (shading,
//! texturing, the output) a lesson image of 640×400 magnified three times on a projector shows
//! stair-stepped silhouettes that the lesson is not about. There the worker also renders the
//! buffer shown at the size the view draws it, and the pixel view shows that render until it is
//! zoomed in far enough to show the pixel grid. Everything else — the inspected pixel, the
//! overlays, the tooltips, the exercise's comparison — stays on the lesson's own pixels, whose
//! capture is unchanged; the picture only looks finer.

use std::sync::Arc;

use pipeline::buffers::{BufferKind, Capture};
use pipeline::capture::FrameCapture;

use crate::lesson::SceneSpec;
use crate::vocabulary::Stage;

/// The finer render is worth it from this magnification of the lesson's image on.
const LEAST_SCALE: f32 = 1.5;
/// At most this many pixels (a 4K view at most).
const MOST_PIXELS: f32 = 8.3e6;

/// Whether `stage` shows `buffer` at the view's resolution: a stage about the shading, and a
/// buffer that is the shading's (the colour, a lighting term, a texturing buffer), not one about
/// the pixel grid (coverage, which triangle, the barycentrics, depth).
#[must_use]
pub fn wanted(stage: Stage, buffer: BufferKind) -> bool {
    matches!(stage, Stage::Shading | Stage::Texturing | Stage::Output)
        && (buffer == BufferKind::Color || buffer.is_lighting() || buffer.is_texturing())
}

/// The size to render at for a view that draws the lesson's `image` (width, height) over `view`
/// physical pixels: the image scaled by `s = min(view_w/w, view_h/h)`, the lesson's shape kept,
/// when `s ≥ 1.5`, and at most 8.3 million pixels; `None` when the lesson's image is nearly as
/// fine.
#[must_use]
pub fn size(image: (u32, u32), view: [u32; 2]) -> Option<(u32, u32)> {
    let (w, h) = (image.0.max(1) as f32, image.1.max(1) as f32);
    let s = (view[0] as f32 / w).min(view[1] as f32 / h);
    let s = s.min((MOST_PIXELS / (w * h)).sqrt());
    (s.is_finite() && s >= LEAST_SCALE).then(|| ((w * s).round() as u32, (h * s).round() as u32))
}

/// The finer render on screen, and what the latest job asked for (a render that could not be
/// made is not asked for again until the view asks for something else).
#[derive(Clone, Debug, Default)]
pub struct ViewResolution {
    /// The buffer shown at the view's resolution, when the latest render made it.
    pub capture: Option<Arc<FrameCapture>>,
    /// What the latest job asked for.
    pub asked: Option<(BufferKind, (u32, u32))>,
}

/// `spec` rendered at `size`, keeping only `buffer`; `None` when it cannot be rendered (the
/// lesson's image stays on screen).
#[must_use]
pub fn render(spec: &SceneSpec, buffer: BufferKind, size: (u32, u32)) -> Option<FrameCapture> {
    let mut settings = spec.settings;
    (settings.width, settings.height) = size;
    settings.capture = Capture::showing([buffer]);
    pipeline::render(&spec.scene, &settings).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_finer_render_keeps_the_lessons_shape_and_is_bounded() {
        // 640×400 drawn over 1900×1000 physical pixels: scaled by 2.5.
        assert_eq!(size((640, 400), [1900, 1000]), Some((1600, 1000)));
        // Magnified less than 1.5 times: the lesson's image is fine as it is.
        assert_eq!(size((1280, 720), [1600, 900]), None);
        // A 16×16 image over a 4K view: at most 8.3 million pixels.
        let (w, h) = size((16, 16), [3840, 2160]).expect("magnified");
        assert_eq!(w, h);
        assert!(w * h <= 8_300_000 && w >= 2000, "{w}×{h}");
        assert_eq!(size((640, 400), [0, 0]), None);
    }

    #[test]
    fn only_the_shadings_buffers_on_its_stages() {
        assert!(wanted(Stage::Output, BufferKind::Color));
        assert!(wanted(Stage::Shading, BufferKind::Diffuse));
        assert!(wanted(Stage::Texturing, BufferKind::MipLevel));
        assert!(!wanted(Stage::Raster, BufferKind::Color));
        assert!(!wanted(Stage::Depth, BufferKind::Color));
        assert!(!wanted(Stage::Output, BufferKind::Coverage));
        assert!(!wanted(Stage::Output, BufferKind::Depth));
    }
}
