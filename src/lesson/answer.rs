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
        use crate::vocabulary::Lang;
        let t = crate::vocabulary::short(self.tolerance as f32, 4);
        let below = crate::vocabulary::short((self.tolerance / RELATIVE_TOLERANCE) as f32, 4);
        let small = self
            .values
            .iter()
            .any(|&e| self.tolerance_at(e) < self.tolerance);
        match (lang, small) {
            (Lang::En, false) => format!("±{t}"),
            (Lang::Zh, false) => format!("±{t}"),
            (Lang::En, true) => format!("±{t}; an entry under {below} within 5 % of itself"),
            (Lang::Zh, true) => format!("±{t}；小于 {below} 的项在其自身的 5% 以内"),
        }
    }

    /// The cells as they are read: several numbers typed into one box spread over it and the
    /// empty boxes after it. `Err(i)`: box `i` holds more numbers than there are empty boxes.
    ///
    /// # Errors
    /// As said.
    pub fn spread(&self, typed: &[String]) -> Result<Vec<String>, usize> {
        spread(typed, self.values.len())
    }

    /// Checks what the student typed, one string per cell row by row (a missing string counts
    /// as an empty cell). Several numbers typed into one box (`2 0.5 -0.5`) are spread over it
    /// and the empty boxes after it; where those are not empty, the box is unreadable.
    #[must_use]
    pub fn check(&self, typed: &[String]) -> Verdict {
        let (_, cols) = self.shape.size();
        let at = |i: usize| (i / cols, i % cols);
        let cells = match spread(typed, self.values.len()) {
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

/// The numbers typed into one box, when it holds several: parts separated by spaces, `;` or
/// `, ` that each read as a number, with no operator between them (`2 0.5 -0.5`, `1; 2`);
/// `None` for a single value or expression (`2 - 0.5`, `2 * pi`).
fn several(text: &str) -> Option<Vec<String>> {
    let text = halfwidth(text);
    let parts: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || c == ';')
        .flat_map(|p| p.split_inclusive(','))
        .map(|p| p.trim_end_matches(','))
        .filter(|p| !p.is_empty())
        .collect();
    // `0,5` is one number with a decimal comma; `0, 5` two.
    let joined_by_comma_only = !text.contains(|c: char| c.is_whitespace() || c == ';');
    (parts.len() > 1 && !joined_by_comma_only && parts.iter().all(|p| evaluate(p).is_ok()))
        .then(|| parts.iter().map(|p| (*p).to_owned()).collect())
}

/// The cells with several numbers typed into one box spread over it and the boxes after it;
/// `Err(i)` when box `i` holds more numbers than there are empty boxes from it on.
fn spread(typed: &[String], n: usize) -> Result<Vec<String>, usize> {
    let mut cells: Vec<String> = (0..n)
        .map(|i| typed.get(i).cloned().unwrap_or_default())
        .collect();
    let mut i = 0;
    while i < n {
        if let Some(parts) = several(&cells[i]) {
            let room = i + parts.len() <= n
                && cells[i + 1..i + parts.len()]
                    .iter()
                    .all(|c| c.trim().is_empty());
            if !room {
                return Err(i);
            }
            for (k, p) in parts.iter().enumerate() {
                cells[i + k].clone_from(p);
            }
            i += parts.len();
        } else {
            i += 1;
        }
    }
    Ok(cells)
}

/// Why a typed cell cannot be read: worded in the interface's language by [`Verdict::describe`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Unreadable {
    /// A character where none can stand.
    Unexpected(char),
    /// A `(` never closed.
    Unclosed,
    /// The text ends where a number should follow.
    MissingAtEnd,
    /// Digits that do not make a number (`1..2`).
    NotANumber(String),
    /// A name that is no function or constant (`tna`).
    UnknownName(String),
    /// The value is infinite or undefined (`1/0`, `sqrt(-1)`).
    NotFinite,
    /// Several numbers in a box with no empty boxes after it to take them.
    Several,
}

