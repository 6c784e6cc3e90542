//! `shader = { vertex = "x.vert", fragment = "x.frag", inside = "inside.glsl" }` for the scene
//! or an object: each stage (and the rasterizer's inside test) a GLSL file beside the lesson, or
//! the GLSL itself written in the lesson; linked by [`pipeline::shader::link()`] (the inside test
//! compiled by [`pipeline::shader::compile_inside`]), every message at its line and column in the
//! file it is in.

use std::ops::Range;
use std::sync::Arc;

use std::collections::BTreeMap;

use pipeline::scene::{ObjectShader, StudentCode};
use pipeline::shader::own_uniform::{OwnKind, OwnUniform};
use pipeline::shader::{HookKind, Hooks, Stage};
use toml::Spanned;

use super::Checker;
use crate::lesson::Diagnostic;
use crate::lesson::folder::Folder;
use crate::lesson::raw::{RawShader, RawUniformValue};

/// The endings of a shader file's name: a value ending so (on one line) names a file.
pub const SHADER_FILE_ENDINGS: [&str; 5] = [".vert", ".frag", ".glsl", ".vs", ".fs"];

/// Where a stage's source came from, to put its messages there.
enum Origin {
    /// A file: its name as written and its text.
    File(String),
    /// Written in the lesson: the source's first byte in the lesson's text, if the source
    /// stands there as it is (no escapes).
    Inline(Option<usize>, Range<usize>),
}

/// One stage's source, read from its file or taken as written.
fn source(c: &mut Checker<'_>, v: &Spanned<String>, base: &Folder) -> Option<(String, Origin)> {
    let written = v.get_ref();
    let one_line = !written.trim().contains('\n');
    if one_line
        && SHADER_FILE_ENDINGS
            .iter()
            .any(|e| written.trim().ends_with(e))
    {
        let file = c.read_beside(v.span(), base, written.trim())?;
        return match String::from_utf8(file.bytes.to_vec()) {
            Ok(text) => Some((text, Origin::File(file.shown))),
            Err(_) => {
                c.error(
                    v.span(),
                    format!("cannot read {}: it is not UTF-8 text", file.shown),
                );
                None
            }
        };
    }
    let at = c
        .text
        .get(v.span())
        .and_then(|raw| raw.find(written.as_str()))
        .map(|k| v.span().start + k);
    Some((written.clone(), Origin::Inline(at, v.span())))
}

