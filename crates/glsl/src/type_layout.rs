//! How a GLSL value lies in the machine's registers: how many 32-bit components a type has and
//! of which kind, where a struct's member or an array's element starts, and a constant's value
//! as the bit patterns its components hold.

use naga::{Expression, Handle, Literal, Module, TypeInner};

use crate::register_form::Kind;

/// Components of a type.
pub fn components(module: &Module, inner: &TypeInner) -> u32 {
    match *inner {
        TypeInner::Scalar(_) | TypeInner::Atomic(_) => 1,
        TypeInner::Vector { size, .. } => size as u32,
        TypeInner::Matrix { columns, rows, .. } => columns as u32 * rows as u32,
        TypeInner::Array {
            base,
            size: naga::ArraySize::Constant(n),
            ..
        } => n.get() * components(module, &module.types[base].inner),
        TypeInner::Struct { ref members, .. } => members
            .iter()
            .map(|m| components(module, &module.types[m.ty].inner))
            .sum(),
        // A texture is passed as a value: its slot ([`Op::Sample`]).
        TypeInner::Image { .. } => 1,
        _ => 0,
    }
}

/// The scalar kind of a scalar, vector or matrix type (float otherwise).
pub fn kind_of(inner: &TypeInner) -> Kind {
    match *inner {
        TypeInner::Scalar(s)
        | TypeInner::Vector { scalar: s, .. }
        | TypeInner::Matrix { scalar: s, .. } => Kind::of(s.kind),
        TypeInner::ValuePointer { scalar, .. } => Kind::of(scalar.kind),
        _ => Kind::Float,
    }
}

/// The offset in components of member or element `index` of a type, and its type.
pub(super) fn member(module: &Module, inner: &TypeInner, index: u32) -> (u32, u32) {
    match *inner {
        TypeInner::Vector { .. } => (index, 1),
        TypeInner::Matrix { rows, .. } => (index * rows as u32, rows as u32),
        TypeInner::Array { base, .. } => {
            let n = components(module, &module.types[base].inner);
            (index * n, n)
        }
        TypeInner::ValuePointer { .. } => (index, 1),
        TypeInner::Struct { ref members, .. } => {
            let before: u32 = members[..index as usize]
                .iter()
                .map(|m| components(module, &module.types[m.ty].inner))
                .sum();
            (
                before,
                components(module, &module.types[members[index as usize].ty].inner),
            )
        }
        _ => (0, 1),
    }
}

/// The type a pointer or value points to or is, and its element count (for dynamic indices).
pub(super) fn element_count(inner: &TypeInner) -> u32 {
    match *inner {
        TypeInner::Vector { size, .. } => size as u32,
        TypeInner::Matrix { columns, .. } => columns as u32,
        TypeInner::Array {
            size: naga::ArraySize::Constant(n),
            ..
        } => n.get(),
        TypeInner::ValuePointer {
            size: Some(size), ..
        } => size as u32,
        _ => 1,
    }
}

/// Evaluates a constant expression of the module (`global_expressions`).
pub fn const_value(module: &Module, h: Handle<Expression>) -> Result<Vec<u32>, String> {
    let e = &module.global_expressions;
    match e[h] {
        Expression::Literal(l) => literal(l),
        Expression::Constant(c) => const_value(module, module.constants[c].init),
        Expression::ZeroValue(ty) => Ok(vec![
            0;
            components(module, &module.types[ty].inner) as usize
        ]),
        Expression::Compose { ref components, .. } => {
            let mut out = Vec::new();
            for &c in components {
                out.extend(const_value(module, c)?);
            }
            Ok(out)
        }
        Expression::Splat { size, value } => Ok(const_value(module, value)?.repeat(size as usize)),
        ref other => Err(format!(
            "a constant expression pipelens cannot evaluate ({other:?})"
        )),
    }
}

pub(super) fn literal(l: Literal) -> Result<Vec<u32>, String> {
    Ok(vec![match l {
        Literal::F32(x) => x.to_bits(),
        Literal::F64(x) | Literal::AbstractFloat(x) => (x as f32).to_bits(),
        Literal::U32(x) => x,
        Literal::I32(x) => x as u32,
        Literal::I64(x) | Literal::AbstractInt(x) => x as i32 as u32,
        Literal::U64(x) => x as u32,
        Literal::Bool(b) => u32::from(b),
        other => return Err(format!("a literal pipelens cannot hold ({other:?})")),
    }])
}
