//! `[[scene.lights]]`, `[scene.shadow]` and `[[scene.figures]]`.

use glam::Vec3;
use pipeline::hierarchy::{Figure, Humanoid, Pose, RobotArm};
use pipeline::light::Light;
use pipeline::scene::PlanarShadow;
use toml::Spanned;

use super::{Checker, triple};
use crate::lesson::raw::{RawFigure, RawLight, RawShadow, RawVec3};
use crate::vocabulary::Text;

/// The lights' names, each checked: not empty, not a number (numbers are indices), not the
/// name of an earlier light.
pub(super) fn names(c: &mut Checker<'_>, lights: &[Spanned<RawLight>]) -> Vec<Option<String>> {
    let mut seen: Vec<&Spanned<String>> = Vec::new();
    for n in lights.iter().filter_map(|l| l.get_ref().name.as_ref()) {
        let name = n.get_ref();
        let ok_chars = name
            .chars()
            .all(|ch| ch.is_alphanumeric() || ch == '_' || ch == '-');
        if name.is_empty() || !ok_chars || name.parse::<usize>().is_ok() {
            c.error(
                n.span(),
                format!("a light's `name` is a word of letters, digits, `_` or `-`, not a number (numbers address lights by index), got \"{name}\""),
            );
        } else if let Some(first) = seen.iter().find(|s| s.get_ref() == name) {
            let line = c.line_of(first.span().start);
            c.error(
                n.span(),
                format!(
                    "two lights are named \"{name}\" (the first on line {line}); names must differ"
                ),
            );
        }
        seen.push(n);
    }
    lights
        .iter()
        .map(|l| l.get_ref().name.as_ref().map(|n| n.get_ref().clone()))
        .collect()
}

pub(super) fn light(c: &mut Checker<'_>, l: &Spanned<RawLight>) -> Option<Light> {
    let raw = l.get_ref();
    let intensity = raw
        .intensity
        .as_ref()
        .and_then(|v| triple(c, "intensity", v))
        .unwrap_or(Vec3::ONE);
    let attenuation = raw
        .attenuation
        .as_ref()
        .and_then(|v| c.vec3("attenuation", v))
        .unwrap_or(Vec3::X);
    let needs = |c: &mut Checker<'_>, key: &str, v: &Option<RawVec3>| -> Option<Vec3> {
        match v {
            Some(v) => c.vec3(key, v),
            None => {
                c.error(
                    l.span(),
                    format!("a {} light needs `{key}`", raw.kind.get_ref()),
                );
                None
            }
        }
    };
    let kind = raw.kind.get_ref().as_str();
    unused_keys(c, raw, kind);
    match kind {
        "ambient" => Some(Light::Ambient { intensity }),
        "point" => Some(Light::Point {
            position: needs(c, "position", &raw.position)?,
            intensity,
            attenuation,
        }),
        "directional" => Some(Light::Directional {
            direction: needs(c, "direction", &raw.direction)?,
            intensity,
        }),
        "spot" => {
            let position = needs(c, "position", &raw.position)?;
            let direction = needs(c, "direction", &raw.direction)?;
            let cutoff = raw
                .cutoff
                .as_ref()
                .and_then(|v| c.finite("cutoff", v))
                .unwrap_or(30.0);
            if !(cutoff > 0.0 && cutoff <= 90.0) {
                let span = raw.cutoff.as_ref().map_or(l.span(), Spanned::span);
                c.error(
                    span,
                    format!("`cutoff` is the cone's half-angle: between 0° and 90°, got {cutoff}"),
                );
            }
            let exponent = raw
                .exponent
                .as_ref()
                .and_then(|v| c.finite("exponent", v))
                .unwrap_or(1.0);
            Some(Light::Spot {
                position,
                direction,
                cutoff_deg: cutoff,
                exponent,
                intensity,
                attenuation,
            })
        }
        other => {
            c.error(
                raw.kind.span(),
                format!("`kind` of a light must be \"ambient\", \"point\", \"directional\" or \"spot\", got \"{other}\""),
            );
            None
        }
    }
}

