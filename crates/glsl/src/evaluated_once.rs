//! Which of a function's expressions its body evaluates where they are emitted, and which are
//! constants, evaluated once before any lane runs: those no `Emit` covers, and a local's initial
//! value with what it is made of (naga emits `mat4(1.0)` in `mat4 m = mat4(1.0);`, but the
//! function's entry copies it into `m` before the body runs).

use naga::{Expression, Handle, Statement};

/// Marks constant expression `h` and the expressions it is made of as not emitted, so that they
/// are evaluated once with the function's constants.
pub(super) fn mark_constant(
    expressions: &naga::Arena<Expression>,
    h: Handle<Expression>,
    emitted: &mut [bool],
) {
    emitted[h.index()] = false;
    let operands: Vec<Handle<Expression>> = match expressions[h] {
        Expression::Compose { ref components, .. } => components.clone(),
        Expression::Splat { value, .. } => vec![value],
        Expression::As { expr, .. } | Expression::Unary { expr, .. } => vec![expr],
        Expression::Binary { left, right, .. } => vec![left, right],
        Expression::Swizzle { vector, .. } => vec![vector],
        Expression::AccessIndex { base, .. } => vec![base],
        Expression::Access { base, index } => vec![base, index],
        Expression::Select {
            condition,
            accept,
            reject,
        } => vec![condition, accept, reject],
        Expression::Relational { argument, .. } => vec![argument],
        Expression::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => [Some(arg), arg1, arg2, arg3]
            .into_iter()
            .flatten()
            .collect(),
        _ => Vec::new(),
    };
    for o in operands {
        mark_constant(expressions, o, emitted);
    }
}

/// Marks every expression some `Emit` covers.
pub(super) fn mark_emitted(block: &naga::Block, emitted: &mut [bool]) {
    for s in block.iter() {
        match *s {
            Statement::Emit(ref r) => {
                for i in r.index_range() {
                    emitted[i as usize] = true;
                }
            }
            Statement::Block(ref b) => mark_emitted(b, emitted),
            Statement::If {
                ref accept,
                ref reject,
                ..
            } => {
                mark_emitted(accept, emitted);
                mark_emitted(reject, emitted);
            }
            Statement::Switch { ref cases, .. } => {
                cases.iter().for_each(|c| mark_emitted(&c.body, emitted))
            }
            Statement::Loop {
                ref body,
                ref continuing,
                ..
            } => {
                mark_emitted(body, emitted);
                mark_emitted(continuing, emitted);
            }
            _ => {}
        }
    }
}
