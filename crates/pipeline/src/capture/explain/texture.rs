//! The texture lookup of the derivation: uv and its screen derivatives, the footprint, λ, the
//! level read and the texels filtered — with `RasterTriangle::uv_at` and `Texture::sample`, as
//! the render did it.

use glam::{Vec2, Vec3};

use super::{Lines, Owner, Remark, Section, TextureStep, n, v2, v3};
use crate::capture::FrameCapture;
use crate::texture::{Filter, Lookup, Mipmap, Texture};

impl FrameCapture {
    /// The texture lookup at the owner's centre, when its object is textured.
    pub(super) fn explain_texture(&self, o: &Owner<'_>, lines: &mut Lines) -> Option<TextureStep> {
        let (_, texture) = self
            .textures
            .iter()
            .find(|(name, _)| *name == o.object.name)?;
        let [Some(a), Some(b), Some(c)] = o.vertices.map(|v| v.uv) else {
            return None;
        };
        let sampler = &self.settings.sampler;
        let (uv, dx, dy) = o.tri.uv_at(
            &o.prim.bary_corners(o.tri),
            [a, b, c],
            o.centre,
            self.settings.height,
            self.settings.perspective_correct,
            true,
        );
        let lookup = texture.sample(uv, dx, dy, sampler);
        let size = texture.levels[0].size();
        let [fx, fy] = lookup.footprint;
        let lengths = [fx.length(), fy.length()];
        let s = Section::Texture;
        lines.add(
            s,
            "uv = Σ_k b_k·uv_k",
            format!("uv_k = {}, {}, {}", v2(a), v2(b), v2(c)),
            v2(uv),
        );
        let quad = (o.centre - crate::raster::quad_offset(o.centre, self.settings.height))
            / crate::raster::ONE;
        lines.add(
            s,
            "∂uv/∂x = uv(x_q + 1, y_q) − uv(x_q, y_q); ∂uv/∂y = uv(x_q, y_q + 1) − uv(x_q, y_q)",
            format!("(x_q, y_q) = ({}, {})", quad.x, quad.y),
            format!("{}; {}", v2(dx), v2(dy)),
        );
        lines.note(Remark::Quad);
        for (axis, d, f) in [("x", dx, fx), ("y", dy, fy)] {
            lines.add(
                s,
                &format!("(∂s/∂{axis}, ∂t/∂{axis}) = (w·∂u/∂{axis}, h·∂v/∂{axis})"),
                format!("({}·{}, {}·{})", n(size.x), n(d.x), n(size.y), n(d.y)),
                v2(f),
            );
        }
        let major = lengths[0].max(lengths[1]);
        lines.add(
            s,
            "L = max(|∂/∂x|, |∂/∂y|)",
            format!("max({}, {})", n(lengths[0]), n(lengths[1])),
            n(major),
        );
        let bias = n(sampler.lod_bias);
        if lookup.taps > 1 {
            lines.add(
                s,
                "N = min(⌈L_major/L_minor⌉, N_max); λ = log_2(L/N) + λ_bias",
                format!(
                    "N = {}; log_2({}/{}) + {bias}",
                    lookup.taps,
                    n(major),
                    lookup.taps
                ),
                n(lookup.lod),
            );
            lines.note(Remark::Anisotropic);
        } else {
            lines.add(
                s,
                "λ = log_2 L + λ_bias",
                format!("log_2 {} + {bias}", n(major)),
                n(lookup.lod),
            );
        }
        let (bilinear, texels) = self.explain_level_read(texture, &lookup, uv, lines);
        Some(TextureStep {
            texture: texture.name.clone(),
            size: [texture.levels[0].width, texture.levels[0].height],
            uv,
            duv: [dx, dy],
            footprint: lookup.footprint,
            lengths,
            taps: lookup.taps,
            lod: lookup.lod,
            level: lookup.level,
            blend: lookup.level_blend,
            bilinear,
            texels,
            color: lookup.color,
        })
    }

