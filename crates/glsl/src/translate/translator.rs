//! The translator of a validated module: its state, each function's parameters, locals and
//! places, and its expressions as the machine's operations (statements in `statements.rs`,
//! texture lookups in `texture.rs`).

use naga::valid::{FunctionInfo, ModuleInfo};
use naga::{AddressSpace, BinaryOperator, Expression, Handle, Module, TypeInner};

use crate::dialect::Adapted;
use crate::evaluated_once::evaluated_once;
use crate::register_form::{
    Code, Function, Kind, Op, OpError, Parameter, Place, Reg, Root, Shape, Unsupported,
};
use crate::type_layout::{components, const_value, element_count, kind_of, literal, member};

/// What a `%` between floats is told (GLSL's `%` takes integers).
pub const FLOAT_MODULO: &str = "GLSL's `%` takes whole numbers only (int, uint, ivec…): for floats write mod(a, b), a − b·floor(a/b)";

/// The translation of a validated module.
pub struct Translator<'m> {
    pub(super) module: &'m Module,
    pub(super) adapted: &'m Adapted,
    pub(super) code: Code,
    /// Names of the textures, in binding order, as globals.
    pub(super) textures: Vec<(Handle<naga::GlobalVariable>, u32)>,
    /// The place of the closing brace of the function being translated: where the `return`
    /// naga writes at the end of a `void` function is (it has no place of its own).
    pub(super) end: std::cell::Cell<usize>,
}

impl<'m> Translator<'m> {
    /// Translates the module's functions and its one entry point. `uniform(name)` says whether a
    /// private global is a uniform pipelens fills; `texture(name)` the slot of a texture global.
    ///
    /// # Errors
    /// An operation the interpreter does not run, with its place.
    pub fn translate(
        module: &'m Module,
        info: &'m ModuleInfo,
        adapted: &'m Adapted,
        is_uniform: &dyn Fn(&str) -> bool,
        texture: &dyn Fn(&str) -> Option<u32>,
    ) -> Result<Code, Unsupported> {
        let mut t = Self {
            module,
            adapted,
            code: Code {
                functions: Vec::new(),
                globals: Vec::new(),
                private_width: 0,
                uniform_width: 0,
                private_init: Vec::new(),
            },
            textures: Vec::new(),
            end: std::cell::Cell::new(0),
        };
        for (h, g) in module.global_variables.iter() {
            let n = components(module, &module.types[g.ty].inner);
            let name = g.name.clone().unwrap_or_default();
            let slot = match g.space {
                AddressSpace::Handle => {
                    if let Some(s) = texture(&name) {
                        t.textures.push((h, s));
                    }
                    None
                }
                AddressSpace::Private if is_uniform(&name) => {
                    let at = t.code.uniform_width;
                    t.code.uniform_width += n;
                    Some((Root::Uniform, Reg { first: at, len: n }))
                }
                _ => {
                    let at = t.code.private_width;
                    t.code.private_width += n;
                    if let Some(init) = g.init {
                        let v = const_value(module, init).map_err(|what| Unsupported {
                            at: 0,
                            what,
                            function: None,
                        })?;
                        t.code.private_init.push((at, v));
                    }
                    Some((Root::Private, Reg { first: at, len: n }))
                }
            };
            t.code.globals.push(slot);
        }
        for (h, f) in module.functions.iter() {
            let start = module.functions.get_span(h).to_range().map(|r| r.start);
            t.end.set(start.map_or(0, |s| closing_brace(adapted, s)));
            let mut func = t.function(f, &info[h])?;
            // A function in the preamble is one pipelens wrote.
            func.builtin = module
                .functions
                .get_span(h)
                .to_range()
                .is_some_and(|r| r.start < adapted.preamble_len);
            t.code.functions.push(func);
        }
        let ep = module.entry_points.first().ok_or(Unsupported {
            function: None,
            at: 0,
            what: "no `main`".to_owned(),
        })?;
        let func = t.function(&ep.function, info.get_entry_point(0))?;
        t.code.functions.push(func);
        Ok(t.code)
    }

