//! What the user has selected (the stage, the buffer, the pixel, the vertex…) and how the depth
//! buffer is drawn. No egui in here; the commands that change it are in `command.rs`.

use pipeline::buffers::BufferKind;
use pipeline::overlay::OverlayKind;

use crate::vocabulary::{Comparison, Stage};

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
    /// The expression watched over the frame, with its shader and the line after which it is
    /// read (the debugger's variable picture; `Scene::watching`).
    pub watch: Option<pipeline::shader::probe::WatchSpec>,
    /// Whether the debugger's cost view is on: the steps the fragment shader ran at each pixel
    /// (`Capture::cost`).
    pub cost: bool,
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
            watch: None,
            cost: false,
        }
    }
}
