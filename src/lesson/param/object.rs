//! `objects.NAME.p`: an object's transform, colour, material, and the parameters of its built-in
//! shape (a Bézier curve's or patch's, an implicit surface's, a signal's or a wheel's).

use glam::Vec3;
use pipeline::mesh::BuiltinMesh;
use pipeline::mesh::implicit::Implicit;

use super::{Problem, Value, choice, number, vec3};

/// The parameters of every object (`objects.NAME.p`): transform, colour, material.
pub(super) const OBJECT_PARAMS: [&str; 14] = [
    "translate",
    "rotate",
    "scale",
    "color",
    "axis",
    "axis_angle",
    "slerp_axis",
    "slerp_angle",
    "slerp_t",
    "ka",
    "kd",
    "ks",
    "shininess",
    "normals",
];

/// The parameters a built-in Bézier curve adds: its control points, the drawn `t` and how many
/// levels of the construction are drawn.
pub(super) const BEZIER_PARAMS: [&str; 6] = ["t", "p0", "p1", "p2", "p3", "levels"];

/// The parameters a built-in Bézier patch adds: the constructed point's `u`, `v`, how much of
/// the construction is drawn, and each control point's height `hIJ` (row I, column J).
pub(super) const PATCH_PARAMS: [&str; 19] = [
    "u", "v", "levels", "h00", "h01", "h02", "h03", "h10", "h11", "h12", "h13", "h20", "h21",
    "h22", "h23", "h30", "h31", "h32", "h33",
];

/// The parameters an implicit surface adds: its shape, the gap between its two primitives, the
/// blend's smoothing, the polygonizing grid's resolution, and the size of its point cloud.
pub(super) const IMPLICIT_PARAMS: [&str; 5] = ["shape", "gap", "smooth", "resolution", "cloud"];

/// `p` of an implicit surface `s`: the surface with it changed.
fn implicit_param(mut s: Implicit, p: &str, v: &Value) -> Result<BuiltinMesh, Problem> {
    match p {
        "shape" => s.shape = choice(v, &pipeline::mesh::implicit::ImplicitShape::NAMES)?,
        "gap" => s.gap = in_range(p, number(v)?, 0.0, 3.0)?,
        "smooth" => s.smooth = in_range(p, number(v)?, 0.0, 2.0)?,
        "resolution" => {
            let n = in_range(p, number(v)?, 0.0, 96.0)?;
            if n < 4.0 {
                return Err(format!("resolution is at least 4 cells, got {n}").into());
            }
            s.resolution = n.round() as u32;
        }
        "cloud" => s.points = in_range(p, number(v)?, 0.0, 20_000.0)?.round() as u32,
        _ => return Err(Problem::Unknown),
    }
    Ok(BuiltinMesh::Implicit(s))
}

/// The parameters a sampled signal and a filmed wheel add.
pub(super) const SIGNAL_PARAMS: [&str; 3] = ["frequency", "rate", "blur"];
/// See [`SIGNAL_PARAMS`].
pub(super) const WHEEL_PARAMS: [&str; 3] = ["spokes", "step", "frames"];

/// `p` of a signal or a wheel: the shape with it changed.
fn sampling_param(shape: BuiltinMesh, p: &str, v: &Value) -> Result<BuiltinMesh, Problem> {
    let x = number(v)?;
    let within = |min: f32, max: f32| in_range(p, x, min, max);
    match (shape, p) {
        (BuiltinMesh::Signal(mut s), "frequency" | "rate" | "blur") => {
            match p {
                "frequency" => s.frequency = within(0.0, 40.0)?,
                "rate" => s.rate = within(1.0, 100.0)?,
                _ => s.blur = within(0.0, 4.0)?,
            }
            Ok(BuiltinMesh::Signal(s))
        }
        (BuiltinMesh::Wheel(mut w), "spokes" | "step" | "frames") => {
            match p {
                "spokes" => w.spokes = within(1.0, 36.0)?.round() as u32,
                "step" => w.step = within(-360.0, 360.0)?,
                _ => w.frames = within(1.0, 8.0)?.round() as u32,
            }
            Ok(BuiltinMesh::Wheel(w))
        }
        _ => Err(Problem::Unknown),
    }
}

/// `p` of a Bézier patch (`u`, `v`, `levels` or a height `hIJ`): the patch with it changed.
fn patch_param(
    mut heights: [[f32; 4]; 4],
    [mut pu, mut pv]: [f32; 2],
    mut levels: u8,
    p: &str,
    v: &Value,
) -> Result<BuiltinMesh, Problem> {
    match p.as_bytes() {
        b"u" => pu = in_range(p, number(v)?, 0.0, 1.0)?,
        b"v" => pv = in_range(p, number(v)?, 0.0, 1.0)?,
        b"levels" => {
            let n = number(v)?;
            if !matches!(n, 0.0 | 1.0 | 2.0) {
                return Err(format!("levels is 0, 1 or 2, got {n}").into());
            }
            levels = n as u8;
        }
        [b'h', i @ b'0'..=b'3', j @ b'0'..=b'3'] => {
            heights[usize::from(i - b'0')][usize::from(j - b'0')] = number(v)?;
        }
        _ => return Err(Problem::Unknown),
    }
    Ok(BuiltinMesh::BezierPatch {
        heights,
        u: pu,
        v: pv,
        levels,
    })
}

