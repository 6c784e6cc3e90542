//! One batch of invocations as the host hands it to the machine and reads it back: each input's
//! components lane by lane, how many lanes run and which of them are invocations (the others a
//! quad's helpers, run only for derivatives), and, after the run, each output component by lane
//! and the lanes that were discarded.
//!
//! Layout: input `i`'s component `c` in lane `l` is `rows[i][c·LANES + l]` (32-bit words: a
//! float's bits, or an integer's); outputs are laid out the same, one output after another.

use crate::machine::{LANES, Machine, RunError, Textures};
use crate::program::Program;

/// The inputs of one batch of up to [`LANES`] invocations.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Batch {
    rows: Vec<Vec<u32>>,
    lanes: usize,
    live: u64,
}

/// The lanes `0..n` as a mask.
#[must_use]
pub fn first_lanes(n: usize) -> u64 {
    if n >= LANES { u64::MAX } else { (1 << n) - 1 }
}

impl Batch {
    /// A batch for `program`'s inputs, every row zero, no lane yet.
    #[must_use]
    pub fn new(program: &Program) -> Self {
        Self {
            rows: program
                .inputs
                .iter()
                .map(|v| vec![0; v.components as usize * LANES])
                .collect(),
            lanes: 0,
            live: 0,
        }
    }

    /// Starts a batch of `lanes` lanes for `program`, keeping the storage of the batch before
    /// (of this program or another): as [`Self::start`], with rows for `program`'s inputs.
    pub fn start_for(&mut self, program: &Program, lanes: usize) {
        self.rows.resize(program.inputs.len(), Vec::new());
        for (rows, v) in self.rows.iter_mut().zip(&program.inputs) {
            rows.resize(v.components as usize * LANES, 0);
        }
        self.start(lanes);
    }

    /// Starts another batch of `lanes` lanes (at most [`LANES`]), all of them invocations, its
    /// inputs zero.
    pub fn start(&mut self, lanes: usize) {
        self.lanes = lanes.min(LANES);
        self.live = first_lanes(self.lanes);
        for r in &mut self.rows {
            r.fill(0);
        }
    }

    /// Marks lane `lane` a helper: it runs, so that its quad's derivatives have its values,
    /// but a run-time error in it is not reported (its outputs are the host's to ignore).
    pub fn helper(&mut self, lane: usize) {
        self.live &= !(1 << lane);
    }

    /// Sets input `input`'s components in lane `lane` (as many as the input has).
    pub fn set(&mut self, input: usize, lane: usize, value: &[f32]) {
        if let Some(rows) = self.rows.get_mut(input) {
            for (c, x) in value.iter().enumerate().take(rows.len() / LANES) {
                rows[c * LANES + lane] = x.to_bits();
            }
        }
    }

    /// Every input's rows (see the module's layout).
    #[must_use]
    pub fn rows(&self) -> &[Vec<u32>] {
        &self.rows
    }

    /// Every input's rows, for a host that writes many lanes at once (see the module's
    /// layout).
    pub fn rows_mut(&mut self) -> &mut [Vec<u32>] {
        &mut self.rows
    }

    /// The lanes that run.
    #[must_use]
    pub fn lanes(&self) -> usize {
        self.lanes
    }

    /// The lanes that are invocations.
    #[must_use]
    pub fn live(&self) -> u64 {
        self.live
    }
}

/// What a batch's run left: the outputs lane by lane, and the lanes that were discarded.
#[derive(Clone, Copy, Debug)]
pub struct Ran<'m> {
    result: &'m [u32],
    /// The invocations' globals, `LANES` values a component (what a watch reads).
    privates: &'m [u32],
    /// The lanes that were discarded.
    pub killed: u64,
    /// Each lane's steps of the student's code, when the machine counts them
    /// (`Machine::count_cost`).
    cost: Option<[u32; LANES]>,
}

