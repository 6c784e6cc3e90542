//! The file as written: serde structures that mirror the TOML one to one, with the position of
//! every value kept (`Spanned`) so that validation can point at it. Unknown keys are rejected
//! here (`deny_unknown_fields`); ranges and meanings are checked in `validate`.

// The fields are the keys of the file, documented one by one in lessons/README.md.
#![allow(missing_docs)]

use std::collections::BTreeMap;

use pipeline::shader::HookKind;
use serde::Deserialize;
use toml::Spanned;

/// A scene file: one `[scene]` table. Lessons add their own tables beside it.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSceneFile {
    /// The scene.
    pub scene: Spanned<RawScene>,
}

/// `[scene]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    /// `[scene.camera]`.
    pub camera: Option<Spanned<RawCamera>>,
    /// `[scene.projection]`.
    pub projection: Option<Spanned<RawProjection>>,
    /// `[scene.render]`.
    pub render: Option<Spanned<RawRender>>,
    /// `[[scene.objects]]`.
    #[serde(default)]
    pub objects: Vec<Spanned<RawObject>>,
    /// `[[scene.lights]]`.
    #[serde(default)]
    pub lights: Vec<Spanned<RawLight>>,
    /// `[scene.shadow]`.
    pub shadow: Option<Spanned<RawShadow>>,
    /// `[[scene.figures]]`.
    #[serde(default)]
    pub figures: Vec<Spanned<RawFigure>>,
    /// `shader = { vertex = "x.vert", fragment = "x.frag" }`: every object's shaders.
    pub shader: Option<Spanned<RawShader>>,
}

/// `shader = { vertex = …, fragment = … }`: a file beside the lesson (`"toon.frag"`) or the
/// GLSL itself, for each stage; a stage left out is pipelens' own.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawShader {
    pub vertex: Option<Spanned<String>>,
    pub fragment: Option<Spanned<String>>,
    /// `bool inside(vec2 p, vec2 a, vec2 b, vec2 c)`, which the rasterizer calls per sample.
    pub inside: Option<Spanned<String>>,
    /// `bool depth_test(float z, float stored)`, which it calls per covered sample.
    pub depth_test: Option<Spanned<String>>,
    /// `vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t)`, a Bézier curve's point.
    pub de_casteljau: Option<Spanned<String>>,
    /// `mat4 shadow_matrix(vec3 light)`, the planar shadow's projection onto `y = 0`.
    pub shadow_matrix: Option<Spanned<String>>,
    /// `vec3 bezier_patch(vec3 p[16], float u, float v)`, a Bézier patch's surface point.
    pub bezier_patch: Option<Spanned<String>>,
    /// `uniforms = { bands = 4, tint = [1, 0.5, 0] }`: the values of the shaders' own
    /// uniforms (`pipeline::shader::own_uniform`).
    pub uniforms: Option<BTreeMap<Spanned<String>, Spanned<RawUniformValue>>>,
}

/// A value a lesson gives a uniform of the shader's own: a number, true or false, or two,
/// three or four numbers.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum RawUniformValue {
    /// `true` or `false`.
    Bool(bool),
    /// A number.
    Number(f64),
    /// Two numbers.
    Pair([f64; 2]),
    /// Three numbers.
    Triple([f64; 3]),
    /// Four numbers.
    Quad([f64; 4]),
}

impl RawShader {
    /// The student's function of kind `kind`, under its key (`inside`, `depth_test`,
    /// `de_casteljau`, `shadow_matrix`, `bezier_patch`: [`HookKind::key`]).
    #[must_use]
    pub fn hook(&self, kind: HookKind) -> Option<&Spanned<String>> {
        match kind {
            HookKind::Inside => self.inside.as_ref(),
            HookKind::DepthTest => self.depth_test.as_ref(),
            HookKind::Curve => self.de_casteljau.as_ref(),
            HookKind::ShadowMatrix => self.shadow_matrix.as_ref(),
            HookKind::Patch => self.bezier_patch.as_ref(),
        }
    }
}

