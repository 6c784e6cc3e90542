//! The handout a lesson exports: one self-contained HTML file whose pictures are what the app
//! shows (overlays, the inspected pixel with its vectors, the profile and its chart), printed
//! answers on request, Chinese captions in Chinese; slides and data on request.

use base64::Engine as _;
use image::RgbaImage;

use crate::support::{pipelens, text};

/// Every image embedded in `html`, in order.
pub fn images(html: &str) -> Vec<RgbaImage> {
    html.split("src=\"data:image/")
        .skip(1)
        .map(|rest| {
            let b64 = rest
                .split_once(";base64,")
                .and_then(|(_, r)| r.split('"').next())
                .expect("a base64 image");
            let bytes = base64::engine::general_purpose::STANDARD
                .decode(b64)
                .expect("base64");
            image::load_from_memory(&bytes)
                .expect("an image")
                .to_rgba8()
        })
        .collect()
}

/// No attribute of `html` names anything outside it: every `src` and `href` is a data URL or
/// a place in the page, and nothing is loaded by a `<link>`, a script or a CSS `url()`.
pub fn assert_self_contained(html: &str, what: &str) {
    for attr in ["src=\"", "href=\""] {
        for value in html.split(attr).skip(1) {
            assert!(
                value.starts_with("data:") || value.starts_with('#'),
                "{what}: {attr}{} points outside the file",
                &value[..value.len().min(40)]
            );
        }
    }
    for word in ["<link", "<script", "@import"] {
        assert!(!html.contains(word), "{what}: {word} in the handout");
    }
    // A Chinese handout's font is a `url(data:…)` in its style; nothing else is fetched.
    for value in html.split("url(").skip(1) {
        assert!(
            value.starts_with("data:"),
            "{what}: url({} points outside the file",
            &value[..value.len().min(40)]
        );
    }
}

/// A Chinese handout carries the app's Chinese font, so that a reader without one (a bare
/// Linux, headless Chromium printing to PDF) sees Chinese, not boxes; an English one does not.
/// The font is cut to the handout's characters: read back with another parser (ab_glyph's
/// ttf-parser), it has a glyph for every character of the page that the whole font has, and none
/// for one the lesson never writes, and lesson 11's Chinese handout stays under 1.5 MB (the
/// whole font alone would be 4 MB in base64).
#[test]
fn a_chinese_handout_embeds_its_font_cut_to_its_characters_and_an_english_one_does_not() {
    use ab_glyph::Font as _;
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/11-shading-frequencies.toml");
    for (lang, embedded) in [("zh", true), ("en", false)] {
        let out = dir.path().join(lang);
        let o = crate::support::pipelens(
            dir.path(),
            &[
                "export",
                lesson.to_str().expect("utf-8"),
                "--out",
                out.to_str().expect("utf-8"),
                "--lang",
                lang,
            ],
        );
        assert!(o.status.success(), "{}", crate::support::text(&o));
        let html = std::fs::read_to_string(out.join("index.html")).expect("index.html");
        let face = "font-family:'pipelens CJK';src:url(data:font/otf;base64,";
        assert_eq!(html.contains(face), embedded, "{lang}");
        if !embedded {
            continue;
        }
        assert!(
            html.len() <= 1_500_000,
            "lesson 11's Chinese handout is {} bytes",
            html.len()
        );
        let start = html.find(face).expect("the font") + face.len();
        let end = start + html[start..].find(')').expect("the url's end");
        let otf = base64::engine::general_purpose::STANDARD
            .decode(&html[start..end])
            .expect("base64");
        let font = ab_glyph::FontRef::try_from_slice(&otf).expect("an OpenType font");
        let page = format!("{}{}", &html[..start], &html[end..]);
        // Every character of the page the whole font draws, the cut draws.
        let whole =
            ab_glyph::FontRef::try_from_slice(pipelens::vocabulary::cjk_font()).expect("a font");
        let missing: String = page
            .chars()
            .filter(|&c| whole.glyph_id(c).0 != 0 && font.glyph_id(c).0 == 0)
            .collect();
        assert!(missing.is_empty(), "no glyph for {missing:?}");
        assert!(page.contains('着') && font.glyph_id('着').0 != 0);
        for c in ['鼠', '龙'] {
            assert!(!page.contains(c));
            assert_eq!(
                font.glyph_id(c).0,
                0,
                "{c} is not on the page, nor in its font"
            );
        }
    }
}

/// Whether `s` has a Chinese character.
fn has_chinese(s: &str) -> bool {
    s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
}

