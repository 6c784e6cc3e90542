//! A lesson being played: the step on screen, the time into its animations, whether its answer
//! is shown and what the check of its typed answer said.

use std::sync::Arc;

use crate::lesson::Lesson;

/// A lesson being played: which step, and how far into its animations.
#[derive(Clone, Debug)]
pub struct LessonPlayer {
    /// The lesson.
    pub lesson: Arc<Lesson>,
    /// The current step.
    pub step: usize,
    /// Seconds into the step's animations.
    pub time: f32,
    /// Whether the animations are moving.
    pub playing: bool,
    /// Whether the answer to the step's question is shown.
    pub show_answer: bool,
    /// What the check of the step's typed answer said (`None`: not checked on this visit).
    pub verdict: Option<crate::lesson::answer::Verdict>,
}

impl LessonPlayer {
    /// A player of `lesson` at step `step`, paused, nothing shown or checked yet.
    #[must_use]
    pub fn new(lesson: Arc<Lesson>, step: usize) -> Self {
        Self {
            lesson,
            step,
            time: 0.0,
            playing: false,
            show_answer: false,
            verdict: None,
        }
    }

    /// The current step.
    #[must_use]
    pub fn current(&self) -> &crate::lesson::Step {
        &self.lesson.steps[self.step]
    }
}
