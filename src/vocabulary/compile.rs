//! A shader's compile messages as sentences in the interface's language: the mistake the core
//! read from naga's message ([`Complaint`]) said plainly at the student's line, and naga's own
//! wording only where no sentence covers it; the code that stopped while it ran (an endless loop,
//! an index out of range, a `texelFetch` outside its texture, a division by zero) too, since the
//! engine reports it as a complaint at its line.

use crate::vocabulary::Written;
use pipeline::shader::{Complaint, ShaderError, Stage, StageError, interface};

use super::Lang;

/// The sentence for `c`, or `None` where the English message is all there is.
#[must_use]
pub fn complaint(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    Some(match c {
        C::MissingSemicolon => lang.t("compile-missing-semicolon").to_owned(),
        C::Unexpected { found, expected } => {
            let list = expected
                .iter()
                .map(|e| token_words(e, lang))
                .collect::<Vec<_>>();
            let found = found.trim().escape_debug().to_string();
            let expected = list.join(lang.t("compile-or"));
            let id = if list.is_empty() {
                "compile-cannot-stand-here"
            } else if found.is_empty() {
                "compile-file-ends-where"
            } else {
                "compile-should-come-first"
            };
            lang.t_with(id, &[("found", &found), ("expected", &expected)])
        }
        C::UnexpectedEnd => lang.t("compile-unexpected-end").to_owned(),
        C::UnknownVariable(n) => lang.t_with("compile-unknown-variable", &[("n", n)]),
        C::UnknownType(n) => lang.t_with("compile-unknown-type", &[("n", n)]),
        C::UnknownField(n) if n.is_empty() => lang.t("compile-no-such-field").to_owned(),
        C::UnknownField(n) => lang.t_with("compile-no-field-named", &[("n", n)]),
        C::UnknownFunction(n) if n.is_empty() => lang.t("compile-no-function-matches").to_owned(),
        C::UnknownFunction(n) => lang.t_with("compile-no-function-named", &[("n", n)]),
        C::AlreadyDeclared(n) => lang.t_with("compile-already-declared", &[("n", n)]),
        C::FunctionAlreadyDefined => lang.t("compile-function-already-defined").to_owned(),
        _ => return form(c, lang),
    })
}

/// The sentence for a complaint about a form of GLSL (an operator, a constructor, a version…),
/// or `None` where the English message is all there is.
fn form(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    Some(match c {
        C::CannotCombine => lang.t("compile-cannot-combine").to_owned(),
        C::TooManyArguments => lang.t("compile-too-many-arguments").to_owned(),
        C::BadConstructor => lang.t("compile-bad-constructor").to_owned(),
        C::NotConstant => lang.t("compile-not-constant").to_owned(),
        C::NotAssignable => lang.t("compile-not-assignable").to_owned(),
        C::VoidValue => lang.t("compile-void-value").to_owned(),
        C::VersionNotFirst => lang.t("compile-version-not-first").to_owned(),
        C::InvalidVersion(v) => lang.t_with("compile-invalid-version", &[("v", v)]),
        C::FloatModulo => lang.t("compile-float-modulo").to_owned(),
        C::BadSwizzle => lang.t("compile-bad-swizzle").to_owned(),
        C::TypeMismatch => lang.t("compile-type-mismatch").to_owned(),
        C::ReturnType => lang.t("compile-return-type").to_owned(),
        C::IntegerOverflow => lang.t("compile-integer-overflow").to_owned(),
        C::NotImplemented(what) => lang.t_with("compile-not-implemented", &[("what", what)]),
        C::NotRunYet(name) => lang.t_with("compile-not-run-yet", &[("name", name)]),
        C::SamplerParameter(ty) => lang.t_with("compile-sampler-parameter", &[("ty", ty)]),
        C::Recursion(name) => lang.t_with("compile-recursion", &[("name", name)]),
        C::DefinedBelow(name) => lang.t_with("compile-defined-below", &[("name", name)]),
        C::ArgumentTypes { name, parameters } => lang.t_with(
            "compile-argument-types",
            &[("name", name), ("parameters", parameters)],
        ),
        _ => return own(c, lang).or_else(|| fault(c, lang)),
    })
}

