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

/// Copies the lanes of `mask` from `src` to `dst` (`mask` holds none of the lanes from `n` on).
/// A partial mask selects lane by lane without a branch: `m = −bit` is all ones for a lane of
/// the mask, and `dst = (src & m) | (dst & !m)`.
pub(crate) fn masked_copy(dst: &mut [u32], src: &[u32], mask: u64, n: usize) {
    if mask.count_ones() as usize >= n {
        copy_lanes(dst, src, n);
        return;
    }
    for (l, (d, &s)) in dst[..n].iter_mut().zip(&src[..n]).enumerate() {
        let m = 0u32.wrapping_sub(((mask >> l) & 1) as u32);
        *d = (s & m) | (*d & !m);
    }
}

/// `dst[..n] = src[..n]`, in whole 8-lane vectors up to `n` rounded up (at most [`LANES`]):
/// the lanes past `n` are no invocation's, so the few copied with the last vector are free to
/// change. Written as vector moves, not `copy_from_slice`: a row is 256 bytes at most, and the
/// C library's `memcpy` that a copy of a length known only at run time calls took a tenth of a
/// shader's time.
pub(crate) fn copy_lanes(dst: &mut [u32], src: &[u32], n: usize) {
    let end = n.next_multiple_of(8).min(LANES);
    for (d, s) in dst[..end]
        .chunks_exact_mut(8)
        .zip(src[..end].chunks_exact(8))
    {
        let v = wide::u32x8::new(s.try_into().unwrap_or([0; 8]));
        d.copy_from_slice(v.as_array());
    }
}
