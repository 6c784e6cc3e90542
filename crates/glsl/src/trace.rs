//! What one invocation did: the machine's events as data ([`Step`], with every value's numbers)
//! at the student's line numbers, and in words, every value written as GLSL writes it
//! (`vec3(0.000, 0.707, 0.707)`).

use naga::TypeInner;

use crate::error::line_column;
use crate::machine::Event;
use crate::program::Program;
use crate::register_form;

/// One line of a trace: where, what happened, and the same in words with the values.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct TraceLine {
    /// Line in the student's source, from 1.
    pub line: usize,
    /// What happened: `n = vec3(0.000, 0.707, 0.707)`, `if: true → then`, `loop: iteration 3`.
    pub text: String,
    /// The value written or returned as GLSL writes it (`vec3(0.000, 0.707, 0.707)`), for words
    /// in another language; `None` for a step that writes none.
    pub value: Option<String>,
    /// What happened, as data: what a program compares (a lab's check), where the text is what
    /// a person reads.
    pub step: Step,
}

/// What one statement of a run did.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Step {
    /// A variable (or a part of one: its whole new value) was written.
    Assign {
        /// The variable.
        name: String,
        /// Its whole new value.
        value: Value,
    },
    /// An `if` chose an arm.
    Branch {
        /// Whether its condition held.
        taken: bool,
    },
    /// A `for` or `while` loop tested its condition.
    LoopTest {
        /// Whether it held: another iteration (else the loop ends).
        holds: bool,
    },
    /// A `break` left the loop.
    Break,
    /// A `continue` went on to the loop's next iteration.
    Continue,
    /// A loop began iteration `k` (from 1).
    Iteration {
        /// Which.
        k: u32,
    },
    /// A function of the student's was called.
    Call {
        /// The function.
        name: String,
    },
    /// It returned, with its value (none for a `void` function).
    Return {
        /// The function.
        name: String,
        /// What it returned.
        value: Option<Value>,
    },
    /// The fragment was thrown away.
    Discard,
}

impl Step {
    /// What this step wrote, with its name: a variable's new value, or a function's return as
    /// `name()` (`level_of_detail()`); `None` for any other step.
    #[must_use]
    pub fn written(&self) -> Option<(String, &Value)> {
        match self {
            Self::Assign { name, value } => Some((name.clone(), value)),
            Self::Return {
                name,
                value: Some(value),
            } => Some((format!("{name}()"), value)),
            _ => None,
        }
    }
}

/// A value of a run: its GLSL type and its scalars in GLSL's order (a matrix column by column,
/// an array element by element, a struct member by member), each as a number (`true` is 1).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Value {
    /// Its type as GLSL spells it (`vec3`, `mat4`, `Light[8]`).
    pub ty: String,
    /// Its scalars.
    pub numbers: Vec<f64>,
}

impl Value {
    /// Whether `self` and `other` are the same value up to rounding: the same type, and each
    /// scalar within `10⁻⁴·(1 + |x|)` — far above what another order of the same operations
    /// gives in `f32`, far below what a wrong formula changes.
    #[must_use]
    pub fn agrees(&self, other: &Self) -> bool {
        self.ty == other.ty
            && self.numbers.len() == other.numbers.len()
            && self
                .numbers
                .iter()
                .zip(&other.numbers)
                .all(|(a, b)| (a - b).abs() <= 1e-4 * (1.0 + a.abs().max(b.abs())))
    }

    /// Its length, for a vector of three floats (a normal left unnormalized shows here).
    #[must_use]
    pub fn length(&self) -> Option<f64> {
        (self.ty == "vec3").then(|| self.numbers.iter().map(|x| x * x).sum::<f64>().sqrt())
    }
}

/// What one invocation did, statement by statement.
pub type Trace = Vec<TraceLine>;

impl Program {
    /// What the traced lane's watch stored, each time it ran the watched line
    /// (`crate::probe`): the number of the student's steps before it (so the value stands at
    /// every step from that index on, until the next), and the value as the watch keeps it (a
    /// `vec4`, the expression's components first).
    #[must_use]
    pub fn watched_values(&self, events: &[Event]) -> Vec<(usize, [f32; 4])> {
        let mut steps = 0;
        let mut seen = Vec::new();
        for e in events {
            match e {
                Event::Assign { name, bits, .. } if name == crate::watched::WATCH => {
                    seen.push((
                        steps,
                        std::array::from_fn(|c| bits.get(c).map_or(0.0, |b| f32::from_bits(*b))),
                    ));
                }
                _ => steps += 1,
            }
        }
        seen
    }

