//! A student's hand-in for a lab step, as the shader panel's **Save** writes it — `shader.vert`,
//! `shader.frag`, and `inside.glsl`, `depth_test.glsl`, `de_casteljau.glsl`, `shadow_matrix.glsl`
//! or `bezier_patch.glsl` for the functions a step runs — put in place of the step's starter and
//! checked as the app checks it. What the student did not hand in stays the starter's.

use std::sync::Arc;

use pipeline::scene::ObjectShader;
use pipeline::shader::HookKind;

use super::Findings;
use crate::lesson::Lesson;
use crate::vocabulary::Lang;

/// The sources of one hand-in, by what they are.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Code {
    /// The vertex shader (`shader.vert`), if handed in.
    pub vertex: Option<String>,
    /// The fragment shader (`shader.frag`), if handed in.
    pub fragment: Option<String>,
    /// The functions the pipeline calls in place of its own (`inside.glsl`, …).
    pub hooks: Vec<(HookKind, String)>,
}

impl Code {
    /// Whether nothing was handed in.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.vertex.is_none() && self.fragment.is_none() && self.hooks.is_empty()
    }

    /// Takes `text` as the file `name` says (`shader.vert`, `*.vert`, `shader.frag`, `*.frag`,
    /// `inside.glsl`, …); whether the name is one a hand-in holds.
    pub fn take(&mut self, name: &str, text: String) -> bool {
        let lower = name.to_ascii_lowercase();
        if lower.ends_with(".vert") {
            self.vertex = Some(text);
        } else if lower.ends_with(".frag") {
            self.fragment = Some(text);
        } else if let Some(kind) = lower.strip_suffix(".glsl").and_then(HookKind::from_key) {
            self.hooks.retain(|(k, _)| *k != kind);
            self.hooks.push((kind, text));
        } else {
            return false;
        }
        true
    }
}

/// A hand-in graded at one lab step.
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    /// Whether it passed.
    pub passed: bool,
    /// Matching pixels (or curve points) and how many were compared, when it ran.
    pub matching: Option<(u64, u64)>,
    /// What the check says, sentence by sentence, in the language asked for: the verdict and
    /// what is off; or why the code could not be checked (it does not compile, its run stops).
    pub sentences: Vec<String>,
}

impl Grade {
    /// A hand-in that could not be checked, for `reason`.
    #[must_use]
    pub fn failed(reason: String) -> Self {
        Self {
            passed: false,
            matching: None,
            sentences: vec![reason],
        }
    }
}

/// Grades `code` at step `k` of `lesson` (an exercise step), as the app checks it: the step's
/// scene with the starter replaced by what was handed in, compared with pipelens' own.
#[must_use]
pub fn grade(lesson: &Lesson, k: usize, code: &Code, lang: Lang) -> Grade {
    let Some(exercise) = lesson.steps.get(k).and_then(|s| s.exercise.as_ref()) else {
        return Grade::failed(lang.t_with(
            "submission-not-a-lab",
            &[("step", &(k + 1)), ("lesson", &lesson.id)],
        ));
    };
    let mut spec = lesson.spec_at(k);
    let starter = &exercise.starter;
    if let Some(shader) = &starter.shader {
        let programs = &shader.programs;
        let vertex = code.vertex.as_deref().unwrap_or(&programs.vertex.source);
        let fragment = code
            .fragment
            .as_deref()
            .unwrap_or(&programs.fragment.source);
        match pipeline::shader::link(Some(vertex), Some(fragment)) {
            Ok(linked) => spec.scene.set_shaders(&ObjectShader {
                programs: Arc::new(linked),
                time: 0.0,
            }),
            Err(errors) => return Grade::failed(compile_failed(&errors, lang)),
        }
    }
    for (kind, source) in &code.hooks {
        if starter.hooks.get(*kind).is_none() {
            continue;
        }
        match pipeline::shader::compile_hook(*kind, source) {
            Ok(hook) => spec.scene.set_hook(&hook),
            Err(errors) => {
                let first = errors
                    .first()
                    .map(|e| crate::vocabulary::compile::message(e, lang))
                    .unwrap_or_default();
                return Grade::failed(lang.t_with(
                    "submission-file-does-not-compile",
                    &[("file", &kind.key()), ("first", &first)],
                ));
            }
        }
    }
    match super::check(&spec, exercise) {
        Ok(found) => Grade {
            passed: found.passed(),
            matching: matching(&found),
            sentences: found.sentences(lang),
        },
        Err(e) => Grade::failed(lang.t_with(
            "submission-its-run-stopped",
            &[("why", &crate::vocabulary::run::render_error(&e, lang))],
        )),
    }
}

/// Matching pixels, or curve points where a curve decides.
fn matching(found: &Findings) -> Option<(u64, u64)> {
    match (&found.curve, &found.difference) {
        (Some(c), _) => Some((c.matching as u64, c.total as u64)),
        (None, Some(d)) => Some((d.matching, d.total)),
        (None, None) => None,
    }
}

/// The first message of shaders that do not compile, with its stage and line.
fn compile_failed(errors: &[pipeline::shader::StageError], lang: Lang) -> String {
    let first = errors.first().map_or_else(String::new, |e| {
        crate::vocabulary::compile::stage_message(e, lang)
    });
    let more = errors.len().saturating_sub(1);
    lang.t_with(
        "submission-does-not-compile",
        &[("first", &first), ("more", &more)],
    )
}

/// A student's work on a lesson in one file, as **Export my work** writes it and `pipelens
/// grade` reads it: each step's code, as the shader panel's Save names its files, and what was
/// typed into its answer's boxes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// The lesson's id (`10-blinn-phong`).
    pub lesson: String,
    /// Each step's work, by step number (from 1).
    pub steps: std::collections::BTreeMap<usize, StepWork>,
}

