//! A watch over the frame: an expression of the student's fragment shader after a line, at
//! every pixel — at the pixel the frame shows it at, read in window terms (y up) with no
//! mirror, and the frame it draws the frame the shader draws; and one of the vertex shader,
//! carried to every pixel as a varying is.

use pipeline::raster::Samples;
use pipeline::shader::probe::{WatchError, WatchKind, WatchSpec};

use crate::shader_frame::{settings, sphere_scene, with_shaders};
use crate::support::render;

/// Line 5 writes n, line 6 the colour (always within [0, 1], so stored as computed).
const FS: &str = "#version 330 core
in vec3 w_nrm;
out vec4 color;
void main() {
    vec3 n = normalize(w_nrm);
    color = vec4(n * 0.5 + 0.5, 1.0);
}
";

/// `gl_FragCoord.xy` is the pixel's centre in window terms, `(x + ½, y + ½)` with y up
/// (GLSL's definition): so the watch's pixel at image row r, column x holds `(x + ½, h − 1 −
/// r + ½)`; where no fragment ran, nothing.
#[test]
fn a_watch_holds_each_pixels_value_where_the_frame_shows_it() {
    let s = settings();
    let scene = with_shaders(sphere_scene(false), None, Some(FS));
    let watched = scene
        .watching(&WatchSpec::fragment(6, "gl_FragCoord.xy"))
        .expect("compiles");
    let f = render(&watched, &s);
    let picture = f
        .shaders
        .as_ref()
        .and_then(|r| r.watch.clone())
        .expect("the frame kept the watch");
    assert_eq!(picture.kind, Some(WatchKind::Vec2));
    assert_eq!(
        (picture.line, picture.expression.as_str()),
        (6, "gl_FragCoord.xy")
    );
    let (w, h) = (s.width as usize, s.height as usize);
    assert_eq!(picture.values.len(), w * h);
    let mut seen = 0;
    for (i, v) in picture.values.iter().enumerate() {
        if let Some(v) = v {
            let (x, row) = (i % w, i / w);
            let expected = [x as f32 + 0.5, (h - 1 - row) as f32 + 0.5];
            assert_eq!([v[0], v[1]], expected, "image row {row}, column {x}");
            seen += 1;
        }
    }
    // The sphere covers the middle of the frame, not its corners.
    assert!(picture.values[(h / 2) * w + w / 2].is_some());
    assert!(picture.values[0].is_none() && picture.values[w * h - 1].is_none());
    assert!(seen > w * h / 10, "{seen} pixels");
}

/// At one sample, the colour watched after the line that writes it is the colour the frame
/// stored at the same pixel, and the watched frame is the student's frame bit for bit.
#[test]
fn the_watched_colour_is_the_frames_colour_at_the_same_pixel() {
    let mut s = settings();
    s.samples = Samples::X1;
    let scene = with_shaders(sphere_scene(false), None, Some(FS));
    let plain = render(&scene, &s);
    let f = render(
        &scene
            .watching(&WatchSpec::fragment(6, "color"))
            .expect("compiles"),
        &s,
    );
    assert_eq!(
        plain.pixels.color, f.pixels.color,
        "the watch changes nothing drawn"
    );
    let picture = f
        .shaders
        .as_ref()
        .and_then(|r| r.watch.clone())
        .expect("a watch");
    assert_eq!(picture.kind, Some(WatchKind::Vec4));
    let mut compared = 0;
    for (v, c) in picture.values.iter().zip(&f.pixels.color) {
        if let Some(v) = v {
            assert!((0..3).all(|k| (v[k] - c[k]).abs() < 1e-6), "{v:?} vs {c:?}");
            compared += 1;
        }
    }
    assert!(compared > 1000);
}

