//! What the stage and the step teach: the matrix or the pixel the inspector opens on.

use super::state::Session;
use crate::vocabulary::Stage;

/// What the stage and the step teach, that the inspector opens on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Teaching {
    /// The model matrix of object `k` (an index into the capture's objects).
    Model(usize),
    /// The matrix stack of the figures.
    Stack,
    /// The view matrix.
    View,
    /// The projection, in both courses' forms.
    Projection,
    /// The viewport transform.
    Viewport,
    /// The inspected pixel.
    Pixel,
}

impl Session {
    /// What the inspector should open on: the matrix the geometry stage applies (the model
    /// matrix of the object in focus, or the figures' matrix stack; V; P; the viewport), and the
    /// pixel on the pixel stages.
    #[must_use]
    pub fn teaching(&self) -> Teaching {
        let sel = &self.selection;
        let focus = sel.focus.as_deref().unwrap_or_default();
        match sel.stage {
            Stage::Model | Stage::World => {
                let figures = &self.spec.scene.figures;
                let focus_is_figure = focus.iter().any(|f| figures.iter().any(|g| &g.name == f));
                if !figures.is_empty()
                    && (focus.is_empty() || focus_is_figure)
                    && sel.vertex.is_none()
                {
                    return Teaching::Stack;
                }
                let objects = self.capture.as_ref().map(|c| &c.objects);
                let by_focus = focus
                    .first()
                    .and_then(|f| objects?.iter().position(|o| &o.name == f));
                let by_vertex = sel.vertex.and_then(|v| {
                    let c = self.capture.as_ref()?;
                    Some(c.vertices.get(v as usize)?.object as usize)
                });
                Teaching::Model(by_focus.or(by_vertex).unwrap_or(0))
            }
            Stage::View => Teaching::View,
            Stage::Clip | Stage::Ndc => Teaching::Projection,
            Stage::Screen => Teaching::Viewport,
            _ => Teaching::Pixel,
        }
    }
}
