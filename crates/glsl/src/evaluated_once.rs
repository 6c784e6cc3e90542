//! Which of a function's expressions are evaluated once, when the function's invariants are
//! (before any lane runs), rather than only where its body emits them: those no `Emit` covers
//! (naga emits no constant), and those naga's own constness tracker
//! ([`naga::proc::ExpressionKindTracker`]) finds constant — a local's initial value among them:
//! naga emits `mat4(1.0)` in `mat4 m = mat4(1.0);`, but the function's entry copies it into `m`
//! before the body runs, so it must be ready then. A constant evaluated early is evaluated
//! again where it is emitted, to the same value.

use naga::Statement;
use naga::proc::ExpressionKindTracker;

/// For each of `f`'s expressions (by handle index), whether it is evaluated once up front.
pub(super) fn evaluated_once(f: &naga::Function) -> Vec<bool> {
    let mut emitted = vec![false; f.expressions.len()];
    mark_emitted(&f.body, &mut emitted);
    let constness = ExpressionKindTracker::from_arena(&f.expressions);
    f.expressions
        .iter()
        .map(|(h, _)| !emitted[h.index()] || constness.is_const(h))
        .collect()
}

/// Marks every expression some `Emit` covers.
fn mark_emitted(block: &naga::Block, emitted: &mut [bool]) {
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
