//! Built-in names in every language of the catalogs: the parts of the articulated figures and
//! the object names the lessons use, so that a scene without `label`s still reads in Chinese.

use super::Lang;

/// A built-in name (a figure's part, a usual object name) in `lang`: the catalogs' message
/// `part-NAME` (spaces and `_` written `-`), so that a scene without `label`s still reads in
/// Chinese; other names as they are.
#[must_use]
pub fn part_name(name: &str, lang: Lang) -> &str {
    lang.keyed("part", name).unwrap_or(name)
}

/// The name of the shadow an object casts, `shadow of NAME`.
#[must_use]
pub fn shadow_of(object: &str, lang: Lang) -> String {
    lang.t_with("names-shadow-of", &[("object", &object)])
}

/// "point light 1", "聚光灯 2"…
#[must_use]
pub fn light_name(light: &pipeline::light::Light, k: usize, lang: Lang) -> String {
    use pipeline::light::Light;
    let kind = match light {
        Light::Point { .. } => lang.t("names-point-light"),
        Light::Spot { .. } => lang.t("names-spotlight"),
        Light::Directional { .. } => lang.t("names-directional-light"),
        Light::Ambient { .. } => lang.t("names-ambient-light"),
    };
    format!("{kind} {k}")
}

/// `text` with its first letter a capital (a sentence's start; Chinese is left as it is).
#[must_use]
pub fn upper_first(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
