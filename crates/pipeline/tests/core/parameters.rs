//! A function's `out` and `inout` parameters, as GLSL 3.30 §6.1.1 defines them: copied in at
//! the call (`inout` only), copied back to the argument when the function returns, and only
//! for the invocations that made the call. Every expected value is worked out by hand.

use pipeline::shader::{Stage, Uniforms};

use crate::shader::{compile, run};

/// `x` in lane `l` is `l · 0.75 − 1` (−1, −0.25, 0.5, 1.25, …).
fn xs(n: usize) -> Vec<Vec<f32>> {
    (0..n).map(|l| vec![l as f32 * 0.75 - 1.0]).collect()
}

#[test]
fn out_parameters_write_back_to_a_local_a_component_and_an_array_element() {
    let src = "#version 330 core
in float x;
out vec4 color;
void split(float v, out float whole, out float part) {
    whole = floor(v);
    part = v - whole;
}
void main() {
    float w;
    float p;
    split(x, w, p);
    vec2 both;
    split(x * 2.0, both.y, both.x);
    float a[3];
    int i = x > 0.0 ? 2 : 0;
    split(x + 10.0, a[i], a[1]);
    color = vec4(w + p * 100.0, both.x + both.y * 100.0, a[i], a[1]);
}
";
    let p = compile(Stage::Fragment, src);
    let (out, _) = run(&p, &Uniforms::default(), &[xs(8)], &[]).expect("runs");
    for (l, o) in out.iter().enumerate() {
        let x = l as f32 * 0.75 - 1.0;
        let (w, f) = (x.floor(), x - x.floor());
        let x2 = x * 2.0;
        let x10 = x + 10.0;
        let want = [
            w + f * 100.0,
            (x2 - x2.floor()) + x2.floor() * 100.0,
            x10.floor(),
            x10 - x10.floor(),
        ];
        for (c, (got, want)) in o.iter().zip(want).enumerate() {
            assert!(
                (got - want).abs() < 1e-4,
                "lane {l} (x = {x}), component {c}: {got} != {want}"
            );
        }
    }
}

#[test]
fn inout_reads_the_argument_and_only_the_calling_lanes_are_written() {
    // Lanes with x < 0 call brighten (c = c·k + 1 on every component); the others keep c.
    let src = "#version 330 core
in float x;
out vec4 color;
void brighten(inout vec3 c, in float k) {
    c = c * k + vec3(1.0);
}
void main() {
    vec3 c = vec3(x, 2.0 * x, 3.0);
    if (x < 0.0) {
        brighten(c, 4.0);
    }
    color = vec4(c, 1.0);
}
";
    let p = compile(Stage::Fragment, src);
    let (out, _) = run(&p, &Uniforms::default(), &[xs(6)], &[]).expect("runs");
    for (l, o) in out.iter().enumerate() {
        let x = l as f32 * 0.75 - 1.0;
        let mut c = [x, 2.0 * x, 3.0];
        if x < 0.0 {
            c = c.map(|v| v * 4.0 + 1.0);
        }
        assert_eq!(&o[..3], &c, "lane {l} (x = {x})");
    }
}

#[test]
fn an_out_parameter_can_be_the_shaders_own_output_and_a_struct() {
    let src = "#version 330 core
in float x;
out vec4 color;
struct Hit { float t; vec3 n; };
void paint(float v, out vec4 c) {
    c = vec4(v, v * v, 0.5, 1.0);
}
bool hit(float v, out Hit h) {
    h.t = v * 3.0;
    h.n = vec3(0.0, 1.0, 0.0);
    return v > 0.0;
}
void main() {
    paint(x, color);
    Hit h;
    if (hit(x, h)) {
        color.z = h.t + h.n.y;
    }
}
";
    let p = compile(Stage::Fragment, src);
    let (out, _) = run(&p, &Uniforms::default(), &[xs(6)], &[]).expect("runs");
    for (l, o) in out.iter().enumerate() {
        let x = l as f32 * 0.75 - 1.0;
        let z = if x > 0.0 { x * 3.0 + 1.0 } else { 0.5 };
        assert_eq!(o, &vec![x, x * x, z, 1.0], "lane {l} (x = {x})");
    }
}

