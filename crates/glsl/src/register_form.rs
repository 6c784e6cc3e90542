//! naga's IR translated once into a register form the [`super::machine`] runs: every
//! expression a register of 32-bit components (one row of lanes per component), every operation
//! resolved to the offsets and shapes it works on, every pointer to a place in a variable.
//!
//! Registers and places are counted in *components*: a `vec3` is 3, a `mat4` 16 (column by
//! column, as GLSL stores it), a struct the sum of its members, an array its length times its
//! element. A register of `c` components over `N` lanes is `c` rows of `N` values.

use naga::{BinaryOperator, Handle, MathFunction, ScalarKind};

/// The kind of a scalar component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `float`.
    Float,
    /// `int`.
    Int,
    /// `uint`.
    Uint,
    /// `bool` (0 or 1).
    Bool,
}

impl Kind {
    pub(super) fn of(kind: ScalarKind) -> Self {
        match kind {
            ScalarKind::Float | ScalarKind::AbstractFloat => Self::Float,
            ScalarKind::Sint | ScalarKind::AbstractInt => Self::Int,
            ScalarKind::Uint => Self::Uint,
            ScalarKind::Bool => Self::Bool,
        }
    }
}

/// A register: its first component and how many it has.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Reg {
    /// Its first component.
    pub first: u32,
    /// How many components it has.
    pub len: u32,
}

/// What a pointer points into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Root {
    /// A local variable of the running function (offset in its locals).
    Local,
    /// A global of the invocation (`in`/`out` copies, the student's globals).
    Private,
    /// A uniform: one value for every lane.
    Uniform,
}

/// A place in a variable: a static offset plus dynamic indices, `len` components long.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Place {
    /// Which storage.
    pub root: Root,
    /// The variable's first component plus every constant index's offset.
    pub offset: u32,
    /// Dynamic indices: the index register, the stride in components, the element count.
    pub dynamic: Vec<(u32, u32, u32)>,
    /// How many components it has.
    pub len: u32,
    /// The variable's name, for traces.
    pub name: String,
    /// The variable's first component and size, for traces.
    pub whole: Reg,
    /// The variable's type, for traces.
    pub ty: Handle<naga::Type>,
}

/// How a binary operation's operands are shaped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Component by component (a scalar operand repeats).
    Each,
    /// `mat(c columns × r rows) · vec(c)`.
    MatVec { c: u32, r: u32 },
    /// `vec(r) · mat(c × r)`.
    VecMat { c: u32, r: u32 },
    /// `mat(k × r) · mat(c × k)`.
    MatMat { k: u32, r: u32, c: u32 },
}

/// The level of detail of a texture lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Level {
    /// From the quad's derivatives of the coordinates (`texture`).
    Auto,
    /// `λ` given (`textureLod`).
    Exact(u32),
    /// Added to `λ` (`texture(s, uv, bias)`).
    Bias(u32),
    /// Level 0.
    Zero,
    /// From the derivatives given (`textureGrad(s, uv, dPdx, dPdy)`): the registers of
    /// `∂uv/∂x` and `∂uv/∂y`, which take the quad's differences' place.
    Gradient { x: u32, y: u32 },
}

/// One expression's operation; its result goes to the expression's register.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    /// Nothing to compute: a pointer, a handle, a function's argument or a call's result.
    None,
    /// Fixed components.
    Const(Vec<u32>),
    /// Registers side by side.
    Compose(Vec<Reg>),
    /// `n` components of a register from `at` on.
    Copy { from: u32, n: u32 },
    /// One component repeated.
    Splat { from: u32, n: u32 },
    /// Components picked.
    Swizzle { from: u32, pattern: Vec<u32> },
    /// A dynamic index into a value: `base`, element size, element count, index register.
    Index {
        base: u32,
        elem: u32,
        count: u32,
        index: u32,
        kind: Kind,
    },
    /// Read a place.
    Load(Place),
    /// A unary operator.
    Unary {
        op: naga::UnaryOperator,
        kind: Kind,
        a: Reg,
    },
    /// A binary operator.
    Binary {
        op: BinaryOperator,
        kind: Kind,
        a: Reg,
        b: Reg,
        shape: Shape,
    },
    /// `c ? a : b`, component by component (a scalar condition for all).
    Select { c: Reg, a: Reg, b: Reg },
    /// `dFdx`, `dFdy`, `fwidth` over the quad.
    Derivative {
        axis: naga::DerivativeAxis,
        fine: bool,
        a: Reg,
    },
    /// `all`, `any`, `isnan`, `isinf`.
    Relational {
        fun: naga::RelationalFunction,
        a: Reg,
    },
    /// A built-in function; `rows` is the vector or column size of its first argument.
    Math {
        fun: MathFunction,
        kind: Kind,
        args: Vec<Reg>,
        rows: u32,
    },
    /// A conversion (`convert`) or a bit cast.
    As {
        a: Reg,
        from: Kind,
        to: Kind,
        convert: bool,
    },
    /// `texture(s, uv)` and its kin: a vec4. `texture`: the register that holds the texture's
    /// slot (a uniform's, or one passed to the function: the same in every lane); `offset`:
    /// the register of the `ivec2` texel offset of `textureOffset` and its kin. The texture of
    /// the other texture operations is a register too.
    Sample {
        texture: u32,
        coordinate: Reg,
        level: Level,
        offset: Option<u32>,
    },
    /// `texture(s, r)` of a `samplerCube`: the cube map in direction `r`, a vec4 (any level
    /// asked for reads the one level a cube map has).
    SampleCube { texture: u32, direction: Reg },
    /// `texelFetch(s, ij, level)`: a vec4.
    Fetch {
        texture: u32,
        coordinate: Reg,
        level: Option<u32>,
    },
    /// `textureSize(s, level)`: an ivec2.
    Size { texture: u32, level: Option<u32> },
}

