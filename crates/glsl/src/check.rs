//! The checks that turn naga's findings and pipelens' own into a student's messages: naga's
//! words said plainly, the uniforms, textures and attributes pipelens provides (with "did you
//! mean"), uniforms never assigned, outputs always written.

use crate::complaint::Complaint;
use crate::error::{ShaderError, error_at, main_span};
use crate::stage::Stage;
use crate::suggest::{Quote, did_you_mean, nearest};
use crate::trace::glsl_type;
use crate::{dialect, interface, register_form};

/// naga's words for a student: handles such as `[7]` and `naga::ir::` paths left out.
pub(super) fn plain(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut skip = false;
    for c in message.chars() {
        match c {
            '[' => skip = true,
            ']' if skip => skip = false,
            _ if !skip => out.push(c),
            _ => {}
        }
    }
    out.replace("naga::ir::", "")
        .replace("  ", " ")
        .replace(" of  ", " of ")
        .trim()
        .to_owned()
}

/// A validation error's causes, outermost first, joined by `: `.
pub(super) fn validation_chain(e: &naga::valid::ValidationError) -> String {
    chain_of(e).join(": ")
}

/// A validation error and each of its sources, outermost first.
fn chain_of(e: &naga::valid::ValidationError) -> Vec<String> {
    use std::error::Error;
    let mut chain = vec![e.to_string()];
    let mut source = e.source();
    while let Some(s) = source {
        chain.push(s.to_string());
        source = s.source();
    }
    chain
}

/// A validation error as one sentence: the innermost cause, said plainly.
pub(super) fn validation_message(e: &naga::valid::ValidationError) -> String {
    let chain = chain_of(e);
    let inner = chain.last().cloned().unwrap_or_default();
    if inner.contains("doesn't match the type stored in") {
        return "the value's type is not the variable's type: a vec3 into a vec4 needs building, \
                vec4(v, 1.0); a vec4 into a vec3 needs picking, v.xyz or v.rgb; a float from \
                an int needs float(i)"
            .to_owned();
    }
    if inner.contains("expression None does not match") {
        return "this function is declared to return a value but can end without `return`: \
                every path through it must end in `return …;`"
            .to_owned();
    }
    if inner.contains("InvalidReturnType") || inner.contains("return type") {
        return format!(
            "the returned value's type is not the function's return type ({})",
            plain(&inner)
        );
    }
    plain(&chain.join(": "))
}

/// Uniforms and textures pipelens knows, with the right types; attributes it feeds.
pub(super) fn check_declarations(
    source: &str,
    stage: Stage,
    adapted: &dialect::Adapted,
    module: &naga::Module,
    errors: &mut Vec<ShaderError>,
) {
    use dialect::Storage;
    for d in &adapted.declarations {
        let error = match d.storage {
            Storage::Uniform => uniform_declaration(source, d, module),
            Storage::Texture => texture_declaration(source, d),
            Storage::Input if stage == Stage::Vertex => attribute_declaration(source, d),
            _ => None,
        };
        errors.extend(error);
    }
    let outputs = adapted
        .declarations
        .iter()
        .filter(|d| d.storage == Storage::Output)
        .count();
    if stage == Stage::Fragment && outputs > 1 {
        let d = adapted
            .declarations
            .iter()
            .rfind(|d| d.storage == Storage::Output);
        errors.push(complain(
            error_at(
                source,
                d.map_or(0..0, |d| d.span.clone()),
                "pipelens draws into one colour buffer: declare one `out vec4` for the fragment's colour",
            ),
            Complaint::OneColourOutput,
        ));
    }
}

/// A uniform's declaration: one pipelens sets, with its type; or one of the student's own
/// (`crate::own_uniform`): a `float`, `int`, `bool` or `vec3` whose comment, if it starts like
/// a control, is one. A name one letter or two from a uniform pipelens sets, with no control,
/// is taken for that uniform misspelt.
fn uniform_declaration(
    source: &str,
    d: &dialect::Declaration,
    module: &naga::Module,
) -> Option<ShaderError> {
    let Some(spec) = interface::uniform(&d.name) else {
        return own_uniform_declaration(source, d, module);
    };
    let written = glsl_type_of_global(module, &d.name).unwrap_or_default();
    let expected = spec.declared_type();
    (written != expected).then(|| {
        complain(
            error_at(
                source,
                d.span.clone(),
                format!(
                    "pipelens' `{}` is a {expected} ({}), declared here as {written}",
                    d.name, spec.meaning
                ),
            ),
            Complaint::UniformType {
                name: d.name.clone(),
                written,
            },
        )
    })
}

