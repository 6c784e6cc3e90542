//! Why a frame could not be drawn, in the interface's language: the student's code that
//! stopped while it ran (an endless loop, an index out of range, a `texelFetch` outside its
//! texture, an integer divided by zero) said at its line, with the object it ran on.

use pipeline::camera::ProjectionProblem;
use pipeline::scene::SceneProblem;
use pipeline::settings::{MAX_CAPTURE_BYTES, MAX_VIEWPORT_SIDE, SettingsProblem};
use pipeline::shader::{HookKind, Stage};
use pipeline::transform::TransformError;
use pipeline::{CodePart, RenderError};

use super::Lang;

/// Why the frame could not be drawn, in `lang`: each problem of the scene or the settings, or
/// the code that stopped, the object it ran on, and its message at its line.
#[must_use]
pub fn render_error(e: &RenderError, lang: Lang) -> String {
    let why = match e {
        RenderError::Invalid(problems) => problems
            .iter()
            .map(|p| scene_problem(p, lang))
            .collect::<Vec<_>>()
            .join(lang.t("run-problem-separator")),
        RenderError::ShadowMatrix { light, matrix } => lang.t_with(
            "run-shadow-matrix",
            &[
                ("x", &light.x),
                ("y", &light.y),
                ("z", &light.z),
                ("matrix", matrix),
            ],
        ),
        RenderError::Code {
            part,
            object,
            error,
            file,
        } => {
            let part = match part {
                CodePart::Shader(Stage::Vertex) => lang.t("compile-vertex-shader"),
                CodePart::Shader(Stage::Fragment) => lang.t("compile-fragment-shader"),
                CodePart::Function(HookKind::Inside) => lang.t("run-part-inside"),
                CodePart::Function(HookKind::DepthTest) => lang.t("run-part-depth-test"),
                CodePart::Function(HookKind::Curve) => lang.t("run-part-curve"),
                CodePart::Function(HookKind::ShadowMatrix) => lang.t("run-part-shadow-matrix"),
                CodePart::Function(HookKind::Patch) => lang.t("run-part-patch"),
            };
            let message = super::compile::message(error, lang);
            match file {
                Some(file) => lang.t_with(
                    "run-code-in-file",
                    &[
                        ("part", &part),
                        ("object", object),
                        ("file", file),
                        ("message", &message),
                    ],
                ),
                None => lang.t_with(
                    "run-code",
                    &[("part", &part), ("object", object), ("message", &message)],
                ),
            }
        }
    };
    lang.t_with("run-cannot-draw", &[("why", &why)])
}

/// A problem that keeps the scene from being drawn (its settings, projection, camera or an
/// object), in `lang`.
#[must_use]
pub fn scene_problem(p: &SceneProblem, lang: Lang) -> String {
    match p {
        SceneProblem::Settings(s) => settings_problem(s, lang),
        SceneProblem::Projection(p) => projection_problem(p, lang),
        SceneProblem::CameraNotFinite => lang.t("run-camera-not-finite").to_owned(),
        SceneProblem::Camera(TransformError::EyeAtCoincide(at)) => {
            lang.t_with("run-eye-at-coincide", &[("at", &format!("{at:?}"))])
        }
        SceneProblem::Camera(TransformError::UpParallelToView { up, dir }) => lang.t_with(
            "run-up-parallel",
            &[("up", &format!("{up:?}")), ("dir", &format!("{dir:?}"))],
        ),
        SceneProblem::Camera(TransformError::ZeroAxis) => lang.t("run-zero-axis").to_owned(),
        SceneProblem::ObjectTransform(name) => {
            lang.t_with("run-object-transform", &[("name", name)])
        }
        SceneProblem::ObjectColour(name) => lang.t_with("run-object-colour", &[("name", name)]),
    }
}

/// A problem with the render settings, in `lang`.
#[must_use]
pub fn settings_problem(p: &SettingsProblem, lang: Lang) -> String {
    match p {
        SettingsProblem::ViewportSide { height, got } => lang.t_with(
            if *height {
                "run-viewport-height"
            } else {
                "run-viewport-width"
            },
            &[("max", &MAX_VIEWPORT_SIDE), ("got", got)],
        ),
        SettingsProblem::CaptureTooLarge {
            width,
            height,
            samples,
            megabytes,
        } => lang.t_with(
            "run-capture-too-large",
            &[
                ("width", width),
                ("height", height),
                ("samples", samples),
                ("megabytes", megabytes),
                ("allowed", &(MAX_CAPTURE_BYTES >> 20)),
            ],
        ),
        SettingsProblem::Background => lang.t("run-background").to_owned(),
    }
}

