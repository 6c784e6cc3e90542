//! The GLSL engine of pipelens: shaders the student writes, the vertex and fragment stages as
//! *programs* (GAMES101, lecture 7: "Shader function executes once per fragment"; Angel: the
//! model-view matrix is passed "to the shader").
//!
//! A shader is GLSL as an OpenGL course writes it (`#version 330 core`, plain `uniform`s,
//! `uniform sampler2D tex;`, `in`/`out` without locations; GLSL 1.x's `attribute`, `varying`
//! and `gl_FragColor` too). [`compile`] adapts it to the GLSL naga reads ([`dialect`]), has naga
//! parse and validate it, checks it against what pipelens provides ([`interface`]), and
//! translates naga's IR once into a register form ([`code`]). A [`Program`] then runs on the
//! CPU over batches of invocations ([`Machine`]), reading the textures its host binds
//! ([`Textures`]), and can record what one invocation did, statement by statement ([`Trace`]).
//!
//! Every message points at the student's own line and column.
//!
//! The pipeline (`pipeline::shader`) re-exports this crate and adds what is its own: the
//! uniforms' values for an object, the textures bound per slot, pipelens' shading modes as GLSL
//! and the pipeline functions the student writes.

mod check;
mod code;
pub mod complaint;
pub mod dialect;
mod emitted;
pub mod glsl330;
pub mod interface;
pub mod lexeme;
mod lowering;
mod machine;
mod modulo;
mod ops;
pub mod power;
mod sampler_arguments;
mod trace;
mod translate;

use std::fmt;
use std::ops::Range;

use naga::{Binding, BuiltIn, Interpolation, TypeInner};

pub use check::complain;
pub use complaint::Complaint;
pub use machine::{DEFAULT_MAX_STEPS, Event, LANES, Machine, RunError, Texel, Textures};
pub use trace::{Step, Trace, TraceLine, Value, float_text, glsl_type};

/// Which programmable stage a shader is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Runs once per vertex: writes `gl_Position` and the varyings.
    Vertex,
    /// Runs once per fragment: writes the colour, or discards.
    Fragment,
}

impl Stage {
    /// "vertex" or "fragment".
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Vertex => "vertex",
            Self::Fragment => "fragment",
        }
    }
}

/// A message about a shader, at its place in the student's source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShaderError {
    /// Line, from 1.
    pub line: usize,
    /// Column, from 1 (in characters).
    pub column: usize,
    /// The bytes it concerns in the student's source.
    pub span: Range<usize>,
    /// What is wrong, as a sentence (English).
    pub message: String,
    /// The mistake as data, for the interface to say in its language; [`Complaint::Other`]
    /// where only `message` says it.
    pub complaint: Complaint,
}

impl fmt::Display for ShaderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {}, column {}: {}",
            self.line, self.column, self.message
        )
    }
}

/// Where a shader's source stands in a file: a shader file (from its first line and column), or
/// a lesson whose text holds the GLSL (`fragment = """…"""`), from the line and column of the
/// source's first character there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Origin {
    /// The file's name as the lesson's messages write it.
    pub file: String,
    /// The line of the source's first character in the file, from 1.
    pub line: usize,
    /// Its column, from 1 (in characters).
    pub column: usize,
}

impl Origin {
    /// `e`, its line and column moved from the source's own to the file's: the source's line 1
    /// starts at this column, its later lines at the file's column 1. (The file's name goes
    /// with it where the error is said: the pipeline's `RenderError::Code`'s `file`.)
    #[must_use]
    pub fn place(&self, mut e: ShaderError) -> ShaderError {
        if e.line == 1 {
            e.column += self.column - 1;
        }
        e.line += self.line - 1;
        e
    }
}

