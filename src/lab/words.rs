//! A lab's verdict in words, in the interface's language: passed, or how many pixels (or curve
//! points) differ and where the first is, and what was found there — the variable, the vertex,
//! the matrix entries. The card in the app and `pipelens grade` print the same sentences.

use pipeline::capture::Difference;
use pipeline::shader::CurveDifference;

use super::{MatrixMismatch, Mismatch};
use crate::vocabulary::Lang;

/// The verdict in words: passed, or how many pixels differ and where the first is.
#[must_use]
pub fn verdict(d: &Difference, lang: Lang) -> String {
    let tolerance = crate::vocabulary::short(d.criteria.tolerance, 1);
    if d.passed() {
        return lang.t_with(
            "lab-words-passed",
            &[("total", &d.total), ("tolerance", &tolerance)],
        );
    }
    let first = d.first.map(pixel).unwrap_or_default();
    // What differs, each clause only where some pixel differs so.
    let mut how = Vec::new();
    if d.largest > d.criteria.tolerance {
        let largest = crate::vocabulary::short(d.largest, 0);
        how.push(lang.t_with("lab-words-colours-differ", &[("largest", &largest)]));
    }
    for (n, id) in [
        (d.coverage_differs, "lab-words-covered-differently"),
        (d.depth_differs, "lab-words-at-another-depth"),
        (d.owner_differs, "lab-words-another-triangle"),
    ] {
        if n > 0 {
            how.push(lang.t_with(id, &[("n", &n)]));
        }
    }
    lang.t_with(
        "lab-words-not-yet",
        &[
            ("matching", &d.matching),
            ("total", &d.total),
            ("differ", &(d.total - d.matching)),
            ("how", &how.join(lang.t("lab-words-clause-separator"))),
            ("first", &first),
        ],
    )
}

/// A pixel as the sentences name it, `(x, y)`, in the coordinates of the verdict's first
/// difference and of the Inspector.
#[must_use]
pub fn pixel((x, y): (u32, u32)) -> String {
    format!("({x}, {y})")
}

