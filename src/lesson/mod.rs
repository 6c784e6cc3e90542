//! Scene files and lessons: plain TOML that a teacher can write, parsed in two tiers.
//!
//! 1. [`raw`] mirrors the file (serde, unknown keys rejected, every value with its position);
//! 2. [`validate`] resolves it into a `pipeline::scene::Scene` and `RenderSettings`, collecting
//!    every problem as a [`Diagnostic`] with file:line:column and what was expected.
//!
//! A lesson ([`script`]) is a scene with `[lesson]` metadata and `[[steps]]`; its parameters are
//! named in [`param`]. The grammar of both is documented in `lessons/README.md`.

pub mod answer;
pub mod describe;
mod diagnostic;
pub mod edit;
pub mod folder;
pub mod forbid;
pub mod library;
pub mod param;
pub mod raw;
pub mod record;
pub mod script;
pub mod start;
mod syntax;
mod typed;
pub mod validate;

pub use folder::{Folder, Given};
pub use script::{Lesson, Step};
pub use validate::shaders::SHADER_FILE_ENDINGS;

use std::path::{Path, PathBuf};

pub use diagnostic::{Diagnostic, Diagnostics, Severity};
use pipeline::scene::Scene;
use pipeline::settings::RenderSettings;

use crate::vocabulary::{Lang, Text};

/// The scene built into pipelens, used when no file is given.
pub const DEFAULT_SCENE: &str = include_str!("../../assets/scenes/default.toml");
/// The name under which the built-in scene appears in messages.
pub const DEFAULT_SCENE_NAME: &str = "<built-in default scene>";

/// A scene ready to render.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneSpec {
    /// What is drawn.
    pub scene: Scene,
    /// How it is drawn.
    pub settings: RenderSettings,
    /// The names objects and figures are shown under in each language (`label = { en, zh }`),
    /// by their `name`.
    pub labels: std::collections::BTreeMap<String, Text>,
    /// The name of each light of `scene.lights` that has one (`name = "key"`), in order.
    pub light_names: Vec<Option<String>>,
}

impl SceneSpec {
    /// A scene with its settings, no labels.
    #[must_use]
    pub fn new(scene: Scene, settings: RenderSettings) -> Self {
        Self {
            scene,
            settings,
            labels: std::collections::BTreeMap::new(),
            light_names: Vec::new(),
        }
    }

    /// The index of the light that `key` names: its `name`, or its index written as a number.
    #[must_use]
    pub fn light_index(&self, key: &str) -> Option<usize> {
        let k = key.parse::<usize>().ok().or_else(|| {
            self.light_names
                .iter()
                .position(|n| n.as_deref() == Some(key))
        })?;
        (k < self.scene.lights.len()).then_some(k)
    }

    /// How parameters address light `k`: by its name if it has one, else by its index.
    #[must_use]
    pub fn light_key(&self, k: usize) -> String {
        self.light_names
            .get(k)
            .cloned()
            .flatten()
            .unwrap_or_else(|| k.to_string())
    }

    /// How an object or figure (or one of a figure's parts, `figure: part`) is named in `lang`:
    /// its label, else the built-in words for its name, else its name.
    #[must_use]
    pub fn label(&self, name: &str, lang: Lang) -> String {
        if let Some(t) = self.labels.get(name) {
            return t.get(lang).to_owned();
        }
        if let Some((figure, part)) = name.split_once(": ") {
            return format!(
                "{}: {}",
                self.label(figure, lang),
                crate::vocabulary::part_name(part, lang)
            );
        }
        if let Some(rest) = name.strip_prefix("shadow of ") {
            return crate::vocabulary::shadow_of(&self.label(rest, lang), lang);
        }
        crate::vocabulary::part_name(name, lang).to_owned()
    }
}

/// The largest scene or lesson file read (a larger one is surely a mistake).
pub const MAX_FILE_BYTES: u64 = 4 * 1024 * 1024;

/// The narration a lesson started from the scene on screen gives its first step, English and
/// Chinese, for the teacher to replace: `pipelens check` warns while it is still there.
pub const PLACEHOLDER_NARRATION: [&str; 2] = [
    "Write here what the viewer should see, and why.",
    "在这里写下观众应当看到什么、为什么。",
];

/// The title a lesson started from the scene on screen gives its first step (not the stage's
/// name, which a teacher writing only one language would leave in the other); `check` warns
/// while it is there.
pub const PLACEHOLDER_STEP_TITLE: [&str; 2] = ["Name this step", "给这一步起个名字"];

/// The title and summary a lesson started from the scene on screen begins with; `check` warns
/// while either is there.
pub const PLACEHOLDER_LESSON: [[&str; 2]; 2] = [
    ["Name this lesson", "给这一课起个名字"],
    [
        "Say what this lesson teaches, in one or two sentences.",
        "用一两句话说说这一课讲什么。",
    ],
];

/// Reads and validates a scene file. Relative mesh paths are relative to the file's folder.
///
/// # Errors
/// Every problem found, each with its position.
pub fn load_scene_file(path: &Path) -> Result<SceneSpec, Diagnostics> {
    let shown = path.display().to_string();
    let text = read_text(path)?;
    let base = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
    parse_scene(&text, &shown, &base)
}

