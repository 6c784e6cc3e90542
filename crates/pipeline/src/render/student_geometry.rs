//! The scene as the student's pipeline functions draw it, before the stages run: a Bézier
//! curve's or patch's mesh from the student's points, the planar shadow from the student's
//! matrix. A run-time error of such a function is a [`RenderError::Code`] naming it.

use super::{CodePart, RenderError};
use crate::scene::Scene;
use crate::shader::HookKind;

/// The scene with each Bézier curve that carries the student's de Casteljau drawn from the
/// student's curve points, and each Bézier patch that carries the student's `bezier_patch` from
/// the student's surface points; `None` when no object carries either.
///
/// # Errors
/// A run-time error of the student's function.
pub(super) fn with_student_curves(
    scene: &Scene,
    budget: u32,
) -> Result<Option<Scene>, RenderError> {
    use crate::mesh::BuiltinMesh;
    if !scene.objects.iter().any(|o| {
        o.code.hooks.get(HookKind::Curve).is_some() || o.code.hooks.get(HookKind::Patch).is_some()
    }) {
        return Ok(None);
    }
    let mut drawn = scene.clone();
    for o in &mut drawn.objects {
        let failed = |kind| {
            let object = o.name.clone();
            move |error| RenderError::Code {
                part: CodePart::Function(kind),
                object,
                error: Box::new(error),
                file: None,
            }
        };
        let within = |h: Option<crate::shader::Hook>| h.map(|h| h.within(budget));
        let mesh = match (
            within(o.code.hooks.slot(HookKind::Curve).take()),
            within(o.code.hooks.slot(HookKind::Patch).take()),
            &o.builtin,
        ) {
            (Some(hook), _, Some(BuiltinMesh::Bezier { points, t, levels })) => {
                let curve = |ts: &[f32]| hook.curve_points(*points, ts);
                crate::mesh::construction_mesh_from(*points, *t, *levels, &curve)
                    .map_err(failed(HookKind::Curve))?
            }
            (
                _,
                Some(hook),
                Some(BuiltinMesh::BezierPatch {
                    heights,
                    u,
                    v,
                    levels,
                }),
            ) => {
                let points =
                    |rows: &[[glam::Vec3; 4]; 4], uvs: &[glam::Vec2]| hook.patch_points(rows, uvs);
                crate::mesh::patch::patch_mesh_from(heights, *u, *v, *levels, &points)
                    .map_err(failed(HookKind::Patch))?
            }
            _ => continue,
        };
        o.mesh = std::sync::Arc::new(mesh);
    }
    Ok(Some(drawn))
}

/// The scene with its planar shadow projected by the student's `shadow_matrix` (called once,
/// for the light relative to the plane); `None` when the scene has no shadow, no object carries
/// the function, or its matrix is already in place.
///
/// # Errors
/// A run-time error of the student's function, or a matrix that is not finite.
pub(super) fn with_student_shadow(
    scene: &Scene,
    budget: u32,
) -> Result<Option<Scene>, RenderError> {
    let Some(shadow) = scene.shadow.filter(|s| s.yours.is_none()) else {
        return Ok(None);
    };
    let kind = HookKind::ShadowMatrix;
    let Some(holder) = scene
        .objects
        .iter()
        .find(|o| o.code.hooks.get(kind).is_some())
    else {
        return Ok(None);
    };
    let light = shadow.light_over_plane();
    let m = holder
        .code
        .hooks
        .get(kind)
        .expect("found above")
        .within(budget)
        .shadow_matrix(light)
        .map_err(|e| RenderError::Code {
            part: CodePart::Function(kind),
            object: holder.name.clone(),
            error: Box::new(e),
            file: None,
        })?;
    if !m.is_finite() {
        return Err(RenderError::ShadowMatrix { light, matrix: m });
    }
    let mut drawn = scene.clone();
    drawn.shadow = Some(crate::scene::PlanarShadow {
        yours: Some(m),
        ..shadow
    });
    Ok(Some(drawn))
}