/// A mismatch in words: the pixel or vertex, the variable, its line, both values, and a
/// vector's length when only pipelens' is 1 (a normal not normalized).
#[must_use]
pub fn mismatch_words(m: &Mismatch, lang: Lang) -> String {
    let values: [(&'static str, &dyn std::fmt::Display); 4] = [
        ("name", &m.name),
        ("line", &m.line),
        ("yours", &m.yours),
        ("theirs", &m.theirs),
    ];
    let mut text = match m.vertex {
        None => {
            let at = m.pixel.map(pixel).unwrap_or_default();
            let mut at_pixel = values.to_vec();
            at_pixel.push(("pixel", &at));
            lang.t_with("lab-words-at-the-pixel", &at_pixel)
        }
        Some(row) => {
            let mut at_vertex = values.to_vec();
            at_vertex.push(("row", &row));
            lang.t_with("lab-words-at-the-vertex", &at_vertex)
        }
    };
    if let Some(len) = super::findings::unnormalized(m.lengths) {
        let len = format!("{len:.4}");
        text.push_str(&lang.t_with("lab-words-not-normalized", &[("length", &len)]));
    }
    text
}

/// The first wrong vertex in words: its row and both clip positions.
pub fn vertex_words(row: u32, yours: glam::Vec4, theirs: glam::Vec4, lang: Lang) -> String {
    let v = |c: glam::Vec4| format!("({:.3}, {:.3}, {:.3}, {:.3})", c.x, c.y, c.z, c.w);
    lang.t_with(
        "lab-words-first-vertex",
        &[("row", &row), ("yours", &v(yours)), ("theirs", &v(theirs))],
    )
}

/// A matrix compared entry by entry, in words: which of pipelens' matrices it stands for and
/// each entry that differs (at most four listed).
#[must_use]
pub fn matrix_words(m: &MatrixMismatch, lang: Lang) -> String {
    let entries: Vec<String> = m
        .entries
        .iter()
        .take(4)
        .map(|(r, c, yours, theirs)| {
            lang.t_with(
                "lab-words-matrix-entry",
                &[
                    ("row", r),
                    ("column", c),
                    ("yours", &format!("{yours:.3}")),
                    ("theirs", &format!("{theirs:.3}")),
                    ("matrix", &m.matrix),
                ],
            )
        })
        .collect();
    let more = m.entries.len().saturating_sub(4);
    let more = if more > 0 {
        lang.t_with("lab-words-matrix-more", &[("more", &more)])
    } else {
        String::new()
    };
    lang.t_with(
        "lab-words-matrix",
        &[
            ("name", &m.name),
            ("line", &m.line),
            ("matrix", &m.matrix),
            ("n", &m.entries.len()),
            (
                "entries",
                &entries.join(lang.t("lab-words-clause-separator")),
            ),
            ("more", &more),
        ],
    )
}

/// The verdict on a curve (or a Bézier patch's surface) in words: passed, or how many points
/// are off, by how much, and the first one with both values.
#[must_use]
pub fn curve_verdict(c: &CurveDifference, lang: Lang) -> String {
    use pipeline::shader::At;
    let tolerance = format!("{:e}", c.tolerance);
    let surface = c.surface;
    let (b, what) = if surface {
        ("b(u, v)", lang.t("lab-words-surface"))
    } else {
        ("b(t)", lang.t("lab-words-curve"))
    };
    if c.passed() {
        return lang.t_with(
            "lab-words-curve-passed",
            &[
                ("total", &c.total),
                ("what", &what),
                ("tolerance", &tolerance),
                ("b", &b),
            ],
        );
    }
    let point = |p: glam::Vec3| {
        if surface {
            format!("({:.4}, {:.4}, {:.4})", p.x, p.y, p.z)
        } else {
            format!("({:.4}, {:.4})", p.x, p.y)
        }
    };
    let largest = if c.largest.is_finite() {
        format!("{:.4}", c.largest)
    } else {
        "∞".to_owned()
    };
    let first = c.first.map_or_else(String::new, |(at, mine, theirs)| {
        let at = match at {
            At::T(t) => format!("t = {t:.4}"),
            At::Uv(uv) => format!("(u, v) = ({:.4}, {:.4})", uv.x, uv.y),
        };
        lang.t_with(
            "lab-words-curve-first",
            &[
                ("at", &at),
                ("yours", &point(mine)),
                ("theirs", &point(theirs)),
            ],
        )
    });
    lang.t_with(
        "lab-words-curve-not-yet",
        &[
            ("matching", &c.matching),
            ("total", &c.total),
            ("what", &what),
            ("tolerance", &tolerance),
            ("b", &b),
            ("largest", &largest),
            ("first", &first),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use pipeline::capture::Criteria;

    fn difference(
        matching: u64,
        (coverage, depth, owner): (u64, u64, u64),
        largest: f32,
    ) -> Difference {
        Difference {
            matching,
            total: 100,
            coverage_differs: coverage,
            depth_differs: depth,
            owner_differs: owner,
            largest,
            first: Some((3, 7)),
            criteria: Criteria {
                tolerance: 2.0,
                depth: Some(1e-4),
                owner: true,
            },
        }
    }

    /// Each sentence as a student reads it, written out by hand in both languages: one of a
    /// kind and several, every clause.
    #[test]
    fn a_verdict_reads_in_either_language_with_its_counts() {
        let passed = difference(100, (0, 0, 0), 0.0);
        assert_eq!(
            verdict(&passed, Lang::EN),
            "Passed: all 100 pixels match pipelens' own (each channel within 2/255)."
        );
        assert_eq!(
            verdict(&passed, Lang::ZH),
            "通过：全部 100 个像素与 pipelens 自带的一致（每个通道相差不超过 2/255）。"
        );
        let one = difference(99, (1, 0, 0), 0.0);
        assert_eq!(
            verdict(&one, Lang::EN),
            "Not yet: 99 of 100 pixels match; 1 differs (1 is covered differently). The first, reading from the top, is (3, 7)."
        );
        let many = difference(90, (4, 1, 2), 37.0);
        assert_eq!(
            verdict(&many, Lang::EN),
            "Not yet: 90 of 100 pixels match; 10 differ (colours by up to 37/255; 4 are covered differently; 1 lies at another depth; 2 belong to another triangle). The first, reading from the top, is (3, 7)."
        );
        assert_eq!(
            verdict(&many, Lang::ZH),
            "还没有通过：100 个像素中 90 个一致，10 个不同（颜色最多相差 37/255；4 个覆盖不同；1 个深度不同；2 个属于另一个三角形）。从上往下读，第一个是 (3, 7)。"
        );
    }

    #[test]
    fn a_mismatch_a_vertex_and_a_matrix_read_in_either_language() {
        let m = Mismatch {
            name: "n".to_owned(),
            line: 12,
            yours: "(0, 2, 0)".to_owned(),
            theirs: "(0, 1, 0)".to_owned(),
            lengths: Some((2.0, 1.0)),
            pixel: Some((31, 7)),
            vertex: None,
        };
        assert_eq!(
            mismatch_words(&m, Lang::EN),
            "At the inspected pixel (31, 7) your `n` (line 12) is (0, 2, 0); pipelens' own shader has (0, 1, 0). Yours has length 2.0000, pipelens' 1: is it normalized?"
        );
        assert_eq!(
            mismatch_words(&m, Lang::ZH),
            "在所检查的像素 (31, 7) 处，你的 `n`（第 12 行）是 (0, 2, 0)；pipelens 自带的着色器得到 (0, 1, 0)。你的长度是 2.0000，pipelens 的是 1：它归一化了吗？"
        );
        let at_vertex = Mismatch {
            vertex: Some(5),
            lengths: None,
            ..m
        };
        assert_eq!(
            mismatch_words(&at_vertex, Lang::ZH),
            "在顶点 5（第一个错误像素所在三角形的一个角）处，你的顶点着色器中的 `n`（第 12 行）是 (0, 2, 0)；pipelens 自带的得到 (0, 1, 0)。"
        );
        let v = glam::Vec4::new(1.0, 0.5, 0.25, 1.0);
        assert_eq!(
            vertex_words(3, v, glam::Vec4::ONE, Lang::EN),
            "The first vertex off is row 3: your clip position (1.000, 0.500, 0.250, 1.000), pipelens' (1.000, 1.000, 1.000, 1.000)."
        );
        let one = MatrixMismatch {
            name: "view".to_owned(),
            line: 4,
            matrix: "V",
            entries: vec![(1, 4, 2.0, -2.0)],
        };
        assert_eq!(
            matrix_words(&one, Lang::EN),
            "Your `view` (line 4) is pipelens' V but for one entry: row 1, column 4 is 2.000 (V has -2.000)."
        );
        let six = MatrixMismatch {
            entries: vec![(1, 1, 0.0, 1.0); 6],
            ..one
        };
        assert_eq!(
            matrix_words(&six, Lang::ZH),
            "你的 `view`（第 4 行）与 pipelens 的 V 有 6 个元素不同：第 1 行第 1 列是 0.000（V 中为 1.000）；第 1 行第 1 列是 0.000（V 中为 1.000）；第 1 行第 1 列是 0.000（V 中为 1.000）；第 1 行第 1 列是 0.000（V 中为 1.000）；还有 2 个。"
        );
    }

    #[test]
    fn a_curves_verdict_reads_in_either_language() {
        let c = CurveDifference {
            matching: 60,
            total: 64,
            largest: 0.5,
            first: Some((
                pipeline::shader::At::T(0.25),
                glam::Vec3::new(1.0, 2.0, 0.0),
                glam::Vec3::new(1.0, 1.5, 0.0),
            )),
            tolerance: 1e-4,
            surface: false,
        };
        assert_eq!(
            curve_verdict(&c, Lang::EN),
            "Not yet: 60 of 64 curve points lie within 1e-4 of pipelens' b(t) (the farthest is 0.5000 away). The first, t = 0.2500: yours (1.0000, 2.0000), pipelens' (1.0000, 1.5000)."
        );
        assert_eq!(
            curve_verdict(&c, Lang::ZH),
            "还没有通过：64 个曲线点中 60 个与 pipelens 的 b(t) 相差不超过 1e-4（最远相差 0.5000）。第一个在 t = 0.2500：你的 (1.0000, 2.0000)，pipelens 的 (1.0000, 1.5000)。"
        );
        let passed = CurveDifference {
            matching: 64,
            first: None,
            surface: true,
            ..c
        };
        assert_eq!(
            curve_verdict(&passed, Lang::ZH),
            "通过：你的曲面的全部 64 个点与 pipelens 的 b(u, v) 相差都不超过 1e-4。"
        );
    }
}
