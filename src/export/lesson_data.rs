//! A lesson's export with `--data`: each step's buffers as PNG and `capture.json` (with the
//! step's pixel) in `step-NN/`, the compared settings' colour images, the profile's CSV, and
//! the textures' mip levels, which are the same for every step and written once.

use anyhow::Result;
use pipeline::capture::FrameCapture;

use super::{ExportFile, ExportOptions, encode_capture, png_rgba, profile_csv};
use crate::lesson::Lesson;

/// With `--data`: step `k`'s buffers, `capture.json` (with the step's pixel), the compared
/// images and the profile; and the textures' mip levels (the same for every step). `export`
/// says where the step's files go, and its `pixel` is the one asked for on the command line.
pub(super) fn data_files(
    lesson: &Lesson,
    k: usize,
    export: ExportOptions,
    capture: &FrameCapture,
    variants: &[(String, FrameCapture)],
) -> Result<(Vec<ExportFile>, Vec<ExportFile>)> {
    let step = &lesson.steps[k];
    if let Some((x, y)) = export.pixel
        && (x >= capture.width() || y >= capture.height())
    {
        anyhow::bail!(
            "--pixel {x},{y} is outside step {}'s {}×{} image",
            k + 1,
            capture.width(),
            capture.height()
        );
    }
    let export = ExportOptions {
        // The frame was drawn with the pixel `capture.json` describes (see `spec_of`).
        pixel: capture.settings.capture.pixel,
        ..export
    };
    let (mut files, textures): (Vec<_>, Vec<_>) = encode_capture(capture, &export)?
        .into_iter()
        .partition(|f| !(f.name.starts_with("texture") || f.name.starts_with("cube")));
    for (label, cap) in variants {
        files.push(ExportFile {
            name: format!("compare_{}.png", slug(label)),
            description: format!("the colour image with {label}"),
            bytes: png_rgba(&cap.image(pipeline::buffers::BufferKind::Color))?,
        });
    }
    if let Some(line) = step.profile_line(capture.width(), capture.height()) {
        let named: Vec<(&str, &FrameCapture)> = if variants.is_empty() {
            vec![("color", capture)]
        } else {
            variants.iter().map(|(l, c)| (l.as_str(), c)).collect()
        };
        files.push(profile_csv(line, &named));
    }
    Ok((files, textures))
}

/// A compared setting's name as a file name: `MSAA 4×` → `msaa_4`.
fn slug(label: &str) -> String {
    let s: String = label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    s.trim_matches('_').replace("__", "_")
}
