//! Stepping through a run that has already happened: a [`Trace`](crate::Trace) read forward and back as a
//! debugger reads a live program. Every position is an index into the trace (the step shown
//! has run); stepping back is free, since nothing is run again.
//!
//! The call depth of a step counts the calls still open when it runs: `call f()` stands at the
//! caller's depth, `f`'s own steps and its `return` one deeper. *Over* goes to the next step no
//! deeper than the one shown, *out* to the next one shallower, *into* to the very next one.

use std::collections::BTreeMap;

use crate::trace::{Step, TraceLine, Value};

/// A breakpoint: a line of the source, and on which of its hits the run stops.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Breakpoint {
    /// The line, from 1.
    pub line: usize,
    /// Stop only at this hit of the line, counted from 1 over the run (`None`: at every hit).
    pub hit: Option<u32>,
}

impl Breakpoint {
    /// A breakpoint at every hit of `line`.
    #[must_use]
    pub fn at(line: usize) -> Self {
        Self { line, hit: None }
    }
}

/// The call depth of each step (see the module's notes).
#[must_use]
pub fn depths(trace: &[TraceLine]) -> Vec<usize> {
    let mut depth = 0usize;
    trace
        .iter()
        .map(|t| {
            let here = depth;
            match t.step {
                Step::Call { .. } => depth += 1,
                Step::Return { .. } => depth = depth.saturating_sub(1),
                _ => {}
            }
            // A call's step stands at its caller's depth; a return's in its function.
            here
        })
        .collect()
}

/// The next step after `at` no deeper than `at` (a call run through whole); `None` at the end.
#[must_use]
pub fn over(trace: &[TraceLine], at: usize) -> Option<usize> {
    let d = depths(trace);
    let here = *d.get(at)?;
    (at + 1..trace.len()).find(|&k| d[k] <= here)
}

/// The next step after `at` shallower than it: the caller's next step once the function
/// shown has returned; `None` in `main` or when nothing follows.
#[must_use]
pub fn out(trace: &[TraceLine], at: usize) -> Option<usize> {
    let d = depths(trace);
    let here = *d.get(at)?;
    (at + 1..trace.len()).find(|&k| d[k] < here)
}

/// The next step after `at` on `line`; `None` when the rest of the run never reaches it.
#[must_use]
pub fn to_line(trace: &[TraceLine], at: usize, line: usize) -> Option<usize> {
    (at + 1..trace.len()).find(|&k| trace[k].line == line)
}

/// How many times the run had reached each step's line, that step included: the first step on
/// a line is its hit 1.
#[must_use]
pub fn hits(trace: &[TraceLine]) -> Vec<u32> {
    let mut seen: BTreeMap<usize, u32> = BTreeMap::new();
    trace
        .iter()
        .map(|t| {
            let n = seen.entry(t.line).or_default();
            *n += 1;
            *n
        })
        .collect()
}

/// Whether step `k` stops at one of `breakpoints`.
fn stops(trace: &[TraceLine], hits: &[u32], breakpoints: &[Breakpoint], k: usize) -> bool {
    breakpoints
        .iter()
        .any(|b| b.line == trace[k].line && b.hit.is_none_or(|h| h == hits[k]))
}

/// The first step after `at` (or from the start, `at = None`) where a breakpoint stops the run.
#[must_use]
pub fn next_break(
    trace: &[TraceLine],
    at: Option<usize>,
    breakpoints: &[Breakpoint],
) -> Option<usize> {
    let h = hits(trace);
    let from = at.map_or(0, |a| a + 1);
    (from..trace.len()).find(|&k| stops(trace, &h, breakpoints, k))
}

/// The last step before `at` where a breakpoint stops the run (running backward).
#[must_use]
pub fn previous_break(trace: &[TraceLine], at: usize, breakpoints: &[Breakpoint]) -> Option<usize> {
    let h = hits(trace);
    (0..at.min(trace.len()))
        .rev()
        .find(|&k| stops(trace, &h, breakpoints, k))
}

/// A variable as it stands at a step: its name, its value, and the line that last wrote it.
#[derive(Clone, Debug, PartialEq)]
pub struct Held<'t> {
    /// The variable (a function's return as `name()`).
    pub name: String,
    /// Its value after its last write up to the step.
    pub value: &'t Value,
    /// The line of that write.
    pub line: usize,
    /// The step of that write.
    pub step: usize,
}

