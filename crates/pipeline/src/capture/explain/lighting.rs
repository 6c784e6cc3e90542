//! The lighting of the derivation, by the shading frequency: Gouraud's vertex colours
//! interpolated, flat shading's one colour per face, or Phong shading evaluated at the pixel
//! light by light with `lighting::light_term`, as the render did it.

use glam::Vec3;

use super::{LightStep, LightingStep, Lines, Owner, Remark, Section, n, v3};
use crate::capture::FrameCapture;
use crate::light::{Light, Material};
use crate::lighting::{self, Frequency, LightTerm, Reflection, ShadeTerms};

impl FrameCapture {
    /// The lighting at the owner's centre by the shading frequency; `None` when unlit.
    pub(super) fn explain_lighting(
        &self,
        o: &Owner<'_>,
        surface: Vec3,
        textured: bool,
        lines: &mut Lines,
    ) -> Option<LightingStep> {
        let frequency = self.settings.shading;
        if frequency == Frequency::Unlit || !o.object.lit {
            return None;
        }
        let mut out = LightingStep {
            frequency,
            reflection: self.settings.reflection,
            normal: o.normal,
            view: (self.camera.eye - o.position).normalize_or_zero(),
            lights: Vec::new(),
            vertex_colors: Vec::new(),
            terms: ShadeTerms::default(),
        };
        let s = Section::Lighting;
        let mut terms = match frequency {
            Frequency::Unlit => return None,
            Frequency::Gouraud => {
                let t = o.prim.vertices.map(|r| {
                    self.vertex_shading
                        .get(r as usize)
                        .copied()
                        .unwrap_or_default()
                });
                out.vertex_colors = t.iter().map(ShadeTerms::color).collect();
                let terms = ShadeTerms::blend([&t[0], &t[1], &t[2]], o.b);
                lines.add(
                    s,
                    "c = Σ_k b_k·I(p_k, n_k)",
                    format!(
                        "I(p_k, n_k) = {}, {}, {}",
                        v3(out.vertex_colors[0]),
                        v3(out.vertex_colors[1]),
                        v3(out.vertex_colors[2])
                    ),
                    v3(terms.color()),
                );
                lines.note(Remark::Gouraud);
                terms
            }
            Frequency::Flat => {
                let terms = self
                    .face_shading
                    .get(o.prim.id as usize)
                    .copied()
                    .unwrap_or_default();
                out.vertex_colors = vec![terms.color()];
                out.normal = terms.normal;
                lines.add(
                    s,
                    "c = I(p_2, c_2, n_face), n_face = normalize((p_1 − p_0)×(p_2 − p_0))",
                    format!("n_face = {}", v3(terms.normal)),
                    v3(terms.color()),
                );
                lines.note(Remark::Flat);
                terms
            }
            Frequency::Phong => self.explain_phong(o, surface, &mut out, lines),
        };
        if textured && frequency != Frequency::Phong {
            // The vertices and faces were lit white; the texel modulates ambient and diffuse.
            terms.ambient *= surface;
            terms.diffuse *= surface;
            lines.add(
                s,
                "c = T·L_a + T·L_d + L_s",
                format!("T = {}", v3(surface)),
                v3(terms.color()),
            );
            lines.note(Remark::Textured);
        }
        out.terms = terms;
        Some(out)
    }