/// Line and column (from 1, the column in characters) of byte `at` of `src`.
#[must_use]
pub fn line_column(src: &str, at: usize) -> (usize, usize) {
    let at = at.min(src.len());
    let at = (0..=at)
        .rev()
        .find(|&i| src.is_char_boundary(i))
        .unwrap_or(0);
    let before = &src[..at];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// A [`ShaderError`] at `span` of `src`, its line and column worked out.
#[must_use]
pub fn error_at(src: &str, span: Range<usize>, message: impl Into<String>) -> ShaderError {
    let (line, column) = line_column(src, span.start);
    ShaderError {
        line,
        column,
        span,
        message: message.into(),
        complaint: Complaint::Other,
    }
}

/// How a varying is interpolated across a triangle (GLSL's qualifiers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolate {
    /// The default (`smooth`): perspective-correct, `(Σ λ_i·a_i/w_i) / (Σ λ_i/w_i)`.
    Perspective,
    /// `noperspective`: affine in the window, `Σ λ_i·a_i` (the screen-space λ).
    Linear,
    /// `flat`: the provoking (last) vertex's value.
    Flat,
}

/// A value passed between stages: a vertex attribute, a varying, an output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Varying {
    /// Its name in the shader (`gl_Position`, `gl_FragCoord` for built-ins).
    pub name: String,
    /// Its location (built-ins: none).
    pub location: Option<u32>,
    /// Its built-in meaning, if it is one.
    pub builtin: Option<BuiltIn>,
    /// Components.
    pub components: u32,
    /// How it is interpolated (fragment inputs).
    pub interpolate: Interpolate,
}

/// A compiled shader: the student's source, naga's module, and the register form it runs.
#[derive(Clone, Debug)]
pub struct Program {
    /// Which stage.
    pub stage: Stage,
    /// The student's source.
    pub source: String,
    module: naga::Module,
    /// The register form.
    pub code: code::Code,
    /// The entry point's inputs, in argument order.
    pub inputs: Vec<Varying>,
    /// The entry point's outputs, in result order.
    pub outputs: Vec<Varying>,
    /// The uniforms it declared: name, and where they are in the machine's uniforms.
    pub uniforms: Vec<(String, code::Reg)>,
    /// The textures it declared, by slot.
    pub textures: Vec<String>,
    /// The declarations the student wrote (uniforms, textures, inputs, outputs).
    pub declarations: Vec<dialect::Declaration>,
    /// Where the source stands in a file, so that a run-time error is at its line there
    /// ([`Self::run_error`]) and names the file; `None` for a source of its own (the shader
    /// panel's).
    pub origin: Option<Origin>,
}

/// naga's parse errors at the student's lines, each with its complaint (a missing `;` at the
/// end of the line that lacks it).
fn parse_errors(
    e: &naga::front::glsl::ParseErrors,
    source: &str,
    adapted: &dialect::Adapted,
) -> Vec<ShaderError> {
    e.errors
        .iter()
        .map(|err| {
            let span = err
                .meta
                .to_range()
                .map_or(0..0, |r| adapted.original_range(r));
            let (mut complaint, at) = complaint::of_parse(&err.kind, source, span);
            let mut e = error_at(source, at.clone(), check::plain(&err.kind.to_string()));
            if complaint == Complaint::MissingSemicolon {
                e.message = "a `;` is missing at the end of this line".to_owned();
            }
            // naga knows a function once its body is read: a call inside the body, or above
            // the definition, is an unknown function to it.
            if let Complaint::UnknownFunction(name) = &complaint
                && glsl330::FUNCTIONS.contains(&name.as_str())
            {
                e.message = code::not_run(name);
                complaint = Complaint::NotRunYet(name.clone());
            } else if let Complaint::UnknownFunction(name) = &complaint
                && let Some(def) = lexeme::definition(source, name)
            {
                let name = name.clone();
                (e.message, complaint) = if lexeme::enclosing_function(source, at.start)
                    == Some(name.as_str())
                {
                    (
                        format!("GLSL does not allow recursion: `{name}` calls itself"),
                        Complaint::Recursion(name),
                    )
                } else if at.start > def {
                    // Defined above and called from elsewhere: no overload takes these types.
                    let parameters = lexeme::parameter_list(source, def);
                    (
                        format!(
                            "the arguments do not match the parameters of `{name}` {parameters}: check each argument's type"
                        ),
                        Complaint::ArgumentTypes { name, parameters },
                    )
                } else {
                    (
                        format!(
                            "`{name}` is called before it is defined: move its definition above, or declare it above (its first line ending in `;`)"
                        ),
                        Complaint::DefinedBelow(name),
                    )
                };
            }
            e.complaint = complaint;
            e
        })
        .collect()
}

