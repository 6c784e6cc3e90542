//! Level 0's texels in 8 bits, laid out in tiles of 4×4 texels: the copy that level 0's
//! lookups read when it holds the same values as the level.
//!
//! A texel is 4 bytes (RGB and a byte of padding), so a tile of 4×4 is 64 bytes, one cache
//! line. Row by row, the two rows a bilinear lookup reads lie a whole level's row apart, two
//! lines a lookup; in tiles they share one line three lookups in four (where neither pair of
//! taps crosses a tile's edge). And a minified texture's next screen row reads rows a few
//! texels further: in tiles four rows high these are often the lines just read, where row by
//! row each texel row is a line of its own.

use glam::Vec3;

use super::Level;

/// Texels to a tile's side.
const SIDE: usize = 4;

/// `k/255` for each 8-bit value `k`: the `f32` that `image` makes of an 8-bit component, so
/// that an 8-bit texel read through this table is the `f32` texel, bit for bit.
const UNIT_OF_BYTE: [f32; 256] = {
    let mut table = [0.0; 256];
    let mut k = 0;
    while k < 256 {
        table[k] = k as f32 / 255.0;
        k += 1;
    }
    table
};

/// A level's texels in 8 bits, tile by tile (see the module's documentation).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct TiledBytes {
    /// Tiles across a tile row: `⌈width / 4⌉`.
    across: usize,
    /// Tile `(a, b)` (from the bottom left) at `(b·across + a)·16`, its texel `(i, j)` within
    /// at `j·4 + i`; a tile past the level's edge holds zeros there.
    texels: Box<[[u8; 4]]>,
}

impl TiledBytes {
    /// The level in 8 bits when every component is exactly a `k/255` (a level loaded from an
    /// 8-bit image): 4 bytes a texel instead of 12, so a minified lookup, which strides across
    /// the level, misses the cache a third as often.
    pub(super) fn of(level: &Level) -> Option<Self> {
        let byte = |c: f32| {
            let k = (c * 255.0).round();
            (0.0..=255.0)
                .contains(&k)
                .then_some(k as u8)
                .filter(|&k| UNIT_OF_BYTE[usize::from(k)].to_bits() == c.to_bits())
        };
        let (w, h) = (level.width as usize, level.height as usize);
        let across = w.div_ceil(SIDE);
        let mut tiled = Self {
            across,
            texels: vec![[0; 4]; across * h.div_ceil(SIDE) * SIDE * SIDE].into_boxed_slice(),
        };
        for (k, t) in level.texels.iter().enumerate() {
            let at = tiled.index(k % w, k / w);
            tiled.texels[at] = [byte(t.x)?, byte(t.y)?, byte(t.z)?, 0];
        }
        Some(tiled)
    }

    /// Where texel `(i, j)` (column, row from the bottom, within the level) is.
    #[inline]
    fn index(&self, i: usize, j: usize) -> usize {
        ((j / SIDE) * self.across + i / SIDE) * (SIDE * SIDE) + (j % SIDE) * SIDE + i % SIDE
    }

    /// Texel `(i, j)` as the `f32` texel it copies.
    #[inline]
    pub(super) fn texel(&self, i: usize, j: usize) -> Vec3 {
        let b = self.texels[self.index(i, j)];
        Vec3::new(
            UNIT_OF_BYTE[usize::from(b[0])],
            UNIT_OF_BYTE[usize::from(b[1])],
            UNIT_OF_BYTE[usize::from(b[2])],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 6×5 level (not a multiple of the tile's side either way) whose texel `(i, j)` is
    /// `((i + 1)/255, (j + 1)/255, (i + 8·j)/255)`: each read back from the tiles at its
    /// place, every component bit for bit, and a level with a component not of 8 bits has no
    /// copy.
    #[test]
    fn every_texel_reads_back_from_its_tile() {
        let (w, h) = (6_u32, 5_u32);
        let value = |i: u32, j: u32| {
            Vec3::new(
                (i + 1) as f32 / 255.0,
                (j + 1) as f32 / 255.0,
                (i + 8 * j) as f32 / 255.0,
            )
        };
        let texels = (0..h)
            .flat_map(|j| (0..w).map(move |i| value(i, j)))
            .collect();
        let mut level = Level {
            width: w,
            height: h,
            texels,
        };
        let tiled = TiledBytes::of(&level).expect("8-bit values");
        // 2 tiles across, 2 up: 64 texels, 30 of them the level's.
        assert_eq!((tiled.across, tiled.texels.len()), (2, 64));
        for j in 0..h {
            for i in 0..w {
                let (got, want) = (tiled.texel(i as usize, j as usize), value(i, j));
                assert_eq!(
                    got.to_array().map(f32::to_bits),
                    want.to_array().map(f32::to_bits)
                );
            }
        }
        // Texel (5, 4) lies in tile (1, 1), at row 0, column 1 within it: (3·16) + 1.
        assert_eq!(tiled.index(5, 4), 49);
        level.texels[7].y = 0.5;
        assert!(TiledBytes::of(&level).is_none());
    }
}
