//! Answers the student types: a question's expected value (`expect = …`: a number, a vector or
//! a matrix) with its tolerance, what the student typed read cell by cell (numbers, or small
//! expressions such as `sqrt(3)/2` or `2*pi/3`), and the verdict — right, or which entries are
//! off and by how much. Nothing is graded by a hidden rule: the tolerance is shown beside the
//! field.

pub use super::typed::{Unreadable, evaluate};

/// The shape of an expected value, as the field to type it into is laid out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// One number.
    Number,
    /// A vector of 2 to 4 numbers, typed in a row.
    Vector(usize),
    /// A matrix of `rows × columns` (2 to 4 each), typed cell by cell.
    Matrix(usize, usize),
}

impl Shape {
    /// Rows and columns of the field.
    #[must_use]
    pub fn size(self) -> (usize, usize) {
        match self {
            Self::Number => (1, 1),
            Self::Vector(n) => (1, n),
            Self::Matrix(r, c) => (r, c),
        }
    }

    /// How many cells the field has.
    #[must_use]
    pub fn cells(self) -> usize {
        let (r, c) = self.size();
        r * c
    }
}

/// A question's expected value: `values` row by row, each typed value right when it is within
/// `tolerance` of its entry (`|typed − expected| ≤ tolerance`).
#[derive(Clone, Debug, PartialEq)]
pub struct Expect {
    /// How the value is laid out.
    pub shape: Shape,
    /// The entries, row by row.
    pub values: Vec<f64>,
    /// The largest difference still counted right.
    pub tolerance: f64,
    /// What each entry is, row by row (`expect_names`), where they are not a vector's x, y, z,
    /// w; empty when the step names none.
    pub names: Vec<String>,
}

/// An exercise step: the student completes a shader (`starter`), which draws the step's
/// picture; pipelens' own stage draws the reference, and every pixel is compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Exercise {
    /// What to do, in both languages.
    pub task: crate::vocabulary::Text,
    /// The code the student starts from (it compiles, and does not pass yet).
    pub starter: pipeline::scene::StudentCode,
    /// How many colour steps (of 255) a pixel may differ from the reference and still match.
    pub tolerance: f32,
    /// What the lab asks the student to compute, so their code may not take it from pipelens:
    /// uniforms it may not declare (`view`, `projection`, `normal_matrix`), functions it may
    /// not call (`texture`).
    pub forbid: Vec<String>,
    /// The value of the student's run that stands for one of pipelens' own quantities at the
    /// first wrong pixel (`level_of_detail()` for λ): compared there, and named in the findings.
    pub compare: Option<Compare>,
}

/// `exercise.compare = { yours = "level_of_detail()", pipelens = "lod" }`: which value of the
/// student's fragment shader stands for which of pipelens' quantities at the inspected pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Compare {
    /// A variable (`uv`) or a function's return (`bilinear()`) of the student's run.
    pub yours: String,
    /// pipelens' quantity it must equal.
    pub pipelens: Quantity,
}

/// A quantity pipelens computes at every textured pixel, which a lab may ask the student to
/// compute.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// The texture coordinates, interpolated perspective-correctly.
    Uv,
    /// The level of detail `λ = log₂ L` (with the bias).
    Lod,
    /// The filtered texel colour.
    Texel,
}

