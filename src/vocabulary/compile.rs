//! A shader's compile messages as sentences in the interface's language: the mistake the core
//! read from naga's message ([`Complaint`]) said plainly at the student's line, and naga's own
//! wording only where no sentence covers it; the code that stopped while it ran (an endless loop,
//! an index out of range, a `texelFetch` outside its texture, a division by zero) too, since the
//! engine reports it as a complaint at its line.

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

/// The sentence for a run-time complaint (`None` for a complaint that is not a run-time one).
fn fault(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    Some(match c {
        C::EndlessLoop { budget } => lang.t_with("compile-endless-loop", &[("budget", budget)]),
        C::IndexOutOfRange {
            index,
            last,
            name: Some(name),
        } => lang.t_with(
            "compile-index-out-of-range-of",
            &[
                ("index", index),
                ("name", name),
                ("count", &(u64::from(*last) + 1)),
                ("last", last),
            ],
        ),
        C::IndexOutOfRange { index, last, .. } => lang.t_with(
            "compile-index-out-of-range",
            &[("index", index), ("last", last)],
        ),
        C::TexelOutside { i, j, level } => lang.t_with(
            "compile-texel-outside",
            &[("i", i), ("j", j), ("level", level)],
        ),
        C::DivisionByZero { remainder: false } => lang.t("compile-division-by-zero").to_owned(),
        C::DivisionByZero { remainder: true } => lang.t("compile-remainder-by-zero").to_owned(),
        _ => return None,
    })
}

/// The sentence for a complaint of pipelens' own checks (the uniforms, textures and attributes
/// it provides, the outputs a stage must write, the varyings linked, the functions it calls).
fn own(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    let meant = |s: &Option<String>| {
        s.as_ref().map_or_else(String::new, |s| {
            lang.t_with("compile-did-you-mean", &[("name", s)])
        })
    };
    let list = |items: Vec<String>| items.join(lang.t("list-separator"));
    Some(match c {
        C::UnknownUniform { name, suggestion } => lang.t_with(
            "compile-unknown-uniform",
            &[
                ("name", name),
                (
                    "uniforms",
                    &list(
                        interface::UNIFORMS
                            .iter()
                            .map(|u| u.names[0].to_owned())
                            .collect(),
                    ),
                ),
                ("meant", &meant(suggestion)),
            ],
        ),
        C::OwnUniformControl { name, why } => lang.t_with(
            "compile-own-uniform-control",
            &[("name", name), ("why", why)],
        ),
        C::UniformType { name, written } => {
            let spec = interface::uniform(name);
            let expected = spec.map_or_else(String::new, interface::UniformSpec::declared_type);
            lang.t_with(
                "compile-uniform-type",
                &[
                    ("name", name),
                    ("expected", &expected),
                    ("meaning", &spec.map_or("", |u| u.meaning)),
                    ("written", written),
                ],
            )
        }
        C::UnknownTexture { name, suggestion } => lang.t_with(
            "compile-unknown-texture",
            &[("name", name), ("meant", &meant(suggestion))],
        ),
        C::TextureType {
            name,
            written,
            expected,
        } => lang.t_with(
            "compile-texture-type",
            &[("name", name), ("expected", expected), ("written", written)],
        ),
        C::UnknownAttribute { name, suggestion } => lang.t_with(
            "compile-unknown-attribute",
            &[
                ("name", name),
                (
                    "attributes",
                    &list(
                        interface::ATTRIBUTES
                            .iter()
                            .map(|a| format!("{} {}", a.glsl, a.names[0]))
                            .collect(),
                    ),
                ),
                ("meant", &meant(suggestion)),
            ],
        ),
        C::OneColourOutput => lang.t("compile-one-colour-output").to_owned(),
        C::UniformWritten(name) => lang.t_with("compile-uniform-written", &[("name", name)]),
        C::NoPosition => lang.t("compile-no-position").to_owned(),
        C::NoOutput => lang.t("compile-no-output").to_owned(),
        C::OutputNotWritten(name) => lang.t_with("compile-output-not-written", &[("name", name)]),
        C::VaryingComponents { name, here, vertex } => lang.t_with(
            "compile-varying-components",
            &[("name", name), ("here", here), ("vertex", vertex)],
        ),
        C::NoVaryingSource { name, outputs } => {
            let outputs = if outputs.is_empty() {
                lang.t("compile-no-outputs").to_owned()
            } else {
                list(outputs.clone())
            };
            lang.t_with(
                "compile-no-varying-source",
                &[("name", name), ("outputs", &outputs)],
            )
        }
        C::HookSignature(signature) => return hook_signature(signature, lang),
        _ => return None,
    })
}

