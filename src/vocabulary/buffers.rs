//! The names of the buffers a capture can show, in both languages (the core's
//! `BufferKind::name` is the file name; `BufferKind::mapping` says how values become colours).

use pipeline::buffers::BufferKind;

use super::Lang;

/// The name of a buffer, as the buffer menu and the handouts show it.
pub fn buffer_name(kind: BufferKind, l: Lang) -> &'static str {
    match kind {
        BufferKind::Color => l.t("buffers-colour"),
        BufferKind::Depth => l.t("buffers-depth"),
        BufferKind::Coverage => l.t("buffers-coverage"),
        BufferKind::PrimitiveId => l.t("buffers-primitive-id"),
        BufferKind::BaryPerspective => l.t("buffers-barycentrics-perspective-correct"),
        BufferKind::BaryAffine => l.t("buffers-barycentrics-affine"),
        BufferKind::Ambient => l.t("buffers-ambient-term"),
        BufferKind::Diffuse => l.t("buffers-diffuse-term"),
        BufferKind::Specular => l.t("buffers-specular-term"),
        BufferKind::Normal => l.t("buffers-normal"),
        BufferKind::NDotL => "n·l",
        BufferKind::NDotH => "n·h",
        BufferKind::Uv => l.t("buffers-texture-coordinates-u-v"),
        BufferKind::MipLevel => l.t("buffers-mip-level"),
        BufferKind::Texel => l.t("buffers-texel-colour"),
        BufferKind::Footprint => l.t("buffers-texture-footprint"),
        BufferKind::Reflected => l.t("buffers-reflected-environment"),
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
    Some(l.t_with(
        "buffers-shown-brighter",
        &[("name", &name), ("gain", &gain)],
    ))
}
