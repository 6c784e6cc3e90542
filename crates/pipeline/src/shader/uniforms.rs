//! The values of the uniforms pipelens sets for one object's draw (their names and types are
//! the engine's [`pipelens_glsl::interface`]).

use glam::{Mat3, Mat4, Vec2, Vec3};

use crate::light::{Light, Material};
use pipelens_glsl::interface::{LIGHT_COMPONENTS, MAX_LIGHTS, uniform};

/// The values of the uniforms for one object's draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Uniforms {
    /// M.
    pub model: Mat4,
    /// V.
    pub view: Mat4,
    /// P.
    pub projection: Mat4,
    /// The eye in world coordinates.
    pub eye: Vec3,
    /// LookAt's `at` and `up`.
    pub at_up: [Vec3; 2],
    /// The scene's lights.
    pub lights: Vec<Light>,
    /// The object's material.
    pub material: Material,
    /// Whether the object has a texture.
    pub has_texture: bool,
    /// `detail_kind`: 0 none, 1 bump, 2 normal map.
    pub detail_kind: i32,
    /// `bump_strength`, `k_h·k_n`.
    pub bump_strength: f32,
    /// `displacement_scale`, k of `p' = p + k·h(u, v)·n` (0 without a displacement map).
    pub displacement_scale: f32,
    /// `reflectivity`, k of environment mapping (0 without an environment).
    pub reflectivity: f32,
    /// Seconds into the step's animation.
    pub time: f32,
    /// The viewport's size in pixels.
    pub resolution: Vec2,
    /// The view volume as `Perspective` names it: `[fovy (degrees), aspect, near, far]`.
    pub lens: [f32; 4],
    /// The object's rotation angles in degrees about x, y and z.
    pub rotation: Vec3,
    /// The object's rotation about an axis: the axis as given and θ in degrees.
    pub axis_angle: (Vec3, f32),
    /// The object's scale factors.
    pub scale: Vec3,
    /// The student's own uniforms, each as the machine's words.
    pub own: Vec<(String, Vec<u32>)>,
}

impl Default for Uniforms {
    fn default() -> Self {
        Self {
            model: Mat4::IDENTITY,
            view: Mat4::IDENTITY,
            projection: Mat4::IDENTITY,
            eye: Vec3::ZERO,
            at_up: [Vec3::NEG_Z, Vec3::Y],
            lights: Vec::new(),
            material: Material::default(),
            has_texture: false,
            detail_kind: 0,
            bump_strength: 0.0,
            displacement_scale: 0.0,
            reflectivity: 0.0,
            time: 0.0,
            resolution: Vec2::ONE,
            lens: [90.0, 1.0, 1.0, 10.0],
            rotation: Vec3::ZERO,
            axis_angle: (Vec3::ZERO, 0.0),
            scale: Vec3::ONE,
            own: Vec::new(),
        }
    }
}

