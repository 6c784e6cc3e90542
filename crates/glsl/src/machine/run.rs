//! One batch's run: the machine's storage for a program (registers, locals, returns, the
//! uniforms) and the entry into the program's `main`, with its trace and its step budget.

use super::events::{Event, RunError};
use super::textures::Textures;
use crate::lanes::{LANES, bit, lanes_where};
use crate::register_form::{Code, Place, Reg, Root};

/// The loop iterations one invocation may run before the machine calls it an endless loop,
/// unless its host allows more ([`Machine::budget`]).
pub const DEFAULT_MAX_STEPS: u32 = 1 << 16;

/// Control flow of the running function: the lanes that left the innermost loop or switch
/// with `break`, and those that left the loop's body with `continue`. (A lane that returns
/// needs no record: it is in no block's mask from there on.)
#[derive(Clone, Copy, Default)]
pub(super) struct Flow {
    /// Lanes that broke out.
    pub(super) broke: u64,
    /// Lanes that continued.
    pub(super) continued: u64,
}

/// What every statement of a running function shares: which function, the lanes that are
/// invocations (not a quad's helpers), and the textures.
#[derive(Clone, Copy)]
pub(super) struct Running<'b> {
    /// The function's index.
    pub fi: usize,
    /// The lanes whose writes and errors count.
    pub live: u64,
    /// The host's textures.
    pub textures: &'b dyn Textures,
}

/// The machine: a program's storage for one batch.
pub struct Machine<'c> {
    pub(super) code: &'c Code,
    pub(super) regs: Vec<Vec<u32>>,
    pub(super) locals: Vec<Vec<u32>>,
    pub(super) returns: Vec<Vec<u32>>,
    pub(crate) privates: Vec<u32>,
    pub(super) uniforms: Vec<u32>,
    pub(super) n: usize,
    pub(super) steps: [u32; LANES],
    /// Loop iterations one invocation may run.
    pub budget: u32,
    pub(super) killed: u64,
    pub(super) trace: Option<(usize, Vec<Event>)>,
    /// When counting: each lane's steps of the student's code in the last run, the steps its
    /// trace would list (a write, a branch, a loop's test or iteration, a call, a return …).
    pub(crate) cost: Option<[u32; LANES]>,
    /// Whether the registers of the values no invocation changes hold them: each function's
    /// constants (its `pre`) and its loads of a uniform at a fixed place. They are evaluated
    /// over every lane once, at the first run after the uniforms are set, not at every run.
    pub(super) invariants_ready: bool,
}

pub(super) type Res<T> = Result<T, RunError>;

impl<'c> Machine<'c> {
    /// A machine for `code`, its uniforms zero.
    #[must_use]
    pub fn new(code: &'c Code) -> Self {
        Self {
            code,
            regs: code
                .functions
                .iter()
                .map(|f| vec![0; f.width as usize * LANES])
                .collect(),
            locals: code
                .functions
                .iter()
                .map(|f| vec![0; f.locals_width as usize * LANES])
                .collect(),
            returns: code.functions.iter().map(|_| Vec::new()).collect(),
            privates: vec![0; code.private_width as usize * LANES],
            uniforms: vec![0; code.uniform_width as usize],
            n: 0,
            steps: [0; LANES],
            budget: DEFAULT_MAX_STEPS,
            killed: 0,
            trace: None,
            cost: None,
            invariants_ready: false,
        }
    }

    /// Sets the uniform at `reg` (where the program keeps it: `Program::uniforms`).
    pub fn set_uniform(&mut self, reg: Reg, bits: &[u32]) {
        let r = reg.first as usize..(reg.first + reg.len) as usize;
        self.uniforms[r].copy_from_slice(&bits[..reg.len as usize]);
        self.invariants_ready = false;
    }

    /// Records what lane `lane` does in the next run.
    pub fn trace_lane(&mut self, lane: Option<usize>) {
        self.trace = lane.map(|l| (l, Vec::new()));
    }

    /// Counts each lane's steps of the student's code from the next run on (`on`), or stops.
    pub fn count_cost(&mut self, on: bool) {
        self.cost = on.then_some([0; LANES]);
    }

    /// The steps lane `lane` ran in the last run, when counting ([`Self::count_cost`]).
    #[must_use]
    pub fn cost(&self, lane: usize) -> Option<u32> {
        self.cost.map(|c| c[lane])
    }

    /// The events of the traced lane's last run.
    pub fn take_trace(&mut self) -> Vec<Event> {
        self.trace
            .as_mut()
            .map(|(_, e)| std::mem::take(e))
            .unwrap_or_default()
    }

    /// Runs the entry point over `n` lanes, `live` of which are real invocations (the others
    /// helpers of a quad). `inputs` holds each argument's rows (`LANES` values a component).
    /// Returns the lanes that were discarded; the result is in [`Self::result`].
    ///
    /// # Errors
    /// A run-time error of a live lane: an index out of range, an integer division by zero,
    /// the step budget spent.
    pub fn run(
        &mut self,
        inputs: &[&[u32]],
        n: usize,
        live: u64,
        bindings: &dyn Textures,
    ) -> Res<u64> {
        self.n = n.min(LANES);
        self.steps = [0; LANES];
        if let Some(c) = self.cost.as_mut() {
            *c = [0; LANES];
        }
        self.killed = 0;
        let code = self.code;
        for (at, v) in &code.private_init {
            for (c, &x) in v.iter().enumerate() {
                let row = (*at as usize + c) * LANES;
                self.privates[row..row + self.n].fill(x);
            }
        }
        if !self.invariants_ready {
            self.prepare_invariants(bindings)?;
        }
        let entry = code.functions.len() - 1;
        let f = &code.functions[entry];
        for (arg, input) in f.args.iter().zip(inputs) {
            let arg = arg.reg();
            let r = arg.first as usize * LANES..(arg.first + arg.len) as usize * LANES;
            self.regs[entry][r].copy_from_slice(&input[..arg.len as usize * LANES]);
        }
        let all = if self.n == LANES {
            u64::MAX
        } else {
            (1 << self.n) - 1
        };
        self.call(entry, all, live, bindings)?;
        Ok(self.killed)
    }

