//! A lesson being edited in the app (issue 36): its file's text, changed by the teacher's
//! clicks — a step recorded from the screen or updated from it, steps duplicated, deleted and
//! moved, the words typed — each change through `toml_edit`, so that every line a change does
//! not touch stays as the teacher wrote it (comments, order, formatting). Every change can be
//! undone and redone; the steps changed since the last save are known; the text is what a save
//! writes. Nothing here touches a file: the app saves, keeps the recovery copy and asks before
//! overwriting a file changed on disk.

mod order;

use std::path::Path;

use toml_edit::{DocumentMut, Item, Table, value};

use super::folder::Folder;
use super::record::{
    VIEW_KEYS, commented, document as parse, put_step, replace, step_table, steps_mut, view_items,
};
use super::script::{Lesson, parse_lesson_in};
use super::{Diagnostics, Step};
use crate::vocabulary::{Lang, Text};
use order::{in_order, renumber};

/// The words of a step the editor types, each in both languages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Words {
    /// `title`, shown on the step's card.
    Title,
    /// `narration`, what the card says.
    Narration,
    /// `question`, asked before the answer is shown (optional).
    Question,
    /// `answer`, shown on request (optional).
    Answer,
    /// The lesson's own `title`, in `[lesson]` (the step `at` it is asked with is not read).
    LessonTitle,
    /// The lesson's `summary`, in `[lesson]`.
    Summary,
}

impl Words {
    /// A step's four, in the card's order.
    pub const ALL: [Self; 4] = [Self::Title, Self::Narration, Self::Question, Self::Answer];

    /// The key in a `[[steps]]` table.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::Title | Self::LessonTitle => "title",
            Self::Narration => "narration",
            Self::Question => "question",
            Self::Answer => "answer",
            Self::Summary => "summary",
        }
    }

    /// Whether the file must have it, in both languages.
    #[must_use]
    pub fn required(self) -> bool {
        !matches!(self, Self::Question | Self::Answer)
    }

    /// Whether it is the lesson's (in `[lesson]`) rather than a step's.
    #[must_use]
    pub fn of_lesson(self) -> bool {
        matches!(self, Self::LessonTitle | Self::Summary)
    }
}

/// One state of the document: its text and which step is which (steps keep their identity
/// across moves, so "changed since the last save" follows a step that moved).
#[derive(Clone, Debug, PartialEq)]
struct State {
    text: String,
    ids: Vec<u64>,
}

/// A lesson file being edited.
#[derive(Clone, Debug)]
pub struct Draft {
    now: State,
    /// Each step of the last save (or of the file as opened): its id and its table as text.
    saved: Vec<(u64, String)>,
    saved_text: String,
    undo: Vec<State>,
    redo: Vec<State>,
    /// The words last typed into (step id, which words, which language): typing on in the same
    /// box is one change to undo, not one per key.
    typing: Option<(u64, Words, Lang)>,
    next_id: u64,
    /// Counts the changes (undone and redone ones too) and the saves: what the words and the
    /// marks on screen were drawn from is known.
    revision: u64,
    /// The name diagnostics give the file, and the folder its meshes and shaders are read from.
    name: String,
    base: Folder,
}

impl Draft {
    /// A draft of the lesson file `text`, as saved (`name` for messages, `base` for the files it
    /// names).
    ///
    /// # Errors
    /// When `text` is not TOML or has no `[[steps]]`.
    pub fn new(text: &str, name: &str, base: &Path) -> Result<Self, String> {
        Self::in_folder(text, name, Folder::on_disk(base))
    }

    /// A draft of the lesson file `text` whose files are read from `base` (a page's: the files
    /// it was given).
    ///
    /// # Errors
    /// When `text` is not TOML or has no `[[steps]]`.
    pub fn in_folder(text: &str, name: &str, base: Folder) -> Result<Self, String> {
        let n = steps_of(&parse(text)?)?.len();
        let mut d = Self {
            now: State {
                text: text.to_owned(),
                ids: (0..n as u64).collect(),
            },
            saved: Vec::new(),
            saved_text: String::new(),
            undo: Vec::new(),
            redo: Vec::new(),
            typing: None,
            next_id: n as u64,
            revision: 0,
            name: name.to_owned(),
            base,
        };
        d.mark_saved();
        Ok(d)
    }

