//! Parameters: camera, projection, render settings, lights and each object's transform and
//! material (`lighting.rs`), as sliders and fields with their formulas in the tooltips. Every
//! change asks for a new capture.

use egui::{DragValue, RichText, Slider, Ui};
use glam::Vec3;
use pipeline::camera::{Projection, ProjectionKind};
use pipeline::lighting::{Frequency, Reflection};
use pipeline::raster::{CullMode, DepthTest, Samples};
use pipeline::settings::MAX_VIEWPORT_SIDE;

use crate::app::command::SceneCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::Lang;

mod fields;
mod lighting;

use fields::vec3_edit;

/// Draws the parameters; returns the new scene when something changed.
pub fn ui(ui: &mut Ui, session: &Session) -> Option<Command> {
    let lang = session.lang;
    let mut spec = session.spec.clone();
    let labels = &session.spec;
    egui::ScrollArea::vertical()
        .id_salt("params")
        .show(ui, |ui| {
            egui::CollapsingHeader::new(RichText::new(lang.t("params-camera")).strong())
                .default_open(true)
                .show(ui, |ui| {
                    let c = &mut spec.scene.camera;
                    let tip = lang.t("params-lookat-eye-at-up-n");
                    vec3_edit(ui, lang.t("params-eye"), &mut c.eye, 0.05, tip);
                    vec3_edit(ui, lang.t("params-at"), &mut c.at, 0.05, tip);
                    vec3_edit(ui, lang.t("params-up"), &mut c.up, 0.02, tip);
                });
            egui::CollapsingHeader::new(RichText::new(lang.t("params-projection")).strong())
                .default_open(true)
                .show(ui, |ui| {
                    let (aspect, focus) = (
                        spec.settings.aspect(),
                        spec.scene.camera.eye.distance(spec.scene.camera.at),
                    );
                    projection_kind(ui, &mut spec.scene.projection, aspect, focus, lang);
                    projection(ui, &mut spec.scene.projection, lang);
                });
            egui::CollapsingHeader::new(
                RichText::new(lang.t("params-rasterizer-settings")).strong(),
            )
            .default_open(true)
            .show(ui, |ui| {
                let shaders_draw = spec.scene.has_shaders();
                render(ui, &mut spec.settings, (shaders_draw, lang));
            });
            if !spec.scene.lights.is_empty() {
                // Open where the picture is lit: the lights are then what a step teaches.
                let lit = spec.settings.shading != Frequency::Unlit;
                egui::CollapsingHeader::new(RichText::new(lang.t("params-lights")).strong())
                    .default_open(lit)
                    .show(ui, |ui| lighting::lights(ui, &mut spec.scene.lights, lang));
            }
            if !spec.scene.figures.is_empty() {
                egui::CollapsingHeader::new(RichText::new(lang.t("params-joint-angles")).strong())
                    .default_open(true)
                    .show(ui, |ui| figures(ui, &mut spec.scene.figures, lang));
            }
            // Open when an object moves between two orientations: its t is the thing to drag.
            let turning = spec.scene.objects.iter().any(|o| o.slerp.is_some());
            egui::CollapsingHeader::new(RichText::new(lang.t("params-objects")).strong())
                .default_open(turning)
                .show(ui, |ui| {
                    for (i, o) in spec.scene.objects.iter_mut().enumerate() {
                        egui::CollapsingHeader::new(labels.label(&o.name, lang))
                            .id_salt(("object", i))
                            .default_open(o.slerp.is_some())
                            .show(ui, |ui| {
                                let tip = lang.t("params-m-t-rz-ry-rx");
                                vec3_edit(
                                    ui,
                                    lang.t("params-translate"),
                                    &mut o.translate,
                                    0.05,
                                    tip,
                                );
                                vec3_edit(ui, lang.t("params-rotate"), &mut o.rotate_deg, 1.0, tip);
                                vec3_edit(ui, lang.t("params-scale"), &mut o.scale, 0.02, tip);
                                orientations(ui, o, lang);
                                if o.lit {
                                    lighting::material(ui, &mut o.material, lang);
                                }
                            });
                    }
                });
        });
    (spec != session.spec).then(|| Command::Scene(SceneCommand::SetSpec(Box::new(spec))))
}

