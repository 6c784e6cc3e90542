//! What one invocation did, in words: the machine's events with the student's line numbers and
//! every value written as GLSL writes it (`vec3(0.000, 0.707, 0.707)`).

use naga::TypeInner;

use super::{Event, Program, code, line_column};

/// One line of a trace: where, and what happened, in words with the values.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct TraceLine {
    /// Line in the student's source, from 1.
    pub line: usize,
    /// What happened: `n = vec3(0.000, 0.707, 0.707)`, `if: true → then`, `loop: iteration 3`.
    pub text: String,
}

/// What one invocation did, statement by statement.
pub type Trace = Vec<TraceLine>;

impl Program {
    /// The trace of the traced lane, in words.
    #[must_use]
    pub fn describe(&self, events: &[Event]) -> Trace {
        events
            .iter()
            .map(|e| {
                let (at, text) = match e {
                    Event::Assign { at, name, ty, bits } => {
                        (*at, format!("{name} = {}", self.format_value(*ty, bits)))
                    }
                    Event::Branch { at, taken } => (
                        *at,
                        format!("if: {taken} → {}", if *taken { "then" } else { "else" }),
                    ),
                    Event::Iteration { at, k } => (*at, format!("loop: iteration {k}")),
                    Event::Call { at, name } => (*at, format!("call {name}()")),
                    Event::Return { at, name } => (*at, format!("return from {name}()")),
                    Event::Discard { at } => {
                        (*at, "discard: the fragment is thrown away".to_owned())
                    }
                };
                TraceLine {
                    line: line_column(&self.source, at).0,
                    text,
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

fn format_value(module: &naga::Module, ty: naga::Handle<naga::Type>, bits: &[u32]) -> String {
    let name = glsl_type(module, ty);
    let scalar = |k: code::Kind, b: u32| match k {
        code::Kind::F => float_text(f32::from_bits(b)),
        code::Kind::I => (b as i32).to_string(),
        code::Kind::U => format!("{b}u"),
        code::Kind::B => (b != 0).to_string(),
    };
    let inner = &module.types[ty].inner;
    match *inner {
        TypeInner::Scalar(_) => bits
            .first()
            .map_or_else(String::new, |&b| scalar(code::kind_of(inner), b)),
        TypeInner::Vector { .. } => {
            format!(
                "{name}({})",
                bits.iter()
                    .map(|&b| scalar(code::kind_of(inner), b))
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
                            .map(|&b| scalar(code::Kind::F, b))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                })
                .collect();
            format!("{name}({})", cols.join(", "))
        }
        TypeInner::Array { base, .. } => {
            let n = code::components(module, &module.types[base].inner) as usize;
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
                    let n = code::components(module, &module.types[m.ty].inner) as usize;
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
