//! A compiled shader ([`Program`]): the stage it runs at, what it declared, its inputs and
//! outputs as naga's bindings give them, and the register form the machine runs.

use naga::{Binding, BuiltIn, Interpolation, TypeInner};

use crate::error::main_span;
use crate::error::{Origin, ShaderError, error_at};
use crate::machine::{Machine, RunError};
pub use crate::stage::Stage;
use crate::{dialect, register_form};

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
    pub(crate) module: naga::Module,
    /// The register form.
    pub code: register_form::Code,
    /// The entry point's inputs, in argument order.
    pub inputs: Vec<Varying>,
    /// The entry point's outputs, in result order.
    pub outputs: Vec<Varying>,
    /// The uniforms it declared: name, and where they are in the machine's uniforms.
    pub uniforms: Vec<(String, register_form::Reg)>,
    /// The textures it declared, by slot.
    pub textures: Vec<String>,
    /// The declarations the student wrote (uniforms, textures, inputs, outputs).
    pub declarations: Vec<dialect::Declaration>,
    /// Where the source stands in a file, so that a run-time error is at its line there
    /// ([`Self::run_error`]) and names the file; `None` for a source of its own (the shader
    /// panel's).
    pub origin: Option<Origin>,
    /// Where a program compiled with a watch keeps what the watch saw (`crate::probe`).
    pub watch: Option<crate::watched::WatchPlaces>,
}

/// The entry point's inputs and outputs, from naga's bindings.
pub(crate) fn interface_of(module: &naga::Module) -> (Vec<Varying>, Vec<Varying>) {
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
                components: crate::type_layout::components(module, &module.types[ty].inner),
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
            .map_or_else(|| main_span(&self.source), |d| d.name_span.clone());
        error_at(&self.source, span, message)
    }

    /// Whether the program has a `discard` anywhere.
    #[must_use]
    pub fn can_discard(&self) -> bool {
        fn kills(stmts: &[register_form::Stmt]) -> bool {
            stmts.iter().any(|s| match s {
                register_form::Stmt::Kill { .. } => true,
                register_form::Stmt::Block(b) => kills(b),
                register_form::Stmt::If(i) => kills(&i.accept) || kills(&i.reject),
                register_form::Stmt::Switch(s) => s.cases.iter().any(|(_, b, _)| kills(b)),
                register_form::Stmt::Loop(l) => kills(&l.body) || kills(&l.continuing),
                _ => false,
            })
        }
        self.code.functions.iter().any(|f| kills(&f.body))
    }
}