/// The sentence for a run-time complaint in Chinese (`None` in English, where the core's
/// message says it, and for a complaint that is not a run-time one).
fn fault(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    if lang.written() == Written::English {
        return None;
    }
    Some(match c {
        C::EndlessLoop { budget } => format!(
            "循环执行超过了 {budget} 步（是不是死循环？如果它本来就要运行更久，请在 [scene.render] 中用 `max_steps` 提高上限）"
        ),
        C::IndexOutOfRange {
            index,
            last,
            name: Some(name),
        } => format!("下标 {index} 越界：`{name}` 的下标只能是 0 到 {last}"),
        C::IndexOutOfRange { index, last, .. } => {
            format!("下标 {index} 越界（只能是 0 到 {last}）")
        }
        C::TexelOutside { i, j, level } => {
            format!("texelFetch 读取的 ({i}, {j})（第 {level} 层）在纹理之外")
        }
        C::DivisionByZero { remainder: false } => "整数除以零".to_owned(),
        C::DivisionByZero { remainder: true } => "整数对零取余（%）".to_owned(),
        _ => return None,
    })
}

/// The sentence for a complaint of pipelens' own checks (the uniforms, textures and attributes
/// it provides, the outputs a stage must write), in Chinese; `None` in English, where the core's
/// message says it.
fn own(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    if lang.written() == Written::English {
        return None;
    }
    let meant = |s: &Option<String>| {
        s.as_ref()
            .map_or_else(String::new, |s| format!("（是不是想写 `{s}`？）"))
    };
    Some(match c {
        C::UnknownUniform { name, suggestion } => format!(
            "pipelens 不设置名为 `{name}` 的 uniform{}；它设置的 uniform：{}",
            meant(suggestion),
            interface::UNIFORMS
                .iter()
                .map(|u| u.names[0])
                .collect::<Vec<_>>()
                .join("、")
        ) + "。自己的 uniform 可以是 float、int、bool、vec2、vec3 或 vec4，在其后的注释中写明控件：`// 0..4 = 1.5`",
        C::OwnUniformControl { name, .. } => format!(
            "`{name}` 是你自己的 uniform；它的注释看起来像控件（`// 最小..最大 = 初值`），但写得不对：范围须是 最小..最大（最小小于最大），初值的个数须与类型相符"
        ),
        C::UniformType { name, written } => format!(
            "pipelens 的 `{name}` 是 {}，这里却声明为 {written}",
            interface::uniform(name).map_or_else(String::new, |u| u
                .glsl
                .replace("MAX_LIGHTS", &interface::MAX_LIGHTS.to_string()))
        ),
        C::UnknownTexture { name, suggestion } => format!(
            "pipelens 不绑定名为 `{name}` 的纹理{}；物体的纹理是 `uniform sampler2D tex;`，凹凸或法线贴图是 `uniform sampler2D detail;`，它所反射的立方体贴图是 `uniform samplerCube environment;`",
            meant(suggestion)
        ),
        C::TextureType {
            name,
            written,
            expected,
        } => format!("pipelens 把 `{name}` 绑定为 {expected}，这里却声明为 {written}"),
        C::UnknownAttribute { name, suggestion } => format!(
            "pipelens 不提供名为 `{name}` 的顶点属性{}；它提供的属性：{}",
            meant(suggestion),
            interface::ATTRIBUTES
                .iter()
                .map(|a| format!("{} {}", a.glsl, a.names[0]))
                .collect::<Vec<_>>()
                .join("、")
        ),
        C::OneColourOutput => {
            "pipelens 只画到一个颜色缓冲：只为片元的颜色声明一个 `out vec4`".to_owned()
        }
        C::UniformWritten(name) => {
            format!("`{name}` 是 uniform：着色器只能读它，不能给它赋值")
        }
        C::NoPosition => "顶点着色器从未写 `gl_Position`（裁剪空间位置）：请加上 `gl_Position = mvp * vec4(position, 1.0);`".to_owned(),
        C::NoOutput => "片元着色器没有输出：请声明 `out vec4 color;`，并把片元的颜色写进去".to_owned(),
        C::OutputNotWritten(name) => {
            format!("片元着色器从未写 `{name}`：这个片元将没有颜色")
        }
        C::VaryingComponents { name, here, vertex } => format!(
            "`{name}` 在这里有 {here} 个分量，在顶点着色器中却有 {vertex} 个：请在两边用相同的类型声明它"
        ),
        C::NoVaryingSource { name, outputs } => format!(
            "顶点着色器没有可插值到这个输入的输出 `{name}`；它的输出：{}",
            if outputs.is_empty() {
                "无".to_owned()
            } else {
                outputs.join("、")
            }
        ),
        C::HookSignature(signature) => format!(
            "pipelens 会调用 `{signature}`：请严格按这个签名定义它（不要 `main`，也不要自己的输入或输出）"
        ),
        _ => return None,
    })
}

