//! The machine's expressions: each evaluated for every lane of the batch, reading its operands'
//! registers and writing its own; a store into a place; the invariant registers (constants, a
//! uniform at a fixed place) evaluated once per uniform set. Errors (an index out of range, an
//! integer division by zero) count only in live lanes.

use naga::{RelationalFunction, UnaryOperator};

use super::events::RunError;
use super::run::{Machine, Res};
use super::textures::Textures;
use crate::complaint::Complaint;
use crate::lanes::{LANES, bit, copy_lanes, masked_copy};
use crate::ops;
use crate::register_form::{Function, Kind, Op, Place, Reg, Root, Shape};

impl Machine<'_> {
    pub(super) fn store(
        &mut self,
        fi: usize,
        place: &Place,
        value: u32,
        mask: u64,
        live: u64,
    ) -> Res<()> {
        let at = self.code.functions[fi]
            .spans
            .get(value as usize)
            .copied()
            .unwrap_or(0);
        if let Some(o) = self.one_offset(fi, place, live & mask, at)? {
            for c in 0..place.len as usize {
                let (dst, src) = ((o as usize + c) * LANES, (value as usize + c) * LANES);
                let row = &self.regs[fi][src..src + LANES];
                let storage = match place.root {
                    Root::Local => &mut self.locals[fi],
                    _ => &mut self.privates,
                };
                masked_copy(&mut storage[dst..dst + LANES], row, mask, self.n);
            }
            return Ok(());
        }
        for l in 0..self.n {
            if mask & bit(l) == 0 {
                continue;
            }
            let o = self.offset_checked(fi, place, l, live & bit(l) != 0, at)?;
            for c in 0..place.len as usize {
                let v = self.regs[fi][(value as usize + c) * LANES + l];
                let storage = match place.root {
                    Root::Local => &mut self.locals[fi],
                    _ => &mut self.privates,
                };
                storage[(o as usize + c) * LANES + l] = v;
            }
        }
        Ok(())
    }

    /// The first component of `place` when it is the same in every one of the `n` lanes: its
    /// fixed offset where it has no dynamic index, or where its dynamic indices hold one value
    /// in every lane (a loop's counter that every lane runs alike), that offset checked once —
    /// an index out of range is an error when any lane of `live` runs, as lane by lane. `None`
    /// when the lanes' indices differ: each lane's own offset is needed.
    fn one_offset(&self, fi: usize, place: &Place, live: u64, at: usize) -> Res<Option<u32>> {
        if place.dynamic.is_empty() {
            return Ok(Some(place.offset));
        }
        let n = self.n;
        let alike = |&(index, _, _): &(u32, u32, u32)| {
            let row = &self.regs[fi][index as usize * LANES..][..n];
            row.iter().all(|&x| x == row[0])
        };
        if n == 0 || !place.dynamic.iter().all(alike) {
            return Ok(None);
        }
        self.offset_checked(fi, place, 0, live != 0, at).map(Some)
    }

    /// Evaluates the invariant expressions (see `invariants_ready`) over all lanes.
    pub(super) fn prepare_invariants(&mut self, b: &dyn Textures) -> Res<()> {
        let code = self.code;
        let n = std::mem::replace(&mut self.n, LANES);
        for (fi, f) in code.functions.iter().enumerate() {
            for &e in &f.pre {
                self.eval(fi, e as usize, u64::MAX, b)?;
            }
            for (e, op) in f.ops.iter().enumerate() {
                if is_fixed_uniform_load(op) {
                    self.eval(fi, e, u64::MAX, b)?;
                }
            }
        }
        self.n = n;
        self.invariants_ready = true;
        Ok(())
    }

    #[allow(clippy::too_many_lines)]
    pub(super) fn eval(&mut self, fi: usize, e: usize, live: u64, b: &dyn Textures) -> Res<()> {
        let code = self.code;
        let f: &Function = &code.functions[fi];
        let dst = f.regs[e];
        let n = self.n;
        let at = f.spans[e];
        let err = |message: String, complaint: Complaint| RunError {
            at,
            message,
            complaint,
        };
        match &f.ops[e] {
            Op::None => {}
            Op::Const(v) => {
                let regs = &mut self.regs[fi];
                for (c, &x) in v.iter().enumerate() {
                    regs[(dst.first as usize + c) * LANES..][..n].fill(x);
                }
            }
            // Evaluated once over every lane by `prepare_invariants`.
            op @ Op::Load(_) if self.invariants_ready && is_fixed_uniform_load(op) => {}
            Op::Load(place) => {
                // One offset for every lane: a place with no dynamic index, or one indexed
                // alike in every lane (`lights[i]` in a loop every lane runs the same way);
                // else each lane's own (`offsets`).
                let fixed = self.one_offset(fi, place, live, at)?;
                let mut offsets = [0u32; LANES];
                if fixed.is_none() {
                    for (l, o) in offsets.iter_mut().enumerate().take(n) {
                        *o = self.offset_checked(fi, place, l, live & bit(l) != 0, at)?;
                    }
                }
                let root = place.root;
                let (src, regs) = match root {
                    Root::Local => (&self.locals[fi], &mut self.regs[fi]),
                    Root::Private => (&self.privates, &mut self.regs[fi]),
                    Root::Uniform => (&self.uniforms, &mut self.regs[fi]),
                };
                for c in 0..place.len as usize {
                    let row = &mut regs[(dst.first as usize + c) * LANES..];
                    match (root, fixed) {
                        (Root::Uniform, Some(o)) => row[..n].fill(src[o as usize + c]),
                        (Root::Uniform, None) => {
                            for (l, x) in row[..n].iter_mut().enumerate() {
                                *x = src[offsets[l] as usize + c];
                            }
                        }
                        (_, Some(o)) => copy_lanes(row, &src[(o as usize + c) * LANES..], n),
                        (_, None) => {
                            for (l, x) in row[..n].iter_mut().enumerate() {
                                *x = src[(offsets[l] as usize + c) * LANES + l];
                            }
                        }
                    }
                }
            }
            op => {
                // Every operand lies below `dst` (an expression's operands come before it in
                // naga's arena, and registers are laid out in that order): read below the
                // split, write above it.
                debug_assert!(
                    op.reads().iter().all(|&r| r < dst.first),
                    "an operand of {op:?} at or above its register {}",
                    dst.first
                );
                let (src, out) = self.regs[fi].split_at_mut(dst.first as usize * LANES);
                let row = |r: u32, c: u32| &src[(r + c) as usize * LANES..][..n];
                // A whole row of lanes, for a copy (every operand's row lies below `dst`).
                let whole = |r: u32, c: u32| &src[(r + c) as usize * LANES..][..LANES];
                let out = &mut out[..dst.len as usize * LANES];
                match op {
                    Op::Compose(parts) => {
                        let mut c = 0;
                        for p in parts {
                            for k in 0..p.len {
                                copy_lanes(&mut out[c * LANES..], whole(p.first, k), n);
                                c += 1;
                            }
                        }
                    }
                    Op::Copy { from, n: count } => {
                        for k in 0..*count {
                            copy_lanes(&mut out[k as usize * LANES..], whole(*from, k), n);
                        }
                    }
                    Op::Splat { from, n: count } => {
                        for k in 0..*count as usize {
                            copy_lanes(&mut out[k * LANES..], whole(*from, 0), n);
                        }
                    }
                    Op::Swizzle { from, pattern } => {
                        for (k, &p) in pattern.iter().enumerate() {
                            copy_lanes(&mut out[k * LANES..], whole(*from, p), n);
                        }
                    }
                    Op::Index {
                        base,
                        elem,
                        count,
                        index,
                        kind,
                    } => {
                        for l in 0..n {
                            let raw = row(*index, 0)[l];
                            let i = if *kind == Kind::Uint {
                                i64::from(raw)
                            } else {
                                i64::from(raw as i32)
                            };
                            let i = if i < 0 || i >= i64::from(*count) {
                                if live & bit(l) != 0 {
                                    return Err(err(
                                        format!("index {i} is out of range (0 to {})", count - 1),
                                        Complaint::IndexOutOfRange {
                                            index: i,
                                            last: count - 1,
                                            name: None,
                                        },
                                    ));
                                }
                                0
                            } else {
                                i as u32
                            };
                            for k in 0..*elem {
                                out[k as usize * LANES + l] = row(*base, i * elem + k)[l];
                            }
                        }
                    }
                    Op::Unary { op, kind, a } => {
                        for k in 0..a.len {
                            let (x, y) = (row(a.first, k), &mut out[k as usize * LANES..][..n]);
                            match (op, kind) {
                                (UnaryOperator::Negate, Kind::Float) => {
                                    ops::map(x, y, |v| (-f32::from_bits(v)).to_bits())
                                }
                                (UnaryOperator::Negate, _) => {
                                    ops::map(x, y, |v| (v as i32).wrapping_neg() as u32)
                                }
                                (UnaryOperator::LogicalNot, _) => {
                                    ops::map(x, y, |v| u32::from(v == 0))
                                }
                                (UnaryOperator::BitwiseNot, Kind::Bool) => {
                                    ops::map(x, y, |v| u32::from(v == 0))
                                }
                                (UnaryOperator::BitwiseNot, _) => ops::map(x, y, |v| !v),
                            }
                        }
                    }
                    Op::Binary {
                        op,
                        kind,
                        a,
                        b: rb,
                        shape,
                    } => {
                        let get = |r: Reg, c: u32| row(r.first, if r.len == 1 { 0 } else { c });
                        match shape {
                            Shape::Each => {
                                for k in 0..dst.len {
                                    ops::binary(
                                        *op,
                                        *kind,
                                        get(*a, k),
                                        get(*rb, k),
                                        &mut out[k as usize * LANES..][..n],
                                        live,
                                    )
                                    .map_err(|d| {
                                        err(
                                            d.message().to_owned(),
                                            Complaint::DivisionByZero {
                                                remainder: d.remainder,
                                            },
                                        )
                                    })?;
                                }
                            }
                            // Matrices have at most four rows and columns: each dot
                            // product's terms fit in an array on the stack.
                            Shape::MatVec { c, r } => {
                                for i in 0..*r {
                                    let mut terms: [(&[u32], &[u32]); 4] = [(&[], &[]); 4];
                                    for j in 0..*c {
                                        terms[j as usize] =
                                            (row(a.first, j * r + i), row(rb.first, j));
                                    }
                                    ops::dot_rows(
                                        &terms[..*c as usize],
                                        &mut out[i as usize * LANES..][..n],
                                    );
                                }
                            }
                            Shape::VecMat { c, r } => {
                                for j in 0..*c {
                                    let mut terms: [(&[u32], &[u32]); 4] = [(&[], &[]); 4];
                                    for i in 0..*r {
                                        terms[i as usize] =
                                            (row(a.first, i), row(rb.first, j * r + i));
                                    }
                                    ops::dot_rows(
                                        &terms[..*r as usize],
                                        &mut out[j as usize * LANES..][..n],
                                    );
                                }
                            }
                            Shape::MatMat { k, r, c } => {
                                for j in 0..*c {
                                    for i in 0..*r {
                                        let mut terms: [(&[u32], &[u32]); 4] = [(&[], &[]); 4];
                                        for m in 0..*k {
                                            terms[m as usize] =
                                                (row(a.first, m * r + i), row(rb.first, j * k + m));
                                        }
                                        ops::dot_rows(
                                            &terms[..*k as usize],
                                            &mut out[(j * r + i) as usize * LANES..][..n],
                                        );
                                    }
                                }
                            }
                        }
                    }
                    Op::Select { c, a, b: rb } => {
                        for k in 0..dst.len {
                            let cond = row(c.first, if c.len == 1 { 0 } else { k });
                            let (x, y) = (row(a.first, k), row(rb.first, k));
                            for (l, o) in out[k as usize * LANES..][..n].iter_mut().enumerate() {
                                *o = if cond[l] != 0 { x[l] } else { y[l] };
                            }
                        }
                    }
                    Op::Derivative { axis, fine, a } => {
                        for k in 0..a.len {
                            ops::derivative(
                                *axis,
                                *fine,
                                row(a.first, k),
                                &mut out[k as usize * LANES..][..n],
                            );
                        }
                    }
                    Op::Relational { fun, a } => match fun {
                        RelationalFunction::All | RelationalFunction::Any => {
                            let all = *fun == RelationalFunction::All;
                            for (l, o) in out[..n].iter_mut().enumerate() {
                                let mut acc = all;
                                for k in 0..a.len {
                                    let v = row(a.first, k)[l] != 0;
                                    acc = if all { acc && v } else { acc || v };
                                }
                                *o = u32::from(acc);
                            }
                        }
                        RelationalFunction::IsNan | RelationalFunction::IsInf => {
                            let nan = *fun == RelationalFunction::IsNan;
                            for k in 0..a.len {
                                ops::map(
                                    row(a.first, k),
                                    &mut out[k as usize * LANES..][..n],
                                    |v| {
                                        let x = f32::from_bits(v);
                                        u32::from(if nan { x.is_nan() } else { x.is_infinite() })
                                    },
                                );
                            }
                        }
                    },
                    Op::Math {
                        fun,
                        kind,
                        args,
                        rows,
                    } => {
                        crate::builtins::math(
                            *fun,
                            *kind,
                            args,
                            *rows,
                            &|r, c| row(r, c),
                            out,
                            dst.len,
                            n,
                        )
                        .map_err(|m| err(m, Complaint::Other))?;
                    }
                    Op::As {
                        a,
                        from,
                        to,
                        convert,
                    } => {
                        for k in 0..a.len {
                            let y = &mut out[k as usize * LANES..];
                            if *convert {
                                ops::convert(*from, *to, row(a.first, k), &mut y[..n]);
                            } else {
                                copy_lanes(y, whole(a.first, k), n);
                            }
                        }
                    }
                    Op::Sample { .. }
                    | Op::SampleCube { .. }
                    | Op::Fetch { .. }
                    | Op::Size { .. } => {
                        super::texture::lookup(op, &row, out, n, live, b)
                            .map_err(|(m, c)| err(m, c))?;
                    }
                    Op::None | Op::Const(_) | Op::Load(_) => {}
                }
            }
        }
        Ok(())
    }
}

/// Whether `op` reads a uniform at a fixed place: its value is the same in every lane and every
/// run until the uniforms change.
pub(super) fn is_fixed_uniform_load(op: &Op) -> bool {
    matches!(op, Op::Load(p) if p.root == Root::Uniform && p.dynamic.is_empty())
}