/// One `[[scene.figures]]` entry: an articulated model and its joint angles in degrees.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFigure {
    pub kind: Spanned<String>,
    pub name: Option<String>,
    /// The name shown in each language.
    pub label: Option<Spanned<RawText>>,
    pub translate: Option<RawVec3>,
    pub base: Option<Spanned<f64>>,
    pub lower: Option<Spanned<f64>>,
    pub upper: Option<Spanned<f64>>,
    pub torso: Option<Spanned<f64>>,
    pub head: Option<Spanned<f64>>,
    pub left_upper_arm: Option<Spanned<f64>>,
    pub left_lower_arm: Option<Spanned<f64>>,
    pub right_upper_arm: Option<Spanned<f64>>,
    pub right_lower_arm: Option<Spanned<f64>>,
    pub left_upper_leg: Option<Spanned<f64>>,
    pub left_lower_leg: Option<Spanned<f64>>,
    pub right_upper_leg: Option<Spanned<f64>>,
    pub right_lower_leg: Option<Spanned<f64>>,
}

/// `[scene.shadow]`: a planar projected shadow.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawShadow {
    pub light: RawVec3,
    pub plane_y: Option<Spanned<f64>>,
    pub color: Option<RawVec3>,
}

/// One `[[scene.lights]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLight {
    /// The name parameters address it by (`lights.key.position`); else its index.
    pub name: Option<Spanned<String>>,
    pub kind: Spanned<String>,
    pub intensity: Option<Spanned<RawScale>>,
    pub position: Option<RawVec3>,
    pub direction: Option<RawVec3>,
    pub attenuation: Option<RawVec3>,
    pub cutoff: Option<Spanned<f64>>,
    pub exponent: Option<Spanned<f64>>,
}

/// `material = { ka = …, kd = …, ks = …, shininess = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMaterial {
    pub ka: Option<Spanned<RawScale>>,
    pub kd: Option<Spanned<RawScale>>,
    pub ks: Option<Spanned<RawScale>>,
    pub shininess: Option<Spanned<f64>>,
}

/// A 3-vector as written: `[x, y, z]`.
pub type RawVec3 = Spanned<[f64; 3]>;

/// `[scene.camera]`: `LookAt(eye, at, up)`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCamera {
    pub eye: Option<RawVec3>,
    pub at: Option<RawVec3>,
    pub up: Option<RawVec3>,
}

/// `[scene.projection]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawProjection {
    pub kind: Option<Spanned<String>>,
    pub fovy: Option<Spanned<f64>>,
    pub aspect: Option<Spanned<f64>>,
    pub near: Option<Spanned<f64>>,
    pub far: Option<Spanned<f64>>,
    pub left: Option<Spanned<f64>>,
    pub right: Option<Spanned<f64>>,
    pub bottom: Option<Spanned<f64>>,
    pub top: Option<Spanned<f64>>,
}

/// `[scene.render]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRender {
    pub width: Option<Spanned<i64>>,
    pub height: Option<Spanned<i64>>,
    pub samples: Option<Spanned<i64>>,
    pub cull: Option<Spanned<String>>,
    pub depth_test: Option<Spanned<String>>,
    pub perspective_correct: Option<bool>,
    pub shading: Option<Spanned<String>>,
    pub reflection: Option<Spanned<String>>,
    pub filter: Option<Spanned<String>>,
    pub mipmap: Option<Spanned<String>>,
    pub wrap: Option<Spanned<String>>,
    pub anisotropy: Option<Spanned<i64>>,
    pub lod_bias: Option<Spanned<f64>>,
    pub per_sample_shading: Option<bool>,
    pub background: Option<RawVec3>,
    /// The loop iterations a shader invocation may run (an endless loop stops there).
    pub max_steps: Option<Spanned<i64>>,
}

