//! Built-in names in both languages: the parts of the articulated figures and the object names
//! the lessons use, so that a scene without `label`s still reads in Chinese.

use super::Lang;
use crate::vocabulary::Written;

/// Names of the core's figures and parts, and of the lessons' usual objects, in Chinese.
const NAMES_ZH: &[(&str, &str)] = &[
    ("robot arm", "机械臂"),
    ("humanoid", "人形"),
    ("base", "支架"),
    ("lower arm", "下臂"),
    ("upper arm", "上臂"),
    ("torso", "躯干"),
    ("head", "头"),
    ("left arm upper", "左上臂"),
    ("left arm lower", "左前臂"),
    ("right arm upper", "右上臂"),
    ("right arm lower", "右前臂"),
    ("left leg upper", "左大腿"),
    ("left leg lower", "左小腿"),
    ("right leg upper", "右大腿"),
    ("right leg lower", "右小腿"),
    ("floor", "地面"),
    ("cube", "立方体"),
    ("sphere", "球"),
    ("wall", "墙"),
    ("triangle", "三角形"),
    ("two triangles", "两个三角形"),
    ("torus", "圆环"),
    ("quad", "四边形"),
    ("curve", "曲线"),
    ("mirror", "镜面"),
    ("body", "身体"),
    ("arm", "机械臂"),
    ("lower", "下臂"),
    ("upper", "上臂"),
    ("left_upper_arm", "左上臂"),
    ("left_lower_arm", "左前臂"),
    ("right_upper_arm", "右上臂"),
    ("right_lower_arm", "右前臂"),
    ("left_upper_leg", "左大腿"),
    ("left_lower_leg", "左小腿"),
    ("right_upper_leg", "右大腿"),
    ("right_lower_leg", "右小腿"),
];

/// A built-in name (a figure's part, a usual object name) in `lang`; other names as they are.
#[must_use]
pub fn part_name(name: &str, lang: Lang) -> &str {
    match lang.written() {
        Written::English => name,
        Written::Chinese => NAMES_ZH
            .iter()
            .find(|(en, _)| *en == name)
            .map_or(name, |(_, zh)| zh),
    }
}

/// The name of the shadow an object casts, `shadow of NAME`.
#[must_use]
pub fn shadow_of(object: &str, lang: Lang) -> String {
    match lang.written() {
        Written::English => format!("shadow of {object}"),
        Written::Chinese => format!("{object}的影子"),
    }
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