    /// Which level `λ` chose, the texels read there and their filtering.
    fn explain_level_read(
        &self,
        texture: &Texture,
        lookup: &Lookup,
        uv: Vec2,
        lines: &mut Lines,
    ) -> (Option<crate::texture::BilinearTaps>, Vec<Vec3>) {
        let s = Section::Texture;
        let sampler = &self.settings.sampler;
        let max_level = texture.levels.len() - 1;
        let (rule, result, remark) = match sampler.mipmap {
            _ if lookup.lod <= 0.0 => ("k = 0", "k = 0".to_owned(), Remark::Magnification),
            Mipmap::None => ("k = 0", "k = 0".to_owned(), Remark::NoMipmap),
            Mipmap::Nearest => (
                "k = ⌊λ + 1/2⌋",
                format!("k = {}", lookup.level),
                Remark::NearestLevel { max: max_level },
            ),
            Mipmap::Linear => (
                "k = ⌊λ⌋, t = λ − k",
                format!("k = {}, t = {}", lookup.level, n(lookup.level_blend)),
                Remark::Trilinear { max: max_level },
            ),
            Mipmap::Ripmap => (
                "(i, j) = (round log₂ Δu, round log₂ Δv)",
                format!("min(i, j) = {}", lookup.level),
                Remark::Ripmap,
            ),
            Mipmap::SummedArea => (
                "T = (S(x₁, y₁) − S(x₀, y₁) − S(x₁, y₀) + S(x₀, y₀))/area",
                v3(lookup.color),
                Remark::SummedArea,
            ),
            Mipmap::Ewa => (
                "T = Σ w·T/Σ w, w = exp(−2Q/F), Q < F",
                format!("k = {}, {} texels", lookup.level, lookup.taps),
                Remark::Ewa,
            ),
        };
        lines.add(s, rule, String::new(), result);
        lines.note(remark);
        if sampler.mipmap.beyond_the_pyramid() {
            // No bilinear taps to list: the range query read its own texels.
            return (None, Vec::new());
        }
        let level = &texture.levels[lookup.level as usize];
        let one_bilinear_tap = lookup.taps == 1 && sampler.filter == Filter::Bilinear;
        if !one_bilinear_tap {
            let nearest = sampler.filter == Filter::Nearest && lookup.taps == 1;
            lines.add(
                s,
                if nearest {
                    "T = T(⌊u·w_k⌋, ⌊v·h_k⌋)"
                } else {
                    "T = Σ_j T_j/N"
                },
                String::new(),
                v3(lookup.color),
            );
            lines.note(if nearest {
                Remark::NearestTexel
            } else {
                Remark::TapsMean
            });
            return (None, Vec::new());
        }
        let taps = level.bilinear_taps(uv, sampler.wrap);
        let at = |i: usize, j: usize| level.texels[j * level.width as usize + i];
        let ([i0, i1], [j0, j1]) = (taps.columns, taps.rows);
        let texels = vec![at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1)];
        lines.add(
            s,
            "x = u·w_k − 1/2, y = v·h_k − 1/2; s = x − ⌊x⌋, t = y − ⌊y⌋",
            format!("({i0}, {j0}), ({i1}, {j0}), ({i0}, {j1}), ({i1}, {j1})"),
            format!("s = {}, t = {}", n(taps.s), n(taps.t)),
        );
        lines.note(Remark::Texels {
            level: lookup.level,
            width: level.width,
            height: level.height,
        });
        lines.add(
            s,
            "T = lerp(lerp(T_00, T_10, s), lerp(T_01, T_11, s), t)",
            format!(
                "T = {}, {}, {}, {}",
                v3(texels[0]),
                v3(texels[1]),
                v3(texels[2]),
                v3(texels[3])
            ),
            v3(level.bilinear(uv, sampler.wrap)),
        );
        if lookup.level_blend > 0.0 {
            lines.add(
                s,
                "T = (1 − t)·T_k + t·T_{k+1}",
                format!("k = {}, t = {}", lookup.level, n(lookup.level_blend)),
                v3(lookup.color),
            );
        }
        (Some(taps), texels)
    }
}
