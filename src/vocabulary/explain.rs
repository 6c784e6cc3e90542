//! The words of "explain this pixel": the parts of the derivation and what each line means, in
//! both languages (the core's derivation carries its formulas and numbers, and its remarks as
//! data).

use crate::vocabulary::Written;
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
        Remark::Corners => s("explain-snapped-to-1-256-pixel"),
        Remark::PixelCentre => s("explain-the-pixel-centre"),
        Remark::EdgeOpposite { edge } => match l.written() {
            Written::English => format!("the edge opposite corner {edge}"),
            Written::Chinese => format!("角点 {edge} 对面的边"),
        },
        Remark::Sample { index, inside } => match (l.written(), inside) {
            (Written::English, true) => format!("sample {index} is covered"),
            (Written::English, false) => format!("sample {index} is not covered"),
            (Written::Chinese, true) => format!("采样点 {index} 被覆盖"),
            (Written::Chinese, false) => format!("采样点 {index} 未被覆盖"),
        },
        Remark::OnEdge { edge, top_left } => match (l.written(), top_left) {
            (Written::English, true) => format!(
                "exactly on edge {edge}, a top or left edge: counts as inside (top-left rule)"
            ),
            (Written::English, false) => format!(
                "exactly on edge {edge}, a bottom or right edge: does not count (top-left rule)"
            ),
            (Written::Chinese, true) => {
                format!("恰好在边 {edge} 上，这是上边或左边：算作内部（左上填充规则）")
            }
            (Written::Chinese, false) => {
                format!("恰好在边 {edge} 上，这是下边或右边：不算内部（左上填充规则）")
            }
        },
        Remark::ScreenLinear => s("explain-depth-is-linear-in-screen"),
        Remark::PerspectiveCorrect => s("explain-perspective-correct-interpolation"),
        Remark::Affine => s("explain-affine-interpolation-for-comparison"),
        Remark::Quad => s("explain-derivatives-as-a-gpu-takes"),
        Remark::Anisotropic => s("explain-anisotropic-n-taps-along-the"),
        Remark::Magnification => s("explain-0-magnification-level-0"),
        Remark::NoMipmap => s("explain-no-mipmap-level-0-always"),
        Remark::NearestLevel { max } => match l.written() {
            Written::English => format!("the nearest level, at most {max}"),
            Written::Chinese => format!("最近的层级，最多为 {max}"),
        },
        Remark::Ripmap => s("explain-ripmap-level-i-halves-u"),
        Remark::SummedArea => s("explain-summed-area-table-the-exact"),
        Remark::Ewa => s("explain-ewa-the-texels-inside-the"),
        Remark::Trilinear { max } => match l.written() {
            Written::English => {
                format!("trilinear: levels k and k+1 blended by t (λ at most {max})")
            }
            Written::Chinese => format!("三线性：按 t 混合第 k 层与第 k+1 层（λ 最多为 {max}）"),
        },
        Remark::Texels {
            level,
            width,
            height,
        } => match l.written() {
            Written::English => {
                format!("the four texels read, of level {level} ({width}×{height})")
            }
            Written::Chinese => format!("读取的四个纹素，第 {level} 层（{width}×{height}）"),
        },
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
            let kind = match (l.written(), kind.as_str()) {
                (Written::English, k) => k.to_owned(),
                (Written::Chinese, "directional") => "平行光".to_owned(),
                (Written::Chinese, "spot") => "聚光灯".to_owned(),
                (Written::Chinese, _) => "点光源".to_owned(),
            };
            match l.written() {
                Written::English => format!("light {index} ({kind}): the unit vector towards it"),
                Written::Chinese => format!("光源 {index}（{kind}）：指向它的单位向量"),
            }
        }
        Remark::Attenuation => s("explain-distance-attenuation"),
        Remark::SpotCone => s("explain-the-spotlight-s-cone-half"),
        Remark::Diffuse => s("explain-diffuse-term-lambert"),
        Remark::HalfVector => s("explain-the-half-vector-between-l"),
        Remark::MirrorVector => s("explain-the-mirror-direction-of-l"),
        Remark::Specular => s("explain-specular-term-max-0-before"),
        Remark::Sum => s("explain-the-sum-of-the-terms"),
        Remark::Samples { covered, samples } => match l.written() {
            Written::English => format!(
                "the mean of the pixel's {samples} samples; {covered} belong to this triangle's primitive, the others keep their own colour or the background"
            ),
            Written::Chinese => format!(
                "像素 {samples} 个采样点的平均；其中 {covered} 个属于该图元，其余保留各自的颜色或背景色"
            ),
        },
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