/// One `[[scene.objects]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawObject {
    pub name: Option<Spanned<String>>,
    /// The name shown in each language, `{ en = "floor", zh = "地面" }`.
    pub label: Option<Spanned<RawText>>,
    /// A built-in name (`"cube"`), an OBJ path (`"models/bunny.obj"`), or a table
    /// `{ builtin = "uv_sphere", segments = 64, rings = 32 }` / `{ obj = "path.obj" }`.
    pub mesh: Spanned<RawMesh>,
    pub translate: Option<RawVec3>,
    pub rotate: Option<RawVec3>,
    /// `{ axis = [x, y, z], angle = degrees }`: a rotation about an arbitrary axis.
    pub rotate_axis: Option<Spanned<RawAxisRotation>>,
    /// `{ axis = [x, y, z], angle = θ, t = 0.5 }`: with `rotate_axis`, the orientation part way
    /// (`t`) from that rotation to this one, by slerp.
    pub slerp_to: Option<Spanned<RawSlerpTo>>,
    /// `[sx, sy, sz]` or one number for a uniform scale.
    pub scale: Option<Spanned<RawScale>>,
    /// `"vertex"`, `"normal"` or `[r, g, b]`.
    pub color: Option<Spanned<RawColor>>,
    pub material: Option<Spanned<RawMaterial>>,
    /// `"checkerboard"`, `"checkerboard_wide"` (512 × 128), `"uv_grid"`, `"mip_levels"` or a path to a PNG or JPEG file.
    pub texture: Option<Spanned<String>>,
    pub casts_shadow: Option<bool>,
    /// Centre the mesh's bounding box at the origin and scale it into the unit sphere.
    pub fit: Option<bool>,
    /// `"average"` or `"area_weighted"`: compute the vertex normals from the faces.
    pub normals: Option<Spanned<String>>,
    /// `{ texture = "bumps" | path, strength = … }`.
    pub bump: Option<Spanned<RawBump>>,
    /// A tangent-space normal map: a PNG/JPEG path.
    pub normal_map: Option<Spanned<String>>,
    /// `{ texture = "bumps" | path, scale = … }`.
    pub displacement: Option<Spanned<RawDisplacement>>,
    /// `{ cube = "room", reflectivity = … }`.
    pub environment: Option<Spanned<RawEnvironment>>,
    /// This object's shaders (see [`RawShader`]), in place of the scene's.
    pub shader: Option<Spanned<RawShader>>,
}

/// `rotate_axis = { axis = [x, y, z], angle = θ }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAxisRotation {
    pub axis: RawVec3,
    pub angle: Spanned<f64>,
}

/// `slerp_to = { axis = [x, y, z], angle = θ, t = 0.5 }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSlerpTo {
    pub axis: RawVec3,
    pub angle: Spanned<f64>,
    pub t: Option<Spanned<f64>>,
}

/// `environment = { cube = "room", reflectivity = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEnvironment {
    pub cube: Spanned<String>,
    pub reflectivity: Option<Spanned<f64>>,
}

/// `displacement = { texture = …, scale = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDisplacement {
    pub texture: Spanned<String>,
    pub scale: Option<Spanned<f64>>,
}

/// `bump = { texture = …, strength = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBump {
    pub texture: Spanned<String>,
    pub strength: Option<Spanned<f64>>,
}

/// A mesh as written.
#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "a built-in mesh name, a path to an .obj file, or a table such as \
    { builtin = \"uv_sphere\", segments = 32, rings = 16 }"
)]
pub enum RawMesh {
    Name(String),
    Table(Box<RawMeshTable>),
}

/// `{ builtin = …, … }` or `{ obj = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMeshTable {
    pub builtin: Option<String>,
    pub obj: Option<String>,
    pub segments: Option<i64>,
    pub rings: Option<i64>,
    pub divisions: Option<i64>,
    pub sides: Option<i64>,
    pub minor: Option<f64>,
    pub repeat: Option<f64>,
    /// A Bézier curve's four control points `[[x, y], …]`.
    pub points: Option<Vec<[f64; 2]>>,
    /// A Bézier curve's parameter, 0…1.
    pub t: Option<f64>,
    /// How many levels of a Bézier curve's (0…3) or patch's (0…2) construction are drawn.
    pub levels: Option<i64>,
    /// A Bézier patch's control point heights, four rows of four.
    pub heights: Option<Vec<[f64; 4]>>,
    /// A Bézier patch's parameters, 0…1.
    pub u: Option<f64>,
    /// See `u`.
    pub v: Option<f64>,
    /// An implicit surface's shape: sphere, torus, blend, union, intersection, difference.
    pub shape: Option<String>,
    /// The distance between an implicit surface's two primitives.
    pub gap: Option<f64>,
    /// An implicit blend's smoothing distance.
    pub smooth: Option<f64>,
    /// An implicit surface's grid cells per axis.
    pub resolution: Option<i64>,
    /// An implicit surface drawn as a cloud of this many points (0: polygonized).
    pub cloud: Option<i64>,
    /// A signal's frequency, cycles per unit time.
    pub frequency: Option<f64>,
    /// A signal's sampling rate, samples per unit time.
    pub rate: Option<f64>,
    /// The box filter's width before sampling, in sample spacings.
    pub blur: Option<f64>,
    /// A wheel's spokes.
    pub spokes: Option<i64>,
    /// A wheel's rotation per frame, degrees.
    pub step: Option<f64>,
    /// How many frames of a wheel are drawn.
    pub frames: Option<i64>,
}

