//! The two palettes of exported drawings: the app's colours on its dark ground for the screen
//! and slides, dark ink on white for print.

/// The colours of the drawn (not rendered) pictures: the app's dark ones for the screen and
/// slides, dark ink on white for print (a handout), which would otherwise print black
/// rectangles. Rendered buffers are the same in both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Palette {
    /// As the app draws them.
    Screen,
    /// On paper.
    Print,
}

impl Palette {
    /// A colour the app draws on black, as this palette draws it: as it is on screen, darkened
    /// to read as well on white in print.
    pub(super) fn ink(self, [r, g, b]: [u8; 3], a: u8) -> [u8; 4] {
        match self {
            Palette::Screen => [r, g, b, a],
            Palette::Print => {
                let dark = |c: u8| (f32::from(c) * 0.62) as u8;
                [dark(r), dark(g), dark(b), a]
            }
        }
    }
}
