//! Shading: the Phong and Blinn-Phong reflection models, light by light, each term kept.
//!
//! For one point `p` with unit normal `n`, unit view vector `v` (towards the eye) and surface
//! colour `c`, each light contributes (the notes' formula, Angel ch. 5 / GAMES101 lecture 7):
//!
//! ```text
//! I = k_a·I_a + f_att·f_spot·( k_d·I_d·max(l·n, 0) + k_s·I_s·max(r·v, 0)^α )      (Phong)
//!                                                   k_s·I_s·max(n·h, 0)^β         (Blinn-Phong)
//! ```
//!
//! - `l` is the unit vector towards the light, `r = 2(l·n)n − l` its mirror direction,
//!   `h = (l + v)/|l + v|` the half vector;
//! - `f_att = 1/(a + b·d + c·d²)` at distance `d` for point and spot lights (`(0, 0, 1)` gives
//!   GAMES101's `I/r²`), 1 for distant lights;
//! - `f_spot = (cos φ)^e` inside a spotlight's cone of half-angle `θ` (φ is the angle between the
//!   spot's axis and `−l`), 0 outside (`cos φ < cos θ`);
//! - `k_a` and `k_d` are the material's coefficients multiplied by the surface colour `c` (a red
//!   surface reflects red light); `k_s` is not (highlights take the light's colour);
//! - the specular term is 0 where `l·n ≤ 0` (a light behind the surface makes no highlight).
//!
//! Where it is evaluated is the shading frequency: once per face (flat), per vertex with the
//! colours interpolated (Gouraud), or per pixel with the normals interpolated (Phong).

use glam::Vec3;
use serde::Serialize;

use crate::light::{Light, Material};

pub mod lanes;
/// `x^y` eight lanes at a time, the same for the specular term and the student's `pow`: the GLSL
/// engine's, so that a shader and the built-in path agree bit for bit.
pub use pipelens_glsl::power;

/// Which specular term.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Reflection {
    /// Phong: `(r·v)^α` with the mirror vector `r = 2(l·n)n − l`.
    Phong,
    /// Blinn-Phong: `(n·h)^β` with the half vector `h = (l + v)/|l + v|`.
    #[default]
    BlinnPhong,
}

/// Where lighting is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Frequency {
    /// No lighting: the surface colour as it is.
    #[default]
    Unlit,
    /// Once per face, with the face normal, at the face's provoking (last) vertex, as OpenGL's
    /// `flat` takes the last vertex's values.
    Flat,
    /// Once per vertex, with the vertex normal; the colours are interpolated.
    Gouraud,
    /// Once per pixel, with the interpolated (renormalised) normal.
    Phong,
}

/// Everything the lighting of one point produced, term by term.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ShadeTerms {
    /// `Σ k_a·I_a`.
    pub ambient: Vec3,
    /// `Σ f_att·f_spot·k_d·I_d·max(l·n, 0)`.
    pub diffuse: Vec3,
    /// `Σ f_att·f_spot·k_s·I_s·max(r·v, 0)^α` (or `max(n·h, 0)^β`).
    pub specular: Vec3,
    /// The environment seen in the mirror direction (environment mapping), zero otherwise.
    pub reflected: Vec3,
    /// The unit normal used.
    pub normal: Vec3,
    /// `l` of the key light (the first light that is not ambient); zero if there is none.
    pub light: Vec3,
    /// `h` of the key light.
    pub half: Vec3,
    /// `n·l` for the key light.
    pub n_dot_l: f32,
    /// `n·h` for the key light (Blinn-Phong) or `r·v` (Phong).
    pub n_dot_h: f32,
}

impl ShadeTerms {
    /// `ambient + diffuse + specular + reflected`.
    #[must_use]
    pub fn color(&self) -> Vec3 {
        self.ambient + self.diffuse + self.specular + self.reflected
    }

    /// The weighted sum of terms (for interpolating Gouraud colours, whose terms are linear).
    #[must_use]
    pub fn blend(t: [&ShadeTerms; 3], w: Vec3) -> ShadeTerms {
        let mix = |f: fn(&ShadeTerms) -> Vec3| f(t[0]) * w.x + f(t[1]) * w.y + f(t[2]) * w.z;
        let mixs = |f: fn(&ShadeTerms) -> f32| f(t[0]) * w.x + f(t[1]) * w.y + f(t[2]) * w.z;
        ShadeTerms {
            ambient: mix(|s| s.ambient),
            diffuse: mix(|s| s.diffuse),
            specular: mix(|s| s.specular),
            reflected: mix(|s| s.reflected),
            normal: mix(|s| s.normal).normalize_or_zero(),
            light: mix(|s| s.light).normalize_or_zero(),
            half: mix(|s| s.half).normalize_or_zero(),
            n_dot_l: mixs(|s| s.n_dot_l),
            n_dot_h: mixs(|s| s.n_dot_h),
        }
    }
}

/// The distance attenuation `1/(a + b·d + c·d²)`; a non-positive denominator counts as 1.
#[must_use]
pub fn attenuation(abc: Vec3, d: f32) -> f32 {
    let denom = abc.x + abc.y * d + abc.z * d * d;
    if denom > 0.0 { 1.0 / denom } else { 1.0 }
}