/// One number for all three components, or three, as written (scales, intensities, coefficients).
#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "one number, or an array of three numbers such as [1.0, 0.5, 0.25]"
)]
pub enum RawScale {
    Uniform(f64),
    Axes([f64; 3]),
}

/// A colour as written.
#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "\"vertex\", \"normal\" or an array of three numbers [r, g, b] in 0…1"
)]
pub enum RawColor {
    Named(String),
    Rgb([f64; 3]),
}

/// A lesson file: `[lesson]`, `[scene]` and `[[steps]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLessonFile {
    pub lesson: Spanned<RawMeta>,
    pub scene: Spanned<RawScene>,
    #[serde(default)]
    pub steps: Vec<Spanned<RawStep>>,
    /// `[comments.zh]`: the Chinese of the comments of the lesson's GLSL, by their English.
    #[serde(default)]
    pub comments: RawComments,
}

/// `[comments]`: a lesson's GLSL comments in another language, `zh = { "English" = "中文" }`.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawComments {
    #[serde(default)]
    pub zh: std::collections::BTreeMap<String, String>,
}

/// `[lesson]`: what the lesson is called and what it needs first.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMeta {
    pub id: Spanned<String>,
    pub title: Spanned<RawText>,
    pub summary: Spanned<RawText>,
    #[serde(default)]
    pub prerequisites: Vec<Spanned<String>>,
}

/// Text in English and Chinese, and in any other language by its BCP 47 tag:
/// `{ en = "…", zh = "…", fr = "…" }`. (Its other keys are its languages, so it cannot deny
/// unknown fields; `validate` checks that each is a well-formed tag.)
#[derive(Debug, Deserialize)]
#[serde(expecting = "a text in both languages, { en = \"…\", zh = \"…\" }")]
pub struct RawText {
    pub en: String,
    pub zh: String,
    #[serde(flatten)]
    pub others: std::collections::BTreeMap<String, String>,
}

impl RawText {
    /// The words, trimmed, each language's that is not empty (its tag unchecked: `validate`
    /// checks the tags).
    pub fn text(&self) -> crate::vocabulary::Text {
        let mut text = crate::vocabulary::Text::new(self.en.trim(), self.zh.trim());
        for (tag, words) in &self.others {
            if !words.trim().is_empty() {
                text.others.insert(tag.clone(), words.trim().to_owned());
            }
        }
        text
    }
}

