//! A block's statements over a batch: each kind of statement a method. `mask` is the lanes a
//! statement applies to; each method returns the lanes that go on to the next statement (an
//! `if` joins its branches' lanes, a loop hands on those that left it; `break` and `continue`
//! take theirs out and record them in `Flow`, `return` and `discard` take theirs out).

use super::events::{Event, RunError};
use super::run::{Flow, Machine, Res, Running};
use crate::complaint::Complaint;
use crate::lanes::{LANES, bit, lanes_where, masked_copy};
use crate::register_form::{Call, If, Loop, Reg, Stmt, Switch};

impl Machine<'_> {
    /// Runs `stmts` in the lanes of `mask`; the lanes that reach the block's end.
    pub(super) fn block(
        &mut self,
        run: Running<'_>,
        stmts: &[Stmt],
        mut mask: u64,
        flow: &mut Flow,
    ) -> Res<u64> {
        let fi = run.fi;
        for s in stmts {
            if mask == 0 {
                break;
            }
            mask = match s {
                Stmt::Emit(r) => {
                    for e in r.clone() {
                        self.eval(fi, e as usize, mask & run.live, run.textures)?;
                    }
                    mask
                }
                Stmt::Block(inner) => self.block(run, inner, mask, flow)?,
                Stmt::If(s) => self.exec_if(run, s, mask, flow)?,
                Stmt::Switch(s) => self.exec_switch(run, s, mask, flow)?,
                Stmt::Loop(s) => self.exec_loop(run, s, mask, flow)?,
                Stmt::Break { at } => {
                    if let Some(at) = *at {
                        self.event(fi, mask, |_, _| Event::Break { at });
                    }
                    flow.broke |= mask;
                    0
                }
                Stmt::Continue { at } => {
                    self.event(fi, mask, |_, _| Event::Continue { at: *at });
                    flow.continued |= mask;
                    0
                }
                Stmt::Return { at, value } => {
                    self.exec_return(fi, *at, *value, mask);
                    0
                }
                Stmt::Kill { at } => {
                    self.event(fi, mask, |_, _| Event::Discard { at: *at });
                    self.killed |= mask;
                    0
                }
                Stmt::Store { at, place, value } => {
                    self.store(fi, place, *value, mask, run.live)?;
                    // naga's own temporaries (a `?:`'s result) have no name: the student's
                    // variables do. A watch's store is not a step of theirs.
                    if !place.name.is_empty() && place.name != crate::watched::WATCH {
                        self.counted(fi, mask);
                    }
                    if self.traced(mask) && !place.name.is_empty() {
                        self.record(fi, mask, |m, l| Event::Assign {
                            at: *at,
                            name: place.name.clone(),
                            ty: place.ty,
                            bits: m.read_whole(fi, place, l),
                        });
                    }
                    mask
                }
                Stmt::Call(c) => self.exec_call(run, c, mask)?,
            };
        }
        Ok(mask)
    }

    /// `if`: each branch with the lanes whose condition holds, or fails; their lanes joined.
    fn exec_if(&mut self, run: Running<'_>, s: &If, mask: u64, flow: &mut Flow) -> Res<u64> {
        let cond = self.lanes_true(run.fi, s.c);
        let (yes, no) = (mask & cond, mask & !cond);
        self.event(run.fi, mask, |_, l| {
            let taken = yes & bit(l) != 0;
            if s.loop_test {
                // `if (!cond) break;`: taken is the condition failing.
                Event::LoopTest {
                    at: s.at,
                    holds: !taken,
                }
            } else {
                Event::Branch { at: s.at, taken }
            }
        });
        let a = if yes != 0 {
            self.block(run, &s.accept, yes, flow)?
        } else {
            0
        };
        let r = if no != 0 {
            self.block(run, &s.reject, no, flow)?
        } else {
            0
        };
        Ok(a | r)
    }

    /// `switch`: each case with the lanes whose selector is its value (`default`: none of the
    /// values), and the lanes that fell through from the case above; a `break` leaves the
    /// switch, not an enclosing loop.
    fn exec_switch(
        &mut self,
        run: Running<'_>,
        s: &Switch,
        mask: u64,
        flow: &mut Flow,
    ) -> Res<u64> {
        let outer = flow.broke;
        flow.broke = 0;
        let selector = |m: &Self, v: i64| {
            let sel = &m.regs[run.fi][s.selector as usize * LANES..][..LANES];
            lanes_where(sel, m.n, |x| i64::from(x as i32) == v || i64::from(x) == v)
        };
        let mut default = mask;
        for (value, _, _) in &s.cases {
            if let Some(v) = value {
                default &= !selector(self, *v);
            }
        }
        let (mut matched, mut falling, mut after) = (0u64, 0u64, 0u64);
        for (value, body, fall_through) in &s.cases {
            let hit = match value {
                Some(v) => mask & selector(self, *v),
                None => default,
            } & !matched;
            matched |= hit;
            let lanes = hit | falling;
            let out = if lanes != 0 {
                self.block(run, body, lanes, flow)?
            } else {
                0
            };
            if *fall_through {
                falling = out;
            } else {
                after |= out;
                falling = 0;
            }
        }
        let mask = after | falling | flow.broke | (mask & !matched);
        flow.broke = outer;
        Ok(mask)
    }

    /// A loop: the body and `continuing` while any lane runs, each live lane's iterations
    /// counted against the budget; the lanes that left it go on.
    ///
    /// # Errors
    /// [`Complaint::EndlessLoop`] when a live lane passes the budget.
    fn exec_loop(&mut self, run: Running<'_>, s: &Loop, mask: u64, flow: &mut Flow) -> Res<u64> {
        let (outer_broke, outer_continued) = (flow.broke, flow.continued);
        let mut running = mask;
        let mut left = 0u64;
        let mut k = 0u32;
        while running != 0 {
            k += 1;
            self.count_iteration(running & run.live, s.at)?;
            self.event(run.fi, running, |_, _| Event::Iteration { at: s.at, k });
            flow.broke = 0;
            flow.continued = 0;
            let mut m = self.block(run, &s.body, running, flow)?;
            m |= flow.continued;
            left |= flow.broke;
            if m != 0 {
                flow.broke = 0;
                m = self.block(run, &s.continuing, m, flow)?;
                left |= flow.broke;
                if let Some(c) = s.break_if {
                    let stop = m & self.lanes_true(run.fi, c);
                    left |= stop;
                    m &= !stop;
                }
            }
            running = m;
        }
        flow.broke = outer_broke;
        flow.continued = outer_continued;
        Ok(left)
    }

    /// One more iteration for each lane of `lanes`.
    ///
    /// # Errors
    /// The loop at `at` ran past the budget in one of them.
    fn count_iteration(&mut self, lanes: u64, at: usize) -> Res<()> {
        for l in (0..self.n).filter(|&l| lanes & bit(l) != 0) {
            self.steps[l] += 1;
            if self.steps[l] > self.budget {
                return Err(RunError {
                    at,
                    message: format!(
                        "the loop ran more than {} steps (an endless loop? If it is meant to run longer, raise the limit with `max_steps` under [scene.render])",
                        self.budget
                    ),
                    complaint: Complaint::EndlessLoop {
                        budget: self.budget,
                    },
                });
            }
        }
        Ok(())
    }

    /// `return`: the value kept for the caller in the lanes of `mask`, and traced (but for
    /// `main`'s end, which needs no line of its own).
    fn exec_return(&mut self, fi: usize, at: usize, value: Option<Reg>, mask: u64) {
        if let Some(v) = value {
            let ret = &mut self.returns[fi];
            ret.resize(v.len as usize * LANES, 0);
            let regs = &self.regs[fi];
            for c in 0..v.len as usize {
                let src = &regs[(v.first as usize + c) * LANES..][..LANES];
                masked_copy(&mut ret[c * LANES..][..LANES], src, mask, self.n);
            }
        }
        let code = self.code;
        let f = &code.functions[fi];
        if fi + 1 < code.functions.len() && f.name != "main" {
            let name = f.name.clone();
            let result = f.result.zip(value);
            self.event(fi, mask, |m, l| Event::Return {
                at,
                name,
                value: result.map(|(ty, v)| {
                    let ret = &m.returns[fi];
                    let bits = (0..v.len as usize).map(|c| ret[c * LANES + l]).collect();
                    (ty, bits)
                }),
            });
        }
    }

    /// A call: the arguments passed in, the callee run in the lanes of `mask`, its result and
    /// its `out` parameters copied back in the lanes that were not discarded.
    fn exec_call(&mut self, run: Running<'_>, s: &Call, mask: u64) -> Res<u64> {
        let (fi, live) = (run.fi, run.live);
        let callee = &self.code.functions[s.function];
        if !callee.builtin {
            self.event(fi, mask, |_, _| Event::Call {
                at: s.at,
                name: callee.name.clone(),
            });
        }
        self.pass_arguments(fi, s.function, &s.args, mask, live, s.at)?;
        self.call(s.function, mask, live, run.textures)?;
        if let Some(r) = s.result {
            let len = r.len as usize * LANES;
            let ret = std::mem::take(&mut self.returns[s.function]);
            let d = r.first as usize * LANES;
            self.regs[fi][d..d + len].copy_from_slice(&ret[..len]);
            self.returns[s.function] = ret;
        }
        let mask = mask & !self.killed;
        self.return_arguments(fi, s.function, &s.args, mask, live, s.at)?;
        Ok(mask)
    }
}
