//! How a parameter is named for a reader, in each language.

use super::SceneSpec;

/// A parameter's name as the parameters panel says it: `objects.cube.rotate` → "rotate of cube"
/// (立方体的旋转), the object by its label; `lights.1.position` → "point light 1 position"
/// (点光源 1 的位置), the light as the panel heads it; `camera.eye` → "camera eye" (相机的视点).
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
            "shininess" => "高光指数 p",
            "normals" => "法线",
            "lod_bias" => "mip 偏移",
            "max_steps" => "循环步数上限",
            "samples" => "采样数",
            "anisotropy" => "各向异性",
            "uniforms" => "着色器的 uniform",
            // A humanoid's joint, "left_upper_leg": in words as the panel's slider says it
            // ("left upper leg"); in Chinese its part's name (左大腿), found by the key.
            other => {
                return match lang.written() {
                    crate::vocabulary::Written::English => other.replace('_', " "),
                    crate::vocabulary::Written::Chinese => other.to_owned(),
                };
            }
        };
        match lang.written() {
            // As the panel's slider says it.
            crate::vocabulary::Written::English if w == "shininess" => "shininess p".to_owned(),
            crate::vocabulary::Written::English => w.replace('_', " "),
            crate::vocabulary::Written::Chinese => zh.to_owned(),
        }
    };
    // "B of A" in English, "A的B" in Chinese (a space before a Latin word: "投影的 fovy").
    let of = |whole: &str, part: &str| match lang.written() {
        crate::vocabulary::Written::English => format!("{part} of {whole}"),
        crate::vocabulary::Written::Chinese
            if part.starts_with(|c: char| c.is_ascii_alphanumeric()) =>
        {
            format!("{whole}的 {part}")
        }
        crate::vocabulary::Written::Chinese => format!("{whole}的{part}"),
    };
    let parts: Vec<&str> = name.split('.').collect();
    match parts.as_slice() {
        ["objects" | "figures", object, p] => of(
            &spec.label(object, lang),
            crate::vocabulary::part_name(&word(p), lang),
        ),
        ["lights", k, p] => {
            let light = spec
                .light_index(k)
                .and_then(|i| {
                    Some(crate::vocabulary::light_name(
                        spec.scene.lights.get(i)?,
                        i,
                        lang,
                    ))
                })
                .unwrap_or_else(|| format!("{} {k}", word("lights")));
            match lang.written() {
                crate::vocabulary::Written::English => format!("{light} {}", word(p)),
                crate::vocabulary::Written::Chinese => format!("{light} 的{}", word(p)),
            }
        }
        ["uniforms", u] => format!("uniform {u}"),
        [group, p] => match lang.written() {
            crate::vocabulary::Written::English => format!("{} {}", word(group), word(p)),
            crate::vocabulary::Written::Chinese => of(&word(group), &word(p)),
        },
        _ => name.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vocabulary::Lang;
    use pipeline::light::Light;

    /// A sphere under an ambient light (0) and a point light (1) named "key".
    fn spec() -> SceneSpec {
        let scene = pipeline::scene::Scene {
            objects: vec![pipeline::scene::Object::new(
                "sphere",
                pipeline::mesh::BuiltinMesh::UvSphere {
                    segments: 8,
                    rings: 4,
                }
                .build(),
            )],
            lights: vec![
                Light::Ambient {
                    intensity: glam::Vec3::splat(0.2),
                },
                Light::Point {
                    position: glam::Vec3::ONE,
                    intensity: glam::Vec3::ONE,
                    attenuation: glam::Vec3::X,
                },
            ],
            ..pipeline::scene::Scene::default()
        };
        let mut spec = SceneSpec::new(scene, pipeline::settings::RenderSettings::default());
        spec.light_names = vec![None, Some("key".to_owned())];
        spec
    }

    /// The names the parameters panel gives: the material's "shininess p" of its object, a
    /// light as the panel heads it (its kind and index, whether the parameter names it by its
    /// index or its name), a group's field, a uniform of the student's.
    #[test]
    fn a_parameter_is_named_as_the_panel_names_it() {
        let s = spec();
        let en = |n: &str| describe(&s, n, Lang::EN);
        let zh = |n: &str| describe(&s, n, Lang::ZH);
        assert_eq!(en("objects.sphere.shininess"), "shininess p of sphere");
        assert_eq!(en("lights.1.position"), "point light 1 position");
        assert_eq!(en("lights.key.position"), "point light 1 position");
        assert_eq!(zh("lights.key.position"), "点光源 1 的位置");
        assert_eq!(en("camera.eye"), "camera eye");
        assert_eq!(zh("camera.eye"), "相机的视点");
        assert_eq!(zh("projection.fovy"), "投影的 fovy");
        assert_eq!(en("uniforms.band"), "uniform band");
        // A humanoid's joint, as its slider says it: "left upper leg", 左大腿.
        assert_eq!(en("figures.body.left_upper_leg"), "left upper leg of body");
        assert!(zh("figures.body.left_upper_leg").ends_with("的左大腿"));
        assert_eq!(
            crate::vocabulary::upper_first(&en("camera.eye")),
            "Camera eye"
        );
        assert_eq!(crate::vocabulary::upper_first("相机的视点"), "相机的视点");
    }
}
