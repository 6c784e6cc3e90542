//! What a student has done, kept across runs: in each lesson, the questions answered right by
//! typing their value (`expect`), and what was last typed into each field. The app keeps it in
//! its storage (on the desktop a file in the user's data folder, in the browser the page's
//! local storage) under [`Progress::KEY`]; the Lessons menu shows it.

use std::collections::{BTreeMap, BTreeSet};

use serde::{Deserialize, Serialize};

use pipeline::shader::HookKind;

use crate::lesson::Lesson;
use crate::lesson::answer::Verdict;

/// Everything a student has done, by lesson id.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Progress {
    /// Each lesson's record, by the lesson's `id`.
    pub lessons: BTreeMap<String, LessonProgress>,
}

/// What a student has done in one lesson. Steps are counted from 1, as the app shows them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(from = "StoredLessonProgress")]
pub struct LessonProgress {
    /// The steps whose typed answer was right.
    pub answered: BTreeSet<usize>,
    /// What was last typed into each step's field, cell by cell.
    pub typed: BTreeMap<usize, Vec<String>>,
    /// The exercise steps whose every pixel matched pipelens' own.
    pub passed: BTreeSet<usize>,
    /// The shaders (vertex, fragment) the student last ran in each exercise step.
    pub code: BTreeMap<usize, (String, String)>,
    /// The functions the pipeline calls (the inside test, the depth test, …) the student last
    /// ran in each exercise step, by the function's lesson key ([`HookKind::key`]) and step. A
    /// key this version does not know (kept by a newer one) is kept as it is.
    pub functions: BTreeMap<String, BTreeMap<usize, String>>,
}

/// A lesson's record as storage holds it: this version's, or the first one's, which kept each
/// kind of function in a field of its own (`inside`, `depth_test`, `curve`, `shadow_matrix`,
/// `bezier_patch`). Read into a [`LessonProgress`]; what is written is always this version's.
#[derive(Default, Deserialize)]
#[serde(default)]
struct StoredLessonProgress {
    answered: BTreeSet<usize>,
    typed: BTreeMap<usize, Vec<String>>,
    passed: BTreeSet<usize>,
    code: BTreeMap<usize, (String, String)>,
    functions: BTreeMap<String, BTreeMap<usize, String>>,
    // The first version's fields, frozen as it wrote them.
    inside: BTreeMap<usize, String>,
    depth_test: BTreeMap<usize, String>,
    curve: BTreeMap<usize, String>,
    shadow_matrix: BTreeMap<usize, String>,
    bezier_patch: BTreeMap<usize, String>,
}

impl From<StoredLessonProgress> for LessonProgress {
    fn from(s: StoredLessonProgress) -> Self {
        let mut functions = s.functions;
        for (kind, by_step) in [
            (HookKind::Inside, s.inside),
            (HookKind::DepthTest, s.depth_test),
            (HookKind::Curve, s.curve),
            (HookKind::ShadowMatrix, s.shadow_matrix),
            (HookKind::Patch, s.bezier_patch),
        ] {
            if !by_step.is_empty() {
                let kept = functions.entry(kind.key().to_owned()).or_default();
                for (step, source) in by_step {
                    kept.entry(step).or_insert(source);
                }
            }
        }
        Self {
            answered: s.answered,
            typed: s.typed,
            passed: s.passed,
            code: s.code,
            functions,
        }
    }
}

impl LessonProgress {
    /// The source of the student's function of kind `kind` last run in step `step` (1-based).
    fn function(&self, kind: HookKind, step: usize) -> Option<&String> {
        self.functions.get(kind.key())?.get(&step)
    }
}

/// The code a student ran in an exercise step: the shaders, the functions the pipeline calls,
/// or both.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SavedCode {
    /// The vertex and fragment shaders' sources.
    pub shaders: Option<(String, String)>,
    /// The functions' sources, by kind (in [`HookKind::ALL`]'s order).
    pub hooks: Vec<(HookKind, String)>,
}

impl Progress {
    /// The key the app's storage keeps the progress under.
    pub const KEY: &'static str = "pipelens-progress";

    /// The progress kept in the app's storage (none kept, or no storage: nothing done yet).
    #[must_use]
    pub fn load(storage: Option<&dyn eframe::Storage>) -> Self {
        storage
            .and_then(|s| eframe::get_value(s, Self::KEY))
            .unwrap_or_default()
    }

    /// Keeps the progress in the app's storage (written to disk, or to the page's local
    /// storage, by eframe), merged with what is kept there already: another window or tab of
    /// the app saves into the same storage, and neither may undo what the other recorded.
    pub fn save(&self, storage: &mut dyn eframe::Storage) {
        let mut kept = Self::load(Some(&*storage));
        kept.merge(self);
        eframe::set_value(storage, Self::KEY, &kept);
    }

    /// Adds `other`'s record to this one: steps answered or passed in either stay so; what was
    /// typed and the code run are `other`'s where it has them.
    pub fn merge(&mut self, other: &Self) {
        for (id, theirs) in &other.lessons {
            let mine = self.lessons.entry(id.clone()).or_default();
            mine.answered.extend(theirs.answered.iter().copied());
            mine.passed.extend(theirs.passed.iter().copied());
            mine.typed
                .extend(theirs.typed.iter().map(|(k, v)| (*k, v.clone())));
            mine.code
                .extend(theirs.code.iter().map(|(k, v)| (*k, v.clone())));
            for (key, by_step) in &theirs.functions {
                let theirs = by_step.iter().map(|(k, v)| (*k, v.clone()));
                mine.functions
                    .entry(key.clone())
                    .or_default()
                    .extend(theirs);
            }
        }
    }

