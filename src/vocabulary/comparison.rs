//! Settings compared side by side: flat | Gouraud | Phong (the Mach band comparison), affine |
//! perspective-correct, 1× | 4× MSAA | 4× SSAA, nearest | bilinear | trilinear | anisotropic.

use pipeline::lighting::Frequency;
use pipeline::raster::Samples;
use pipeline::settings::RenderSettings;
use pipeline::texture::{Filter, Mipmap, Sampler};

use super::Lang;

/// A comparison of settings side by side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comparison {
    /// Flat | Gouraud | Phong shading: the Mach band comparison.
    Shading,
    /// Affine | perspective-correct interpolation.
    Interpolation,
    /// 1 sample | 4 samples shaded once per pixel (MSAA) | 4 samples each shaded (SSAA).
    Samples,
    /// Nearest | bilinear | trilinear | anisotropic texture filtering.
    Filtering,
    /// Trilinear | anisotropic 16× | ripmap | summed-area table | EWA: minification beyond the
    /// mipmap, beside what GPUs do (N trilinear taps along the footprint's major axis).
    Minification,
}

impl Comparison {
    /// The comparison named `shading`, `interpolation` or `samples`, for the command line.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.key() == name)
    }

    /// Its name in files and on the command line.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::Shading => "shading",
            Self::Interpolation => "interpolation",
            Self::Samples => "samples",
            Self::Filtering => "filtering",
            Self::Minification => "minification",
        }
    }

    /// Every comparison.
    pub const ALL: [Comparison; 5] = [
        Self::Shading,
        Self::Interpolation,
        Self::Samples,
        Self::Filtering,
        Self::Minification,
    ];

    /// Its name.
    #[must_use]
    pub fn name(self, l: Lang) -> &'static str {
        match self {
            Self::Shading => l.tr("flat | Gouraud | Phong", "平面 | Gouraud | Phong"),
            Self::Interpolation => l.tr("affine | perspective-correct", "仿射 | 透视校正"),
            Self::Samples => l.tr("1× | 4× MSAA | 4× SSAA", "1× | 4× MSAA | 4× SSAA"),
            Self::Filtering => l.tr(
                "nearest | bilinear | trilinear | anisotropic",
                "最近邻 | 双线性 | 三线性 | 各向异性",
            ),
            Self::Minification => l.tr(
                "trilinear | anisotropic | ripmap | summed-area table | EWA",
                "三线性 | 各向异性 | ripmap | 求和面积表 | EWA",
            ),
        }
    }

    /// The settings compared, each with its label, derived from `base`.
    #[must_use]
    pub fn variants(self, base: &RenderSettings) -> Vec<(String, RenderSettings)> {
        let with = |label: &str, f: &dyn Fn(&mut RenderSettings)| {
            let mut s = *base;
            f(&mut s);
            (label.to_owned(), s)
        };
        match self {
            Self::Shading => vec![
                with("flat", &|s| s.shading = Frequency::Flat),
                with("Gouraud", &|s| s.shading = Frequency::Gouraud),
                with("Phong", &|s| s.shading = Frequency::Phong),
            ],
            Self::Interpolation => vec![
                with("affine", &|s| s.perspective_correct = false),
                with("perspective-correct", &|s| s.perspective_correct = true),
            ],
            Self::Samples => vec![
                with("1×", &|s| s.samples = Samples::X1),
                with("4× MSAA", &|s| {
                    s.samples = Samples::X4;
                    s.per_sample_shading = false;
                }),
                with("4× SSAA", &|s| {
                    s.samples = Samples::X4;
                    s.per_sample_shading = true;
                }),
            ],
            Self::Filtering | Self::Minification => {
                let sampler = |filter, mipmap, anisotropy| {
                    move |s: &mut RenderSettings| {
                        s.sampler = Sampler {
                            filter,
                            mipmap,
                            anisotropy,
                            ..s.sampler
                        };
                    }
                };
                if self == Self::Minification {
                    return vec![
                        with("trilinear", &sampler(Filter::Bilinear, Mipmap::Linear, 1)),
                        with(
                            "anisotropic 16×",
                            &sampler(Filter::Bilinear, Mipmap::Linear, 16),
                        ),
                        with("ripmap", &sampler(Filter::Bilinear, Mipmap::Ripmap, 1)),
                        with(
                            "summed-area table",
                            &sampler(Filter::Bilinear, Mipmap::SummedArea, 1),
                        ),
                        with("EWA", &sampler(Filter::Bilinear, Mipmap::Ewa, 1)),
                    ];
                }
                vec![
                    with("nearest", &sampler(Filter::Nearest, Mipmap::None, 1)),
                    with("bilinear", &sampler(Filter::Bilinear, Mipmap::None, 1)),
                    with("trilinear", &sampler(Filter::Bilinear, Mipmap::Linear, 1)),
                    with(
                        "anisotropic 16×",
                        &sampler(Filter::Bilinear, Mipmap::Linear, 16),
                    ),
                ]
            }
        }
    }
}

/// A compared setting's label in `lang` (the labels [`Comparison::variants`] gives are the
/// English ones, which also name the exported files).
#[must_use]
pub fn variant_label(key: &str, l: Lang) -> String {
    match key {
        "flat" => l.tr("flat", "平面").to_owned(),
        "affine" => l.tr("affine", "仿射").to_owned(),
        "perspective-correct" => l.tr("perspective-correct", "透视校正").to_owned(),
        "nearest" => l.tr("nearest", "最近邻").to_owned(),
        "bilinear" => l.tr("bilinear", "双线性").to_owned(),
        "trilinear" => l.tr("trilinear", "三线性").to_owned(),
        "anisotropic 16×" => l.tr("anisotropic 16×", "各向异性 16×").to_owned(),
        "summed-area table" => l.tr("summed-area table", "求和面积表").to_owned(),
        other => other.to_owned(),
    }
}
