//! `pipelens export --watch EXPR@LINE`, run as a user runs it: a fragment shader's expression
//! after a line, at every pixel, as numbers and pictures, at the pixels the frame shows.

use crate::support::{pipelens, repo, text};

/// The lesson's debugger step: its fragment shader computes `diffuse` on line 22.
const LESSON: &str = "lessons/24-shader-programs.toml";
const STEP: &str = "7";

/// `pipelens export LESSON --step STEP --watch WATCH --out OUT`.
fn export_watch(watch: &str, out: &std::path::Path) -> std::process::Output {
    let out = out.to_str().expect("utf-8");
    pipelens(
        &repo(),
        &[
            "export", LESSON, "--step", STEP, "--watch", watch, "--out", out,
        ],
    )
}

/// `gl_FragCoord.xy` is, by GLSL's definition, the pixel's centre in window terms (y up): so
/// every row of watch.csv holds `x + ½, y + ½` beside its pixel `x, y`, which also says the
/// numbers are not mirrored top to bottom.
#[test]
fn every_pixel_of_the_csv_holds_its_own_window_centre() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("watch");
    let o = export_watch("gl_FragCoord.xy@22", &out);
    let said = text(&o);
    assert!(o.status.success(), "{said}");
    assert!(said.contains("a vec2 at"), "{said}");
    let csv = std::fs::read_to_string(out.join("watch.csv")).expect("watch.csv");
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("x,y,value.x,value.y"));
    let mut rows = 0;
    for line in lines {
        let v: Vec<f32> = line
            .split(',')
            .map(|n| n.parse().expect("a number"))
            .collect();
        assert_eq!([v[2], v[3]], [v[0] + 0.5, v[1] + 0.5], "{line}");
        rows += 1;
    }
    // The sphere covers about a third of the 480 × 360 frame.
    assert!(rows > 30_000 && rows < 120_000, "{rows} pixels");
    for png in ["watch.png", "watch-x.png", "watch-y.png"] {
        let img = image::open(out.join(png)).expect(png);
        assert_eq!((img.width(), img.height()), (480, 360), "{png}");
    }
}

/// A condition says where it holds and where first (reading from the top); a watch that cannot
/// be made says why, with the line, and writes nothing.
#[test]
fn a_condition_says_where_it_holds_and_a_bad_watch_writes_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("mask");
    let run = |watch: &str| export_watch(watch, &out);
    let o = run("dot(n, l) < 0.0@22");
    let said = text(&o);
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("holds at") && said.contains("the first, reading from the top, at pixel"),
        "{said}"
    );
    assert!(
        std::fs::read_to_string(out.join("watch.csv"))
            .expect("watch.csv")
            .starts_with("x,y,value\n")
    );
    std::fs::remove_dir_all(&out).expect("cleared");
    for (watch, says) in [
        ("n@27", "line 27 does not end a statement"),
        ("nope@22", "does not compile here"),
        ("n@999", "has no line 999"),
    ] {
        let o = run(watch);
        let said = text(&o);
        assert!(!o.status.success(), "{watch}: {said}");
        assert!(said.contains(says), "{watch}: {said}");
        assert!(!out.join("watch.png").exists(), "{watch} wrote a picture");
    }
    let o = pipelens(
        &repo(),
        &["export", LESSON, "--watch", "n@18", "--out", "x"],
    );
    assert!(text(&o).contains("add --step N"), "{}", text(&o));
}

/// The rows of a watch's CSV: pixel `(x, y)` and its first value.
fn csv_values(dir: &std::path::Path) -> std::collections::HashMap<(u32, u32), f64> {
    let csv = std::fs::read_to_string(dir.join("watch.csv")).expect("watch.csv");
    csv.lines()
        .skip(1)
        .map(|line| {
            let v: Vec<&str> = line.split(',').collect();
            let n = |k: usize| v[k].parse::<f64>().expect("a number");
            ((n(0) as u32, n(1) as u32), n(2))
        })
        .collect()
}

/// A vertex shader's expression (`EXPR@vertex:LINE`) reaches each pixel interpolated with
/// perspective-correct weights: for the clip w that pipelens' vertex shader writes on its line
/// 32, `(Σ λᵢ·wᵢ/wᵢ)/(Σ λᵢ/wᵢ) = 1/(Σ λᵢ/wᵢ)`, which is by GLSL's definition
/// `1 / gl_FragCoord.w` — the fragment shader's own watch of it, at every pixel.
#[test]
fn a_vertex_expression_is_interpolated_as_a_varying() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (vertex, fragment) = (dir.path().join("vertex"), dir.path().join("fragment"));
    let o = export_watch("gl_Position.w@vertex:32", &vertex);
    let said = text(&o);
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("after line 32 of the vertex shader, interpolated"),
        "{said}"
    );
    let o = export_watch("1.0 / gl_FragCoord.w@22", &fragment);
    assert!(o.status.success(), "{}", text(&o));
    let (from_vertex, from_fragment) = (csv_values(&vertex), csv_values(&fragment));
    assert!(from_vertex.len() > 30_000, "{} pixels", from_vertex.len());
    assert_eq!(from_vertex.len(), from_fragment.len());
    for (at, w) in &from_vertex {
        let expected = from_fragment[at];
        assert!(
            (w - expected).abs() <= 1e-4 * expected.abs(),
            "{at:?}: {w} vs {expected}"
        );
    }
    // Not a shader pipelens has.
    let o = export_watch("p@geometry:3", &dir.path().join("none"));
    assert!(!o.status.success() && text(&o).contains("\"geometry\" is not a shader"));
}
