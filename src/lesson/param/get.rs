//! Reading a parameter: the value `set` would have to be given to leave the scene as it is. A
//! step recorded from what is on screen writes, as `set` entries, the parameters whose values
//! differ from the lesson's scene.

use glam::Vec3;
use pipeline::camera::Projection;
use pipeline::mesh::BuiltinMesh;

use super::Value;
use crate::lesson::SceneSpec;
use crate::lesson::validate::{CULL, DEPTH_TEST, FILTER, MIPMAP, REFLECTION, SHADING, WRAP};

/// The value of parameter `name` in `spec`, as `set` takes it; `None` for an unknown name, a
/// parameter the scene's projection, light or shape does not have, or one that is not kept as a
/// value (an object's `normals`, how its vertex normals were once averaged).
#[must_use]
pub fn get(spec: &SceneSpec, name: &str) -> Option<Value> {
    let parts: Vec<&str> = name.split('.').collect();
    match parts.as_slice() {
        ["camera", p] => {
            let c = &spec.scene.camera;
            Some(Value::Vec3(match *p {
                "eye" => c.eye,
                "at" => c.at,
                "up" => c.up,
                _ => return None,
            }))
        }
        ["projection", p] => projection(&spec.scene.projection, p),
        ["render", p] => render(spec, p),
        ["shadow", "light"] => spec.scene.shadow.map(|s| Value::Vec3(s.light)),
        ["objects", object, p] => {
            let o = spec.scene.objects.iter().find(|o| o.name == *object)?;
            shape(o.builtin?, p).or_else(|| object_param(o, p))
        }
        ["lights", k, p] => light(&spec.scene.lights[spec.light_index(k)?], p),
        ["figures", figure, joint] => {
            let mut f = spec
                .scene
                .figures
                .iter()
                .find(|f| f.name == *figure)?
                .clone();
            let joints = f.pose.joints_mut();
            let (_, value) = joints.into_iter().find(|(j, _)| j == joint)?;
            Some(Value::Number(*value))
        }
        ["uniforms", u] => {
            use pipeline::shader::own_uniform::OwnKind;
            let u = spec
                .scene
                .own_uniforms()
                .into_iter()
                .find(|o| o.name == *u)?;
            Some(match u.kind {
                OwnKind::Float | OwnKind::Int => Value::Number(u.value[0]),
                OwnKind::Bool => Value::Bool(u.value[0] != 0.0),
                OwnKind::Vec2 => Value::Vec2(glam::Vec2::from_slice(&u.value)),
                OwnKind::Vec3 => Value::Vec3(Vec3::from_slice(&u.value)),
                OwnKind::Vec4 => Value::Vec4(glam::Vec4::from_slice(&u.value)),
            })
        }
        _ => None,
    }
}

/// The name `options` give `value`.
fn named<T: PartialEq>(options: &[(&str, T)], value: &T) -> Option<Value> {
    options
        .iter()
        .find(|(_, t)| t == value)
        .map(|(n, _)| Value::Name((*n).to_owned()))
}

fn projection(p: &Projection, key: &str) -> Option<Value> {
    let number = |x: f32| Some(Value::Number(x));
    match (p, key) {
        (_, "kind") => Some(Value::Name(
            match p {
                Projection::Perspective { .. } => "perspective",
                Projection::Frustum { .. } => "frustum",
                Projection::Ortho { .. } => "ortho",
            }
            .to_owned(),
        )),
        (Projection::Perspective { fovy_deg, .. }, "fovy") => number(*fovy_deg),
        (Projection::Perspective { aspect, .. }, "aspect") => aspect.map(Value::Number),
        (
            Projection::Perspective { near, .. }
            | Projection::Frustum { near, .. }
            | Projection::Ortho { near, .. },
            "near",
        ) => number(*near),
        (
            Projection::Perspective { far, .. }
            | Projection::Frustum { far, .. }
            | Projection::Ortho { far, .. },
            "far",
        ) => number(*far),
        (Projection::Frustum { left, .. } | Projection::Ortho { left, .. }, "left") => {
            number(*left)
        }
        (Projection::Frustum { right, .. } | Projection::Ortho { right, .. }, "right") => {
            number(*right)
        }
        (Projection::Frustum { bottom, .. } | Projection::Ortho { bottom, .. }, "bottom") => {
            number(*bottom)
        }
        (Projection::Frustum { top, .. } | Projection::Ortho { top, .. }, "top") => number(*top),
        _ => None,
    }
}

fn render(spec: &SceneSpec, key: &str) -> Option<Value> {
    let s = &spec.settings;
    match key {
        "samples" => Some(Value::Number(s.samples.count() as f32)),
        "cull" => named(CULL, &s.cull),
        "depth_test" => named(DEPTH_TEST, &s.depth_test),
        "perspective_correct" => Some(Value::Bool(s.perspective_correct)),
        "per_sample_shading" => Some(Value::Bool(s.per_sample_shading)),
        "shading" => named(SHADING, &s.shading),
        "reflection" => named(REFLECTION, &s.reflection),
        "filter" => named(FILTER, &s.sampler.filter),
        "mipmap" => named(MIPMAP, &s.sampler.mipmap),
        "wrap" => named(WRAP, &s.sampler.wrap),
        "anisotropy" => Some(Value::Number(s.sampler.anisotropy as f32)),
        "lod_bias" => Some(Value::Number(s.sampler.lod_bias)),
        "max_steps" => Some(Value::Number(s.max_steps as f32)),
        _ => None,
    }
}