/// The code `raw` names: linked shaders (a stage left out is pipelens' own) and the inside
/// test, or diagnostics (in the shader files or the lesson).
pub(in crate::lesson) fn shader(
    c: &mut Checker<'_>,
    raw: &Spanned<RawShader>,
    base: &Folder,
) -> Option<StudentCode> {
    let r = raw.get_ref();
    if r.vertex.is_none()
        && r.fragment.is_none()
        && HookKind::ALL.iter().all(|k| r.hook(*k).is_none())
    {
        c.error(raw.span(), "`shader` needs a `vertex` or a `fragment` shader (a file such as \"toon.frag\", or the GLSL itself), or an `inside`, `depth_test`, `de_casteljau`, `shadow_matrix` or `bezier_patch` function");
        return None;
    }
    let vertex = r.vertex.as_ref().map(|v| source(c, v, base));
    let fragment = r.fragment.as_ref().map(|v| source(c, v, base));
    let functions = HookKind::ALL.map(|k| (k, r.hook(k).map(|v| source(c, v, base))));
    // A stage that named a missing file has its diagnostic already.
    if [&vertex, &fragment]
        .into_iter()
        .chain(functions.iter().map(|(_, f)| f))
        .any(|s| matches!(s, Some(None)))
    {
        return None;
    }
    let (vertex, fragment) = (vertex.flatten(), fragment.flatten());
    let mut ok = true;
    let shader = if vertex.is_none() && fragment.is_none() {
        None
    } else {
        match pipeline::shader::link(
            vertex.as_ref().map(|v| v.0.as_str()),
            fragment.as_ref().map(|f| f.0.as_str()),
        ) {
            Ok(programs) => Some(ObjectShader {
                programs: Arc::new(
                    programs.placed(placed(c, vertex.as_ref()), placed(c, fragment.as_ref())),
                ),
                time: 0.0,
            }),
            Err(errors) => {
                for e in errors {
                    let given = match e.stage {
                        Stage::Vertex => vertex.as_ref(),
                        Stage::Fragment => fragment.as_ref(),
                    };
                    let message = format!("{} shader: {}", e.stage.name(), said(&e.error));
                    place(c, given, raw.span(), &e.error, message);
                }
                ok = false;
                None
            }
        }
    };
    let mut hook = |kind: HookKind, given: Option<(String, Origin)>| {
        let result = given
            .as_ref()
            .map(|g| pipeline::shader::compile_hook(kind, &g.0))?;
        match result {
            Ok(hook) => Some(hook),
            Err(errors) => {
                for e in errors {
                    let message = format!("{}: {}", hook_name(kind), said(&e));
                    place(c, given.as_ref(), raw.span(), &e, message);
                }
                ok = false;
                None
            }
        }
    };
    let mut hooks = Hooks::default();
    for (kind, given) in functions {
        if let Some(compiled) = hook(kind, given.flatten()) {
            hooks.set(compiled);
        }
    }
    let uniforms = r
        .uniforms
        .as_ref()
        .map(|given| own_values(c, given, shader.as_ref()))
        .unwrap_or_default();
    ok.then_some(StudentCode {
        shader,
        hooks,
        uniforms,
    })
}

/// `shader.uniforms`: each a uniform of the shaders' own, its value of its type and inside its
/// control's range (an `int` a whole number).
fn own_values(
    c: &mut Checker<'_>,
    given: &BTreeMap<Spanned<String>, Spanned<RawUniformValue>>,
    shader: Option<&ObjectShader>,
) -> BTreeMap<String, Vec<f32>> {
    let own: Vec<OwnUniform> = shader.map_or_else(Vec::new, |sh| {
        let mut own = sh.programs.vertex.own_uniforms();
        own.extend(sh.programs.fragment.own_uniforms());
        own
    });
    let mut values = BTreeMap::new();
    for (name, value) in given {
        let Some(u) = own.iter().find(|u| u.name == *name.get_ref()) else {
            let names: Vec<&str> = own.iter().map(|u| u.name.as_str()).collect();
            c.error(
                name.span(),
                format!(
                    "the shaders declare no uniform of their own called `{}`{}",
                    name.get_ref(),
                    if names.is_empty() {
                        " (they declare none: `uniform float k; // 0..1 = 0.5` is one)".to_owned()
                    } else {
                        format!(
                            "; theirs: {}{}",
                            names.join(", "),
                            pipeline::shader::suggest::did_you_mean(
                                name.get_ref(),
                                names.iter().copied(),
                                pipeline::shader::suggest::Quote::Code
                            )
                        )
                    }
                ),
            );
            continue;
        };
        match own_value(u, value.get_ref()) {
            Ok(v) => {
                values.insert(u.name.clone(), v);
            }
            Err(e) => c.error(value.span(), format!("`{}`: {e}", u.name)),
        }
    }
    values
}

