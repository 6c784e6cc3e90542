//! A shader lesson on paper and on slides: the handout prints the code each step runs (its edit
//! marked, a lab's TODO), the debugger's run at the step's pixel, and the slides show the code
//! a step is about beside its picture.

use image::RgbaImage;

use crate::support::{pipelens, text};

/// The text of each marked (yellow) row of the listings in `section`, tags left out.
fn marked_rows(section: &str) -> Vec<String> {
    section
        .split("<tr class=\"m\">")
        .skip(1)
        .map(|row| {
            let row = &row[..row.find("</tr>").unwrap_or(row.len())];
            crate::support::without_tags(row)
                .replace("&lt;", "<")
                .replace("&gt;", ">")
        })
        .collect()
}

/// Lesson 24's handout prints the shaders each step runs: the rim step's listing marks the
/// lines its edit added (and not the lines it kept), the debugger's step the run at its pixel,
/// the vertex-shader step its vertex shader and not pipelens' own fragment shader beside it, a
/// lab its starter with the TODO marked.
#[test]
fn a_shader_step_prints_its_code_with_its_edit_marked() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/24-shader-programs.toml");
    let out = dir.path().join("h");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            lesson.to_str().expect("utf-8"),
            "--out",
            out.to_str().expect("utf-8"),
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    let html = std::fs::read_to_string(out.join("index.html")).expect("index.html");
    let section = |n: usize| {
        let start = html
            .find(&format!("<section id=\"step-{n}\">"))
            .unwrap_or_else(|| panic!("step {n}"));
        let end = html[start..].find("</section>").expect("its end") + start;
        html[start..end].to_owned()
    };
    let rim = marked_rows(&section(4));
    assert!(
        rim.iter().any(|r| r.contains("float rim = ")),
        "the rim's line is marked: {rim:?}"
    );
    assert!(
        !rim.iter().any(|r| r.contains("vec3 n = normalize(w_nrm);")),
        "a kept line is not: {rim:?}"
    );
    // The debugger's step prints its pixel's run: the inputs, each statement, the branch.
    let debugger = section(7);
    assert!(
        debugger.contains("The debugger at pixel ("),
        "no run printed"
    );
    for row in [
        "<td class=\"n\">in</td><td class=\"l\">w_nrm = vec3(",
        "if: true → then",
        "color = vec4(",
    ] {
        assert!(debugger.contains(row), "the run lacks {row:?}");
    }
    assert!(
        !section(6).contains("The debugger at pixel"),
        "a step with no pixel has no run"
    );
    let vertex = section(9);
    assert!(vertex.contains("<code>shader.vert</code>"));
    assert!(
        !vertex.contains("<code>shader.frag</code>"),
        "pipelens' own is not repeated"
    );
    assert!(vertex.contains("gl_Position"));
    let lab = marked_rows(&section(10));
    // Line 29 of the starter (counted in the lesson file), and only it.
    assert_eq!(
        lab,
        ["29    // TODO: the diffuse term k_d·c·I·max(n·l, 0), added to L."],
        "the lab's TODO is marked"
    );
}

/// Pixels of `img` of exactly `rgb`.
fn exactly(img: &RgbaImage, rgb: [u8; 3]) -> usize {
    img.pixels().filter(|p| p.0[..3] == rgb).count()
}

/// A shader step's slide shows the code it is about beside its picture: the debugger's step its
/// run with the branch marked, a lab its starter's TODO (marked) under the words, and the
/// lighting legend at the slide's size in the words' column, not over the picture (the
/// picture's top-left keeps the scene's background); a step with no code has no panel.
#[test]
fn a_shader_slide_shows_its_code_beside_the_picture() {
    let dir = tempfile::tempdir().expect("temp dir");
    let slide = |lesson: &str, step: &str| {
        let out = dir.path().join(format!("{lesson}-{step}"));
        let path = crate::support::repo().join(format!("lessons/{lesson}.toml"));
        let o = pipelens(
            dir.path(),
            &[
                "export",
                path.to_str().expect("utf-8"),
                "--out",
                out.to_str().expect("utf-8"),
                "--slides",
                "--step",
                step,
            ],
        );
        assert!(o.status.success(), "{}", text(&o));
        let n: usize = step.parse().expect("a number");
        image::open(out.join(format!("slides/step-{n:02}.png")))
            .expect("the slide")
            .to_rgba8()
    };
    // The panel's ground and a marked row's (slides.rs), from their own constants.
    let (ground, marked) = ([34, 37, 43], [70, 62, 36]);
    for (step, what) in [("7", "the debugger's run"), ("10", "the lab's starter")] {
        let s = slide("24-shader-programs", step);
        assert!(
            exactly(&s, ground) > 20_000,
            "step {step}: no panel for {what}"
        );
        assert!(
            exactly(&s, marked) > 5_000,
            "step {step}: nothing marked in {what}"
        );
        // The code is in the right-hand column, beside the picture (which ends near x = 1208).
        let left_of_column = (0..1080)
            .flat_map(|y| (0..1200).map(move |x| (x, y)))
            .filter(|&(x, y)| s.get_pixel(x, y).0[..3] == ground)
            .count();
        assert_eq!(
            left_of_column, 0,
            "step {step}: the panel covers the picture"
        );
    }
    let debugger = slide("24-shader-programs", "7");
    // The picture's top-left (slide 48..400 × 130..230) is the scene's dark ground: no legend
    // box magnified over it.
    let bright = (130..230)
        .flat_map(|y| (48..400).map(move |x| (x, y)))
        .filter(|&(x, y)| debugger.get_pixel(x, y).0[..3].iter().any(|&c| c > 120))
        .count();
    assert_eq!(bright, 0, "the legend is drawn over the picture");
    // (A few of its picture's pixels may have the panel's colour by chance; a panel has
    // tens of thousands.)
    let plain = slide("04-orthographic", "1");
    assert!(
        exactly(&plain, ground) < 1_000,
        "a step with no code has a code panel"
    );
}

/// Lesson 25's question asks for f and f/aspect: the handout's boxes carry those names above
/// them, and the teacher's key fills them with 2.4142 and 1.5089 (cot 22.5° = 2.41421 and
/// 2.41421/1.6 = 1.50888, by hand).
#[test]
fn a_handouts_boxes_carry_the_names_the_question_gives() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lesson = crate::support::repo().join("lessons/25-lab-model-projection.toml");
    let out = dir.path().join("h");
    let o = pipelens(
        dir.path(),
        &[
            "export",
            lesson.to_str().expect("utf-8"),
            "--step",
            "4",
            "--answers",
            "--out",
            out.to_str().expect("utf-8"),
        ],
    );
    assert!(o.status.success(), "{}", text(&o));
    let html = std::fs::read_to_string(out.join("index.html")).expect("index.html");
    assert!(
        html.contains(
            "<tr><th>f</th><th>f/aspect</th></tr><tr><td>2.4142</td><td>1.5089</td></tr>"
        ),
        "{}",
        &html[html.find("class=\"fill\"").unwrap_or(0)..][..300.min(html.len())]
    );
}
