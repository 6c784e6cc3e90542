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
        let tip = lang.t("lighting-i-the-light-s-intensity");
        if intensity.x == intensity.y && intensity.y == intensity.z {
            let mut grey = intensity.x;
            if ui
                .add(Slider::new(&mut grey, 0.0..=3.0).text(lang.t("lighting-intensity-i")))
                .on_hover_text(tip)
                .changed()
            {
                *intensity = Vec3::splat(grey);
            }
        } else {
            vec3_edit(ui, lang.t("lighting-intensity-i"), intensity, 0.02, tip);
        }
        if let Some(a) = attenuation {
            let tip = lang.t("lighting-f-att-1-a-b");
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
    let to_light = lang.t("lighting-l-position-p-position-p");
    match light {
        Light::Ambient { intensity } => (intensity, None),
        Light::Directional {
            direction,
            intensity,
        } => {
            let tip = lang.t("lighting-l-direction-direction-the-light");
            vec3_edit(ui, lang.t("lighting-direction"), direction, 0.05, tip);
            (intensity, None)
        }
        Light::Point {
            position,
            intensity,
            attenuation,
        } => {
            vec3_edit(ui, lang.t("lighting-position"), position, 0.05, to_light);
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
            vec3_edit(ui, lang.t("lighting-position"), position, 0.05, to_light);
            let axis = lang.t("lighting-the-cone-s-axis");
            vec3_edit(ui, lang.t("lighting-axis"), direction, 0.05, axis);
            ui.add(
                Slider::new(cutoff_deg, 1.0..=90.0)
                    .text(lang.t("lighting-cutoff"))
                    .suffix("°"),
            )
            .on_hover_text(lang.t("lighting-f-spot-cos-e-inside"));
            ui.add(Slider::new(exponent, 0.0..=128.0).text("e"))
                .on_hover_text(lang.t("lighting-f-spot-cos-e-a"));
            (intensity, Some(attenuation))
        }
    }
}

/// An object's material: k_a, k_d, k_s per RGB channel and the shininess.
pub(super) fn material(ui: &mut Ui, m: &mut pipeline::light::Material, lang: Lang) {
    ui.label(RichText::new(lang.t("lighting-material")).strong());
    vec3_edit(
        ui,
        "k_a",
        &mut m.ka,
        0.01,
        lang.t("lighting-ambient-l-a-k-a"),
    );
    vec3_edit(
        ui,
        "k_d",
        &mut m.kd,
        0.01,
        lang.t("lighting-diffuse-l-d-k-d"),
    );
    vec3_edit(
        ui,
        "k_s",
        &mut m.ks,
        0.01,
        lang.t("lighting-specular-l-s-k-s"),
    );
    ui.add(
        Slider::new(&mut m.shininess, 1.0..=512.0)
            .logarithmic(true)
            .text(lang.t("lighting-shininess-p")),
    )
    .on_hover_text(lang.t("lighting-p-in-n-h-p"));
}
