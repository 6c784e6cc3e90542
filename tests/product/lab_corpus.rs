//! The labs' corpus: for every lab, wrong solutions of the kinds students hand in, each graded
//! failed with the check's sentence, and correct ones written differently (helper functions,
//! another algebraic form, `mix`, a positive multiple where that is right), each graded passed —
//! through `pipelens::lab::submission::grade`, the check the app and `pipelens grade` make.
//! Shortcuts (pipelens' own matrix or filter taken where the lab asks for it) are refused.

use pipelens::lab::submission::{Code, grade};
use pipelens::lesson::Document;
use pipelens::vocabulary::Lang;

use crate::labs::SOLUTIONS;

/// What a hand-in should be graded.
pub(crate) enum Want {
    /// Passed.
    Right,
    /// Failed, its sentences holding each of these words.
    Wrong(&'static [&'static str]),
}

/// The lab titled `title` in `lesson`: its step and the lesson.
fn lab(lesson_id: &str, title: &str) -> (pipelens::lesson::Lesson, usize) {
    let path = crate::support::repo().join(format!("lessons/{lesson_id}.toml"));
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("{lesson_id} loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == title && s.exercise.is_some())
        .unwrap_or_else(|| panic!("{lesson_id} has the lab {title}"));
    (*lesson, k)
}

/// The starter of step `k` with its TODO (from the labs' solutions) replaced by `code`: only the
/// file that holds the TODO is handed in, as a student's Save would hold it. `code` written as
/// `DECLARATIONS\n---\nBODY` also puts the declarations after the file's `#version` line (at
/// its top where it has none).
fn hand_in(lesson: &pipelens::lesson::Lesson, k: usize, code: &str) -> Code {
    let (top, code) = code.split_once("\n---\n").unwrap_or(("", code));
    let edit = |source: &str| {
        let body = source.replace(todo_of(lesson, k), code);
        match body.split_once('\n') {
            _ if top.is_empty() => body,
            Some((version, rest)) if version.starts_with("#version") => {
                format!("{version}\n{top}\n{rest}")
            }
            _ => format!("{top}\n{body}"),
        }
    };
    let todo = todo_of(lesson, k);
    let starter = &lesson.steps[k].exercise.as_ref().expect("a lab").starter;
    let mut out = Code::default();
    if let Some(sh) = &starter.shader {
        for (name, source) in [
            ("shader.vert", &sh.programs.vertex.source),
            ("shader.frag", &sh.programs.fragment.source),
        ] {
            if source.contains(todo) {
                out.take(name, edit(source));
            }
        }
    }
    for kind in pipeline::shader::HookKind::ALL {
        if let Some(h) = starter.hooks.get(kind)
            && h.source.contains(todo)
        {
            out.take(&format!("{}.glsl", kind.key()), edit(&h.source));
        }
    }
    assert!(
        !out.is_empty(),
        "{}: the TODO {todo:?} is in no file",
        lesson.id
    );
    out
}

/// The line of step `k`'s starter that says TODO, as the labs' solutions replace it.
fn todo_of(lesson: &pipelens::lesson::Lesson, k: usize) -> &'static str {
    let title = &lesson.steps[k].title.en;
    SOLUTIONS
        .iter()
        .find(|(id, t, ..)| *id == lesson.id && t == title)
        .expect("the lab has a solution")
        .2
}

#[test]
fn every_lab_s_corpus_is_graded_as_a_teacher_would() {
    let mut wrong_per_lab = std::collections::BTreeMap::<(&str, &str), (usize, usize)>::new();
    let mut faults = Vec::new();
    let corpus = crate::lab_corpus_geometry::CORPUS
        .iter()
        .chain(crate::lab_corpus_shading::CORPUS);
    for (lesson_id, title, code, want) in corpus {
        let (lesson, k) = lab(lesson_id, title);
        let g = grade(&lesson, k, &hand_in(&lesson, k, code), Lang::EN);
        let said = g.sentences.join(" ");
        let counts = wrong_per_lab.entry((lesson_id, title)).or_default();
        match want {
            Want::Right => {
                counts.1 += 1;
                if !g.passed {
                    faults.push(format!(
                        "{lesson_id} / {title}: a right answer fails: {said}\n{code}"
                    ));
                }
            }
            Want::Wrong(words) => {
                counts.0 += 1;
                if g.passed {
                    faults.push(format!(
                        "{lesson_id} / {title}: a wrong answer passes:\n{code}"
                    ));
                } else if let Some(w) = words.iter().find(|w| !said.contains(**w)) {
                    faults.push(format!(
                        "{lesson_id} / {title}: {said:?} lacks {w:?}\n{code}"
                    ));
                }
                // A value compared at a pixel is compared at the first that differs, the one
                // the verdict names ("… is (x, y).").
                let named = |after: &str| {
                    let rest = &said[said.find(after)? + after.len()..];
                    Some(rest[..=rest.find(')')?].to_owned())
                };
                if let Some(at) = named("At the inspected pixel ")
                    && named("reading from the top, is ") != Some(at.clone())
                {
                    faults.push(format!(
                        "{lesson_id} / {title}: the value is read at {at}, not at the first \
                         difference: {said}"
                    ));
                }
                // Both languages say it: the Chinese verdict in Chinese, every sentence of it.
                let zh = grade(&lesson, k, &hand_in(&lesson, k, code), Lang::ZH);
                assert_eq!(zh.passed, g.passed);
                for sentence in &zh.sentences {
                    let english = ["Not yet", "your ", "Your ", " is ", " the ", "pixels match"];
                    if let Some(w) = english.iter().find(|w| sentence.contains(**w)) {
                        faults.push(format!(
                            "{lesson_id} / {title}: English ({w:?}) in the Chinese sentence {sentence:?}"
                        ));
                    }
                }
            }
        }
        eprintln!("{lesson_id} / {title}: {said}");
    }
    assert!(faults.is_empty(), "{}", faults.join("\n\n"));
    for ((lesson, title), (wrong, right)) in wrong_per_lab {
        assert!(
            wrong >= 5 && right >= 3,
            "{lesson} / {title}: {wrong} wrong and {right} right answers in the corpus"
        );
    }
}