/// An object's rotation about an axis (the first orientation) and, when it has one, the second
/// orientation of its slerp with the slider for t.
fn orientations(ui: &mut Ui, o: &mut pipeline::scene::Object, lang: Lang) {
    let Some((axis, degrees)) = &mut o.axis_rotation else {
        return;
    };
    let first = if o.slerp.is_some() {
        lang.t("params-q-axis")
    } else {
        lang.t("params-axis-n")
    };
    let tip = lang.t("params-r-n-cos-i-1");
    axis_angle(ui, first, axis, degrees, tip, lang);
    if let Some(s) = &mut o.slerp {
        axis_angle(
            ui,
            lang.t("params-q-axis-2"),
            &mut s.axis,
            &mut s.angle_deg,
            tip,
            lang,
        );
        ui.add(Slider::new(&mut s.t, 0.0..=1.0).text("slerp t"))
            .on_hover_text(lang.t("params-slerp-q-q-t-sin"));
    }
}

/// An axis (kept non-zero: a zero axis is refused) and an angle in degrees.
fn axis_angle(ui: &mut Ui, label: &str, axis: &mut Vec3, degrees: &mut f32, tip: &str, lang: Lang) {
    let mut edited = *axis;
    vec3_edit(ui, label, &mut edited, 0.02, tip);
    if edited.length() > 1e-6 {
        *axis = edited;
    }
    ui.horizontal(|ui| {
        ui.label(lang.t("params-angle")).on_hover_text(tip);
        ui.add(
            DragValue::new(degrees)
                .speed(1.0)
                .suffix("°")
                .max_decimals(1),
        );
    });
}

/// The projection's kind; switching keeps the view volume as near as the new kind can
/// ([`Projection::with_kind`], as a lesson's `projection.kind` does): a viewport of `aspect`,
/// the camera `focus` from what it looks at.
fn projection_kind(ui: &mut Ui, p: &mut Projection, aspect: f32, focus: f32, lang: Lang) {
    let name = |k: ProjectionKind| match k {
        ProjectionKind::Perspective => lang.t("params-perspective"),
        ProjectionKind::Frustum => lang.t("params-frustum"),
        ProjectionKind::Ortho => lang.t("params-ortho"),
    };
    let kind = p.kind();
    let mut choice = kind;
    egui::ComboBox::new("projection-kind", lang.t("params-projection-2"))
        .selected_text(name(kind))
        .show_ui(ui, |ui| {
            for k in ProjectionKind::ALL {
                ui.selectable_value(&mut choice, k, name(k));
            }
        });
    if choice != kind {
        *p = p.with_kind(choice, aspect, focus);
    }
}

fn projection(ui: &mut Ui, p: &mut Projection, lang: Lang) {
    match p {
        Projection::Perspective {
            fovy_deg,
            aspect,
            near,
            far,
        } => {
            // The useful range spread over the panel's width; a typed value may go beyond it.
            ui.add(
                Slider::new(fovy_deg, 10.0..=150.0)
                    .clamping(egui::SliderClamping::Never)
                    .step_by(0.5)
                    .text("fovy °"),
            )
            .on_hover_text(lang.t("params-vertical-field-of-view-top"));
            let mut auto = aspect.is_none();
            if ui
                .checkbox(&mut auto, lang.t("params-aspect-from-the-viewport"))
                .changed()
            {
                *aspect = if auto { None } else { Some(1.0) };
            }
            if let Some(a) = aspect {
                ui.add(Slider::new(a, 0.1..=5.0).text("aspect"));
            }
            near_far(ui, near, far, lang);
        }
        Projection::Frustum {
            left,
            right,
            bottom,
            top,
            near,
            far,
        }
        | Projection::Ortho {
            left,
            right,
            bottom,
            top,
            near,
            far,
        } => {
            ui.label(RichText::new(lang.t("params-the-near-rectangle-l-r")).weak());
            ui.horizontal(|ui| {
                ui.add(DragValue::new(left).speed(0.01).prefix("l "));
                ui.add(DragValue::new(right).speed(0.01).prefix("r "));
                ui.add(DragValue::new(bottom).speed(0.01).prefix("b "));
                ui.add(DragValue::new(top).speed(0.01).prefix("t "));
            });
            near_far(ui, near, far, lang);
        }
    }
}

