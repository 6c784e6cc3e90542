//! The intensity profile along a line (the Mach band comparison): the curves the app plots and
//! the handout charts, with the same colours and axis labels.

use pipeline::capture::FrameCapture;

use super::Lang;

/// The colour of the k-th curve (flat, Gouraud, Phong… in the comparison's order).
pub const CURVE_COLORS: [[u8; 3]; 4] = [
    [255, 170, 60],
    [90, 200, 255],
    [150, 255, 120],
    [230, 120, 255],
];

/// The horizontal axis.
#[must_use]
pub fn x_label(lang: Lang) -> &'static str {
    lang.t("profile-position-along-the-yellow-line")
}

/// The vertical axis.
#[must_use]
pub fn y_label(lang: Lang) -> &'static str {
    lang.t("profile-intensity-rec-709-luminance")
}

/// The points of one curve: (distance along `line` in pixels, luminance), `line` being
/// `[x0, y0, x1, y1]` in image pixels, y down.
#[must_use]
pub fn points(capture: &FrameCapture, line: [f32; 4]) -> Vec<[f64; 2]> {
    let length = (line[2] - line[0]).hypot(line[3] - line[1]);
    capture
        .profile([line[0], line[1]], [line[2], line[3]])
        .iter()
        .map(|s| [f64::from(s.t * length), f64::from(s.intensity)])
        .collect()
}
