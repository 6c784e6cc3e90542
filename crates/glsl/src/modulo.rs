//! `%` between an integer vector and a scalar (`ivec2 p % 16`, `7 % uvec3 q`): valid GLSL 3.30
//! (§5.9: the scalar applies to each component) that naga's GLSL front end passes on without
//! the splat it writes for `+ − / & | ^ << >>`, so naga's validator refuses it ("Operation
//! Modulo can't work with …"). naga's typifier finds each such operand in the parsed module,
//! the text is rewritten with the scalar made a vector (`p % ivec2(16)`), and naga reads it
//! again; every insertion is an [`Edit`], so a message still maps to the student's column.

use std::ops::Range;

use naga::{BinaryOperator, Expression, ScalarKind, TypeInner};

use super::dialect::Adapted;
use super::lowering::Edit;

impl Adapted {
    /// The text with each of `operands` — a scalar beside an integer vector under `%`, at its
    /// place in [`Self::text`] — made that vector.
    pub(super) fn splat_modulo_operands(&mut self, operands: &[(Range<usize>, String)]) {
        let (text, splats) = wrap(&self.text, self.preamble_len, operands);
        self.text = text;
        self.splats = splats;
    }
}

/// The scalar operands of `%` beside an integer vector in `module`: where each is in the text
/// naga read, and the vector type it becomes (`ivec2`).
#[must_use]
pub fn scalar_operands(module: &naga::Module) -> Vec<(Range<usize>, String)> {
    let functions = module
        .functions
        .iter()
        .map(|(_, f)| f)
        .chain(module.entry_points.iter().map(|e| &e.function));
    let mut out = Vec::new();
    for f in functions {
        let ctx = naga::proc::ResolveContext::with_locals(module, &f.local_variables, &f.arguments);
        let mut types = naga::front::Typifier::new();
        let Some((last, _)) = f.expressions.iter().last() else {
            continue;
        };
        if types.grow(last, &f.expressions, &ctx).is_err() {
            continue;
        }
        for (_, e) in f.expressions.iter() {
            let Expression::Binary {
                op: BinaryOperator::Modulo,
                left,
                right,
            } = *e
            else {
                continue;
            };
            let (l, r) = (
                types.get(left, &module.types),
                types.get(right, &module.types),
            );
            let (scalar, vector) = match (l, r) {
                (&TypeInner::Vector { size, scalar }, &TypeInner::Scalar(_)) => {
                    (right, (size, scalar))
                }
                (&TypeInner::Scalar(_), &TypeInner::Vector { size, scalar }) => {
                    (left, (size, scalar))
                }
                _ => continue,
            };
            let prefix = match vector.1.kind {
                ScalarKind::Sint => "ivec",
                ScalarKind::Uint => "uvec",
                // `%` on floats is refused later with GLSL's reason.
                _ => continue,
            };
            if let Some(span) = f.expressions.get_span(scalar).to_range() {
                out.push((span, format!("{prefix}{}", vector.0 as u8)));
            }
        }
    }
    out
}

/// `module`, or — when it has a scalar beside an integer vector under `%` — the module naga
/// reads from `adapted` with each such scalar made a vector, `adapted` rewritten to match. If
/// that reading fails, `module` stands (and the validator's message about it).
pub(super) fn read_again_splatted(
    module: naga::Module,
    adapted: &mut Adapted,
    options: &naga::front::glsl::Options,
) -> naga::Module {
    let operands = scalar_operands(&module);
    if operands.is_empty() {
        return module;
    }
    let mut rewritten = adapted.clone();
    rewritten.splat_modulo_operands(&operands);
    match naga::front::glsl::Frontend::default().parse(options, &rewritten.text) {
        Ok(m) => {
            *adapted = rewritten;
            m
        }
        Err(_) => module,
    }
}

/// `text` with each operand of `operands` (offsets in `text`, past `from`) wrapped in its
/// vector's constructor, and the insertions as edits of the text after `from`.
#[must_use]
pub fn wrap(text: &str, from: usize, operands: &[(Range<usize>, String)]) -> (String, Vec<Edit>) {
    let mut inserts: Vec<(usize, String)> = operands
        .iter()
        .filter(|(span, _)| span.start >= from && span.end <= text.len())
        .flat_map(|(span, ty)| [(span.start, format!("{ty}(")), (span.end, ")".to_owned())])
        .collect();
    // At one offset a closing parenthesis goes before an opening one.
    inserts.sort_by_key(|(at, s)| (*at, s != ")"));
    let mut out = String::with_capacity(text.len() + inserts.len() * 8);
    let mut edits = Vec::new();
    let mut copied = 0;
    for (at, s) in inserts {
        out.push_str(&text[copied..at]);
        copied = at;
        let new = out.len() - from;
        out.push_str(&s);
        edits.push(Edit {
            new: new..out.len() - from,
            old: at - from..at - from,
        });
    }
    out.push_str(&text[copied..]);
    (out, edits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operands_are_wrapped_and_offsets_map_back() {
        let text = "ab p % 16 + q % k;";
        let (out, edits) = wrap(text, 3, &[(7..9, "ivec2".into()), (16..17, "uvec3".into())]);
        assert_eq!(out, "ab p % ivec2(16) + q % uvec3(k);");
        // Past the preamble (3 bytes): `1` of 16 is at 10 in the new text, 7 + 3 before.
        let back = |at: usize| super::super::lowering::before_edits(&edits, at - 3) + 3;
        let find = |s: &str| out.find(s).expect("in the rewritten text");
        assert_eq!(back(find("16")), 7);
        assert_eq!(back(find(" + ")), 9);
        assert_eq!(back(find("(k)") + 1), 16);
        // Inside an insertion: where it was inserted.
        assert_eq!(back(find("ivec2")), 7);
    }
}