/// Every caption the export writes itself (class `ui`, the figures' captions) is Chinese.
pub fn assert_captions_chinese(html: &str, what: &str) {
    let mut seen = 0;
    // A caption ends where its element ends: `</figcaption>` for a figure's (whose matrix name
    // is in bold inside it), the first closing tag for the rest.
    for (marker, end) in [
        ("class=\"ui\">", "</"),
        ("<figcaption>", "</figcaption>"),
        ("<figcaption class=\"ui\">", "</figcaption>"),
    ] {
        for rest in html.split(marker).skip(1) {
            let inside = rest.split(end).next().unwrap_or_default();
            // A matrix's caption is its symbol and formula (`M_viewport`, `x_w = (x+1)·width/2`),
            // translated by the formula table, which
            // `every_matrix_formula_a_lesson_shows_reads_in_chinese` checks.
            if inside.starts_with("<b>") {
                continue;
            }
            let caption: String = inside
                .split('<')
                .map(|part| part.split_once('>').map_or(part, |(_, t)| t))
                .collect();
            seen += 1;
            assert!(
                has_chinese(&caption),
                "{what}: the caption \"{caption}\" is not in Chinese"
            );
        }
    }
    assert!(seen > 0, "{what}: no caption found");
}

const LESSON: &str = r#"
[lesson]
id = "picture"
title = { en = "A picture", zh = "一幅图" }
summary = { en = "What the handout draws.", zh = "讲义画什么。" }

[scene.camera]
eye = [0, 0, 3]

[scene.render]
width = 160
height = 120
shading = "phong"

[[scene.lights]]
kind = "point"
position = [2, 2, 3]

[[scene.objects]]
name = "ball"
mesh = { builtin = "uv_sphere", segments = 12, rings = 6 }
color = [0.8, 0.3, 0.2]

[[steps]]
title = { en = "Everything drawn", zh = "全部画出" }
narration = { en = "Edges, a pixel and a profile.", zh = "边、像素与剖面。" }
stage = "shading"
buffer = "color"
overlays = ["edges"]
pixel = [80, 70]
profile = [0, 60, 159, 60]
question = { en = "Why?", zh = "为什么？" }
answer = { en = "Because of the normal.", zh = "因为法线。" }

[[steps]]
title = { en = "Nothing drawn", zh = "什么都不画" }
narration = { en = "The same image alone.", zh = "只有同一幅图。" }
buffer = "color"
animate = [{ param = "projection.fovy", from = 40, to = 60, seconds = 2 }]
question = { en = "And now?", zh = "现在呢？" }
answer = { en = "The same, bigger.", zh = "一样，只是更大。" }
"#;

/// Pixels of `img` within `tol` of `rgb` in every channel.
fn count(img: &RgbaImage, rows: std::ops::Range<u32>, rgb: [u8; 3], tol: i32) -> usize {
    img.enumerate_pixels()
        .filter(|(_, y, p)| {
            rows.contains(y) && (0..3).all(|c| (i32::from(p.0[c]) - i32::from(rgb[c])).abs() <= tol)
        })
        .count()
}

fn export(dir: &std::path::Path, extra: &[&str]) -> String {
    std::fs::write(dir.join("picture.toml"), LESSON).expect("write");
    let mut args = vec!["export", "picture.toml", "--out", "out"];
    args.extend(extra);
    let o = pipelens(dir, &args);
    assert!(o.status.success(), "{}", text(&o));
    std::fs::read_to_string(dir.join("out/index.html")).expect("index.html")
}