/// What the translation could not do, as a message at its place: `%` on floats, a built-in
/// pipelens does not run yet, or the form it met.
fn unsupported(source: &str, u: code::Unsupported) -> ShaderError {
    let complaint = if u.what == translate::FLOAT_MODULO {
        Complaint::FloatModulo
    } else {
        u.function.map_or(Complaint::Other, Complaint::NotRunYet)
    };
    check::complain(error_at(source, u.at..u.at, u.what), complaint)
}

/// Compiles the student's GLSL for `stage`.
///
/// # Errors
/// Every problem found, each at its line and column: a declaration pipelens cannot adapt,
/// naga's parse and validation errors, a uniform, texture, attribute or output pipelens does
/// not know, an output never written, an operation the machine does not run.
pub fn compile(stage: Stage, source: &str) -> Result<Program, Vec<ShaderError>> {
    if let Some(e) = check::version(source) {
        return Err(vec![e]);
    }
    check::dropped_arguments(source)?;
    check::sampler_parameters(source)?;
    let mut adapted = dialect::adapt(source, stage).map_err(|errs| {
        errs.into_iter()
            .map(|e| error_at(source, e.span, e.message))
            .collect::<Vec<_>>()
    })?;
    let mut frontend = naga::front::glsl::Frontend::default();
    let options = naga::front::glsl::Options::from(match stage {
        Stage::Vertex => naga::ShaderStage::Vertex,
        Stage::Fragment => naga::ShaderStage::Fragment,
    });
    let module = frontend
        .parse(&options, &adapted.text)
        .map_err(|e| parse_errors(&e, source, &adapted))?;
    let module = modulo::read_again_splatted(module, &mut adapted, &options);
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    )
    .validate(&module)
    .map_err(|e| {
        let span = e
            .spans()
            .last()
            .and_then(|(s, _)| s.to_range())
            .map_or(0..0, |r| adapted.original_range(r));
        let message = check::validation_message(e.as_inner());
        if message.contains("builtin(position)") {
            return vec![check::complain(
                error_at(source, check::main_span(source), check::NO_POSITION),
                Complaint::NoPosition,
            )];
        }
        let mut err = error_at(source, span, message);
        err.complaint = complaint::of_text(&check::validation_chain(e.as_inner()));
        vec![err]
    })?;
    let mut errors = Vec::new();
    check::check_declarations(source, stage, &adapted, &module, &mut errors);
    let uniform_names: Vec<String> = adapted
        .declarations
        .iter()
        .filter(|d| d.storage == dialect::Storage::Uniform)
        .map(|d| d.name.clone())
        .collect();
    let textures: Vec<String> = adapted
        .declarations
        .iter()
        .filter(|d| d.storage == dialect::Storage::Texture)
        .map(|d| d.name.clone())
        .collect();
    let is_uniform = |name: &str| uniform_names.iter().any(|u| u == name);
    let texture = |name: &str| {
        let n = name.strip_prefix(dialect::TEXTURE_PREFIX)?;
        textures.iter().position(|t| t == n).map(|p| p as u32)
    };
    let code =
        match translate::Translator::translate(&module, &info, &adapted, &is_uniform, &texture) {
            Ok(c) => c,
            Err(u) => {
                errors.push(unsupported(source, u));
                return Err(errors);
            }
        };
    check::check_writes(source, stage, &adapted, &module, &code, &mut errors);
    if !errors.is_empty() {
        return Err(errors);
    }
    let (inputs, outputs) = interface_of(&module);
    let uniforms = module
        .global_variables
        .iter()
        .filter_map(|(h, g)| {
            let name = g.name.clone()?;
            match code.globals[h.index()] {
                Some((code::Root::Uniform, reg)) => Some((name, reg)),
                _ => None,
            }
        })
        .collect();
    Ok(Program {
        stage,
        source: source.to_owned(),
        module,
        code,
        inputs,
        outputs,
        uniforms,
        textures,
        declarations: adapted.declarations.clone(),
        origin: None,
    })
}

