//! A lab's verdict in words, in the interface's language: passed, or how many pixels (or curve
//! points) differ and where the first is, and what was found there — the variable, the vertex,
//! the matrix entries. The card in the app and `pipelens grade` print the same sentences.

use crate::vocabulary::Written;
use pipeline::capture::Difference;
use pipeline::shader::CurveDifference;

use super::{MatrixMismatch, Mismatch};
use crate::vocabulary::Lang;

/// The verdict in words: passed, or how many pixels differ and where the first is.
#[must_use]
pub fn verdict(d: &Difference, lang: Lang) -> String {
    let tolerance = crate::vocabulary::short(d.criteria.tolerance, 1);
    if d.passed() {
        return match lang.written() {
            Written::English => format!(
                "Passed: all {} pixels match pipelens' own (each channel within {tolerance}/255).",
                d.total
            ),
            Written::Chinese => format!(
                "通过：全部 {} 个像素与 pipelens 自带的一致（每个通道相差不超过 {tolerance}/255）。",
                d.total
            ),
        };
    }
    let differ = d.total - d.matching;
    let largest = crate::vocabulary::short(d.largest, 0);
    let first = d
        .first
        .map(|(x, y)| format!("({x}, {y})"))
        .unwrap_or_default();
    // What differs, each clause only where some pixel differs so.
    let mut how = Vec::new();
    if d.largest > d.criteria.tolerance {
        how.push(match lang.written() {
            Written::English => format!("colours by up to {largest}/255"),
            Written::Chinese => format!("颜色最多相差 {largest}/255"),
        });
    }
    let counted = |n: u64, one: &str, many: &str, zh: &str| match lang.written() {
        Written::English if n == 1 => format!("1 {one}"),
        Written::English => format!("{n} {many}"),
        Written::Chinese => format!("{n} 个{zh}"),
    };
    if d.coverage_differs > 0 {
        how.push(counted(
            d.coverage_differs,
            "is covered differently",
            "are covered differently",
            "覆盖不同",
        ));
    }
    if d.depth_differs > 0 {
        how.push(counted(
            d.depth_differs,
            "lies at another depth",
            "lie at another depth",
            "深度不同",
        ));
    }
    if d.owner_differs > 0 {
        how.push(counted(
            d.owner_differs,
            "belongs to another triangle",
            "belong to another triangle",
            "属于另一个三角形",
        ));
    }
    match lang.written() {
        Written::English => format!(
            "Not yet: {} of {} pixels match; {} ({}). The first, reading from the top, is {first}.",
            d.matching,
            d.total,
            if differ == 1 {
                "1 differs".to_owned()
            } else {
                format!("{differ} differ")
            },
            how.join("; ")
        ),
        Written::Chinese => format!(
            "还没有通过：{} 个像素中 {} 个一致，{differ} 个不同（{}）。从上往下读，第一个是 {first}。",
            d.total,
            d.matching,
            how.join("；")
        ),
    }
}

/// A mismatch in words: the variable, its line, both values, and a vector's length when only
/// pipelens' is 1 (a normal not normalized).
#[must_use]
pub fn mismatch_words(m: &Mismatch, lang: Lang) -> String {
    let unnormalized = super::findings::unnormalized(m.lengths);
    let mut text = match (lang.written(), m.vertex) {
        (Written::English, None) => format!(
            "At the inspected pixel your `{}` (line {}) is {}; pipelens' own shader has {}.",
            m.name, m.line, m.yours, m.theirs
        ),
        (Written::Chinese, None) => format!(
            "在所检查的像素处，你的 `{}`（第 {} 行）是 {}；pipelens 自带的着色器得到 {}。",
            m.name, m.line, m.yours, m.theirs
        ),
        (Written::English, Some(row)) => format!(
            "At vertex {row} (a corner of the first wrong pixel's triangle) your vertex shader's `{}` (line {}) is {}; pipelens' own has {}.",
            m.name, m.line, m.yours, m.theirs
        ),
        (Written::Chinese, Some(row)) => format!(
            "在顶点 {row}（第一个错误像素所在三角形的一个角）处，你的顶点着色器中的 `{}`（第 {} 行）是 {}；pipelens 自带的得到 {}。",
            m.name, m.line, m.yours, m.theirs
        ),
    };
    if let Some(len) = unnormalized {
        text.push_str(&match lang.written() {
            Written::English => {
                format!(" Yours has length {len:.4}, pipelens' 1: is it normalized?")
            }
            Written::Chinese => format!("你的长度是 {len:.4}，pipelens 的是 1：它归一化了吗？"),
        });
    }
    text
}