fn near_far(ui: &mut Ui, near: &mut f32, far: &mut f32, lang: Lang) {
    ui.horizontal(|ui| {
        ui.add(
            DragValue::new(near)
                .speed(0.01)
                .range(0.001..=1e4)
                .prefix(lang.t("params-near")),
        )
        .on_hover_text(lang.t("params-distance-to-the-near-plane"));
        ui.add(
            DragValue::new(far)
                .speed(0.1)
                .range(0.002..=1e5)
                .prefix(lang.t("params-far")),
        )
        .on_hover_text(lang.t("params-distance-to-the-far-plane"));
    });
    if *far <= *near {
        *far = *near * 2.0;
    }
}

fn render(
    ui: &mut Ui,
    s: &mut pipeline::settings::RenderSettings,
    (shaders_draw, lang): (bool, Lang),
) {
    ui.horizontal(|ui| {
        ui.label(lang.t("params-viewport"));
        ui.add(
            DragValue::new(&mut s.width)
                .range(1..=MAX_VIEWPORT_SIDE)
                .suffix(" px"),
        );
        ui.label("×");
        ui.add(
            DragValue::new(&mut s.height)
                .range(1..=MAX_VIEWPORT_SIDE)
                .suffix(" px"),
        );
    });
    if let Some(problem) = s.capture_problem() {
        ui.colored_label(
            egui::Color32::LIGHT_RED,
            crate::vocabulary::run::settings_problem(&problem, lang),
        );
    }
    ui.horizontal(|ui| {
        ui.label(lang.t("params-samples-per-pixel"));
        for n in [Samples::X1, Samples::X4, Samples::X8, Samples::X16] {
            let count = n.count().to_string();
            let picked = ui.add(crate::app::style::glyph_button(
                ui,
                &count,
                Some(s.samples == n),
            ));
            if picked.clicked() {
                s.samples = n;
            }
            picked.on_hover_text(lang.t("params-msaa-coverage-and-depth-per"));
        }
    });
    ui.horizontal(|ui| {
        ui.label(lang.t("params-culling"));
        for (m, n) in [
            (CullMode::None, lang.t("params-none")),
            (CullMode::Back, lang.t("params-back")),
            (CullMode::Front, lang.t("params-front")),
        ] {
            ui.selectable_value(&mut s.cull, m, n)
                .on_hover_text(lang.t("params-front-faces-are-counter-clockwise"));
        }
    });
    ui.horizontal(|ui| {
        egui::ComboBox::new("depth-test", lang.t("params-depth-test"))
            .selected_text(depth_test_name(s.depth_test, lang))
            .show_ui(ui, |ui| {
                for t in [
                    DepthTest::Less,
                    DepthTest::LessEqual,
                    DepthTest::Greater,
                    DepthTest::GreaterEqual,
                    DepthTest::Always,
                ] {
                    ui.selectable_value(&mut s.depth_test, t, depth_test_name(t, lang));
                }
            });
    });
    ui.checkbox(
        &mut s.per_sample_shading,
        lang.t("params-shade-every-sample-ssaa"),
    )
    .on_hover_text(lang.t("params-off-multisampling-shades-once-per"));
    shading(ui, s, shaders_draw, lang);
    texture_sampling(ui, s, lang);
    ui.checkbox(
        &mut s.perspective_correct,
        lang.t("params-perspective-correct-interpolation"),
    )
    .on_hover_text("b_i = (λ_i / w_i) / Σ_k (λ_k / w_k)");
}

/// The shading frequency and the specular term; while the student's shaders draw the picture
/// they are greyed, with a note: they then only choose what the shader panel's "pipelens' own"
/// writes.
fn shading(
    ui: &mut Ui,
    s: &mut pipeline::settings::RenderSettings,
    shaders_draw: bool,
    lang: Lang,
) {
    if shaders_draw {
        ui.label(
            egui::RichText::new(lang.t("params-your-shaders-draw-the-picture"))
                .color(ui.visuals().warn_fg_color),
        );
    }
    let weak = ui.visuals().weak_text_color();
    ui.scope(|ui| {
        if shaders_draw {
            ui.visuals_mut().override_text_color = Some(weak);
        }
        shading_choices(ui, s, lang);
    });
}