/// The spotlight factor `(cos φ)^e` with `cos φ = (−l)·axis`, or 0 outside the cone of
/// half-angle `cutoff_deg`.
#[must_use]
pub fn spot_factor(l: Vec3, axis: Vec3, cutoff_deg: f32, exponent: f32) -> f32 {
    let cos_phi = (-l).dot(axis.normalize_or_zero());
    if cos_phi < cutoff_deg.to_radians().cos() {
        0.0
    } else {
        power::pow(cos_phi.max(0.0), exponent)
    }
}

/// The unit vector `l` from point `p` towards `light`: `normalize(position − p)` for point and
/// spot lights, `−direction` for a directional one; `None` for ambient light, which has none.
#[must_use]
pub fn light_vector(light: &Light, p: Vec3) -> Option<Vec3> {
    match *light {
        Light::Ambient { .. } => None,
        Light::Point { position, .. } | Light::Spot { position, .. } => {
            Some((position - p).normalize_or_zero())
        }
        Light::Directional { direction, .. } => Some(-direction.normalize_or_zero()),
    }
}

/// What one light contributes at a point, term by term (see the module's formula).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct LightTerm {
    /// `l`, the unit vector towards the light.
    pub l: Vec3,
    /// `h = (l + v)/|l + v|`.
    pub h: Vec3,
    /// `r = 2(l·n)n − l`, the mirror direction of `l`.
    pub r: Vec3,
    /// The distance to the light (0 for a directional light).
    pub distance: f32,
    /// `f_att = 1/(a + b·d + c·d²)` (1 for a directional light).
    pub attenuation: f32,
    /// `f_spot = (cos φ)^e` inside a spotlight's cone, 0 outside, 1 for other lights.
    pub spot: f32,
    /// The light's intensity `I`.
    pub intensity: Vec3,
    /// `n·l`.
    pub n_dot_l: f32,
    /// `n·h` (Blinn-Phong) or `r·v` (Phong).
    pub spec_dot: f32,
    /// `f_att·f_spot·k_d·c·I·max(n·l, 0)`.
    pub diffuse: Vec3,
    /// `f_att·f_spot·k_s·I·max(spec_dot, 0)^shininess`, 0 where `n·l ≤ 0`.
    pub specular: Vec3,
}

/// What light `light` (not ambient) contributes at point `p` with unit normal `n`, unit view
/// vector `v` and surface colour `c`; `None` for an ambient light.
#[must_use]
pub fn light_term(
    light: &Light,
    p: Vec3,
    n: Vec3,
    v: Vec3,
    c: Vec3,
    m: &Material,
    model: Reflection,
) -> Option<LightTerm> {
    let l = light_vector(light, p)?;
    let (intensity, distance, attenuation_abc, spot) = match *light {
        Light::Ambient { .. } => return None,
        Light::Point {
            position,
            intensity,
            attenuation: abc,
        } => (intensity, (position - p).length(), Some(abc), 1.0),
        Light::Directional { intensity, .. } => (intensity, 0.0, None, 1.0),
        Light::Spot {
            position,
            direction,
            cutoff_deg,
            exponent,
            intensity,
            attenuation: abc,
        } => (
            intensity,
            (position - p).length(),
            Some(abc),
            spot_factor(l, direction, cutoff_deg, exponent),
        ),
    };
    let f_att = attenuation_abc.map_or(1.0, |abc| attenuation(abc, distance));
    let factor = f_att * spot;
    let n_dot_l = n.dot(l);
    let h = (l + v).normalize_or_zero();
    let r = 2.0 * n_dot_l * n - l;
    let spec_dot = match model {
        Reflection::Phong => r.dot(v),
        Reflection::BlinnPhong => n.dot(h),
    };
    let specular = if n_dot_l > 0.0 {
        factor * m.ks * intensity * power::pow(spec_dot.max(0.0), m.shininess)
    } else {
        Vec3::ZERO
    };
    Some(LightTerm {
        l,
        h,
        r,
        distance,
        attenuation: f_att,
        spot,
        intensity,
        n_dot_l,
        spec_dot,
        diffuse: factor * m.kd * c * intensity * n_dot_l.max(0.0),
        specular,
    })
}

/// Lights the point `p` (world coordinates) with unit normal `n`, seen from `eye`, of surface
/// colour `c`: `Σ k_a·c·I_a` over the ambient lights plus each other light's [`light_term`]. A
/// normal facing away from the eye is used as it is (no two-sided lighting).
#[must_use]
pub fn shade(
    p: Vec3,
    n: Vec3,
    eye: Vec3,
    c: Vec3,
    lights: &[Light],
    m: &Material,
    model: Reflection,
) -> ShadeTerms {
    let n = n.normalize_or_zero();
    let v = (eye - p).normalize_or_zero();
    let mut out = ShadeTerms {
        normal: n,
        ..ShadeTerms::default()
    };
    let mut key = true;
    for light in lights {
        if let Light::Ambient { intensity } = *light {
            out.ambient += m.ka * c * intensity;
            continue;
        }
        let Some(t) = light_term(light, p, n, v, c, m, model) else {
            continue;
        };
        out.diffuse += t.diffuse;
        out.specular += t.specular;
        if key {
            (out.light, out.half, out.n_dot_l, out.n_dot_h) = (t.l, t.h, t.n_dot_l, t.spec_dot);
            key = false;
        }
    }
    out
}
