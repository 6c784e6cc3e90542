//! A call's arguments: `in` values copied into the callee's registers, `out` and `inout`
//! variables copied into its parameters and, when it returns, back (GLSL 3.30 §6.1.1).

use super::events::Event;
use super::run::{Machine, Res};
use crate::lanes::{LANES, bit};
use crate::register_form::{Argument, Parameter, Root};

impl Machine<'_> {
    /// Copies a call's arguments into the callee `to`: an `in` value into its register, an
    /// `inout` (or `out`) variable into its parameter's locals, lane by lane in `mask`.
    pub(super) fn pass_arguments(
        &mut self,
        fi: usize,
        to: usize,
        args: &[Argument],
        mask: u64,
        live: u64,
        at: usize,
    ) -> Res<()> {
        let callee = &self.code.functions[to];
        // A callee is never the caller (GLSL has no recursion): its storage is another
        // function's, taken out while the arguments are copied in.
        let mut regs = std::mem::take(&mut self.regs[to]);
        let mut locals = std::mem::take(&mut self.locals[to]);
        let copied = (|| {
            for (param, arg) in callee.args.iter().zip(args) {
                match (*param, arg) {
                    (Parameter::Value(d), Argument::Value(src)) => {
                        let (s, d) = (src.first as usize * LANES, d.first as usize * LANES);
                        let len = src.len as usize * LANES;
                        regs[d..d + len].copy_from_slice(&self.regs[fi][s..s + len]);
                    }
                    (Parameter::Ref(d), Argument::Ref(place)) => {
                        let storage = self.storage(fi, place.root);
                        for l in (0..self.n).filter(|&l| mask & bit(l) != 0) {
                            let o = self.offset_checked(fi, place, l, live & bit(l) != 0, at)?;
                            for c in 0..d.len as usize {
                                locals[(d.first as usize + c) * LANES + l] =
                                    storage[(o as usize + c) * LANES + l];
                            }
                        }
                    }
                    _ => {}
                }
            }
            Ok(())
        })();
        self.regs[to] = regs;
        self.locals[to] = locals;
        copied
    }

    /// Copies the callee's `out` and `inout` parameters back to the caller's variables in the
    /// lanes of `mask` (those that made the call and were not discarded), each an assignment
    /// in the trace at the call's place.
    pub(super) fn return_arguments(
        &mut self,
        fi: usize,
        from: usize,
        args: &[Argument],
        mask: u64,
        live: u64,
        at: usize,
    ) -> Res<()> {
        let callee = &self.code.functions[from];
        for (param, arg) in callee.args.iter().zip(args) {
            let (Parameter::Ref(src), Argument::Ref(place)) = (*param, arg) else {
                continue;
            };
            for l in (0..self.n).filter(|&l| mask & bit(l) != 0) {
                let o = self.offset_checked(fi, place, l, live & bit(l) != 0, at)?;
                for c in 0..src.len as usize {
                    let v = self.locals[from][(src.first as usize + c) * LANES + l];
                    let storage = match place.root {
                        Root::Local => &mut self.locals[fi],
                        _ => &mut self.privates,
                    };
                    storage[(o as usize + c) * LANES + l] = v;
                }
            }
            if self.traced(mask) && !place.name.is_empty() {
                self.event(fi, mask, |m, l| Event::Assign {
                    at,
                    name: place.name.clone(),
                    ty: place.ty,
                    bits: m.read_whole(fi, place, l),
                });
            }
        }
        Ok(())
    }
}
