//! How a parameter is named for a reader, in each language.

use super::SceneSpec;

/// A parameter's name as a reader says it: `objects.cube.rotate` → "cube · rotate" (立方体 · 旋转),
/// the object by its label.
#[must_use]
pub fn describe(spec: &SceneSpec, name: &str, lang: crate::vocabulary::Lang) -> String {
    let word = |w: &str| -> String {
        let zh = match w {
            "camera" => "相机",
            "projection" => "投影",
            "render" => "渲染",
            "lights" => "光源",
            "shadow" => "阴影",
            "eye" => "视点",
            "at" => "参考点",
            "up" => "上方向",
            "near" => "近平面 near",
            "far" => "远平面 far",
            "translate" => "平移",
            "rotate" => "旋转",
            "scale" => "缩放",
            "color" => "颜色",
            "axis" => "旋转轴",
            "axis_angle" => "绕轴旋转角",
            "slerp_axis" => "slerp 终点旋转轴",
            "slerp_angle" => "slerp 终点旋转角",
            "slerp_t" => "slerp 参数 t",
            "position" => "位置",
            "direction" => "方向",
            "intensity" => "强度",
            "cutoff" => "截止角",
            "exponent" => "衰减指数",
            "light" => "光源",
            "shininess" => "高光指数",
            "normals" => "法线",
            "lod_bias" => "mip 偏移",
            "max_steps" => "循环步数上限",
            "samples" => "采样数",
            "anisotropy" => "各向异性",
            "uniforms" => "着色器的 uniform",
            other => return other.to_owned(),
        };
        match lang {
            crate::vocabulary::Lang::En => w.replace('_', " "),
            crate::vocabulary::Lang::Zh => zh.to_owned(),
        }
    };
    let parts: Vec<&str> = name.split('.').collect();
    match parts.as_slice() {
        ["objects" | "figures", object, p] => {
            format!(
                "{} · {}",
                spec.label(object, lang),
                crate::vocabulary::part_name(&word(p), lang)
            )
        }
        ["lights", k, p] => format!("{} {k} · {}", word("lights"), word(p)),
        [group, p] => format!("{} · {}", word(group), word(p)),
        _ => name.to_owned(),
    }
}
