//! `pipelens export`, run as a user runs it: every buffer and the numbers, the mip levels, the
//! three shading frequencies' profile, a pixel's record and derivation, the depth files exactly, a cancelled export leaving only whole
//! files, a lesson's warnings.

use crate::support::{pipelens, repo, text};

const EXPECTED_FILES: [&str; 16] = [
    "color.png",
    "depth.png",
    "depth16.png",
    "depth.pfm",
    "coverage.png",
    "primitive_id.png",
    "bary_perspective.png",
    "bary_affine.png",
    "normal.png",
    "n_dot_l.png",
    "n_dot_h.png",
    "ambient.png",
    "diffuse.png",
    "specular.png",
    "overlays.png",
    "capture.json",
];

#[test]
fn export_writes_every_buffer_and_the_numbers() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("snap");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            "--out",
            out.to_str().expect("utf-8 path"),
            "--size",
            "160x100",
            "--samples",
            "4",
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    assert!(
        !text(&o).contains('\r'),
        "no progress bar in a log (stderr is not a terminal here)"
    );
    for f in EXPECTED_FILES {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    // No temporary files are left behind.
    let names: Vec<String> = std::fs::read_dir(&out)
        .expect("listing")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names.len(), EXPECTED_FILES.len(), "{names:?}");
    let color = image::open(out.join("color.png")).expect("color.png decodes");
    assert_eq!((color.width(), color.height()), (160, 100));
    let d16 = image::open(out.join("depth16.png")).expect("depth16.png decodes");
    assert!(
        matches!(d16, image::DynamicImage::ImageLuma16(_)),
        "16-bit grey"
    );
    let overlays = image::open(out.join("overlays.png")).expect("overlays.png decodes");
    assert_eq!(overlays.width(), 160 * 8, "magnified to at least 1280 wide");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("capture.json")).expect("read"))
            .expect("valid JSON");
    assert_eq!(json["settings"]["width"], 160);
    assert_eq!(json["settings"]["samples"], "X4");
    assert_eq!(
        json["matrices"]["projection"]["name"],
        "P = Perspective(fovy, aspect, near, far)"
    );
    assert_eq!(
        json["matrices"]["projection"]["factors"]
            .as_array()
            .map(Vec::len),
        Some(3)
    );
    let fates: Vec<&str> = json["primitives"]
        .as_array()
        .expect("primitives")
        .iter()
        .filter_map(|p| p["fate"].as_str())
        .collect();
    assert!(
        fates.contains(&"drawn") && fates.contains(&"clipped") && fates.contains(&"culled"),
        "{fates:?}"
    );
    assert!(
        json["vertices"][0]["clip"]
            .as_array()
            .is_some_and(|a| a.len() == 4)
    );
}

#[test]
fn a_textured_scene_exports_every_mip_level() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("t");
    let scene = repo().join("assets/scenes/texture.toml");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            scene.to_str().expect("utf-8"),
            "--out",
            out.to_str().expect("utf-8"),
            "--size",
            "96x64",
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    for f in ["uv.png", "mip_level.png", "texel.png"] {
        assert!(out.join(f).is_file(), "{f}");
    }
    // The floor's 512×512 checkerboard: levels 0 (512) to 9 (1×1).
    let top = image::open(out.join("texture0_level0.png")).expect("level 0");
    assert_eq!(top.width(), 512);
    let last = image::open(out.join("texture0_level9.png")).expect("level 9");
    assert_eq!((last.width(), last.height()), (1, 1));
}

#[test]
fn a_pixel_record_tells_why_the_pixel_has_its_colour() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("px");
    let scene = repo().join("assets/scenes/texture.toml");
    let args = |pixel: &'static str| {
        vec![
            "export".to_owned(),
            scene.to_string_lossy().into_owned(),
            "--out".to_owned(),
            out.to_string_lossy().into_owned(),
            "--size".to_owned(),
            "160x100".to_owned(),
            "--pixel".to_owned(),
            pixel.to_owned(),
        ]
    };
    let run = |pixel| {
        let a = args(pixel);
        pipelens(
            dir.path(),
            &a.iter().map(String::as_str).collect::<Vec<_>>(),
        )
    };
    // Outside the viewport: one clear message, nothing written.
    let o = run("160,10");
    assert!(!o.status.success());
    assert!(
        text(&o).contains("outside the 160×100 viewport"),
        "{}",
        text(&o)
    );
    assert!(!out.exists(), "nothing is written");
    // On the floor (bottom centre): lit and textured, and the terms sum to the colour.
    let o = run("80,5");
    assert!(o.status.success(), "{}", text(&o));
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("capture.json")).expect("read"))
            .expect("valid JSON");
    let p = &json["pixel"];
    assert_eq!((p["x"].as_u64(), p["y"].as_u64()), (Some(80), Some(5)));
    assert!(p["primitive"].is_u64(), "{p}");
    let fragments = p["fragments"].as_array().expect("fragments");
    assert!(fragments.iter().any(|f| f["visible"] == true));
    let t = &p["texture"];
    assert!(
        t["footprint"].as_array().is_some_and(|a| a.len() == 4),
        "{t}"
    );
    assert!(t["lod"].is_f64());
    let l = &p["lighting"];
    let f = |v: &serde_json::Value, k: usize| v[k].as_f64().expect("number");
    for k in 0..3 {
        let sum = f(&l["ambient"], k)
            + f(&l["diffuse"], k)
            + f(&l["specular"], k)
            + f(&l["reflected"], k);
        let shown = f(&p["color"], k);
        assert!(
            (sum.min(1.0) - shown).abs() < 0.02,
            "channel {k}: {sum} vs {shown}"
        );
    }
}

