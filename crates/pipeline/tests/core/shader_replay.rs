//! A watch in a run the frame kept: the inspected fragment, or a vertex, run again with the
//! shader compiled with a watch (`pipeline::watch_fragment`, `pipeline::watch_vertex`) — the
//! debugger's watch list. The expected values are known by hand: a loop adding ¼ three times,
//! a normalized vector's length, the colour the run wrote, a mesh's own vertex.

use pipeline::ReplayError;
use pipeline::shader::probe::WatchKind;

use crate::shader_frame::{settings, sphere_scene, with_shaders};
use crate::support::render;

/// Line 7 runs three times (s = ¼, ½, ¾); line 9 normalizes; line 10 writes the colour.
const FS: &str = "#version 330 core
in vec3 w_nrm;
out vec4 color;
void main() {
  float s = 0.0;
  for (int i = 0; i < 3; i++) {
    s += 0.25;
  }
  vec3 n = normalize(w_nrm);
  color = vec4(n * 0.5 + 0.5, s);
}
";

const VS: &str = "#version 330 core
in vec3 position;
in vec3 normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
out vec3 w_nrm;
void main() {
  w_nrm = normal;
  gl_Position = projection * view * model * vec4(position, 1.0);
}
";

#[test]
fn a_watch_reads_the_inspected_fragments_own_run_after_its_line() {
    let mut s = settings();
    s.capture.pixel = Some((80, 60));
    let scene = with_shaders(sphere_scene(false), None, Some(FS));
    let f = render(&scene, &s);
    let frag = &f.shaders.as_ref().expect("a record").pixel[0];
    let at = |line: usize, expr: &str| pipeline::watch_fragment(&scene, &f, frag, (line, expr));
    // Three stores after line 7, each right after one of its steps in the run shown.
    let s_values = at(7, "s").expect("runs");
    assert_eq!(s_values.kind, Some(WatchKind::Float));
    let s_values = s_values.stores;
    let after_line_7: Vec<usize> = frag
        .trace
        .iter()
        .enumerate()
        .filter(|(_, t)| t.line == 7)
        .map(|(i, _)| i + 1)
        .collect();
    assert_eq!(
        s_values,
        [
            (after_line_7[0], [0.25, 0.0, 0.0, 0.0]),
            (after_line_7[1], [0.5, 0.0, 0.0, 0.0]),
            (after_line_7[2], [0.75, 0.0, 0.0, 0.0]),
        ]
    );
    let length = at(9, "length(n)").expect("runs").stores;
    assert_eq!(length.len(), 1);
    assert!((length[0].1[0] - 1.0).abs() < 1e-6, "{length:?}");
    let colour = at(10, "color").expect("runs").stores;
    assert_eq!(Some(colour[0].1), frag.output, "the colour the run wrote");
    assert_eq!(colour[0].1[3], 0.75);
    // An input the shader never declared was never interpolated: named, not made up.
    match at(10, "gl_FragCoord.x") {
        Err(ReplayError::Input(name)) => assert_eq!(name, "gl_FragCoord"),
        other => panic!("{other:?}"),
    }
    // A name not in scope at the line is the compiler's message, at the line.
    match at(5, "n") {
        Err(ReplayError::Watch(e)) => assert!(e.to_string().contains('n'), "{e}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_watch_reads_a_vertexs_own_run() {
    let s = settings();
    let scene = with_shaders(sphere_scene(false), Some(VS), Some(FS));
    let f = render(&scene, &s);
    let row = 5;
    let seen = pipeline::watch_vertex(&scene, &f, row, (9, "position")).expect("runs");
    assert_eq!(seen.kind, Some(WatchKind::Vec3));
    let seen = seen.stores;
    let p = scene.objects[0].mesh.positions[row];
    assert_eq!(seen.len(), 1);
    assert_eq!(&seen[0].1[..3], &p.to_array()[..]);
    assert!(matches!(
        pipeline::watch_vertex(&scene, &f, f.vertices.len(), (9, "position")),
        Err(ReplayError::NotKept)
    ));
}