/// A uniform pipelens does not set: the student's own when a control can set its type (and
/// its comment, if it starts like a control, is one), else a message.
fn own_uniform_declaration(
    source: &str,
    d: &dialect::Declaration,
    module: &naga::Module,
) -> Option<ShaderError> {
    use crate::own_uniform::{OwnKind, comment_after, control, own_uniform};
    let known: Vec<&str> = interface::UNIFORMS
        .iter()
        .flat_map(|u| u.names.iter().copied())
        .collect();
    let written = glsl_type_of_global(module, &d.name).unwrap_or_default();
    let controlled =
        comment_after(source, d.span.end).is_some_and(|c| control(c).is_ok_and(|c| c.is_some()));
    let suggestion = nearest(&d.name, known.iter().copied());
    // Misspelt: `ligth_pos`, close to a uniform pipelens sets of the same type, with no
    // control of its own (`uniform float k;` is not a misspelt `ka`: that is a vec3).
    let misspelt = !controlled
        && suggestion
            .and_then(interface::uniform)
            .is_some_and(|u| u.glsl == written);
    match OwnKind::of(&written) {
        _ if misspelt => {}
        Some(kind) => {
            return own_uniform(source, d, kind).err().map(|why| {
                complain(
                    error_at(
                        source,
                        d.span.clone(),
                        format!(
                            "`{}` is a uniform of your own; its comment reads like its control (`// MIN..MAX = VALUE`) but {why}",
                            d.name
                        ),
                    ),
                    Complaint::OwnUniformControl {
                        name: d.name.clone(),
                        why,
                    },
                )
            });
        }
        None => {}
    }
    let firsts: Vec<&str> = interface::UNIFORMS.iter().map(|u| u.names[0]).collect();
    Some(complain(
        error_at(
            source,
            d.name_span.clone(),
            format!(
                "pipelens sets no uniform called `{}`; the uniforms it sets: {}. A uniform of your own is a float, int, bool, vec2, vec3 or vec4, its control in a comment after it: `// 0..4 = 1.5`{}",
                d.name,
                firsts.join(", "),
                did_you_mean(&d.name, known.iter().copied(), Quote::Code),
            ),
        ),
        Complaint::UnknownUniform {
            name: d.name.clone(),
            suggestion: suggestion.map(str::to_owned),
        },
    ))
}

/// A texture's declaration: one pipelens binds.
fn texture_declaration(source: &str, d: &dialect::Declaration) -> Option<ShaderError> {
    if let Some(slot) = interface::texture_slot(&d.name) {
        let expected = slot.sampler();
        return (d.type_name != expected).then(|| {
            complain(
                error_at(
                    source,
                    d.name_span.clone(),
                    format!(
                        "pipelens binds `{}` as a {expected}, declared here as {}",
                        d.name, d.type_name
                    ),
                ),
                Complaint::TextureType {
                    name: d.name.clone(),
                    written: d.type_name.clone(),
                    expected,
                },
            )
        });
    }
    let known = interface::TEXTURES.map(|(n, _)| n);
    Some(complain(
        error_at(
            source,
            d.name_span.clone(),
            format!(
                "pipelens binds no texture called `{}`; the object's texture is `uniform sampler2D tex;`, its bump or normal map `uniform sampler2D detail;`, the cube map it mirrors `uniform samplerCube environment;`{}",
                d.name,
                did_you_mean(&d.name, known.iter().copied(), Quote::Code)
            ),
        ),
        Complaint::UnknownTexture {
            name: d.name.clone(),
            suggestion: nearest(&d.name, known.iter().copied()).map(str::to_owned),
        },
    ))
}

/// A vertex shader's input: an attribute pipelens feeds.
fn attribute_declaration(source: &str, d: &dialect::Declaration) -> Option<ShaderError> {
    if interface::attribute_location(&d.name).is_some() {
        return None;
    }
    let names: Vec<&str> = interface::ATTRIBUTES
        .iter()
        .flat_map(|a| a.names.iter().copied())
        .collect();
    let declared: Vec<String> = interface::ATTRIBUTES
        .iter()
        .map(|a| format!("{} {}", a.glsl, a.names[0]))
        .collect();
    Some(complain(
        error_at(
            source,
            d.name_span.clone(),
            format!(
                "pipelens feeds no vertex attribute called `{}`; the attributes: {}{}",
                d.name,
                declared.join(", "),
                did_you_mean(&d.name, names.iter().copied(), Quote::Code),
            ),
        ),
        Complaint::UnknownAttribute {
            name: d.name.clone(),
            suggestion: nearest(&d.name, names.iter().copied()).map(str::to_owned),
        },
    ))
}