/// One step's work.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StepWork {
    /// The step's title, for a reader of the file.
    pub title: String,
    /// The code last run there.
    pub code: Code,
    /// What was typed into the answer's boxes, in order.
    pub answers: Vec<String>,
}

impl Work {
    /// The file's text: TOML, one table a step, the code as multi-line strings.
    ///
    /// # Errors
    /// Never for text (the encoder's error is passed on).
    pub fn to_text(&self) -> Result<String, String> {
        let mut root = toml::Table::new();
        root.insert("lesson".into(), self.lesson.clone().into());
        let mut steps = toml::Table::new();
        for (n, s) in &self.steps {
            let mut t = toml::Table::new();
            t.insert("title".into(), s.title.clone().into());
            for (name, text) in s.code.files() {
                t.insert(name, text.into());
            }
            if !s.answers.is_empty() {
                t.insert("answers".into(), s.answers.clone().into());
            }
            steps.insert(n.to_string(), t.into());
        }
        root.insert("steps".into(), steps.into());
        let body = toml::to_string_pretty(&root).map_err(|e| e.to_string())?;
        Ok(format!(
            "# pipelens: my work on a lesson, as Export my work wrote it. Hand this file in;\n\
             # a teacher grades it with `pipelens grade LESSON THIS_FILE`.\n{body}"
        ))
    }

    /// Reads a work file.
    ///
    /// # Errors
    /// What is wrong with it, in words: not TOML, no `lesson`, a step that is not a number.
    pub fn from_text(text: &str) -> Result<Self, String> {
        let root: toml::Table = toml::from_str(text).map_err(|e| {
            format!(
                "not a work file pipelens wrote: {}",
                e.message().trim_end_matches('\n')
            )
        })?;
        let lesson = root
            .get("lesson")
            .and_then(toml::Value::as_str)
            .ok_or("not a work file pipelens wrote: it names no `lesson`")?
            .to_owned();
        let mut steps = std::collections::BTreeMap::new();
        for (key, value) in root
            .get("steps")
            .and_then(toml::Value::as_table)
            .into_iter()
            .flatten()
        {
            let n: usize = key
                .parse()
                .map_err(|_| format!("`steps.{key}` is not a step number"))?;
            let table = value
                .as_table()
                .ok_or_else(|| format!("`steps.{n}` is not a table"))?;
            let mut s = StepWork::default();
            for (name, v) in table {
                match (name.as_str(), v) {
                    ("title", toml::Value::String(t)) => s.title.clone_from(t),
                    ("answers", toml::Value::Array(a)) => {
                        s.answers = a
                            .iter()
                            .map(|x| x.as_str().unwrap_or_default().to_owned())
                            .collect();
                    }
                    (file, toml::Value::String(code)) => {
                        s.code.take(file, code.clone());
                    }
                    _ => {}
                }
            }
            steps.insert(n, s);
        }
        Ok(Self { lesson, steps })
    }
}

impl Code {
    /// The files of this hand-in, named as the shader panel's Save names them.
    #[must_use]
    pub fn files(&self) -> Vec<(String, String)> {
        let mut out = Vec::new();
        if let Some(v) = &self.vertex {
            out.push(("shader.vert".to_owned(), v.clone()));
        }
        if let Some(f) = &self.fragment {
            out.push(("shader.frag".to_owned(), f.clone()));
        }
        for (kind, source) in &self.hooks {
            out.push((format!("{}.glsl", kind.key()), source.clone()));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A shader that does not compile is said by its stage and first message, and how many
    /// more there are, by the language's plural rules.
    #[test]
    fn a_compile_failure_names_its_stage_and_counts_the_rest() {
        let errors = pipeline::shader::link(
            Some("void main() { gl_Position = vec4(0.0) }"),
            Some("out vec4 c; void main() { c = vec4(1.0) }"),
        )
        .expect_err("two missing semicolons");
        let one = compile_failed(&errors[1..], Lang::EN);
        assert!(
            one.starts_with("Does not compile: fragment shader, "),
            "{one}"
        );
        assert!(!one.contains("more message"), "{one}");
        let en = compile_failed(&errors, Lang::EN);
        assert!(en.starts_with("Does not compile: vertex shader, "), "{en}");
        assert!(en.ends_with(" (and 1 more message)"), "{en}");
        let zh = compile_failed(&errors, Lang::ZH);
        assert!(zh.starts_with("无法编译：顶点着色器，"), "{zh}");
        assert!(zh.ends_with("（另有 1 条消息）"), "{zh}");
    }

    /// A work file written and read back holds the same code and answers; a file that is not
    /// one says so.
    #[test]
    fn a_work_file_reads_back_what_was_written() {
        let mut code = Code::default();
        code.take(
            "shader.frag",
            "void main() {\n    // \"quoted\" ''' \n}\n".to_owned(),
        );
        code.take(
            "inside.glsl",
            "bool inside(vec2 p, vec2 a, vec2 b, vec2 c) { return true; }".to_owned(),
        );
        let mut work = Work {
            lesson: "07-rasterization".to_owned(),
            ..Work::default()
        };
        work.steps.insert(
            6,
            StepWork {
                title: "Lab: the inside test".to_owned(),
                code,
                answers: vec!["0.5".to_owned(), "１／２".to_owned()],
            },
        );
        let text = work.to_text().expect("encodes");
        assert_eq!(Work::from_text(&text), Ok(work));
        assert!(Work::from_text("hello").is_err());
        assert!(Work::from_text("x = 1").is_err_and(|e| e.contains("names no `lesson`")));
    }
}
