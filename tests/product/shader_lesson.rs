//! The shader lesson (24): each step's edit runs and shows what it teaches, and the debugger's
//! step traces its pixel.

use pipelens::lesson::{Document, load_file};

use crate::support::repo;

#[test]
fn the_shader_lesson_runs_each_edit_and_traces_its_pixel() {
    let doc = load_file(&repo().join("lessons/24-shader-programs.toml"))
        .unwrap_or_else(|e| panic!("{e}"));
    let Document::Lesson(lesson) = doc else {
        panic!("not a lesson")
    };
    let frame = |k: usize, pixel: Option<(u32, u32)>| {
        let mut spec = lesson.spec_at(k);
        spec.settings.samples = pipeline::raster::Samples::X1;
        spec.settings.capture.pixel = pixel;
        assert!(
            spec.scene.objects.iter().all(|o| o.shader.is_some()),
            "step {k} runs a shader on every object"
        );
        pipeline::render(&spec.scene, &spec.settings).unwrap_or_else(|e| panic!("step {k}: {e}"))
    };
    let source = |k: usize| {
        let spec = lesson.spec_at(k);
        spec.scene.objects[0]
            .shader
            .as_ref()
            .expect("a shader")
            .programs
            .fragment
            .source
            .clone()
    };
    // Each step is an edit of the one before: the exponent, r·v, a rim, toon, discard.
    assert!(source(1).contains("float p = 8.0;"));
    assert!(source(2).contains("reflect(-l, n)"));
    assert!(source(3).contains("rim"));
    assert!(source(4).contains("floor(d * 4.0)"));
    assert!(source(5).contains("discard"));
    let key = |c: &[f32; 3]| c.map(|v| (v * 255.0).round() as i32);
    let colours = |k: usize| {
        let c = frame(k, None);
        c.pixels
            .color
            .iter()
            .map(key)
            .collect::<std::collections::BTreeSet<_>>()
    };
    let smooth = colours(0);
    let toon = colours(4);
    assert!(
        smooth.len() > 200,
        "Blinn-Phong shades smoothly: {} colours",
        smooth.len()
    );
    // Four bands (and black where n·l ≤ 0), the highlight, the background.
    assert!(toon.len() <= 8, "toon has a few flat bands: {toon:?}");
    let wider = frame(1, None);
    let narrow = frame(0, None);
    let bright =
        |c: &pipeline::capture::FrameCapture| c.pixels.color.iter().filter(|p| p[1] > 0.6).count();
    assert!(
        bright(&wider) > 2 * bright(&narrow),
        "p = 8 spreads the highlight: {} against {} bright pixels",
        bright(&wider),
        bright(&narrow)
    );
    let holes = frame(5, None);
    let record = holes.shaders.as_ref().expect("a shader record");
    assert!(
        record.discarded > 1000,
        "the checkerboard discards: {}",
        record.discarded
    );
    // The debugger's step: the inspected pixel's fragment with its inputs and its run.
    let step = &lesson.steps[6];
    let traced = frame(6, step.pixel);
    let fragments = &traced.shaders.as_ref().expect("a record").pixel;
    let f = fragments
        .first()
        .expect("the step's pixel is on the sphere");
    assert!(
        f.inputs.iter().any(|(name, _)| name == "w_nrm"),
        "{:?}",
        f.inputs
    );
    for v in ["n = vec3(", "h = vec3(", "specular = ", "color = vec4("] {
        assert!(
            f.trace.iter().any(|t| t.text.starts_with(v)),
            "the run shows `{v}`: {:?}",
            f.trace
        );
    }
}

#[test]
fn the_selected_vertex_is_traced_through_its_vertex_shader() {
    let doc = load_file(&repo().join("lessons/24-shader-programs.toml"))
        .unwrap_or_else(|e| panic!("{e}"));
    let Document::Lesson(lesson) = doc else {
        panic!("not a lesson")
    };
    let spec = lesson.spec_at(0);
    let capture = pipeline::render(&spec.scene, &spec.settings).expect("renders");
    let row = 200;
    let t = pipeline::trace_vertex(&spec.scene, &capture, row)
        .expect("runs")
        .expect("the sphere runs pipelens' vertex shader as GLSL");
    let names: Vec<&str> = t.inputs.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["position", "normal", "uv", "color"]);
    assert!(
        t.trace
            .iter()
            .any(|l| l.text.starts_with("gl_Position = vec4(")),
        "{:?}",
        t.trace
    );
    // Its gl_Position is the clip position of the vertex table's row.
    let clip = capture.vertices[row].clip;
    let written = &t
        .outputs
        .iter()
        .find(|(n, _)| n == "gl_Position")
        .expect("gl_Position")
        .1;
    assert_eq!(
        written,
        &format!(
            "vec4({:.3}, {:.3}, {:.3}, {:.3})",
            clip.x, clip.y, clip.z, clip.w
        )
    );
    // A row past the table is no vertex.
    assert!(
        pipeline::trace_vertex(&spec.scene, &capture, capture.vertices.len())
            .expect("runs")
            .is_none()
    );
}
