//! What a step asks of the student, checked when the lesson is read: `expect = …` and
//! `tolerance`, the value its question asks to type; `exercise = { … }`, code to write.

use crate::lesson::folder::Folder;

use toml::Spanned;

use super::super::answer::{
    Compare, DEFAULT_TOLERANCE, EXERCISE_TOLERANCE, Exercise, Expect, Quantity, Shape,
};
use super::super::raw::{RawExercise, RawExpect, RawStep};
use super::super::validate::Checker;

impl Checker<'_> {
    /// A step's `expect` and `tolerance`: a finite number, a vector of 2–4 or a matrix of 2–4
    /// rows of 2–4, for a question the step asks; a positive tolerance, only beside `expect`.
    pub(super) fn expect(&mut self, r: &RawStep) -> Option<Expect> {
        let tolerance = match &r.tolerance {
            Some(t) if r.expect.is_none() => {
                self.error(t.span(), "`tolerance` belongs beside an `expect` value");
                return None;
            }
            Some(t) if !(t.get_ref().is_finite() && *t.get_ref() > 0.0) => {
                self.error(
                    t.span(),
                    format!("`tolerance` must be a positive number, got {}", t.get_ref()),
                );
                DEFAULT_TOLERANCE
            }
            Some(t) => *t.get_ref(),
            None => DEFAULT_TOLERANCE,
        };
        if let (Some(n), None) = (&r.expect_names, &r.expect) {
            self.error(n.span(), "`expect_names` belongs beside an `expect` value");
            return None;
        }
        let e = r.expect.as_ref()?;
        if r.question.is_none() {
            self.error(e.span(), "`expect` needs a `question` in the same step: it is the value that question asks for");
            return None;
        }
        let (shape, values) = match e.get_ref() {
            RawExpect::Number(x) => (Shape::Number, vec![*x]),
            RawExpect::Vector(v) => (Shape::Vector(v.len()), v.clone()),
            RawExpect::Matrix(rows) => {
                let cols = rows.first().map_or(0, Vec::len);
                if rows.iter().any(|row| row.len() != cols) {
                    self.error(
                        e.span(),
                        "every row of an `expect` matrix needs as many numbers as the first",
                    );
                    return None;
                }
                (Shape::Matrix(rows.len(), cols), rows.concat())
            }
        };
        let (rows, cols) = shape.size();
        let fits = |n: usize| (2..=4).contains(&n);
        if shape != Shape::Number && !(fits(cols) && (rows == 1 || fits(rows))) {
            self.error(
                e.span(),
                format!("an `expect` vector has 2 to 4 numbers and a matrix 2 to 4 rows of 2 to 4; this one is {rows}×{cols}"),
            );
            return None;
        }
        if values.iter().any(|v| !v.is_finite() || v.abs() > 1e15) {
            self.error(
                e.span(),
                "`expect` needs finite numbers of magnitude at most 1e15",
            );
            return None;
        }
        let names = self.expect_names(r, shape, values.len());
        Some(Expect {
            shape,
            values,
            tolerance,
            names,
        })
    }

    /// A step's `expect_names`: one short name per entry of a vector or matrix, as its boxes
    /// show them (`["top", "right"]`, `["r·v", "n·h"]`); none for a lone number, which is
    /// "your value".
    fn expect_names(&mut self, r: &RawStep, shape: Shape, entries: usize) -> Vec<String> {
        let Some(n) = &r.expect_names else {
            return Vec::new();
        };
        let names = n.get_ref();
        let problem = if shape == Shape::Number {
            Some(
                "`expect_names` names the entries of a vector or matrix; a single value needs none"
                    .to_owned(),
            )
        } else if names.len() != entries {
            Some(format!(
                "`expect_names` needs one name per entry of `expect`: {entries}, got {}",
                names.len()
            ))
        } else {
            names
                .iter()
                .find(|x| x.trim().is_empty() || x.chars().count() > 12)
                .map(|bad| format!(
                    "each of `expect_names` is a short name of 1 to 12 characters that fits its box, got \"{bad}\""
                ))
        };
        if let Some(p) = problem {
            self.error(n.span(), p);
            return Vec::new();
        }
        names.iter().map(|x| x.trim().to_owned()).collect()
    }

    /// A step's `exercise`: the task in both languages, a starter that compiles (its messages
    /// point into the lesson or the shader's file), a tolerance of 0 to 255 colour steps.
    pub(super) fn exercise(&mut self, e: &Spanned<RawExercise>, base: &Folder) -> Option<Exercise> {
        let r = e.get_ref();
        let task = self.text_of("task", &r.task);
        let starter = super::super::validate::shaders::shader(self, &r.starter, base)?;
        let tolerance = match &r.tolerance {
            Some(t) if !(0.0..=255.0).contains(t.get_ref()) => {
                self.error(
                    t.span(),
                    format!(
                        "an exercise's `tolerance` is in colour steps, 0 to 255; got {}",
                        t.get_ref()
                    ),
                );
                EXERCISE_TOLERANCE
            }
            Some(t) => *t.get_ref() as f32,
            None => EXERCISE_TOLERANCE,
        };
        let forbid = self.forbid(r);
        let compare = self.compare(r, &starter);
        Some(Exercise {
            task,
            starter,
            tolerance,
            forbid,
            compare,
        })
    }

    /// An exercise's `compare`: a value the starter's fragment shader writes or returns, and one
    /// of pipelens' quantities.
    fn compare(
        &mut self,
        r: &RawExercise,
        starter: &pipeline::scene::StudentCode,
    ) -> Option<Compare> {
        let c = r.compare.as_ref()?;
        let raw = c.get_ref();
        let Some(pipelens) = Quantity::from_key(&raw.pipelens) else {
            let keys: Vec<_> = Quantity::KEYS
                .iter()
                .map(|(k, _)| format!("`{k}`"))
                .collect();
            self.error(
                c.span(),
                format!(
                    "`compare.pipelens` is one of {}; got `{}`",
                    keys.join(", "),
                    raw.pipelens
                ),
            );
            return None;
        };
        let name = raw.yours.trim_end_matches("()");
        let fragment = starter
            .shader
            .as_ref()
            .map(|s| s.programs.fragment.source.as_str())
            .unwrap_or_default();
        if name.is_empty() || !crate::lesson::forbid::names(fragment).contains(name) {
            self.error(
                c.span(),
                format!(
                    "`compare.yours` names `{}`, which the starter's fragment shader does not have",
                    raw.yours
                ),
            );
            return None;
        }
        Some(Compare {
            yours: raw.yours.clone(),
            pipelens,
        })
    }

    /// An exercise's `forbid`: GLSL names.
    fn forbid(&mut self, r: &RawExercise) -> Vec<String> {
        let Some(f) = &r.forbid else {
            return Vec::new();
        };
        let names = f.get_ref().clone();
        for n in &names {
            let ident = n
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            if !ident {
                self.error(
                    f.span(),
                    format!("`forbid` lists GLSL names (uniforms or functions); `{n}` is not one"),
                );
                return Vec::new();
            }
        }
        names
    }
}
