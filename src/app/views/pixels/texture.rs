//! The textures of the buffer shown: the lesson's own pixels, or, on a stage about the shading
//! and until the view is zoomed in to the pixel grid, the same buffer rendered at the view's
//! resolution (`app::view_resolution`), drawn with the lesson capture's gain so that the two agree.

use egui::TextureOptions;
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;

use crate::app::session::Session;

/// The pixel grid is drawn from this magnification on: there the lesson's own pixels show.
pub(super) const GRID_ZOOM: f32 = 6.0;

/// The lesson's texture, the finer one, and the gain of the lighting term shown.
#[derive(Default)]
pub(super) struct Textures {
    lesson: crate::app::views::BufferTexture,
    at_view_size: crate::app::views::BufferTexture,
    gain: crate::app::views::TermGain,
    /// The variable picture's, per frame shown and expression.
    watch: Option<((u64, usize, String), egui::TextureHandle)>,
}

impl Textures {
    /// The texture to draw at magnification `zoom` (made again when the capture, the buffer or
    /// the depth ramp changes) and the gain its lighting term is drawn with.
    pub(super) fn get(
        &mut self,
        ctx: &egui::Context,
        session: &Session,
        capture: &FrameCapture,
        zoom: f32,
    ) -> (egui::TextureHandle, f32) {
        let sel = &session.selection;
        let generation = session.shown_generation;
        let gain = self
            .gain
            .get((generation, sel.buffer), || capture.term_gain(sel.buffer));
        if let Some(fine) = session.view_resolution.capture.as_ref().filter(|d| {
            zoom < GRID_ZOOM
                && crate::app::view_resolution::wanted(sel.stage, sel.buffer)
                && d.settings
                    .capture
                    .covers(pipeline::buffers::Capture::showing([sel.buffer]))
        }) {
            let texture = self.at_view_size.get(
                ctx,
                "pixel-view-fine",
                (generation, sel.buffer, gain),
                fine,
                TextureOptions::LINEAR,
            );
            return (texture, gain);
        }
        let depth = sel.depth_view;
        let variant = if sel.buffer == BufferKind::Depth {
            let [a, b] = depth.range.unwrap_or([f32::NAN; 2]);
            (u64::from(a.to_bits()) << 32 | u64::from(b.to_bits())) ^ u64::from(depth.linear)
        } else {
            0
        };
        let texture = self.lesson.get_with(
            ctx,
            "pixel-view",
            (generation, sel.buffer, variant),
            TextureOptions::NEAREST,
            || match sel.buffer {
                BufferKind::Depth => capture.depth_image(depth.linear, depth.range),
                kind => capture.image_shown(kind, gain),
            },
        );
        (texture, gain)
    }

    /// The texture of the variable picture `picture` of the frame `generation` (its value as
    /// a colour, a number on the ramp), made again when either changes.
    pub(super) fn watch(
        &mut self,
        ctx: &egui::Context,
        generation: u64,
        picture: &pipeline::capture::WatchPicture,
    ) -> egui::TextureHandle {
        let key = (generation, picture.line, picture.expression.clone());
        if let Some((k, t)) = &self.watch
            && *k == key
        {
            return t.clone();
        }
        let drawn = picture.drawn(pipeline::capture::WatchView::Value);
        let size = [drawn.image.width() as usize, drawn.image.height() as usize];
        let image = egui::ColorImage::from_rgba_unmultiplied(size, drawn.image.as_raw());
        let t = ctx.load_texture("pixel-view-watch", image, TextureOptions::NEAREST);
        self.watch = Some((key, t.clone()));
        t
    }
}