fn light(light: &pipeline::light::Light, key: &str) -> Option<Value> {
    use pipeline::light::Light;
    match (light, key) {
        (Light::Point { position, .. } | Light::Spot { position, .. }, "position") => {
            Some(Value::Vec3(*position))
        }
        (Light::Directional { direction, .. } | Light::Spot { direction, .. }, "direction") => {
            Some(Value::Vec3(*direction))
        }
        (
            Light::Ambient { intensity }
            | Light::Point { intensity, .. }
            | Light::Directional { intensity, .. }
            | Light::Spot { intensity, .. },
            "intensity",
        ) => Some(Value::Vec3(*intensity)),
        (Light::Spot { cutoff_deg, .. }, "cutoff") => Some(Value::Number(*cutoff_deg)),
        (Light::Spot { exponent, .. }, "exponent") => Some(Value::Number(*exponent)),
        _ => None,
    }
}

/// A parameter of an object's built-in shape, when `p` is one of that shape's.
fn shape(shape: BuiltinMesh, p: &str) -> Option<Value> {
    let number = |x: f32| Some(Value::Number(x));
    match shape {
        BuiltinMesh::Bezier { points, t, levels } => match p.as_bytes() {
            b"t" => number(t),
            b"levels" => number(f32::from(levels)),
            [b'p', k @ b'0'..=b'3'] => Some(Value::Vec3(points[usize::from(k - b'0')].extend(0.0))),
            _ => None,
        },
        BuiltinMesh::BezierPatch {
            heights,
            u,
            v,
            levels,
        } => match p.as_bytes() {
            b"u" => number(u),
            b"v" => number(v),
            b"levels" => number(f32::from(levels)),
            [b'h', i @ b'0'..=b'3', j @ b'0'..=b'3'] => {
                number(heights[usize::from(i - b'0')][usize::from(j - b'0')])
            }
            _ => None,
        },
        BuiltinMesh::Implicit(s) => match p {
            "shape" => named(&pipeline::mesh::implicit::ImplicitShape::NAMES, &s.shape),
            "gap" => number(s.gap),
            "smooth" => number(s.smooth),
            "resolution" => number(s.resolution as f32),
            "cloud" => number(s.points as f32),
            _ => None,
        },
        BuiltinMesh::Signal(s) => match p {
            "frequency" => number(s.frequency),
            "rate" => number(s.rate),
            "blur" => number(s.blur),
            _ => None,
        },
        BuiltinMesh::Wheel(w) => match p {
            "spokes" => number(w.spokes as f32),
            "step" => number(w.step),
            "frames" => number(w.frames as f32),
            _ => None,
        },
        _ => None,
    }
}

/// An object's transform, colour or material parameter.
fn object_param(o: &pipeline::scene::Object, p: &str) -> Option<Value> {
    let v3 = |v: Vec3| Some(Value::Vec3(v));
    match p {
        "translate" => v3(o.translate),
        "rotate" => v3(o.rotate_deg),
        "scale" => v3(o.scale),
        "color" => match o.color {
            pipeline::scene::ColorSource::Uniform(c) => v3(c),
            _ => None,
        },
        "axis" => o.axis_rotation.and_then(|(a, _)| v3(a)),
        "axis_angle" => o.axis_rotation.map(|(_, a)| Value::Number(a)),
        "slerp_axis" => o.slerp.and_then(|s| v3(s.axis)),
        "slerp_angle" => o.slerp.map(|s| Value::Number(s.angle_deg)),
        "slerp_t" => o.slerp.map(|s| Value::Number(s.t)),
        "ka" => v3(o.material.ka),
        "kd" => v3(o.material.kd),
        "ks" => v3(o.material.ks),
        "shininess" => Some(Value::Number(o.material.shininess)),
        _ => None,
    }
}

/// The parameters whose values differ between `base` (the lesson's scene) and `now`, with
/// their values in `now`, in [`super::names`]' order: what a step recorded from `now` sets.
/// Numbers equal to a part in a million count as equal (a slider's float noise). A uniform of
/// the shaders' own that `base` does not have is left out (it comes with the shader).
#[must_use]
pub fn differences(base: &SceneSpec, now: &SceneSpec) -> Vec<(String, Value)> {
    super::names(now)
        .into_iter()
        .filter_map(|name| {
            let v = get(now, &name)?;
            let was = get(base, &name);
            // A uniform of a shader `base` does not run comes with that shader, its value
            // from its comment: not something `set` could change on `base`.
            if was.is_none() && name.starts_with("uniforms.") {
                return None;
            }
            let same = was.is_some_and(|b| close(&b, &v));
            (!same).then_some((name, v))
        })
        .collect()
}

fn close(a: &Value, b: &Value) -> bool {
    let near = |x: f32, y: f32| (x - y).abs() <= 1e-6 * x.abs().max(y.abs()).max(1.0);
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => near(*x, *y),
        (Value::Vec2(x), Value::Vec2(y)) => (0..2).all(|k| near(x[k], y[k])),
        (Value::Vec3(x), Value::Vec3(y)) => (0..3).all(|k| near(x[k], y[k])),
        (Value::Vec4(x), Value::Vec4(y)) => (0..4).all(|k| near(x[k], y[k])),
        _ => a == b,
    }
}