/// A key this kind of light does not use (`position` on an ambient light…) is a mistake to point
/// at, not to ignore.
fn unused_keys(c: &mut Checker<'_>, raw: &RawLight, kind: &str) {
    const KINDS: [&str; 4] = ["ambient", "point", "directional", "spot"];
    // Each key, where it is written, and the kinds of light that use it.
    let keys: [(&str, _, &[&str]); 5] = [
        (
            "position",
            raw.position.as_ref().map(Spanned::span),
            &["point", "spot"],
        ),
        (
            "direction",
            raw.direction.as_ref().map(Spanned::span),
            &["directional", "spot"],
        ),
        (
            "attenuation",
            raw.attenuation.as_ref().map(Spanned::span),
            &["point", "spot"],
        ),
        ("cutoff", raw.cutoff.as_ref().map(Spanned::span), &["spot"]),
        (
            "exponent",
            raw.exponent.as_ref().map(Spanned::span),
            &["spot"],
        ),
    ];
    if !KINDS.contains(&kind) {
        return; // the unknown kind is the error, reported with the kind
    }
    for (key, span, users) in keys {
        if let Some(span) = span.filter(|_| !users.contains(&kind)) {
            c.error(
                span,
                format!(
                    "{} {kind} light has no `{key}` (only {} lights do): remove it",
                    if kind.starts_with('a') { "an" } else { "a" },
                    users.join(" and ")
                ),
            );
        }
    }
}

pub(super) fn shadow(c: &mut Checker<'_>, sh: &Spanned<RawShadow>) -> Option<PlanarShadow> {
    let raw = sh.get_ref();
    let light = c.vec3("light", &raw.light)?;
    let plane_y = raw
        .plane_y
        .as_ref()
        .and_then(|v| c.finite("plane_y", v))
        .unwrap_or(0.0);
    if light.y <= plane_y {
        c.error(
            raw.light.span(),
            format!(
                "the shadow's light must be above its plane y = {plane_y}, got y = {}",
                light.y
            ),
        );
        return None;
    }
    let color = raw
        .color
        .as_ref()
        .and_then(|v| c.vec3("color", v))
        .unwrap_or(Vec3::splat(0.05));
    Some(PlanarShadow {
        light,
        plane_y,
        color,
        yours: None,
    })
}

pub(super) fn figure(
    c: &mut Checker<'_>,
    f: &Spanned<RawFigure>,
) -> Option<(Figure, Option<Text>)> {
    let raw = f.get_ref();
    let mut angle = |key: &str, v: &Option<Spanned<f64>>| {
        v.as_ref().and_then(|v| c.finite(key, v)).unwrap_or(0.0)
    };
    let (pose, misplaced): (_, Vec<(&str, bool)>) = match raw.kind.get_ref().as_str() {
        "robot_arm" => (
            Pose::RobotArm(RobotArm {
                base: angle("base", &raw.base),
                lower: angle("lower", &raw.lower),
                upper: angle("upper", &raw.upper),
            }),
            vec![("torso", raw.torso.is_some()), ("head", raw.head.is_some())],
        ),
        "humanoid" => (
            Pose::Humanoid(Humanoid {
                torso: angle("torso", &raw.torso),
                head: angle("head", &raw.head),
                left_upper_arm: angle("left_upper_arm", &raw.left_upper_arm),
                left_lower_arm: angle("left_lower_arm", &raw.left_lower_arm),
                right_upper_arm: angle("right_upper_arm", &raw.right_upper_arm),
                right_lower_arm: angle("right_lower_arm", &raw.right_lower_arm),
                left_upper_leg: angle("left_upper_leg", &raw.left_upper_leg),
                left_lower_leg: angle("left_lower_leg", &raw.left_lower_leg),
                right_upper_leg: angle("right_upper_leg", &raw.right_upper_leg),
                right_lower_leg: angle("right_lower_leg", &raw.right_lower_leg),
            }),
            vec![
                ("base", raw.base.is_some()),
                ("lower", raw.lower.is_some()),
                ("upper", raw.upper.is_some()),
            ],
        ),
        other => {
            c.error(
                raw.kind.span(),
                format!(
                    "`kind` of a figure must be \"robot_arm\" or \"humanoid\", got \"{other}\""
                ),
            );
            return None;
        }
    };
    for (key, present) in misplaced {
        if present {
            c.error(
                f.span(),
                format!("`{key}` is not a joint of a {}", raw.kind.get_ref()),
            );
        }
    }
    let translate = raw
        .translate
        .as_ref()
        .and_then(|v| c.vec3("translate", v))
        .unwrap_or(Vec3::ZERO);
    let label = raw.label.as_ref().map(|l| c.text_of("label", l));
    let figure = Figure {
        name: raw
            .name
            .clone()
            .unwrap_or_else(|| raw.kind.get_ref().replace('_', " ")),
        pose,
        translate,
    };
    Some((figure, label))
}
