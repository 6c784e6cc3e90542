//! Runs a program in register form ([`super::code`]) over a batch of up to [`LANES`]
//! invocations at once, as a GPU runs a warp: every expression is evaluated for all lanes, and
//! a *mask* (one bit a lane) says which lanes a statement applies to. An `if` runs its two
//! branches with the lanes whose condition holds and the others; a loop runs until every lane
//! has left it; `break`, `continue`, `return` and `discard` take their lanes out of the mask.
//!
//! Fragments come in 2×2 quads (lanes `4q` … `4q + 3`: top-left, top-right, bottom-left,
//! bottom-right), so `dFdx(v) = v(x+1, y) − v(x, y)` is a difference within the quad, and
//! `texture()` takes its level of detail from the quad's differences of the coordinates.
//!
//! A step budget stops endless loops: each lane may run at most [`Machine::budget`] loop
//! iterations in one invocation.

use glam::{IVec2, Vec2, Vec3};

use super::code::{Code, Place, Reg, Root};

mod call;
mod eval;
mod events;
mod statements;
mod texture;

pub use events::{Event, RunError};

/// The most invocations one batch runs (16 quads).
pub const LANES: usize = 64;

/// The loop iterations one invocation may run before the machine calls it an endless loop,
/// unless its host allows more ([`Machine::budget`]).
pub const DEFAULT_MAX_STEPS: u32 = 1 << 16;

/// What `texelFetch` finds at an address.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Texel {
    /// The texel's colour.
    At(glam::Vec3),
    /// The address lies outside the level (or the level outside the texture): a run-time error.
    Outside,
    /// Nothing is bound there, or the texture has no such level: black.
    Unbound,
}

/// The textures a run reads, bound by slot (the order the shader declared its samplers in) by
/// the engine's host. A lookup in a slot with nothing of its kind bound reads black. The sampler
/// state (filter, mipmaps, wrap, bias, anisotropy) is the host's, bound with the texture.
pub trait Textures {
    /// `texture(s, uv)` and its kin on the 2D texture in `slot`, the level of detail from the
    /// footprint's derivatives `dx`, `dy` (in uv a pixel) and the extra `bias`, each level's
    /// read moved by `offset` texels of that level.
    fn sample(
        &self,
        slot: u32,
        uv: Vec2,
        dx: Vec2,
        dy: Vec2,
        bias: f32,
        offset: IVec2,
    ) -> Option<Vec3>;
    /// `textureLod(s, uv, lod)`: the level of detail given.
    fn sample_lod(&self, slot: u32, uv: Vec2, lod: f32, offset: IVec2) -> Option<Vec3>;
    /// `texture(s, r)` of the cube map in `slot`, by direction.
    fn sample_cube(&self, slot: u32, direction: Vec3) -> Option<Vec3>;
    /// `texelFetch(s, ij, level)`: the texel at the integer address.
    fn texel(&self, slot: u32, level: i32, i: i32, j: i32) -> Texel;
    /// `textureSize(s, level)`: the level's width and height, (0, 0) past the last level or
    /// with nothing bound (a cube map has one level, its face's).
    fn size(&self, slot: u32, level: usize) -> (u32, u32);
}

/// No textures: every lookup reads black (a program that declares none).
impl Textures for () {
    fn sample(&self, _: u32, _: Vec2, _: Vec2, _: Vec2, _: f32, _: IVec2) -> Option<Vec3> {
        None
    }
    fn sample_lod(&self, _: u32, _: Vec2, _: f32, _: IVec2) -> Option<Vec3> {
        None
    }
    fn sample_cube(&self, _: u32, _: Vec3) -> Option<Vec3> {
        None
    }
    fn texel(&self, _: u32, _: i32, _: i32, _: i32) -> Texel {
        Texel::Unbound
    }
    fn size(&self, _: u32, _: usize) -> (u32, u32) {
        (0, 0)
    }
}

/// Control flow of the running function: the lanes that left the innermost loop or switch
/// with `break`, and those that left the loop's body with `continue`. (A lane that returns
/// needs no record: it is in no block's mask from there on.)
#[derive(Clone, Copy, Default)]
struct Flow {
    /// Lanes that broke out.
    broke: u64,
    /// Lanes that continued.
    continued: u64,
}

