//! What the user has selected (the stage, the buffer, the pixel, the vertex…), and the commands
//! panels return to change it or the session. No egui in here.

use pipeline::buffers::BufferKind;
use pipeline::overlay::OverlayKind;

use crate::lesson::{Lesson, SceneSpec};
use crate::observer::Orbit;
use crate::vocabulary::{Comparison, Lang, Stage};

/// What the user has selected.
#[derive(Clone, Debug, PartialEq)]
pub struct Selection {
    /// The stage in the main view.
    pub stage: Stage,
    /// The buffer a pixel stage shows.
    pub buffer: BufferKind,
    /// Overlays drawn over pixel views.
    pub overlays: Vec<OverlayKind>,
    /// Draw sample positions when zoomed in.
    pub show_samples: bool,
    /// Vertex normals drawn as short lines in the world view.
    pub show_normals: bool,
    /// Show the observer view beside the stage.
    pub show_observer: bool,
    /// The selected row of the vertex table.
    pub vertex: Option<u32>,
    /// The pixel being inspected (window coordinates, y up).
    pub pixel: Option<(u32, u32)>,
    /// Progress of the animated transition from the previous space (0 → 1).
    pub transition: f32,
    /// Settings compared side by side in the pixel stages, if any.
    pub comparison: Option<Comparison>,
    /// The profile line `[x0, y0, x1, y1]` in image pixels (y down), if one is drawn.
    pub profile: Option<[f32; 4]>,
    /// How the depth buffer is drawn.
    pub depth_view: DepthView,
    /// The objects and figures the geometry views frame (`None`: every object).
    pub focus: Option<Vec<String>>,
}

/// How the depth buffer is drawn: window depth or eye distance, over a range.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DepthView {
    /// Show the eye distance (linear) instead of the window depth z_w.
    pub linear: bool,
    /// Black at the first value, white at the second; `None`: the nearest and farthest present.
    pub range: Option<[f32; 2]>,
}

impl Default for Selection {
    fn default() -> Self {
        Self {
            stage: Stage::default(),
            buffer: BufferKind::Color,
            overlays: vec![OverlayKind::TriangleEdges],
            show_samples: true,
            show_normals: false,
            show_observer: true,
            vertex: None,
            pixel: None,
            transition: 1.0,
            comparison: None,
            profile: None,
            depth_view: DepthView::default(),
            focus: None,
        }
    }
}

/// Everything a panel can ask for.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Show a stage.
    SelectStage(Stage),
    /// One stage on (→).
    NextStage,
    /// One stage back (←).
    PreviousStage,
    /// Show a buffer in the pixel view.
    SelectBuffer(BufferKind),
    /// Turn an overlay on or off.
    ToggleOverlay(OverlayKind),
    /// Turn sample points on or off.
    ToggleSamples,
    /// Turn the world view's vertex normals on or off.
    ToggleNormals,
    /// Show or hide the observer view.
    ToggleObserver,
    /// Select a vertex-table row (or none).
    SelectVertex(Option<u32>),
    /// Inspect a pixel (or none).
    SelectPixel(Option<(u32, u32)>),
    /// Replace the scene and settings (a parameter changed) and render again.
    SetSpec(Box<SceneSpec>),
    /// Move the observer's camera.
    SetOrbit(Orbit),
    /// The observer's panel has this width/height: render it so.
    SetObserverAspect(f32),
    /// The pixel view draws the image over this many physical pixels (`display`).
    SetViewPixels([u32; 2]),
    /// Replay the transition into the current stage.
    PlayTransition,
    /// Switch the language.
    SetLang(Lang),
    /// Compare settings side by side (or stop).
    SetComparison(Option<Comparison>),
    /// Draw (or clear) the profile line.
    SetProfile(Option<[f32; 4]>),
    /// Change how the depth buffer is drawn.
    SetDepthView(DepthView),
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