    pub(super) fn at(&self, span: naga::Span) -> usize {
        span.to_range()
            .map_or(0, |r| self.adapted.original_offset(r.start))
    }

    pub(super) fn function(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
    ) -> Result<Function, Unsupported> {
        let module = self.module;
        let ty = |h: Handle<Expression>| fi[h].ty.inner_with(&module.types);
        let mut regs = Vec::with_capacity(f.expressions.len());
        let mut width = 0;
        for (h, _) in f.expressions.iter() {
            let n = match *ty(h) {
                TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. } => 0,
                ref inner => components(module, inner),
            };
            regs.push(Reg {
                first: width,
                len: n,
            });
            width += n;
        }
        let mut locals = Vec::new();
        let mut locals_width = 0;
        for (_, l) in f.local_variables.iter() {
            let n = components(module, &module.types[l.ty].inner);
            locals.push((
                Reg {
                    first: locals_width,
                    len: n,
                },
                l.init.map(|h| regs[h.index()].first),
            ));
            locals_width += n;
        }
        // An `out` or `inout` parameter is a pointer naga's body reads and writes through: it
        // gets components of its own after the locals, which the call fills and empties.
        let args = f
            .arguments
            .iter()
            .map(|a| match module.types[a.ty].inner {
                TypeInner::Pointer { base, .. } => {
                    let n = components(module, &module.types[base].inner);
                    let reg = Reg {
                        first: locals_width,
                        len: n,
                    };
                    locals_width += n;
                    Parameter::Ref(reg)
                }
                _ => Parameter::Value(Reg::default()),
            })
            .collect();
        let once = evaluated_once(f);
        let mut func = Function {
            name: f.name.clone().unwrap_or_else(|| "main".to_owned()),
            builtin: false,
            ops: Vec::with_capacity(f.expressions.len()),
            regs,
            spans: Vec::with_capacity(f.expressions.len()),
            pre: Vec::new(),
            width,
            locals,
            locals_width,
            args,
            result: f.result.as_ref().map(|r| r.ty),
            body: Vec::new(),
        };
        for (h, e) in f.expressions.iter() {
            let span = f.expressions.get_span(h);
            let op = self.op(f, fi, e, &func).map_err(|e| Unsupported {
                at: self.at(span),
                what: e.what,
                function: e.function,
            })?;
            if let Expression::FunctionArgument(i) = *e
                && let Parameter::Value(reg) = &mut func.args[i as usize]
            {
                *reg = func.regs[h.index()];
            }
            if once[h.index()] && !matches!(op, Op::None) {
                func.pre.push(h.index() as u32);
            }
            func.ops.push(op);
            func.spans.push(self.at(span));
        }
        func.body = self.block(f, fi, &f.body, &func, 0)?;
        Ok(func)
    }

    pub(super) fn place(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
        h: Handle<Expression>,
        func: &Function,
    ) -> Result<Place, String> {
        let module = self.module;
        let ty = |h: Handle<Expression>| fi[h].ty.inner_with(&module.types);
        match f.expressions[h] {
            Expression::LocalVariable(l) => {
                let (reg, _) = func.locals[l.index()];
                let var = &f.local_variables[l];
                Ok(Place {
                    root: Root::Local,
                    offset: reg.first,
                    dynamic: Vec::new(),
                    len: reg.len,
                    name: var.name.clone().unwrap_or_default(),
                    whole: reg,
                    ty: var.ty,
                })
            }
            Expression::GlobalVariable(g) => {
                let var = &module.global_variables[g];
                let (root, reg) = self.code.globals[g.index()]
                    .ok_or_else(|| "a texture used as a value".to_owned())?;
                Ok(Place {
                    root,
                    offset: reg.first,
                    dynamic: Vec::new(),
                    len: reg.len,
                    name: var.name.clone().unwrap_or_default(),
                    whole: reg,
                    ty: var.ty,
                })
            }
            Expression::AccessIndex { base, index } => {
                let mut p = self.place(f, fi, base, func)?;
                let pointee = pointee(module, ty(base));
                let (off, n) = member(module, pointee, index);
                p.offset += off;
                p.len = n;
                Ok(p)
            }
            Expression::Access { base, index } => {
                let mut p = self.place(f, fi, base, func)?;
                let pointee = pointee(module, ty(base));
                let (_, n) = member(module, pointee, 0);
                p.dynamic
                    .push((func.regs[index.index()].first, n, element_count(pointee)));
                p.len = n;
                Ok(p)
            }
            Expression::FunctionArgument(i) => {
                let Parameter::Ref(reg) = func.args[i as usize] else {
                    return Err("a parameter used as a variable".to_owned());
                };
                let param = &f.arguments[i as usize];
                let TypeInner::Pointer { base, .. } = module.types[param.ty].inner else {
                    return Err("a parameter used as a variable".to_owned());
                };
                Ok(Place {
                    root: Root::Local,
                    offset: reg.first,
                    dynamic: Vec::new(),
                    len: reg.len,
                    name: param.name.clone().unwrap_or_default(),
                    whole: reg,
                    ty: base,
                })
            }
            ref other => Err(format!("a pointer pipelens cannot follow ({other:?})")),
        }
    }

    #[allow(clippy::too_many_lines)]
    pub(super) fn op(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
        e: &Expression,
        func: &Function,
    ) -> Result<Op, OpError> {
        let module = self.module;
        let ty = |h: Handle<Expression>| fi[h].ty.inner_with(&module.types);
        let reg = |h: Handle<Expression>| func.regs[h.index()];
        Ok(match *e {
            Expression::Literal(l) => Op::Const(literal(l)?),
            Expression::Constant(c) => Op::Const(const_value(module, module.constants[c].init)?),
            Expression::ZeroValue(t) => {
                Op::Const(vec![0; components(module, &module.types[t].inner) as usize])
            }
            Expression::Compose { ref components, .. } => {
                Op::Compose(components.iter().map(|&c| reg(c)).collect())
            }
            Expression::Splat { size, value } => Op::Splat {
                from: reg(value).first,
                n: size as u32,
            },
            Expression::Swizzle {
                size,
                vector,
                ref pattern,
            } => Op::Swizzle {
                from: reg(vector).first,
                pattern: pattern[..size as usize].iter().map(|&c| c as u32).collect(),
            },
            Expression::AccessIndex { base, index } => match *ty(base) {
                TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. } => Op::None,
                ref inner => {
                    let (off, n) = member(module, inner, index);
                    Op::Copy {
                        from: reg(base).first + off,
                        n,
                    }
                }
            },
            Expression::Access { base, index } => match *ty(base) {
                TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. } => Op::None,
                ref inner => {
                    let (_, elem) = member(module, inner, 0);
                    Op::Index {
                        base: reg(base).first,
                        elem,
                        count: element_count(inner),
                        index: reg(index).first,
                        kind: kind_of(ty(index)),
                    }
                }
            },
            // A texture's value is its slot, which a call passes on.
            Expression::GlobalVariable(g) => self
                .texture_value(g)
                .map_or(Op::None, |slot| Op::Const(vec![slot])),
            Expression::FunctionArgument(_)
            | Expression::LocalVariable(_)
            | Expression::CallResult(_) => Op::None,
            Expression::Load { pointer } => Op::Load(self.place(f, fi, pointer, func)?),
            Expression::Unary { op, expr } => Op::Unary {
                op,
                kind: kind_of(ty(expr)),
                a: reg(expr),
            },
            Expression::Binary { op, left, right } => {
                let (lt, rt) = (ty(left), ty(right));
                let shape = match (op, lt, rt) {
                    (
                        BinaryOperator::Multiply,
                        &TypeInner::Matrix { columns, rows, .. },
                        &TypeInner::Vector { .. },
                    ) => Shape::MatVec {
                        c: columns as u32,
                        r: rows as u32,
                    },
                    (
                        BinaryOperator::Multiply,
                        &TypeInner::Vector { .. },
                        &TypeInner::Matrix { columns, rows, .. },
                    ) => Shape::VecMat {
                        c: columns as u32,
                        r: rows as u32,
                    },
                    (
                        BinaryOperator::Multiply,
                        &TypeInner::Matrix {
                            columns: k, rows, ..
                        },
                        &TypeInner::Matrix { columns, .. },
                    ) => Shape::MatMat {
                        k: k as u32,
                        r: rows as u32,
                        c: columns as u32,
                    },
                    _ => Shape::Each,
                };
                // naga reads `%` on floats (WGSL has it); GLSL does not, and a real OpenGL
                // refuses the shader (its `mod` is naga's floor form, never this operator).
                if op == BinaryOperator::Modulo && kind_of(lt) == Kind::Float {
                    return Err(FLOAT_MODULO.to_owned().into());
                }
                Op::Binary {
                    op,
                    kind: kind_of(lt),
                    a: reg(left),
                    b: reg(right),
                    shape,
                }
            }
            Expression::Select {
                condition,
                accept,
                reject,
            } => Op::Select {
                c: reg(condition),
                a: reg(accept),
                b: reg(reject),
            },
            Expression::Derivative { axis, ctrl, expr } => Op::Derivative {
                axis,
                fine: ctrl == naga::DerivativeControl::Fine,
                a: reg(expr),
            },
            Expression::Relational { fun, argument } => Op::Relational {
                fun,
                a: reg(argument),
            },
            Expression::Math {
                fun,
                arg,
                arg1,
                arg2,
                arg3,
            } => {
                if !crate::builtins::supported(fun) {
                    return Err(OpError::not_run(&crate::builtins::glsl_name(fun)));
                }
                let args = [Some(arg), arg1, arg2, arg3]
                    .into_iter()
                    .flatten()
                    .map(reg)
                    .collect();
                let rows = match *ty(arg) {
                    TypeInner::Vector { size, .. } => size as u32,
                    TypeInner::Matrix { rows, .. } => rows as u32,
                    _ => 1,
                };
                Op::Math {
                    fun,
                    kind: kind_of(ty(arg)),
                    args,
                    rows,
                }
            }
            Expression::As {
                expr,
                kind,
                convert,
            } => Op::As {
                a: reg(expr),
                from: kind_of(ty(expr)),
                to: Kind::of(kind),
                convert: convert.is_some(),
            },
            Expression::ImageSample { .. }
            | Expression::ImageLoad { .. }
            | Expression::ImageQuery { .. } => self.texture_op(f, fi, e, &reg)?,
            ref other => {
                return Err(format!(
                    "an operation pipelens does not run yet ({})",
                    describe(other)
                )
                .into());
            }
        })
    }
}

/// The student's offset of the `}` that closes the function whose header starts at `start`
/// (naga's offset): the brace that balances the first `{` after it, comments skipped.
pub(super) fn closing_brace(adapted: &Adapted, start: usize) -> usize {
    let text = adapted.text.get(start..).unwrap_or_default();
    let mut depth = 0;
    for l in crate::lexeme::lex(text) {
        match &text[l.span.clone()] {
            "{" => depth += 1,
            "}" if depth == 1 => return adapted.original_offset(start + l.span.start),
            "}" => depth -= 1,
            _ => {}
        }
    }
    adapted.original_offset(start)
}

/// The first word of an IR node's debug form: `Atomic`, `ImageStore`.
pub(super) fn describe(node: &dyn std::fmt::Debug) -> String {
    let s = format!("{node:?}");
    s.split([' ', '(', '{'])
        .next()
        .unwrap_or_default()
        .to_owned()
}

/// The type a pointer points to.
pub(super) fn pointee<'a>(module: &'a Module, inner: &'a TypeInner) -> &'a TypeInner {
    match *inner {
        TypeInner::Pointer { base, .. } => &module.types[base].inner,
        _ => inner,
    }
}
