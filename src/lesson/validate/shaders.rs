//! `shader = { vertex = "x.vert", fragment = "x.frag", inside = "inside.glsl" }` for the scene
//! or an object: each stage (and the rasterizer's inside test) a GLSL file beside the lesson, or
//! the GLSL itself written in the lesson; linked by [`pipeline::shader::link()`] (the inside test
//! compiled by [`pipeline::shader::compile_inside`]), every message at its line and column in the
//! file it is in.

use std::ops::Range;
use std::path::Path;
use std::sync::Arc;

use pipeline::scene::{ObjectShader, StudentCode};
use pipeline::shader::{HookKind, Hooks, Stage};
use toml::Spanned;

use super::Checker;
use crate::lesson::Diagnostic;
use crate::lesson::raw::RawShader;

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
fn source(c: &mut Checker<'_>, v: &Spanned<String>, base: &Path) -> Option<(String, Origin)> {
    let written = v.get_ref();
    let one_line = !written.trim().contains('\n');
    if one_line
        && SHADER_FILE_ENDINGS
            .iter()
            .any(|e| written.trim().ends_with(e))
    {
        let path = c.file_beside(v.span(), base, written.trim())?;
        return match std::fs::read_to_string(&path) {
            Ok(text) => Some((text, Origin::File(path.display().to_string()))),
            Err(e) => {
                c.error(v.span(), format!("cannot read {}: {e}", path.display()));
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
    base: &Path,
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
                    let message = format!("{} shader: {}", e.stage.name(), e.error.message);
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
                    let message = format!("{}: {}", hook_name(kind), e.message);
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
    ok.then_some(StudentCode { shader, hooks })
}

/// How a message names the function it is about.
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
