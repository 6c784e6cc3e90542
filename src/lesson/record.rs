//! Writing a step into a lesson file, as a teacher's "Add step" records it from what is on screen:
//! the step becomes a `[[steps]]` table appended to the file with `toml_edit`, so that every other
//! line — the teacher's comments, order and formatting — stays byte for byte as it was, and the
//! file still reads as the same lesson with one more step.

use toml_edit::{Array, DocumentMut, InlineTable, Item, Table, value};

use super::Step;
use super::param::{Animation, Easing, Repeat, Value};
use super::script::{LAYOUTS, Layout, OVERLAYS};
use crate::vocabulary::{Lang, Text};

/// `text`, a lesson file, with `step` appended as its last `[[steps]]`.
///
/// # Errors
/// When `text` is not TOML, has no `[[steps]]` array, `step` has no narration in one of the two
/// languages yet, or it holds what a recorded step cannot (shaders, an exercise or a typed
/// answer: those are written by hand).
pub fn append_step(text: &str, step: &Step) -> Result<String, String> {
    insert_step(text, usize::MAX, step)
}

/// `text`, a lesson file, with `step` as its step `at` (counted from 0; past the end: the last),
/// before the step that was there and that step's comments.
///
/// # Errors
/// See [`append_step`].
pub fn insert_step(text: &str, at: usize, step: &Step) -> Result<String, String> {
    let mut doc = document(text)?;
    let table = step_table(step)?;
    put_step(steps_mut(&mut doc)?, at, table);
    Ok(doc.to_string())
}

/// `text` read as a TOML document to edit.
///
/// # Errors
/// When it is not TOML.
pub(super) fn document(text: &str) -> Result<DocumentMut, String> {
    text.parse()
        .map_err(|e| format!("the lesson file is not TOML: {e}"))
}

/// The document's `[[steps]]`.
///
/// # Errors
/// When it has none.
pub(super) fn steps_mut(doc: &mut DocumentMut) -> Result<&mut toml_edit::ArrayOfTables, String> {
    doc.get_mut("steps")
        .and_then(Item::as_array_of_tables_mut)
        .ok_or_else(|| "the lesson file has no [[steps]]".to_owned())
}

/// `new` with the comment and spacing around the value `old` it replaces.
pub(super) fn commented(
    old: Option<&toml_edit::Value>,
    mut new: toml_edit::Value,
) -> toml_edit::Value {
    if let Some(old) = old {
        *new.decor_mut() = old.decor().clone();
    }
    new
}

/// `table[key] = item`, the comment after the value it replaces kept.
pub(super) fn replace(table: &mut Table, key: &str, item: Item) {
    let item = match item {
        Item::Value(v) => Item::Value(commented(table.get(key).and_then(Item::as_value), v)),
        other => other,
    };
    table.insert(key, item);
}

/// `table` as step `at` of `steps` (past the end: the last), written in the file where the step
/// it goes before was, before that step's comments (a tie in place goes by order).
pub fn put_step(steps: &mut toml_edit::ArrayOfTables, at: usize, mut table: Table) {
    match steps.get(at).map(Table::position) {
        Some(position) => {
            table.set_position(position);
            steps.insert(at, table);
        }
        None => steps.push(table),
    }
}

/// The languages `text` has no words in yet (blank counts as none).
#[must_use]
pub fn unworded(text: &Text) -> Vec<Lang> {
    [Lang::EN, Lang::ZH]
        .into_iter()
        .filter(|&l| text.get(l).trim().is_empty())
        .collect()
}

/// A `[[steps]]` table holding `step`: what it names, in the order a lesson's author writes it.
///
/// # Errors
/// See [`append_step`].
pub fn step_table(step: &Step) -> Result<Table, String> {
    if step.shader.is_some() || step.exercise.is_some() || step.expect.is_some() {
        return Err(
            "a recorded step has no shaders, exercise or typed answer: write those in the file"
                .to_owned(),
        );
    }
    let mut t = Table::new();
    t.insert("title", value(text(&step.title)));
    // `narration.en = """…"""`, as a lesson's author writes it, in both languages (the file format
    // asks for both).
    let missing: Vec<&str> = unworded(&step.narration)
        .into_iter()
        .map(|l| if l == Lang::EN { "English" } else { "Chinese" })
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "step \"{}\" has no narration in {} yet: a lesson's step needs its words in both languages",
            step.title.en,
            missing.join(" and ")
        ));
    }
    let mut narration = Table::new();
    narration.set_dotted(true);
    for (lang, key) in [(Lang::EN, "en"), (Lang::ZH, "zh")] {
        narration.insert(key, value(step.narration.get(lang)));
    }
    t.insert("narration", Item::Table(narration));
    for (key, item) in view_items(step) {
        t.insert(key, item);
    }
    if let Some(q) = &step.question {
        t.insert("question", value(text(q)));
    }
    if let Some(a) = &step.answer {
        t.insert("answer", value(text(a)));
    }
    Ok(t)
}