/// The machine: a program's storage for one batch.
pub struct Machine<'c> {
    code: &'c Code,
    regs: Vec<Vec<u32>>,
    locals: Vec<Vec<u32>>,
    returns: Vec<Vec<u32>>,
    privates: Vec<u32>,
    uniforms: Vec<u32>,
    n: usize,
    steps: [u32; LANES],
    /// Loop iterations one invocation may run.
    pub budget: u32,
    killed: u64,
    trace: Option<(usize, Vec<Event>)>,
    /// Whether the registers of the values no invocation changes hold them: each function's
    /// constants (its `pre`) and its loads of a uniform at a fixed place. They are evaluated
    /// over every lane once, at the first run after the uniforms are set, not at every run.
    invariants_ready: bool,
}

type Res<T> = Result<T, RunError>;

fn bit(l: usize) -> u64 {
    1 << l
}

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
            invariants_ready: false,
        }
    }

    /// Sets the uniform at `reg` (where the program keeps it: `Program::uniforms`).
    pub fn set_uniform(&mut self, reg: Reg, bits: &[u32]) {
        let r = reg.at as usize..(reg.at + reg.n) as usize;
        self.uniforms[r].copy_from_slice(&bits[..reg.n as usize]);
        self.invariants_ready = false;
    }

    /// Records what lane `lane` does in the next run.
    pub fn trace_lane(&mut self, lane: Option<usize>) {
        self.trace = lane.map(|l| (l, Vec::new()));
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
            let r = arg.at as usize * LANES..(arg.at + arg.n) as usize * LANES;
            self.regs[entry][r].copy_from_slice(&input[..arg.n as usize * LANES]);
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

    fn call(&mut self, fi: usize, mask: u64, live: u64, b: &dyn Textures) -> Res<()> {
        let code = self.code;
        let f = &code.functions[fi];
        // The constants (`pre`) were evaluated once, by `prepare_invariants`.
        let regs = &self.regs[fi];
        let locals = &mut self.locals[fi];
        for (reg, init) in &f.locals {
            for c in 0..reg.n as usize {
                let row = (reg.at as usize + c) * LANES;
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
        let run = statements::Running {
            fi,
            live,
            textures: b,
        };
        self.block(run, &f.body, mask, &mut flow)?;
        Ok(())
    }

    fn traced(&self, mask: u64) -> bool {
        self.trace
            .as_ref()
            .is_some_and(|(l, _)| mask & bit(*l) != 0)
    }

    /// Records an event of the traced lane, if it is in `mask` and function `fi` is the
    /// student's (the entry point naga wraps around `main` copies inputs and outputs only; a
    /// built-in pipelens wrote in GLSL is not the student's either).
    fn event(&mut self, fi: usize, mask: u64, e: impl FnOnce(&Self, usize) -> Event) {
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
    fn lanes_true(&self, fi: usize, c: u32) -> u64 {
        lanes_where(&self.regs[fi][c as usize * LANES..][..LANES], self.n, |x| {
            x != 0
        })
    }

    fn storage(&self, fi: usize, root: Root) -> &[u32] {
        match root {
            Root::Local => &self.locals[fi],
            Root::Private => &self.privates,
            Root::Uniform => &self.uniforms,
        }
    }

    /// The first component of `place` in lane `l`, or the index that is out of range.
    fn offset(&self, fi: usize, place: &Place, l: usize) -> Result<u32, (i64, u32)> {
        let mut at = place.at;
        for &(index, stride, count) in &place.dynamic {
            let i = i64::from(self.regs[fi][index as usize * LANES + l] as i32);
            if i < 0 || i >= i64::from(count) {
                return Err((i, count));
            }
            at += i as u32 * stride;
        }
        Ok(at)
    }

    fn offset_checked(
        &self,
        fi: usize,
        place: &Place,
        l: usize,
        live: bool,
        at: usize,
    ) -> Res<u32> {
        match self.offset(fi, place, l) {
            Ok(o) => Ok(o),
            Err(_) if !live => Ok(place.at),
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

    fn read_whole(&self, fi: usize, place: &Place, l: usize) -> Vec<u32> {
        let s = self.storage(fi, place.root);
        (place.whole.at..place.whole.at + place.whole.n)
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

/// The lanes among the first `n` where `f` holds.
fn lanes_where(row: &[u32], n: usize, f: impl Fn(u32) -> bool) -> u64 {
    row[..n]
        .iter()
        .enumerate()
        .fold(0, |m, (l, &x)| if f(x) { m | bit(l) } else { m })
}

/// Copies the lanes of `mask` from `src` to `dst`.
fn masked_copy(dst: &mut [u32], src: &[u32], mask: u64, n: usize) {
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