/// A value written for `u`, checked against its type and range.
fn own_value(u: &OwnUniform, value: &RawUniformValue) -> Result<Vec<f32>, String> {
    #[allow(clippy::cast_possible_truncation)]
    let v: Vec<f32> = match (u.kind, value) {
        (OwnKind::Bool, RawUniformValue::Bool(b)) => vec![f32::from(u8::from(*b))],
        (OwnKind::Float | OwnKind::Int, RawUniformValue::Number(x)) => vec![*x as f32],
        (OwnKind::Vec2, RawUniformValue::Pair(t)) => t.iter().map(|x| *x as f32).collect(),
        (OwnKind::Vec3, RawUniformValue::Triple(t)) => t.iter().map(|x| *x as f32).collect(),
        (OwnKind::Vec4, RawUniformValue::Quad(t)) => t.iter().map(|x| *x as f32).collect(),
        (kind, _) => {
            return Err(format!(
                "a {} takes {}",
                kind.glsl(),
                match kind {
                    OwnKind::Bool => "true or false",
                    OwnKind::Vec2 => "two numbers [x, y]",
                    OwnKind::Vec3 => "three numbers [x, y, z]",
                    OwnKind::Vec4 => "four numbers [x, y, z, w]",
                    _ => "a number",
                }
            ));
        }
    };
    if u.kind == OwnKind::Int && v[0].fract() != 0.0 {
        return Err(format!("an int takes a whole number, got {}", v[0]));
    }
    let (lo, hi) = u.range;
    if u.kind != OwnKind::Bool && v.iter().any(|x| !(lo..=hi).contains(x)) {
        let written: Vec<String> = v.iter().map(ToString::to_string).collect();
        return Err(format!(
            "{} is outside its control's range {lo}..{hi} (the comment after its declaration)",
            written.join(", ")
        ));
    }
    Ok(v)
}

/// How a message names the function it is about.
/// A compile message as a lesson's diagnostic says it: the sentence the app shows the student
/// (`` `eye` is not declared here: … ``), in English as diagnostics are, or naga's words where
/// no sentence covers the mistake.
fn said(e: &pipeline::shader::ShaderError) -> String {
    crate::vocabulary::compile::complaint(&e.complaint, crate::vocabulary::Lang::EN)
        .unwrap_or_else(|| e.message.clone())
}

fn hook_name(kind: HookKind) -> &'static str {
    match kind {
        HookKind::Inside => "inside test",
        HookKind::DepthTest => "depth test",
        HookKind::Curve => "de Casteljau",
        HookKind::ShadowMatrix => "shadow matrix",
        HookKind::Patch => "Bézier patch",
    }
}

/// Where a stage's source stands, for its run-time errors: a shader file from its start, GLSL
/// in the lesson at its first character there (none where the lesson's text escapes it).
fn placed(c: &Checker<'_>, given: Option<&(String, Origin)>) -> Option<pipeline::shader::Origin> {
    let (file, line, column) = match given? {
        (_, Origin::File(name)) => (name.clone(), 1, 1),
        (_, Origin::Inline(Some(at), _)) => {
            let d = Diagnostic::at(c.file, c.text, *at..*at, "");
            (c.file.to_owned(), d.line, d.column)
        }
        (_, Origin::Inline(None, _)) => return None,
    };
    Some(pipeline::shader::Origin { file, line, column })
}

/// A shader's message where its source is: in its file, at its place in the lesson, or at the
/// `shader` table (pipelens' own stage: only a link error can point there).
fn place(
    c: &mut Checker<'_>,
    given: Option<&(String, Origin)>,
    table: Range<usize>,
    error: &pipeline::shader::ShaderError,
    message: String,
) {
    match given {
        Some((text, Origin::File(name))) => {
            c.found
                .push(Diagnostic::at(name, text, error.span.clone(), message));
        }
        Some((_, Origin::Inline(Some(at), _))) => {
            c.error(at + error.span.start..at + error.span.end, message);
        }
        Some((_, Origin::Inline(None, span))) => {
            c.error(
                span.clone(),
                format!("{message} (line {} of the shader)", error.line),
            );
        }
        None => c.error(table, message),
    }
}

/// Gives every object the scene's `code`, where the object has none of its own of that kind (an
/// object's own `shader = { … }` comes first).
pub(in crate::lesson) fn give(objects: &mut [pipeline::scene::Object], code: &StudentCode) {
    for o in objects {
        if o.code.shader.is_none() {
            o.code.shader.clone_from(&code.shader);
        }
        for hook in code.hooks.iter() {
            if o.code.hooks.get(hook.kind).is_none() {
                o.code.hooks.set(hook.clone());
            }
        }
    }
}
