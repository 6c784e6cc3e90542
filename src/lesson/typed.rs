//! What a student types into an answer's cell, read: a number or a small expression (`√3/2`,
//! `2π/3`, `cot(22.5°)`, `log2(8)`), full-width forms from a Chinese input method, and several
//! numbers typed into one box spread over the boxes after it; or why it cannot be read, in the
//! interface's language.

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
pub(super) fn spread(typed: &[String], n: usize) -> Result<Vec<String>, usize> {
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

/// Why a typed cell cannot be read: worded in the interface's language by
/// [`super::answer::Verdict::describe`].
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
        match self {
            Self::Unexpected(c) => lang.t_with("typed-unexpected", &[("what", c)]),
            Self::Unclosed => lang.t("typed-unclosed").to_owned(),
            Self::MissingAtEnd => lang.t("typed-missing-at-end").to_owned(),
            Self::NotANumber(t) => lang.t_with("typed-not-a-number", &[("what", t)]),
            Self::UnknownName(t) => lang.t_with("typed-unknown-name", &[("what", t)]),
            Self::NotFinite => lang.t("typed-not-finite").to_owned(),
            Self::Several => lang.t("typed-several").to_owned(),
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

/// A function a typed cell may call: its name and what it does to its argument.
type Function = (&'static str, fn(f64) -> f64);

/// The functions a typed cell may call.
const FUNCTIONS: [Function; 13] = [
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

    /// Why a typed box is not read, in both languages (written by hand).
    #[test]
    fn an_unreadable_box_says_why_in_both_languages() {
        use crate::vocabulary::Lang;
        assert_eq!(
            Unreadable::NotANumber("1..2".into()).words(Lang::EN),
            "`1..2` is not a number"
        );
        assert_eq!(
            Unreadable::NotANumber("1..2".into()).words(Lang::ZH),
            "`1..2` 不是数"
        );
        assert_eq!(Unreadable::Unexpected('#').words(Lang::ZH), "不应出现 `#`");
        assert_eq!(Unreadable::Unclosed.words(Lang::EN), "a `(` is not closed");
    }
}
