//! The parameters' editing fields shared by the panel's sections: a vector as three drag
//! values with its label and tooltip.

use egui::{DragValue, Ui};
use glam::Vec3;

/// `v` edited as x, y and z dragged by `speed`, after `label` (explained by `tip`).
pub(super) fn vec3_edit(ui: &mut Ui, label: &str, v: &mut Vec3, speed: f32, tip: &str) {
    ui.horizontal(|ui| {
        ui.label(label).on_hover_text(tip);
        ui.add(
            DragValue::new(&mut v.x)
                .speed(speed)
                .prefix("x ")
                .max_decimals(3),
        );
        ui.add(
            DragValue::new(&mut v.y)
                .speed(speed)
                .prefix("y ")
                .max_decimals(3),
        );
        ui.add(
            DragValue::new(&mut v.z)
                .speed(speed)
                .prefix("z ")
                .max_decimals(3),
        );
    });
}
