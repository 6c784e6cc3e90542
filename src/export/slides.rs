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

/// What a slide shows besides the step's title, picture and words.
#[derive(Clone, Debug, Default)]
pub struct Extras {
    /// The legend of the picture's drawings (the lighting vectors), drawn at the slide's size
    /// beside the picture, not over it.
    pub legend: Vec<String>,
    /// Under the picture: what it is (a lab's "pipelens' own: what your code must draw").
    pub caption: Option<String>,
    /// The code or the run the step is about: a heading, then rows `(line, text, marked)`.
    pub code: Option<(String, Vec<super::listing::Row>)>,
    /// A lab's task, after the narration.
    pub task: Option<String>,
}

/// The type of a slide's code panel.
const CODE_TYPE: f32 = 22.0;
/// The height of one row of the code panel.
const CODE_ROW: f32 = 30.0;
/// The type of the legend.
const LEGEND_TYPE: f32 = 26.0;

/// The slide of step `k`, showing `picture` and `extras`.
#[must_use]
pub fn slide(
    lesson: &Lesson,
    k: usize,
    picture: &RgbaImage,
    extras: &Extras,
    lang: Lang,
) -> RgbaImage {
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
    let mut paragraphs = paragraphs(step.narration.get(lang));
    if let Some(task) = &extras.task {
        paragraphs.push((task.clone(), ACCENT));
    }
    let (w0, h0) = (picture.width() as f32, picture.height() as f32);
    let full = WIDTH as f32 - 2.0 * margin;
    // A caption under the picture takes a line from it.
    let tall = if extras.caption.is_some() {
        836.0
    } else {
        880.0
    };
    let beside = (1160.0 / w0).min(tall / h0);
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
        // The legend on the footer's line, at its right.
        let legend = extras.legend.join("   ");
        let x = WIDTH as f32 - margin - text::width(&legend, 22.0);
        text::draw(&mut img, x, HEIGHT as f32 - 24.0, 22.0, INK, &legend);
    } else {
        imageops::overlay(&mut img, &scaled, margin as i64, 130);
        if let Some(caption) = &extras.caption {
            let y = 130.0 + ph as f32 + 34.0;
            text::draw(&mut img, margin, y, 26.0, ACCENT, caption);
        }
        let left = margin + pw as f32 + 48.0;
        let width = WIDTH as f32 - left - margin;
        // From the column's foot up: the code panel, the legend; the words above them.
        let mut bottom = 130.0 + 900.0;
        if let Some((heading, rows)) = &extras.code {
            bottom -= code_panel(&mut img, (left, width), bottom, heading, rows);
        }
        if !extras.legend.is_empty() {
            bottom -= 16.0 + extras.legend.len() as f32 * LEGEND_TYPE * 1.35;
            for (i, line) in extras.legend.iter().enumerate() {
                let y = bottom + LEGEND_TYPE * (1.0 + 1.35 * i as f32);
                text::draw(&mut img, left, y, LEGEND_TYPE, INK, line);
            }
        }
        narration(
            &mut img,
            &paragraphs,
            (left, width),
            130.0,
            bottom - 130.0 - 24.0,
        );
    }
    img
}

/// The code panel at the foot of the column `(x, width)` ending at `bottom`: the heading, then
/// each row's line number and text in monospace (a marked row on a lighter ground, a line too
/// long for the column cut with `…`). Returns its height.
fn code_panel(
    img: &mut RgbaImage,
    (x, width): (f32, f32),
    bottom: f32,
    heading: &str,
    rows: &[super::listing::Row],
) -> f32 {
    let height = 44.0 + rows.len() as f32 * CODE_ROW + 12.0;
    let top = bottom - height;
    text::draw(img, x, top + 28.0, 24.0, ACCENT, heading);
    let numbers = text::code_width("000 ", CODE_TYPE);
    for (i, (line, code, marked)) in rows.iter().enumerate() {
        let y = top + 44.0 + i as f32 * CODE_ROW;
        let ground = if *marked { [70, 62, 36] } else { [34, 37, 43] };
        text::fill(
            img,
            x as u32,
            y as u32,
            width as u32,
            CODE_ROW as u32,
            ground,
        );
        let nw = text::code_width(line, CODE_TYPE);
        text::draw_code(img, x + numbers - nw - 8.0, y + 22.0, CODE_TYPE, DIM, line);
        let room = width - numbers - 8.0;
        let mut shown = code.trim_end().to_owned();
        while text::code_width(&shown, CODE_TYPE) > room && shown.pop().is_some() {}
        if shown.len() < code.trim_end().len() {
            shown.pop();
            shown.push('…');
        }
        text::draw_code(img, x + numbers, y + 22.0, CODE_TYPE, INK, &shown);
    }
    height
}

/// The type size of words under a picture that spans the slide (the largest size the
/// narration may shrink from there).
const STACKED_TYPE: f32 = 38.0;

/// A paragraph of a slide: its text (`**formulas**` in the accent colour) and the colour of
/// the rest.
type Paragraph = (String, [u8; 3]);

/// The narration's paragraphs (list items bulleted), in ink.
fn paragraphs(text: &str) -> Vec<Paragraph> {
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
            (joined, INK)
        })
        .collect()
}

/// The height `paragraphs` take in type of `size` wrapped to `width`.
fn needed(paragraphs: &[Paragraph], size: f32, width: f32) -> f32 {
    let lines: usize = paragraphs
        .iter()
        .map(|(p, color)| text::wrap_marked(p, (*color, ACCENT), size, width).len())
        .sum();
    lines as f32 * size * 1.45 + (paragraphs.len() as f32 - 1.0).max(0.0) * size * 0.6
}

/// The narration in the largest type from 46 down to 20 pixels that fits `height`.
fn narration(
    img: &mut RgbaImage,
    paragraphs: &[Paragraph],
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
        .map(|(p, color)| text::wrap_marked(p, (*color, ACCENT), size, width))
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
