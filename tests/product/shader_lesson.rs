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
            spec.scene.objects.iter().all(|o| o.code.shader.is_some()),
            "step {k} runs a shader on every object"
        );
        pipeline::render(&spec.scene, &spec.settings).unwrap_or_else(|e| panic!("step {k}: {e}"))
    };
    let source = |k: usize| {
        let spec = lesson.spec_at(k);
        spec.scene.objects[0]
            .code
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
    assert!(source(4).contains("floor(d * bands) / bands"));
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

/// Why a lesson's scene at one step is left out of the built-in-as-GLSL comparison: what the
/// shipped shaders do not model (each named, so a reader sees what is compared).
fn not_modelled(spec: &pipelens::lesson::SceneSpec) -> Option<&'static str> {
    let s = &spec.settings;
    let objects = &spec.scene.objects;
    if objects.iter().any(|o| o.code.shader.is_some()) {
        Some("the lesson runs its own shaders")
    } else if !s.perspective_correct {
        Some("affine interpolation (a shader writes `noperspective` for that)")
    } else if s.per_sample_shading {
        Some("per-sample shading (a fragment shader runs once per pixel)")
    } else if objects
        .iter()
        .all(|o| pipeline::shader::builtin_sources(s.shading, s.reflection, o.surface()).is_none())
    {
        Some(
            "r·v with Gouraud, flat or a bump map, or a bump-mapped mirror: no shipped shader pair",
        )
    } else {
        None
    }
}

#[test]
fn pipelens_own_shading_as_glsl_gives_the_built_in_pixels_on_the_lessons_scenes() {
    let mut compared = Vec::new();
    let mut left_out = Vec::new();
    for path in crate::support::lesson_files() {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            continue;
        };
        for k in 0..lesson.steps.len() {
            let mut spec = lesson.spec_at(k);
            let case = format!("{} step {}", lesson.id, k + 1);
            if let Some(why) = not_modelled(&spec) {
                left_out.push(format!("{case}: {why}"));
                continue;
            }
            spec.settings.width = spec.settings.width.min(160);
            spec.settings.height = spec.settings.height.min(100);
            // Mip-mapped lookups included: both paths take λ from the 2×2 quad's derivatives.
            // An object no shipped pair models is taken out of both pictures.
            let (shading, reflection) = (spec.settings.shading, spec.settings.reflection);
            spec.scene.objects.retain(|o| {
                let modelled =
                    pipeline::shader::builtin_sources(shading, reflection, o.surface()).is_some();
                if !modelled {
                    left_out.push(format!(
                        "{case}: object {} taken out (no shipped pair)",
                        o.name
                    ));
                }
                modelled
            });
            let glsl = spec
                .scene
                .with_builtin_shaders(&spec.settings)
                .unwrap_or_else(|e| panic!("{case}: {e:?}"))
                .expect("checked above");
            let built_in = pipeline::render(&spec.scene, &spec.settings).expect("renders");
            let shaded =
                pipeline::render(&glsl, &spec.settings).unwrap_or_else(|e| panic!("{case}: {e}"));
            assert_eq!(
                built_in.pixels.coverage, shaded.pixels.coverage,
                "{case}: coverage"
            );
            let (worst, at) = built_in
                .pixels
                .color
                .iter()
                .zip(&shaded.pixels.color)
                .enumerate()
                .map(|(i, (a, b))| ((0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f32::max), i))
                .fold((0.0, 0), |m, d| if d.0 > m.0 { d } else { m });
            assert!(
                worst <= 1.0 / 255.0,
                "{case} ({:?}, {:?}): pixel {at} differs by {worst}: {:?} built in, {:?} as GLSL",
                spec.settings.shading,
                spec.settings.reflection,
                built_in.pixels.color[at],
                shaded.pixels.color[at]
            );
            compared.push(case);
        }
    }
    eprintln!(
        "compared {} steps; left out {}:\n  {}",
        compared.len(),
        left_out.len(),
        left_out.join("\n  ")
    );
    assert!(
        compared.len() >= 130,
        "compared only {} steps: {compared:?}",
        compared.len()
    );
}

