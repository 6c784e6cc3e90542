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
            Self::Shading => l.t("comparison-flat-gouraud-phong"),
            Self::Interpolation => l.t("comparison-affine-perspective-correct"),
            Self::Samples => l.t("comparison-1-4-msaa-4-ssaa"),
            Self::Filtering => l.t("comparison-nearest-bilinear-trilinear-anisotropic"),
            Self::Minification => l.t("comparison-trilinear-anisotropic-ripmap-summed-area"),
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
        "flat" => l.t("comparison-flat").to_owned(),
        "affine" => l.t("comparison-affine").to_owned(),
        "perspective-correct" => l.t("comparison-perspective-correct").to_owned(),
        "nearest" => l.t("comparison-nearest").to_owned(),
        "bilinear" => l.t("comparison-bilinear").to_owned(),
        "trilinear" => l.t("comparison-trilinear").to_owned(),
        "anisotropic 16×" => l.t("comparison-anisotropic-16").to_owned(),
        "summed-area table" => l.t("comparison-summed-area-table").to_owned(),
        other => other.to_owned(),
    }
}
