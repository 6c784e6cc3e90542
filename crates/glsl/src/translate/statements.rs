//! naga's statements in register form: a block's statements with their places, and a call's
//! arguments (an `out` or `inout` parameter's by its variable's place).

use naga::valid::FunctionInfo;
use naga::{Expression, Handle, Statement, TypeInner};

use super::translator::{Translator, describe};
use crate::register_form::{Argument, Call, Function, If, Loop, Stmt, Switch, Unsupported};

impl Translator<'_> {
    /// A call's arguments: an `in` parameter's value by its register, an `out` or `inout`
    /// parameter's variable by its place.
    fn arguments(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
        arguments: &[Handle<Expression>],
        func: &Function,
    ) -> Result<Vec<Argument>, String> {
        arguments
            .iter()
            .map(|&a| match *fi[a].ty.inner_with(&self.module.types) {
                TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. } => {
                    self.place(f, fi, a, func).map(Argument::Ref)
                }
                _ => Ok(Argument::Value(func.regs[a.index()])),
            })
            .collect()
    }

    /// A block's statements. One naga made up without a place of its own (the `if (!cond)
    /// break;` it writes for a `for` or `while` condition) takes `around`, the place of the
    /// statement that holds the block, so the trace names the loop's line, not line 1.
    pub(super) fn block(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
        block: &naga::Block,
        func: &Function,
        around: usize,
    ) -> Result<Vec<Stmt>, Unsupported> {
        let mut out = Vec::with_capacity(block.len());
        for (s, span) in block.span_iter() {
            let at = if span.is_defined() {
                self.at(*span)
            } else {
                around
            };
            let err = |what: String| Unsupported {
                at,
                what,
                function: None,
            };
            let reg = |h: Handle<Expression>| func.regs[h.index()];
            out.push(match *s {
                Statement::Emit(ref range) => Stmt::Emit(range.index_range()),
                Statement::Block(ref b) => Stmt::Block(self.block(f, fi, b, func, at)?),
                Statement::If {
                    condition,
                    ref accept,
                    ref reject,
                } => Stmt::If(If {
                    at,
                    c: reg(condition).first,
                    accept: self.block(f, fi, accept, func, at)?,
                    reject: self.block(f, fi, reject, func, at)?,
                    // naga's `if (!cond) break;` for a loop's condition has no place of its own.
                    loop_test: !span.is_defined()
                        && reject.is_empty()
                        && matches!(accept.iter().next(), Some(Statement::Break)),
                }),
                Statement::Switch {
                    selector,
                    ref cases,
                } => {
                    let mut cs = Vec::new();
                    for c in cases {
                        let value = match c.value {
                            naga::SwitchValue::I32(v) => Some(i64::from(v)),
                            naga::SwitchValue::U32(v) => Some(i64::from(v)),
                            naga::SwitchValue::Default => None,
                        };
                        cs.push((value, self.block(f, fi, &c.body, func, at)?, c.fall_through));
                    }
                    Stmt::Switch(Switch {
                        at,
                        selector: reg(selector).first,
                        cases: cs,
                    })
                }
                Statement::Loop {
                    ref body,
                    ref continuing,
                    break_if,
                } => Stmt::Loop(Loop {
                    at,
                    body: self.block(f, fi, body, func, at)?,
                    continuing: self.block(f, fi, continuing, func, at)?,
                    break_if: break_if.map(|b| reg(b).first),
                }),
                Statement::Break => Stmt::Break {
                    at: span.is_defined().then_some(at),
                },
                Statement::Continue => Stmt::Continue { at },
                Statement::Return { value } => Stmt::Return {
                    at: if span.is_defined() {
                        at
                    } else {
                        self.end.get()
                    },
                    value: value.map(reg),
                },
                Statement::Kill => Stmt::Kill { at },
                Statement::Store { pointer, value } => Stmt::Store {
                    at,
                    place: self.place(f, fi, pointer, func).map_err(err)?,
                    value: reg(value).first,
                },
                Statement::Call {
                    function,
                    ref arguments,
                    result,
                } => Stmt::Call(Call {
                    at,
                    function: function.index(),
                    args: self.arguments(f, fi, arguments, func).map_err(err)?,
                    result: result.map(reg),
                }),
                Statement::ControlBarrier(_) | Statement::MemoryBarrier(_) => continue,
                ref other => {
                    return Err(err(format!(
                        "a statement pipelens does not run ({})",
                        describe(other)
                    )));
                }
            });
        }
        Ok(out)
    }
}