impl Quantity {
    /// Every quantity, with its key in a lesson file.
    pub const KEYS: [(&'static str, Self); 3] =
        [("uv", Self::Uv), ("lod", Self::Lod), ("texel", Self::Texel)];

    /// The quantity a lesson file names `key`.
    #[must_use]
    pub fn from_key(key: &str) -> Option<Self> {
        Self::KEYS.iter().find(|(k, _)| *k == key).map(|(_, q)| *q)
    }
}

/// An exercise's tolerance when the lesson gives none: one 8-bit step, as far as the student's
/// shaders and pipelens' own shading may differ by rounding alone.
pub const EXERCISE_TOLERANCE: f32 = 1.0;

/// The tolerance when a lesson gives none: half a unit in the third decimal, so that an answer
/// rounded to three decimals, as the app prints numbers, is right.
pub const DEFAULT_TOLERANCE: f64 = 0.0005 + 1e-9;

/// One entry typed wrong.
#[derive(Clone, Debug, PartialEq)]
pub struct Miss {
    /// The entry's row and column, from 0.
    pub at: (usize, usize),
    /// What the student's text evaluated to.
    pub typed: f64,
    /// `typed − expected`: by how much, and which way, it is off.
    pub off_by: f64,
}

/// What the check of a typed answer says.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// Every entry within the tolerance.
    Right,
    /// Some cells are still empty (their row and column, from 0).
    Empty(Vec<(usize, usize)>),
    /// A cell's text is not a number: where, what was typed, and why it cannot be read.
    Unreadable {
        /// The cell's row and column.
        at: (usize, usize),
        /// The text typed.
        text: String,
        /// What is wrong with it.
        why: Unreadable,
    },
    /// The entries that are off, in reading order.
    Off(Vec<Miss>),
}

/// Below this share of an entry's own size an answer is right even where the lesson's tolerance
/// is wider: an entry smaller than 20 tolerances (`0.000792` with `±0.005`) is checked within
/// 5 % of itself, so that `0` is not right for it while two significant digits are.
pub const RELATIVE_TOLERANCE: f64 = 0.05;

impl Expect {
    /// The name of the entry at row `r`, column `c`: the one the step gives
    /// (`expect_names`), else a vector's x, y, z, w; `None` for a lone number, a matrix's
    /// cells (said by row and column) and a vector longer than four.
    #[must_use]
    pub fn entry_name(&self, (r, c): (usize, usize)) -> Option<&str> {
        let (_, cols) = self.shape.size();
        if let Some(name) = self.names.get(r * cols + c) {
            return Some(name);
        }
        match self.shape {
            Shape::Vector(_) => ["x", "y", "z", "w"].get(c).copied(),
            Shape::Number | Shape::Matrix(..) => None,
        }
    }

    /// The tolerance for `expected`: the lesson's, or 5 % of `|expected|` where that is
    /// smaller ([`RELATIVE_TOLERANCE`]). Zero keeps the lesson's.
    #[must_use]
    pub fn tolerance_at(&self, expected: f64) -> f64 {
        if expected == 0.0 {
            self.tolerance
        } else {
            self.tolerance.min(RELATIVE_TOLERANCE * expected.abs())
        }
    }

    /// The tolerance in words, as the field and the handout state it: `±0.005`, and, where an
    /// entry is small enough to be checked within 5 % of itself, that too.
    #[must_use]
    pub fn tolerance_words(&self, lang: crate::vocabulary::Lang) -> String {
        let t = crate::vocabulary::short(self.tolerance as f32, 4);
        let below = crate::vocabulary::short((self.tolerance / RELATIVE_TOLERANCE) as f32, 4);
        let small = self
            .values
            .iter()
            .any(|&e| self.tolerance_at(e) < self.tolerance);
        if small {
            lang.t_with(
                "answer-tolerance-and-relative",
                &[("t", &t), ("below", &below)],
            )
        } else {
            format!("±{t}")
        }
    }

    /// The cells as they are read: several numbers typed into one box spread over it and the
    /// empty boxes after it. `Err(i)`: box `i` holds more numbers than there are empty boxes.
    ///
    /// # Errors
    /// As said.
    pub fn spread(&self, typed: &[String]) -> Result<Vec<String>, usize> {
        super::typed::spread(typed, self.values.len())
    }