/// The first wrong vertex in words: its row and both clip positions.
pub fn vertex_words(row: u32, yours: glam::Vec4, theirs: glam::Vec4, lang: Lang) -> String {
    let v = |c: glam::Vec4| format!("({:.3}, {:.3}, {:.3}, {:.3})", c.x, c.y, c.z, c.w);
    match lang.written() {
        Written::English => format!(
            "The first vertex off is row {row}: your clip position {}, pipelens' {}.",
            v(yours),
            v(theirs)
        ),
        Written::Chinese => format!(
            "第一个出错的顶点在第 {row} 行：你的裁剪坐标 {}，pipelens 的 {}。",
            v(yours),
            v(theirs)
        ),
    }
}

/// A matrix compared entry by entry, in words: which of pipelens' matrices it stands for and
/// each entry that differs (at most four listed).
#[must_use]
pub fn matrix_words(m: &MatrixMismatch, lang: Lang) -> String {
    let entries: Vec<String> = m
        .entries
        .iter()
        .take(4)
        .map(|(r, c, yours, theirs)| match lang.written() {
            Written::English => format!(
                "row {r}, column {c} is {yours:.3} ({} has {theirs:.3})",
                m.matrix
            ),
            Written::Chinese => format!(
                "第 {r} 行第 {c} 列是 {yours:.3}（{} 中为 {theirs:.3}）",
                m.matrix
            ),
        })
        .collect();
    let more = m.entries.len().saturating_sub(4);
    match lang.written() {
        Written::English => format!(
            "Your `{}` (line {}) is pipelens' {} but for {}: {}{}.",
            m.name,
            m.line,
            m.matrix,
            match m.entries.len() {
                1 => "one entry".to_owned(),
                n => format!("{n} entries"),
            },
            entries.join("; "),
            if more > 0 {
                format!("; and {more} more")
            } else {
                String::new()
            }
        ),
        Written::Chinese => format!(
            "你的 `{}`（第 {} 行）与 pipelens 的 {} 有 {} 个元素不同：{}{}。",
            m.name,
            m.line,
            m.matrix,
            m.entries.len(),
            entries.join("；"),
            if more > 0 {
                format!("；还有 {more} 个")
            } else {
                String::new()
            }
        ),
    }
}

/// The verdict on a curve (or a Bézier patch's surface) in words: passed, or how many points
/// are off, by how much, and the first one with both values.
#[must_use]
pub fn curve_verdict(c: &CurveDifference, lang: Lang) -> String {
    use pipeline::shader::At;
    let tolerance = format!("{:e}", c.tolerance);
    let surface = c.surface;
    let (b, what) = match (surface, lang.written()) {
        (false, Written::English) => ("b(t)", "curve"),
        (true, Written::English) => ("b(u, v)", "surface"),
        (false, Written::Chinese) => ("b(t)", "曲线"),
        (true, Written::Chinese) => ("b(u, v)", "曲面"),
    };
    if c.passed() {
        return match lang.written() {
            Written::English => format!(
                "Passed: all {} points of your {what} lie within {tolerance} of pipelens' {b}.",
                c.total
            ),
            Written::Chinese => format!(
                "通过：你的{what}的全部 {} 个点与 pipelens 的 {b} 相差都不超过 {tolerance}。",
                c.total
            ),
        };
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
        match lang.written() {
            Written::English => format!(
                " The first, {at}: yours {}, pipelens' {}.",
                point(mine),
                point(theirs)
            ),
            Written::Chinese => format!(
                "第一个在 {at}：你的 {}，pipelens 的 {}。",
                point(mine),
                point(theirs)
            ),
        }
    });
    match lang.written() {
        Written::English => format!(
            "Not yet: {} of {} {what} points lie within {tolerance} of pipelens' {b} (the farthest is {largest} away).{first}",
            c.matching, c.total
        ),
        Written::Chinese => format!(
            "还没有通过：{} 个{what}点中 {} 个与 pipelens 的 {b} 相差不超过 {tolerance}（最远相差 {largest}）。{first}",
            c.total, c.matching
        ),
    }
}