impl Op {
    /// The first register of each operand the operation reads (the registers a place's dynamic
    /// indices are in, for a load). Each is an expression naga's arena holds before this one,
    /// so each lies below the operation's own register: the machine splits the register file
    /// there, reading below and writing above (`machine::eval`).
    #[must_use]
    pub fn reads(&self) -> Vec<u32> {
        let level = |l: &Level| match *l {
            Level::Exact(r) | Level::Bias(r) => vec![r],
            Level::Gradient { x, y } => vec![x, y],
            Level::Auto | Level::Zero => Vec::new(),
        };
        match self {
            Self::None | Self::Const(_) => Vec::new(),
            Self::Compose(parts) => parts.iter().map(|r| r.first).collect(),
            Self::Copy { from, .. } | Self::Splat { from, .. } | Self::Swizzle { from, .. } => {
                vec![*from]
            }
            Self::Index { base, index, .. } => vec![*base, *index],
            Self::Load(p) => p.dynamic.iter().map(|d| d.0).collect(),
            Self::Unary { a, .. }
            | Self::Derivative { a, .. }
            | Self::Relational { a, .. }
            | Self::As { a, .. } => vec![a.first],
            Self::Binary { a, b, .. } => vec![a.first, b.first],
            Self::Select { c, a, b } => vec![c.first, a.first, b.first],
            Self::Math { args, .. } => args.iter().map(|r| r.first).collect(),
            Self::Sample {
                texture,
                coordinate,
                level: l,
                offset,
            } => [
                vec![*texture, coordinate.first],
                level(l),
                offset.iter().copied().collect(),
            ]
            .concat(),
            Self::SampleCube { texture, direction } => vec![*texture, direction.first],
            Self::Fetch {
                texture,
                coordinate,
                level,
            } => [
                vec![*texture, coordinate.first],
                level.iter().copied().collect(),
            ]
            .concat(),
            Self::Size { texture, level } => {
                [vec![*texture], level.iter().copied().collect()].concat()
            }
        }
    }
}

/// A statement in register form; `at` is its place in the student's source (bytes).
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// Evaluate these expressions in order.
    Emit(std::ops::Range<u32>),
    /// A nested block.
    Block(Vec<Stmt>),
    /// `if`.
    If(If),
    /// `switch` on an integer.
    Switch(Switch),
    /// A loop.
    Loop(Loop),
    /// `break`, at its place (`None`: one naga made for a loop's condition).
    Break { at: Option<usize> },
    /// `continue`, at its place.
    Continue { at: usize },
    /// `return`, with the value's register.
    Return { at: usize, value: Option<Reg> },
    /// `discard`.
    Kill { at: usize },
    /// `*place = value`.
    Store { at: usize, place: Place, value: u32 },
    /// A call.
    Call(Call),
}

/// `if`; `loop_test` when naga made it for a `for` or `while` condition (`if (!cond)
/// break;`): the trace says the loop's condition, not an `if` the student did not write.
#[derive(Clone, Debug, PartialEq)]
pub struct If {
    /// Its place in the student's source.
    pub at: usize,
    /// The register of the condition.
    pub c: u32,
    /// The statements where it holds.
    pub accept: Vec<Stmt>,
    /// The statements where it does not.
    pub reject: Vec<Stmt>,
    /// Whether naga made it for a loop's condition.
    pub loop_test: bool,
}

/// `switch` on an integer: the cases (None = default), their bodies, and fall-through.
#[derive(Clone, Debug, PartialEq)]
pub struct Switch {
    /// Its place in the student's source.
    pub at: usize,
    /// The register of the selector.
    pub selector: u32,
    /// Each case: its value (`None`: `default`), its body, whether it falls through.
    pub cases: Vec<(Option<i64>, Vec<Stmt>, bool)>,
}

