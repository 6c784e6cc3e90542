//! The Parameters panel's lights and materials: what lighting lessons ask a student to drag,
//! each with its formula in the tooltip.

use egui::{RichText, Slider, Ui};
use glam::Vec3;
use pipeline::light::Light;

use super::fields::vec3_edit;
use crate::vocabulary::Lang;

/// Each light's intensity (one slider for a grey light, the three channels otherwise) and where
/// it is: position, direction, attenuation, a spot's cone.
pub(super) fn lights(ui: &mut Ui, lights: &mut [Light], lang: Lang) {
    for (k, light) in lights.iter_mut().enumerate() {
        ui.label(RichText::new(crate::vocabulary::light_name(light, k, lang)).strong());
        let (intensity, attenuation) = placement(ui, light, lang);
        let tip = lang.tr(
            "I, the light's intensity per RGB channel: L = k·I·…",
            "I：光源在 RGB 各通道的强度，L = k·I·…",
        );
        if intensity.x == intensity.y && intensity.y == intensity.z {
            let mut grey = intensity.x;
            if ui
                .add(Slider::new(&mut grey, 0.0..=3.0).text(lang.tr("intensity I", "强度 I")))
                .on_hover_text(tip)
                .changed()
            {
                *intensity = Vec3::splat(grey);
            }
        } else {
            vec3_edit(ui, lang.tr("intensity I", "强度 I"), intensity, 0.02, tip);
        }
        if let Some(a) = attenuation {
            let tip = lang.tr("f_att = 1/(a + b·d + c·d²)", "f_att = 1/(a + b·d + c·d²)");
            vec3_edit(ui, "a, b, c", a, 0.005, tip);
        }
        ui.separator();
    }
}

/// Where `light` is (position, direction, a spot's cone), as fields; returns its intensity and
/// its attenuation (a point or spot light's), for the caller to show.
fn placement<'a>(
    ui: &mut Ui,
    light: &'a mut Light,
    lang: Lang,
) -> (&'a mut Vec3, Option<&'a mut Vec3>) {
    let to_light = lang.tr(
        "l = (position − p)/|position − p|",
        "l = (position − p)/|position − p|",
    );
    match light {
        Light::Ambient { intensity } => (intensity, None),
        Light::Directional {
            direction,
            intensity,
        } => {
            let tip = lang.tr(
                "l = −direction/|direction|: the light travels along it",
                "l = −direction/|direction|：光沿这个方向传播",
            );
            vec3_edit(ui, lang.tr("direction", "方向"), direction, 0.05, tip);
            (intensity, None)
        }
        Light::Point {
            position,
            intensity,
            attenuation,
        } => {
            vec3_edit(ui, lang.tr("position", "位置"), position, 0.05, to_light);
            (intensity, Some(attenuation))
        }
        Light::Spot {
            position,
            direction,
            cutoff_deg,
            exponent,
            intensity,
            attenuation,
        } => {
            vec3_edit(ui, lang.tr("position", "位置"), position, 0.05, to_light);
            let axis = lang.tr("the cone's axis", "圆锥的轴");
            vec3_edit(ui, lang.tr("axis", "锥轴"), direction, 0.05, axis);
            ui.add(
                Slider::new(cutoff_deg, 1.0..=90.0)
                    .text(lang.tr("cutoff", "截止角"))
                    .suffix("°"),
            )
            .on_hover_text(lang.tr(
                "f_spot = (cos φ)^e inside the cutoff angle, 0 outside",
                "截止角以内 f_spot = (cos φ)^e，以外为 0",
            ));
            ui.add(Slider::new(exponent, 0.0..=128.0).text("e"))
                .on_hover_text(lang.tr(
                    "f_spot = (cos φ)^e: a larger e fades the disc towards its rim",
                    "f_spot = (cos φ)^e：e 越大，圆斑向边缘衰减越快",
                ));
            (intensity, Some(attenuation))
        }
    }
}

/// An object's material: k_a, k_d, k_s per RGB channel and the shininess.
pub(super) fn material(ui: &mut Ui, m: &mut pipeline::light::Material, lang: Lang) {
    ui.label(RichText::new(lang.tr("material", "材质")).strong());
    vec3_edit(
        ui,
        "k_a",
        &mut m.ka,
        0.01,
        lang.tr("ambient: L_a = k_a·c·I_a", "环境光：L_a = k_a·c·I_a"),
    );
    vec3_edit(
        ui,
        "k_d",
        &mut m.kd,
        0.01,
        lang.tr(
            "diffuse: L_d = k_d·c·(I/r²)·max(0, n·l)",
            "漫反射：L_d = k_d·c·(I/r²)·max(0, n·l)",
        ),
    );
    vec3_edit(
        ui,
        "k_s",
        &mut m.ks,
        0.01,
        lang.tr(
            "specular: L_s = k_s·(I/r²)·max(0, n·h)^p",
            "高光：L_s = k_s·(I/r²)·max(0, n·h)^p",
        ),
    );
    ui.add(
        Slider::new(&mut m.shininess, 1.0..=512.0)
            .logarithmic(true)
            .text(lang.tr("shininess p", "高光指数 p")),
    )
    .on_hover_text(lang.tr(
        "p in (n·h)^p (Blinn-Phong) or (r·v)^p (Phong): larger, a smaller and sharper highlight",
        "(n·h)^p（Blinn-Phong）或 (r·v)^p（Phong）中的 p：越大，高光越小越锐利",
    ));
}
