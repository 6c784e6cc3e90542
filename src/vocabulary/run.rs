//! Why a frame could not be drawn, in the interface's language: the student's code that
//! stopped while it ran (an endless loop, an index out of range, a `texelFetch` outside its
//! texture, an integer divided by zero) said at its line, with the object it ran on.

use pipeline::shader::Complaint;
use pipeline::{CodePart, RenderError};

use super::Lang;

/// The sentence for a run-time complaint in Chinese (`None` in English, where the core's
/// message says it, and for a complaint that is not a run-time one).
#[must_use]
pub fn fault(c: &Complaint, lang: Lang) -> Option<String> {
    use Complaint as C;
    if lang == Lang::En {
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

/// Why the frame could not be drawn, in `lang`: the code that stopped, the object it ran on,
/// and its message at its line in the interface's language; a problem of the scene or the
/// settings as the core says it.
#[must_use]
pub fn render_error(e: &RenderError, lang: Lang) -> String {
    match (e, lang) {
        (RenderError::Code { .. }, Lang::En) | (RenderError::Invalid(_), _) => e.to_string(),
        (
            RenderError::Code {
                part,
                object,
                error,
                file,
            },
            Lang::Zh,
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

#[cfg(test)]
mod tests {
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
            render_error(&e, Lang::Zh),
            "无法绘制场景：物体 sphere 的片元着色器，第 12 行第 5 列：循环执行超过了 65536 步（是不是死循环？如果它本来就要运行更久，请在 [scene.render] 中用 `max_steps` 提高上限）"
        );
        assert_eq!(
            render_error(&e, Lang::En),
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
            render_error(&e, Lang::Zh)
                .starts_with("无法绘制场景：物体 curve 的函数 de_casteljau，第 12 行第 5 列："),
            "{}",
            render_error(&e, Lang::Zh)
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
            render_error(&e, Lang::Zh).starts_with(
                "无法绘制场景：物体 sphere 的片元着色器，lessons/24-shader-programs.toml，第 12 行第 5 列："
            ),
            "{}",
            render_error(&e, Lang::Zh)
        );
        assert!(
            render_error(&e, Lang::En).starts_with(
                "the scene cannot be drawn: fragment shader of sphere, lessons/24-shader-programs.toml, line 12, column 5: "
            ),
            "{}",
            render_error(&e, Lang::En)
        );
    }
}
