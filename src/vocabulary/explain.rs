//! The words of "explain this pixel": the parts of the derivation and what each line means, in
//! both languages (the core's derivation carries its formulas and numbers, and its remarks as
//! data).

use pipeline::capture::{Remark, Section};

use super::Lang;

/// The heading of a part of the derivation.
#[must_use]
pub fn section_name(s: Section, l: Lang) -> &'static str {
    match s {
        Section::Vertices => l.t("explain-the-triangle-s-vertices-clip"),
        Section::Rasterization => l.t("explain-inside-test-edge-functions"),
        Section::Interpolation => l.t("explain-interpolation-at-the-pixel-centre"),
        Section::Texture => l.t("explain-texture-lookup"),
        Section::Lighting => l.t("explain-lighting"),
        Section::Colour => l.t("explain-the-colour"),
    }
}

/// What a line of the derivation means, in words.
#[must_use]
// One arm a remark, in both languages: a table, long by nature.
#[allow(clippy::too_many_lines)]
pub fn remark(r: &Remark, l: Lang) -> String {
    let s = |id: &'static str| l.t(id).to_owned();
    match r {
        Remark::BehindEye => s("explain-behind-the-eye-no-ndc"),
        Remark::Clipped => s("explain-the-triangle-crosses-the-view"),
        Remark::Corners => s("explain-the-corners-snapped"),
        Remark::PixelCentre => s("explain-the-pixel-centre"),
        Remark::EdgeOpposite { edge } => l.t_with("explain-edge-opposite", &[("edge", edge)]),
        Remark::Sample { index, inside } => l.t_with(
            if *inside {
                "explain-sample-covered"
            } else {
                "explain-sample-not-covered"
            },
            &[("index", index)],
        ),
        Remark::OnEdge { edge, top_left } => l.t_with(
            if *top_left {
                "explain-on-a-top-or-left-edge"
            } else {
                "explain-on-a-bottom-or-right-edge"
            },
            &[("edge", edge)],
        ),
        Remark::ScreenLinear => s("explain-depth-is-linear-in-screen"),
        Remark::PerspectiveCorrect => s("explain-perspective-correct-interpolation"),
        Remark::Affine => s("explain-affine-interpolation-for-comparison"),
        Remark::Quad => s("explain-derivatives-as-a-gpu-takes"),
        Remark::Anisotropic => s("explain-anisotropic-n-taps-along-the"),
        Remark::Magnification => s("explain-0-magnification-level-0"),
        Remark::NoMipmap => s("explain-no-mipmap-level-0-always"),
        Remark::NearestLevel { max } => l.t_with("explain-nearest-level", &[("max", max)]),
        Remark::Ripmap => s("explain-ripmap-level-i-halves-u"),
        Remark::SummedArea => s("explain-summed-area-table-the-exact"),
        Remark::Ewa => s("explain-ewa-the-texels-inside-the"),
        Remark::Trilinear { max } => l.t_with("explain-trilinear", &[("max", max)]),
        Remark::Texels {
            level,
            width,
            height,
        } => l.t_with(
            "explain-four-texels",
            &[("level", level), ("width", width), ("height", height)],
        ),
        Remark::NearestTexel => s("explain-nearest-the-texel-containing-the"),
        Remark::TapsMean => s("explain-the-mean-of-the-taps"),
        Remark::Gouraud => s("explain-gouraud-lit-at-each-vertex"),
        Remark::Flat => s("explain-flat-lit-once-per-face"),
        Remark::Textured => s("explain-textured-the-texel-t-multiplies"),
        Remark::Bump => s("explain-bump-or-normal-mapping-tilts"),
        Remark::Mirror => s("explain-a-mirror-it-reflects-its"),
        Remark::Material => s("explain-the-material-k-a-k"),
        Remark::Ambient => s("explain-ambient-term"),
        Remark::Light { index, kind } => {
            let kind = l.t(match kind.as_str() {
                "directional" => "explain-directional-light",
                "spot" => "explain-spot-light",
                _ => "explain-point-light",
            });
            l.t_with(
                "explain-light-towards",
                &[("index", index), ("kind", &kind)],
            )
        }
        Remark::Attenuation => s("explain-distance-attenuation"),
        Remark::SpotCone => s("explain-the-spotlight-s-cone-half"),
        Remark::Diffuse => s("explain-diffuse-term-lambert"),
        Remark::HalfVector => s("explain-the-half-vector-between-l"),
        Remark::MirrorVector => s("explain-the-mirror-direction-of-l"),
        Remark::Specular => s("explain-specular-term-max-0-before"),
        Remark::Sum => s("explain-the-sum-of-the-terms"),
        Remark::Samples { covered, samples } => l.t_with(
            "explain-mean-of-samples",
            &[("samples", samples), ("covered", covered)],
        ),
        Remark::Clamped => s("explain-the-colour-buffer-keeps-each"),
        Remark::Bytes => s("explain-the-8-bit-colour-in"),
    }
}

/// The legend of the lighting vectors drawn at an inspected pixel (app and exported pictures).
#[must_use]
pub fn lighting_legend(lang: Lang) -> [&'static str; 2] {
    [
        lang.t("explain-n-normal-l-to-the"),
        "h = (l + v)/|l + v| · r = 2(n·l)n − l",
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sentences with numbers in them, as a reader should see them (written by hand).
    #[test]
    fn the_remarks_with_numbers_read_as_sentences_in_both_languages() {
        let on_edge = Remark::OnEdge {
            edge: 2,
            top_left: false,
        };
        assert_eq!(
            remark(&on_edge, Lang::EN),
            "exactly on edge 2, a bottom or right edge: does not count (top-left rule)"
        );
        assert_eq!(
            remark(&on_edge, Lang::ZH),
            "恰好在边 2 上，这是下边或右边：不算内部（左上填充规则）"
        );
        let texels = Remark::Texels {
            level: 3,
            width: 32,
            height: 16,
        };
        assert_eq!(
            remark(&texels, Lang::EN),
            "the four texels read, of level 3 (32×16)"
        );
        assert_eq!(
            remark(&texels, Lang::ZH),
            "读取的四个纹素，第 3 层（32×16）"
        );
        let spot = Remark::Light {
            index: 1,
            kind: "spot".to_owned(),
        };
        assert_eq!(
            remark(&spot, Lang::EN),
            "light 1 (spot): the unit vector towards it"
        );
        assert_eq!(
            remark(&spot, Lang::ZH),
            "光源 1（聚光灯）：指向它的单位向量"
        );
        let one = Remark::Samples {
            covered: 1,
            samples: 4,
        };
        assert_eq!(
            remark(&one, Lang::EN),
            "the mean of the pixel's 4 samples; 1 belongs to this triangle's primitive, the others keep their own colour or the background"
        );
        let three = Remark::Samples {
            covered: 3,
            samples: 4,
        };
        assert!(remark(&three, Lang::EN).contains("; 3 belong to this"));
        assert_eq!(
            remark(&three, Lang::ZH),
            "像素 4 个采样点的平均；其中 3 个属于该图元，其余保留各自的颜色或背景色"
        );
        assert_eq!(
            remark(
                &Remark::Sample {
                    index: 0,
                    inside: true
                },
                Lang::ZH
            ),
            "采样点 0 被覆盖"
        );
    }
}