#[test]
fn the_trace_shows_the_callees_writes_and_the_copies_back_at_the_call() {
    let src = "#version 330 core
in float x;
out vec4 color;
void split(float v, out float whole, out float part) {
    whole = floor(v);
    part = v - whole;
}
void main() {
    float w;
    float p;
    split(x, w, p);
    color = vec4(w, p, 0.0, 1.0);
}
";
    let p = compile(Stage::Fragment, src);
    // Lane 1: x = −0.25, so whole = −1 and part = 0.75.
    let text = crate::shader::traced_lane_1(&p, -0.25);
    let at = |s: &str| text.iter().position(|t| t == s);
    // The `void` function's return is at its closing brace (line 7), not at line 1.
    let order = [
        "5: whole = -1.000",
        "6: part = 0.750",
        "7: return from split()",
        "11: w = -1.000",
        "11: p = 0.750",
    ]
    .map(|s| at(s).unwrap_or_else(|| panic!("no `{s}` in {text:#?}")));
    assert!(order.is_sorted(), "{text:#?}");
}

#[test]
fn const_in_and_precision_qualifiers_on_parameters_are_read() {
    // `const in`, `in const` and `in highp` are the same read-only parameter (GLSL 3.30
    // §6.1.1, §4.5.2); each squares x here.
    for params in [
        "const in float v",
        "in const float v",
        "in highp float v",
        "const mediump float v",
    ] {
        let src = format!(
            "#version 330 core\nin float x;\nout vec4 color;\nfloat sq({params}) {{\n    return v * v;\n}}\nvoid main() {{\n    color = vec4(sq(x));\n}}\n"
        );
        let p = compile(Stage::Fragment, &src);
        let (out, _) = run(&p, &Uniforms::default(), &[xs(4)], &[]).expect("runs");
        for (l, o) in out.iter().enumerate() {
            let x = l as f32 * 0.75 - 1.0;
            assert_eq!(o[0], x * x, "{params}, lane {l}");
        }
    }
}

#[test]
fn a_sampler_pipelens_does_not_bind_is_refused_as_a_parameter_at_its_type() {
    use pipeline::shader::Complaint;
    let src = "#version 330 core\nin vec3 uvw;\nout vec4 color;\nvec4 look(sampler3D s, vec3 at) {\n    return texture(s, at);\n}\nvoid main() {\n    color = vec4(uvw, 1.0);\n}\n";
    let e = crate::shader::errors(Stage::Fragment, src);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        e[0].complaint,
        Complaint::SamplerParameter("sampler3D".into())
    );
    // `vec4 look(` is 10 characters: the type starts at column 11 of line 4.
    assert_eq!((e[0].line, e[0].column), (4, 11));
    assert!(
        e[0].message.contains("only a `sampler2D`"),
        "{}",
        e[0].message
    );
}

#[test]
fn a_mistake_in_a_function_that_takes_a_sampler_is_placed_in_the_students_text() {
    // The sampler's uses are rewritten for naga (`texture(sampler2D(s, …), at)`); the unknown
    // name after one is still at its own column: `    return texture(s, at) * ` is 28 bytes.
    let src = "#version 330 core\nuniform sampler2D tex;\nin vec2 uv;\nout vec4 color;\nvec4 look(sampler2D s, vec2 at) {\n    return texture(s, at) * nope;\n}\nvoid main() {\n    color = look(tex, uv);\n}\n";
    let e = crate::shader::errors(Stage::Fragment, src);
    assert_eq!((e[0].line, e[0].column), (6, 29), "{e:?}");
    assert!(e[0].message.contains("nope"), "{}", e[0].message);
    // A value where the sampler goes: refused at the call's line, with the parameters to
    // compare with (not "recursion", as it once read).
    let src = src
        .replace(" * nope", "")
        .replace("look(tex, uv)", "look(uv, uv)");
    let e = crate::shader::errors(Stage::Fragment, &src);
    assert_eq!(e[0].line, 9, "{e:?}");
    assert_eq!(
        e[0].complaint,
        pipeline::shader::Complaint::ArgumentTypes {
            name: "look".into(),
            parameters: "(sampler2D s, vec2 at)".into()
        }
    );
}