impl Unreadable {
    /// The reason in words.
    #[must_use]
    pub fn words(&self, lang: crate::vocabulary::Lang) -> String {
        use crate::vocabulary::Lang;
        match (self, lang) {
            (Self::Unexpected(c), Lang::En) => format!("unexpected `{c}`"),
            (Self::Unexpected(c), Lang::Zh) => format!("不应出现 `{c}`"),
            (Self::Unclosed, Lang::En) => "a `(` is not closed".to_owned(),
            (Self::Unclosed, Lang::Zh) => "有一个 `(` 没有闭合".to_owned(),
            (Self::MissingAtEnd, Lang::En) => "a number is missing at the end".to_owned(),
            (Self::MissingAtEnd, Lang::Zh) => "末尾缺少一个数".to_owned(),
            (Self::NotANumber(t), Lang::En) => format!("`{t}` is not a number"),
            (Self::NotANumber(t), Lang::Zh) => format!("`{t}` 不是数"),
            (Self::UnknownName(t), Lang::En) => format!(
                "`{t}` is not a function pipelens knows: sqrt, sin, cos, tan, cot, asin, acos, atan, ln, log2, log10, exp, deg, pi"
            ),
            (Self::UnknownName(t), Lang::Zh) => format!(
                "pipelens 不认识函数 `{t}`：可用 sqrt、sin、cos、tan、cot、asin、acos、atan、ln、log2、log10、exp、deg、pi"
            ),
            (Self::NotFinite, Lang::En) => "not a finite number".to_owned(),
            (Self::NotFinite, Lang::Zh) => "不是有限的数".to_owned(),
            (Self::Several, Lang::En) => {
                "several numbers in one box: type one number in each box".to_owned()
            }
            (Self::Several, Lang::Zh) => "一个格子里有多个数：请每格填一个数".to_owned(),
        }
    }
}

/// Full-width forms (what a Chinese input method types: `０．５`, `（`, `－`) as their ASCII
/// forms, the ideographic space as a space and the ideographic full stop as a point.
fn halfwidth(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '\u{FF01}'..='\u{FF5E}' => char::from_u32(c as u32 - 0xFEE0).unwrap_or(c),
            '\u{3000}' => ' ',
            '。' => '.',
            c => c,
        })
        .collect()
}

/// The value of a typed cell: a number (`0.5`, `-1e-3`, `.5`), or an expression of numbers,
/// `pi` (`π`), `+ − * / ^`, parentheses, `sqrt(…)` (`√…`), `sin cos tan cot asin acos atan`
/// (radians), `ln log2 log10 exp`, and degrees as `deg(30)` or `30°`: what a student writes for
/// `√3/2`, `2π/3` or `cot(22.5°)`. A comma is read as a decimal point (`0,5`); full-width
/// digits and signs from a Chinese input method are read as their ASCII forms.
///
/// # Errors
/// What cannot be read.
pub fn evaluate(text: &str) -> Result<f64, Unreadable> {
    let text = halfwidth(text)
        .replace(',', ".")
        .replace('−', "-")
        .replace('×', "*");
    let mut p = Parser {
        chars: text.chars().filter(|c| !c.is_whitespace()).collect(),
        at: 0,
    };
    let v = p.sum()?;
    if let Some(c) = p.peek() {
        return Err(Unreadable::Unexpected(c));
    }
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Unreadable::NotFinite)
    }
}

/// A recursive-descent reader of [`evaluate`]'s expressions.
struct Parser {
    chars: Vec<char>,
    at: usize,
}

