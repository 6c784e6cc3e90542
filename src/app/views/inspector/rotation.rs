//! An object's rotation about an arbitrary axis, beside its model matrix: R(n, θ) by Rodrigues'
//! formula and by the unit quaternion; and, when the object moves between two orientations, the
//! slerp between their quaternions, number by number.

use egui::{RichText, Ui};

use crate::app::session::Session;
use crate::app::views::typeset;

/// The rotation forms of object `k`, if it has a rotation about an axis: the slerp when it moves
/// between two orientations, Rodrigues and the quaternion otherwise.
pub fn forms(ui: &mut Ui, session: &Session, k: usize) {
    let Some(o) = session.spec.scene.objects.get(k) else {
        return;
    };
    match (o.axis_rotation, o.slerp) {
        (Some((axis, degrees)), Some(s)) => slerp_forms(ui, session, (axis, degrees), s),
        (Some(_), None) => axis_forms(ui, session, k),
        _ => {}
    }
}

/// For an object turned about an arbitrary axis (shown first: the rotation is the subject), the
/// rotation R(n, θ) of its model matrix's factors two more ways, computed
/// independently: Rodrigues' formula, and the unit quaternion q (through glam's `Quat`), with the
/// slerp halfway from no rotation to q.
fn axis_forms(ui: &mut Ui, session: &Session, k: usize) {
    let Some((axis, degrees)) = session
        .spec
        .scene
        .objects
        .get(k)
        .and_then(|o| o.axis_rotation)
    else {
        return;
    };
    let Some(n) = axis.try_normalize() else {
        return;
    };
    let lang = session.lang;
    let theta = degrees.to_radians();
    let style = crate::app::views::typeset::Style::body(ui);
    ui.add_space(6.0);
    egui::CollapsingHeader::new(RichText::new(lang.t("rotation-the-same-rotation-r-n")).strong())
        .id_salt("axis-rotation-forms")
        .default_open(true)
        .show(ui, |ui| {
            typeset::formula(
                ui,
                "R(n, θ) = cos θ·I + (1 − cos θ)·n·n^T + sin θ·N",
                &style,
            );
            typeset::note(
                ui,
                &format!(
                    "{} n = ({:.3}, {:.3}, {:.3}), θ = {degrees:.1}°",
                    lang.t("rotation-rodrigues-formula-n-the-cross"),
                    n.x,
                    n.y,
                    n.z
                ),
            );
            if let Ok(r) = pipeline::transform::rotate_axis_rodrigues(n, theta) {
                crate::app::views::matrix_grid(ui, &r, "rodrigues", lang);
            }
            ui.add_space(4.0);
            let q = glam::Quat::from_axis_angle(n, theta);
            typeset::formula(ui, "q = (cos(θ/2), sin(θ/2)·n), v′ = q·v·q^(−1)", &style);
            typeset::note(
                ui,
                &format!(
                    "q = ({:.3}, {:.3}, {:.3}, {:.3}) {}",
                    q.w,
                    q.x,
                    q.y,
                    q.z,
                    lang.t("rotation-w-x-y-z-q")
                ),
            );
            crate::app::views::matrix_grid(ui, &glam::Mat4::from_quat(q), "quaternion", lang);
            let half = glam::Quat::IDENTITY.slerp(q, 0.5);
            typeset::note(
                ui,
                &format!(
                    "slerp(1, q, ½) = ({:.3}, {:.3}, {:.3}, {:.3}): {}",
                    half.w,
                    half.x,
                    half.y,
                    half.z,
                    lang.t("rotation-halfway-along-the-shortest-arc")
                ),
            );
        });
}

/// slerp from q₀ (the rotation about the object's axis) to q₁ (its `slerp_to`): the two
/// quaternions, cos Ω = q₀·q₁ (and the sign flip to the shorter arc), the two weights at t, the
/// result with its axis and angle, and its matrix.
fn slerp_forms(
    ui: &mut Ui,
    session: &Session,
    (axis, degrees): (glam::Vec3, f32),
    s: pipeline::transform::SlerpTo,
) {
    let Ok((q0, q1)) = s.ends(axis, degrees) else {
        return;
    };
    let lang = session.lang;
    let style = typeset::Style::body(ui);
    let quat = |q: &pipeline::transform::Quaternion| {
        format!("({:.3}, {:.3}, {:.3}, {:.3})", q.w, q.v.x, q.v.y, q.v.z)
    };
    let arc = q0.arc_to(&q1);
    let (a, b) = arc.weights(s.t);
    let q = q0.slerp(&q1, s.t);
    let (n, angle) = q.axis_angle();
    ui.add_space(6.0);
    egui::CollapsingHeader::new(
        RichText::new(lang.t("rotation-between-two-orientations-slerp")).strong(),
    )
    .id_salt("slerp-forms")
    .default_open(true)
    .show(ui, |ui| {
        typeset::formula(
            ui,
            "slerp(q₀, q₁, t) = [sin((1 − t)Ω)·q₀ + sin(tΩ)·q₁]/(sin Ω), cos Ω = q₀·q₁",
            &style,
        );
        typeset::note(
            ui,
            &format!(
                "q₀ = {} ({degrees:.1}°, {})",
                quat(&q0),
                lang.t("rotation-the-first-axis"),
            ),
        );
        typeset::note(
            ui,
            &format!(
                "q₁ = {} ({:.1}°, {})",
                quat(&q1),
                s.angle_deg,
                lang.t("rotation-the-second-axis"),
            ),
        );
        let dot = q0.dot(&q1);
        let flip = if arc.flipped {
            lang.t("rotation-0-slerp-takes-q-the")
        } else {
            ""
        };
        typeset::note(
            ui,
            &format!(
                "q₀·q₁ = {dot:.3}{flip}; Ω = {:.1}°, {} 2Ω = {:.1}°",
                arc.omega.to_degrees(),
                lang.t("rotation-the-turn-from-one-to"),
                2.0 * arc.omega.to_degrees()
            ),
        );
        typeset::note(
            ui,
            &format!(
                "t = {:.2}: {} {a:.3}, {b:.3}",
                s.t,
                lang.t("rotation-weights"),
            ),
        );
        typeset::note(
            ui,
            &format!(
                "slerp = {} = {angle:.1}° {} ({:.3}, {:.3}, {:.3})",
                quat(&q),
                lang.t("rotation-about"),
                n.x,
                n.y,
                n.z,
                angle = angle.to_degrees(),
            ),
        );
        crate::app::views::matrix_grid(ui, &q.to_matrix(), "slerp", lang);
    });
}
