//! Lights and materials of the notes (Angel, chapter on lighting; GAMES101 lecture 7): ambient,
//! point, directional and spot lights, and the reflection coefficients `k_a`, `k_d`, `k_s` and
//! the shininess of the Phong and Blinn-Phong models (evaluated in `lighting`).

use glam::Vec3;
use serde::Serialize;

/// A light source of the notes (Angel, chapter on lighting): each colour component is an
/// intensity, usually in `[0, 1]` (GAMES101's `I` may be larger, with `I/r²` falloff).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Light {
    /// Ambient light `I_a`: the same at every point, from every direction.
    Ambient {
        /// Intensity per RGB component.
        intensity: Vec3,
    },
    /// A point light at `position` radiating equally in all directions, attenuated by
    /// `1/(a + b·d + c·d²)` at distance `d`.
    Point {
        /// World position.
        position: Vec3,
        /// Intensity per RGB component.
        intensity: Vec3,
        /// `(a, b, c)` of the attenuation `1/(a + b·d + c·d²)`; `(1, 0, 0)` is none,
        /// `(0, 0, 1)` is GAMES101's `I/r²`.
        attenuation: Vec3,
    },
    /// A distant light: parallel rays travelling along `direction`, no attenuation.
    Directional {
        /// Direction the light travels (from the light towards the scene).
        direction: Vec3,
        /// Intensity per RGB component.
        intensity: Vec3,
    },
    /// A spotlight: a point light limited to the cone of half-angle `cutoff_deg` around
    /// `direction`, its intensity falling off as `cos^e φ` with the angle `φ` from the axis.
    Spot {
        /// World position (apex of the cone).
        position: Vec3,
        /// Axis of the cone.
        direction: Vec3,
        /// Half-angle of the cone in degrees.
        cutoff_deg: f32,
        /// Falloff exponent `e`.
        exponent: f32,
        /// Intensity per RGB component.
        intensity: Vec3,
        /// `(a, b, c)` of the distance attenuation.
        attenuation: Vec3,
    },
}

/// A light drawn where it is: line segments in world coordinates, and the point its label goes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Gizmo {
    /// Segments `[a, b]`, world coordinates.
    pub segments: Vec<[Vec3; 2]>,
    /// Where to write the light's name.
    pub label_at: Vec3,
}

impl Light {
    /// The light's intensity per RGB component.
    #[must_use]
    pub fn intensity(&self) -> Vec3 {
        match *self {
            Self::Ambient { intensity }
            | Self::Point { intensity, .. }
            | Self::Directional { intensity, .. }
            | Self::Spot { intensity, .. } => intensity,
        }
    }

    /// How to draw the light in a picture of a scene centred at `centre` whose size is about
    /// `size`: a point light as a star of three crossed segments; a spotlight as its apex, its
    /// axis and its cone of half-angle `cutoff` (eight rays and the circle that ends them, a
    /// length `size` from the apex); a directional light as three parallel arrows along its
    /// direction, ending beside `centre`. An ambient light is everywhere, and a light switched
    /// off (intensity 0) sheds nothing: `None`.
    #[must_use]
    pub fn gizmo(&self, centre: Vec3, size: f32) -> Option<Gizmo> {
        if self.intensity() == Vec3::ZERO {
            return None;
        }
        let star = |p: Vec3, r: f32| {
            [
                Vec3::X,
                Vec3::Y,
                Vec3::Z,
                Vec3::new(1.0, 1.0, 0.0).normalize(),
            ]
            .map(|a| [p - a * r, p + a * r])
            .to_vec()
        };
        match *self {
            Self::Ambient { .. } => None,
            Self::Point { position, .. } => Some(Gizmo {
                segments: star(position, size * 0.06),
                label_at: position + Vec3::Y * size * 0.08,
            }),
            Self::Spot {
                position,
                direction,
                cutoff_deg,
                ..
            } => {
                let axis = direction.normalize_or_zero();
                let (u, v) = axis.any_orthonormal_pair();
                let reach = size * 0.7;
                let (s, c) = cutoff_deg.to_radians().sin_cos();
                let rim = |k: usize| {
                    let a = k as f32 * std::f32::consts::TAU / 16.0;
                    position + (axis * c + (u * a.cos() + v * a.sin()) * s) * reach
                };
                let mut segments = star(position, size * 0.04);
                segments.push([position, position + axis * reach * c]);
                segments.extend((0..16).step_by(2).map(|k| [position, rim(k)]));
                segments.extend((0..16).map(|k| [rim(k), rim(k + 1)]));
                Some(Gizmo {
                    segments,
                    label_at: position + Vec3::Y * size * 0.06,
                })
            }
            Self::Directional { direction, .. } => {
                let d = direction.normalize_or_zero();
                let (u, v) = d.any_orthonormal_pair();
                let (length, head) = (size * 0.5, size * 0.08);
                let mut segments = Vec::new();
                for offset in [Vec3::ZERO, u * size * 0.15, v * size * 0.15] {
                    let tip = centre - d * size * 0.55 + offset;
                    let tail = tip - d * length;
                    segments.push([tail, tip]);
                    segments.push([tip, tip - d * head + u * head * 0.5]);
                    segments.push([tip, tip - d * head - u * head * 0.5]);
                }
                Some(Gizmo {
                    label_at: centre - d * (size * 1.1),
                    segments,
                })
            }
        }
    }
}

/// A material's reflection coefficients for the Phong and Blinn-Phong models:
/// `I = k_a·I_a + 1/(a + b·d + c·d²)·(k_d·I_d·max(l·n, 0) + k_s·I_s·max(r·v, 0)^α)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Material {
    /// Ambient reflection `k_a` per RGB component.
    pub ka: Vec3,
    /// Diffuse reflection `k_d` per RGB component.
    pub kd: Vec3,
    /// Specular reflection `k_s` per RGB component.
    pub ks: Vec3,
    /// Shininess: `α` for Phong's `(r·v)^α`, `β` for Blinn-Phong's `(n·h)^β`.
    pub shininess: f32,
}

impl Default for Material {
    /// A plain grey plastic: `k_a = 0.1`, `k_d = 0.7`, `k_s = 0.5`, shininess 32.
    fn default() -> Self {
        Self {
            ka: Vec3::splat(0.1),
            kd: Vec3::splat(0.7),
            ks: Vec3::splat(0.5),
            shininess: 32.0,
        }
    }
}