fn floats(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

impl pipelens_glsl::UniformValues for Uniforms {
    fn components(&self, name: &str) -> Option<Vec<u32>> {
        Uniforms::components(self, name)
    }
}

impl Uniforms {
    /// The value of the uniform called `name`, as 32-bit components in GLSL's order (matrices
    /// column by column; a `Light` as its members in order). `None`: pipelens sets no such
    /// uniform.
    #[must_use]
    pub fn components(&self, name: &str) -> Option<Vec<u32>> {
        if let Some((_, words)) = self.own.iter().find(|(n, _)| n == name) {
            return Some(words.clone());
        }
        let spec = uniform(name)?;
        let m = &self.material;
        let first = self.lights.iter().find_map(|l| match *l {
            Light::Point {
                position,
                intensity,
                ..
            }
            | Light::Spot {
                position,
                intensity,
                ..
            } => Some((position, intensity)),
            _ => None,
        });
        let (light_pos, light_color) = first.unwrap_or((Vec3::ZERO, Vec3::ZERO));
        let ambient: Vec3 = self
            .lights
            .iter()
            .filter_map(|l| match *l {
                Light::Ambient { intensity } => Some(intensity),
                _ => None,
            })
            .sum();
        Some(match spec.names[0] {
            "model" => floats(&self.model.to_cols_array()),
            "view" => floats(&self.view.to_cols_array()),
            "projection" => floats(&self.projection.to_cols_array()),
            "mvp" => floats(&(self.projection * self.view * self.model).to_cols_array()),
            "model_view" => floats(&(self.view * self.model).to_cols_array()),
            "normal_matrix" => floats(
                &Mat3::from_mat4(self.model)
                    .inverse()
                    .transpose()
                    .to_cols_array(),
            ),
            "eye" => floats(&self.eye.to_array()),
            "light_pos" => floats(&light_pos.to_array()),
            "light_color" => floats(&light_color.to_array()),
            "ambient_light" => floats(&ambient.to_array()),
            "lights" => self.light_components(),
            "light_count" => vec![self.lights.len().min(MAX_LIGHTS) as u32],
            "ka" => floats(&m.ka.to_array()),
            "kd" => floats(&m.kd.to_array()),
            "ks" => floats(&m.ks.to_array()),
            "shininess" => floats(&[m.shininess]),
            "use_tex" => vec![u32::from(self.has_texture)],
            "detail_kind" => vec![self.detail_kind as u32],
            "bump_strength" => floats(&[self.bump_strength]),
            "displacement_scale" => floats(&[self.displacement_scale]),
            "reflectivity" => floats(&[self.reflectivity]),
            "fovy" => floats(&self.lens[0..1]),
            "aspect" => floats(&self.lens[1..2]),
            "near" => floats(&self.lens[2..3]),
            "far" => floats(&self.lens[3..4]),
            "rotation" => floats(&self.rotation.to_array()),
            "axis" => floats(&self.axis_angle.0.to_array()),
            "angle" => floats(&[self.axis_angle.1]),
            "scale" => floats(&self.scale.to_array()),
            "resolution" => floats(&self.resolution.to_array()),
            "at" => floats(&self.at_up[0].to_array()),
            "up" => floats(&self.at_up[1].to_array()),
            "time" => floats(&[self.time]),
            // A row of the table with no value here: no value rather than another's (a test
            // asks every row for one).
            _ => return None,
        })
    }

    /// `lights` as [`MAX_LIGHTS`] records of `Light`: `kind` (0 ambient, 1 point, 2
    /// directional, 3 spot), `position`, `direction`, `intensity`, `attenuation` (a, b, c of
    /// `1/(a + b·d + c·d²)`), `cutoff_cos`, `exponent`; unset records are zero.
    fn light_components(&self) -> Vec<u32> {
        let mut out = Vec::with_capacity(MAX_LIGHTS * LIGHT_COMPONENTS);
        for k in 0..MAX_LIGHTS {
            let (kind, p, d, i, a, cut, e) = match self.lights.get(k) {
                Some(Light::Ambient { intensity }) => {
                    (0, Vec3::ZERO, Vec3::ZERO, *intensity, Vec3::X, -1.0, 0.0)
                }
                Some(Light::Point {
                    position,
                    intensity,
                    attenuation,
                }) => (
                    1,
                    *position,
                    Vec3::ZERO,
                    *intensity,
                    *attenuation,
                    -1.0,
                    0.0,
                ),
                Some(Light::Directional {
                    direction,
                    intensity,
                }) => (2, Vec3::ZERO, *direction, *intensity, Vec3::X, -1.0, 0.0),
                Some(Light::Spot {
                    position,
                    direction,
                    cutoff_deg,
                    exponent,
                    intensity,
                    attenuation,
                }) => (
                    3,
                    *position,
                    *direction,
                    *intensity,
                    *attenuation,
                    cutoff_deg.to_radians().cos(),
                    *exponent,
                ),
                None => (0, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, 0.0, 0.0),
            };
            out.push(kind as u32);
            for v in [p, d, i, a] {
                out.extend(floats(&v.to_array()));
            }
            out.extend(floats(&[cut, e]));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use pipelens_glsl::interface::UNIFORMS;

    /// Every uniform of the engine's table, by each of its names, has a value here, of as many
    /// components as its GLSL type holds (counted from the type's name, not from the values).
    #[test]
    fn every_uniform_the_shader_can_declare_has_a_value_of_its_type() {
        let u = Uniforms {
            time: 2.5,
            ..Uniforms::default()
        };
        for spec in &UNIFORMS {
            let want = match spec.glsl {
                "mat4" => 16,
                "mat3" => 9,
                "vec3" => 3,
                "vec2" => 2,
                "float" | "int" | "bool" => 1,
                "Light[MAX_LIGHTS]" => MAX_LIGHTS * LIGHT_COMPONENTS,
                other => panic!("a type this test does not count: {other}"),
            };
            for name in spec.names {
                let got = u
                    .components(name)
                    .unwrap_or_else(|| panic!("no value for `{name}`"));
                assert_eq!(got.len(), want, "`{name}` ({})", spec.glsl);
            }
        }
        assert_eq!(u.components("time"), Some(vec![2.5f32.to_bits()]));
        assert_eq!(u.components("no_such_uniform"), None);
    }
}
