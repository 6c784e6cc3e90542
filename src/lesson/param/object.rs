//! `objects.NAME.p`: an object's transform, colour, material, and the parameters of its built-in
//! shape (a Bézier curve's or patch's).

use glam::Vec3;

use super::{Problem, Value, choice, number, vec3};

/// The parameters of every object (`objects.NAME.p`): transform, colour, material.
pub(super) const OBJECT_PARAMS: [&str; 11] = [
    "translate",
    "rotate",
    "scale",
    "color",
    "axis",
    "axis_angle",
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

/// `objects.NAME.p` of an implicit surface.
fn implicit_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Result<(), Problem> {
    let Some(pipeline::mesh::BuiltinMesh::Implicit(mut s)) = o.builtin else {
        return Err(Problem::Unknown);
    };
    let within = |x: f32, max: f32| {
        if (0.0..=max).contains(&x) {
            Ok(x)
        } else {
            Err(format!("{p} must be from 0 to {max}, got {x}"))
        }
    };
    match p {
        "shape" => s.shape = choice(v, &pipeline::mesh::implicit::ImplicitShape::NAMES)?,
        "gap" => s.gap = within(number(v)?, 3.0)?,
        "smooth" => s.smooth = within(number(v)?, 2.0)?,
        "resolution" => {
            let n = within(number(v)?, 96.0)?;
            if n < 4.0 {
                return Err(format!("resolution is at least 4 cells, got {n}").into());
            }
            s.resolution = n.round() as u32;
        }
        "cloud" => s.points = within(number(v)?, 20_000.0)?.round() as u32,
        _ => return Err(Problem::Unknown),
    }
    let shape = pipeline::mesh::BuiltinMesh::Implicit(s);
    o.builtin = Some(shape);
    o.mesh = std::sync::Arc::new(shape.build());
    Ok(())
}

/// The parameters a sampled signal and a filmed wheel add.
pub(super) const SIGNAL_PARAMS: [&str; 3] = ["frequency", "rate", "blur"];
/// See [`SIGNAL_PARAMS`].
pub(super) const WHEEL_PARAMS: [&str; 3] = ["spokes", "step", "frames"];

/// `objects.NAME.p` of a signal or a wheel.
fn sampling_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Result<(), Problem> {
    use pipeline::mesh::BuiltinMesh;
    let x = number(v)?;
    let within = |min: f32, max: f32| {
        if (min..=max).contains(&x) {
            Ok(x)
        } else {
            Err(format!("{p} must be from {min} to {max}, got {x}"))
        }
    };
    let shape = match (o.builtin, p) {
        (Some(BuiltinMesh::Signal(mut s)), _) => {
            match p {
                "frequency" => s.frequency = within(0.0, 40.0)?,
                "rate" => s.rate = within(1.0, 100.0)?,
                "blur" => s.blur = within(0.0, 4.0)?,
                _ => return Err(Problem::Unknown),
            }
            BuiltinMesh::Signal(s)
        }
        (Some(BuiltinMesh::Wheel(mut w)), _) => {
            match p {
                "spokes" => w.spokes = within(1.0, 36.0)?.round() as u32,
                "step" => w.step = within(-360.0, 360.0)?,
                "frames" => w.frames = within(1.0, 8.0)?.round() as u32,
                _ => return Err(Problem::Unknown),
            }
            BuiltinMesh::Wheel(w)
        }
        _ => return Err(Problem::Unknown),
    };
    o.builtin = Some(shape);
    o.mesh = std::sync::Arc::new(shape.build());
    Ok(())
}

/// `objects.NAME.p` of a Bézier patch: `u`, `v`, `levels` or a height `hIJ`.
fn patch_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Result<(), Problem> {
    let Some(pipeline::mesh::BuiltinMesh::BezierPatch {
        mut heights,
        u: mut pu,
        v: mut pv,
        mut levels,
    }) = o.builtin
    else {
        return Err(Problem::Unknown);
    };
    match p.as_bytes() {
        b"u" | b"v" => {
            let x = number(v)?;
            if !(0.0..=1.0).contains(&x) {
                return Err(format!("{p} must be from 0 to 1, got {x}").into());
            }
            *(if p == "u" { &mut pu } else { &mut pv }) = x;
        }
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
    let shape = pipeline::mesh::BuiltinMesh::BezierPatch {
        heights,
        u: pu,
        v: pv,
        levels,
    };
    o.builtin = Some(shape);
    o.mesh = std::sync::Arc::new(shape.build());
    Ok(())
}

/// A parameter of the object's built-in shape that only some shapes have (a patch's, an implicit
/// surface's, a signal's or a wheel's), or `None` when `p` is not one of its shape's.
fn shape_param(o: &mut pipeline::scene::Object, p: &str, v: &Value) -> Option<Result<(), Problem>> {
    use pipeline::mesh::BuiltinMesh;
    match o.builtin? {
        BuiltinMesh::BezierPatch { .. } if PATCH_PARAMS.contains(&p) => Some(patch_param(o, p, v)),
        BuiltinMesh::Implicit(_) if IMPLICIT_PARAMS.contains(&p) => Some(implicit_param(o, p, v)),
        BuiltinMesh::Signal(_) if SIGNAL_PARAMS.contains(&p) => Some(sampling_param(o, p, v)),
        BuiltinMesh::Wheel(_) if WHEEL_PARAMS.contains(&p) => Some(sampling_param(o, p, v)),
        _ => None,
    }
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
        "t" | "p0" | "p1" | "p2" | "p3" | "levels" => {
            let Some(pipeline::mesh::BuiltinMesh::Bezier {
                mut points,
                mut t,
                mut levels,
            }) = o.builtin
            else {
                return Err(Problem::Unknown);
            };
            if p == "t" {
                t = number(v)?;
                if !(0.0..=1.0).contains(&t) {
                    return Err(format!("t must be from 0 to 1, got {t}").into());
                }
            } else if p == "levels" {
                let n = number(v)?;
                if !matches!(n, 0.0 | 1.0 | 2.0 | 3.0) {
                    return Err(format!("levels is 0, 1, 2 or 3, got {n}").into());
                }
                levels = n as u8;
            } else {
                let k = usize::from(p.as_bytes()[1] - b'0');
                points[k] = vec3(v)?.truncate();
            }
            let shape = pipeline::mesh::BuiltinMesh::Bezier { points, t, levels };
            o.builtin = Some(shape);
            o.mesh = std::sync::Arc::new(shape.build());
        }
        "axis_angle" => {
            let axis = o.axis_rotation.map_or(Vec3::Y, |(a, _)| a);
            o.axis_rotation = Some((axis, number(v)?));
        }
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}