/// Reads a text file with a size limit and a clear message for each failure.
///
/// # Errors
/// A diagnostic naming the file and why it cannot be read.
pub fn read_text(path: &Path) -> Result<String, Diagnostics> {
    let shown = path.display().to_string();
    let fail = |m: String| Diagnostics(vec![Diagnostic::whole_file(&shown, m)]);
    let meta = std::fs::metadata(path).map_err(|e| fail(format!("cannot read the file: {e}")))?;
    if meta.is_dir() {
        return Err(fail("this is a folder, not a file".to_owned()));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(fail(format!(
            "the file is {} bytes; a scene or lesson file may have at most {MAX_FILE_BYTES}",
            meta.len()
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| fail(format!("cannot read the file: {e}")))?;
    String::from_utf8(bytes).map_err(|e| {
        fail(format!(
            "the file is not UTF-8 text (invalid byte at offset {}): is it a binary file?",
            e.utf8_error().valid_up_to()
        ))
    })
}

/// Parses and validates scene text. `file` names it in messages; `base` resolves mesh paths.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_scene(text: &str, file: &str, base: &Path) -> Result<SceneSpec, Diagnostics> {
    parse_scene_in(text, file, &Folder::on_disk(base))
}

/// Parses and validates scene text, the files it names read from `base`.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_scene_in(text: &str, file: &str, base: &Folder) -> Result<SceneSpec, Diagnostics> {
    let raw: raw::RawSceneFile = parse_toml(text, file)?;
    validate::scene(&raw.scene, text, file, base)
}

/// What a file holds: a bare scene, or a lesson.
#[derive(Clone, Debug, PartialEq)]
pub enum Document {
    /// A scene file (`[scene]` only).
    Scene(Box<SceneSpec>),
    /// A lesson (`[lesson]`, `[scene]`, `[[steps]]`).
    Lesson(Box<Lesson>),
}

impl Document {
    /// The scene to show first.
    #[must_use]
    pub fn first_spec(&self) -> SceneSpec {
        match self {
            Self::Scene(s) => (**s).clone(),
            Self::Lesson(l) => l.spec_at(0),
        }
    }
}

/// The lesson built into pipelens, opened when no file is given: a tour of the pipeline.
pub const DEFAULT_LESSON: &str = library::LESSONS[0].1;
/// The name under which the built-in lesson appears in messages.
pub const DEFAULT_LESSON_NAME: &str = "lessons/00-tour.toml (built in)";

/// Reads and validates a scene file or a lesson, whichever it is.
///
/// # Errors
/// Every problem found, each with its position.
pub fn load_file(path: &Path) -> Result<Document, Diagnostics> {
    let shown = path.display().to_string();
    let text = read_text(path)?;
    let base = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
    parse_document(&text, &shown, &base)
}

/// Parses scene or lesson text.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_document(text: &str, file: &str, base: &Path) -> Result<Document, Diagnostics> {
    parse_document_in(text, file, &Folder::on_disk(base))
}

/// Parses scene or lesson text, the files it names read from `base` (a page's: the files it
/// was given).
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_document_in(text: &str, file: &str, base: &Folder) -> Result<Document, Diagnostics> {
    if script::is_lesson(text) {
        script::parse_lesson_in(text, file, base).map(|l| Document::Lesson(Box::new(l)))
    } else {
        parse_scene_in(text, file, base).map(|s| Document::Scene(Box::new(s)))
    }
}

/// The built-in default lesson.
///
/// # Errors
/// Never for the shipped lesson (a test checks it).
pub fn default_lesson() -> Result<Lesson, Diagnostics> {
    script::parse_lesson(DEFAULT_LESSON, DEFAULT_LESSON_NAME, Path::new("."))
}

/// The built-in default scene.
///
/// # Errors
/// Never for the shipped scene (a test checks it); the type is shared with files.
pub fn default_scene() -> Result<SceneSpec, Diagnostics> {
    parse_scene(DEFAULT_SCENE, DEFAULT_SCENE_NAME, Path::new("."))
}

/// Deserializes TOML, turning a syntax or shape error into a diagnostic with a suggestion for
/// misspelt keys.
///
/// # Errors
/// The one error the TOML reader reports, with its position.
pub fn parse_toml<T: serde::de::DeserializeOwned>(
    text: &str,
    file: &str,
) -> Result<T, Diagnostics> {
    if text.trim().is_empty() {
        return Err(Diagnostics(vec![Diagnostic::whole_file(
            file,
            "the file is empty: a scene file needs a [scene] table (see lessons/README.md)",
        )]));
    }
    toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        Diagnostics(vec![syntax::explain(text, file, span, e.message().trim())])
    })
}

impl SceneSpec {
    /// The names a picture of `capture` writes over the objects it compares: each object the
    /// lesson labels (`label = { en, zh }`) with the point above it in the image (pixels,
    /// y down), when at least two labelled objects are in the picture (one alone needs no
    /// name). Empty otherwise.
    #[must_use]
    pub fn object_labels(
        &self,
        capture: &pipeline::capture::FrameCapture,
        points: &[Option<[f32; 2]>],
        lang: Lang,
    ) -> Vec<([f32; 2], String)> {
        let shown: Vec<([f32; 2], String)> = capture
            .objects
            .iter()
            .zip(points)
            .filter_map(|(o, p)| {
                let text = self.labels.get(&o.name)?;
                Some(((*p)?, text.get(lang).to_owned()))
            })
            .collect();
        if shown.len() >= 2 { shown } else { Vec::new() }
    }
}
