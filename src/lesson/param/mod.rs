//! Lesson parameters: the names a lesson's `set` and `animate` use to change the scene
//! (`"projection.fovy"`, `"objects.bunny.rotate"`, `"figures.arm.lower"`…), their values, and
//! animations between two values over time.

mod describe;
mod get;
mod object;

use object::{
    BEZIER_PARAMS, IMPLICIT_PARAMS, OBJECT_PARAMS, PATCH_PARAMS, SIGNAL_PARAMS, WHEEL_PARAMS,
    object_param,
};

pub use describe::describe;
pub use get::{differences, get};

use glam::Vec3;
use pipeline::camera::{Projection, ProjectionKind};
use pipeline::raster::Samples;
use pipeline::settings::MAX_MAX_STEPS;

use super::SceneSpec;
use super::validate::{CULL, DEPTH_TEST, FILTER, MIPMAP, REFLECTION, SHADING, WRAP};

/// A value a parameter is set to.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A number.
    Number(f32),
    /// Two numbers (a `vec2` uniform of the shader's own).
    Vec2(glam::Vec2),
    /// Three numbers.
    Vec3(Vec3),
    /// Four numbers (a `vec4` uniform of the shader's own).
    Vec4(glam::Vec4),
    /// `true` or `false`.
    Bool(bool),
    /// A name, such as `"phong"`.
    Name(String),
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Number(x) => write!(f, "{x}"),
            Self::Vec2(v) => write!(f, "[{}, {}]", v.x, v.y),
            Self::Vec3(v) => write!(f, "[{}, {}, {}]", v.x, v.y, v.z),
            Self::Vec4(v) => write!(f, "[{}, {}, {}, {}]", v.x, v.y, v.z, v.w),
            Self::Bool(b) => write!(f, "{b}"),
            Self::Name(n) => write!(f, "\"{n}\""),
        }
    }
}

/// How an animation moves between its ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Easing {
    /// At a constant rate: `s = t`.
    Linear,
    /// Slow at both ends (smoothstep): `s = 3t² − 2t³`.
    EaseInOut,
}

/// What an animation does when it reaches its end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Repeat {
    /// Stops at `to`.
    Once,
    /// Starts again from `from`.
    Loop,
    /// Goes back to `from`, then forth again.
    PingPong,
}

impl Easing {
    /// The names a lesson file gives them.
    pub const NAMES: [(&str, Self); 2] =
        [("linear", Self::Linear), ("ease_in_out", Self::EaseInOut)];
    /// Without `easing`.
    pub const DEFAULT: Self = Self::EaseInOut;
}

impl Repeat {
    /// The names a lesson file gives them.
    pub const NAMES: [(&str, Self); 3] = [
        ("once", Self::Once),
        ("loop", Self::Loop),
        ("ping_pong", Self::PingPong),
    ];
    /// Without `repeat`.
    pub const DEFAULT: Self = Self::PingPong;
}

/// A parameter moving from one value to another.
#[derive(Clone, Debug, PartialEq)]
pub struct Animation {
    /// The parameter's name.
    pub param: String,
    /// The value at the start.
    pub from: Value,
    /// The value at the end.
    pub to: Value,
    /// Seconds from `from` to `to`.
    pub seconds: f32,
    /// The pace.
    pub easing: Easing,
    /// What happens at the end.
    pub repeat: Repeat,
}

impl Animation {
    /// The value `t` seconds after the start: `from + (to − from)·ease(phase)`, the phase
    /// running 0 → 1 over `seconds` and then stopping, restarting or reversing.
    #[must_use]
    pub fn value_at(&self, t: f32) -> Value {
        let x = (t / self.seconds.max(1e-6)).max(0.0);
        let phase = match self.repeat {
            Repeat::Once => x.min(1.0),
            Repeat::Loop => x.fract(),
            Repeat::PingPong => {
                let p = x % 2.0;
                if p > 1.0 { 2.0 - p } else { p }
            }
        };
        let s = match self.easing {
            Easing::Linear => phase,
            Easing::EaseInOut => phase * phase * (3.0 - 2.0 * phase),
        };
        match (&self.from, &self.to) {
            (Value::Number(a), Value::Number(b)) => Value::Number(a + (b - a) * s),
            (Value::Vec2(a), Value::Vec2(b)) => Value::Vec2(a.lerp(*b, s)),
            (Value::Vec3(a), Value::Vec3(b)) => Value::Vec3(a.lerp(*b, s)),
            (Value::Vec4(a), Value::Vec4(b)) => Value::Vec4(a.lerp(*b, s)),
            _ => self.to.clone(),
        }
    }

    /// Whether it has stopped moving `t` seconds after the start.
    #[must_use]
    pub fn finished(&self, t: f32) -> bool {
        self.repeat == Repeat::Once && t >= self.seconds
    }
}