#[test]
fn the_handout_picture_has_the_overlays_the_pixel_and_the_chart() {
    let dir = tempfile::tempdir().expect("temp dir");
    let html = export(dir.path(), &[]);
    assert_self_contained(&html, "picture");
    let imgs = images(&html);
    let (drawn, plain) = (&imgs[0], &imgs[1]);
    // 160×120 magnified 4×, and under it the chart.
    assert_eq!(drawn.width(), 640);
    assert_eq!((plain.width(), plain.height()), (640, 480));
    assert!(drawn.height() > 480 + 200, "a chart under the picture");
    let picture = 0..480;
    // The edges (white), the pixel's frame (yellow) and its half vector (cyan) over the image.
    let white = count(drawn, picture.clone(), [255, 255, 255], 30);
    assert!(
        white > count(plain, picture.clone(), [255, 255, 255], 30) + 400,
        "edges: {white} white pixels"
    );
    assert!(
        count(drawn, picture.clone(), [255, 215, 0], 40) > 20,
        "the pixel's frame"
    );
    assert!(count(plain, picture.clone(), [255, 215, 0], 40) < 5);
    assert!(
        count(drawn, picture.clone(), [90, 220, 255], 40) > 10,
        "h drawn"
    );
    // The chart: the curve in the first curve colour, in print on white (the slides keep the
    // app's dark plot: `a_geometry_picture_prints_in_ink_on_white_and_projects_dark`).
    let chart = 488..drawn.height();
    assert!(
        count(drawn, chart.clone(), [255, 170, 60], 40) > 100,
        "the curve"
    );
    assert!(
        count(drawn, chart, [255, 255, 255], 0) > 10_000,
        "the chart's background"
    );
    // The animated step: a GIF and a filmstrip of five frames captioned with fovy's values.
    assert!(html.contains("data:image/gif;base64,"));
    // ease_in_out: 3t² − 2t³ at t = 0, ¼, ½, ¾, 1 gives 0, 0.156, 0.5, 0.844, 1 of the way.
    for fovy in ["40", "43.12", "50", "56.88", "60"] {
        assert!(
            html.contains(&format!("projection fovy = {fovy}</figcaption>")),
            "frame at fovy = {fovy}"
        );
    }
    // A student's handout: the answers folded away on screen, not printed.
    assert!(html.contains("<details class=\"screen\">"));
    assert!(html.contains(".screen{display:none}"));
}

/// Print palette: a handout's drawn pictures (a geometry stage, a chart) are ink on white, not
/// the black rectangles the app's dark drawings print as; the slides, projected, keep them dark.
#[test]
fn a_geometry_picture_prints_in_ink_on_white_and_projects_dark() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = LESSON.replace(
        "stage = \"shading\"\nbuffer = \"color\"",
        "stage = \"world\"",
    );
    assert_ne!(lesson, LESSON);
    std::fs::write(dir.path().join("picture.toml"), lesson).expect("write");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            "picture.toml",
            "--out",
            "out",
            "--slides",
            "--step",
            "1",
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    let html = std::fs::read_to_string(dir.path().join("out/index.html")).expect("index.html");
    let page = &images(&html)[0];
    let slide = image::open(dir.path().join("out/slides/step-01.png"))
        .expect("the slide")
        .to_rgba8();
    let share = |img: &RgbaImage, light: bool| {
        let n = img
            .pixels()
            .filter(|p| {
                let l = (u32::from(p.0[0]) + u32::from(p.0[1]) + u32::from(p.0[2])) / 3;
                if light { l > 235 } else { l < 30 }
            })
            .count();
        n as f64 / f64::from(img.width() * img.height())
    };
    assert!(
        share(page, true) > 0.8,
        "the page's picture is white: {}",
        share(page, true)
    );
    assert!(
        share(page, false) < 0.05,
        "and has no dark ground: {}",
        share(page, false)
    );
    assert!(
        share(&slide, false) > 0.3,
        "the slide stays dark: {}",
        share(&slide, false)
    );
}

#[test]
fn the_answer_key_prints_every_answer_and_chinese_captions_are_chinese() {
    let dir = tempfile::tempdir().expect("temp dir");
    let html = export(dir.path(), &["--answers", "--lang", "zh"]);
    assert!(!html.contains("<details"), "nothing folded in a key");
    for answer in ["因为法线。", "一样，只是更大。"] {
        assert!(
            html.contains(&format!("<b class=\"ui\">答案：</b><p>{answer}</p>")),
            "{answer}"
        );
    }
    assert_captions_chinese(&html, "picture");
    assert!(html.contains("投影的 fovy = 40</figcaption>"));
}

#[test]
fn slides_and_data_only_on_request() {
    let dir = tempfile::tempdir().expect("temp dir");
    export(dir.path(), &["--slides", "--data"]);
    let out = dir.path().join("out");
    for k in 1..=2 {
        let slide = image::open(out.join(format!("slides/step-0{k}.png")))
            .expect("a slide")
            .to_rgba8();
        assert_eq!((slide.width(), slide.height()), (1920, 1080));
        // The title in the accent colour, the picture, the narration in light type.
        assert!(count(&slide, 40..110, [255, 214, 120], 40) > 200, "title");
        assert!(
            count(&slide, 130..1040, [235, 235, 235], 30) > 200,
            "narration"
        );
        let step = out.join(format!("step-0{k}"));
        assert!(step.join("color.png").is_file() && step.join("capture.json").is_file());
    }
    assert!(out.join("step-01/profile.csv").is_file());
    let dir = tempfile::tempdir().expect("temp dir");
    export(dir.path(), &[]);
    let names: Vec<String> = std::fs::read_dir(dir.path().join("out"))
        .expect("out")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["index.html"]);
}

