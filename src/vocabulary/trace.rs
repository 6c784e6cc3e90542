//! A shader's run in words, in the interface's language: each line of a trace ([`TraceLine`])
//! as the inspector, the handout and the slides write it. GLSL stays GLSL (`n = vec3(…)`,
//! `if`, `discard`); the words around it are translated.

use pipeline::shader::{Step, TraceLine};

use super::Lang;

/// What `line` did, in `lang` (its English the trace's own text, which a test compares): `n = vec3(0.000, 0.707, 0.707)`; `if: true → then` or
/// `if：条件成立 → then`; `loop: iteration 3` or `循环：第 3 次迭代`; a call, a return with its
/// value, a discard.
#[must_use]
pub fn words(line: &TraceLine, lang: Lang) -> String {
    let value = line.value.as_deref().unwrap_or_default();
    match &line.step {
        Step::Assign { name, .. } => return format!("{name} = {value}"),
        Step::Branch { taken } => lang.t(if *taken {
            "trace-if-true"
        } else {
            "trace-if-false"
        }),
        Step::Iteration { k } => return lang.t_with("trace-iteration", &[("k", k)]),
        Step::LoopTest { holds } => lang.t(if *holds {
            "trace-loop-holds"
        } else {
            "trace-loop-ends"
        }),
        Step::Break => lang.t("trace-break"),
        Step::Continue => lang.t("trace-continue"),
        Step::Call { name } => return lang.t_with("trace-call", &[("name", name)]),
        Step::Return {
            name,
            value: Some(_),
        } => return lang.t_with("trace-returns", &[("name", name), ("value", &value)]),
        Step::Return { name, value: None } => {
            return lang.t_with("trace-return-from", &[("name", name)]);
        }
        Step::Discard => lang.t("trace-discard"),
    }
    .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use pipeline::shader::Value;

    /// Each kind of step in Chinese holds no English word but GLSL's, and in English is the
    /// trace's own text.
    #[test]
    fn each_step_is_worded_in_either_language() {
        let line = |step: Step, text: &str, value: Option<&str>| TraceLine {
            line: 3,
            text: text.to_owned(),
            value: value.map(str::to_owned),
            step,
        };
        let v = Value {
            ty: "float".to_owned(),
            numbers: vec![0.5],
        };
        let lines = [
            line(
                Step::Assign {
                    name: "d".into(),
                    value: v.clone(),
                },
                "d = 0.500",
                Some("0.500"),
            ),
            line(Step::Branch { taken: false }, "if: false → else", None),
            line(Step::Iteration { k: 2 }, "loop: iteration 2", None),
            line(Step::Call { name: "f".into() }, "call f()", None),
            line(
                Step::Return {
                    name: "f".into(),
                    value: Some(v),
                },
                "f() returns 0.500",
                Some("0.500"),
            ),
            line(Step::Discard, "discard: the fragment is thrown away", None),
            line(
                Step::LoopTest { holds: false },
                "loop condition: false → the loop ends",
                None,
            ),
            line(Step::Break, "break: the loop ends", None),
            line(Step::Continue, "continue: on to the next iteration", None),
        ];
        let zh: Vec<String> = lines.iter().map(|l| words(l, Lang::ZH)).collect();
        assert_eq!(
            zh,
            [
                "d = 0.500",
                "if：条件不成立 → else",
                "循环：第 2 次迭代",
                "调用 f()",
                "f() 返回 0.500",
                "discard：丢弃这个片元",
                "循环条件：不成立 → 循环结束",
                "break：跳出循环",
                "continue：进入下一次迭代"
            ]
        );
        for l in &lines {
            assert_eq!(words(l, Lang::EN), l.text);
        }
    }
}