/// Lesson 24 teaches Blinn-Phong as the course writes it, L = k_a·c·I_a + k_d·c·I·max(n·l, 0) +
/// k_s·I·max(n·h, 0)^p with the specular term only where n·l > 0: its first and last steps
/// draw what pipelens' own Blinn-Phong shading draws (each channel within 2/255 on every
/// pixel). And step 3's sentence: at the same p = 64, Phong's highlight is smaller than
/// Blinn-Phong's, because (n·h)^p > (r·v)^p — fewer pixels have a specular factor above ½.
#[test]
fn lesson_24_s_blinn_phong_is_the_course_s_and_phong_s_highlight_is_smaller() {
    let Ok(Document::Lesson(lesson)) = load_file(&repo().join("lessons/24-shader-programs.toml"))
    else {
        panic!("lesson 24 loads")
    };
    for k in [0, 6, 7] {
        let spec = lesson.spec_at(k);
        let mine = pipeline::render(&spec.scene, &spec.settings).expect("renders");
        let mut own = spec.scene.clone();
        own.clear_code();
        let theirs = pipeline::render(&own, &spec.settings).expect("renders");
        let d = mine.difference(&theirs, 2.0).expect("same size");
        assert!(
            d.passed(),
            "step {}: {} of {} pixels within 2/255 of pipelens' own (largest {}/255)",
            k + 1,
            d.matching,
            d.total,
            d.largest
        );
    }
    // The specular factor over the sphere, from the lit scene's own buffers: pipelens' built-in
    // terms with Blinn-Phong's n·h and with Phong's r·v, both at p = 64.
    let highlight = |reflection: &str| {
        let mut spec = lesson.spec_at(0);
        spec.scene.clear_code();
        pipelens::lesson::param::apply(
            &mut spec,
            "render.reflection",
            &pipelens::lesson::param::Value::Name(reflection.to_owned()),
        )
        .expect("a reflection model");
        assert_eq!(spec.scene.objects[0].material.shininess, 64.0);
        let c = pipeline::render(&spec.scene, &spec.settings).expect("renders");
        let sh = c.pixels.shading.as_ref().expect("lit");
        // k_s·I = 0.6: a specular factor above ½ is a specular term above 0.3.
        sh.specular
            .iter()
            .filter(|s| s.iter().any(|v| v.to_f32() > 0.3))
            .count()
    };
    let (blinn, phong) = (highlight("blinn_phong"), highlight("phong"));
    eprintln!("specular factor above ½: Blinn-Phong {blinn} px, Phong {phong} px");
    assert!(
        phong > 0 && phong * 2 < blinn,
        "Phong's highlight ({phong} px) is not clearly smaller than Blinn-Phong's ({blinn} px)"
    );
}

/// A run-time error of a shader written in a scene file, or in a shader file beside it, names
/// that file and its line and column there — the place the teacher edits — not the shader's
/// own line 1, 2, 3 (the same source compiled alone gives the shader's own place).
#[test]
fn a_run_time_error_names_the_file_and_line_where_the_glsl_is_written() {
    use pipeline::RenderError;
    let glsl = "#version 330 core\nout vec4 color;\nvoid main() {\n    float a[2] = float[2](0.0, 1.0);\n    int i = int(gl_FragCoord.x) + 5;\n    color = vec4(a[i]);\n}\n";
    // Alone: the shader's own line and column.
    let alone = pipeline::shader::link(None, Some(glsl)).expect("links");
    let settings = pipeline::settings::RenderSettings {
        width: 32,
        height: 24,
        ..pipeline::settings::RenderSettings::default()
    };
    let error_of = |scene: &pipeline::scene::Scene| match pipeline::render(scene, &settings) {
        Err(e @ RenderError::Code { .. }) => {
            let words = e.to_string();
            let RenderError::Code { error, file, .. } = e else {
                unreachable!()
            };
            (*error, file, words)
        }
        other => panic!("expected a run-time error, got {:?}", other.map(|_| ())),
    };
    let dir = tempfile::tempdir().expect("temp dir");
    let object = "[[scene.objects]]\nmesh = \"cube\"\n";
    // Inline: the GLSL starts on line 4 of the scene file (TOML drops the newline after ''').
    let scene = format!("{object}shader = {{ fragment = '''\n{glsl}''' }}\n");
    let spec = pipelens::lesson::parse_scene(&scene, "t.toml", dir.path()).expect("valid");
    let mut own = spec.scene.clone();
    own.objects[0].code.shader = Some(pipeline::scene::ObjectShader {
        programs: std::sync::Arc::new(alone),
        time: 0.0,
    });
    let (own, file, _) = error_of(&own);
    assert!(own.message.contains("out of range"), "{own}");
    assert_eq!(file, None);
    let (placed, file, words) = error_of(&spec.scene);
    assert_eq!(file.as_deref(), Some("t.toml"));
    assert_eq!((placed.line, placed.column), (own.line + 3, own.column));
    assert_eq!(placed.message, own.message);
    assert!(
        words.contains(&format!(
            "t.toml, line {}, column {}: ",
            own.line + 3,
            own.column
        )),
        "{words}"
    );
    // From a file beside the scene: that file's own line and column, and its name.
    std::fs::write(dir.path().join("index.frag"), glsl).expect("write");
    let scene = format!("{object}shader = {{ fragment = \"index.frag\" }}\n");
    let spec = pipelens::lesson::parse_scene(&scene, "t.toml", dir.path()).expect("valid");
    let (placed, file, words) = error_of(&spec.scene);
    assert!(
        file.as_deref().is_some_and(|f| f.ends_with("index.frag")),
        "{words}"
    );
    assert_eq!((placed.line, placed.column), (own.line, own.column));
    // A source that starts after the key on its line keeps its first line's column shift.
    let origin = pipeline::shader::Origin {
        file: "l.toml".into(),
        line: 7,
        column: 24,
    };
    let on_first = origin.place(pipeline::shader::ShaderError {
        line: 1,
        column: 3,
        ..own.clone()
    });
    assert_eq!((on_first.line, on_first.column), (7, 26));
    let below = origin.place(pipeline::shader::ShaderError {
        line: 2,
        column: 3,
        ..own
    });
    assert_eq!((below.line, below.column), (8, 3));
}