fn shading_choices(ui: &mut Ui, s: &mut pipeline::settings::RenderSettings, lang: Lang) {
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.t("params-shading"));
        for (f, n) in [
            (Frequency::Unlit, lang.t("params-unlit")),
            (Frequency::Flat, lang.t("params-flat")),
            (Frequency::Gouraud, "Gouraud"),
            (Frequency::Phong, "Phong"),
        ] {
            ui.selectable_value(&mut s.shading, f, n)
                .on_hover_text(lang.t("params-flat-once-per-face-gouraud"));
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.t("params-specular"));
        ui.selectable_value(&mut s.reflection, Reflection::Phong, "Phong (r·v)^α");
        ui.selectable_value(
            &mut s.reflection,
            Reflection::BlinnPhong,
            "Blinn-Phong (n·h)^β",
        );
    });
}

fn texture_sampling(ui: &mut Ui, s: &mut pipeline::settings::RenderSettings, lang: Lang) {
    use pipeline::texture::{Filter, Mipmap};
    let smp = &mut s.sampler;
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.t("params-texture-filter"));
        ui.selectable_value(&mut smp.filter, Filter::Nearest, lang.t("params-nearest"));
        ui.selectable_value(&mut smp.filter, Filter::Bilinear, lang.t("params-bilinear"));
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.t("params-mipmap"));
        for (m, n) in [
            (Mipmap::None, lang.t("params-none")),
            (Mipmap::Nearest, lang.t("params-nearest-level")),
            (Mipmap::Linear, lang.t("params-trilinear")),
            (Mipmap::Ripmap, "ripmap"),
            (Mipmap::SummedArea, lang.t("params-summed-area-table")),
            (Mipmap::Ewa, "EWA"),
        ] {
            ui.selectable_value(&mut smp.mipmap, m, n)
                .on_hover_text(lang.t("params-log-max-uw-vh-x"));
        }
    });
    ui.add(Slider::new(&mut smp.anisotropy, 1..=16).text(lang.t("params-anisotropy")))
        .on_hover_text(lang.t("params-up-to-n-samples-along"));
    ui.add(Slider::new(&mut smp.lod_bias, -4.0..=4.0).text(lang.t("params-mip-bias")))
        .on_hover_text("λ + bias");
}

fn figures(ui: &mut Ui, figures: &mut [pipeline::hierarchy::Figure], lang: Lang) {
    use pipeline::hierarchy::Pose;
    for f in figures {
        ui.label(RichText::new(&f.name).strong());
        let joints: Vec<(&str, &mut f32)> = match &mut f.pose {
            Pose::RobotArm(a) => vec![
                (lang.t("params-base-b-y"), &mut a.base),
                (lang.t("params-lower-arm-la-z"), &mut a.lower),
                (lang.t("params-upper-arm-ua-z"), &mut a.upper),
            ],
            Pose::Humanoid(h) => vec![
                (lang.t("params-torso-y"), &mut h.torso),
                (lang.t("params-head-y"), &mut h.head),
                (lang.t("params-left-upper-arm"), &mut h.left_upper_arm),
                (lang.t("params-left-lower-arm"), &mut h.left_lower_arm),
                (lang.t("params-right-upper-arm"), &mut h.right_upper_arm),
                (lang.t("params-right-lower-arm"), &mut h.right_lower_arm),
                (lang.t("params-left-upper-leg"), &mut h.left_upper_leg),
                (lang.t("params-left-lower-leg"), &mut h.left_lower_leg),
                (lang.t("params-right-upper-leg"), &mut h.right_upper_leg),
                (lang.t("params-right-lower-leg"), &mut h.right_lower_leg),
            ],
        };
        for (name, angle) in joints {
            ui.add(Slider::new(angle, -180.0..=180.0).text(name).suffix("°"))
                .on_hover_text(lang.t("params-the-joint-s-rotation-every"));
        }
    }
}

/// A depth test by its comparison, as OpenGL names it, and in words.
fn depth_test_name(t: DepthTest, lang: Lang) -> &'static str {
    match t {
        DepthTest::Less => lang.t("params-less-gl-less"),
        DepthTest::LessEqual => lang.t("params-less-or-equal"),
        DepthTest::Greater => lang.t("params-greater"),
        DepthTest::GreaterEqual => lang.t("params-greater-or-equal"),
        DepthTest::Always => lang.t("params-always-painter-s-order"),
    }
}