/// Every parameter name of `spec`, for suggestions and documentation.
#[must_use]
pub fn names(spec: &SceneSpec) -> Vec<String> {
    let mut out: Vec<String> = [
        "camera.eye",
        "camera.at",
        "camera.up",
        "projection.kind",
        "projection.fovy",
        "projection.aspect",
        "projection.near",
        "projection.far",
        "projection.left",
        "projection.right",
        "projection.bottom",
        "projection.top",
        "render.samples",
        "render.cull",
        "render.depth_test",
        "render.perspective_correct",
        "render.per_sample_shading",
        "render.shading",
        "render.reflection",
        "render.filter",
        "render.mipmap",
        "render.wrap",
        "render.anisotropy",
        "render.lod_bias",
        "shadow.light",
    ]
    .map(str::to_owned)
    .to_vec();
    for o in &spec.scene.objects {
        let own: &[&str] = match o.builtin {
            Some(pipeline::mesh::BuiltinMesh::Bezier { .. }) => &BEZIER_PARAMS,
            Some(pipeline::mesh::BuiltinMesh::BezierPatch { .. }) => &PATCH_PARAMS,
            Some(pipeline::mesh::BuiltinMesh::Implicit(_)) => &IMPLICIT_PARAMS,
            Some(pipeline::mesh::BuiltinMesh::Signal(_)) => &SIGNAL_PARAMS,
            Some(pipeline::mesh::BuiltinMesh::Wheel(_)) => &WHEEL_PARAMS,
            _ => &[],
        };
        for p in OBJECT_PARAMS.iter().chain(own) {
            out.push(format!("objects.{}.{p}", o.name));
        }
    }
    for (k, light) in spec.scene.lights.iter().enumerate() {
        let key = spec.light_key(k);
        for p in ["position", "direction", "intensity"] {
            out.push(format!("lights.{key}.{p}"));
        }
        if matches!(light, pipeline::light::Light::Spot { .. }) {
            out.push(format!("lights.{key}.cutoff"));
            out.push(format!("lights.{key}.exponent"));
        }
    }
    let mut figures = spec.scene.figures.clone();
    for f in &mut figures {
        let name = f.name.clone();
        for (joint, _) in f.pose.joints_mut() {
            out.push(format!("figures.{name}.{joint}"));
        }
    }
    for u in spec.scene.own_uniforms() {
        out.push(format!("uniforms.{}", u.name));
    }
    out
}

/// The closest parameter name to `name`, if one is close.
#[must_use]
pub fn suggestion(spec: &SceneSpec, name: &str) -> Option<String> {
    let names = names(spec);
    pipeline::shader::suggest::nearest(name, names.iter().map(String::as_str)).map(str::to_owned)
}

fn number(v: &Value) -> Result<f32, String> {
    match v {
        Value::Number(x) if x.is_finite() => Ok(*x),
        other => Err(format!("expected a finite number, got {other}")),
    }
}

fn vec3(v: &Value) -> Result<Vec3, String> {
    match v {
        Value::Vec3(x) if x.is_finite() => Ok(*x),
        other => Err(format!(
            "expected three finite numbers [x, y, z], got {other}"
        )),
    }
}

/// A vector of `n` finite numbers (2, 3 or 4), as a uniform of the shader's own takes it.
fn vector(v: &Value, n: usize) -> Result<Vec<f32>, String> {
    let numbers = match v {
        Value::Vec2(x) if n == 2 => x.to_array().to_vec(),
        Value::Vec3(x) if n == 3 => x.to_array().to_vec(),
        Value::Vec4(x) if n == 4 => x.to_array().to_vec(),
        other => return Err(format!("expected {n} finite numbers, got {other}")),
    };
    if numbers.iter().all(|x| x.is_finite()) {
        Ok(numbers)
    } else {
        Err(format!("expected {n} finite numbers, got {v}"))
    }
}

fn boolean(v: &Value) -> Result<bool, String> {
    match v {
        Value::Bool(b) => Ok(*b),
        other => Err(format!("expected true or false, got {other}")),
    }
}

fn choice<T: Copy>(v: &Value, options: &[(&str, T)]) -> Result<T, String> {
    let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
    match v {
        Value::Name(n) => options
            .iter()
            .find(|(o, _)| o == n)
            .map(|(_, t)| *t)
            .ok_or_else(|| format!("expected one of {}, got \"{n}\"", names.join(", "))),
        other => Err(format!("expected one of {}, got {other}", names.join(", "))),
    }
}

