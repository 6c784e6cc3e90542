//! The lessons built into pipelens: every file of `lessons/`, embedded, so that the app offers
//! them all with no files beside it (the desktop app's Lessons menu, and the web build, which has
//! no disk). A test keeps this list equal to the folder.

use std::path::Path;

use super::{Diagnostics, script::Lesson};
use crate::vocabulary::Text;

/// Each built-in lesson: its file name in `lessons/` and its text.
pub const LESSONS: [(&str, &str); 26] = [
    ("00-tour.toml", include_str!("../../lessons/00-tour.toml")),
    (
        "01-transforms.toml",
        include_str!("../../lessons/01-transforms.toml"),
    ),
    (
        "02-arbitrary-axis.toml",
        include_str!("../../lessons/02-arbitrary-axis.toml"),
    ),
    (
        "03-frames-lookat.toml",
        include_str!("../../lessons/03-frames-lookat.toml"),
    ),
    (
        "04-orthographic.toml",
        include_str!("../../lessons/04-orthographic.toml"),
    ),
    (
        "05-perspective.toml",
        include_str!("../../lessons/05-perspective.toml"),
    ),
    (
        "06-clipping-ndc-viewport.toml",
        include_str!("../../lessons/06-clipping-ndc-viewport.toml"),
    ),
    (
        "07-rasterization.toml",
        include_str!("../../lessons/07-rasterization.toml"),
    ),
    (
        "08-antialiasing.toml",
        include_str!("../../lessons/08-antialiasing.toml"),
    ),
    (
        "09-z-buffer.toml",
        include_str!("../../lessons/09-z-buffer.toml"),
    ),
    (
        "10-blinn-phong.toml",
        include_str!("../../lessons/10-blinn-phong.toml"),
    ),
    (
        "11-shading-frequencies.toml",
        include_str!("../../lessons/11-shading-frequencies.toml"),
    ),
    (
        "12-interpolation.toml",
        include_str!("../../lessons/12-interpolation.toml"),
    ),
    (
        "13-texture-mapping.toml",
        include_str!("../../lessons/13-texture-mapping.toml"),
    ),
    (
        "14-mipmaps.toml",
        include_str!("../../lessons/14-mipmaps.toml"),
    ),
    (
        "15-surface-detail.toml",
        include_str!("../../lessons/15-surface-detail.toml"),
    ),
    (
        "16-planar-shadows.toml",
        include_str!("../../lessons/16-planar-shadows.toml"),
    ),
    (
        "17-hierarchy.toml",
        include_str!("../../lessons/17-hierarchy.toml"),
    ),
    (
        "18-bezier.toml",
        include_str!("../../lessons/18-bezier.toml"),
    ),
    (
        "19-bezier-surfaces.toml",
        include_str!("../../lessons/19-bezier-surfaces.toml"),
    ),
    (
        "20-frames-projections.toml",
        include_str!("../../lessons/20-frames-projections.toml"),
    ),
    (
        "21-geometry-representations.toml",
        include_str!("../../lessons/21-geometry-representations.toml"),
    ),
    (
        "22-sampling-aliasing.toml",
        include_str!("../../lessons/22-sampling-aliasing.toml"),
    ),
    (
        "23-beyond-mipmaps.toml",
        include_str!("../../lessons/23-beyond-mipmaps.toml"),
    ),
    (
        "24-shader-programs.toml",
        include_str!("../../lessons/24-shader-programs.toml"),
    ),
    (
        "25-lab-model-projection.toml",
        include_str!("../../lessons/25-lab-model-projection.toml"),
    ),
];

/// What the app calls the built-in lesson `file` (a name in [`LESSONS`]):
/// `lessons/05-perspective.toml (built in)`.
#[must_use]
pub fn source_name(file: &str) -> String {
    format!("lessons/{file} (built in)")
}

/// The built-in lesson the app's name `source` names (see [`source_name`]): its file's name and
/// its text; `None` for any other source.
#[must_use]
pub fn named(source: &str) -> Option<(&'static str, &'static str)> {
    let file = source
        .strip_prefix("lessons/")?
        .strip_suffix(" (built in)")?;
    LESSONS.iter().find(|(f, _)| *f == file).copied()
}

/// The built-in lesson `file` (a name in [`LESSONS`]), parsed.
///
/// # Errors
/// Never for a shipped lesson (a test loads every one); an unknown name is reported as a
/// diagnostic naming the lessons there are.
pub fn lesson(file: &str) -> Result<Lesson, Diagnostics> {
    let name = source_name(file);
    match LESSONS.iter().find(|(f, _)| *f == file) {
        Some((_, text)) => super::script::parse_lesson(text, &name, Path::new(".")),
        None => Err(Diagnostics(vec![super::Diagnostic::whole_file(
            &name,
            format!(
                "no built-in lesson is called {file}; there are {}",
                LESSONS.map(|(f, _)| f).join(", ")
            ),
        )])),
    }
}

/// How many of a lesson's steps ask for a value to type (`expect`) or are exercises, read from
/// its text without building the lesson (for the Lessons menu's progress).
#[must_use]
pub fn typed_questions(text: &str) -> usize {
    text.parse::<toml::Table>()
        .ok()
        .and_then(|t| {
            let steps = t.get("steps")?.as_array()?;
            Some(
                steps
                    .iter()
                    .filter(|s| s.get("expect").is_some() || s.get("exercise").is_some())
                    .count(),
            )
        })
        .unwrap_or(0)
}

/// A built-in lesson's title, read from its `[lesson]` table without building its scene (for
/// menus): in English, Chinese and every other language it gives, or the file name when the
/// text has none.
#[must_use]
pub fn title(text: &str, file: &str) -> Text {
    text.parse::<toml::Table>()
        .ok()
        .and_then(|t| t.get("lesson")?.get("title").cloned())
        .and_then(|v| v.try_into::<super::raw::RawText>().ok())
        .map_or_else(|| Text::new(file, file), |r| r.text())
}
