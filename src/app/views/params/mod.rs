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
    egui::ScrollArea::vertical().id_salt("params").show(ui, |ui| {
        egui::CollapsingHeader::new(RichText::new(lang.tr("Camera", "相机")).strong()).default_open(true).show(ui, |ui| {
            let c = &mut spec.scene.camera;
            let tip = lang.tr("LookAt(eye, at, up): n = (eye − at)/|eye − at|, u = up × n/|up × n|, v = n × u", "LookAt(eye, at, up)：n = (eye − at)/|eye − at|，u = up × n/|up × n|，v = n × u");
            vec3_edit(ui, lang.tr("eye", "视点"), &mut c.eye, 0.05, tip);
            vec3_edit(ui, lang.tr("at", "参考点"), &mut c.at, 0.05, tip);
            vec3_edit(ui, lang.tr("up", "上方向"), &mut c.up, 0.02, tip);
        });
        egui::CollapsingHeader::new(RichText::new(lang.tr("Projection", "投影")).strong()).default_open(true).show(ui, |ui| {
            let (aspect, focus) = (spec.settings.aspect(), spec.scene.camera.eye.distance(spec.scene.camera.at));
            projection_kind(ui, &mut spec.scene.projection, aspect, focus, lang);
            projection(ui, &mut spec.scene.projection, lang);
        });
        egui::CollapsingHeader::new(RichText::new(lang.tr("Rasterizer settings", "光栅化设置")).strong()).default_open(true).show(ui, |ui| {
            let shaders_draw = spec.scene.has_shaders();
            render(ui, &mut spec.settings, (shaders_draw, lang));
        });
        if !spec.scene.lights.is_empty() {
            // Open where the picture is lit: the lights are then what a step teaches.
            let lit = spec.settings.shading != Frequency::Unlit;
            egui::CollapsingHeader::new(RichText::new(lang.tr("Lights", "光源")).strong())
                .default_open(lit)
                .show(ui, |ui| lighting::lights(ui, &mut spec.scene.lights, lang));
        }
        if !spec.scene.figures.is_empty() {
            egui::CollapsingHeader::new(RichText::new(lang.tr("Joint angles", "关节角")).strong())
                .default_open(true)
                .show(ui, |ui| figures(ui, &mut spec.scene.figures, lang));
        }
        // Open when an object moves between two orientations: its t is the thing to drag.
        let turning = spec.scene.objects.iter().any(|o| o.slerp.is_some());
        egui::CollapsingHeader::new(RichText::new(lang.tr("Objects", "物体")).strong()).default_open(turning).show(ui, |ui| {
            for (i, o) in spec.scene.objects.iter_mut().enumerate() {
                egui::CollapsingHeader::new(labels.label(&o.name, lang)).id_salt(("object", i)).default_open(o.slerp.is_some()).show(ui, |ui| {
                    let tip = lang.tr("M = T·Rz·Ry·Rx·S", "M = T·Rz·Ry·Rx·S");
                    vec3_edit(ui, lang.tr("translate", "平移"), &mut o.translate, 0.05, tip);
                    vec3_edit(ui, lang.tr("rotate °", "旋转 °"), &mut o.rotate_deg, 1.0, tip);
                    vec3_edit(ui, lang.tr("scale", "缩放"), &mut o.scale, 0.02, tip);
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
        lang.tr("q₀ axis", "q₀ 旋转轴")
    } else {
        lang.tr("axis n", "旋转轴 n")
    };
    let tip = lang.tr(
        "R(n, θ) = cos θ·I + (1 − cos θ)·n·n^T + sin θ·N; q = (cos(θ/2), sin(θ/2)·n)",
        "R(n, θ) = cos θ·I + (1 − cos θ)·n·n^T + sin θ·N；q = (cos(θ/2), sin(θ/2)·n)",
    );
    axis_angle(ui, first, axis, degrees, tip, lang);
    if let Some(s) = &mut o.slerp {
        axis_angle(
            ui,
            lang.tr("q₁ axis", "q₁ 旋转轴"),
            &mut s.axis,
            &mut s.angle_deg,
            tip,
            lang,
        );
        ui.add(Slider::new(&mut s.t, 0.0..=1.0).text("slerp t")).on_hover_text(lang.tr(
            "slerp(q₀, q₁, t) = sin((1 − t)Ω)/sin Ω·q₀ + sin(tΩ)/sin Ω·q₁, cos Ω = q₀·q₁: t = 0 is q₀, t = 1 is q₁, at a constant angular speed between",
            "slerp(q₀, q₁, t) = sin((1 − t)Ω)/sin Ω·q₀ + sin(tΩ)/sin Ω·q₁，cos Ω = q₀·q₁：t = 0 为 q₀，t = 1 为 q₁，其间匀角速度转动",
        ));
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
        ui.label(lang.tr("angle θ", "转角 θ")).on_hover_text(tip);
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
        ProjectionKind::Perspective => lang.tr("Perspective", "透视 Perspective"),
        ProjectionKind::Frustum => lang.tr("Frustum", "视见体 Frustum"),
        ProjectionKind::Ortho => lang.tr("Ortho", "正交 Ortho"),
    };
    let kind = p.kind();
    let mut choice = kind;
    egui::ComboBox::new("projection-kind", lang.tr("projection", "投影"))
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
            .on_hover_text(lang.tr(
                "Vertical field of view. top = near·tan(fovy/2), right = top·aspect (the review slides' near·tan(fovy) is an erratum).",
                "垂直视场角。top = near·tan(fovy/2)，right = top·aspect（复习讲义中的 near·tan(fovy) 是笔误）。",
            ));
            let mut auto = aspect.is_none();
            if ui
                .checkbox(
                    &mut auto,
                    lang.tr("aspect from the viewport", "宽高比取视口的"),
                )
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
            ui.label(
                RichText::new(lang.tr(
                    "the near rectangle [l, r] × [b, t]",
                    "近平面矩形 [l, r] × [b, t]",
                ))
                .weak(),
            );
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
        ui.add(DragValue::new(near).speed(0.01).range(0.001..=1e4).prefix(lang.tr("near ", "近 near "))).on_hover_text(lang.tr(
            "Distance to the near plane z = −near. Small near values waste depth precision: z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d).",
            "到近平面 z = −near 的距离。near 过小会浪费深度精度：z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d)。",
        ));
        ui.add(DragValue::new(far).speed(0.1).range(0.002..=1e5).prefix(lang.tr("far ", "远 far "))).on_hover_text(lang.tr("Distance to the far plane z = −far.", "到远平面 z = −far 的距离。"));
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
        ui.label(lang.tr("viewport", "视口"));
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
        ui.label(lang.tr("samples per pixel", "每像素采样数"));
        for n in [Samples::X1, Samples::X4, Samples::X8, Samples::X16] {
            ui.selectable_value(&mut s.samples, n, n.count().to_string()).on_hover_text(lang.tr(
                "MSAA: coverage and depth per sample, colour once per pixel and triangle; 4 uses the rotated grid.",
                "MSAA：每个采样点单独计算覆盖与深度，每个像素每个三角形只着色一次；4× 使用旋转网格。",
            ));
        }
    });
    ui.horizontal(|ui| {
        ui.label(lang.tr("culling", "面剔除"));
        for (m, n) in [
            (CullMode::None, lang.tr("none", "无")),
            (CullMode::Back, lang.tr("back", "背面")),
            (CullMode::Front, lang.tr("front", "正面")),
        ] {
            ui.selectable_value(&mut s.cull, m, n)
                .on_hover_text(lang.tr(
                    "Front faces are counter-clockwise on screen.",
                    "屏幕上逆时针的面为正面。",
                ));
        }
    });
    ui.horizontal(|ui| {
        egui::ComboBox::new("depth-test", lang.tr("depth test", "深度测试"))
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
    ui.checkbox(&mut s.per_sample_shading, lang.tr("shade every sample (SSAA)", "每个采样点着色（SSAA）")).on_hover_text(lang.tr(
        "Off: multisampling shades once per pixel and triangle at the pixel centre. On: supersampling shades each sample at its own position.",
        "关：多重采样每个像素每个三角形在像素中心着色一次。开：超采样在每个采样点各自着色。",
    ));
    shading(ui, s, shaders_draw, lang);
    texture_sampling(ui, s, lang);
    ui.checkbox(
        &mut s.perspective_correct,
        lang.tr("perspective-correct interpolation", "透视校正插值"),
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
            egui::RichText::new(lang.tr(
                "Your shaders draw the picture: the shading frequency and the specular term below change nothing on screen; they choose what the shader panel's \"pipelens' own\" writes.",
                "画面由你的着色器绘制：下面的着色频率与镜面项不改变画面；它们决定着色器面板中“pipelens 自带”写出的着色器。",
            ))
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
        ui.label(lang.tr("shading", "着色频率"));
        for (f, n) in [
            (Frequency::Unlit, lang.tr("unlit", "无光照")),
            (Frequency::Flat, lang.tr("flat", "平面")),
            (Frequency::Gouraud, "Gouraud"),
            (Frequency::Phong, "Phong"),
        ] {
            ui.selectable_value(&mut s.shading, f, n).on_hover_text(lang.tr(
                "Flat: once per face. Gouraud: per vertex, colours interpolated. Phong: normals interpolated, lighting per pixel.",
                "平面：每个面一次。Gouraud：按顶点计算，颜色插值。Phong：法向插值，按像素计算光照。",
            ));
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("specular", "镜面项"));
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
        ui.label(lang.tr("texture filter", "纹理过滤"));
        ui.selectable_value(
            &mut smp.filter,
            Filter::Nearest,
            lang.tr("nearest", "最近邻"),
        );
        ui.selectable_value(
            &mut smp.filter,
            Filter::Bilinear,
            lang.tr("bilinear", "双线性"),
        );
    });
    ui.horizontal_wrapped(|ui| {
        ui.label("mipmap");
        for (m, n) in [
            (Mipmap::None, lang.tr("none", "无")),
            (Mipmap::Nearest, lang.tr("nearest level", "最近层")),
            (Mipmap::Linear, lang.tr("trilinear", "三线性")),
            (Mipmap::Ripmap, "ripmap"),
            (Mipmap::SummedArea, lang.tr("summed-area table", "求和面积表")),
            (Mipmap::Ewa, "EWA"),
        ] {
            ui.selectable_value(&mut smp.mipmap, m, n).on_hover_text(lang.tr(
                "λ = log₂ max(|∂(uw, vh)/∂x|, |∂(uw, vh)/∂y|): the level whose texels are the size of a pixel.",
                "λ = log₂ max(|∂(uw, vh)/∂x|, |∂(uw, vh)/∂y|)：纹素大小与像素相当的层级。",
            ));
        }
    });
    ui.add(Slider::new(&mut smp.anisotropy, 1..=16).text(lang.tr("anisotropy", "各向异性")))
        .on_hover_text(lang.tr(
            "Up to N samples along the footprint's major axis; λ = log₂(major/N).",
            "沿覆盖区域（足迹）长轴最多取 N 个样本；λ = log₂(长轴/N)。",
        ));
    ui.add(Slider::new(&mut smp.lod_bias, -4.0..=4.0).text(lang.tr("mip bias", "mip 偏移")))
        .on_hover_text("λ + bias");
}

fn figures(ui: &mut Ui, figures: &mut [pipeline::hierarchy::Figure], lang: Lang) {
    use pipeline::hierarchy::Pose;
    for f in figures {
        ui.label(RichText::new(&f.name).strong());
        let joints: Vec<(&str, &mut f32)> = match &mut f.pose {
            Pose::RobotArm(a) => vec![
                (lang.tr("base θ_b (y)", "支架 θ_b (y)"), &mut a.base),
                (lang.tr("lower arm θ_la (z)", "下臂 θ_la (z)"), &mut a.lower),
                (lang.tr("upper arm θ_ua (z)", "上臂 θ_ua (z)"), &mut a.upper),
            ],
            Pose::Humanoid(h) => vec![
                (lang.tr("torso (y)", "躯干 (y)"), &mut h.torso),
                (lang.tr("head (y)", "头 (y)"), &mut h.head),
                (lang.tr("left upper arm", "左上臂"), &mut h.left_upper_arm),
                (lang.tr("left lower arm", "左下臂"), &mut h.left_lower_arm),
                (lang.tr("right upper arm", "右上臂"), &mut h.right_upper_arm),
                (lang.tr("right lower arm", "右下臂"), &mut h.right_lower_arm),
                (lang.tr("left upper leg", "左大腿"), &mut h.left_upper_leg),
                (lang.tr("left lower leg", "左小腿"), &mut h.left_lower_leg),
                (lang.tr("right upper leg", "右大腿"), &mut h.right_upper_leg),
                (lang.tr("right lower leg", "右小腿"), &mut h.right_lower_leg),
            ],
        };
        for (name, angle) in joints {
            ui.add(Slider::new(angle, -180.0..=180.0).text(name).suffix("°"))
                .on_hover_text(lang.tr(
                    "The joint's rotation: every part below it in the tree follows (M ← M·local).",
                    "关节旋转：树中其下的所有部件随之运动（M ← M·local）。",
                ));
        }
    }
}

/// A depth test by its comparison, as OpenGL names it, and in words.
fn depth_test_name(t: DepthTest, lang: Lang) -> &'static str {
    match t {
        DepthTest::Less => lang.tr("< less (GL_LESS)", "< 更近 (GL_LESS)"),
        DepthTest::LessEqual => lang.tr("≤ less or equal", "≤ 更近或相等"),
        DepthTest::Greater => lang.tr("> greater", "> 更远"),
        DepthTest::GreaterEqual => lang.tr("≥ greater or equal", "≥ 更远或相等"),
        DepthTest::Always => lang.tr("always (painter's order)", "总是通过（画家顺序）"),
    }
}