/// "the rasterizer calls `bool inside(…)` for every sample: define it with exactly that
/// signature": who calls the function the student writes, and when (`None` for a signature
/// pipelens does not call, which the core's English message then says).
fn hook_signature(signature: &str, lang: Lang) -> Option<String> {
    use pipeline::shader::HookKind as K;
    let kind = K::ALL.into_iter().find(|k| k.signature() == signature)?;
    let calls = lang.t_with(
        match kind {
            K::Inside => "compile-hook-calls-inside",
            K::DepthTest => "compile-hook-calls-depth-test",
            K::Curve => "compile-hook-calls-curve",
            K::ShadowMatrix => "compile-hook-calls-shadow-matrix",
            K::Patch => "compile-hook-calls-patch",
        },
        &[("signature", &signature)],
    );
    Some(lang.t_with("compile-hook-signature", &[("calls", &calls)]))
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
        let mut kinds = std::collections::HashSet::new();
        for (errors, names) in own_check_cases() {
            let own = errors
                .iter()
                .find(|e| e.complaint != Complaint::Other)
                .unwrap_or_else(|| panic!("no complaint among {errors:?}"));
            kinds.insert(std::mem::discriminant(&own.complaint));
            let zh = message(own, Lang::ZH);
            assert!(zh.contains(names), "{zh}");
            assert!(
                !zh.contains(" is ") && !zh.contains(" the ") && !zh.contains("pipelens sets"),
                "English in the Chinese sentence: {zh}"
            );
            // The English catalog says what the core says, word for word.
            assert_eq!(
                complaint(&own.complaint, Lang::EN).as_deref(),
                Some(own.message.as_str())
            );
        }
        // Every one of pipelens' own checks was met: the uniforms (unknown, own control, type),
        // the textures (unknown, type), the attributes, one colour output, a uniform written,
        // no position, no output, an output not written, the varyings (components, source),
        // a pipeline function's signature.
        assert_eq!(kinds.len(), 14);
    }

    /// Real shaders that each of pipelens' own checks refuses, with a word its Chinese sentence
    /// must hold.
    fn own_check_cases() -> Vec<(Vec<ShaderError>, &'static str)> {
        use pipeline::shader::{Stage, compile};
        let frag = |body: &str| format!("#version 330 core\nout vec4 color;\n{body}\n");
        vec![
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
        ]
        .into_iter()
        .chain(linked_and_called_cases())
        .collect()
    }

    /// Real shaders that linking refuses, and functions of the pipeline with the wrong
    /// signature, with a word the Chinese sentence must hold.
    fn linked_and_called_cases() -> Vec<(Vec<ShaderError>, &'static str)> {
        use pipeline::shader::{HookKind, Stage, compile, compile_hook, link};
        let frag = |body: &str| format!("#version 330 core\nout vec4 color;\n{body}\n");
        vec![
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
                compile(Stage::Fragment, &frag("uniform float k; // 4..1 = 2\nvoid main() { color = vec4(k); }"))
                    .expect_err("refused"),
                "`k`",
            ),
            (
                compile(Stage::Fragment, &frag("uniform samplerCube tex;\nvoid main() { color = texture(tex, vec3(1.0)); }"))
                    .expect_err("refused"),
                "samplerCube",
            ),
            (
                compile(Stage::Fragment, &frag("out vec4 glow;\nvoid main() { color = vec4(1.0); glow = color; }"))
                    .expect_err("refused"),
                "`out vec4`",
            ),
            (
                compile(Stage::Fragment, "#version 330 core\nvoid main() { float x = 1.0; }\n")
                    .expect_err("refused"),
                "`out vec4 color;`",
            ),
            (
                link(
                    Some("#version 330 core\nin vec3 position;\nout vec2 v_uv;\nvoid main() { v_uv = vec2(0.0); gl_Position = vec4(position, 1.0); }\n"),
                    Some(&frag("in vec3 v_normal;\nvoid main() { color = vec4(v_normal, 1.0); }")),
                )
                .expect_err("refused")
                .into_iter()
                .map(|e| e.error)
                .collect(),
                "v_uv",
            ),
            (
                compile_hook(HookKind::Inside, "bool inside(vec2 p) { return true; }")
                    .expect_err("refused"),
                "inside",
            ),
            (
                compile_hook(HookKind::DepthTest, "bool depth_test(float z) { return true; }")
                    .expect_err("refused"),
                "depth_test",
            ),
            (
                compile_hook(HookKind::Curve, "vec2 de_casteljau(float t) { return vec2(t); }")
                    .expect_err("refused"),
                "贝塞尔曲线",
            ),
            (
                compile_hook(HookKind::ShadowMatrix, "mat4 shadow_matrix() { return mat4(1.0); }")
                    .expect_err("refused"),
                "y = 0",
            ),
            (
                compile_hook(HookKind::Patch, "vec3 bezier_patch(float u) { return vec3(u); }")
                    .expect_err("refused"),
                "贝塞尔曲面",
            ),
        ]
    }

    /// The code that stopped while it ran, in a real frame: a loop past its budget, an index
    /// out of range (of a named array and of an array value), a `texelFetch` outside its
    /// texture, an integer divided by zero and its remainder. The English catalog says what
    /// the engine says; the Chinese holds no English sentence.
    #[test]
    fn every_run_time_fault_reads_as_the_engine_says_it_and_in_chinese() {
        use pipeline::scene::{Object, ObjectShader, Scene};
        let run = |body: &str| {
            let fs = format!(
                "#version 330 core\nout vec4 color;\nuniform sampler2D tex;\nvoid main() {{\n  int x = int(gl_FragCoord.x);\n  {body}\n}}\n"
            );
            let programs = pipeline::shader::link(None, Some(&fs)).expect("it compiles");
            let mut quad = Object::new("quad", pipeline::mesh::BuiltinMesh::Cube.build());
            quad.texture = Some(std::sync::Arc::new(
                pipeline::texture::Texture::checkerboard(8, 2),
            ));
            quad.code.shader = Some(ObjectShader {
                programs: std::sync::Arc::new(programs),
                time: 0.0,
            });
            let scene = Scene {
                objects: vec![quad],
                ..Scene::default()
            };
            let settings = pipeline::settings::RenderSettings {
                width: 16,
                height: 16,
                ..Default::default()
            };
            match pipeline::render(&scene, &settings) {
                Err(pipeline::RenderError::Code { error, .. }) => *error,
                other => panic!("{body}: {other:?}"),
            }
        };
        let faults = [
            run("float f = 0.0;\n  while (f >= 0.0) { f += 1.0; }\n  color = vec4(f);"),
            run("float a[3] = float[3](1.0, 2.0, 3.0);\n  color = vec4(a[x + 3]);"),
            run("color = vec4(float[3](1.0, 2.0, 3.0)[x + 3]);"),
            run("color = texelFetch(tex, ivec2(x + 100, 0), 0);"),
            run("color = vec4(float(7 / (x * 0)));"),
            run("color = vec4(float(7 % (x * 0)));"),
        ];
        let mut kinds = std::collections::HashSet::new();
        for e in &faults {
            kinds.insert(
                format!("{:?}", e.complaint)
                    .split([' ', '(', '{'])
                    .next()
                    .map(str::to_owned),
            );
            assert_eq!(
                complaint(&e.complaint, Lang::EN).as_deref(),
                Some(e.message.as_str()),
                "{:?}",
                e.complaint
            );
            let zh = complaint(&e.complaint, Lang::ZH).expect("a sentence");
            assert!(!zh.contains(" is ") && !zh.contains(" by "), "{zh}");
        }
        assert_eq!(kinds.len(), 4, "{faults:?}");
        assert!(
            faults.iter().any(|e| matches!(&e.complaint, Complaint::IndexOutOfRange { name: Some(n), .. } if n == "a")),
            "{faults:?}"
        );
        assert!(
            faults
                .iter()
                .any(|e| matches!(&e.complaint, Complaint::IndexOutOfRange { name: None, .. })),
            "{faults:?}"
        );
        assert!(
            faults
                .iter()
                .any(|e| e.complaint == Complaint::DivisionByZero { remainder: true }),
            "{faults:?}"
        );
    }
}
