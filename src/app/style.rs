//! Fonts and styles: the embedded Chinese font, and the normal and classroom styles.

use egui::{FontData, FontFamily};

/// The Chinese font, embedded so that Chinese renders on any machine.
pub const CJK_FONT: &[u8] = include_bytes!("../../assets/fonts/NotoSansSC-subset.otf");

/// Adds the Chinese font after egui's own fonts (which have no CJK glyphs), and egui's Hack as
/// the last fallback of the proportional family: it has symbols the others lack (⁻ ⌊ ⌋).
pub fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        "noto-sans-sc".to_owned(),
        std::sync::Arc::new(FontData::from_static(CJK_FONT)),
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
    apply_style(ctx, false);
}

/// Text sizes and contrast: normal, or classroom (large type, high contrast, for a projector).
pub fn apply_style(ctx: &egui::Context, classroom: bool) {
    use egui::{FontId, TextStyle};
    let scale = if classroom { 1.35 } else { 1.0 };
    ctx.set_theme(egui::Theme::Dark);
    ctx.global_style_mut(|style| {
        style.text_styles = [
            (TextStyle::Heading, FontId::proportional(22.0 * scale)),
            (TextStyle::Body, FontId::proportional(15.0 * scale)),
            (TextStyle::Button, FontId::proportional(15.0 * scale)),
            (TextStyle::Small, FontId::proportional(12.0 * scale)),
            (TextStyle::Monospace, FontId::monospace(13.5 * scale)),
        ]
        .into();
        style.visuals = egui::Visuals::dark();
        if classroom {
            style.visuals.override_text_color = Some(egui::Color32::WHITE);
            style.visuals.panel_fill = egui::Color32::BLACK;
            style.visuals.window_fill = egui::Color32::BLACK;
            style.visuals.widgets.noninteractive.bg_stroke.width = 1.5;
            style.visuals.selection.bg_fill = egui::Color32::from_rgb(0, 90, 200);
        }
    });
}
