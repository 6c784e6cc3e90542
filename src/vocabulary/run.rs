//! Why a frame could not be drawn, in the interface's language: the student's code that
//! stopped while it ran (an endless loop, an index out of range, a `texelFetch` outside its
//! texture, an integer divided by zero) said at its line, with the object it ran on.

use crate::vocabulary::Written;
use pipeline::camera::ProjectionProblem;
use pipeline::scene::SceneProblem;
use pipeline::settings::{MAX_CAPTURE_BYTES, MAX_VIEWPORT_SIDE, SettingsProblem};
use pipeline::transform::TransformError;
use pipeline::{CodePart, RenderError};

use super::Lang;

/// Why the frame could not be drawn, in `lang`: the code that stopped, the object it ran on,
/// and its message at its line in the interface's language; a problem of the scene or the
/// settings as the core says it.
#[must_use]
pub fn render_error(e: &RenderError, lang: Lang) -> String {
    match (e, lang.written()) {
        (_, Written::English) => e.to_string(),
        (RenderError::Invalid(problems), Written::Chinese) => format!(
            "无法绘制场景：{}",
            problems
                .iter()
                .map(|p| scene_problem(p, lang))
                .collect::<Vec<_>>()
                .join("；")
        ),
        (RenderError::ShadowMatrix { light, matrix }, Written::Chinese) => format!(
            "无法绘制场景：shadow_matrix(vec3({}, {}, {})) 返回的矩阵含有非有限的数（是否除以了零？）：{matrix}",
            light.x, light.y, light.z
        ),
        (
            RenderError::Code {
                part,
                object,
                error,
                file,
            },
            Written::Chinese,
        ) => {
            let part = match part {
                CodePart::Shader(pipeline::shader::Stage::Vertex) => "顶点着色器".to_owned(),
                CodePart::Shader(pipeline::shader::Stage::Fragment) => "片元着色器".to_owned(),
                CodePart::Function(kind) => format!("函数 {}", kind.key()),
            };
            let file = file
                .as_deref()
                .map(|f| format!("{f}，"))
                .unwrap_or_default();
            format!(
                "无法绘制场景：物体 {object} 的{part}，{file}{}",
                super::compile::message(error, lang)
            )
        }
    }
}

/// A problem that keeps the scene from being drawn (its settings, projection, camera or an
/// object), in `lang`.
#[must_use]
pub fn scene_problem(p: &SceneProblem, lang: Lang) -> String {
    if lang.written() == Written::English {
        return p.to_string();
    }
    match (p, lang) {
        (SceneProblem::Settings(s), _) => settings_problem(s, lang),
        (SceneProblem::Projection(p), _) => projection_problem(p, lang),
        (SceneProblem::CameraNotFinite, _) => "相机的 eye、at 和 up 必须是有限的数".to_owned(),
        (SceneProblem::Camera(TransformError::EyeAtCoincide(at)), _) => {
            format!("视点与参考点重合（{at:?}）：没有观察方向")
        }
        (SceneProblem::Camera(TransformError::UpParallelToView { up, dir }), _) => format!(
            "上方向 {up:?} 与观察方向 {dir:?} 平行：u = v_up × n 为零，相机坐标系无法确定（请换一个上方向）"
        ),
        (SceneProblem::Camera(TransformError::ZeroAxis), _) => "旋转轴是零向量".to_owned(),
        (SceneProblem::ObjectTransform(name), _) => {
            format!("物体 `{name}`：它的变换必须是有限的数")
        }
        (SceneProblem::ObjectColour(name), _) => format!("物体 `{name}`：它的颜色必须是有限的数"),
    }
}

/// A problem with the render settings, in `lang`.
#[must_use]
pub fn settings_problem(p: &SettingsProblem, lang: Lang) -> String {
    if lang.written() == Written::English {
        return p.to_string();
    }
    match (p, lang) {
        (SettingsProblem::ViewportSide { height, got }, _) => format!(
            "视口的{}必须在 1 到 {MAX_VIEWPORT_SIDE} 像素之间，现在是 {got}",
            if *height { "高度" } else { "宽度" }
        ),
        (
            SettingsProblem::CaptureTooLarge {
                width,
                height,
                samples,
                megabytes,
            },
            _,
        ) => format!(
            "{width}×{height} 像素 × {samples} 个采样的捕获约需 {megabytes} MB，超过了允许的 {} MB；请减小尺寸或采样数",
            MAX_CAPTURE_BYTES >> 20
        ),
        (SettingsProblem::Background, _) => "背景颜色必须是有限的数".to_owned(),
    }
}

/// A problem with the projection's parameters, in `lang`.
#[must_use]
pub fn projection_problem(p: &ProjectionProblem, lang: Lang) -> String {
    use ProjectionProblem as P;
    if lang.written() == Written::English {
        return p.to_string();
    }
    match (p, lang) {
        (P::Fovy(f), _) => format!("fovy 必须在 0° 到 180° 之间（不含两端），现在是 {f}"),
        (P::Aspect(a), _) => format!("aspect 必须是正数，现在是 {a}"),
        (P::LeftRight { left, right }, _) => {
            format!("left 必须小于 right，现在 left = {left}，right = {right}")
        }
        (P::BottomTop { bottom, top }, _) => {
            format!("bottom 必须小于 top，现在 bottom = {bottom}，top = {top}")
        }
        (P::Near(n), _) => format!("透视投影的 near 必须为正（它是视点前方的距离），现在是 {n}"),
        (P::FarNear { near, far }, _) => {
            format!("far 必须大于 near，现在 near = {near}，far = {far}")
        }
        (P::NotFinite, _) => "投影的每个参数都必须是有限的数".to_owned(),
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
            message: "the loop ran more than 65536 steps (an endless loop?)".to_owned(),
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
        assert_eq!(
            render_error(&e, Lang::EN),
            "the scene cannot be drawn: fragment shader of sphere, line 12, column 5: the loop ran more than 65536 steps (an endless loop?)"
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
        // The rest of the problems, one by one: Chinese, none of the English words.
        let rest = [
            SceneProblem::Projection(ProjectionProblem::LeftRight {
                left: 1.0,
                right: -1.0,
            }),
            SceneProblem::Projection(ProjectionProblem::BottomTop {
                bottom: 1.0,
                top: 0.0,
            }),
            SceneProblem::Projection(ProjectionProblem::NotFinite),
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
            SceneProblem::CameraNotFinite,
            SceneProblem::Camera(TransformError::UpParallelToView {
                up: glam::Vec3::Y,
                dir: glam::Vec3::NEG_Y,
            }),
            SceneProblem::ObjectTransform("cube".to_owned()),
            SceneProblem::ObjectColour("cube".to_owned()),
        ];
        for p in &rest {
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
}
