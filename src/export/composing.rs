//! Pictures put together for handouts and slides: side by side, one above the other, and words
//! set on a darkened box over a picture (a label at a point, a note at the bottom).

use image::{Rgba, RgbaImage, imageops};

use super::text;

/// Darkens a rectangle to 30 % (a box behind words over a picture).
/// White text on a darkened box centred at `(cx, cy)`, as the app writes a mesh's labels.
pub(super) fn centred_label(img: &mut RgbaImage, cx: f32, cy: f32, label: &str) {
    const SIZE: f32 = 20.0;
    let w = text::width(label, SIZE);
    let (x, y) = ((cx - w / 2.0 - 4.0).max(0.0), (cy - 14.0).max(0.0));
    darken(img, x as u32, y as u32, (w + 8.0) as u32, 28);
    text::draw(img, x + 4.0, y + 21.0, SIZE, [255, 255, 255], label);
}

pub(super) fn darken(img: &mut RgbaImage, x: u32, y: u32, w: u32, h: u32) {
    for py in y..(y + h).min(img.height()) {
        for px in x..(x + w).min(img.width()) {
            let p = img.get_pixel_mut(px, py);
            for c in 0..3 {
                p.0[c] = (u16::from(p.0[c]) * 3 / 10) as u8;
            }
        }
    }
}

/// A line of text on a dark box at the bottom-left (what a picture says about how it is drawn).
pub(super) fn bottom_note(img: &mut RgbaImage, note: &str) {
    let size = (img.width() as f32 / 48.0).clamp(16.0, 28.0);
    let (w, h) = (text::width(note, size) + size, size * 1.6);
    let y = img.height().saturating_sub(h as u32 + 8);
    darken(img, 8, y, w as u32, h as u32);
    text::draw(
        img,
        8.0 + size / 2.0,
        y as f32 + size * 1.15,
        size,
        [255, 255, 255],
        note,
    );
}

/// `a` and `b` side by side, `b` scaled to `a`'s height.
pub(super) fn beside(a: &RgbaImage, b: &RgbaImage) -> RgbaImage {
    let h = a.height();
    let w = (b.width() as f32 * h as f32 / b.height() as f32).round() as u32;
    let b = imageops::resize(b, w.max(1), h, imageops::FilterType::Triangle);
    let mut out = RgbaImage::from_pixel(a.width() + 8 + b.width(), h, Rgba([30, 30, 30, 255]));
    imageops::overlay(&mut out, a, 0, 0);
    imageops::overlay(&mut out, &b, i64::from(a.width() + 8), 0);
    out
}

/// `a` above `b`, `b` as wide as `a`.
pub(super) fn above(a: &RgbaImage, b: &RgbaImage) -> RgbaImage {
    let mut out = RgbaImage::from_pixel(
        a.width(),
        a.height() + 8 + b.height(),
        Rgba([30, 30, 30, 255]),
    );
    imageops::overlay(&mut out, a, 0, 0);
    imageops::overlay(&mut out, b, 0, i64::from(a.height() + 8));
    out
}