/// A loop as naga writes every `for`, `while` and `do`: the body, the `continuing` block, and
/// the register of `break if`.
#[derive(Clone, Debug, PartialEq)]
pub struct Loop {
    /// Its place in the student's source.
    pub at: usize,
    /// The body.
    pub body: Vec<Stmt>,
    /// What runs after the body and after a `continue` (a `for`'s increment).
    pub continuing: Vec<Stmt>,
    /// The register of the condition that ends the loop after `continuing`.
    pub break_if: Option<u32>,
}

/// A call: the function, its arguments, the result's register.
#[derive(Clone, Debug, PartialEq)]
pub struct Call {
    /// Its place in the student's source.
    pub at: usize,
    /// The callee's index among the code's functions.
    pub function: usize,
    /// What each parameter is passed.
    pub args: Vec<Argument>,
    /// The register the result goes to.
    pub result: Option<Reg>,
}

/// What a call passes for one parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum Argument {
    /// An `in` parameter's value: the register it is copied from.
    Value(Reg),
    /// An `out` or `inout` parameter's variable (GLSL 3.30 §6.1.1): copied into the callee's
    /// parameter when the call starts (naga writes `out`'s as a fresh spill variable, so its
    /// value is undefined there as GLSL says), and back to this place when it returns, in
    /// the lanes that made the call.
    Ref(Place),
}

/// Where a function keeps one parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parameter {
    /// An `in` parameter: a register.
    Value(Reg),
    /// An `out` or `inout` parameter: its own components among the function's locals, which
    /// the body reads and writes as a variable and the call copies in and back.
    Ref(Reg),
}

impl Parameter {
    /// Its components (a register or locals).
    #[must_use]
    pub fn reg(self) -> Reg {
        match self {
            Self::Value(r) | Self::Ref(r) => r,
        }
    }
}

/// One function in register form.
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    /// Its name (`main`, the student's helpers).
    pub name: String,
    /// Whether pipelens wrote it (a built-in naga lacks, [`super::glsl330::WRITTEN_IN_GLSL`]):
    /// its steps are not the student's, so the trace shows none of them.
    pub builtin: bool,
    /// The operation of each expression, in order.
    pub ops: Vec<Op>,
    /// The register of each expression.
    pub regs: Vec<Reg>,
    /// Where each expression is in the student's source (bytes), for errors.
    pub spans: Vec<usize>,
    /// Expressions evaluated once with the invariants, before any lane runs: constants and
    /// those no `Emit` covers (see `evaluated_once.rs`).
    pub pre: Vec<u32>,
    /// Components of all registers.
    pub width: u32,
    /// Local variables: first component, size, and the register of their initial value.
    pub locals: Vec<(Reg, Option<u32>)>,
    /// Components of all locals, the `out` and `inout` parameters' after the variables'.
    pub locals_width: u32,
    /// Where each parameter is kept.
    pub args: Vec<Parameter>,
    /// The type it returns (`None`: `void`).
    pub result: Option<naga::Handle<naga::Type>>,
    /// The body.
    pub body: Vec<Stmt>,
}

/// A program in register form: its functions (callees before callers) and its storage.
#[derive(Clone, Debug, PartialEq)]
pub struct Code {
    /// naga's functions, then the entry point last.
    pub functions: Vec<Function>,
    /// Each global: where it is and in which storage (`None`: a texture or sampler).
    pub globals: Vec<Option<(Root, Reg)>>,
    /// Components of the invocation's globals.
    pub private_width: u32,
    /// Components of the uniforms.
    pub uniform_width: u32,
    /// Initial values of private globals that have one: place, components.
    pub private_init: Vec<(u32, Vec<u32>)>,
}

/// Something the translation cannot do, with where (bytes in the adapted source).
#[derive(Clone, Debug)]
pub struct Unsupported {
    /// Where, in the adapted source.
    pub at: usize,
    /// What.
    pub what: String,
    /// The built-in function pipelens does not run, as GLSL spells it, when that is what it is.
    pub function: Option<String>,
}

/// Why an expression cannot be translated: the words, and the built-in function pipelens does
/// not run when that is the reason.
#[derive(Clone, Debug)]
pub struct OpError {
    /// What.
    pub what: String,
    /// The built-in function, as GLSL spells it.
    pub function: Option<String>,
}

impl From<String> for OpError {
    fn from(what: String) -> Self {
        Self {
            what,
            function: None,
        }
    }
}

impl OpError {
    /// The built-in function `name` (as GLSL spells it), which pipelens does not run yet.
    #[must_use]
    pub fn not_run(name: &str) -> Self {
        Self {
            what: not_run(name),
            function: Some(name.to_owned()),
        }
    }
}

/// What a built-in pipelens does not run yet is told: "pipelens does not run `modf` yet".
#[must_use]
pub fn not_run(name: &str) -> String {
    format!("pipelens does not run `{name}` yet")
}