/// The variables of the function the step `at` runs in, each with its last value up to that
/// step (that step's write included), in the order they were first written. A function's
/// frame begins at the step after its call; the caller's values come back when it returns.
#[must_use]
pub fn in_scope(trace: &[TraceLine], at: usize) -> Vec<Held<'_>> {
    // One frame of names per open call; a return closes its function's frame.
    let mut frames: Vec<Vec<Held<'_>>> = vec![Vec::new()];
    for (k, t) in trace.iter().enumerate().take(at + 1) {
        if let Some((name, value)) = written(&t.step) {
            let frame = frames.last_mut().expect("main's frame is never closed");
            match frame.iter_mut().find(|h| h.name == name) {
                Some(h) => {
                    h.value = value;
                    h.line = t.line;
                    h.step = k;
                }
                None => frame.push(Held {
                    name,
                    value,
                    line: t.line,
                    step: k,
                }),
            }
        }
        // A call opens its function's frame after its own step, a return closes it after its
        // own: the step shown stands in its function.
        if k < at {
            match &t.step {
                Step::Call { .. } => frames.push(Vec::new()),
                Step::Return { .. } if frames.len() > 1 => {
                    frames.pop();
                }
                _ => {}
            }
        }
    }
    frames.pop().unwrap_or_default()
}

/// What a step wrote into its frame: a variable (a return's value belongs to its caller, and
/// is shown there as `name()`).
fn written(step: &Step) -> Option<(String, &Value)> {
    match step {
        Step::Assign { name, value } => Some((name.clone(), value)),
        _ => None,
    }
}

/// Each line's last step up to step `at` (any function's), for what the source shows beside
/// its lines: `line → step`.
#[must_use]
pub fn beside_lines(trace: &[TraceLine], at: usize) -> BTreeMap<usize, usize> {
    trace
        .iter()
        .enumerate()
        .take(at + 1)
        .map(|(k, t)| (t.line, k))
        .collect()
}