/// `uniforms.NAME`: a uniform of the shaders' own, set inside its control's range (an `int`
/// rounded, so that an animation passes through whole numbers).
fn own_uniform(spec: &mut SceneSpec, name: &str, v: &Value) -> Result<(), Problem> {
    use pipeline::shader::own_uniform::OwnKind;
    let u = spec
        .scene
        .own_uniforms()
        .into_iter()
        .find(|u| u.name == name)
        .ok_or(Problem::Unknown)?;
    let value = match u.kind {
        OwnKind::Float => vec![number(v)?],
        OwnKind::Int => vec![number(v)?.round()],
        OwnKind::Bool => vec![f32::from(u8::from(boolean(v)?))],
        OwnKind::Vec2 | OwnKind::Vec3 | OwnKind::Vec4 => vector(v, u.kind.components())?,
    };
    let (lo, hi) = u.range;
    if value.iter().any(|x| !(lo..=hi).contains(x)) {
        return Err(format!(
            "{v} is outside its control's range {lo}..{hi} (the comment after its declaration)"
        )
        .into());
    }
    spec.scene.uniforms.insert(u.name, value);
    Ok(())
}

/// Sets parameter `name` of `spec` to `value`, then checks that the scene can still be drawn.
///
/// # Errors
/// An unknown name (with a suggestion), a value of the wrong kind, or a value that makes
/// the camera or the projection invalid; `spec` is then unchanged.
pub fn apply(spec: &mut SceneSpec, name: &str, value: &Value) -> Result<(), String> {
    let mut next = spec.clone();
    set(&mut next, name, value).map_err(|e| match e {
        Problem::Unknown => {
            let hint = suggestion(spec, name)
                .map(|s| {
                    pipeline::shader::suggest::hint(&s, pipeline::shader::suggest::Quote::Value)
                })
                .unwrap_or_default();
            format!("unknown parameter \"{name}\"{hint}")
        }
        Problem::Value(m) => format!("\"{name}\": {m}"),
    })?;
    let cam = &next.scene.camera;
    if let Err(e) = pipeline::transform::camera_frame(cam.eye, cam.at, cam.up) {
        return Err(format!(
            "\"{name}\" = {value} makes the camera degenerate: {e}"
        ));
    }
    let problems = next.scene.projection.problems();
    if let Some(p) = problems.first() {
        return Err(format!("\"{name}\" = {value}: {p}"));
    }
    *spec = next;
    Ok(())
}

enum Problem {
    Unknown,
    Value(String),
}

impl From<String> for Problem {
    fn from(m: String) -> Self {
        Self::Value(m)
    }
}

