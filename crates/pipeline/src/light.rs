//! Lights and materials of the notes (Angel, chapter on lighting; GAMES101 lecture 7): ambient,
//! point, directional and spot lights, and the reflection coefficients `k_a`, `k_d`, `k_s` and
//! the shininess of the Phong and Blinn-Phong models (evaluated in `shade`).

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
