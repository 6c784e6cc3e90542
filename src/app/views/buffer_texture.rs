//! A capture's buffer on the GPU as an egui texture, and a lighting term's display gain, each
//! found again only when what it depends on changed, not on every UI frame.

/// A lighting term's display gain (`FrameCapture::term_gain`, a scan of every pixel), found
/// again only when the capture (its generation) or the buffer changes, not on every UI frame.
#[derive(Default)]
pub struct TermGain(Option<((u64, pipeline::buffers::BufferKind), f32)>);

impl TermGain {
    /// The gain for `key`, from `find` when the key changed.
    pub fn get(
        &mut self,
        key: (u64, pipeline::buffers::BufferKind),
        find: impl FnOnce() -> f32,
    ) -> f32 {
        match self.0 {
            Some((k, gain)) if k == key => gain,
            _ => {
                let gain = find();
                self.0 = Some((key, gain));
                gain
            }
        }
    }
}

/// A capture's buffer uploaded as an egui texture, uploaded again only when the capture (its
/// generation), the buffer or the way it is drawn (`variant`) changes.
#[derive(Default)]
pub struct BufferTexture(
    Option<(
        (u64, pipeline::buffers::BufferKind, u64),
        egui::TextureHandle,
    )>,
);

impl BufferTexture {
    /// The texture of `kind` from `capture` (generation `generation`), its lighting terms drawn
    /// `gain` times brighter, with its objects' outlines (`capture.image_shown`).
    pub fn get(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        (generation, kind, gain): (u64, pipeline::buffers::BufferKind, f32),
        capture: &pipeline::capture::FrameCapture,
        options: egui::TextureOptions,
    ) -> egui::TextureHandle {
        let key = (generation, kind, u64::from(gain.to_bits()));
        self.get_with(ctx, name, key, options, || capture.image_shown(kind, gain))
    }

    /// The texture for `key`, made by `make` when the key changed.
    pub fn get_with(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        key: (u64, pipeline::buffers::BufferKind, u64),
        options: egui::TextureOptions,
        make: impl FnOnce() -> image::RgbaImage,
    ) -> egui::TextureHandle {
        if let Some((k, t)) = &self.0
            && *k == key
        {
            return t.clone();
        }
        let img = make();
        let size = [img.width() as usize, img.height() as usize];
        let color = egui::ColorImage::from_rgba_unmultiplied(size, img.as_raw());
        let t = ctx.load_texture(name, color, options);
        self.0 = Some((key, t.clone()));
        t
    }
}