/// An expected token as the sentence says it: a symbol in backticks, a kind of token in words.
fn token_words(token: &str, lang: Lang) -> String {
    let id = match token {
        "a name" => "compile-token-a-name",
        "a type" => "compile-token-a-type",
        "a whole number" => "compile-token-a-whole-number",
        "a number" => "compile-token-a-number",
        "true or false" => "compile-token-true-or-false",
        "the end of the file" => "compile-token-the-end-of-the-file",
        symbol => return format!("`{symbol}`"),
    };
    lang.t(id).to_owned()
}

/// A compile message as the student reads it: its line and column, then the sentence in
/// `lang` (naga's or pipelens' English wording where no sentence covers it).
#[must_use]
pub fn message(e: &ShaderError, lang: Lang) -> String {
    let said = complaint(&e.complaint, lang).unwrap_or_else(|| e.message.clone());
    lang.t_with(
        "compile-at",
        &[("line", &e.line), ("column", &e.column), ("said", &said)],
    )
}

/// A shader's compile message with the stage it is in: "fragment shader, line 4, column 18: …".
#[must_use]
pub fn stage_message(e: &StageError, lang: Lang) -> String {
    let stage = lang.t(match e.stage {
        Stage::Vertex => "compile-vertex-shader",
        Stage::Fragment => "compile-fragment-shader",
    });
    lang.t_with(
        "compile-stage-message",
        &[("stage", &stage), ("message", &message(&e.error, lang))],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A missing `;` on line 3 is said at line 3 — the end of the line that lacks it — in both
    /// languages, with no parser wording (the token found on line 4 is a type).
    #[test]
    fn a_missing_semicolon_is_a_sentence_at_its_own_line() {
        let src = "#version 330 core\nout vec4 color;\nvoid main() {\n    float x = 1.0\n    vec3 c = vec3(x);\n    color = vec4(c, 1.0);\n}\n";
        let Err(errors) = pipeline::shader::compile(pipeline::shader::Stage::Fragment, src) else {
            panic!("it compiles");
        };
        let e = &errors[0];
        assert_eq!(e.complaint, Complaint::MissingSemicolon);
        assert_eq!((e.line, e.column), (4, 18), "after `1.0` on line 4");
        assert_eq!(
            message(e, Lang::EN),
            "line 4, column 18: a `;` is missing at the end of this line"
        );
        assert_eq!(message(e, Lang::ZH), "第 4 行第 18 列：这一行末尾缺少 `;`");
    }

    /// A language with no sentences of its own here (French, a lesson's language) reads the
    /// English ones, not the Chinese; the stage comes first, then the line, in each language.
    #[test]
    fn another_language_reads_english_and_the_stage_is_named_first() {
        let src = "#version 330 core\nout vec4 color;\nvoid main() {\n    float x = 1.0\n    color = vec4(x);\n}\n";
        let Err(errors) = pipeline::shader::compile(Stage::Fragment, src) else {
            panic!("it compiles");
        };
        let english = "line 4, column 18: a `;` is missing at the end of this line";
        assert_eq!(message(&errors[0], Lang::uncatalogued("fr")), english);
        let staged = StageError {
            stage: Stage::Fragment,
            error: errors[0].clone(),
        };
        assert_eq!(
            stage_message(&staged, Lang::EN),
            format!("fragment shader, {english}")
        );
        assert_eq!(
            stage_message(&staged, Lang::ZH),
            "片元着色器，第 4 行第 18 列：这一行末尾缺少 `;`"
        );
    }

    /// Every complaint but `Other` has a sentence in both languages, and the Chinese one holds
    /// no English sentence.
    #[test]
    fn every_complaint_is_said_in_both_languages() {
        let all = [
            Complaint::MissingSemicolon,
            Complaint::Unexpected {
                found: "}".into(),
                expected: vec![")".into()],
            },
            Complaint::UnexpectedEnd,
            Complaint::UnknownVariable("n".into()),
            Complaint::UnknownType("vec5".into()),
            Complaint::UnknownField("w".into()),
            Complaint::UnknownFunction("depth".into()),
            Complaint::AlreadyDeclared("n".into()),
            Complaint::FunctionAlreadyDefined,
            Complaint::CannotCombine,
            Complaint::TooManyArguments,
            Complaint::BadConstructor,
            Complaint::NotConstant,
            Complaint::NotAssignable,
            Complaint::VoidValue,
            Complaint::VersionNotFirst,
            Complaint::InvalidVersion("999".into()),
            Complaint::FloatModulo,
            Complaint::BadSwizzle,
            Complaint::TypeMismatch,
            Complaint::ReturnType,
            Complaint::IntegerOverflow,
            Complaint::NotImplemented("x".into()),
            Complaint::NotRunYet("modf".into()),
            Complaint::SamplerParameter("sampler3D".into()),
            Complaint::Recursion("depth".into()),
            Complaint::DefinedBelow("shade".into()),
            Complaint::ArgumentTypes {
                name: "look".into(),
                parameters: "(sampler2D s, vec2 at)".into(),
            },
        ];
        assert!(all.len() >= 20);
        for c in &all {
            let en = complaint(c, Lang::EN).expect("a sentence");
            let zh = complaint(c, Lang::ZH).expect("a sentence");
            assert_ne!(en, zh);
            assert!(
                !zh.contains(" is ") && !zh.contains(" the "),
                "English in the Chinese sentence: {zh}"
            );
        }
        assert_eq!(complaint(&Complaint::Other, Lang::EN), None);
    }

    /// pipelens' own checks (the uniforms, textures and attributes it provides, the outputs a
    /// stage must write, the varyings linked), met in real shaders, are said in Chinese in the
    /// Chinese interface — no English sentence of the core's reaches it — and in English as the
    /// core says them.
    #[test]
    fn pipelens_own_checks_are_sentences_in_chinese_too() {
        use pipeline::shader::{Stage, compile, compile_hook, link};
        let frag = |body: &str| format!("#version 330 core\nout vec4 color;\n{body}\n");
        let cases: Vec<(Vec<ShaderError>, &str)> = vec![
            (
                compile(Stage::Fragment, &frag("uniform vec3 eyes;\nvoid main() { color = vec4(eyes, 1.0); }"))
                    .expect_err("refused"),
                "`eye`",
            ),
            (
                compile(Stage::Fragment, &frag("uniform vec4 eye;\nvoid main() { color = eye; }"))
                    .expect_err("refused"),
                "vec3",
            ),
            (
                compile(Stage::Fragment, &frag("uniform sampler2D texx;\nvoid main() { color = texture(texx, vec2(0.0)); }"))
                    .expect_err("refused"),
                "`tex`",
            ),
            (
                compile(Stage::Vertex, "#version 330 core\nin vec3 pos;\nvoid main() { gl_Position = vec4(pos, 1.0); }\n")
                    .expect_err("refused"),
                "position",
            ),
            (
                compile(Stage::Vertex, "#version 330 core\nin vec3 position;\nvoid main() { vec3 p = position; }\n")
                    .expect_err("refused"),
                "gl_Position",
            ),
            (
                compile(Stage::Fragment, &frag("void main() { vec4 c = vec4(1.0); }"))
                    .expect_err("refused"),
                "`color`",
            ),
            (
                compile(Stage::Fragment, &frag("uniform vec3 eye;\nvoid main() { eye = vec3(0.0); color = vec4(1.0); }"))
                    .expect_err("refused"),
                "uniform",
            ),
            (
                link(
                    Some("#version 330 core\nin vec3 position;\nout vec2 v_uv;\nvoid main() { v_uv = vec2(0.0); gl_Position = vec4(position, 1.0); }\n"),
                    Some(&frag("in vec3 v_uv;\nvoid main() { color = vec4(v_uv, 1.0); }")),
                )
                .expect_err("refused")
                .into_iter()
                .map(|e| e.error)
                .collect(),
                "3",
            ),
            (
                compile_hook(pipeline::shader::HookKind::Inside, "bool inside(vec2 p) { return true; }")
                    .expect_err("refused"),
                "inside",
            ),
        ];
        for (errors, names) in cases {
            let own = errors
                .iter()
                .find(|e| e.complaint != Complaint::Other)
                .unwrap_or_else(|| panic!("no complaint among {errors:?}"));
            let zh = message(own, Lang::ZH);
            assert!(zh.contains(names), "{zh}");
            assert!(
                !zh.contains(" is ") && !zh.contains(" the ") && !zh.contains("pipelens sets"),
                "English in the Chinese sentence: {zh}"
            );
            assert!(message(own, Lang::EN).contains(&own.message), "{own:?}");
        }
    }
}
