//! A new lesson's first text: the template `pipelens new-lesson` writes (every key a step can
//! take, with comments), the same with a mesh of one's own in place of its sphere, or the scene
//! on screen — a scene file's with its comments, a lesson's without its (they speak of that
//! lesson's steps) — and one step recorded from what is on screen. Each reads back through
//! `check` as a lesson.

use std::path::Path;

use toml_edit::visit_mut::{self, VisitMut};
use toml_edit::{Decor, Item, KeyMut, Table, value};

use super::Step;
use super::record::{self, document, replace, step_table};
use crate::vocabulary::Text;

/// The template of a new lesson (`assets/templates/new-lesson.toml`).
pub const NEW_LESSON: &str = include_str!("../../assets/templates/new-lesson.toml");

/// The template of a new lab (`assets/templates/new-lab.toml`).
pub const NEW_LAB: &str = include_str!("../../assets/templates/new-lab.toml");

/// The lesson's id a file's name gives: its name without `.toml`.
///
/// # Errors
/// When the file does not end in `.toml`, or its name could not be a TOML string as written.
pub fn id_of(file: &Path) -> Result<String, String> {
    if file.extension().is_none_or(|e| e != "toml") {
        return Err(format!(
            "{}: a lesson file ends in .toml, e.g. lessons/20-my-lesson.toml",
            file.display()
        ));
    }
    file.file_stem()
        .and_then(|s| s.to_str())
        .filter(|s| !s.is_empty() && !s.contains('"') && !s.contains('\\'))
        .map(str::to_owned)
        .ok_or_else(|| {
            format!(
                "{}: the file's name becomes the lesson's id; use letters, digits and -",
                file.display()
            )
        })
}

/// The template (a lab's with `lab`) for the lesson file `file`.
///
/// # Errors
/// See [`id_of`].
pub fn from_template(file: &Path, lab: bool) -> Result<String, String> {
    let id = id_of(file)?;
    Ok(if lab { NEW_LAB } else { NEW_LESSON }
        .replace("{id}", &id)
        .replace("{file}", &file.display().to_string()))
}

/// The template for `file` with the mesh file `mesh` (a path from the lesson's folder, or
/// absolute) in place of its sphere, fitted into the unit sphere, and the template's first step
/// only (the rest are for the teacher to record).
///
/// # Errors
/// See [`id_of`].
pub fn from_mesh(file: &Path, mesh: &str) -> Result<String, String> {
    let mut doc = document(&from_template(file, false)?)?;
    let objects = doc["scene"]["objects"]
        .as_array_of_tables_mut()
        .ok_or("the template has no objects")?;
    let model = objects
        .iter_mut()
        .find(|o| o.get("name").and_then(Item::as_str) == Some("model"))
        .ok_or("the template has no object named model")?;
    let name = Path::new(mesh)
        .file_stem()
        .map_or_else(|| "model".to_owned(), |s| s.to_string_lossy().into_owned());
    replace(model, "mesh", value(mesh));
    replace(model, "label", value(text(&name, &name)));
    let steps = doc["steps"]
        .as_array_of_tables_mut()
        .ok_or("the template has no steps")?;
    while steps.len() > 1 {
        steps.remove(1);
    }
    Ok(doc.to_string())
}

/// The lesson `source` (a built-in lesson's text, say) as the lesson file `file`: the same,
/// its id the file's name.
///
/// # Errors
/// When `source` is not a lesson file's TOML, or see [`id_of`].
pub fn renamed(source: &str, file: &Path) -> Result<String, String> {
    let id = id_of(file)?;
    let mut doc = document(source)?;
    let header = doc
        .get_mut("lesson")
        .and_then(Item::as_table_mut)
        .ok_or("the file has no [lesson]")?;
    replace(header, "id", value(id.as_str()));
    Ok(doc.to_string())
}