/// The colour a value shows, when it can be one: a `vec3` or `vec4` whose every component
/// lies in [0, 1] (alpha 1 for a `vec3`).
#[must_use]
pub fn colour(value: &Value) -> Option<[f32; 4]> {
    let in_unit = value.numbers.iter().all(|x| (0.0..=1.0).contains(x));
    #[allow(clippy::cast_possible_truncation)]
    let c = |k: usize| value.numbers[k] as f32;
    match (value.ty.as_str(), in_unit) {
        ("vec3", true) => Some([c(0), c(1), c(2), 1.0]),
        ("vec4", true) => Some([c(0), c(1), c(2), c(3)]),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assign(line: usize, name: &str, x: f64) -> TraceLine {
        TraceLine {
            line,
            text: format!("{name} = {x}"),
            value: Some(x.to_string()),
            step: Step::Assign {
                name: name.to_owned(),
                value: Value {
                    ty: "float".to_owned(),
                    numbers: vec![x],
                },
            },
        }
    }

    fn step(line: usize, step: Step) -> TraceLine {
        TraceLine {
            line,
            text: String::new(),
            value: None,
            step,
        }
    }

    /// A run written by hand from this source:
    ///
    /// ```glsl
    /// 1 float half_of(float x) {
    /// 2     float h = x * 0.5;
    /// 3     return h;
    /// 4 }
    /// 5 void main() {
    /// 6     float a = 2.0;
    /// 7     float b = half_of(a);
    /// 8     for (int i = 0; i < 2; i++) { a += b; }
    /// 9 }
    /// ```
    fn run() -> Vec<TraceLine> {
        let ret = |x: f64| Step::Return {
            name: "half_of".to_owned(),
            value: Some(Value {
                ty: "float".to_owned(),
                numbers: vec![x],
            }),
        };
        vec![
            assign(6, "a", 2.0), // 0
            step(
                7,
                Step::Call {
                    name: "half_of".to_owned(),
                },
            ), // 1
            assign(2, "h", 1.0), // 2
            step(3, ret(1.0)),   // 3
            assign(7, "b", 1.0), // 4
            step(8, Step::LoopTest { holds: true }), // 5
            assign(8, "a", 3.0), // 6
            step(8, Step::LoopTest { holds: true }), // 7
            assign(8, "a", 4.0), // 8
            step(8, Step::LoopTest { holds: false }), // 9
        ]
    }

    #[test]
    fn a_call_stands_at_its_callers_depth_and_its_body_one_deeper() {
        assert_eq!(depths(&run()), [0, 0, 1, 1, 0, 0, 0, 0, 0, 0]);
    }

    #[test]
    fn over_runs_a_call_through_into_enters_it_out_leaves_it() {
        let t = run();
        assert_eq!(over(&t, 1), Some(4), "over the call: b's assignment");
        assert_eq!(
            over(&t, 2),
            Some(3),
            "inside the function, over goes on in it"
        );
        assert_eq!(out(&t, 2), Some(4), "out of half_of: back in main");
        assert_eq!(out(&t, 5), None, "main has no caller");
        assert_eq!(over(&t, 9), None, "the end of the run");
    }

    #[test]
    fn to_line_finds_the_next_hit_and_none_past_the_last() {
        let t = run();
        assert_eq!(to_line(&t, 0, 8), Some(5));
        assert_eq!(to_line(&t, 5, 8), Some(6));
        assert_eq!(to_line(&t, 4, 2), None, "line 2 ran only before");
    }

    #[test]
    fn a_breakpoint_with_a_hit_count_stops_at_that_hit_only() {
        let t = run();
        // Line 8 is hit by steps 5..=9: hits 1 to 5.
        assert_eq!(hits(&t)[5..], [1, 2, 3, 4, 5]);
        let every = [Breakpoint::at(8)];
        assert_eq!(next_break(&t, None, &every), Some(5));
        assert_eq!(next_break(&t, Some(5), &every), Some(6));
        let third = [Breakpoint {
            line: 8,
            hit: Some(3),
        }];
        assert_eq!(next_break(&t, None, &third), Some(7));
        assert_eq!(next_break(&t, Some(7), &third), None);
        assert_eq!(previous_break(&t, 9, &third), Some(7));
        assert_eq!(previous_break(&t, 7, &third), None);
    }

    #[test]
    fn the_scope_is_the_functions_own_and_the_callers_comes_back() {
        let t = run();
        let names = |at| -> Vec<(String, f64)> {
            in_scope(&t, at)
                .into_iter()
                .map(|h| (h.name, h.value.numbers[0]))
                .collect()
        };
        assert_eq!(
            names(2),
            [("h".to_owned(), 1.0)],
            "inside half_of: its h only"
        );
        assert_eq!(
            names(3),
            [("h".to_owned(), 1.0)],
            "its return is still in it"
        );
        assert_eq!(
            names(4),
            [("a".to_owned(), 2.0), ("b".to_owned(), 1.0)],
            "back in main: a as it was, b just written"
        );
        assert_eq!(names(8)[0], ("a".to_owned(), 4.0), "a's last write");
    }

    #[test]
    fn each_line_shows_its_last_step_up_to_the_step() {
        let t = run();
        let shown = beside_lines(&t, 7);
        assert_eq!(shown[&8], 7, "the loop's test, after a's write");
        assert_eq!(shown[&3], 3, "the return");
        assert_eq!(shown[&7], 4, "b's write, after the call on the same line");
        assert!(!beside_lines(&t, 0).contains_key(&8));
    }

    #[test]
    fn a_colour_is_a_vec3_or_vec4_within_zero_and_one() {
        let v = |ty: &str, numbers: Vec<f64>| Value {
            ty: ty.to_owned(),
            numbers,
        };
        assert_eq!(
            colour(&v("vec3", vec![1.0, 0.5, 0.0])),
            Some([1.0, 0.5, 0.0, 1.0])
        );
        assert_eq!(colour(&v("vec3", vec![0.0, -0.7, 0.7])), None, "a normal");
        assert_eq!(colour(&v("vec2", vec![0.5, 0.5])), None);
        assert_eq!(
            colour(&v("vec4", vec![0.25, 0.5, 0.75, 0.5])),
            Some([0.25, 0.5, 0.75, 0.5])
        );
    }
}
