//! Slides: one 1920×1080 PNG per step — the title, the step's picture as large as it fits, and
//! the narration in large type beside it or, under a wide picture, below it (its formulas
//! highlighted) — the files a teacher drags into a slide deck.

use image::{Rgba, RgbaImage, imageops};

use super::text::{self, Run};
use crate::lesson::Lesson;
use crate::vocabulary::Lang;

/// The slide's size.
pub const WIDTH: u32 = 1920;
/// The slide's size.
pub const HEIGHT: u32 = 1080;

const BACKGROUND: [u8; 3] = [22, 24, 28];
const INK: [u8; 3] = [235, 235, 235];
const ACCENT: [u8; 3] = [255, 214, 120];
const DIM: [u8; 3] = [150, 150, 150];

/// The slide of step `k`, showing `picture`.
#[must_use]
pub fn slide(lesson: &Lesson, k: usize, picture: &RgbaImage, lang: Lang) -> RgbaImage {
    let step = &lesson.steps[k];
    let [r, g, b] = BACKGROUND;
    let mut img = RgbaImage::from_pixel(WIDTH, HEIGHT, Rgba([r, g, b, 255]));
    let margin = 48.0;
    let title = format!("{}. {}", k + 1, step.title.get(lang));
    text::draw_runs(
        &mut img,
        margin,
        92.0,
        56.0,
        &text::marked_runs(&title, ACCENT, ACCENT),
    );
    let footer = format!(
        "{} · {} / {}",
        lesson.title.get(lang),
        k + 1,
        lesson.steps.len()
    );
    text::draw(&mut img, margin, HEIGHT as f32 - 24.0, 22.0, DIM, &footer);
    // The picture as large as it can be: beside the words (on the left, in 1160×880) or, a wide
    // picture, across the slide with the words under it, whichever leaves it the larger.
    let paragraphs = paragraphs(step.narration.get(lang));
    let (w0, h0) = (picture.width() as f32, picture.height() as f32);
    let full = WIDTH as f32 - 2.0 * margin;
    let beside = (1160.0 / w0).min(880.0 / h0);
    let under_words = needed(&paragraphs, STACKED_TYPE, full).max(2.0 * STACKED_TYPE * 1.45);
    let stacked = (full / w0).min((880.0 - under_words - 24.0).max(0.0) / h0);
    let across = stacked > beside * 1.1;
    let s = if across { stacked } else { beside };
    let (pw, ph) = ((w0 * s).round() as u32, (h0 * s).round() as u32);
    let filter = if s >= 2.0 {
        imageops::FilterType::Nearest
    } else {
        imageops::FilterType::Triangle
    };
    let scaled = imageops::resize(picture, pw.max(1), ph.max(1), filter);
    if across {
        let x = margin + (full - pw as f32) / 2.0;
        imageops::overlay(&mut img, &scaled, x as i64, 130);
        let top = 130.0 + ph as f32 + 24.0;
        let height = HEIGHT as f32 - 70.0 - top;
        narration(&mut img, &paragraphs, (margin, full), top, height);
    } else {
        imageops::overlay(&mut img, &scaled, margin as i64, 130);
        let left = margin + pw as f32 + 48.0;
        let width = WIDTH as f32 - left - margin;
        narration(&mut img, &paragraphs, (left, width), 130.0, 900.0);
    }
    img
}

/// The type size of words under a picture that spans the slide (the largest size the
/// narration may shrink from there).
const STACKED_TYPE: f32 = 38.0;

/// The narration's paragraphs as runs (formulas highlighted, list items bulleted).
fn paragraphs(text: &str) -> Vec<Vec<Run>> {
    text.split("\n\n")
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .map(|p| {
            let joined = p
                .lines()
                .map(|l| {
                    l.trim()
                        .strip_prefix("- ")
                        .map_or_else(|| l.trim().to_owned(), |b| format!("• {b}"))
                })
                .collect::<Vec<_>>()
                .join(" ");
            text::marked_runs(&joined, INK, ACCENT)
        })
        .collect()
}

/// The height `paragraphs` take in type of `size` wrapped to `width`.
fn needed(paragraphs: &[Vec<Run>], size: f32, width: f32) -> f32 {
    let lines: usize = paragraphs
        .iter()
        .map(|p| text::wrap(p, size, width).len())
        .sum();
    lines as f32 * size * 1.45 + (paragraphs.len() as f32 - 1.0).max(0.0) * size * 0.6
}

/// The narration in the largest type from 46 down to 20 pixels that fits `height`.
fn narration(
    img: &mut RgbaImage,
    paragraphs: &[Vec<Run>],
    (x, width): (f32, f32),
    top: f32,
    height: f32,
) {
    let mut size = 46.0;
    while needed(paragraphs, size, width) > height && size > 20.0 {
        size -= 2.0;
    }
    let layout: Vec<Vec<Vec<Run>>> = paragraphs
        .iter()
        .map(|p| text::wrap(p, size, width))
        .collect();
    let mut y = top + size;
    for paragraph in layout {
        for line in paragraph {
            if y > top + height {
                return;
            }
            text::draw_runs(img, x, y, size, &line);
            y += size * 1.45;
        }
        y += size * 0.6;
    }
}
