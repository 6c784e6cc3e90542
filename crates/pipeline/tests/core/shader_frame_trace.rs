//! The student's fragment shader traced inside a frame: the inspected pixel keeps its run, each
//! value as numbers, a function's return, a loop's condition on the loop's line, `break` and
//! `continue` named.

use pipeline::shader::{Step, Value};

use crate::shader_frame::{settings, sphere_scene, with_shaders};
use crate::support::render;

#[test]
fn the_inspected_pixel_keeps_its_fragment_shaders_run() {
    let fs = "#version 330 core\nin vec3 w_nrm;\nout vec4 color;\nvoid main() {\n  vec3 n = normalize(w_nrm);\n  float k = n.z > 0.5 ? 1.0 : 0.25;\n  color = vec4(n * 0.5 + 0.5, k);\n}\n";
    let mut s = settings();
    s.capture.pixel = Some((80, 60));
    let f = render(&with_shaders(sphere_scene(false), None, Some(fs)), &s);
    let record = f.shaders.as_ref().expect("a shader record");
    assert_eq!(
        record.pixel.len(),
        1,
        "one triangle covers the centre pixel"
    );
    let frag = &record.pixel[0];
    assert_eq!(frag.inputs.len(), 1);
    assert_eq!(frag.inputs[0].0, "w_nrm");
    let lines: Vec<usize> = frag.trace.iter().map(|t| t.line).collect();
    assert_eq!(lines, [5, 6, 6, 7], "{:#?}", frag.trace);
    assert_eq!(frag.trace[1].text, "if: true → then");
    assert!(
        frag.trace[0].text.starts_with("n = vec3("),
        "{:?}",
        frag.trace[0]
    );
    // The traced colour is the pixel's colour.
    let out = frag.output.expect("not discarded");
    let i = (119 - 60) * 160 + 80;
    assert!(
        (0..3).all(|c| (out[c] - f.pixels.color[i][c]).abs() < 1e-6),
        "{out:?} vs {:?}",
        f.pixels.color[i]
    );
}

/// The trace is data: each step's values as numbers, a helper's return with its value. The
/// shader's values are constants, so every number is known by hand: `twice(0.25)` returns 0.5,
/// `m` is the 2×2 matrix with columns (h, 2) = (0.5, 2) and (3, 4), the `if` takes its arm.
#[test]
fn the_trace_holds_each_value_as_numbers_and_a_functions_return() {
    let fs = "#version 330 core\nout vec4 color;\nfloat twice(float x) {\n  return 2.0 * x;\n}\nvoid main() {\n  float h = twice(0.25);\n  mat2 m = mat2(h, 2.0, 3.0, 4.0);\n  bool big = h > 0.4;\n  if (big) {\n    h = 1.0;\n  }\n  color = vec4(h, m[1][0], 0.0, 1.0);\n}\n";
    let mut s = settings();
    s.capture.pixel = Some((80, 60));
    let f = render(&with_shaders(sphere_scene(false), None, Some(fs)), &s);
    let frag = &f.shaders.as_ref().expect("a record").pixel[0];
    let steps: Vec<&Step> = frag.trace.iter().map(|t| &t.step).collect();
    let value = |ty: &str, numbers: &[f64]| Value {
        ty: ty.to_owned(),
        numbers: numbers.to_vec(),
    };
    let returned = Step::Return {
        name: "twice".to_owned(),
        value: Some(value("float", &[0.5])),
    };
    assert!(steps.contains(&&returned), "{:#?}", frag.trace);
    let line = frag
        .trace
        .iter()
        .find(|t| t.step == returned)
        .map(|t| (t.line, t.text.as_str()));
    assert_eq!(line, Some((4, "twice() returns 0.500")));
    for (name, v) in [
        ("h", value("float", &[0.5])),
        ("m", value("mat2", &[0.5, 2.0, 3.0, 4.0])),
        ("big", value("bool", &[1.0])),
        ("h", value("float", &[1.0])),
    ] {
        let assigned = Step::Assign {
            name: name.to_owned(),
            value: v,
        };
        assert!(
            steps.contains(&&assigned),
            "{assigned:?} in {:#?}",
            frag.trace
        );
    }
    assert!(steps.contains(&&Step::Branch { taken: true }));
    assert!(steps.contains(&&Step::Call {
        name: "twice".to_owned()
    }));
}

#[test]
fn a_loops_condition_is_traced_on_the_loops_line() {
    // naga writes a `for` condition as `if (!cond) break;` with no place of its own.
    let fs = "#version 330 core\nout vec4 color;\nvoid main() {\n  float s = 0.0;\n  for (int i = 0; i < 3; i++) {\n    s += 0.25;\n  }\n  color = vec4(s);\n}\n";
    let mut s = settings();
    s.capture.pixel = Some((80, 60));
    let f = render(&with_shaders(sphere_scene(false), None, Some(fs)), &s);
    let frag = &f.shaders.as_ref().expect("a record").pixel[0];
    let lines: Vec<usize> = frag.trace.iter().map(|t| t.line).collect();
    assert!(
        lines.iter().all(|&l| (4..=8).contains(&l)),
        "{:#?}",
        frag.trace
    );
    // i = 0, 1, 2: `i < 3` holds; i = 3: it does not — four tests on the `for` line, read as the
    // loop's condition (not as an `if` the student did not write).
    let tests: Vec<(usize, &Step)> = frag
        .trace
        .iter()
        .filter(|t| matches!(t.step, Step::LoopTest { .. } | Step::Branch { .. }))
        .map(|t| (t.line, &t.step))
        .collect();
    let holds = |h| Step::LoopTest { holds: h };
    assert_eq!(
        tests,
        [
            (5, &holds(true)),
            (5, &holds(true)),
            (5, &holds(true)),
            (5, &holds(false))
        ],
        "{:#?}",
        frag.trace
    );
    assert!(
        frag.trace
            .iter()
            .any(|t| t.text == "loop condition: false → the loop ends")
    );
    assert_eq!(frag.output.expect("drawn")[0], 0.75);
}

/// `continue` and `break` are named at their lines, after the `if` that chose them; the loop
/// test is the `while`'s condition.
#[test]
fn break_and_continue_are_named_in_the_trace() {
    let fs = "#version 330 core\nout vec4 color;\nvoid main() {\n  int i = 0;\n  float s = 0.0;\n  while (i < 10) {\n    i += 1;\n    if (i == 2) continue;\n    if (i == 3) break;\n    s += 0.25;\n  }\n  color = vec4(s);\n}\n";
    let mut s = settings();
    s.capture.pixel = Some((80, 60));
    let f = render(&with_shaders(sphere_scene(false), None, Some(fs)), &s);
    let frag = &f.shaders.as_ref().expect("a record").pixel[0];
    let at = |step: &Step| {
        frag.trace
            .iter()
            .filter(|t| &t.step == step)
            .map(|t| t.line)
            .collect::<Vec<_>>()
    };
    // i = 1: s = 0.25; i = 2: continue (line 8); i = 3: break (line 9). The `while` tests its
    // condition on line 6 three times, each holding: the loop ends by the break.
    assert_eq!(at(&Step::Continue), [8], "{:#?}", frag.trace);
    assert_eq!(at(&Step::Break), [9], "{:#?}", frag.trace);
    assert_eq!(at(&Step::LoopTest { holds: true }), [6, 6, 6]);
    assert!(at(&Step::LoopTest { holds: false }).is_empty());
    assert_eq!(frag.output.expect("drawn")[0], 0.25);
}