    /// What was typed into step `k`'s (0-based) field of `lesson`, `cells` long.
    #[must_use]
    pub fn typed(&self, lesson: &Lesson, k: usize, cells: usize) -> Vec<String> {
        let mut t = self
            .lessons
            .get(&lesson.id)
            .and_then(|l| l.typed.get(&(k + 1)))
            .cloned()
            .unwrap_or_default();
        t.resize(cells, String::new());
        t
    }

    /// Keeps `text` as cell `cell` of step `k`'s (0-based) field, `cells` long.
    pub fn type_cell(
        &mut self,
        lesson: &Lesson,
        (k, cell, cells): (usize, usize, usize),
        text: String,
    ) {
        let mut t = self.typed(lesson, k, cells);
        if let Some(c) = t.get_mut(cell) {
            *c = text;
        }
        self.lessons
            .entry(lesson.id.clone())
            .or_default()
            .typed
            .insert(k + 1, t);
    }

    /// Checks step `k`'s (0-based) typed answer against its `expect`, and remembers the step
    /// as answered when it is right; `None` when the step expects nothing.
    pub fn check(&mut self, lesson: &Lesson, k: usize) -> Option<Verdict> {
        let expect = lesson.steps.get(k)?.expect.as_ref()?;
        let typed = self.typed(lesson, k, expect.shape.cells());
        // Several numbers typed into one box go into the boxes after it, as they are read.
        if let Ok(cells) = expect.spread(&typed)
            && cells != typed
        {
            self.lessons
                .entry(lesson.id.clone())
                .or_default()
                .typed
                .insert(k + 1, cells);
        }
        let verdict = expect.check(&typed);
        if verdict == Verdict::Right {
            self.lessons
                .entry(lesson.id.clone())
                .or_default()
                .answered
                .insert(k + 1);
        }
        Some(verdict)
    }

    /// Keeps the code the student ran in exercise step `k` (0-based), and the step as passed
    /// when every pixel matched.
    pub fn keep_code(&mut self, lesson: &Lesson, k: usize, code: SavedCode, passed: bool) {
        let l = self.lessons.entry(lesson.id.clone()).or_default();
        if let Some(shaders) = code.shaders {
            l.code.insert(k + 1, shaders);
        }
        for (kind, source) in code.hooks {
            l.functions
                .entry(kind.key().to_owned())
                .or_default()
                .insert(k + 1, source);
        }
        if passed {
            l.passed.insert(k + 1);
        }
    }

    /// The code the student last ran in exercise step `k` (0-based), if any was kept.
    #[must_use]
    pub fn code(&self, lesson: &Lesson, k: usize) -> Option<SavedCode> {
        let l = self.lessons.get(&lesson.id)?;
        let code = SavedCode {
            shaders: l.code.get(&(k + 1)).cloned(),
            hooks: HookKind::ALL
                .into_iter()
                .filter_map(|kind| Some((kind, l.function(kind, k + 1)?.clone())))
                .collect(),
        };
        (code != SavedCode::default()).then_some(code)
    }

    /// Whether exercise step `k` (0-based) was passed.
    #[must_use]
    pub fn passed(&self, lesson: &Lesson, k: usize) -> bool {
        self.lessons
            .get(&lesson.id)
            .is_some_and(|l| l.passed.contains(&(k + 1)))
    }

    /// Whether step `k`'s (0-based) question was answered right.
    #[must_use]
    pub fn answered(&self, lesson: &Lesson, k: usize) -> bool {
        self.lessons
            .get(&lesson.id)
            .is_some_and(|l| l.answered.contains(&(k + 1)))
    }

    /// `(done, of)`: how many of the lesson's questions with a value to type were answered
    /// right and exercises passed, of how many.
    #[must_use]
    pub fn done(&self, lesson: &Lesson) -> (usize, usize) {
        let asks: Vec<usize> = (0..lesson.steps.len())
            .filter(|&k| lesson.steps[k].expect.is_some() || lesson.steps[k].exercise.is_some())
            .collect();
        let done = asks
            .iter()
            .filter(|&&k| self.answered(lesson, k) || self.passed(lesson, k))
            .count();
        (done, asks.len())
    }

    /// The progress of `id`'s lesson, as kept (for the Lessons menu, which lists lessons not
    /// loaded).
    #[must_use]
    pub fn of(&self, id: &str) -> Option<&LessonProgress> {
        self.lessons.get(id)
    }
}

/// The student's work on `lesson` as one file's content: each step's code last run and what
/// was typed into its answer's boxes (steps with neither left out).
#[must_use]
pub fn work(progress: &Progress, lesson: &Lesson) -> crate::lab::submission::Work {
    use crate::lab::submission::{Code, StepWork, Work};
    let mut work = Work {
        lesson: lesson.id.clone(),
        ..Work::default()
    };
    for (k, step) in lesson.steps.iter().enumerate() {
        let mut code = Code::default();
        if let Some(saved) = progress.code(lesson, k) {
            if let Some((vertex, fragment)) = saved.shaders {
                code.take("shader.vert", vertex);
                code.take("shader.frag", fragment);
            }
            for (kind, source) in saved.hooks {
                code.take(&format!("{}.glsl", kind.key()), source);
            }
        }
        let answers = step
            .expect
            .as_ref()
            .map(|e| progress.typed(lesson, k, e.shape.cells()))
            .filter(|t| t.iter().any(|c| !c.trim().is_empty()))
            .unwrap_or_default();
        if !code.is_empty() || !answers.is_empty() {
            work.steps.insert(
                k + 1,
                StepWork {
                    title: step.title.en.clone(),
                    code,
                    answers,
                },
            );
        }
    }
    work
}