/// The keys of a step that say what is on screen — everything "Update step" rewrites from the
/// screen; the words, the shaders, an exercise and a typed answer are not among them.
pub const VIEW_KEYS: [&str; 14] = [
    "stage",
    "layout",
    "compare",
    "buffer",
    "overlays",
    "focus",
    "orbit",
    "pixel",
    "vertex",
    "profile",
    "depth_range",
    "watch",
    "set",
    "animate",
];

/// What `step` shows, as the `[[steps]]` entries of [`VIEW_KEYS`] it has, in the order a
/// lesson's author writes them.
#[must_use]
pub fn view_items(step: &Step) -> Vec<(&'static str, Item)> {
    let mut items = Vec::new();
    if let Some(stage) = step.stage {
        items.push(("stage", value(stage.name(Lang::EN).to_lowercase())));
    }
    if step.layout != Layout::Single && step.compare.is_none() {
        let name = LAYOUTS
            .iter()
            .find(|(_, l)| *l == step.layout)
            .map(|(n, _)| *n);
        items.push(("layout", value(name.unwrap_or("single"))));
    }
    if let Some(c) = step.compare {
        items.push(("compare", value(c.key())));
    }
    if let Some(b) = step.buffer {
        items.push(("buffer", value(b.name())));
    }
    if let Some(overlays) = &step.overlays {
        let names: Array = overlays
            .iter()
            .filter_map(|o| OVERLAYS.iter().find(|(_, k)| k == o).map(|(n, _)| *n))
            .collect();
        items.push(("overlays", value(names)));
    }
    if let Some(focus) = &step.focus {
        items.push((
            "focus",
            value(focus.iter().map(String::as_str).collect::<Array>()),
        ));
    }
    if let Some(o) = step.orbit {
        items.push(("orbit", value(o.map(number).into_iter().collect::<Array>())));
    }
    if let Some((x, y)) = step.pixel {
        items.push((
            "pixel",
            value(Array::from_iter([i64::from(x), i64::from(y)])),
        ));
    }
    if let Some(v) = step.vertex {
        items.push(("vertex", value(i64::from(v))));
    }
    if let Some(p) = step.profile {
        items.push((
            "profile",
            value(p.map(number).into_iter().collect::<Array>()),
        ));
    }
    if let Some(r) = step.depth_range {
        items.push((
            "depth_range",
            value(r.map(number).into_iter().collect::<Array>()),
        ));
    }
    if let Some(watch) = &step.watch {
        items.push(("watch", value(watch.to_string())));
    }
    if !step.set.is_empty() {
        let mut set = InlineTable::new();
        for (name, v) in &step.set {
            set.insert(name, param_value(v));
        }
        items.push(("set", value(set)));
    }
    if !step.animate.is_empty() {
        let list: Array = step.animate.iter().map(animation).collect();
        items.push(("animate", value(list)));
    }
    items
}

/// `{ en = "…", zh = "…" }` and any other language the text has, without a language left
/// empty.
pub(super) fn text(t: &Text) -> InlineTable {
    let mut out = InlineTable::new();
    let others = t.others.iter().map(|(k, v)| (k.as_str(), v));
    for (key, words) in [("en", &t.en), ("zh", &t.zh)].into_iter().chain(others) {
        if !words.is_empty() {
            out.insert(key, words.as_str().into());
        }
    }
    out
}

/// A parameter's value as `set` and `animate` write it.
fn param_value(v: &Value) -> toml_edit::Value {
    match v {
        Value::Number(x) => number(*x),
        Value::Vec2(v) => Array::from_iter(v.to_array().map(number)).into(),
        Value::Vec3(v) => Array::from_iter(v.to_array().map(number)).into(),
        Value::Vec4(v) => Array::from_iter(v.to_array().map(number)).into(),
        Value::Bool(b) => (*b).into(),
        Value::Name(n) => n.as_str().into(),
    }
}

/// A number as the shortest decimal that reads back as the same `f32` (`0.3`, not
/// `0.30000001192092896`); whole numbers as integers.
fn number(x: f32) -> toml_edit::Value {
    if x.fract() == 0.0 && x.abs() < 1e9 {
        (x as i64).into()
    } else {
        format!("{x}").parse::<f64>().unwrap_or(f64::from(x)).into()
    }
}

/// `{ param = "…", from = …, to = …, seconds = …, easing = …, repeat = … }`, the last two only
/// when not the defaults.
fn animation(a: &Animation) -> toml_edit::Value {
    let mut t = InlineTable::new();
    t.insert("param", a.param.as_str().into());
    t.insert("from", param_value(&a.from));
    t.insert("to", param_value(&a.to));
    t.insert("seconds", number(a.seconds));
    if a.easing != Easing::DEFAULT
        && let Some((name, _)) = Easing::NAMES.iter().find(|(_, e)| *e == a.easing)
    {
        t.insert("easing", (*name).into());
    }
    if a.repeat != Repeat::DEFAULT
        && let Some((name, _)) = Repeat::NAMES.iter().find(|(_, r)| *r == a.repeat)
    {
        t.insert("repeat", (*name).into());
    }
    t.into()
}