    /// The file's text as edited.
    #[must_use]
    pub fn text(&self) -> &str {
        &self.now.text
    }

    /// A number that changes with every change to the text (undone and redone ones too) and
    /// with every save (which changes what counts as changed).
    #[must_use]
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The text of the last save (or as opened).
    #[must_use]
    pub fn saved_text(&self) -> &str {
        &self.saved_text
    }

    /// The name diagnostics give the file.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// How many steps the lesson has.
    #[must_use]
    pub fn len(&self) -> usize {
        self.now.ids.len()
    }

    /// Whether it has no steps (a lesson always has one; only a broken file has none).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.now.ids.is_empty()
    }

    /// The lesson as the text now reads, with every problem `pipelens check` would report.
    ///
    /// # Errors
    /// The diagnostics, file:line:column, when the text is not a valid lesson.
    pub fn lesson(&self) -> Result<Lesson, Diagnostics> {
        parse_lesson_in(&self.now.text, &self.name, &self.base)
    }

    /// Whether the text differs from the last save.
    #[must_use]
    pub fn is_dirty(&self) -> bool {
        self.now.text != self.saved_text
    }

    /// The text is now what is on disk: nothing has changed since.
    pub fn mark_saved(&mut self) {
        self.saved_text = self.now.text.clone();
        self.saved = self
            .now
            .ids
            .iter()
            .zip(step_texts(&self.now.text))
            .map(|(&id, t)| (id, t))
            .collect();
        self.typing = None;
        self.revision += 1;
    }

    /// Whether step `at` changed since the last save: new, moved, or edited.
    #[must_use]
    pub fn changed(&self, at: usize) -> bool {
        self.changed_steps().get(at).copied().unwrap_or(false)
    }

    /// For each step, whether it changed since the last save: it is new, its words or view
    /// differ, or it moved. A step moved is one outside the longest run of saved steps still in
    /// their saved order (moving one step marks that step, not the ones it passed; a deletion
    /// or a copy moves nothing).
    #[must_use]
    pub fn changed_steps(&self) -> Vec<bool> {
        let now = step_texts(&self.now.text);
        let saved_at = |id: &u64| self.saved.iter().position(|(i, _)| i == id);
        let ranks: Vec<Option<usize>> = self.now.ids.iter().map(saved_at).collect();
        let kept = in_order(&ranks);
        ranks
            .iter()
            .enumerate()
            .map(|(at, rank)| match rank {
                Some(k) => !kept[at] || now.get(at) != Some(&self.saved[*k].1),
                None => true,
            })
            .collect()
    }

    /// How many steps of the last save are gone.
    #[must_use]
    pub fn deleted(&self) -> usize {
        self.saved
            .iter()
            .filter(|(id, _)| !self.now.ids.contains(id))
            .count()
    }

    /// Whether there is a change to undo / to redo.
    #[must_use]
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// See [`Self::can_undo`].
    #[must_use]
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// Goes back one change; `false` when there was none.
    pub fn undo(&mut self) -> bool {
        self.step_back(true)
    }

    /// Takes again the change last undone; `false` when there was none.
    pub fn redo(&mut self) -> bool {
        self.step_back(false)
    }

    /// Takes back the change last made, leaving nothing to redo: a change the app refuses (its
    /// lesson would not check) leaves no trace.
    pub fn discard_last(&mut self) -> bool {
        let Some(state) = self.undo.pop() else {
            return false;
        };
        self.now = state;
        self.typing = None;
        self.revision += 1;
        true
    }

    fn step_back(&mut self, undo: bool) -> bool {
        let (from, to) = if undo {
            (&mut self.undo, &mut self.redo)
        } else {
            (&mut self.redo, &mut self.undo)
        };
        let Some(state) = from.pop() else {
            return false;
        };
        to.push(std::mem::replace(&mut self.now, state));
        self.typing = None;
        self.revision += 1;
        true
    }

    /// Replaces the whole text (the recovery copy restored, or the file as it is now on disk),
    /// as one change that can be undone.
    ///
    /// # Errors
    /// When `text` is not TOML or has no `[[steps]]`.
    pub fn replace_text(&mut self, text: &str) -> Result<(), String> {
        let n = steps_of(&parse(text)?)?.len();
        let ids = (0..n)
            .map(|k| {
                self.now.ids.get(k).copied().unwrap_or_else(|| {
                    self.next_id += 1;
                    self.next_id
                })
            })
            .collect();
        self.commit(
            State {
                text: text.to_owned(),
                ids,
            },
            None,
        );
        Ok(())
    }

    /// `step` (recorded from the screen) as step `at`, before the one there.
    ///
    /// # Errors
    /// See [`super::record::insert_step`].
    pub fn insert(&mut self, at: usize, step: &Step) -> Result<(), String> {
        let at = at.min(self.len());
        let table = step_table(step)?;
        let id = self.new_id();
        self.change(None, |doc, ids| {
            put_step(steps_mut(doc)?, at, table);
            ids.insert(at, id);
            Ok(())
        })
    }

    /// Step `at` shows what `step` shows: its stage, buffer, layout, overlays, pixel, vertex,
    /// framing, `set` and `animate` ([`VIEW_KEYS`]) are `step`'s; its words, shaders, exercise
    /// and typed answer are kept.
    ///
    /// # Errors
    /// When there is no step `at`.
    pub fn update(&mut self, at: usize, step: &Step) -> Result<(), String> {
        let items = view_items(step);
        self.change(None, |doc, _| {
            let t = step_mut(doc, at)?;
            for key in VIEW_KEYS {
                match items.iter().find(|(k, _)| *k == key) {
                    Some((_, item)) => replace(t, key, item.clone()),
                    None => {
                        t.remove(key);
                    }
                }
            }
            Ok(())
        })
    }

    /// A copy of step `at` right after it.
    ///
    /// # Errors
    /// When there is no step `at`.
    pub fn duplicate(&mut self, at: usize) -> Result<(), String> {
        let id = self.new_id();
        self.change(None, |doc, ids| {
            let steps = steps_mut(doc)?;
            let mut copy = steps.get(at).ok_or_else(|| no_step(at))?.clone();
            // The comments above the step stay with the original.
            copy.decor_mut().set_prefix("\n");
            steps.insert(at + 1, copy);
            ids.insert(at + 1, id);
            renumber(steps, &(0..steps.len()).collect::<Vec<_>>());
            Ok(())
        })
    }

    /// Step `at` removed, with the comments above it.
    ///
    /// # Errors
    /// When there is no step `at`, or it is the only one (a lesson has at least one step).
    pub fn delete(&mut self, at: usize) -> Result<(), String> {
        if self.len() <= 1 {
            return Err("a lesson keeps at least one step".to_owned());
        }
        self.change(None, |doc, ids| {
            let steps = steps_mut(doc)?;
            if at >= steps.len() {
                return Err(no_step(at));
            }
            steps.remove(at);
            ids.remove(at);
            Ok(())
        })
    }

    /// Step `from` moved to be step `to`, with the comments above it.
    ///
    /// # Errors
    /// When there is no step `from` or `to`.
    pub fn move_step(&mut self, from: usize, to: usize) -> Result<(), String> {
        if from == to {
            return Ok(());
        }
        self.change(None, |doc, ids| {
            let steps = steps_mut(doc)?;
            let n = steps.len();
            if from >= n || to >= n {
                return Err(no_step(from.max(to)));
            }
            let mut order: Vec<usize> = (0..n).collect();
            let k = order.remove(from);
            order.insert(to, k);
            let id = ids.remove(from);
            ids.insert(to, id);
            renumber(steps, &order);
            Ok(())
        })
    }

    /// The words `which` of step `at` (or of the lesson), in both languages, as the file has them
    /// now (empty when it has none).
    #[must_use]
    pub fn words(&self, at: usize, which: Words) -> Text {
        let doc = parse(&self.now.text).ok();
        let table = doc.as_ref().and_then(|d| {
            if which.of_lesson() {
                d.get("lesson").and_then(Item::as_table)
            } else {
                d.get("steps")
                    .and_then(Item::as_array_of_tables)
                    .and_then(|s| s.get(at))
            }
        });
        let item = table.and_then(|t| t.get(which.key()));
        let read = |lang: &str| {
            item.and_then(|i| i.get(lang))
                .and_then(Item::as_str)
                .unwrap_or_default()
                .to_owned()
        };
        Text::new(read("en"), read("zh"))
    }

    /// The words `which` of step `at` (or of the lesson) in `lang` are `words`. Typing on in the
    /// same box is one change to undo. An optional text (question, answer) empty in both languages is removed.
    ///
    /// # Errors
    /// When there is no step `at`.
    pub fn set_words(
        &mut self,
        at: usize,
        which: Words,
        lang: Lang,
        words: &str,
    ) -> Result<(), String> {
        // The lesson's words are typed in boxes of their own, whichever step is on screen.
        let id = if which.of_lesson() {
            u64::MAX
        } else {
            *self.now.ids.get(at).ok_or_else(|| no_step(at))?
        };
        let key = if lang == Lang::EN { "en" } else { "zh" };
        let other = if lang == Lang::EN { "zh" } else { "en" };
        self.change(Some((id, which, lang)), |doc, _| {
            let t = if which.of_lesson() {
                doc.get_mut("lesson")
                    .and_then(Item::as_table_mut)
                    .ok_or("the lesson file has no [lesson]")?
            } else {
                step_mut(doc, at)?
            };
            let name = which.key();
            let empty_other = t
                .get(name)
                .and_then(|i| i.get(other))
                .and_then(Item::as_str)
                .is_none_or(|s| s.trim().is_empty());
            if !which.required() && words.trim().is_empty() && empty_other {
                t.remove(name);
                return Ok(());
            }
            match t.get_mut(name) {
                Some(Item::Table(inner)) => replace(inner, key, value(words)),
                Some(Item::Value(toml_edit::Value::InlineTable(inner))) => {
                    let v = commented(inner.get(key), words.into());
                    inner.insert(key, v);
                }
                _ => {
                    // Written as the template writes narration: `question.en = "…"`.
                    let mut inner = Table::new();
                    inner.set_dotted(true);
                    inner.insert(key, value(words));
                    t.insert(name, Item::Table(inner));
                }
            }
            Ok(())
        })
    }

    fn new_id(&mut self) -> u64 {
        self.next_id += 1;
        self.next_id
    }

    /// Applies `edit` to the document and its step ids as one change to undo (or, while
    /// `typing` is the box typed in last, as part of the change before).
    fn change(
        &mut self,
        typing: Option<(u64, Words, Lang)>,
        edit: impl FnOnce(&mut DocumentMut, &mut Vec<u64>) -> Result<(), String>,
    ) -> Result<(), String> {
        let mut doc = parse(&self.now.text)?;
        let mut ids = self.now.ids.clone();
        edit(&mut doc, &mut ids)?;
        let text = doc.to_string();
        if text == self.now.text && ids == self.now.ids {
            return Ok(());
        }
        self.commit(State { text, ids }, typing);
        Ok(())
    }

    fn commit(&mut self, state: State, typing: Option<(u64, Words, Lang)>) {
        let goes_on = typing.is_some() && typing == self.typing;
        let before = std::mem::replace(&mut self.now, state);
        if !goes_on {
            self.undo.push(before);
        }
        self.redo.clear();
        self.typing = typing;
        self.revision += 1;
    }
}

fn steps_of(doc: &DocumentMut) -> Result<&toml_edit::ArrayOfTables, String> {
    doc.get("steps")
        .and_then(Item::as_array_of_tables)
        .ok_or_else(|| "the lesson file has no [[steps]]".to_owned())
}

fn step_mut(doc: &mut DocumentMut, at: usize) -> Result<&mut Table, String> {
    steps_mut(doc)?.get_mut(at).ok_or_else(|| no_step(at))
}

fn no_step(at: usize) -> String {
    format!("the lesson has no step {}", at + 1)
}

/// Each step's table as text, to tell which changed.
fn step_texts(text: &str) -> Vec<String> {
    parse(text)
        .ok()
        .and_then(|d| {
            steps_of(&d)
                .ok()
                .map(|s| s.iter().map(ToString::to_string).collect())
        })
        .unwrap_or_default()
}