/// A problem with the projection's parameters, in `lang`.
#[must_use]
pub fn projection_problem(p: &ProjectionProblem, lang: Lang) -> String {
    use ProjectionProblem as P;
    match p {
        P::Fovy(f) => lang.t_with("run-fovy", &[("fovy", f)]),
        P::Aspect(a) => lang.t_with("run-aspect", &[("aspect", a)]),
        P::LeftRight { left, right } => {
            lang.t_with("run-left-right", &[("left", left), ("right", right)])
        }
        P::BottomTop { bottom, top } => {
            lang.t_with("run-bottom-top", &[("bottom", bottom), ("top", top)])
        }
        P::Near(n) => lang.t_with("run-near", &[("near", n)]),
        P::FarNear { near, far } => lang.t_with("run-far-near", &[("near", near), ("far", far)]),
        P::NotFinite => lang.t("run-projection-not-finite").to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use pipeline::shader::Complaint;

    use super::*;

    /// A loop past its budget in a fragment shader, said in Chinese with its line, its object
    /// and no English; in English as the core says it.
    #[test]
    fn a_stopped_run_is_said_in_either_language() {
        let error = pipeline::shader::ShaderError {
            line: 12,
            column: 5,
            span: 0..0,
            message: "the loop ran more than 65536 steps (an endless loop? If it is meant to run longer, raise the limit with `max_steps` under [scene.render])".to_owned(),
            complaint: Complaint::EndlessLoop { budget: 65536 },
        };
        let e = RenderError::Code {
            part: CodePart::Shader(pipeline::shader::Stage::Fragment),
            object: "sphere".to_owned(),
            error: Box::new(error),
            file: None,
        };
        assert_eq!(
            render_error(&e, Lang::ZH),
            "无法绘制场景：物体 sphere 的片元着色器，第 12 行第 5 列：循环执行超过了 65536 步（是不是死循环？如果它本来就要运行更久，请在 [scene.render] 中用 `max_steps` 提高上限）"
        );
        assert_eq!(render_error(&e, Lang::EN), e.to_string());
        assert_eq!(
            render_error(&e, Lang::EN),
            "the scene cannot be drawn: fragment shader of sphere, line 12, column 5: the loop ran more than 65536 steps (an endless loop? If it is meant to run longer, raise the limit with `max_steps` under [scene.render])"
        );
        // A function the pipeline calls is named by its GLSL name in Chinese too.
        let RenderError::Code { error, .. } = e else {
            unreachable!()
        };
        let e = RenderError::Code {
            part: CodePart::Function(pipeline::shader::HookKind::Curve),
            object: "curve".to_owned(),
            error,
            file: None,
        };
        assert!(
            render_error(&e, Lang::ZH)
                .starts_with("无法绘制场景：物体 curve 的函数 de_casteljau，第 12 行第 5 列："),
            "{}",
            render_error(&e, Lang::ZH)
        );
        // Code written in a lesson (or a shader file) names the file before its line.
        let RenderError::Code { error, .. } = e else {
            unreachable!()
        };
        let e = RenderError::Code {
            part: CodePart::Shader(pipeline::shader::Stage::Fragment),
            object: "sphere".to_owned(),
            error,
            file: Some("lessons/24-shader-programs.toml".to_owned()),
        };
        assert!(
            render_error(&e, Lang::ZH).starts_with(
                "无法绘制场景：物体 sphere 的片元着色器，lessons/24-shader-programs.toml，第 12 行第 5 列："
            ),
            "{}",
            render_error(&e, Lang::ZH)
        );
        assert!(
            render_error(&e, Lang::EN).starts_with(
                "the scene cannot be drawn: fragment shader of sphere, lessons/24-shader-programs.toml, line 12, column 5: "
            ),
            "{}",
            render_error(&e, Lang::EN)
        );
    }

    /// A scene that cannot be drawn for many reasons at once (a viewport of width 0, a
    /// background NaN, fovy 200°, a negative aspect, near and far behind the eye, eye = at)
    /// says each in Chinese, in the core's order, with no English sentence left.
    #[test]
    fn every_problem_that_keeps_a_scene_from_being_drawn_is_said_in_chinese() {
        use pipeline::camera::Projection;
        let mut scene = pipeline::scene::Scene {
            uniforms: Default::default(),
            projection: Projection::Perspective {
                fovy_deg: 200.0,
                aspect: Some(-1.0),
                near: -1.0,
                far: -2.0,
            },
            ..Default::default()
        };
        scene.camera.at = scene.camera.eye;
        let settings = pipeline::settings::RenderSettings {
            width: 0,
            background: glam::Vec3::NAN,
            ..Default::default()
        };
        let e = pipeline::render(&scene, &settings).expect_err("nothing can be drawn");
        let zh = render_error(&e, Lang::ZH);
        let said: Vec<&str> = zh
            .strip_prefix("无法绘制场景：")
            .expect("the frame's sentence")
            .split('；')
            .collect();
        assert_eq!(
            said,
            [
                "视口的宽度必须在 1 到 16384 像素之间，现在是 0",
                "背景颜色必须是有限的数",
                "fovy 必须在 0° 到 180° 之间（不含两端），现在是 200",
                "aspect 必须是正数，现在是 -1",
                "透视投影的 near 必须为正（它是视点前方的距离），现在是 -1",
                "far 必须大于 near，现在 near = -1，far = -2",
                "视点与参考点重合（Vec3(0.0, 0.0, 3.0)）：没有观察方向",
            ]
        );
        // In English, the core's sentences.
        assert!(
            render_error(&e, Lang::EN)
                .starts_with("the scene cannot be drawn: the viewport width must be between 1 and 16384 pixels, got 0; the background colour must be finite; fovy must be between"),
            "{}",
            render_error(&e, Lang::EN)
        );
        // A language with no Chinese in it (French, a lesson's own) reads the core's English.
        let fr = Lang::uncatalogued("fr");
        assert_eq!(render_error(&e, fr), render_error(&e, Lang::EN));
        assert_eq!(
            scene_problem(&SceneProblem::CameraNotFinite, fr),
            SceneProblem::CameraNotFinite.to_string()
        );
        // Every problem, one by one: Chinese, none of the English words.
        for p in &every_problem() {
            let zh = scene_problem(p, Lang::ZH);
            assert_ne!(zh, scene_problem(p, Lang::EN));
            for english in ["must", "got", "the ", " is "] {
                assert!(!zh.contains(english), "English in {zh}");
            }
        }
        let shadow = RenderError::ShadowMatrix {
            light: glam::Vec3::new(0.0, 2.0, 0.0),
            matrix: glam::Mat4::NAN,
        };
        assert!(
            render_error(&shadow, Lang::ZH)
                .starts_with("无法绘制场景：shadow_matrix(vec3(0, 2, 0)) 返回的矩阵含有非有限的数")
        );
    }

    /// In English every problem reads as the core's `Display` says it, word for word — each
    /// of the scene's, the settings', the projection's and the camera's, each part of the
    /// student's code a run can stop in, with and without its file — so the catalog and the
    /// core cannot drift apart.
    #[test]
    fn the_english_catalog_says_what_the_core_says() {
        let problems = every_problem();
        for p in &problems {
            assert_eq!(scene_problem(p, Lang::EN), p.to_string());
        }
        let mut errors = vec![
            RenderError::Invalid(problems),
            RenderError::ShadowMatrix {
                light: glam::Vec3::new(0.5, 2.0, -1.0),
                matrix: glam::Mat4::NAN,
            },
        ];
        let error = pipeline::shader::ShaderError {
            line: 3,
            column: 9,
            span: 0..0,
            message: "integer division by zero".to_owned(),
            complaint: Complaint::DivisionByZero { remainder: false },
        };
        let parts = [
            CodePart::Shader(Stage::Vertex),
            CodePart::Shader(Stage::Fragment),
        ]
        .into_iter()
        .chain(HookKind::ALL.map(CodePart::Function));
        for part in parts {
            for file in [None, Some("lessons/22-rasterization-lab.toml".to_owned())] {
                errors.push(RenderError::Code {
                    part,
                    object: "tri".to_owned(),
                    error: Box::new(error.clone()),
                    file,
                });
            }
        }
        for e in &errors {
            assert_eq!(render_error(e, Lang::EN), e.to_string());
            assert_ne!(render_error(e, Lang::ZH), e.to_string());
        }
    }

    /// One of every problem that keeps a scene from being drawn.
    fn every_problem() -> Vec<SceneProblem> {
        vec![
            SceneProblem::Settings(SettingsProblem::ViewportSide {
                height: false,
                got: 0,
            }),
            SceneProblem::Settings(SettingsProblem::ViewportSide {
                height: true,
                got: 20_000,
            }),
            SceneProblem::Settings(SettingsProblem::CaptureTooLarge {
                width: 16_384,
                height: 16_384,
                samples: 16,
                megabytes: 53_248,
            }),
            SceneProblem::Settings(SettingsProblem::Background),
            SceneProblem::Projection(ProjectionProblem::Fovy(200.0)),
            SceneProblem::Projection(ProjectionProblem::Aspect(-1.5)),
            SceneProblem::Projection(ProjectionProblem::LeftRight {
                left: 1.0,
                right: -1.0,
            }),
            SceneProblem::Projection(ProjectionProblem::BottomTop {
                bottom: 1.0,
                top: 0.25,
            }),
            SceneProblem::Projection(ProjectionProblem::Near(-0.5)),
            SceneProblem::Projection(ProjectionProblem::FarNear {
                near: 2.0,
                far: 1.0,
            }),
            SceneProblem::Projection(ProjectionProblem::NotFinite),
            SceneProblem::CameraNotFinite,
            SceneProblem::Camera(TransformError::EyeAtCoincide(glam::Vec3::new(
                0.0, 0.0, 3.0,
            ))),
            SceneProblem::Camera(TransformError::UpParallelToView {
                up: glam::Vec3::Y,
                dir: glam::Vec3::NEG_Y,
            }),
            SceneProblem::Camera(TransformError::ZeroAxis),
            SceneProblem::ObjectTransform("cube".to_owned()),
            SceneProblem::ObjectColour("cube".to_owned()),
        ]
    }
}
