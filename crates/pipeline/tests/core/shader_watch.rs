//! A watch over the frame: an expression of the student's fragment shader after a line, at
//! every pixel — at the pixel the frame shows it at, read in window terms (y up) with no
//! mirror, and the frame it draws the frame the shader draws.

use pipeline::raster::Samples;
use pipeline::shader::probe::{WatchError, WatchKind};

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
    let watched = scene.watching(6, "gl_FragCoord.xy").expect("compiles");
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
    let f = render(&scene.watching(6, "color").expect("compiles"), &s);
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
    let f = render(&scene.watching(5, "n.y > 0.0").expect("compiles"), &s);
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
        scene.watching(3, "n"),
        Err(WatchError::NotAfterStatement(3))
    ));
    assert!(matches!(
        scene.watching(5, "m"),
        Err(WatchError::Compile(_))
    ));
    assert!(matches!(
        sphere_scene(false).watching(5, "n"),
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
