//! Whether the window is small: a phone, a tablet in portrait, a phone held sideways. The app
//! then lays itself out as `compact.rs` says.

use egui::Context;

/// Whether the window is too small for the desktop's bar and card: narrower than 700 points
/// (a phone or a tablet in portrait) or lower than 480 (a phone in landscape), or touched by
/// a finger and narrower than 1100 (a tablet, whose finger-sized controls do not fit the
/// desktop's bar in one row; it gets the phone's layout and its swipe).
#[must_use]
pub fn is_compact(ctx: &Context) -> bool {
    let r = ctx.content_rect();
    is_narrow(ctx) || r.height() < 480.0 || super::style::is_touch(ctx) && r.width() < 1100.0
}

/// Whether the window is narrower than 700 points: a phone held upright (a tablet in portrait
/// is wider).
#[must_use]
pub fn is_narrow(ctx: &Context) -> bool {
    ctx.content_rect().width() < 700.0
}
