//! Fonts and styles: the embedded Chinese font, and the normal and classroom styles.

use egui::{FontData, FontFamily};

pub use crate::vocabulary::cjk_font;

/// Adds the Chinese font after egui's own fonts (which have no CJK glyphs), and egui's Hack as
/// the last fallback of the proportional family: it has symbols the others lack (⁻ ⌊ ⌋).
pub fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        "noto-sans-sc".to_owned(),
        std::sync::Arc::new(FontData::from_static(cjk_font())),
    );
    for (family, extra) in [
        (FontFamily::Proportional, &["noto-sans-sc", "Hack"][..]),
        (FontFamily::Monospace, &["noto-sans-sc"][..]),
    ] {
        let list = fonts.families.entry(family).or_default();
        list.extend(extra.iter().map(|s| (*s).to_owned()));
    }
    ctx.set_fonts(fonts);
}

/// Prepares an egui context for the app: the Chinese font and the normal style.
pub fn setup_context(ctx: &egui::Context) {
    install_fonts(ctx);
    apply_style(ctx, false, false);
}

/// The text sizes at `scale` (1: normal, 1.6: classroom).
#[must_use]
pub fn text_styles(scale: f32) -> std::collections::BTreeMap<egui::TextStyle, egui::FontId> {
    use egui::{FontId, TextStyle};
    [
        (TextStyle::Heading, FontId::proportional(21.0 * scale)),
        (TextStyle::Body, FontId::proportional(15.0 * scale)),
        (TextStyle::Button, FontId::proportional(15.0 * scale)),
        (TextStyle::Small, FontId::proportional(12.5 * scale)),
        (TextStyle::Monospace, FontId::monospace(14.0 * scale)),
    ]
    .into()
}

/// The window's chrome keeps its normal size in classroom mode: the type grows where students
/// read (the picture, the narration, the inspector), and the picture never shrinks.
pub fn chrome_style(ui: &mut egui::Ui) {
    ui.style_mut().text_styles = text_styles(1.0);
}

/// The least side of a control one clicks or taps (points, CSS pixels in a page): 24 with a
/// mouse (WCAG 2.2's target size, 2.5.8), 44 under a finger (a fingertip's width, as the
/// platforms' guidelines ask).
#[must_use]
pub fn target_size(touch: bool) -> f32 {
    if touch { 44.0 } else { 24.0 }
}

/// Whether the touch screen's style is in force ([`apply_style`] with `touch`): its controls
/// are a finger's size.
#[must_use]
pub fn is_touch(ctx: &egui::Context) -> bool {
    ctx.global_style().spacing.interact_size.y >= target_size(true)
}

/// A button for one glyph (◀, ×, ?, —), at least as wide as it is high: its own width would be
/// a sliver of the [`target_size`]. `selected` makes it a toggle's button (shown pressed).
pub fn glyph_button<'a>(ui: &egui::Ui, glyph: &'a str, selected: Option<bool>) -> egui::Button<'a> {
    let button = match selected {
        Some(on) => egui::Button::selectable(on, glyph),
        None => egui::Button::new(glyph),
    };
    button.min_size(egui::Vec2::splat(ui.spacing().interact_size.y))
}

/// Text sizes and contrast: normal, or classroom (large type and high contrast for a projector:
/// body text 24 points, as slides use, white on black). Secondary text keeps a contrast of at
/// least 7:1 against the panels (grey 190 on grey 27 in the dark theme). Every control is at
/// least [`target_size`] high, and under a finger (`touch`) wider too, with panel edges that
/// are easier to take hold of.
pub fn apply_style(ctx: &egui::Context, classroom: bool, touch: bool) {
    let scale = if classroom { 1.6 } else { 1.0 };
    ctx.set_theme(egui::Theme::Dark);
    ctx.global_style_mut(|style| {
        style.text_styles = text_styles(scale);
        let target = target_size(touch);
        // A drag value is as wide as it is high at least; a panel's edge is taken hold of a
        // target's width across.
        style.spacing.interact_size = egui::vec2(target.max(40.0), target);
        style.interaction.resize_grab_radius_side = target / 2.0;
        if touch {
            // A short word's button ("flat", "Fit") as wide as a finger; one glyph's is
            // `glyph_button`.
            style.spacing.button_padding.x = 11.0;
        }
        style.visuals = egui::Visuals::dark();
        style.visuals.weak_text_color = Some(egui::Color32::from_gray(190));
        // Words on a raised box (grey 40 or 50: a card, a table's row) keep 4.5:1: egui's grey
        // 140 was 4.4:1 on grey 40, 3.8:1 on grey 50.
        style.visuals.widgets.noninteractive.fg_stroke.color = egui::Color32::from_gray(210);
        style.spacing.slider_width = 220.0 * scale;
        // The focus is seen (WCAG 2.4.7): egui draws a focused widget as an active one, whose
        // 1-point white outline is easy to miss on a grey button; 2 points in the focus colour,
        // the ring a focused picture has too (`views::picture_keys`).
        let focus = style.visuals.selection.stroke.color;
        style.visuals.widgets.active.bg_stroke = egui::Stroke::new(2.0, focus);
        if classroom {
            style.visuals.override_text_color = Some(egui::Color32::WHITE);
            style.visuals.weak_text_color = Some(egui::Color32::from_gray(225));
            style.visuals.panel_fill = egui::Color32::BLACK;
            style.visuals.window_fill = egui::Color32::BLACK;
            style.visuals.selection.bg_fill = egui::Color32::from_rgb(0, 90, 200);
        }
    });
}
