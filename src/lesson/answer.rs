//! Answers the student types: a question's expected value (`expect = …`: a number, a vector or
//! a matrix) with its tolerance, what the student typed read cell by cell (numbers, or small
//! expressions such as `sqrt(3)/2` or `2*pi/3`), and the verdict — right, or which entries are
//! off and by how much. Nothing is graded by a hidden rule: the tolerance is shown beside the
//! field.

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
        why: String,
    },
    /// The entries that are off, in reading order.
    Off(Vec<Miss>),
}

impl Expect {
    /// Checks what the student typed, one string per cell row by row (a missing string counts
    /// as an empty cell).
    #[must_use]
    pub fn check(&self, typed: &[String]) -> Verdict {
        let (_, cols) = self.shape.size();
        let at = |i: usize| (i / cols, i % cols);
        let cell = |i: usize| typed.get(i).map_or("", |s| s.trim());
        let empty: Vec<_> = (0..self.values.len())
            .filter(|&i| cell(i).is_empty())
            .map(at)
            .collect();
        if !empty.is_empty() {
            return Verdict::Empty(empty);
        }
        let mut misses = Vec::new();
        for (i, &expected) in self.values.iter().enumerate() {
            let value = match evaluate(cell(i)) {
                Ok(v) => v,
                Err(why) => {
                    return Verdict::Unreadable {
                        at: at(i),
                        text: cell(i).to_owned(),
                        why,
                    };
                }
            };
            if (value - expected).abs() > self.tolerance {
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

/// The value of a typed cell: a number (`0.5`, `-1e-3`, `.5`), or an expression of numbers,
/// `pi` (`π`), `+ − * / ^`, parentheses and `sqrt(…)` (`√…`): what a student writes for
/// `√3/2` or `2π/3`. A comma is read as a decimal point (`0,5`).
///
/// # Errors
/// What cannot be read, in words.
pub fn evaluate(text: &str) -> Result<f64, String> {
    let text = text.replace(',', ".").replace('−', "-").replace('×', "*");
    let mut p = Parser {
        chars: text.chars().filter(|c| !c.is_whitespace()).collect(),
        at: 0,
    };
    let v = p.sum()?;
    if p.at < p.chars.len() {
        return Err(format!("unexpected `{}`", p.chars[p.at]));
    }
    if v.is_finite() {
        Ok(v)
    } else {
        Err("not a finite number".to_owned())
    }
}

/// A recursive-descent reader of [`evaluate`]'s expressions.
struct Parser {
    chars: Vec<char>,
    at: usize,
}

impl Parser {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    fn eat(&mut self, c: char) -> bool {
        let found = self.peek() == Some(c);
        self.at += usize::from(found);
        found
    }

    /// sum = product (('+' | '-') product)*
    fn sum(&mut self) -> Result<f64, String> {
        let mut v = self.product()?;
        loop {
            if self.eat('+') {
                v += self.product()?;
            } else if self.eat('-') {
                v -= self.product()?;
            } else {
                return Ok(v);
            }
        }
    }

    /// product = power (('*' | '/') power)*
    fn product(&mut self) -> Result<f64, String> {
        let mut v = self.power()?;
        loop {
            if self.eat('*') || self.eat('·') {
                v *= self.power()?;
            } else if self.eat('/') {
                v /= self.power()?;
            } else {
                return Ok(v);
            }
        }
    }

    /// power = unary ('^' power)?
    fn power(&mut self) -> Result<f64, String> {
        let base = self.unary()?;
        if self.eat('^') {
            Ok(base.powf(self.power()?))
        } else {
            Ok(base)
        }
    }

    /// unary = '-' unary | '+' unary | atom (an atom may follow a number: `2pi`, `2sqrt(3)`)
    fn unary(&mut self) -> Result<f64, String> {
        if self.eat('-') {
            return Ok(-self.unary()?);
        }
        if self.eat('+') {
            return self.unary();
        }
        let v = self.atom()?;
        if matches!(self.peek(), Some('p' | 'π' | 's' | '√' | '(')) {
            return Ok(v * self.atom()?);
        }
        Ok(v)
    }

    fn atom(&mut self) -> Result<f64, String> {
        let rest: String = self.chars[self.at..].iter().collect();
        if self.eat('(') {
            let v = self.sum()?;
            return if self.eat(')') {
                Ok(v)
            } else {
                Err("a `(` is not closed".to_owned())
            };
        }
        if self.eat('π')
            || rest.starts_with("pi") && {
                self.at += 2;
                true
            }
        {
            return Ok(std::f64::consts::PI);
        }
        if self.eat('√')
            || rest.starts_with("sqrt") && {
                self.at += 4;
                true
            }
        {
            return Ok(self.atom()?.sqrt());
        }
        let start = self.at;
        while let Some(c) = self.peek() {
            let exponent = matches!(c, '+' | '-')
                && matches!(self.chars.get(self.at.wrapping_sub(1)), Some('e' | 'E'));
            if c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E') || exponent {
                self.at += 1;
            } else {
                break;
            }
        }
        let number: String = self.chars[start..self.at].iter().collect();
        if number.is_empty() {
            return Err(match self.peek() {
                Some(c) => format!("unexpected `{c}`"),
                None => "a number is missing at the end".to_owned(),
            });
        }
        number
            .parse()
            .map_err(|_| format!("`{number}` is not a number"))
    }
}

impl Verdict {
    /// The verdict in words, for the student: right; or each entry off, with what was typed
    /// and by how much it is too large or too small; or which cells are empty or unreadable.
    #[must_use]
    pub fn describe(&self, expect: &Expect, lang: crate::vocabulary::Lang) -> String {
        use crate::vocabulary::Lang;
        let num = |v: f64| crate::vocabulary::short(v as f32, 4);
        let cell = |(r, c): (usize, usize)| match (expect.shape, lang) {
            (Shape::Number, Lang::En) => "your value".to_owned(),
            (Shape::Number, Lang::Zh) => "你的数值".to_owned(),
            (Shape::Vector(_), Lang::En) => format!("component {}", c + 1),
            (Shape::Vector(_), Lang::Zh) => format!("第 {} 个分量", c + 1),
            (Shape::Matrix(..), Lang::En) => format!("row {}, column {}", r + 1, c + 1),
            (Shape::Matrix(..), Lang::Zh) => format!("第 {} 行第 {} 列", r + 1, c + 1),
        };
        let tolerance = num(expect.tolerance);
        match self {
            Self::Right => {
                lang.tr("Right: every entry within ±", "正确：每一项都在 ±")
                    .to_owned()
                    + &tolerance
                    + lang.tr(" of the answer.", " 之内。")
            }
            Self::Empty(cells) => {
                let list: Vec<String> = cells.iter().map(|&at| cell(at)).collect();
                match lang {
                    Lang::En => format!("Still empty: {}.", list.join("; ")),
                    Lang::Zh => format!("尚未填写：{}。", list.join("；")),
                }
            }
            Self::Unreadable { at, text, why } => match lang {
                Lang::En => format!("{}: \"{text}\" is not a number ({why}).", cell(*at)),
                Lang::Zh => format!("{}：“{text}”不是数值（{why}）。", cell(*at)),
            },
            Self::Off(misses) => {
                let each: Vec<String> = misses
                    .iter()
                    .map(|m| {
                        let by = num(m.off_by.abs());
                        match (lang, m.off_by > 0.0) {
                            (Lang::En, true) => {
                                format!("{} = {} is {by} too large", cell(m.at), num(m.typed))
                            }
                            (Lang::En, false) => {
                                format!("{} = {} is {by} too small", cell(m.at), num(m.typed))
                            }
                            (Lang::Zh, true) => {
                                format!("{} = {} 大了 {by}", cell(m.at), num(m.typed))
                            }
                            (Lang::Zh, false) => {
                                format!("{} = {} 小了 {by}", cell(m.at), num(m.typed))
                            }
                        }
                    })
                    .collect();
                match lang {
                    Lang::En => format!(
                        "Not yet ({} of {} off, tolerance ±{tolerance}): {}.",
                        misses.len(),
                        expect.values.len(),
                        each.join("; ")
                    ),
                    Lang::Zh => format!(
                        "还不对（{} 项中有 {} 项超出 ±{tolerance}）：{}。",
                        expect.values.len(),
                        misses.len(),
                        each.join("；")
                    ),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typed_numbers_and_expressions_are_read() {
        let close = |t: &str, v: f64| {
            let got = evaluate(t).unwrap_or_else(|e| panic!("{t}: {e}"));
            assert!((got - v).abs() < 1e-12, "{t} = {got}, not {v}");
        };
        close("0.64", 0.64);
        close(" -1e-3 ", -0.001);
        close(".5", 0.5);
        close("0,5", 0.5);
        close("sqrt(3)/2", 3f64.sqrt() / 2.0);
        close("√3/2", 3f64.sqrt() / 2.0);
        close("2pi/3", 2.0 * std::f64::consts::PI / 3.0);
        close("2*π/3", 2.0 * std::f64::consts::PI / 3.0);
        close("-(1+2)*3", -9.0);
        close("2^3^2", 512.0);
        close("1 − 0.25", 0.75);
        for bad in ["", "abc", "1/", "(1+2", "1..2", "1/0"] {
            assert!(evaluate(bad).is_err(), "{bad:?} was read");
        }
    }

    #[test]
    fn a_verdict_names_the_entries_off_and_by_how_much() {
        let e = Expect {
            shape: Shape::Matrix(2, 2),
            values: vec![1.0, 0.0, 0.0, 0.5],
            tolerance: 0.01,
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
