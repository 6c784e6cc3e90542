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