fn set(spec: &mut SceneSpec, name: &str, v: &Value) -> Result<(), Problem> {
    let parts: Vec<&str> = name.split('.').collect();
    match parts.as_slice() {
        ["camera", p] => {
            let cam = &mut spec.scene.camera;
            let slot = match *p {
                "eye" => &mut cam.eye,
                "at" => &mut cam.at,
                "up" => &mut cam.up,
                _ => return Err(Problem::Unknown),
            };
            *slot = vec3(v)?;
        }
        ["projection", "kind"] => {
            let kinds = ProjectionKind::ALL.map(|k| (k.key(), k));
            let kind = choice(v, &kinds)?;
            let camera = &spec.scene.camera;
            spec.scene.projection = spec.scene.projection.with_kind(
                kind,
                spec.settings.aspect(),
                camera.eye.distance(camera.at),
            );
        }
        ["projection", p] => projection(&mut spec.scene.projection, p, v)?,
        ["render", p] => render(spec, p, v)?,
        ["shadow", "light"] => match &mut spec.scene.shadow {
            Some(s) => s.light = vec3(v)?,
            None => return Err("the scene has no [scene.shadow]".to_owned().into()),
        },
        ["objects", object, p] => {
            let o = spec
                .scene
                .objects
                .iter_mut()
                .find(|o| o.name == *object)
                .ok_or(Problem::Unknown)?;
            object_param(o, p, v)?;
        }
        ["lights", k, p] => {
            let k = spec.light_index(k).ok_or(Problem::Unknown)?;
            let light = &mut spec.scene.lights[k];
            light_param(light, p, v)?;
        }
        ["figures", figure, joint] => {
            let f = spec
                .scene
                .figures
                .iter_mut()
                .find(|f| f.name == *figure)
                .ok_or(Problem::Unknown)?;
            let mut joints = f.pose.joints_mut();
            let slot = joints
                .iter_mut()
                .find(|(j, _)| j == joint)
                .ok_or(Problem::Unknown)?;
            *slot.1 = number(v)?;
        }
        ["uniforms", u] => own_uniform(spec, u, v)?,
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}

fn projection(p: &mut Projection, key: &str, v: &Value) -> Result<(), Problem> {
    let x = number(v)?;
    match (p, key) {
        (Projection::Perspective { fovy_deg, .. }, "fovy") => *fovy_deg = x,
        (Projection::Perspective { aspect, .. }, "aspect") => *aspect = Some(x),
        (
            Projection::Perspective { near, .. }
            | Projection::Frustum { near, .. }
            | Projection::Ortho { near, .. },
            "near",
        ) => *near = x,
        (
            Projection::Perspective { far, .. }
            | Projection::Frustum { far, .. }
            | Projection::Ortho { far, .. },
            "far",
        ) => *far = x,
        (Projection::Frustum { left, .. } | Projection::Ortho { left, .. }, "left") => *left = x,
        (Projection::Frustum { right, .. } | Projection::Ortho { right, .. }, "right") => {
            *right = x;
        }
        (Projection::Frustum { bottom, .. } | Projection::Ortho { bottom, .. }, "bottom") => {
            *bottom = x;
        }
        (Projection::Frustum { top, .. } | Projection::Ortho { top, .. }, "top") => *top = x,
        (_, "fovy" | "aspect" | "left" | "right" | "bottom" | "top") => {
            return Err(format!(
                "the scene's projection has no `{key}` (fovy and aspect belong to \"perspective\"; left, right, bottom, top to \"frustum\" and \"ortho\")"
            )
            .into());
        }
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}

fn render(spec: &mut SceneSpec, key: &str, v: &Value) -> Result<(), Problem> {
    let s = &mut spec.settings;
    match key {
        "samples" => {
            let n = number(v)?;
            s.samples = Samples::from_count(n as u32)
                .filter(|_| n.fract() == 0.0 && n >= 1.0)
                .ok_or_else(|| format!("expected 1, 4, 8 or 16 samples, got {n}"))?;
        }
        "cull" => s.cull = choice(v, CULL)?,
        "depth_test" => s.depth_test = choice(v, DEPTH_TEST)?,
        "perspective_correct" => s.perspective_correct = boolean(v)?,
        "per_sample_shading" => s.per_sample_shading = boolean(v)?,
        "shading" => s.shading = choice(v, SHADING)?,
        "reflection" => s.reflection = choice(v, REFLECTION)?,
        "filter" => s.sampler.filter = choice(v, FILTER)?,
        "mipmap" => s.sampler.mipmap = choice(v, MIPMAP)?,
        "wrap" => s.sampler.wrap = choice(v, WRAP)?,
        "anisotropy" => {
            let n = number(v)?;
            if !(1.0..=16.0).contains(&n) {
                return Err(format!("expected 1 (off) to 16, got {n}").into());
            }
            s.sampler.anisotropy = n.round() as u32;
        }
        "lod_bias" => s.sampler.lod_bias = number(v)?,
        "max_steps" => {
            let n = number(v)?;
            if n.fract() != 0.0 || !(1.0..=MAX_MAX_STEPS as f32).contains(&n) {
                return Err(format!(
                    "expected a whole number of loop iterations from 1 to {MAX_MAX_STEPS}, got {n}"
                )
                .into());
            }
            s.max_steps = n as u32;
        }
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}

fn light_param(light: &mut pipeline::light::Light, key: &str, v: &Value) -> Result<(), Problem> {
    use pipeline::light::Light;
    match (light, key) {
        (Light::Point { position, .. } | Light::Spot { position, .. }, "position") => {
            *position = vec3(v)?;
        }
        (Light::Directional { direction, .. } | Light::Spot { direction, .. }, "direction") => {
            *direction = vec3(v)?;
        }
        (
            Light::Ambient { intensity }
            | Light::Point { intensity, .. }
            | Light::Directional { intensity, .. }
            | Light::Spot { intensity, .. },
            "intensity",
        ) => {
            *intensity = match v {
                Value::Number(_) => Vec3::splat(number(v)?),
                _ => vec3(v)?,
            };
        }
        (Light::Spot { cutoff_deg, .. }, "cutoff") => {
            let c = number(v)?;
            if !(c > 0.0 && c <= 90.0) {
                return Err(format!(
                    "expected the cone's half-angle in degrees, 0 < cutoff ≤ 90, found {c}"
                )
                .into());
            }
            *cutoff_deg = c;
        }
        (Light::Spot { exponent, .. }, "exponent") => {
            let e = number(v)?;
            if !(e.is_finite() && e >= 0.0) {
                return Err(format!("expected a falloff exponent e ≥ 0, found {e}").into());
            }
            *exponent = e;
        }
        (_, "position" | "direction") => {
            return Err(format!("this kind of light has no `{key}`").into());
        }
        (_, "cutoff" | "exponent") => {
            return Err(format!("only a spot light has a `{key}`").into());
        }
        _ => return Err(Problem::Unknown),
    }
    Ok(())
}
