//! GLSL shown in the interface's language: the code stays GLSL, its `//` comments are put in
//! the reader's language — a lesson's own from its file (`[comments.zh]`), pipelens' shipped
//! shaders' from this module's table. A comment with no translation stays as written.

use crate::vocabulary::Written;
use std::collections::BTreeMap;

use pipeline::shader::lexeme::{Kind, lex};

use super::Lang;

/// `source` with its comments in `lang`: a comment's words found in the `lesson`'s table or in
/// pipelens' own are replaced (the code, the lines and each comment's indent unchanged).
#[must_use]
pub fn localize(source: &str, lang: Lang, lesson: &BTreeMap<String, String>) -> String {
    match lang.written() {
        Written::English => source.to_owned(),
        Written::Chinese => pipeline::shader::lexeme::map_comments(source, |words| {
            chinese(words, lesson).map(str::to_owned)
        }),
    }
}

/// The Chinese of a comment's `words`, from the lesson's table or pipelens' own.
fn chinese<'a>(words: &str, lesson: &'a BTreeMap<String, String>) -> Option<&'a str> {
    lesson.get(words).map(String::as_str).or_else(|| {
        SHIPPED
            .iter()
            .find(|(en, _)| *en == words)
            .map(|(_, zh)| *zh)
    })
}

/// The words of `source`'s `//` comments that have no Chinese (neither in the `lesson`'s table
/// nor in pipelens' own) and are not GLSL themselves (a declaration quoted in a comment).
#[must_use]
pub fn untranslated(source: &str, lesson: &BTreeMap<String, String>) -> Vec<String> {
    lex(source)
        .into_iter()
        .filter(|l| l.kind == Kind::Comment)
        .filter_map(|l| source[l.span].strip_prefix("//").map(str::trim))
        .filter(|words| !words.is_empty() && !is_code(words))
        .filter(|words| chinese(words, lesson).is_none())
        .map(str::to_owned)
        .collect()
}

/// Whether a comment's words are GLSL quoted as it is (`struct Light { … };`,
/// `const int LIGHT_POINT = 1;`): they read the same in every language.
fn is_code(words: &str) -> bool {
    let first = words.split_whitespace().next().unwrap_or_default();
    words.ends_with(';')
        && matches!(
            first,
            "struct" | "const" | "uniform" | "float" | "int" | "vec2" | "vec3" | "vec4"
        )
}

