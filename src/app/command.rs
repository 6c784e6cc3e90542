//! Everything a panel can ask of the session, by kind: the lesson being played, the lesson file,
//! the scene, how the frame is shown, what is picked in it. Panels return [`Command`]s and never
//! change the session while they draw; `Session::apply` (`session/apply.rs`) applies each kind
//! in one place. No egui in here.

use pipeline::buffers::BufferKind;
use pipeline::overlay::OverlayKind;

use super::selection::DepthView;
use crate::lesson::{Lesson, SceneSpec};
use crate::observer::Orbit;
use crate::vocabulary::{Comparison, Lang, Stage};

/// Everything a panel can ask for, by kind.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// The lesson being played: its steps, its animations, the student's typed answers.
    Lesson(LessonCommand),
    /// The lesson file: reloaded from disk, or revised in the lesson editor.
    Editor(EditorCommand),
    /// The scene and settings drawn.
    Scene(SceneCommand),
    /// How the frame is shown: the stage, the buffer and its overlays, the observer, the compared settings, the depth ramp, the language, the sizes views draw at.
    View(ViewCommand),
    /// What is picked in the picture: a vertex, a pixel, the profile line.
    Selection(SelectionCommand),
}

/// The lesson being played: its steps, its animations, the student's typed answers.
#[derive(Clone, Debug, PartialEq)]
pub enum LessonCommand {
    /// Go to step `k` of the lesson.
    GoToStep(usize),
    /// The lesson's next step (→, Page Down).
    NextStep,
    /// The lesson's previous step (←, Page Up).
    PreviousStep,
    /// Play or pause the step's animations (Space).
    TogglePlay,
    /// Time passes (seconds): animations move.
    Tick(f32),
    /// Show or hide the answer to the step's question.
    ShowAnswer(bool),
    /// The student typed `text` into cell `cell` (row by row) of the step's answer field.
    TypeAnswer {
        /// The cell, row by row from 0.
        cell: usize,
        /// Its whole text now.
        text: String,
    },
    /// Check the step's typed answer against its `expect` (Enter, or the Check button).
    CheckAnswer,
}

/// The lesson file: reloaded from disk, or revised in the lesson editor.
#[derive(Clone, Debug, PartialEq)]
pub enum EditorCommand {
    /// The lesson file changed on disk and loaded: replace it, staying on the same step.
    ReloadLesson(Box<Lesson>),
    /// The lesson as edited in the app, at its step `step`: entered, or (`enter` false, for a
    /// change of words) with the screen kept as it is.
    ReviseLesson {
        /// The lesson as it reads now.
        lesson: Box<Lesson>,
        /// The step to be at.
        step: usize,
        /// Whether the step is entered (its scene and view set as it says).
        enter: bool,
    },
    /// The file changed on disk and is broken (the message), or is fine again (`None`).
    SetReloadError(Option<String>),
}

/// The scene and settings drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneCommand {
    /// Replace the scene and settings (a parameter changed) and render again.
    SetSpec(Box<SceneSpec>),
}

/// How the frame is shown: the stage, the buffer and its overlays, the observer, the compared settings, the depth ramp, the language, the sizes views draw at.
#[derive(Clone, Debug, PartialEq)]
pub enum ViewCommand {
    /// Show a stage.
    SelectStage(Stage),
    /// One stage on (→).
    NextStage,
    /// One stage back (←).
    PreviousStage,
    /// Replay the transition into the current stage.
    PlayTransition,
    /// Switch the language.
    SetLang(Lang),
    /// The screen is touched (true) or typed and clicked on: the lessons' words follow.
    SetTouch(bool),
    /// Move the observer's camera.
    SetOrbit(Orbit),
    /// The observer's panel has this width/height: render it so.
    SetObserverAspect(f32),
    /// The pixel view draws the image over this many physical pixels (`display`).
    SetViewPixels([u32; 2]),
    /// Show or hide the observer view.
    ToggleObserver,
    /// Compare settings side by side (or stop).
    SetComparison(Option<Comparison>),
    /// Change how the depth buffer is drawn.
    SetDepthView(DepthView),
    /// Show a buffer in the pixel view.
    SelectBuffer(BufferKind),
    /// Turn an overlay on or off.
    ToggleOverlay(OverlayKind),
    /// Turn sample points on or off.
    ToggleSamples,
    /// Turn the world view's vertex normals on or off.
    ToggleNormals,
}

/// What is picked in the picture: a vertex, a pixel, the profile line.
#[derive(Clone, Debug, PartialEq)]
pub enum SelectionCommand {
    /// Select a vertex-table row (or none).
    SelectVertex(Option<u32>),
    /// Inspect a pixel (or none).
    SelectPixel(Option<(u32, u32)>),
    /// Draw (or clear) the profile line.
    SetProfile(Option<[f32; 4]>),
    /// Watch a shader's expression after a line over the frame (or stop).
    SetWatch(Option<pipeline::shader::probe::WatchSpec>),
    /// Turn the debugger's cost view on or off.
    SetCost(bool),
}
