//! The words of "explain this pixel": the parts of the derivation and what each line means, in
//! both languages (the core's derivation carries its formulas and numbers, and its remarks as
//! data).

use pipeline::capture::{Remark, Section};

use super::Lang;

/// The heading of a part of the derivation.
#[must_use]
pub fn section_name(s: Section, l: Lang) -> &'static str {
    match s {
        Section::Vertices => l.tr(
            "The triangle's vertices: clip → NDC → window",
            "三角形的顶点：裁剪 → NDC → 屏幕",
        ),
        Section::Rasterization => l.tr("Inside test: edge functions", "内部测试：边函数"),
        Section::Interpolation => l.tr("Interpolation at the pixel centre", "在像素中心插值"),
        Section::Texture => l.tr("Texture lookup", "纹理查询"),
        Section::Lighting => l.tr("Lighting", "光照"),
        Section::Colour => l.tr("The colour", "颜色"),
    }
}

/// What a line of the derivation means, in words.
#[must_use]
// One arm a remark, in both languages: a table, long by nature.
#[allow(clippy::too_many_lines)]
pub fn remark(r: &Remark, l: Lang) -> String {
    let s = |en: &str, zh: &str| l.tr_owned(en, zh);
    match r {
        Remark::BehindEye => s(
            "behind the eye: no NDC; clipping cut the triangle first",
            "在视点之后：没有 NDC；裁剪先把三角形切开",
        ),
        Remark::Clipped => s(
            "the triangle crosses the view volume: the pixel lies in a piece of the clipped polygon",
            "三角形跨越视见体：该像素位于裁剪后多边形的一部分中",
        ),
        Remark::Corners => s(
            "snapped to 1/256 pixel, counter-clockwise; v_k is vertex k, c_k a corner made by clipping",
            "对齐到 1/256 像素，逆时针；v_k 是第 k 个顶点，c_k 是裁剪产生的角点",
        ),
        Remark::PixelCentre => s("the pixel centre", "像素中心"),
        Remark::EdgeOpposite { edge } => match l {
            Lang::En => format!("the edge opposite corner {edge}"),
            Lang::Zh => format!("角点 {edge} 对面的边"),
        },
        Remark::Sample { index, inside } => match (l, inside) {
            (Lang::En, true) => format!("sample {index} is covered"),
            (Lang::En, false) => format!("sample {index} is not covered"),
            (Lang::Zh, true) => format!("采样点 {index} 被覆盖"),
            (Lang::Zh, false) => format!("采样点 {index} 未被覆盖"),
        },
        Remark::OnEdge { edge, top_left } => match (l, top_left) {
            (Lang::En, true) => format!(
                "exactly on edge {edge}, a top or left edge: counts as inside (top-left rule)"
            ),
            (Lang::En, false) => format!(
                "exactly on edge {edge}, a bottom or right edge: does not count (top-left rule)"
            ),
            (Lang::Zh, true) => {
                format!("恰好在边 {edge} 上，这是上边或左边：算作内部（左上填充规则）")
            }
            (Lang::Zh, false) => {
                format!("恰好在边 {edge} 上，这是下边或右边：不算内部（左上填充规则）")
            }
        },
        Remark::ScreenLinear => s(
            "depth is linear in screen space",
            "深度在屏幕空间中是线性的",
        ),
        Remark::PerspectiveCorrect => s("perspective-correct interpolation", "透视校正插值"),
        Remark::Affine => s(
            "affine interpolation, for comparison",
            "仿射插值（用于对比）",
        ),
        Remark::Quad => s(
            "derivatives as a GPU takes them: differences within the pixel's 2×2 quad, at its lower-left pixel (x_q, y_q); the quad's four pixels share them and λ",
            "导数按 GPU 的做法求：在像素所在的 2×2 像素块（quad）内作差，取在其左下像素 (x_q, y_q) 处；块内四个像素共用这组导数和 λ",
        ),
        Remark::Anisotropic => s(
            "anisotropic: N taps along the footprint's major axis",
            "各向异性：沿覆盖区域（footprint）长轴取 N 个样本",
        ),
        Remark::Magnification => s("λ ≤ 0: magnification, level 0", "λ ≤ 0：放大，使用第 0 层"),
        Remark::NoMipmap => s("no mipmap: level 0 always", "无 mipmap：总是第 0 层"),
        Remark::NearestLevel { max } => match l {
            Lang::En => format!("the nearest level, at most {max}"),
            Lang::Zh => format!("最近的层级，最多为 {max}"),
        },
        Remark::Ripmap => s(
            "ripmap: level i halves u, level j halves v, each chosen from a side of the footprint's bounding box; a diagonal footprint's box is too big",
            "ripmap：第 i 层在 u 方向减半、第 j 层在 v 方向减半，各自由覆盖区域包围盒的一条边决定；斜向覆盖区域的包围盒偏大",
        ),
        Remark::SummedArea => s(
            "summed-area table: the exact mean of the texels in the footprint's bounding box, four table reads whatever its size",
            "求和面积表：覆盖区域包围盒内纹素的精确平均值，无论大小只需读表四次",
        ),
        Remark::Ewa => s(
            "EWA: the texels inside the footprint's ellipse, weighted by a Gaussian, on the level where the ellipse's minor axis is about a texel",
            "EWA：覆盖区域椭圆内的纹素按高斯权重平均，在椭圆短轴约为一个纹素的层级上进行",
        ),
        Remark::Trilinear { max } => match l {
            Lang::En => format!("trilinear: levels k and k+1 blended by t (λ at most {max})"),
            Lang::Zh => format!("三线性：按 t 混合第 k 层与第 k+1 层（λ 最多为 {max}）"),
        },
        Remark::Texels {
            level,
            width,
            height,
        } => match l {
            Lang::En => format!("the four texels read, of level {level} ({width}×{height})"),
            Lang::Zh => format!("读取的四个纹素，第 {level} 层（{width}×{height}）"),
        },
        Remark::NearestTexel => s(
            "nearest: the texel containing the point",
            "最近邻：包含该点的纹素",
        ),
        Remark::TapsMean => s("the mean of the taps", "各样本的平均"),
        Remark::Gouraud => s(
            "Gouraud: lit at each vertex, the colours interpolated",
            "Gouraud：在每个顶点计算光照，再对颜色插值",
        ),
        Remark::Flat => s(
            "flat: lit once per face, at its provoking (last) vertex, with the face normal",
            "平面着色：每个面在其引发顶点（最后一个顶点）处用面法线计算一次光照",
        ),
        Remark::Textured => s(
            "textured: the texel T multiplies the ambient and diffuse terms",
            "有纹理：纹素 T 乘以环境光项和漫反射项",
        ),
        Remark::Bump => s(
            "bump or normal mapping tilts the normal",
            "凹凸映射或法线映射使法线倾斜",
        ),
        Remark::Mirror => s(
            "a mirror: it reflects its environment along r and keeps 1 − k of its own light",
            "镜面：沿 r 反射环境，自身光照保留 1 − k",
        ),
        Remark::Material => s(
            "the material: k_a, k_d, k_s and the shininess p",
            "材质：k_a、k_d、k_s 与高光指数 p",
        ),
        Remark::Ambient => s("ambient term", "环境光项"),
        Remark::Light { index, kind } => {
            let kind = match (l, kind.as_str()) {
                (Lang::En, k) => k.to_owned(),
                (Lang::Zh, "directional") => "平行光".to_owned(),
                (Lang::Zh, "spot") => "聚光灯".to_owned(),
                (Lang::Zh, _) => "点光源".to_owned(),
            };
            match l {
                Lang::En => format!("light {index} ({kind}): the unit vector towards it"),
                Lang::Zh => format!("光源 {index}（{kind}）：指向它的单位向量"),
            }
        }
        Remark::Attenuation => s("distance attenuation", "距离衰减"),
        Remark::SpotCone => s("the spotlight's cone, half-angle θ", "聚光灯的光锥，半角 θ"),
        Remark::Diffuse => s("diffuse term (Lambert)", "漫反射项（Lambert）"),
        Remark::HalfVector => s("the half vector between l and v", "l 与 v 之间的半程向量"),
        Remark::MirrorVector => s("the mirror direction of l", "l 的镜面反射方向"),
        Remark::Specular => s(
            "specular term; max(·, 0) before the power, and 0 where n·l ≤ 0",
            "镜面反射项；先取 max(·, 0) 再求幂，n·l ≤ 0 时为 0",
        ),
        Remark::Sum => s("the sum of the terms", "各项之和"),
        Remark::Samples { covered, samples } => match l {
            Lang::En => format!(
                "the mean of the pixel's {samples} samples; {covered} belong to this triangle's primitive, the others keep their own colour or the background"
            ),
            Lang::Zh => format!(
                "像素 {samples} 个采样点的平均；其中 {covered} 个属于该图元，其余保留各自的颜色或背景色"
            ),
        },
        Remark::Clamped => s(
            "the colour buffer keeps each sample's colour clamped to [0, 1]",
            "颜色缓冲把每个采样点的颜色截断到 [0, 1] 再保存",
        ),
        Remark::Bytes => s("the 8-bit colour in the image", "图像中的 8 位颜色"),
    }
}

/// The legend of the lighting vectors drawn at an inspected pixel (app and exported pictures).
#[must_use]
pub fn lighting_legend(lang: Lang) -> [&'static str; 2] {
    [
        lang.tr(
            "n normal · l to the light · v to the eye",
            "n 法线 · l 指向光源 · v 指向视点",
        ),
        "h = (l + v)/|l + v| · r = 2(n·l)n − l",
    ]
}