    /// The entry point's result: each component's row of lanes.
    #[must_use]
    pub fn result(&self) -> &[u32] {
        &self.returns[self.code.functions.len() - 1]
    }

    pub(super) fn call(&mut self, fi: usize, mask: u64, live: u64, b: &dyn Textures) -> Res<()> {
        let code = self.code;
        let f = &code.functions[fi];
        // The constants (`pre`) were evaluated once, by `prepare_invariants`.
        let regs = &self.regs[fi];
        let locals = &mut self.locals[fi];
        for (reg, init) in &f.locals {
            for c in 0..reg.len as usize {
                let row = (reg.first as usize + c) * LANES;
                match init {
                    Some(i) => {
                        let src = (*i as usize + c) * LANES;
                        locals[row..row + LANES].copy_from_slice(&regs[src..src + LANES]);
                    }
                    None => locals[row..row + LANES].fill(0),
                }
            }
        }
        let mut flow = Flow::default();
        let run = Running {
            fi,
            live,
            textures: b,
        };
        self.block(run, &f.body, mask, &mut flow)?;
        Ok(())
    }

    pub(super) fn traced(&self, mask: u64) -> bool {
        self.trace
            .as_ref()
            .is_some_and(|(l, _)| mask & bit(*l) != 0)
    }

    /// Records an event of the traced lane, if it is in `mask` and function `fi` is the
    /// student's (the entry point naga wraps around `main` copies inputs and outputs only; a
    /// built-in pipelens wrote in GLSL is not the student's either).
    pub(super) fn event(&mut self, fi: usize, mask: u64, e: impl FnOnce(&Self, usize) -> Event) {
        self.counted(fi, mask);
        self.record(fi, mask, e);
    }

    /// One step more for each lane of `mask`, when counting and function `fi` is the student's.
    pub(super) fn counted(&mut self, fi: usize, mask: u64) {
        if self.cost.is_none()
            || fi + 1 == self.code.functions.len()
            || self.code.functions[fi].builtin
        {
            return;
        }
        if let Some(c) = self.cost.as_mut() {
            for (l, k) in c.iter_mut().enumerate().take(self.n) {
                *k += u32::from(mask & bit(l) != 0);
            }
        }
    }

    /// [`Self::event`] without counting it (a watch's store, which the student did not write).
    pub(super) fn record(&mut self, fi: usize, mask: u64, e: impl FnOnce(&Self, usize) -> Event) {
        if fi + 1 == self.code.functions.len() || self.code.functions[fi].builtin {
            return;
        }
        if let Some(&(l, _)) = self.trace.as_ref().filter(|(l, _)| mask & bit(*l) != 0) {
            let ev = e(self, l);
            if let Some((_, events)) = self.trace.as_mut() {
                events.push(ev);
            }
        }
    }

    /// The lanes whose bool at register row `c` is true.
    pub(super) fn lanes_true(&self, fi: usize, c: u32) -> u64 {
        lanes_where(&self.regs[fi][c as usize * LANES..][..LANES], self.n, |x| {
            x != 0
        })
    }

    pub(super) fn storage(&self, fi: usize, root: Root) -> &[u32] {
        match root {
            Root::Local => &self.locals[fi],
            Root::Private => &self.privates,
            Root::Uniform => &self.uniforms,
        }
    }

    /// The first component of `place` in lane `l`, or the index that is out of range.
    pub(super) fn offset(&self, fi: usize, place: &Place, l: usize) -> Result<u32, (i64, u32)> {
        let mut at = place.offset;
        for &(index, stride, count) in &place.dynamic {
            let i = i64::from(self.regs[fi][index as usize * LANES + l] as i32);
            if i < 0 || i >= i64::from(count) {
                return Err((i, count));
            }
            at += i as u32 * stride;
        }
        Ok(at)
    }

    pub(super) fn offset_checked(
        &self,
        fi: usize,
        place: &Place,
        l: usize,
        live: bool,
        at: usize,
    ) -> Res<u32> {
        match self.offset(fi, place, l) {
            Ok(o) => Ok(o),
            Err(_) if !live => Ok(place.offset),
            Err((i, count)) => Err(RunError {
                at,
                message: format!(
                    "index {i} is out of range: `{}` has {count} elements (0 to {})",
                    place.name,
                    count - 1
                ),
                complaint: crate::complaint::Complaint::IndexOutOfRange {
                    index: i,
                    last: count - 1,
                    name: Some(place.name.clone()),
                },
            }),
        }
    }

    pub(super) fn read_whole(&self, fi: usize, place: &Place, l: usize) -> Vec<u32> {
        let s = self.storage(fi, place.root);
        (place.whole.first..place.whole.first + place.whole.len)
            .map(|c| {
                if place.root == Root::Uniform {
                    s[c as usize]
                } else {
                    s[c as usize * LANES + l]
                }
            })
            .collect()
    }
}