/// A condition is a mask of 0 and 1; a watch the scene cannot make says why.
#[test]
fn a_condition_is_a_mask_and_a_bad_watch_says_why() {
    let s = settings();
    let scene = with_shaders(sphere_scene(false), None, Some(FS));
    let f = render(
        &scene
            .watching(&WatchSpec::fragment(5, "n.y > 0.0"))
            .expect("compiles"),
        &s,
    );
    let picture = f
        .shaders
        .as_ref()
        .and_then(|r| r.watch.clone())
        .expect("a watch");
    assert_eq!(picture.kind, Some(WatchKind::Bool));
    let values: Vec<f32> = picture.values.iter().flatten().map(|v| v[0]).collect();
    assert!(values.iter().all(|&b| b == 0.0 || b == 1.0));
    // The sphere's upper half faces up: both values occur; the top row of the sphere holds.
    assert!(values.contains(&0.0) && values.contains(&1.0));
    assert!(matches!(
        scene.watching(&WatchSpec::fragment(3, "n")),
        Err(WatchError::NotAfterStatement(3))
    ));
    assert!(matches!(
        scene.watching(&WatchSpec::fragment(5, "m")),
        Err(WatchError::Compile(_))
    ));
    assert!(matches!(
        sphere_scene(false).watching(&WatchSpec::fragment(5, "n")),
        Err(WatchError::NoShader)
    ));
}

/// The cost view: each pixel's steps of the fragment shader. A pixel loops `x mod 4` times
/// (x its window column), so along a row inside the sphere the cost climbs by the same amount
/// per iteration; at the inspected pixel it is the length of that fragment's own trace.
#[test]
fn the_cost_view_counts_each_pixels_steps_as_its_trace_does() {
    const LOOPING: &str = "#version 330 core
in vec3 w_nrm;
out vec4 color;
void main() {
    float s = 0.0;
    for (int i = 0; i < int(gl_FragCoord.x) % 4; i++) {
        s += 0.25;
    }
    color = vec4(normalize(w_nrm) * 0.5 + 0.5, 1.0) * (0.5 + 0.5 * s);
}
";
    let mut s = settings();
    s.samples = Samples::X1;
    s.capture.cost = true;
    s.capture.pixel = Some((80, 60));
    let scene = with_shaders(sphere_scene(false), None, Some(LOOPING));
    let f = render(&scene, &s);
    let record = f.shaders.as_ref().expect("a record");
    let cost = record.cost.as_ref().expect("the cost view");
    let at = |x: u32, y: u32| cost.at(x, y).map(|v| v[0] as u32);
    let traced = &record.pixel[0];
    assert_eq!(at(80, 60), Some(traced.trace.len() as u32));
    // Columns 80 to 83 of row 60: 0, 1, 2 and 3 iterations.
    let row: Vec<u32> = (80..84)
        .map(|x| at(x, 60).expect("on the sphere"))
        .collect();
    let per_iteration = row[1] - row[0];
    assert!(per_iteration > 0);
    assert_eq!(
        row,
        [
            row[0],
            row[0] + per_iteration,
            row[0] + 2 * per_iteration,
            row[0] + 3 * per_iteration
        ]
    );
    // Outside the sphere nothing ran.
    assert_eq!(at(0, 0), None);
    // Not asked for, not kept.
    s.capture.cost = false;
    assert!(render(&scene, &s).shaders.expect("a record").cost.is_none());
}

/// A vertex shader that passes the object normal on, and past line 10 only for the vertices of
/// the upper half (y > 0).
const VS: &str = "#version 330 core
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
in vec3 position;
in vec3 normal;
out vec3 w_nrm;
void main() {
    w_nrm = normal;
    if (position.y > 0.0) {
        w_nrm = w_nrm * 1.0;
    }
    gl_Position = projection * (view * (model * vec4(position, 1.0)));
}
";

/// A fragment shader whose line 5 keeps the interpolated input as it arrives.
const FS_INPUT: &str = "#version 330 core
in vec3 w_nrm;
out vec4 color;
void main() {
    vec3 m = w_nrm;
    color = vec4(normalize(m) * 0.5 + 0.5, 1.0);
}
";

/// The picture a scene's frame keeps of `watch`.
fn picture_of(
    scene: &pipeline::scene::Scene,
    watch: &WatchSpec,
) -> pipeline::capture::WatchPicture {
    let f = render(&scene.watching(watch).expect("compiles"), &settings());
    f.shaders
        .and_then(|r| r.watch)
        .expect("the frame kept the watch")
}