#[test]
fn a_cancelled_export_stops_between_files_and_leaves_only_whole_ones() {
    use pipelens::export::{Cancel, ExportFile, write_files};
    let dir = tempfile::tempdir().expect("temp dir");
    let files: Vec<ExportFile> = (0..5)
        .map(|k| ExportFile {
            name: format!("f{k}.txt"),
            description: String::new(),
            bytes: vec![b'x'; 1000],
        })
        .collect();
    let cancel = Cancel::default();
    let flag = cancel.clone();
    // Cancelled while the second file is being reported: the third is never started.
    let e = write_files(
        dir.path(),
        &files,
        &mut |done, _, _| {
            if done == 2 {
                flag.cancel();
            }
        },
        (&cancel, pipelens::vocabulary::Lang::EN),
    )
    .expect_err("cancelled");
    assert!(
        e.to_string()
            .contains("export cancelled: every file written before is whole"),
        "{e}"
    );
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .expect("listing")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        ["f0.txt", "f1.txt"],
        "whole files only, no temporaries"
    );
    assert!(
        names
            .iter()
            .all(|n| std::fs::metadata(dir.path().join(n)).map(|m| m.len()).ok() == Some(1000))
    );
}

/// `export --pixel` writes the pixel's edge functions and the derivation of its colour, as the
/// app's pixel inspector shows them: checked on a triangle worked out by hand.
#[test]
fn export_pixel_writes_the_edge_functions_and_the_derivation() {
    let dir = tempfile::tempdir().expect("temp dir");
    // The triangle (0, 0), (4, 0), (0, 4) in an 8×8 window (an orthographic camera over
    // [0, 8]², so world x, y are window x, y), its corners red, green, blue.
    std::fs::write(
        dir.path().join("tri.obj"),
        "v 0 0 0 1 0 0\nv 4 0 0 0 1 0\nv 0 4 0 0 0 1\nf 1 2 3\n",
    )
    .expect("write the mesh");
    std::fs::write(
        dir.path().join("scene.toml"),
        r#"[scene.camera]
eye = [0, 0, 1]
at = [0, 0, 0]

[scene.projection]
kind = "ortho"
left = 0
right = 8
bottom = 0
top = 8
near = 0
far = 2

[scene.render]
width = 8
height = 8

[[scene.objects]]
name = "rgb"
mesh = "tri.obj"
"#,
    )
    .expect("write the scene");
    let o = pipelens(
        dir.path(),
        &["export", "scene.toml", "--out", "out", "--pixel", "1,1"],
    );
    assert!(o.status.success(), "{}", text(&o));
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("out/capture.json")).expect("read"))
            .expect("valid JSON");
    let e = &json["pixel"]["explanation"];
    let numbers = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .expect("an array")
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    // At the centre p = (1.5, 1.5): E_0 = (−4)(1.5 − 0) − (4)(1.5 − 4) = 4 (the edge opposite
    // the first corner), E_1 = 0·(1.5 − 4) − (−4)(1.5 − 0) = 6, E_2 = 4·1.5 = 6; their sum is
    // twice the area, 16; λ = (4, 6, 6)/16.
    assert_eq!(numbers(&e["edges"]["centre"]), [4.0, 6.0, 6.0]);
    assert_eq!(e["edges"]["area2"].as_f64(), Some(16.0));
    assert_eq!(numbers(&e["edges"]["lambda"]), [0.25, 0.375, 0.375]);
    assert_eq!(numbers(&e["edges"]["centre_position"]), [1.5, 1.5]);
    // The colour is λ·(red, green, blue), and the derivation arrives at it in 8 bits.
    let color = numbers(&e["color"]);
    for (c, want) in color.iter().zip([0.25, 0.375, 0.375]) {
        assert!((c - want).abs() < 1e-6, "{color:?}");
    }
    let lines = e["lines"].as_array().expect("lines");
    let line = |start: &str| {
        lines
            .iter()
            .find(|l| l["formula"].as_str().is_some_and(|f| f.starts_with(start)))
            .unwrap_or_else(|| panic!("a line {start}: {lines:?}"))
    };
    assert_eq!(line("E_0")["result"], "4");
    assert_eq!(
        line("E_0")["numbers"],
        "(0 − 4)·(1.5 − 0) − (4 − 0)·(1.5 − 4)"
    );
    assert_eq!(line("λ_k")["result"], "(0.25, 0.375, 0.375)");
    assert_eq!(line("RGB_8")["result"], "(64, 96, 96)");
    // Each fragment carries its own inside test.
    assert_eq!(
        numbers(&json["pixel"]["fragments"][0]["edges"]["centre"]),
        [4.0, 6.0, 6.0]
    );
}