/// The versions of GLSL there are (OpenGL's and OpenGL ES's), as `#version` writes them.
const VERSIONS: [u32; 17] = [
    100, 110, 120, 130, 140, 150, 300, 310, 320, 330, 400, 410, 420, 430, 440, 450, 460,
];

/// A `#version` line GLSL refuses (`#version 999 core`, `#version 3.30`, an unknown profile):
/// pipelens reads every shader alike, but the student's shader must also compile on the
/// course's real OpenGL.
pub(super) fn version(source: &str) -> Option<ShaderError> {
    let span = dialect::version_directive(source)?;
    let written = source[span.clone()]
        .trim_start_matches('#')
        .trim_start()
        .strip_prefix("version")?
        .trim();
    let mut words = written.split_whitespace();
    let number = words.next().and_then(|n| n.parse::<u32>().ok());
    let profile = words.next();
    let known = number.is_some_and(|n| VERSIONS.contains(&n))
        && matches!(profile, None | Some("core" | "compatibility" | "es"))
        && words.next().is_none();
    (!known).then(|| {
        complain(
            error_at(
                source,
                span.start..span.start + source[span.clone()].trim_end().len(),
                format!(
                    "GLSL has no version `{written}`: write `#version 330 core` (or 110, 120 for the old GLSL)"
                ),
            ),
            Complaint::InvalidVersion(written.to_owned()),
        )
    })
}

/// The built-in functions naga misreads, each call refused at its name: `texelFetchOffset`,
/// whose offset naga drops (it would be drawn without it), and GLSL 1.20's 1D and 3D lookups,
/// which naga reads as constructors of its `texture1D` and `texture3D` types ("Too many
/// arguments") — pipelens binds no 1D or 3D texture.
///
/// # Errors
/// Each such call.
pub(super) fn dropped_arguments(source: &str) -> Result<(), Vec<ShaderError>> {
    const DROPPED: [&str; 9] = [
        "texelFetchOffset",
        "texture1D",
        "texture1DProj",
        "texture1DLod",
        "texture1DProjLod",
        "texture3D",
        "texture3DProj",
        "texture3DLod",
        "texture3DProjLod",
    ];
    let errors = super::lexeme::calls(source)
        .into_iter()
        .filter(|l| DROPPED.contains(&&source[l.span.clone()]))
        .map(|l| {
            let name = &source[l.span.clone()];
            complain(
                error_at(source, l.span.clone(), super::register_form::not_run(name)),
                Complaint::NotRunYet(name.to_owned()),
            )
        })
        .collect::<Vec<_>>();
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}