/// `export LESSON --data --pixel X,Y` writes that pixel's record into every step's
/// `capture.json` (in place of the step's own); without `--data` the flag is refused, and a
/// pixel outside a step's image is an error naming the step, not a silent omission.
#[test]
fn a_lessons_data_holds_the_pixel_asked_for() {
    let dir = tempfile::tempdir().expect("temp dir");
    export(dir.path(), &["--data", "--pixel", "20,30"]);
    for k in 1..=2 {
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(dir.path().join(format!("out/step-0{k}/capture.json")))
                .expect("capture.json"),
        )
        .expect("json");
        let pixel = &json["pixel"];
        assert_eq!(
            (pixel["x"].as_u64(), pixel["y"].as_u64()),
            (Some(20), Some(30)),
            "step {k}: {pixel}"
        );
    }
    // Without --pixel, step 1 keeps its own pixel (80, 70).
    let dir = tempfile::tempdir().expect("temp dir");
    export(dir.path(), &["--data"]);
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("out/step-01/capture.json")).expect("json"),
    )
    .expect("json");
    assert_eq!(json["pixel"]["x"].as_u64(), Some(80));
    for (args, expect) in [
        (&["--pixel", "20,30"][..], "add --data"),
        (
            &["--data", "--pixel", "500,30"][..],
            "outside step 1's 160×120 image",
        ),
    ] {
        let dir = tempfile::tempdir().expect("temp dir");
        std::fs::write(dir.path().join("picture.toml"), LESSON).expect("write");
        let mut all = vec!["export", "picture.toml", "--out", "out"];
        all.extend(args);
        let o = pipelens(dir.path(), &all);
        assert!(!o.status.success(), "{args:?} succeeded");
        assert!(text(&o).contains(expect), "{args:?}: {}", text(&o));
    }
}

/// A slide is full: lesson 17's step 2 has a wide picture (the wireframe beside the observer),
/// which spans the slide with the narration under it. Beside the words it filled 44 % of the
/// rows under the title and left the lower half blank.
#[test]
fn a_wide_picture_spans_the_slide_with_the_words_under_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/17-hierarchy.toml");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            lesson.to_str().expect("utf-8"),
            "--out",
            "out",
            "--slides",
            "--step",
            "2",
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    let slide = image::open(dir.path().join("out/slides/step-02.png"))
        .expect("the slide")
        .to_rgba8();
    let ground = *slide.get_pixel(slide.width() - 1, slide.height() / 2);
    let (below_title, above_footer) = (130, slide.height() - 70);
    let full = (below_title..above_footer)
        .filter(|&y| {
            (0..slide.width()).any(|x| {
                let p = slide.get_pixel(x, y);
                (0..3).any(|c| (i32::from(p.0[c]) - i32::from(ground.0[c])).abs() > 20)
            })
        })
        .count();
    let share = full as f64 / f64::from(above_footer - below_title);
    assert!(share > 0.7, "rows with content under the title: {share:.2}");
}

/// Every picture of a handout says in its `alt` what it shows (issue "Every student can use
/// it", WCAG 1.1.1): its step's title, the stage, the buffer, the size and the objects; at the step's pixel, the
/// pixel, its object and its derivation's last line, the colour — the very colour the plain
/// picture has there (window pixel (80, 70) of 160×120, y up, is row 119 − 70 = 49, magnified
/// four times: the picture's pixel (322, 198)). The second step, with no pixel, says no more.
#[test]
fn each_picture_says_what_it_shows() {
    let dir = tempfile::tempdir().expect("temp dir");
    let html = export(dir.path(), &[]);
    let alts: Vec<&str> = html
        .split("<figure><img src=\"data:image/png")
        .skip(1)
        .filter_map(|f| f.split("alt=\"").nth(1)?.split('"').next())
        .collect();
    assert_eq!(alts.len(), 2, "{alts:?}");
    let first = alts[0];
    assert!(
        first.starts_with(
            "Everything drawn — Shading stage, Colour buffer, 160×120 pixels: ball. At pixel (80, 70), ball's triangle "
        ),
        "{first}"
    );
    let plain = &images(&html)[1];
    let [r, g, b, _] = plain.get_pixel(322, 198).0;
    assert!(
        first.ends_with(&format!("= ({r}, {g}, {b}).")),
        "{first} against ({r}, {g}, {b})"
    );
    assert_eq!(
        alts[1],
        "Nothing drawn — Shading stage, Colour buffer, 160×120 pixels: ball."
    );
}