/// A vertex shader's value is carried to each pixel as a varying is: the vertex watch of the
/// output after the line that writes it is, at every pixel, what the fragment shader received
/// in that input (its own watch of it); and watching changes nothing drawn.
#[test]
fn a_vertex_watch_is_the_varying_the_fragment_receives() {
    let scene = with_shaders(sphere_scene(false), Some(VS), Some(FS_INPUT));
    let from_vertex = picture_of(&scene, &WatchSpec::vertex(9, "w_nrm"));
    let received = picture_of(&scene, &WatchSpec::fragment(5, "w_nrm"));
    assert!(from_vertex.from_vertex && !received.from_vertex);
    assert_eq!(from_vertex.kind, Some(WatchKind::Vec3));
    assert_eq!(from_vertex.line, 9);
    let mut compared = 0;
    for (a, b) in from_vertex.values.iter().zip(&received.values) {
        assert_eq!(a.is_some(), b.is_some(), "the same pixels");
        if let (Some(a), Some(b)) = (a, b) {
            assert!((0..3).all(|c| (a[c] - b[c]).abs() < 1e-6), "{a:?} vs {b:?}");
            compared += 1;
        }
    }
    assert!(compared > 1000, "{compared} pixels");
    let s = settings();
    let plain = render(&scene, &s);
    let watched = render(
        &scene
            .watching(&WatchSpec::vertex(9, "w_nrm"))
            .expect("compiles"),
        &s,
    );
    assert_eq!(plain.pixels.color, watched.pixels.color);
}

/// A bool passes flat (GLSL allows no other), from the triangle's last vertex: a mask of 0 and
/// 1 that holds at the sphere's top and not at its bottom; a line that only the upper half's
/// vertices run leaves the lower half's triangles without a value.
#[test]
fn a_vertex_condition_is_flat_and_an_unrun_line_leaves_no_value() {
    let scene = with_shaders(sphere_scene(false), Some(VS), Some(FS_INPUT));
    let s = settings();
    let cx = s.width / 2;
    // The sphere's top and bottom pixels on the centre column: the last and first rows of
    // that column that the sphere covers (window y up).
    let covered: Vec<u32> = {
        let p = picture_of(&scene, &WatchSpec::vertex(9, "w_nrm"));
        (0..s.height).filter(|&y| p.at(cx, y).is_some()).collect()
    };
    let (bottom, top) = (covered[0] + 2, covered[covered.len() - 1] - 2);
    let mask = picture_of(&scene, &WatchSpec::vertex(9, "position.y > 0.0"));
    assert_eq!(mask.kind, Some(WatchKind::Bool));
    assert!(
        mask.values
            .iter()
            .flatten()
            .all(|v| v[0] == 0.0 || v[0] == 1.0)
    );
    assert_eq!(mask.at(cx, top).map(|v| v[0]), Some(1.0));
    assert_eq!(mask.at(cx, bottom).map(|v| v[0]), Some(0.0));
    // Line 11 runs only where y > 0: the upper half has the value, the lower half none.
    let upper = picture_of(&scene, &WatchSpec::vertex(11, "w_nrm.y"));
    assert_eq!(upper.kind, Some(WatchKind::Float));
    assert!(upper.at(cx, top).is_some_and(|v| v[0] > 0.5));
    assert_eq!(upper.at(cx, bottom), None);
    // Where a triangle has the value all three corners ran line 11, so its last vertex lies
    // above y = 0 and the mask holds there; where the mask fails, the last vertex did not run
    // it and there is no value.
    for (u, m) in upper.values.iter().zip(&mask.values) {
        if u.is_some() {
            assert_eq!(m.map(|m| m[0]), Some(1.0));
        }
        if m.is_some_and(|m| m[0] == 0.0) {
            assert!(u.is_none());
        }
    }
    // A line that ends no statement, and a name not in the vertex shader, say why.
    assert!(matches!(
        scene.watching(&WatchSpec::vertex(7, "w_nrm")),
        Err(WatchError::NotAfterStatement(7))
    ));
    assert!(matches!(
        scene.watching(&WatchSpec::vertex(9, "gl_FragCoord")),
        Err(WatchError::Compile(_))
    ));
}