    /// The trace of the traced lane, as data and in words.
    #[must_use]
    pub fn describe(&self, events: &[Event]) -> Trace {
        events
            .iter()
            // A watch's own store (`crate::probe`) is pipelens', not a step of the student's.
            .filter(|e| !matches!(e, Event::Assign { name, .. } if name == crate::watched::WATCH))
            .map(|e| {
                let value = |ty: naga::Handle<naga::Type>, bits: &[u32]| Value {
                    ty: glsl_type(&self.module, ty),
                    numbers: scalars(&self.module, ty, bits),
                };
                let shown = match e {
                    Event::Assign { ty, bits, .. }
                    | Event::Return {
                        value: Some((ty, bits)),
                        ..
                    } => Some(self.format_value(*ty, bits)),
                    _ => None,
                };
                let (at, text, step) = match e {
                    Event::Assign { at, name, ty, bits } => (
                        *at,
                        format!("{name} = {}", shown.as_deref().unwrap_or_default()),
                        Step::Assign {
                            name: name.clone(),
                            value: value(*ty, bits),
                        },
                    ),
                    Event::Branch { at, taken } => (
                        *at,
                        format!("if: {taken} → {}", if *taken { "then" } else { "else" }),
                        Step::Branch { taken: *taken },
                    ),
                    Event::LoopTest { at, holds } => (
                        *at,
                        if *holds {
                            "loop condition: true → another iteration".to_owned()
                        } else {
                            "loop condition: false → the loop ends".to_owned()
                        },
                        Step::LoopTest { holds: *holds },
                    ),
                    Event::Break { at } => (*at, "break: the loop ends".to_owned(), Step::Break),
                    Event::Continue { at } => (
                        *at,
                        "continue: on to the next iteration".to_owned(),
                        Step::Continue,
                    ),
                    Event::Iteration { at, k } => (
                        *at,
                        format!("loop: iteration {k}"),
                        Step::Iteration { k: *k },
                    ),
                    Event::Call { at, name } => (
                        *at,
                        format!("call {name}()"),
                        Step::Call { name: name.clone() },
                    ),
                    Event::Return { at, name, value: v } => (
                        *at,
                        match v {
                            Some(_) => {
                                format!("{name}() returns {}", shown.as_deref().unwrap_or_default())
                            }
                            None => format!("return from {name}()"),
                        },
                        Step::Return {
                            name: name.clone(),
                            value: v.as_ref().map(|(ty, bits)| value(*ty, bits)),
                        },
                    ),
                    Event::Discard { at } => (
                        *at,
                        "discard: the fragment is thrown away".to_owned(),
                        Step::Discard,
                    ),
                };
                TraceLine {
                    line: line_column(&self.source, at).0,
                    text,
                    value: shown,
                    step,
                }
            })
            .collect()
    }

    /// A value as GLSL writes it: `vec3(0.100, 0.200, 0.300)`, `mat2(vec2(…), vec2(…))`.
    #[must_use]
    pub fn format_value(&self, ty: naga::Handle<naga::Type>, bits: &[u32]) -> String {
        format_value(&self.module, ty, bits)
    }
}

/// A float as the debugger shows it: three decimals (`0.250`), or three significant digits in
/// scientific form where three decimals would hide it (`2.512e-5`: a cross product of two
/// per-pixel differences is that small) or it is very large; `NaN` and `inf` as they are.
#[must_use]
pub fn float_text(x: f32) -> String {
    let a = x.abs();
    if !x.is_finite() {
        format!("{x}")
    } else if a != 0.0 && !(0.0005..1e7).contains(&a) {
        format!("{x:.3e}")
    } else {
        format!("{x:.3}")
    }
}

