//! A batch's lanes and their masks: one bit a lane in a `u64`.

/// The most invocations one batch runs (16 quads).
pub const LANES: usize = 64;

/// The mask of lane `l` alone.
pub(crate) fn bit(l: usize) -> u64 {
    1 << l
}

/// The lanes among the first `n` where `f` holds.
pub(crate) fn lanes_where(row: &[u32], n: usize, f: impl Fn(u32) -> bool) -> u64 {
    row[..n]
        .iter()
        .enumerate()
        .fold(0, |m, (l, &x)| if f(x) { m | bit(l) } else { m })
}

/// Copies the lanes of `mask` from `src` to `dst`.
pub(crate) fn masked_copy(dst: &mut [u32], src: &[u32], mask: u64, n: usize) {
    if mask.count_ones() as usize >= n {
        dst[..n].copy_from_slice(&src[..n]);
        return;
    }
    for l in 0..n {
        if mask & bit(l) != 0 {
            dst[l] = src[l];
        }
    }
}
