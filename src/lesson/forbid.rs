//! A lab that asks the student to compute something does not take pipelens' own as the answer:
//! its `exercise.forbid` lists the uniforms (`view`, `projection`, `normal_matrix`) the student's
//! code may not declare and the functions (`texture`) it may not call. A name pipelens sets as a
//! uniform is refused where it is declared `uniform`; any other name where it is called. A local
//! variable that happens to be called `view` is no shortcut.

use crate::vocabulary::Lang;

/// A forbidden name found in the student's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shortcut {
    /// The name.
    pub name: String,
    /// Whether it is a uniform pipelens sets (else a function).
    pub uniform: bool,
    /// The file it is in, as the shader panel's tab names it (`shader.vert`, `inside.glsl`).
    pub file: String,
    /// Its line (from 1).
    pub line: usize,
}

impl Shortcut {
    /// Why the check refuses it, in words.
    #[must_use]
    pub fn words(&self, lang: Lang) -> String {
        let (name, file, line) = (&self.name, &self.file, self.line);
        lang.t_with(
            if self.uniform {
                "forbid-own-uniform"
            } else {
                "forbid-own-function"
            },
            &[("file", file), ("line", &line), ("name", name)],
        )
    }
}

/// The student's sources in a scene's code, each with the file name the shader panel's Save
/// gives it: `shader.vert`, `shader.frag`, `inside.glsl`, …
#[must_use]
pub fn sources(code: &pipeline::scene::StudentCode) -> Vec<(String, &str)> {
    files(code.shader.as_ref(), |kind| code.hooks.get(kind))
}

/// The sources a shader pair and a set of functions hold, named as [`sources`] names them.
#[must_use]
pub fn files<'a>(
    shader: Option<&'a pipeline::scene::ObjectShader>,
    hook: impl Fn(pipeline::shader::HookKind) -> Option<&'a pipeline::shader::Hook>,
) -> Vec<(String, &'a str)> {
    let mut out = Vec::new();
    if let Some(sh) = shader {
        out.push(("shader.vert".to_owned(), sh.programs.vertex.source.as_str()));
        out.push((
            "shader.frag".to_owned(),
            sh.programs.fragment.source.as_str(),
        ));
    }
    for kind in pipeline::shader::HookKind::ALL {
        if let Some(h) = hook(kind) {
            out.push((format!("{}.glsl", kind.key()), h.source.as_str()));
        }
    }
    out
}

/// The first use of a forbidden name in `sources` (each a file name and its text), in the
/// order given: a `uniform` declaration of a name pipelens sets as a uniform, a call of any
/// other name. Comments are skipped, and so is a file the student left as the lab's `starter`
/// has it (pipelens' own vertex shader may read a texture where the lab is about the fragment
/// stage's).
#[must_use]
pub fn find(
    forbid: &[String],
    sources: &[(String, &str)],
    starter: &[(String, &str)],
) -> Option<Shortcut> {
    if forbid.is_empty() {
        return None;
    }
    for (file, text) in sources {
        if starter
            .iter()
            .any(|(f, t)| f == file && pipeline::shader::lexeme::same_code(t, text))
        {
            continue;
        }
        let tokens = tokens(text);
        let mut in_uniform = false;
        for (k, (token, line)) in tokens.iter().enumerate() {
            match token.as_str() {
                "uniform" => in_uniform = true,
                ";" => in_uniform = false,
                _ => {}
            }
            let Some(name) = forbid.iter().find(|n| *n == token) else {
                continue;
            };
            let uniform = pipeline::shader::interface::uniform(name).is_some();
            let called = tokens.get(k + 1).is_some_and(|(t, _)| t == "(");
            if (uniform && in_uniform) || (!uniform && called) {
                return Some(Shortcut {
                    name: name.clone(),
                    uniform,
                    file: file.clone(),
                    line: *line,
                });
            }
        }
    }
    None
}

/// The identifiers of GLSL source `text`, comments left out.
#[must_use]
pub fn names(text: &str) -> std::collections::BTreeSet<String> {
    tokens(text).into_iter().map(|(t, _)| t).collect()
}

/// The identifiers and punctuation of GLSL source with their lines, comments left out.
fn tokens(text: &str) -> Vec<(String, usize)> {
    use pipeline::shader::lexeme::{Kind, lex};
    lex(text)
        .into_iter()
        .filter(|l| matches!(l.kind, Kind::Word | Kind::Punctuation))
        .map(|l| (text[l.span].to_owned(), l.line))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_declared_uniform_and_a_called_function_are_found_a_local_is_not() {
        let forbid = ["view".to_owned(), "texture".to_owned()];
        let local =
            "mat4 look_at() {\n    mat4 view = mat4(1.0); // not the uniform\n    return view;\n}";
        let none: &[(String, &str)] = &[];
        assert_eq!(find(&forbid, &[("shader.vert".into(), local)], none), None);
        let declared =
            "uniform mat4 model;\n// uniform mat4 view;\nuniform mat4 projection,\n    view;\n";
        assert_eq!(
            find(&forbid, &[("shader.vert".into(), declared)], none),
            Some(Shortcut {
                name: "view".into(),
                uniform: true,
                file: "shader.vert".into(),
                line: 4
            })
        );
        let called = "/* texture(tex, uv) */\nvec3 c = texture (tex, uv).rgb;";
        let found = find(&forbid, &[("shader.frag".into(), called)], none).expect("a call");
        assert_eq!((found.line, found.uniform), (2, false));
        assert_eq!(
            find(
                &forbid,
                &[("shader.frag".into(), "float texture = 1.0;")],
                none
            ),
            None
        );
        // The starter's own file, unchanged, is not the student's shortcut.
        let own = [("shader.vert".to_owned(), called)];
        assert_eq!(find(&forbid, &own, &own), None);
    }

    /// The shortcut read as a whole sentence in both languages (written by hand).
    #[test]
    fn a_shortcut_is_told_with_its_file_and_line() {
        let uniform = Shortcut {
            name: "view".into(),
            uniform: true,
            file: "shader.vert".into(),
            line: 4,
        };
        assert_eq!(
            uniform.words(Lang::EN),
            "Not yet: shader.vert line 4 declares pipelens' own `view` — this lab asks you to \
             compute it yourself, so the uniform is not yours to use here."
        );
        let call = Shortcut {
            name: "texture".into(),
            uniform: false,
            file: "shader.frag".into(),
            line: 2,
        };
        assert_eq!(
            call.words(Lang::ZH),
            "还没有通过：shader.frag 第 2 行调用了 `texture()`——本练习要求你自己算出它的结果，这里不能调用它。"
        );
    }
}
