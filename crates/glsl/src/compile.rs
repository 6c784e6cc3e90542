//! [`compile`]: the student's GLSL through the dialect, naga's parser and validator, the
//! checks against what pipelens provides, and the translation to the register form; every
//! message at the student's line and column.

use crate::complaint::{self, Complaint};
use crate::error::{ShaderError, error_at};
use crate::program::{Program, interface_of};
use crate::stage::Stage;
use crate::{check, dialect, glsl330, lexeme, modulo, register_form, translate};

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
                e.message = register_form::not_run(name);
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
fn unsupported(source: &str, u: register_form::Unsupported) -> ShaderError {
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
    compile_with(stage, source, "")
}

/// [`compile`] with `extra`, GLSL of pipelens' own, at the end of what is put before the
/// student's code: its functions are pipelens' (kept out of the trace).
pub(crate) fn compile_with(
    stage: Stage,
    source: &str,
    extra: &str,
) -> Result<Program, Vec<ShaderError>> {
    if let Some(e) = check::version(source) {
        return Err(vec![e]);
    }
    check::dropped_arguments(source)?;
    check::sampler_parameters(source)?;
    let mut adapted = dialect::adapt(source, stage, extra).map_err(|errs| {
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
                error_at(source, crate::error::main_span(source), check::NO_POSITION),
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
                Some((register_form::Root::Uniform, reg)) => Some((name, reg)),
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
        watch: None,
    })
}
