//! How a parameter is named for a reader, in each language.

use super::SceneSpec;

/// A parameter's name as the parameters panel says it: `objects.cube.rotate` → "rotate of cube"
/// (立方体的旋转), the object by its label; `lights.1.position` → "point light 1 position"
/// (点光源 1 的位置), the light as the panel heads it; `camera.eye` → "camera eye" (相机的视点).
#[must_use]
pub fn describe(spec: &SceneSpec, name: &str, lang: crate::vocabulary::Lang) -> String {
    // A key's words, `param-KEY` in the catalogs; a humanoid's joint, "left_upper_leg", as
    // the panel's slider says it ("left upper leg"), kept as its key where the words are
    // Chinese so that `part_name` finds its part's name (左大腿).
    let word = |w: &str| -> String {
        match lang.keyed("param", w) {
            Some(words) => words.to_owned(),
            None if lang.is_chinese() => w.to_owned(),
            None => w.replace('_', " "),
        }
    };
    // "B of A", its words the catalogs' (in Chinese "A的B", a space before a Latin word:
    // "投影的 fovy").
    let latin = |part: &str| part.starts_with(|c: char| c.is_ascii_alphanumeric());
    let of = |whole: &str, part: &str| {
        let id = if latin(part) {
            "describe-of-latin"
        } else {
            "describe-of"
        };
        lang.t_with(id, &[("whole", &whole), ("part", &part)])
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
            lang.t_with(
                "describe-light-part",
                &[("light", &light), ("part", &word(p))],
            )
        }
        ["uniforms", u] => format!("uniform {u}"),
        [group, p] => {
            let (group, part) = (word(group), word(p));
            let id = if latin(&part) {
                "describe-group-part-latin"
            } else {
                "describe-group-part"
            };
            lang.t_with(id, &[("group", &group), ("part", &part)])
        }
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