/// The functions a typed cell may call, by name: what each does to its argument.
const FUNCTIONS: [(&str, fn(f64) -> f64); 13] = [
    ("sqrt", f64::sqrt),
    ("sin", f64::sin),
    ("cos", f64::cos),
    ("tan", f64::tan),
    ("cot", |x| 1.0 / x.tan()),
    ("asin", f64::asin),
    ("acos", f64::acos),
    ("atan", f64::atan),
    ("ln", f64::ln),
    ("log2", f64::log2),
    ("log10", f64::log10),
    ("exp", f64::exp),
    ("deg", f64::to_radians),
];

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
    fn sum(&mut self) -> Result<f64, Unreadable> {
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
    fn product(&mut self) -> Result<f64, Unreadable> {
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
    fn power(&mut self) -> Result<f64, Unreadable> {
        let base = self.unary()?;
        if self.eat('^') {
            Ok(base.powf(self.power()?))
        } else {
            Ok(base)
        }
    }

    /// unary = '-' unary | '+' unary | atom '°'? (an atom may follow a number: `2pi`,
    /// `2sqrt(3)`)
    fn unary(&mut self) -> Result<f64, Unreadable> {
        if self.eat('-') {
            return Ok(-self.unary()?);
        }
        if self.eat('+') {
            return self.unary();
        }
        let mut v = self.atom()?;
        if self
            .peek()
            .is_some_and(|c| c == 'π' || c == '√' || c == '(' || c.is_ascii_alphabetic())
        {
            v *= self.atom()?;
        }
        if self.eat('°') {
            v = v.to_radians();
        }
        Ok(v)
    }

    fn atom(&mut self) -> Result<f64, Unreadable> {
        if self.eat('(') {
            let v = self.sum()?;
            return if self.eat(')') {
                Ok(v)
            } else {
                Err(Unreadable::Unclosed)
            };
        }
        if self.eat('π') {
            return Ok(std::f64::consts::PI);
        }
        if self.eat('√') {
            return Ok(self.atom()?.sqrt());
        }
        if self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            let start = self.at;
            while self.peek().is_some_and(|c| c.is_ascii_alphanumeric()) {
                self.at += 1;
            }
            let name: String = self.chars[start..self.at].iter().collect();
            let lower = name.to_ascii_lowercase();
            if lower == "pi" {
                return Ok(std::f64::consts::PI);
            }
            return match FUNCTIONS.iter().find(|(n, _)| *n == lower) {
                Some((_, f)) => Ok(f(self.atom()?)),
                None => Err(Unreadable::UnknownName(name)),
            };
        }
        let start = self.at;
        while let Some(c) = self.peek() {
            let exponent = matches!(c, '+' | '-')
                && matches!(self.chars.get(self.at.wrapping_sub(1)), Some('e' | 'E'));
            let mark = matches!(c, 'e' | 'E')
                && self
                    .chars
                    .get(self.at + 1)
                    .is_some_and(|n| n.is_ascii_digit() || matches!(n, '+' | '-'));
            if c.is_ascii_digit() || c == '.' || mark || exponent {
                self.at += 1;
            } else {
                break;
            }
        }
        let number: String = self.chars[start..self.at].iter().collect();
        if number.is_empty() {
            return Err(match self.peek() {
                Some(c) => Unreadable::Unexpected(c),
                None => Unreadable::MissingAtEnd,
            });
        }
        number.parse().map_err(|_| Unreadable::NotANumber(number))
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
        let tolerance = expect.tolerance_words(lang);
        match self {
            Self::Right => match lang {
                Lang::En => format!("Right: every entry within {tolerance} of the answer."),
                Lang::Zh => format!("正确：每一项都在 {tolerance} 之内。"),
            },
            Self::Empty(cells) => {
                let list: Vec<String> = cells.iter().map(|&at| cell(at)).collect();
                match lang {
                    Lang::En => format!("Still empty: {}.", list.join("; ")),
                    Lang::Zh => format!("尚未填写：{}。", list.join("；")),
                }
            }
            Self::Unreadable { at, text, why } => match lang {
                Lang::En => format!(
                    "{}: \"{text}\" is not a number ({}).",
                    cell(*at),
                    why.words(lang)
                ),
                Lang::Zh => format!("{}：“{text}”不是数值（{}）。", cell(*at), why.words(lang)),
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
                        "Not yet ({} of {} off, tolerance {tolerance}): {}.",
                        misses.len(),
                        expect.values.len(),
                        each.join("; ")
                    ),
                    Lang::Zh => format!(
                        "还不对（{} 项中有 {} 项超出 {tolerance}）：{}。",
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
            let got = evaluate(t).unwrap_or_else(|e| panic!("{t}: {e:?}"));
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
        // A Chinese input method's full-width forms.
        close("０．５", 0.5);
        close("－２／４", -0.5);
        close("（１＋２）＊３", 9.0);
        close("1。25", 1.25);
        // The functions a graphics course writes, by hand: tan 45° = 1, cot 30° = √3,
        // log2 8 = 3, ln e = 1, deg 180 = π.
        close("tan(deg(45))", 1.0);
        close("tan(45°)", 1.0);
        close("cot(30°)", 3f64.sqrt());
        close("1/tan(pi/6)", 3f64.sqrt());
        close("log2(8)", 3.0);
        close("ln(exp(1))", 1.0);
        close("deg(180)", std::f64::consts::PI);
        close("2cos(60°)", 1.0);
        close("2e-3", 0.002);
        assert_eq!(
            evaluate("tna(1)"),
            Err(Unreadable::UnknownName("tna".into()))
        );
        assert_eq!(evaluate("sqrt(-1)"), Err(Unreadable::NotFinite));
    }

    #[test]
    fn reasons_are_worded_in_the_interface_s_language() {
        use crate::vocabulary::Lang;
        let e = Expect {
            shape: Shape::Number,
            values: vec![1.0],
            tolerance: 0.001,
        };
        let v = e.check(&["(1".to_owned()]);
        let zh = v.describe(&e, Lang::Zh);
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

    /// Lesson 10 step 4's 0.8^32 = 0.000792 with the step's ±0.005: 0 is not right for it (it
    /// was), two significant digits are; a larger entry keeps the lesson's tolerance.
    #[test]
    fn a_small_answer_is_checked_relative_to_itself() {
        let e = Expect {
            shape: Shape::Vector(2),
            values: vec![0.000792, 0.185302],
            tolerance: 0.005,
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
            e.tolerance_words(crate::vocabulary::Lang::En)
                .contains("an entry under 0.1 within 5 % of itself")
        );
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