impl Ran<'_> {
    /// Component `c` of the outputs (one after another) in lane `lane`, as a float.
    #[must_use]
    pub fn output(&self, c: usize, lane: usize) -> f32 {
        self.result
            .get(c * LANES + lane)
            .map_or(0.0, |b| f32::from_bits(*b))
    }

    /// The first `N` output components in lane `lane`.
    #[must_use]
    pub fn outputs<const N: usize>(&self, lane: usize) -> [f32; N] {
        std::array::from_fn(|c| self.output(c, lane))
    }

    /// The outputs' rows, one output after another (see the module's layout).
    #[must_use]
    pub fn rows(&self) -> &[u32] {
        self.result
    }

    /// What lane `lane`'s watch saw, for a program compiled with one (`crate::probe`): `None`
    /// where the lane never ran the watched line.
    #[must_use]
    pub fn watched(
        &self,
        places: &crate::watched::WatchPlaces,
        lane: usize,
    ) -> Option<crate::watched::Watched> {
        places.read(self.privates, lane)
    }

    /// The steps of the student's code lane `lane` ran, when the machine counts them.
    #[must_use]
    pub fn cost(&self, lane: usize) -> Option<u32> {
        self.cost.map(|c| c[lane])
    }

    /// Whether lane `lane` was discarded.
    #[must_use]
    pub fn discarded(&self, lane: usize) -> bool {
        self.killed & (1 << lane) != 0
    }
}