/// A lesson for `file` on the scene of `source` (a lesson's or a scene file's text), its
/// `[lesson]` header new, its steps replaced by `step`. A scene file's comments are kept; a
/// lesson's are not: they explain that lesson's header, lights and steps ("the light that
/// makes step 3's highlight"), which the new lesson does not have.
///
/// # Errors
/// When `source` is not TOML, `file` is not a lesson file's name (see [`id_of`]) or `step`
/// cannot be written (see [`step_table`]).
pub fn from_scene(source: &str, file: &Path, step: &Step) -> Result<String, String> {
    let id = id_of(file)?;
    let mut doc = document(source)?;
    if doc.contains_key("lesson") {
        Uncomment.visit_document_mut(&mut doc);
        let trailing = uncommented(doc.trailing().as_str().unwrap_or_default());
        doc.set_trailing(trailing);
    }
    doc.remove("steps");
    // A lesson's `[comments]` translate its shaders' comments: with no shader left in the
    // scene (a recorded step holds none), they belong to the old lesson.
    if !scene_has_shaders(&doc) {
        doc.remove("comments");
    }
    let mut header = Table::new();
    header.insert("id", value(id.as_str()));
    let [[title_en, title_zh], [summary_en, summary_zh]] = super::PLACEHOLDER_LESSON;
    header.insert("title", value(text(title_en, title_zh)));
    header.insert("summary", value(text(summary_en, summary_zh)));
    header.insert("prerequisites", value(toml_edit::Array::new()));
    match doc.get_mut("lesson").and_then(Item::as_table_mut) {
        // A lesson's header keeps its place; its keys are the new lesson's.
        Some(old) => {
            old.clear();
            old.extend(header.iter().map(|(k, v)| (k.to_owned(), v.clone())));
        }
        None => {
            // First in the file, as the template has it.
            header.set_position(Some(-1));
            doc.insert("lesson", Item::Table(header));
        }
    }
    let mut steps = toml_edit::ArrayOfTables::new();
    steps.push(step_table(step)?);
    doc.insert("steps", Item::ArrayOfTables(steps));
    // The old first comment's line gone, the file starts at its header.
    Ok(doc.to_string().trim_start().to_owned())
}

/// Whether the scene of `doc` runs shaders of its own: `shader` on the scene or an object.
fn scene_has_shaders(doc: &toml_edit::DocumentMut) -> bool {
    let Some(scene) = doc.get("scene").and_then(Item::as_table_like) else {
        return false;
    };
    scene.contains_key("shader")
        || scene
            .get("objects")
            .and_then(Item::as_array_of_tables)
            .is_some_and(|objects| objects.iter().any(|o| o.contains_key("shader")))
}

/// `{ en = "…", zh = "…" }`.
fn text(en: &str, zh: &str) -> toml_edit::InlineTable {
    record::text(&Text::new(en, zh))
}

/// Takes every comment out of a document, its blank lines kept.
struct Uncomment;

impl VisitMut for Uncomment {
    fn visit_table_mut(&mut self, node: &mut Table) {
        uncomment(node.decor_mut());
        visit_mut::visit_table_mut(self, node);
    }

    fn visit_table_like_kv_mut(&mut self, mut key: KeyMut<'_>, node: &mut Item) {
        uncomment(key.leaf_decor_mut());
        uncomment(key.dotted_decor_mut());
        visit_mut::visit_table_like_kv_mut(self, key, node);
    }

    fn visit_array_mut(&mut self, node: &mut toml_edit::Array) {
        let trailing = uncommented(node.trailing().as_str().unwrap_or_default());
        node.set_trailing(trailing);
        visit_mut::visit_array_mut(self, node);
    }

    fn visit_value_mut(&mut self, node: &mut toml_edit::Value) {
        uncomment(node.decor_mut());
        visit_mut::visit_value_mut(self, node);
    }
}

/// `decor` with its comments taken out.
fn uncomment(decor: &mut Decor) {
    let prefix = decor.prefix().and_then(|p| p.as_str()).map(uncommented);
    let suffix = decor.suffix().and_then(|p| p.as_str()).map(uncommented);
    if let Some(p) = prefix {
        decor.set_prefix(p);
    }
    if let Some(s) = suffix {
        decor.set_suffix(s);
    }
}

/// Whitespace and comments (a decor's text) with the comments taken out: a line of comment
/// goes with its line break (a comment after a value is its decor's whole text); blank lines
/// stay.
fn uncommented(text: &str) -> String {
    text.split_inclusive('\n')
        .filter(|line| !line.trim_start().starts_with('#'))
        .collect()
}
