//! The pixel a student clicks on to learn why it has its colour: resolved again by itself, so
//! that its lighting terms and texture lookup are there whether or not the frame keeps those
//! buffers for every pixel.

use super::resolve::ResolveContext;
use crate::capture::{InspectedPixel, PixelTexture};
use crate::lighting::Frequency;

impl ResolveContext<'_> {
    /// The terms and lookup of window pixel `(x, y)`, resolved again by itself as the resolve
    /// resolved it (coarse shading shares no block with it); `None` outside the viewport.
    pub(super) fn inspected(&self, (x, y): (u32, u32)) -> Option<InspectedPixel> {
        let i = crate::grid::Grid::new(self.settings.width, self.settings.height)
            .checked_index(x, y)?;
        // Its lookup keeps λ and the footprint, which the frame's colour may not need.
        let with_derivatives = ResolveContext {
            derivatives: true,
            ..*self
        };
        let r = with_derivatives.pixel(x, y, i, None);
        let lit = self.settings.shading != Frequency::Unlit;
        let texture = r.texture.map(|(uv, l)| PixelTexture::new(uv, &l));
        Some(InspectedPixel::new(
            i,
            lit,
            r.terms.as_ref(),
            texture.as_ref(),
        ))
    }
}