/// The Chinese of the comments of pipelens' shipped shaders (`shader/builtin/`), line by line:
/// a sentence that runs over several comment lines is split over as many lines here.
const SHIPPED: &[(&str, &str)] = &[
    (
        "pipelens' per-pixel (Phong-frequency) lighting with the Blinn-Phong model, as a shader:",
        "pipelens 的逐像素（Phong 频率）光照，用 Blinn-Phong 模型，写成着色器：",
    ),
    (
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)",
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)",
    ),
    (
        "with h = normalize(l + v), f_att = 1/(a + b·d + c·d²), f_spot = (cos φ)^e inside the cone.",
        "其中 h = normalize(l + v)，f_att = 1/(a + b·d + c·d²)，在光锥内 f_spot = (cos φ)^e。",
    ),
    (
        "pipelens declares these before your code (a program of your own declares them itself):",
        "pipelens 在你的代码之前声明了这些（你自己的程序要自己声明）：",
    ),
    ("the surface colour", "表面颜色"),
    (
        "pipelens' flat shading, the fragment half: one normal per face and one lighting per face.",
        "pipelens 的平面着色，片元部分：每个面一个法向量，每个面一次光照。",
    ),
    (
        "The face normal is the cross product of two directions in the face's plane: as x and y move",
        "面法向量是面所在平面内两个方向的叉积：当 x 和 y",
    ),
    (
        "on the screen the world position p moves within the face, so ∂p/∂x and ∂p/∂y are two such",
        "在屏幕上移动时，世界坐标 p 在面内移动，所以 ∂p/∂x 和 ∂p/∂y 就是两个这样的",
    ),
    (
        "directions and n_face = ±normalize(dFdx(p) × dFdy(p)), + for a front face. (Only the",
        "方向，n_face = ±normalize(dFdx(p) × dFdy(p))，正面取 +。（一般只有",
    ),
    (
        "direction holds in general: (p1 − p0)×(p2 − p0) = 2·area·(∂p/∂x × ∂p/∂y) holds for an affine",
        "方向成立：(p1 − p0)×(p2 − p0) = 2·面积·(∂p/∂x × ∂p/∂y) 只对仿射",
    ),
    (
        "mapping alone, not under perspective.)",
        "映射成立，透视下不成立。）",
    ),
    (
        "The Blinn-Phong lighting is that of gouraud.vert, at the provoking vertex f_pos: every",
        "Blinn-Phong 光照与 gouraud.vert 的相同，在引发顶点 f_pos 处计算：",
    ),
    (
        "fragment of the face computes the same colour. A textured surface is lit white (c = 1) and",
        "面上每个片元算出同一个颜色。有纹理的表面按白色照亮（c = 1），",
    ),
    (
        "its texel modulates ambient and diffuse, as with Gouraud shading.",
        "纹素再调制环境光和漫反射，与 Gouraud 着色相同。",
    ),
    (
        "pipelens' flat shading, the vertex half: the vertex stage of pipelens.vert, and the values a",
        "pipelens 的平面着色，顶点部分：pipelens.vert 的顶点阶段，以及一个面",
    ),
    (
        "face is lit with. OpenGL gives a `flat` output the provoking (last) vertex's value across the",
        "光照所用的值。OpenGL 让 `flat` 输出在整个三角形上取引发顶点（最后一个顶点）的值：",
    ),
    (
        "whole triangle: the face is lit at that vertex, with its colour.",
        "面在这个顶点处、用它的颜色照亮。",
    ),
    (
        "displacement mapping's height map (none: black)",
        "位移贴图的高度图（没有时为黑色）",
    ),
    ("its k (0 without one)", "它的 k（没有位移贴图时为 0）"),
    (
        "world position, interpolated: its derivatives give the face normal",
        "插值后的世界坐标：它的导数给出面法向量",
    ),
    (
        "the provoking vertex's world position",
        "引发顶点的世界坐标",
    ),
    ("and its colour", "以及它的颜色"),
    (
        "Displacement mapping moves the vertex along its normal: p' = p + k·h(u, v)·n, h the",
        "位移贴图沿法向量移动顶点：p' = p + k·h(u, v)·n，h 为",
    ),
    (
        "height map's luminance (bilinear, level 0).",
        "高度图的亮度（双线性，第 0 层）。",
    ),
    (
        "pipelens' Gouraud shading, the fragment half: the lighting of the three vertices arrives",
        "pipelens 的 Gouraud 着色，片元部分：三个顶点的光照经插值",
    ),
    (
        "interpolated; a texel modulates the ambient and diffuse part (OpenGL's GL_MODULATE), the",
        "到达这里；纹素调制环境光和漫反射部分（OpenGL 的 GL_MODULATE），",
    ),
    ("specular part is added on top.", "高光部分再加在上面。"),
    (
        "ambient + diffuse, lit with a white surface when textured",
        "环境光 + 漫反射，有纹理时按白色表面计算",
    ),
    (
        "pipelens' Gouraud shading, the vertex half: the Blinn-Phong lighting of each vertex, once per",
        "pipelens 的 Gouraud 着色，顶点部分：每个顶点的 Blinn-Phong 光照，每个顶点",
    ),
    (
        "vertex, with its own normal,",
        "计算一次，用它自己的法向量，",
    ),
    (
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p),",
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p)，",
    ),
    (
        "sent to the fragment stage to be interpolated across the triangle (gouraud.frag). A textured",
        "送到片元阶段，在三角形上插值（gouraud.frag）。有纹理的",
    ),
    (
        "surface is lit white here (c = 1); its texel modulates ambient and diffuse per pixel.",
        "表面在这里按白色照亮（c = 1）；纹素在每个像素上调制环境光和漫反射。",
    ),
    ("ambient + diffuse", "环境光 + 漫反射"),
    ("specular", "高光"),
    (
        "pipelens' per-pixel Blinn-Phong lighting (blinn_phong.frag) with a bump or normal map: the",
        "pipelens 带凹凸贴图或法线贴图的逐像素 Blinn-Phong 光照（blinn_phong.frag）：",
    ),
    (
        "interpolated normal n is tilted in the tangent frame before lighting.",
        "插值得到的法向量 n 先在切线坐标系中倾斜，再计算光照。",
    ),
    (
        "Tangent frame: T = ∂p/∂u, B = ∂p/∂v. The screen derivatives of p and uv obey",
        "切线坐标系：T = ∂p/∂u，B = ∂p/∂v。p 和 uv 的屏幕导数满足",
    ),
    (
        "dFdx(p) = T·dFdx(u) + B·dFdx(v),  dFdy(p) = T·dFdy(u) + B·dFdy(v),",
        "dFdx(p) = T·dFdx(u) + B·dFdx(v)，dFdy(p) = T·dFdy(u) + B·dFdy(v)，",
    ),
    (
        "two equations solved for T and B (the same T, B as from the triangle's edges).",
        "解这两个方程得到 T 和 B（与由三角形的边求出的 T、B 相同）。",
    ),
    (
        "T' = normalize(T − n(n·T)), B' = ±n×T' (the sign of B), n' = normalize(T'·x + B'·y + n·z):",
        "T' = normalize(T − n(n·T))，B' = ±n×T'（B 的符号），n' = normalize(T'·x + B'·y + n·z)：",
    ),
    (
        "bump map (GAMES101): (x, y, z) = (−dU, −dV, 1), dU = k_h·k_n·(h(u + 1/w, v) − h(u, v)),",
        "凹凸贴图（GAMES101）：(x, y, z) = (−dU, −dV, 1)，dU = k_h·k_n·(h(u + 1/w, v) − h(u, v))，",
    ),
    (
        "dV = k_h·k_n·(h(u, v + 1/h) − h(u, v)), h the texel's luminance;",
        "dV = k_h·k_n·(h(u, v + 1/h) − h(u, v))，h 为纹素的亮度；",
    ),
    (
        "normal map:          (x, y, z) = 2·texel − 1.",
        "法线贴图：          (x, y, z) = 2·texel − 1。",
    ),
    (
        "0 none, 1 bump map, 2 normal map",
        "0 无，1 凹凸贴图，2 法线贴图",
    ),
    ("k_h·k_n", "k_h·k_n"),
    (
        "pipelens' per-pixel Blinn-Phong lighting of a mirror (environment mapping), as a shader:",
        "pipelens 对镜面物体的逐像素 Blinn-Phong 光照（环境映射），写成着色器：",
    ),
    (
        "L = (1 − k)·(ambient + diffuse) + specular + k·env(r),   r = 2(n·v)n − v = reflect(−v, n)",
        "L = (1 − k)·(环境光 + 漫反射) + 高光 + k·env(r)，   r = 2(n·v)n − v = reflect(−v, n)",
    ),
    (
        "with ambient = Σ k_a·c·I_a, diffuse = Σ f_att·f_spot·k_d·c·I·max(n·l, 0),",
        "其中 环境光 = Σ k_a·c·I_a，漫反射 = Σ f_att·f_spot·k_d·c·I·max(n·l, 0)，",
    ),
    (
        "specular = Σ f_att·f_spot·k_s·I·max(n·h, 0)^p, env(r) the cube map seen in direction r and",
        "高光 = Σ f_att·f_spot·k_s·I·max(n·h, 0)^p，env(r) 是沿方向 r 看到的立方体贴图，",
    ),
    (
        "k the reflectivity: a mirror shows k of what it reflects and keeps 1 − k of its own light.",
        "k 是反射率：镜面显示所反射内容的 k 倍，并保留自身光照的 1 − k 倍。",
    ),
    (
        "the surroundings: +x, −x, +y, −y, +z, −z",
        "周围环境：+x、−x、+y、−y、+z、−z 六个面",
    ),
    ("k", "k"),
    (
        "the mirror direction 2(n·v)n − v",
        "镜面反射方向 2(n·v)n − v",
    ),
    ("env(r)", "env(r)"),
    (
        "the height or normal map: bilinear, repeating, level 0",
        "高度图或法线贴图：双线性、重复、第 0 层",
    ),
    (
        "The luminance of the height map at uv: h(u, v).",
        "高度图在 uv 处的亮度：h(u, v)。",
    ),
    (
        "n tilted by the bump or normal map at uv.",
        "在 uv 处按凹凸贴图或法线贴图倾斜后的 n。",
    ),
    (
        "the uvs do not grow across this triangle: no frame",
        "uv 在这个三角形上不变化：没有切线坐标系",
    ),
    (
        "pipelens' per-pixel (Phong-frequency) lighting with Phong's reflection model, as a shader:",
        "pipelens 的逐像素（Phong 频率）光照，用 Phong 反射模型，写成着色器：",
    ),
    (
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(r·v, 0)^p)",
        "L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(r·v, 0)^p)",
    ),
    (
        "with r = reflect(−l, n) = 2(n·l)n − l, f_att = 1/(a + b·d + c·d²), f_spot = (cos φ)^e inside",
        "其中 r = reflect(−l, n) = 2(n·l)n − l，f_att = 1/(a + b·d + c·d²)，在光锥内",
    ),
    (
        "the cone. blinn_phong.frag differs in one line: n·h in place of r·v.",
        "f_spot = (cos φ)^e。blinn_phong.frag 只有一行不同：用 n·h 代替 r·v。",
    ),
    (
        "pipelens' own vertex stage as a shader: the position (displaced, with a displacement map)",
        "pipelens 自带的顶点阶段，写成着色器：位置（有位移贴图时先位移）",
    ),
    (
        "through M, V and P one matrix at a time (model → world → eye → clip, in the order the vertex",
        "依次经过 M、V、P 三个矩阵（模型 → 世界 → 眼睛 → 裁剪，与顶点表",
    ),
    (
        "table shows them), and what the fragment stage interpolates (world position, unit world normal, texture coordinates, colour).",
        "显示的顺序相同），以及片元阶段要插值的量（世界坐标、单位世界法向量、纹理坐标、颜色）。",
    ),
    ("world position M·p", "世界坐标 M·p"),
    (
        "world normal (M⁻¹)^T·n, normalized (interpolation shortens it again)",
        "世界法向量 (M⁻¹)^T·n，已归一化（插值会再次使它变短）",
    ),
    (
        "pipelens' unlit shading as a shader: the surface colour as it is, the texel where the object",
        "pipelens 的无光照着色，写成着色器：表面颜色原样输出，物体有纹理时",
    ),
    (
        "is textured, else the vertex colour (interpolated).",
        "用纹素，否则用（插值后的）顶点颜色。",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Every comment of every shipped shader has its Chinese, and the Chinese source is the
    /// same code with as many lines.
    #[test]
    fn the_shipped_shaders_read_in_chinese() {
        let none = BTreeMap::new();
        let shipped = pipeline::shader::SHIPPED_VERTEX
            .iter()
            .chain(&pipeline::shader::SHIPPED_FRAGMENT);
        for source in shipped {
            let missing = untranslated(source, &none);
            assert!(missing.is_empty(), "no Chinese for {missing:#?}");
            let zh = localize(source, Lang::ZH, &none);
            assert!(pipeline::shader::lexeme::same_code(source, &zh));
            assert_eq!(zh.lines().count(), source.lines().count());
            assert!(zh.contains('的'), "{zh}");
        }
    }
}