/// The built-in scene rendered at `width`×`height` and exported (`export_capture`) into a
/// temporary folder.
fn exported_default_scene(
    width: u32,
    height: u32,
) -> (pipeline::capture::FrameCapture, tempfile::TempDir) {
    let spec = pipelens::lesson::default_scene().expect("the built-in scene");
    let mut settings = spec.settings;
    (settings.width, settings.height) = (width, height);
    let capture = pipeline::render(&spec.scene, &settings).expect("renders");
    let dir = tempfile::tempdir().expect("temp dir");
    let opts = pipelens::export::ExportOptions {
        out: dir.path().to_path_buf(),
        overlay_zoom: 1,
        max_records: 10,
        pixel: None,
        cancel: pipelens::export::Cancel::default(),
        lang: pipelens::vocabulary::Lang::EN,
    };
    pipelens::export::export_capture(&capture, &opts, &mut |_, _, _| {}).expect("exports");
    (capture, dir)
}

/// `depth16.png` holds round(65535·z_w) of every pixel, as the capture has it: read back, every
/// pixel equals the capture's window depth (a byte-swapped file would hold 64 for z_w = 0.25).
#[test]
fn depth16_round_trips_every_pixel_of_the_capture() {
    let (capture, dir) = exported_default_scene(96, 60);
    let read = image::open(dir.path().join("depth16.png"))
        .expect("decodes")
        .into_luma16();
    let expected = capture.depth16();
    assert_eq!(read.dimensions(), expected.dimensions());
    let mut varied = std::collections::BTreeSet::new();
    for (x, y, p) in read.enumerate_pixels() {
        let want = expected.get_pixel(x, y)[0];
        assert_eq!(p[0], want, "pixel ({x}, {y})");
        varied.insert(want);
    }
    assert!(varied.len() > 50, "a scene with many depths");
    assert!(
        varied.iter().any(|v| (v >> 8) != (v & 0xff)),
        "values whose two bytes differ, which a swap would change"
    );
}

/// `depth.pfm` holds every pixel's float window depth bit for bit: its header names the size and
/// little-endian order, and its rows run from the bottom (window order), so window pixel (x, y)
/// is image row height − 1 − y of the capture.
#[test]
fn depth_pfm_holds_the_captures_float_depth_exactly() {
    let (capture, dir) = exported_default_scene(90, 50);
    let bytes = std::fs::read(dir.path().join("depth.pfm")).expect("depth.pfm written");
    let header = b"Pf\n90 50\n-1.0\n";
    assert_eq!(&bytes[..header.len()], header);
    let floats: Vec<f32> = bytes[header.len()..]
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert_eq!(floats.len(), 90 * 50);
    let mut distinct = std::collections::BTreeSet::new();
    for y in 0..50usize {
        for x in 0..90usize {
            let want = capture.pixels.depth[(49 - y) * 90 + x];
            let got = floats[y * 90 + x];
            assert_eq!(got.to_bits(), want.to_bits(), "window pixel ({x}, {y})");
            distinct.insert(got.to_bits());
        }
    }
    assert!(distinct.len() > 50, "a scene with many depths");
}