/// The scalars of a value of type `ty` held in `bits`, in GLSL's order, each as a number.
fn scalars(module: &naga::Module, ty: naga::Handle<naga::Type>, bits: &[u32]) -> Vec<f64> {
    let inner = &module.types[ty].inner;
    let number = |k: register_form::Kind, b: u32| match k {
        register_form::Kind::Float => f64::from(f32::from_bits(b)),
        register_form::Kind::Int => f64::from(b as i32),
        register_form::Kind::Uint => f64::from(b),
        register_form::Kind::Bool => f64::from(u8::from(b != 0)),
    };
    match *inner {
        TypeInner::Scalar(_) | TypeInner::Vector { .. } => bits
            .iter()
            .map(|&b| number(crate::type_layout::kind_of(inner), b))
            .collect(),
        TypeInner::Matrix { .. } => bits
            .iter()
            .map(|&b| number(register_form::Kind::Float, b))
            .collect(),
        TypeInner::Array { base, .. } => {
            let n = crate::type_layout::components(module, &module.types[base].inner) as usize;
            bits.chunks(n.max(1))
                .flat_map(|c| scalars(module, base, c))
                .collect()
        }
        TypeInner::Struct { ref members, .. } => {
            let mut at = 0;
            let mut out = Vec::new();
            for m in members {
                let n = crate::type_layout::components(module, &module.types[m.ty].inner) as usize;
                out.extend(scalars(module, m.ty, &bits[at..(at + n).min(bits.len())]));
                at += n;
            }
            out
        }
        _ => Vec::new(),
    }
}

fn format_value(module: &naga::Module, ty: naga::Handle<naga::Type>, bits: &[u32]) -> String {
    let name = glsl_type(module, ty);
    let scalar = |k: register_form::Kind, b: u32| match k {
        register_form::Kind::Float => float_text(f32::from_bits(b)),
        register_form::Kind::Int => (b as i32).to_string(),
        register_form::Kind::Uint => format!("{b}u"),
        register_form::Kind::Bool => (b != 0).to_string(),
    };
    let inner = &module.types[ty].inner;
    match *inner {
        TypeInner::Scalar(_) => bits.first().map_or_else(String::new, |&b| {
            scalar(crate::type_layout::kind_of(inner), b)
        }),
        TypeInner::Vector { .. } => {
            format!(
                "{name}({})",
                bits.iter()
                    .map(|&b| scalar(crate::type_layout::kind_of(inner), b))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        }
        TypeInner::Matrix { rows, .. } => {
            let cols: Vec<String> = bits
                .chunks(rows as usize)
                .map(|c| {
                    format!(
                        "vec{}({})",
                        rows as u32,
                        c.iter()
                            .map(|&b| scalar(register_form::Kind::Float, b))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                })
                .collect();
            format!("{name}({})", cols.join(", "))
        }
        TypeInner::Array { base, .. } => {
            let n = crate::type_layout::components(module, &module.types[base].inner) as usize;
            let items: Vec<String> = bits
                .chunks(n.max(1))
                .map(|c| format_value(module, base, c))
                .collect();
            format!("{name}({})", items.join(", "))
        }
        TypeInner::Struct { ref members, .. } => {
            let mut at = 0;
            let items: Vec<String> = members
                .iter()
                .map(|m| {
                    let n =
                        crate::type_layout::components(module, &module.types[m.ty].inner) as usize;
                    let s = format!(
                        "{}: {}",
                        m.name.as_deref().unwrap_or("?"),
                        format_value(module, m.ty, &bits[at..(at + n).min(bits.len())])
                    );
                    at += n;
                    s
                })
                .collect();
            format!("{name} {{ {} }}", items.join(", "))
        }
        _ => name,
    }
}

/// The GLSL spelling of a type (`vec3`, `mat4`, `Light[8]`).
#[must_use]
pub fn glsl_type(module: &naga::Module, ty: naga::Handle<naga::Type>) -> String {
    let t = &module.types[ty];
    let prefix = |k: naga::ScalarKind| match k {
        naga::ScalarKind::Sint | naga::ScalarKind::AbstractInt => "i",
        naga::ScalarKind::Uint => "u",
        naga::ScalarKind::Bool => "b",
        _ => "",
    };
    match t.inner {
        TypeInner::Scalar(s) => match s.kind {
            naga::ScalarKind::Sint | naga::ScalarKind::AbstractInt => "int",
            naga::ScalarKind::Uint => "uint",
            naga::ScalarKind::Bool => "bool",
            _ => "float",
        }
        .to_owned(),
        TypeInner::Vector { size, scalar } => format!("{}vec{}", prefix(scalar.kind), size as u32),
        TypeInner::Matrix { columns, rows, .. } if columns == rows => {
            format!("mat{}", columns as u32)
        }
        TypeInner::Matrix { columns, rows, .. } => format!("mat{}x{}", columns as u32, rows as u32),
        TypeInner::Array {
            base,
            size: naga::ArraySize::Constant(n),
            ..
        } => format!("{}[{n}]", glsl_type(module, base)),
        _ => t.name.clone().unwrap_or_else(|| "?".to_owned()),
    }
}
