//! The names of the buffers a capture can show, in both languages (the core's
//! `BufferKind::name` is the file name; `BufferKind::mapping` says how values become colours).

use pipeline::buffers::BufferKind;

use super::Lang;

/// The name of a buffer, as the buffer menu and the handouts show it.
pub fn buffer_name(kind: BufferKind, l: Lang) -> &'static str {
    match kind {
        BufferKind::Color => l.tr("Colour", "颜色"),
        BufferKind::Depth => l.tr("Depth", "深度"),
        BufferKind::Coverage => l.tr("Coverage", "覆盖率"),
        BufferKind::PrimitiveId => l.tr("Primitive id", "图元编号"),
        BufferKind::BaryPerspective => {
            l.tr("Barycentrics (perspective-correct)", "重心坐标（透视校正）")
        }
        BufferKind::BaryAffine => l.tr("Barycentrics (affine)", "重心坐标（仿射）"),
        BufferKind::Ambient => l.tr("Ambient term", "环境光项"),
        BufferKind::Diffuse => l.tr("Diffuse term", "漫反射项"),
        BufferKind::Specular => l.tr("Specular term", "镜面反射项"),
        BufferKind::Normal => l.tr("Normal", "法向量"),
        BufferKind::NDotL => "n·l",
        BufferKind::NDotH => "n·h",
        BufferKind::Uv => l.tr("Texture coordinates (u, v)", "纹理坐标 (u, v)"),
        BufferKind::MipLevel => l.tr("Mip level", "Mipmap 层级"),
        BufferKind::Texel => l.tr("Texel colour", "纹素颜色"),
        BufferKind::Footprint => l.tr("Texture footprint", "纹理覆盖区域（足迹）"),
        BufferKind::Reflected => l.tr("Reflected (environment)", "反射项（环境映射（反射映射））"),
    }
}

/// What a picture of a dim lighting term drawn `gain` times brighter says about itself (see
/// `FrameCapture::term_gain`); `None` when it is drawn as it is.
#[must_use]
pub fn gain_note(kind: BufferKind, gain: f32, l: Lang) -> Option<String> {
    if gain <= 1.0 {
        return None;
    }
    let name = buffer_name(kind, l);
    Some(match l {
        Lang::En => format!("{name} shown ×{gain}: {gain} times brighter than its values"),
        Lang::Zh => format!("{name}放大 ×{gain} 显示：亮度是其数值的 {gain} 倍"),
    })
}