/// A lesson's export says on stderr which step's frame dropped triangles for a `gl_Position`
/// that is not finite, and how many — the step, not only the frame — and writes the rest.
#[test]
fn a_lesson_export_warns_of_each_steps_not_finite_positions() {
    let dir = tempfile::tempdir().expect("temp dir");
    let vertex = "#version 330 core\nuniform mat4 mvp;\nin vec3 position;\nvoid main() {\n    gl_Position = mvp * vec4(position, 1.0);\n    if (position.x > 0.5) {\n        gl_Position.w = 1.0 / (position.x - position.x);\n    }\n}\n";
    let red = "#version 330 core\nout vec4 color;\nvoid main() {\n    color = vec4(1.0, 0.0, 0.0, 1.0);\n}\n";
    let lesson = format!(
        "[lesson]\nid = \"nan\"\ntitle = {{ en = \"NaN\", zh = \"NaN\" }}\nsummary = {{ en = \"A position that is not a number.\", zh = \"不是数的位置。\" }}\n\n\
         [[scene.objects]]\nname = \"sphere\"\nmesh = {{ builtin = \"uv_sphere\", segments = 16, rings = 8 }}\n\n\
         [[steps]]\ntitle = {{ en = \"Plain\", zh = \"普通\" }}\nnarration = {{ en = \"The sphere.\", zh = \"球。\" }}\n\n\
         [[steps]]\ntitle = {{ en = \"Dropped\", zh = \"丢弃\" }}\nnarration = {{ en = \"Its right side is gone.\", zh = \"右侧没有了。\" }}\n\
         shader.vertex = '''\n{vertex}'''\nshader.fragment = '''\n{red}'''\n"
    );
    std::fs::write(dir.path().join("nan.toml"), lesson).expect("write");
    let out = dir.path().join("out");
    let o = pipelens(
        dir.path(),
        &["export", "nan.toml", "--out", out.to_str().expect("utf-8")],
    );
    let said = text(&o);
    assert!(o.status.success(), "{said}");
    assert!(out.join("index.html").exists(), "{said}");
    let warnings: Vec<&str> = said.lines().filter(|l| l.contains("warning:")).collect();
    assert_eq!(warnings.len(), 1, "{said}");
    assert!(
        warnings[0].contains("step 2: ") && warnings[0].contains("triangle(s) dropped"),
        "{said}"
    );
}

#[test]
fn a_profile_compares_the_three_shading_frequencies() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("p");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            "--out",
            out.to_str().expect("utf-8"),
            "--size",
            "160x100",
            "--profile",
            "0,60,159,60",
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    let csv = std::fs::read_to_string(out.join("profile.csv")).expect("profile.csv");
    let mut lines = csv.lines();
    let header = lines.next().expect("header");
    assert!(
        header.starts_with("t,x,y,flat_r")
            && header.contains("gouraud_intensity")
            && header.ends_with("phong_intensity")
    );
    assert_eq!(lines.count(), 160, "one row per pixel step");
    let o = pipelens(dir.path(), &["export", "--out", "q", "--profile", "1,2,3"]);
    assert!(!o.status.success());
    assert!(text(&o).contains("expected four numbers"), "{}", text(&o));
}

/// A lesson whose step's code stops while it runs (lesson 24 with an endless loop put at the
/// start of step 1's fragment shader's `main`) is not exported: the error names the step, the
/// object, the file, the line and why, in the language asked for (`--lang zh`: the zh-Hans
/// catalog's `lesson-step-not-drawn`, `run-cannot-draw`, `run-code-in-file` and
/// `compile-endless-loop`; in English the core's own sentence), and nothing is written.
#[test]
fn a_step_whose_code_stops_is_not_exported_and_says_why_in_its_language() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson =
        std::fs::read_to_string(repo().join("lessons/24-shader-programs.toml")).expect("lesson 24");
    let endless = "void main() {\n    float f = 0.0;\n    while (f >= 0.0) { f += 1.0; }\n";
    let broken = lesson.replacen("void main() {\n", endless, 1);
    let line = broken[..broken.find("    while (f").expect("the loop")]
        .lines()
        .count()
        + 1;
    std::fs::write(dir.path().join("broken.toml"), broken).expect("written");
    let out = dir.path().join("out");
    for (lang, said) in [
        (
            "zh",
            format!(
                "第 1 步：无法绘制场景：物体 sphere 的片元着色器，broken.toml，第 {line} 行第 5 列：循环执行超过了 65536 步"
            ),
        ),
        (
            "en",
            format!(
                "step 1: the scene cannot be drawn: fragment shader of sphere, broken.toml, line {line}, column 5: the loop ran more than 65536 steps"
            ),
        ),
    ] {
        let o = pipelens(
            dir.path(),
            &[
                "export",
                "broken.toml",
                "--step",
                "1",
                "--lang",
                lang,
                "--out",
                "out",
            ],
        );
        assert!(!o.status.success());
        assert!(text(&o).contains(&said), "{lang}: {}", text(&o));
        assert!(!out.exists(), "nothing is written");
    }
}
