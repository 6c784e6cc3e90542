//! An animated step's frames: each picture scaled to a filmstrip frame's width, captioned for a
//! GIF (which has no caption of its own), and the frames encoded as a looping GIF.

use anyhow::{Context, Result};
use image::RgbaImage;

/// The width of a filmstrip frame and a GIF frame.
const FRAME_WIDTH: u32 = 360;

/// A picture scaled to a filmstrip frame's width.
pub(super) fn small(img: &RgbaImage) -> RgbaImage {
    if img.width() <= FRAME_WIDTH {
        return img.clone();
    }
    let h = (img.height() as f32 * FRAME_WIDTH as f32 / img.width() as f32).round() as u32;
    image::imageops::resize(
        img,
        FRAME_WIDTH,
        h.max(1),
        image::imageops::FilterType::Triangle,
    )
}

/// The caption drawn on a dark band at the bottom of a GIF frame (a GIF has no caption of its
/// own).
pub(super) fn caption_on(img: &mut RgbaImage, caption: &str) {
    let band = 30.min(img.height());
    let y = img.height() - band;
    super::text::fill(img, 0, y, img.width(), band, [20, 20, 20]);
    super::text::draw(
        img,
        8.0,
        (img.height() - 9) as f32,
        18.0,
        [255, 220, 120],
        caption,
    );
}

/// An endlessly looping GIF of `frames`, `delay_ms` apart.
pub(super) fn gif(frames: &[RgbaImage], delay_ms: u32) -> Result<Vec<u8>> {
    use image::codecs::gif::{GifEncoder, Repeat};
    let mut bytes = Vec::new();
    {
        let mut enc = GifEncoder::new_with_speed(&mut bytes, 20);
        enc.set_repeat(Repeat::Infinite).context("encoding a GIF")?;
        for f in frames {
            let frame = image::Frame::from_parts(
                f.clone(),
                0,
                0,
                image::Delay::from_numer_denom_ms(delay_ms, 1),
            );
            enc.encode_frame(frame).context("encoding a GIF")?;
        }
    }
    Ok(bytes)
}