/// A sampler of a kind pipelens does not bind declared as a function's parameter (`vec4
/// look(sampler3D s, vec3 r)`): valid GLSL, said at the type rather than naga's "Expected
/// RightParen". A `sampler2D` or `samplerCube` parameter runs (see `dialect/sampler_arguments.rs`).
///
/// # Errors
/// Each such parameter.
pub(super) fn sampler_parameters(source: &str) -> Result<(), Vec<ShaderError>> {
    use super::lexeme::{Kind, lex};
    const SAMPLERS: [&str; 8] = [
        "sampler1D",
        "sampler3D",
        "sampler1DShadow",
        "sampler2DShadow",
        "samplerCubeShadow",
        "sampler1DArray",
        "sampler2DArray",
        "sampler2DRect",
    ];
    let (mut braces, mut parens) = (0i32, 0i32);
    let mut errors = Vec::new();
    for l in lex(source) {
        let text = &source[l.span.clone()];
        match text {
            "{" => braces += 1,
            "}" => braces -= 1,
            "(" => parens += 1,
            ")" => parens -= 1,
            ty if braces == 0 && parens > 0 && l.kind == Kind::Word && SAMPLERS.contains(&ty) => {
                errors.push(complain(
                    error_at(
                        source,
                        l.span.clone(),
                        format!(
                            "pipelens passes only a `sampler2D` or a `samplerCube` to a function: it binds no `{ty}`"
                        ),
                    ),
                    Complaint::SamplerParameter(ty.to_owned()),
                ));
            }
            _ => {}
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}

/// `error` with the mistake `complaint` as data.
#[must_use]
pub fn complain(mut error: ShaderError, complaint: Complaint) -> ShaderError {
    error.complaint = complaint;
    error
}

/// The GLSL spelling of a global's type.
pub(super) fn glsl_type_of_global(module: &naga::Module, name: &str) -> Option<String> {
    let g = module
        .global_variables
        .iter()
        .find(|(_, g)| g.name.as_deref() == Some(name))?
        .1;
    Some(glsl_type(module, g.ty))
}

/// Uniforms are read-only; the outputs must be written.
pub(super) fn check_writes(
    source: &str,
    stage: Stage,
    adapted: &dialect::Adapted,
    module: &naga::Module,
    code: &register_form::Code,
    errors: &mut Vec<ShaderError>,
) {
    let mut stores: Vec<(usize, register_form::Root, String)> = Vec::new();
    for f in &code.functions {
        collect_stores(&f.body, &mut stores);
    }
    for (at, root, name) in &stores {
        if *root == register_form::Root::Uniform {
            errors.push(complain(
                error_at(
                    source,
                    *at..*at,
                    format!("`{name}` is a uniform: a shader reads it, it cannot assign to it"),
                ),
                Complaint::UniformWritten(name.clone()),
            ));
        }
    }
    // The entry point's wrapper stores inputs into their globals; the student's `main` must
    // store into each output.
    let main = code.functions.len().checked_sub(2);
    let written = |name: &str| {
        stores.iter().any(|(_, _, n)| n == name)
            && main.is_some_and(|m| {
                code.functions[..=m]
                    .iter()
                    .any(|f| stores_into(&f.body, name))
            })
    };
    match stage {
        Stage::Vertex if !written("gl_Position") => {
            let at = main_span(source);
            errors.push(complain(
                error_at(source, at, NO_POSITION),
                Complaint::NoPosition,
            ));
        }
        Stage::Fragment => {
            let out = adapted
                .declarations
                .iter()
                .find(|d| d.storage == dialect::Storage::Output);
            let name = out.map_or(dialect::FRAG_COLOR, |d| d.name.as_str());
            let declared = out.is_some()
                || module
                    .global_variables
                    .iter()
                    .any(|(_, g)| g.name.as_deref() == Some(dialect::FRAG_COLOR));
            if !declared {
                errors.push(complain(
                    error_at(source, main_span(source), "the fragment shader has no output: declare `out vec4 color;` and write the fragment's colour into it"),
                    Complaint::NoOutput,
                ));
            } else if !written(name) {
                let span = out.map_or_else(|| main_span(source), |d| d.span.clone());
                let name = out.map_or("gl_FragColor", |d| d.name.as_str());
                errors.push(complain(
                    error_at(
                        source,
                        span,
                        format!("the fragment shader never writes `{name}`: the fragment would have no colour"),
                    ),
                    Complaint::OutputNotWritten(name.to_owned()),
                ));
            }
        }
        Stage::Vertex => {}
    }
}

/// What a vertex shader without `gl_Position` is told.
pub(super) const NO_POSITION: &str = "the vertex shader never writes `gl_Position` (the clip-space position): \
                           add `gl_Position = mvp * vec4(position, 1.0);`";

pub(super) fn stores_into(stmts: &[register_form::Stmt], name: &str) -> bool {
    let mut s = Vec::new();
    collect_stores(stmts, &mut s);
    s.iter().any(|(_, _, n)| n == name)
}

pub(super) fn collect_stores(
    stmts: &[register_form::Stmt],
    out: &mut Vec<(usize, register_form::Root, String)>,
) {
    use register_form::Stmt;
    for s in stmts {
        match s {
            Stmt::Store { at, place, .. } => out.push((*at, place.root, place.name.clone())),
            Stmt::Block(b) => collect_stores(b, out),
            Stmt::If(i) => {
                collect_stores(&i.accept, out);
                collect_stores(&i.reject, out);
            }
            Stmt::Switch(s) => s.cases.iter().for_each(|(_, b, _)| collect_stores(b, out)),
            Stmt::Loop(l) => {
                collect_stores(&l.body, out);
                collect_stores(&l.continuing, out);
            }
            _ => {}
        }
    }
}