    /// Per-pixel lighting: the normal, `v`, then every light's terms.
    fn explain_phong(
        &self,
        o: &Owner<'_>,
        surface: Vec3,
        out: &mut LightingStep,
        lines: &mut Lines,
    ) -> ShadeTerms {
        let s = Section::Lighting;
        let stored = self.pixels.shading.as_ref().map(|b| b.at(o.i));
        if o.object.detail
            && let Some(st) = &stored
        {
            // Bump and normal maps are not in the capture: the normal they made is.
            out.normal = Vec3::from(st.normal).normalize_or_zero();
            lines.add(s, "n = normalize(TBN·n_t)", String::new(), v3(out.normal));
            lines.note(Remark::Bump);
        }
        lines.add(
            s,
            "v = normalize(eye − p)",
            format!("normalize({} − {})", v3(self.camera.eye), v3(o.position)),
            v3(out.view),
        );
        let m = &o.object.material;
        lines.add(
            s,
            "k_a, k_d, k_s, p",
            format!(
                "{}, {}, {}, {}",
                v3(m.ka),
                v3(m.kd),
                v3(m.ks),
                n(m.shininess)
            ),
            String::new(),
        );
        lines.note(Remark::Material);
        let mut terms = ShadeTerms {
            normal: out.normal,
            ..ShadeTerms::default()
        };
        for (index, light) in self.lights.iter().enumerate() {
            if let Light::Ambient { intensity } = *light {
                let a = m.ka * surface * intensity;
                terms.ambient += a;
                lines.add(
                    s,
                    "L_a = k_a·c·I_a",
                    format!("{}·{}·{}", v3(m.ka), v3(surface), v3(intensity)),
                    v3(a),
                );
                lines.note(Remark::Ambient);
                out.lights.push(LightStep {
                    index,
                    light: *light,
                    term: None,
                });
                continue;
            }
            let Some(t) = lighting::light_term(
                light,
                o.position,
                out.normal,
                out.view,
                surface,
                m,
                out.reflection,
            ) else {
                continue;
            };
            explain_light(index, light, &t, m, surface, out.reflection, lines);
            if out.lights.iter().all(|l| l.term.is_none()) {
                (terms.light, terms.half, terms.n_dot_l, terms.n_dot_h) =
                    (t.l, t.h, t.n_dot_l, t.spec_dot);
            }
            terms.diffuse += t.diffuse;
            terms.specular += t.specular;
            out.lights.push(LightStep {
                index,
                light: *light,
                term: Some(t),
            });
        }
        if let Some(k) = o.object.reflectivity {
            let k = k.clamp(0.0, 1.0);
            // The cube map is not in the capture: what it reflected is.
            terms.reflected = stored
                .as_ref()
                .map_or(Vec3::ZERO, |b| Vec3::from(b.reflected));
            terms.ambient *= 1.0 - k;
            terms.diffuse *= 1.0 - k;
            lines.add(
                s,
                "L_r = k·C_env(r), r = 2(n·v)n − v; L_a, L_d × (1 − k)",
                format!("k = {}", n(k)),
                v3(terms.reflected),
            );
            lines.note(Remark::Mirror);
        }
        terms
    }
}

/// One light's lines: l, distance and attenuation, the spot factor, n·l, h or r, the diffuse
/// and specular terms.
fn explain_light(
    index: usize,
    light: &Light,
    t: &LightTerm,
    m: &Material,
    surface: Vec3,
    reflection: Reflection,
    lines: &mut Lines,
) {
    let s = Section::Lighting;
    let (l_formula, kind) = match light {
        Light::Directional { .. } => ("l = −d/|d|", "directional"),
        Light::Spot { .. } => ("l = normalize(p_light − p)", "spot"),
        _ => ("l = normalize(p_light − p)", "point"),
    };
    lines.add(s, l_formula, String::new(), v3(t.l));
    lines.note(Remark::Light {
        index,
        kind: kind.to_owned(),
    });
    if let Light::Point {
        attenuation: abc, ..
    }
    | Light::Spot {
        attenuation: abc, ..
    } = light
    {
        lines.add(
            s,
            "f_att = 1/(a + b·d + c·d^2)",
            format!(
                "d = {}; 1/({} + {}·{} + {}·{}^2)",
                n(t.distance),
                n(abc.x),
                n(abc.y),
                n(t.distance),
                n(abc.z),
                n(t.distance)
            ),
            n(t.attenuation),
        );
        lines.note(Remark::Attenuation);
    }
    if let Light::Spot {
        cutoff_deg,
        exponent,
        ..
    } = light
    {
        lines.add(
            s,
            "f_spot = (cos φ)^e if φ ≤ θ, else 0",
            format!("θ = {}°, e = {}", n(*cutoff_deg), n(*exponent)),
            n(t.spot),
        );
        lines.note(Remark::SpotCone);
    }
    lines.add(s, "n·l", String::new(), n(t.n_dot_l));
    lines.add(
        s,
        "L_d = f_att·k_d·c·I·max(n·l, 0)",
        format!(
            "{}·{}·{}·{}·{}",
            n(t.attenuation * t.spot),
            v3(m.kd),
            v3(surface),
            v3(t.intensity),
            n(t.n_dot_l.max(0.0))
        ),
        v3(t.diffuse),
    );
    lines.note(Remark::Diffuse);
    let (vector, dot) = match reflection {
        Reflection::BlinnPhong => (("h = (l + v)/|l + v|", t.h), "n·h"),
        Reflection::Phong => (("r = 2(n·l)n − l", t.r), "r·v"),
    };
    lines.add(s, vector.0, String::new(), v3(vector.1));
    lines.note(match reflection {
        Reflection::BlinnPhong => Remark::HalfVector,
        Reflection::Phong => Remark::MirrorVector,
    });
    lines.add(s, dot, String::new(), n(t.spec_dot));
    lines.add(
        s,
        &format!("L_s = f_att·k_s·I·max({dot}, 0)^p"),
        format!(
            "{}·{}·{}·{}^{}",
            n(t.attenuation * t.spot),
            v3(m.ks),
            v3(t.intensity),
            n(t.spec_dot.max(0.0)),
            n(m.shininess)
        ),
        v3(t.specular),
    );
    lines.note(Remark::Specular);
}