/// The entry point's inputs and outputs, from naga's bindings.
fn interface_of(module: &naga::Module) -> (Vec<Varying>, Vec<Varying>) {
    let Some(ep) = module.entry_points.first() else {
        return (Vec::new(), Vec::new());
    };
    let varying =
        |name: Option<&String>, ty: naga::Handle<naga::Type>, binding: Option<&Binding>| {
            let (location, builtin, interpolate) = match binding {
                Some(Binding::Location {
                    location,
                    interpolation,
                    ..
                }) => (
                    Some(*location),
                    None,
                    match interpolation {
                        Some(Interpolation::Flat) => Interpolate::Flat,
                        Some(Interpolation::Linear) => Interpolate::Linear,
                        _ => Interpolate::Perspective,
                    },
                ),
                Some(Binding::BuiltIn(b)) => (None, Some(*b), Interpolate::Perspective),
                None => (None, None, Interpolate::Perspective),
            };
            let name = match builtin {
                Some(BuiltIn::Position { .. }) => "gl_Position".to_owned(),
                Some(BuiltIn::FrontFacing) => "gl_FrontFacing".to_owned(),
                Some(b) => format!("{b:?}"),
                None => name.cloned().unwrap_or_default(),
            };
            Varying {
                name,
                location,
                builtin,
                components: code::components(module, &module.types[ty].inner),
                interpolate,
            }
        };
    let inputs = ep
        .function
        .arguments
        .iter()
        .map(|a| varying(a.name.as_ref(), a.ty, a.binding.as_ref()))
        .collect();
    let outputs = match ep.function.result.as_ref() {
        Some(r) => match module.types[r.ty].inner {
            TypeInner::Struct { ref members, .. } => members
                .iter()
                .map(|m| varying(m.name.as_ref(), m.ty, m.binding.as_ref()))
                .collect(),
            _ => vec![varying(None, r.ty, r.binding.as_ref())],
        },
        None => Vec::new(),
    };
    (inputs, outputs)
}

/// Where a program's uniforms take their values: the components of the uniform called
/// `name` as 32-bit words in GLSL's order, or `None` when the host sets no such uniform.
pub trait UniformValues {
    /// The value of the uniform `name`.
    fn components(&self, name: &str) -> Option<Vec<u32>>;
}

impl Program {
    /// A machine to run this program, its uniforms zero.
    #[must_use]
    pub fn machine(&self) -> Machine<'_> {
        Machine::new(&self.code)
    }

    /// Fills a machine's uniforms from `values`.
    pub fn set_uniforms(&self, machine: &mut Machine<'_>, values: &dyn UniformValues) {
        for (name, reg) in &self.uniforms {
            if let Some(bits) = values.components(name) {
                machine.set_uniform(*reg, &bits);
            }
        }
    }

    /// A [`RunError`] as a message at its line.
    #[must_use]
    pub fn run_error(&self, e: &RunError) -> ShaderError {
        let error = ShaderError {
            complaint: e.complaint.clone(),
            ..error_at(&self.source, e.at..e.at, e.message.clone())
        };
        match &self.origin {
            Some(origin) => origin.place(error),
            None => error,
        }
    }

    /// A message at the declaration of `name` (or at `main` when it has none).
    #[must_use]
    pub fn error_at_name(&self, name: &str, message: String) -> ShaderError {
        let span = self
            .declarations
            .iter()
            .find(|d| d.name == name)
            .map_or_else(|| check::main_span(&self.source), |d| d.name_span.clone());
        error_at(&self.source, span, message)
    }

    /// Whether the program has a `discard` anywhere.
    #[must_use]
    pub fn can_discard(&self) -> bool {
        fn kills(stmts: &[code::Stmt]) -> bool {
            stmts.iter().any(|s| match s {
                code::Stmt::Kill { .. } => true,
                code::Stmt::Block(b) => kills(b),
                code::Stmt::If { accept, reject, .. } => kills(accept) || kills(reject),
                code::Stmt::Switch { cases, .. } => cases.iter().any(|(_, b, _)| kills(b)),
                code::Stmt::Loop {
                    body, continuing, ..
                } => kills(body) || kills(continuing),
                _ => false,
            })
        }
        self.code.functions.iter().any(|f| kills(&f.body))
    }
}