impl Machine<'_> {
    /// Runs the entry point over `batch`, reading `textures`.
    ///
    /// # Errors
    /// A run-time error of an invocation (not a helper): an index out of range, an integer
    /// division by zero, a `texelFetch` outside its texture, the loop budget spent.
    pub fn run_batch(
        &mut self,
        batch: &Batch,
        textures: &dyn Textures,
    ) -> Result<Ran<'_>, RunError> {
        let inputs: Vec<&[u32]> = batch.rows.iter().map(Vec::as_slice).collect();
        let killed = self.run(&inputs, batch.lanes, batch.live, textures)?;
        Ok(Ran {
            result: self.result(),
            privates: &self.privates,
            killed,
            cost: self.cost,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::Machine;
    use crate::{Stage, compile};

    /// One quad: inputs set lane by lane, a discarded lane, a helper whose index past the
    /// array's end is not an error, and the outputs read back by component and lane; each
    /// value worked out from the shader by hand.
    #[test]
    fn a_batch_runs_its_lanes_and_reads_back_by_component_and_lane() {
        let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n    float a[2] = float[2](10.0, 20.0);\n    if (x < 0.0) {\n        discard;\n    }\n    color = vec4(x, a[int(x) % 4], dFdx(x), 1.0);\n}\n";
        let program = compile(Stage::Fragment, src).expect("compiles");
        let mut machine = program.machine();
        let mut batch = Batch::new(&program);
        batch.start(4);
        for (l, x) in [0.0f32, 1.0, -1.0, 3.0].into_iter().enumerate() {
            batch.set(0, l, &[x]);
        }
        // Lane 3 reads a[3]: out of range, but it is a helper.
        batch.helper(3);
        assert_eq!(batch.live(), 0b0111);
        let ran = machine.run_batch(&batch, &()).expect("runs");
        // Lanes 0 and 1: x, a[x], dFdx = x(top right) − x(top left) = 1 − 0.
        assert_eq!(ran.outputs::<4>(0), [0.0, 10.0, 1.0, 1.0]);
        assert_eq!(ran.outputs::<4>(1), [1.0, 20.0, 1.0, 1.0]);
        assert!(ran.discarded(2));
        assert!(!ran.discarded(0) && !ran.discarded(1));
        // The same lane 3 as an invocation: its index is an error, at line 9.
        batch.start(4);
        for (l, x) in [0.0f32, 1.0, -1.0, 3.0].into_iter().enumerate() {
            batch.set(0, l, &[x]);
        }
        let e = machine.run_batch(&batch, &()).expect_err("a[3]");
        assert_eq!(program.run_error(&e).line, 9);
    }

    /// Places indexed by a loop's counter, alike in every lane (read and written with one
    /// offset for all lanes), beside places indexed by each lane's own value; and an index out
    /// of range alike in every lane: an error while a lane is live, none when every lane is a
    /// helper. The lights' intensities' x are k = (2, 3, 5) (a light is 15 components: kind,
    /// position, direction, intensity from the 8th, …); by hand, with a[i] = k[i]·x:
    /// Σ a = 10x, a[int x] = k[int x]·x, and k[light_count] = k[1] = 3.
    #[test]
    fn a_place_indexed_alike_in_every_lane_reads_and_writes_as_lane_by_lane() {
        let src = "#version 330 core\nuniform Light lights[MAX_LIGHTS];\nuniform int light_count;\nin float x;\nout vec4 color;\nvoid main() {\n    float a[3];\n    for (int i = 0; i < 3; i++) {\n        a[i] = lights[i].intensity.x * x;\n    }\n    int j = int(x);\n    color = vec4(a[0] + a[1] + a[2], a[j], lights[j].intensity.x, lights[light_count].intensity.x);\n}\n";
        let program = compile(Stage::Fragment, src).expect("compiles");
        let mut machine = program.machine();
        let set = |machine: &mut Machine<'_>, name: &str, values: &[(usize, u32)]| {
            let (_, reg) = program
                .uniforms
                .iter()
                .find(|(n, _)| n == name)
                .expect("declared");
            let mut bits = vec![0; reg.len as usize];
            for &(at, v) in values {
                bits[at] = v;
            }
            machine.set_uniform(*reg, &bits);
        };
        let k = [2f32, 3.0, 5.0];
        let intensities: Vec<(usize, u32)> = (0..3).map(|i| (i * 15 + 7, k[i].to_bits())).collect();
        set(&mut machine, "lights", &intensities);
        set(&mut machine, "light_count", &[(0, 1)]);
        let mut batch = Batch::new(&program);
        let start = |batch: &mut Batch| {
            batch.start(4);
            for (l, x) in [0.0f32, 1.0, 2.0, 1.0].into_iter().enumerate() {
                batch.set(0, l, &[x]);
            }
        };
        start(&mut batch);
        let ran = machine.run_batch(&batch, &()).expect("runs");
        assert_eq!(ran.outputs::<4>(0), [0.0, 0.0, 2.0, 3.0]);
        assert_eq!(ran.outputs::<4>(1), [10.0, 3.0, 3.0, 3.0]);
        assert_eq!(ran.outputs::<4>(2), [20.0, 10.0, 5.0, 3.0]);
        assert_eq!(ran.outputs::<4>(3), [10.0, 3.0, 3.0, 3.0]);
        // lights[light_count] with light_count = 8 in every lane: out of range (line 12).
        set(&mut machine, "lights", &intensities);
        set(&mut machine, "light_count", &[(0, 8)]);
        start(&mut batch);
        let e = machine.run_batch(&batch, &()).expect_err("lights[8]");
        assert_eq!(program.run_error(&e).line, 12);
        assert!(
            e.message.contains("index 8 is out of range"),
            "{}",
            e.message
        );
        // Every lane a helper: no error, and the lanes still ran.
        start(&mut batch);
        for l in 0..4 {
            batch.helper(l);
        }
        let ran = machine
            .run_batch(&batch, &())
            .expect("helpers report nothing");
        assert_eq!(ran.outputs::<3>(2), [20.0, 10.0, 5.0]);
    }

    /// Each lane's cost is the length of its own trace: the counter and the recorder agree lane
    /// by lane, over lanes that loop 0, 1, 2 and 5 times and take either branch. By hand, a lane
    /// with k iterations runs `s = 0` (1), the loop (k iterations, each with its test, `s += 1`
    /// and `i++`, and the last test that leaves), the `if` (1), one write in its branch (1) and
    /// `color = …` (1).
    #[test]
    fn each_lanes_cost_is_the_length_of_its_own_trace() {
        let src = "#version 330 core\nin float x;\nout vec4 color;\nvoid main() {\n    float s = 0.0;\n    for (int i = 0; i < int(x); i++) {\n        s += 1.0;\n    }\n    float t;\n    if (s > 1.5) {\n        t = 1.0;\n    } else {\n        t = 0.0;\n    }\n    color = vec4(s, t, 0.0, 1.0);\n}\n";
        let program = compile(Stage::Fragment, src).expect("compiles");
        let mut machine = program.machine();
        let mut batch = Batch::new(&program);
        batch.start(4);
        for (l, x) in [0.0f32, 1.0, 2.0, 5.0].into_iter().enumerate() {
            batch.set(0, l, &[x]);
        }
        machine.count_cost(true);
        machine.run_batch(&batch, &()).expect("runs");
        let costs: Vec<u32> = (0..4).map(|l| machine.cost(l).expect("counting")).collect();
        for (l, cost) in costs.iter().enumerate() {
            machine.trace_lane(Some(l));
            machine.run_batch(&batch, &()).expect("runs");
            let events = machine.take_trace();
            assert_eq!(
                *cost as usize,
                program.describe(&events).len(),
                "lane {l}: {:#?}",
                program.describe(&events)
            );
        }
        // More iterations, more steps: each one adds the same few.
        assert!(costs[0] < costs[1] && costs[1] < costs[2] && costs[2] < costs[3]);
        assert_eq!(costs[3] - costs[2], 3 * (costs[2] - costs[1]));
        machine.count_cost(false);
        assert_eq!(machine.cost(0), None);
    }
}