/// One `[[steps]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawStep {
    pub title: Spanned<RawText>,
    pub narration: Spanned<RawText>,
    pub stage: Option<Spanned<String>>,
    pub layout: Option<Spanned<String>>,
    pub compare: Option<Spanned<String>>,
    pub buffer: Option<Spanned<String>>,
    pub overlays: Option<Vec<Spanned<String>>>,
    #[serde(default)]
    pub set: std::collections::BTreeMap<Spanned<String>, Spanned<RawValue>>,
    #[serde(default)]
    pub animate: Vec<Spanned<RawAnimate>>,
    pub pixel: Option<Spanned<[i64; 2]>>,
    pub vertex: Option<Spanned<i64>>,
    pub profile: Option<Spanned<[f64; 4]>>,
    /// The objects or figures the geometry views frame.
    pub focus: Option<Vec<Spanned<String>>>,
    /// The observer's direction `[yaw, pitch]` in degrees: round the vertical axis from +z
    /// toward +x, and above the horizon.
    pub orbit: Option<Spanned<[f64; 2]>>,
    /// The depth buffer's grey ramp: black at the first window depth, white at the second.
    pub depth_range: Option<Spanned<[f64; 2]>>,
    /// The debugger's variable picture: a fragment-shader expression after a line,
    /// `"EXPR@LINE"`.
    pub watch: Option<Spanned<String>>,
    /// The fragment shader's lines the step is about, `[first, last]` (or `[line]`): the
    /// shader panel opens on them, scrolled to and marked.
    pub shader_lines: Option<Spanned<Vec<i64>>>,
    /// The panels the step opens on entering it: `"inspector"`, `"shader"`.
    pub panels: Option<Vec<Spanned<String>>>,
    /// `shader = { vertex = …, fragment = … }`: every object's shaders from this step on.
    pub shader: Option<Spanned<RawShader>>,
    pub question: Option<Spanned<RawText>>,
    /// The value the question asks for, typed by the student: a number, `[x, y, z]`, or a
    /// matrix's rows `[[…], […]]`.
    pub expect: Option<Spanned<RawExpect>>,
    /// How far a typed entry may be from `expect` and still be right.
    pub tolerance: Option<Spanned<f64>>,
    /// What each entry of `expect` is, where they are not a vector's x, y, z, w:
    /// `expect_names = ["top", "right"]`.
    pub expect_names: Option<Spanned<Vec<String>>>,
    pub answer: Option<Spanned<RawText>>,
    /// The student writes code: `{ task, starter = { vertex, fragment }, tolerance }`.
    pub exercise: Option<Spanned<RawExercise>>,
}

/// `exercise = { task = { en, zh }, starter = { fragment = "…" }, tolerance = 1 }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawExercise {
    pub task: Spanned<RawText>,
    pub starter: Spanned<RawShader>,
    /// Colour steps (of 255) a pixel may differ from pipelens' own and still match.
    pub tolerance: Option<Spanned<f64>>,
    /// Uniforms the student may not declare and functions they may not call: what the lab
    /// asks them to compute (`forbid = ["view"]`, `forbid = ["texture"]`).
    pub forbid: Option<Spanned<Vec<String>>>,
    /// `compare = { yours = "level_of_detail()", pipelens = "lod" }`: the value of the student's
    /// run that stands for pipelens' quantity at the first wrong pixel.
    pub compare: Option<Spanned<RawCompare>>,
}

/// `compare = { yours = "…", pipelens = "uv" | "lod" | "texel" }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCompare {
    pub yours: String,
    pub pipelens: String,
}

/// `expect = …` as written.
#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "`expect` takes a number (expect = 0.64), a vector (expect = [0.6, 0.8, 0]) or a matrix's rows \
    (expect = [[1, 0], [0, 1]])"
)]
pub enum RawExpect {
    Number(f64),
    Vector(Vec<f64>),
    Matrix(Vec<Vec<f64>>),
}

/// `{ param = "…", from = …, to = …, seconds = …, easing = "…", repeat = "…" }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAnimate {
    pub param: Spanned<String>,
    pub from: Spanned<RawValue>,
    pub to: Spanned<RawValue>,
    pub seconds: Spanned<f64>,
    pub easing: Option<Spanned<String>>,
    pub repeat: Option<Spanned<String>>,
}

/// A parameter value as written.
#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "a number, [x, y, z], true or false, or a name such as \"phong\" (write the \
    parameter's name in quotes: \"projection.fovy\" = 60); a vec2 or vec4 uniform of the \
    shader's own takes [x, y] or [x, y, z, w]"
)]
pub enum RawValue {
    Bool(bool),
    Number(f64),
    Vec2([f64; 2]),
    Vec3([f64; 3]),
    Vec4([f64; 4]),
    Name(String),
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each function's key in a lesson's `shader = { … }` is the kind's key in the core's table,
    /// and gives that kind only.
    #[test]
    fn each_function_key_is_its_kinds() {
        for kind in HookKind::ALL {
            let text = format!("{} = \"void f() {{}}\"", kind.key());
            let raw: RawShader = toml::from_str(&text).expect("a shader table");
            for other in HookKind::ALL {
                assert_eq!(
                    raw.hook(other).is_some(),
                    other == kind,
                    "{text}: {other:?}"
                );
            }
        }
    }
}
