//! Positions on a grid of pixels or texels, one way. The course counts window positions from the
//! bottom-left corner (y up, as `glViewport` and `gl_FragCoord` do) and texel rows from the
//! bottom of the texture (v up); every buffer and image here is stored as a picture is read, top
//! row first. A [`Grid`] turns one into the other:
//!
//! - image row of window row `y`: `row = h − 1 − y` (and back: `y = h − 1 − row`, the same map);
//! - index of window position `(x, y)` in a buffer stored top row first: `(h − 1 − y)·w + x`;
//! - window position of index `i`: `(i mod w, h − 1 − ⌊i / w⌋)`.
//!
//! Every place that indexes a buffer by a window position goes through it, so that no picture
//! can be read upside down by one and the right way up by another.

/// A `width × height` grid whose positions count y up and whose storage runs top row first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

impl Grid {
    /// The grid of `width × height` positions.
    #[must_use]
    pub const fn new(width: u32, height: u32) -> Self {
        Self { width, height }
    }

    /// Whether `(x, y)` lies on the grid.
    #[must_use]
    pub const fn contains(&self, x: u32, y: u32) -> bool {
        x < self.width && y < self.height
    }

    /// The image row (counted down from the top) of window row `y` (counted up from the
    /// bottom), and the other way round: `h − 1 − y`. `y` must lie on the grid.
    #[must_use]
    pub const fn row(&self, y: u32) -> u32 {
        debug_assert!(y < self.height);
        self.height - 1 - y
    }

    /// The index of window position `(x, y)` in a buffer stored top row first:
    /// `(h − 1 − y)·w + x`. The position must lie on the grid.
    #[must_use]
    pub const fn index(&self, x: u32, y: u32) -> usize {
        debug_assert!(x < self.width);
        self.row(y) as usize * self.width as usize + x as usize
    }

    /// [`index`](Self::index) where `(x, y)` lies on the grid, else `None`.
    #[must_use]
    pub const fn checked_index(&self, x: u32, y: u32) -> Option<usize> {
        if self.contains(x, y) {
            Some(self.index(x, y))
        } else {
            None
        }
    }

    /// The window position of index `i` of a buffer stored top row first:
    /// `(i mod w, h − 1 − ⌊i / w⌋)`. `i` must lie within the buffer.
    #[must_use]
    pub const fn position(&self, i: usize) -> (u32, u32) {
        let w = self.width as usize;
        ((i % w) as u32, self.row((i / w) as u32))
    }

    /// The number of positions, `w·h`.
    #[must_use]
    pub const fn len(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// Whether the grid has no position.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::Grid;

    /// A 3×2 grid by hand: window (0, 0) is the bottom-left pixel, stored in the second (last)
    /// image row, at index 3; window (2, 1) is the top-right one, index 2.
    #[test]
    fn window_positions_and_indices_by_hand() {
        let g = Grid::new(3, 2);
        assert_eq!(g.index(0, 0), 3);
        assert_eq!(g.index(2, 0), 5);
        assert_eq!(g.index(0, 1), 0);
        assert_eq!(g.index(2, 1), 2);
        assert_eq!(g.row(0), 1);
        assert_eq!(g.row(1), 0);
        assert_eq!(g.checked_index(3, 0), None);
        assert_eq!(g.checked_index(0, 2), None);
        for i in 0..g.len() {
            let (x, y) = g.position(i);
            assert_eq!(g.index(x, y), i);
        }
    }
}