    /// Checks what the student typed, one string per cell row by row (a missing string counts
    /// as an empty cell). Several numbers typed into one box (`2 0.5 -0.5`) are spread over it
    /// and the empty boxes after it; where those are not empty, the box is unreadable.
    #[must_use]
    pub fn check(&self, typed: &[String]) -> Verdict {
        let (_, cols) = self.shape.size();
        let at = |i: usize| (i / cols, i % cols);
        let cells = match super::typed::spread(typed, self.values.len()) {
            Ok(cells) => cells,
            Err(i) => {
                return Verdict::Unreadable {
                    at: at(i),
                    text: typed[i].trim().to_owned(),
                    why: Unreadable::Several,
                };
            }
        };
        let cell = |i: usize| cells.get(i).map_or("", |s| s.trim());
        let empty: Vec<_> = (0..self.values.len())
            .filter(|&i| cell(i).is_empty())
            .map(at)
            .collect();
        if !empty.is_empty() {
            return Verdict::Empty(empty);
        }
        let mut misses = Vec::new();
        for (i, &expected) in self.values.iter().enumerate() {
            let value = match super::typed::evaluate(cell(i)) {
                Ok(v) => v,
                Err(why) => {
                    return Verdict::Unreadable {
                        at: at(i),
                        text: cell(i).to_owned(),
                        why,
                    };
                }
            };
            if (value - expected).abs() > self.tolerance_at(expected) {
                misses.push(Miss {
                    at: at(i),
                    typed: value,
                    off_by: value - expected,
                });
            }
        }
        if misses.is_empty() {
            Verdict::Right
        } else {
            Verdict::Off(misses)
        }
    }
}

impl Verdict {
    /// The verdict in words, for the student: right; or each entry off, with what was typed
    /// and by how much it is too large or too small; or which cells are empty or unreadable.
    #[must_use]
    pub fn describe(&self, expect: &Expect, lang: crate::vocabulary::Lang) -> String {
        let num = |v: f64| crate::vocabulary::short(v as f32, 4);
        // Each entry by the name its box shows (the step's, or a vector's x, y, z, w).
        let cell = |(r, c): (usize, usize)| match (expect.entry_name((r, c)), expect.shape) {
            (Some(name), _) => lang.t_with("answer-named-entry", &[("name", &name)]),
            (None, Shape::Number) => lang.t("answer-your-value").to_owned(),
            (None, Shape::Vector(_)) => lang.t_with("answer-component", &[("n", &(c + 1))]),
            (None, Shape::Matrix(..)) => lang.t_with(
                "answer-row-column",
                &[("row", &(r + 1)), ("column", &(c + 1))],
            ),
        };
        let list = |items: &[String]| items.join(lang.t("answer-list-separator"));
        let tolerance = expect.tolerance_words(lang);
        match self {
            Self::Right => lang.t_with("answer-right", &[("tolerance", &tolerance)]),
            Self::Empty(cells) => {
                let cells: Vec<String> = cells.iter().map(|&at| cell(at)).collect();
                lang.t_with("answer-still-empty", &[("cells", &list(&cells))])
            }
            Self::Unreadable { at, text, why } => lang.t_with(
                "answer-not-a-number",
                &[
                    ("cell", &cell(*at)),
                    ("text", text),
                    ("why", &why.words(lang)),
                ],
            ),
            Self::Off(misses) => {
                let each: Vec<String> = misses
                    .iter()
                    .map(|m| {
                        let by = num(m.off_by.abs());
                        lang.t_with(
                            if m.off_by > 0.0 {
                                "answer-too-large"
                            } else {
                                "answer-too-small"
                            },
                            &[("cell", &cell(m.at)), ("typed", &num(m.typed)), ("by", &by)],
                        )
                    })
                    .collect();
                lang.t_with(
                    "answer-not-yet",
                    &[
                        ("off", &misses.len()),
                        ("entries", &expect.values.len()),
                        ("tolerance", &tolerance),
                        ("each", &list(&each)),
                    ],
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reasons_are_worded_in_the_interface_s_language() {
        use crate::vocabulary::Lang;
        let e = Expect {
            shape: Shape::Number,
            values: vec![1.0],
            tolerance: 0.001,
            names: Vec::new(),
        };
        let v = e.check(&["(1".to_owned()]);
        let zh = v.describe(&e, Lang::ZH);
        assert!(zh.contains("没有闭合"), "{zh}");
        assert!(
            !zh.contains("is not"),
            "English in the Chinese message: {zh}"
        );
    }

    /// Several numbers typed into one box are spread over the empty boxes after it (`2 0.5
    /// -0.5` was read as 20); where the boxes after it are filled, the box is refused with
    /// that reason. An expression with spaces is still one value.
    #[test]
    fn several_numbers_in_one_box_are_spread_or_refused() {
        let e = Expect {
            shape: Shape::Vector(3),
            values: vec![2.0, 0.5, -0.5],
            tolerance: 0.001,
            names: Vec::new(),
        };
        let typed = |cells: [&str; 3]| cells.map(str::to_owned).to_vec();
        assert_eq!(e.check(&typed(["2 0.5 -0.5", "", ""])), Verdict::Right);
        assert_eq!(e.check(&typed(["2, 0.5; -0.5", "", ""])), Verdict::Right);
        assert_eq!(e.check(&typed(["2", "0.5 -0.5", ""])), Verdict::Right);
        assert!(matches!(
            e.check(&typed(["2 0.5", "0.5", "-0.5"])),
            Verdict::Unreadable {
                at: (0, 0),
                why: Unreadable::Several,
                ..
            }
        ));
        // One value each, written with spaces and a decimal comma.
        assert_eq!(e.check(&typed(["1 + 1", "0,5", "- 0.5"])), Verdict::Right);
    }

    /// A vector's entry that is off is named as its box is, x, y or z: 2.5 typed for y = 2 is
    /// 0.5 too large.
    #[test]
    fn a_vectors_entry_is_named_as_its_box() {
        use crate::vocabulary::Lang;
        let e = Expect {
            shape: Shape::Vector(3),
            values: vec![1.0, 2.0, 3.0],
            tolerance: 0.01,
            names: Vec::new(),
        };
        let typed = |cells: [&str; 3]| cells.map(str::to_owned).to_vec();
        let v = e.check(&typed(["1", "2.5", "3"]));
        assert!(
            v.describe(&e, Lang::EN)
                .contains("y = 2.5 is 0.5 too large")
        );
        assert!(v.describe(&e, Lang::ZH).contains("y 分量 = 2.5 大了 0.5"));
        let empty = e.check(&typed(["1", "2", ""]));
        assert!(empty.describe(&e, Lang::EN).contains("Still empty: z."));
    }

    /// A whole verdict as a student reads it, in both languages (written by hand).
    #[test]
    fn a_matrix_verdict_reads_as_a_sentence() {
        use crate::vocabulary::Lang;
        let e = Expect {
            shape: Shape::Matrix(2, 2),
            values: vec![1.0, 0.0, 0.0, 1.0],
            tolerance: 0.01,
            names: Vec::new(),
        };
        let typed = |cells: [&str; 4]| cells.map(str::to_owned).to_vec();
        let v = e.check(&typed(["1", "0.5", "0", "0.5"]));
        assert_eq!(
            v.describe(&e, Lang::EN),
            "Not yet (2 of 4 off, tolerance ±0.01): row 1, column 2 = 0.5 is 0.5 too large; \
             row 2, column 2 = 0.5 is 0.5 too small."
        );
        assert_eq!(
            v.describe(&e, Lang::ZH),
            "还不对（4 项中有 2 项超出 ±0.01）：第 1 行第 2 列 = 0.5 大了 0.5；第 2 行第 2 列 = 0.5 小了 0.5。"
        );
        let empty = e.check(&typed(["1", "", "0", ""]));
        assert_eq!(
            empty.describe(&e, Lang::EN),
            "Still empty: row 1, column 2; row 2, column 2."
        );
        assert_eq!(
            e.check(&typed(["1", "0", "0", "1"])).describe(&e, Lang::ZH),
            "正确：每一项都在 ±0.01 之内。"
        );
    }

    /// Lesson 10 step 4's 0.8^32 = 0.000792 with the step's ±0.005: 0 is not right for it (it
    /// was), two significant digits are; a larger entry keeps the lesson's tolerance.
    #[test]
    fn a_small_answer_is_checked_relative_to_itself() {
        let e = Expect {
            shape: Shape::Vector(2),
            values: vec![0.000792, 0.185302],
            tolerance: 0.005,
            names: Vec::new(),
        };
        let typed = |cells: [&str; 2]| cells.map(str::to_owned).to_vec();
        assert!(matches!(e.check(&typed(["0", "0.185"])), Verdict::Off(m) if m.len() == 1));
        assert_eq!(e.check(&typed(["0.00079", "0.187"])), Verdict::Right);
        assert_eq!(e.check(&typed(["0.0008", "0.19"])), Verdict::Right);
        assert!(matches!(
            e.check(&typed(["0.0008", "0.191"])),
            Verdict::Off(_)
        ));
        assert_eq!(e.tolerance_at(0.0), 0.005);
        assert!(
            e.tolerance_words(crate::vocabulary::Lang::EN)
                .contains("an entry under 0.1 within 5 % of itself")
        );
    }

    #[test]
    fn a_verdict_names_the_entries_off_and_by_how_much() {
        let e = Expect {
            shape: Shape::Matrix(2, 2),
            values: vec![1.0, 0.0, 0.0, 0.5],
            tolerance: 0.01,
            names: Vec::new(),
        };
        let typed = |cells: [&str; 4]| cells.map(str::to_owned).to_vec();
        assert_eq!(e.check(&typed(["1", "0", "0", "1/2"])), Verdict::Right);
        assert_eq!(
            e.check(&typed(["1.005", "0", "-0.009", ".5"])),
            Verdict::Right
        );
        assert_eq!(
            e.check(&typed(["1", "", "0", " "])),
            Verdict::Empty(vec![(0, 1), (1, 1)])
        );
        let Verdict::Off(misses) = e.check(&typed(["1", "0", "0.25", "0.7"])) else {
            panic!("two entries are off");
        };
        assert_eq!(misses.len(), 2);
        assert_eq!((misses[0].at, misses[1].at), ((1, 0), (1, 1)));
        assert!((misses[1].off_by - 0.2).abs() < 1e-12);
        assert!(matches!(
            e.check(&typed(["1", "0", "x", "1"])),
            Verdict::Unreadable { at: (1, 0), .. }
        ));
    }
}
