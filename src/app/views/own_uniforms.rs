//! The controls of the student's own uniforms in the shader panel: each `uniform` of theirs
//! pipelens does not set (`pipeline::shader::own_uniform`) as a slider (`float`, `int` in
//! whole steps), a checkbox (`bool`), numbers (`vec2`), a colour or numbers (`vec3`, `vec4`
//! with its alpha), its range and first
//! value from the comment after its declaration. A change sets the parameter `uniforms.NAME`,
//! the one a lesson's `set` and `animate` use, so the recorder writes it into a step.

use egui::{RichText, Ui};
use pipeline::shader::own_uniform::{OwnKind, OwnUniform};

use crate::app::command::SceneCommand;
use crate::app::session::{Command, Session};
use crate::lesson::param::Value;
use crate::vocabulary::Lang;

/// The controls, under a heading, when the shaders declare uniforms of their own; the command
/// that sets the one moved.
pub fn controls(ui: &mut Ui, session: &Session) -> Option<Command> {
    let own = session.spec.scene.own_uniforms();
    if own.is_empty() {
        return None;
    }
    let lang = session.lang;
    let mut moved: Option<(String, Value)> = None;
    egui::CollapsingHeader::new(lang.t("own-uniforms-your-uniforms"))
        .id_salt("own uniforms")
        .default_open(true)
        .show(ui, |ui| {
            for u in &own {
                ui.horizontal(|ui| {
                    let label = ui.label(RichText::new(&u.name).monospace());
                    if let Some(v) = control(ui, u, label.id, lang) {
                        moved = Some((u.name.clone(), v));
                    }
                });
            }
        });
    let (name, value) = moved?;
    let mut spec = session.spec.clone();
    crate::lesson::param::apply(&mut spec, &format!("uniforms.{name}"), &value).ok()?;
    Some(Command::Scene(SceneCommand::SetSpec(Box::new(spec))))
}

/// One uniform's control, labelled by `label`; its new value when moved.
fn control(ui: &mut Ui, u: &OwnUniform, label: egui::Id, lang: Lang) -> Option<Value> {
    let (lo, hi) = u.range;
    let tip = lang.t_with(
        "own-uniforms-tip",
        &[
            ("kind", &u.kind.glsl()),
            ("name", &u.name),
            ("line", &u.line),
            ("lo", &lo),
            ("hi", &hi),
        ],
    );
    match u.kind {
        OwnKind::Float => {
            let mut x = u.value[0];
            // A step of a power of ten, a hundredth of the range or finer: the comment's
            // values (0.25 of 0..1, 1.5 of 0..4) lie on it, and an arrow key moves by it.
            let step = 10f64.powf((f64::from(hi - lo) / 100.0).log10().floor());
            ui.add(egui::Slider::new(&mut x, lo..=hi).step_by(step))
                .labelled_by(label)
                .on_hover_text(tip)
                .changed()
                .then_some(Value::Number(x))
        }
        OwnKind::Int => {
            #[allow(clippy::cast_possible_truncation)]
            let (mut k, lo, hi) = (u.value[0] as i32, lo.ceil() as i32, hi.floor() as i32);
            #[allow(clippy::cast_precision_loss)]
            ui.add(egui::Slider::new(&mut k, lo..=hi).step_by(1.0))
                .labelled_by(label)
                .on_hover_text(tip)
                .changed()
                .then_some(Value::Number(k as f32))
        }
        OwnKind::Bool => {
            let mut b = u.value[0] != 0.0;
            ui.checkbox(&mut b, "")
                .labelled_by(label)
                .on_hover_text(tip)
                .changed()
                .then_some(Value::Bool(b))
        }
        OwnKind::Vec3 if u.colour => {
            let mut c = [u.value[0], u.value[1], u.value[2]];
            ui.color_edit_button_rgb(&mut c)
                .labelled_by(label)
                .on_hover_text(tip)
                .changed()
                .then_some(Value::Vec3(glam::Vec3::from_array(c)))
        }
        OwnKind::Vec4 if u.colour => {
            let mut c = [u.value[0], u.value[1], u.value[2], u.value[3]];
            ui.color_edit_button_rgba_unmultiplied(&mut c)
                .labelled_by(label)
                .on_hover_text(tip)
                .changed()
                .then_some(Value::Vec4(glam::Vec4::from_array(c)))
        }
        OwnKind::Vec2 | OwnKind::Vec3 | OwnKind::Vec4 => {
            let mut v = u.value.clone();
            let speed = (hi - lo) / 200.0;
            let mut changed = false;
            for x in &mut v {
                changed |= ui
                    .add(egui::DragValue::new(x).range(lo..=hi).speed(speed))
                    .labelled_by(label)
                    .on_hover_text(&tip)
                    .changed();
            }
            changed.then(|| match *v.as_slice() {
                [x, y] => Value::Vec2(glam::vec2(x, y)),
                [x, y, z, w] => Value::Vec4(glam::vec4(x, y, z, w)),
                _ => Value::Vec3(glam::Vec3::from_slice(&v)),
            })
        }
    }
}
