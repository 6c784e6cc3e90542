//! The course as a whole: what every lesson asks of a student, and that every character it writes
//! prints.

use pipelens::lesson::{Document, load_file};

use crate::support::lesson_files;

/// The course's pedagogy, lesson by lesson: at least two questions, each with an answer in both
/// languages; one of them asked before an animation ("predict, then watch": on a step that
/// animates, worded as a prediction in both languages); one of them a computation (its answer
/// works numbers through an equation).
#[test]
fn every_lesson_asks_a_prediction_and_a_computation() {
    for path in lesson_files() {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            panic!("{} is not a lesson", path.display());
        };
        let name = &lesson.id;
        let asked: Vec<_> = lesson
            .steps
            .iter()
            .filter_map(|s| Some((s, s.question.as_ref()?)))
            .collect();
        assert!(asked.len() >= 2, "{name}: {} question(s)", asked.len());
        for (step, q) in &asked {
            let a = step
                .answer
                .as_ref()
                .unwrap_or_else(|| panic!("{name}: `{}` has no answer", q.en));
            for text in [&q.en, &q.zh, &a.en, &a.zh] {
                assert!(
                    !text.trim().is_empty(),
                    "{name}: an empty question or answer"
                );
            }
        }
        let predictions: Vec<_> = asked
            .iter()
            .filter(|(_, q)| q.en.starts_with("Predict") || q.zh.contains("预测"))
            .collect();
        assert!(
            !predictions.is_empty(),
            "{name}: no question asks for a prediction"
        );
        for (step, q) in &predictions {
            assert!(
                !step.animate.is_empty(),
                "{name}: the prediction `{}` is not on a step that animates",
                q.en
            );
            assert!(
                q.en.starts_with("Predict") && q.zh.contains("预测"),
                "{name}: `{}` is worded as a prediction in one language only",
                q.en
            );
        }
        let computed = asked.iter().any(|(s, _)| {
            s.answer.as_ref().is_some_and(|a| {
                let digits = a.en.chars().filter(char::is_ascii_digit).count();
                a.en.contains('=') && digits >= 4 && a.zh.contains('=')
            })
        });
        assert!(computed, "{name}: no question is worked out in numbers");
    }
}

/// Every character a lesson writes (titles, narration, questions, answers, in both languages) is
/// in the embedded fonts, so it prints in handouts and slides as it reads in the app, never as a
/// box (a superscript ᵀ, for one, is not: write M^T).
#[test]
fn every_character_of_every_lesson_is_in_the_embedded_fonts() {
    for path in lesson_files() {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            panic!("{} is not a lesson", path.display());
        };
        for t in texts(&lesson) {
            for text in [&t.en, &t.zh] {
                let missing: String = text
                    .chars()
                    .filter(|&c| !pipelens::export::text::covers(c))
                    .collect();
                assert!(
                    missing.is_empty(),
                    "{}: no glyph for {missing:?} in {text:?}",
                    lesson.id
                );
            }
        }
    }
}

/// A function's name with an underscore (`level_of_detail(uv)`) is code: written outside
/// backticks, the typesetter takes `_detail` for a subscript and the student reads `level_of`
/// with `detail` below it. Every title, narration, task, question and answer of every lesson
/// writes such a call in backticks (a subscript like `k_d` or `M_viewport`, not followed by `(`,
/// stays as it is).
#[test]
fn function_names_with_underscores_are_written_as_code() {
    for path in lesson_files() {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            panic!("{} is not a lesson", path.display());
        };
        for t in texts(&lesson) {
            for text in [&t.en, &t.zh] {
                // The text outside backticks, then each word followed by `(`.
                let prose: String = text.split('`').step_by(2).collect::<Vec<_>>().join(" ");
                let mut word = String::new();
                for c in prose.chars() {
                    if c.is_ascii_alphanumeric() || c == '_' {
                        word.push(c);
                        continue;
                    }
                    assert!(
                        !(c == '(' && word.contains('_') && word.len() > 3),
                        "{}: `{word}(` outside backticks in {text:?}",
                        lesson.id
                    );
                    word.clear();
                }
            }
        }
    }
}

/// Every text a lesson shows: its title and summary, and each step's title, narration,
/// question, answer and exercise task.
fn texts(lesson: &pipelens::lesson::Lesson) -> Vec<&pipelens::vocabulary::Text> {
    let mut texts = vec![&lesson.title, &lesson.summary];
    for s in &lesson.steps {
        texts.extend([&s.title, &s.narration]);
        texts.extend(s.question.iter().chain(&s.answer));
        texts.extend(s.exercise.iter().map(|e| &e.task));
    }
    texts
}

/// Every comment of the GLSL a lesson shows — a step's shaders and a lab's starter — reads in
/// Chinese in the Chinese interface: each has its Chinese in the lesson's `[comments.zh]` or in
/// pipelens' own table; and each entry of `[comments.zh]` is a comment the lesson has (none
/// left over from an edit).
#[test]
fn every_glsl_comment_a_lesson_shows_has_its_chinese() {
    use pipelens::vocabulary::glsl::untranslated;
    let mut faults = Vec::new();
    for path in lesson_files() {
        let Document::Lesson(lesson) = load_file(&path).unwrap_or_else(|e| panic!("{e}")) else {
            panic!("{} is not a lesson", path.display());
        };
        let name = &lesson.id;
        let mut sources: Vec<String> = Vec::new();
        for step in &lesson.steps {
            let codes = step
                .shader
                .iter()
                .chain(step.exercise.as_ref().map(|e| &e.starter));
            for code in codes {
                sources.extend(
                    pipelens::lesson::forbid::sources(code)
                        .into_iter()
                        .map(|(_, s)| s.to_owned()),
                );
            }
        }
        for source in &sources {
            for words in untranslated(source, &lesson.comments) {
                faults.push(format!("{name}: no Chinese for {words:?}"));
            }
        }
        for english in lesson.comments.keys() {
            if !sources.iter().any(|s| s.contains(english.as_str())) {
                faults.push(format!(
                    "{name}: [comments.zh] has {english:?}, in no comment"
                ));
            }
        }
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}