/// `p` of a Bézier curve (`t`, `levels` or a control point `pK`): the curve with it changed.
fn curve_param(
    mut points: [glam::Vec2; 4],
    mut t: f32,
    mut levels: u8,
    p: &str,
    v: &Value,
) -> Result<BuiltinMesh, Problem> {
    match p {
        "t" => t = in_range(p, number(v)?, 0.0, 1.0)?,
        "levels" => {
            let n = number(v)?;
            if !matches!(n, 0.0 | 1.0 | 2.0 | 3.0) {
                return Err(format!("levels is 0, 1, 2 or 3, got {n}").into());
            }
            levels = n as u8;
        }
        _ => {
            let k = usize::from(p.as_bytes()[1] - b'0');
            points[k] = vec3(v)?.truncate();
        }
    }
    Ok(BuiltinMesh::Bezier { points, t, levels })
}

/// `x` when it lies in `[min, max]`, else a message naming parameter `p`.
fn in_range(p: &str, x: f32, min: f32, max: f32) -> Result<f32, String> {
    if (min..=max).contains(&x) {
        Ok(x)
    } else {
        Err(format!("{p} must be from {min} to {max}, got {x}"))
    }
}

/// A parameter of the object's built-in shape that only some shapes have (a Bézier curve's or
/// patch's, an implicit surface's, a signal's or a wheel's), or `None` when `p` is not one of its
/// shape's. The shape changed, the object's mesh is built again from it.
fn shape_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Option<Result<(), Problem>> {
    let shape = match o.builtin? {
        BuiltinMesh::Bezier { points, t, levels } if BEZIER_PARAMS.contains(&p) => {
            curve_param(points, t, levels, p, v)
        }
        BuiltinMesh::BezierPatch {
            heights,
            u,
            v: pv,
            levels,
        } if PATCH_PARAMS.contains(&p) => patch_param(heights, [u, pv], levels, p, v),
        BuiltinMesh::Implicit(s) if IMPLICIT_PARAMS.contains(&p) => implicit_param(s, p, v),
        s @ (BuiltinMesh::Signal(_) | BuiltinMesh::Wheel(_))
            if SIGNAL_PARAMS.contains(&p) || WHEEL_PARAMS.contains(&p) =>
        {
            sampling_param(s, p, v)
        }
        _ => return None,
    };
    Some(shape.map(|shape| {
        o.builtin = Some(shape);
        o.mesh = std::sync::Arc::new(shape.build());
    }))
}

/// `objects.NAME.p`: the object's transform, colour, material, or its built-in shape.
pub(super) fn object_param(
    o: &mut pipeline::scene::Object,
    p: &str,
    v: &Value,
) -> Result<(), Problem> {
    if let Some(done) = shape_param(o, p, v) {
        return done;
    }
    match p {
        "translate" => o.translate = vec3(v)?,
        "rotate" => o.rotate_deg = vec3(v)?,
        "scale" => {
            o.scale = match v {
                Value::Number(_) => Vec3::splat(number(v)?),
                _ => vec3(v)?,
            };
        }
        "color" => o.color = pipeline::scene::ColorSource::Uniform(vec3(v)?),
        "axis" => {
            let axis = vec3(v)?;
            if axis.length() < 1e-6 {
                return Err("the axis must not be the zero vector".to_owned().into());
            }
            let angle = o.axis_rotation.map_or(0.0, |(_, a)| a);
            o.axis_rotation = Some((axis, angle));
        }
        "ka" | "kd" | "ks" => {
            let k = match v {
                Value::Number(_) => Vec3::splat(number(v)?),
                _ => vec3(v)?,
            };
            if k.min_element() < 0.0 {
                return Err("reflection coefficients must not be negative"
                    .to_owned()
                    .into());
            }
            let m = &mut o.material;
            *match p {
                "ka" => &mut m.ka,
                "kd" => &mut m.kd,
                _ => &mut m.ks,
            } = k;
        }
        "normals" => {
            let averaging = choice(v, crate::lesson::validate::NORMALS)?;
            let mut mesh = (*o.mesh).clone();
            mesh.compute_vertex_normals(averaging);
            o.mesh = std::sync::Arc::new(mesh);
        }
        "shininess" => {
            let x = number(v)?;
            if !(x >= 0.0) {
                return Err(format!("shininess must not be negative, got {x}").into());
            }
            o.material.shininess = x;
        }
        "axis_angle" => {
            let axis = o.axis_rotation.map_or(Vec3::Y, |(a, _)| a);
            o.axis_rotation = Some((axis, number(v)?));
        }
        "slerp_axis" | "slerp_angle" | "slerp_t" => slerp_param(o, p, v)?,
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}

/// `slerp_axis`, `slerp_angle`, `slerp_t`: the second orientation of a slerp and how far along
/// the arc. The first one is the object's rotation about an axis; without a `slerp_to` yet, the
/// second starts equal to it (and `t = 0`), so setting its parameters one by one builds it.
fn slerp_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Result<(), Problem> {
    let Some((axis, angle_deg)) = o.axis_rotation else {
        return Err(
            "slerp starts from the object's rotation about an axis: give it `rotate_axis` first"
                .to_owned()
                .into(),
        );
    };
    let s = o.slerp.get_or_insert(pipeline::transform::SlerpTo {
        axis,
        angle_deg,
        t: 0.0,
    });
    match p {
        "slerp_axis" => {
            let axis = vec3(v)?;
            if axis.length() < 1e-6 {
                return Err("the axis must not be the zero vector".to_owned().into());
            }
            s.axis = axis;
        }
        "slerp_angle" => s.angle_deg = number(v)?,
        _ => s.t = in_range(p, number(v)?, 0.0, 1.0)?,
    }
    Ok(())
}
