//! A row of the keys GLSL is written with that a phone's keyboard keeps on its second or third
//! page (`;` `{` `}` `(` `)` `.` `=` `*`), under the code on a touch screen's Code tab, which
//! sits just above the keyboard. A key types into the source where its cursor is, replacing
//! what is selected, and the source keeps the keyboard: the tap on the key does not take the
//! focus away (and with it the phone's keyboard) as a tap elsewhere would.

use egui::text::{CCursor, CCursorRange};
use egui::{Id, Ui};

/// The keys, in the order the row shows them.
pub const KEYS: [&str; 8] = [";", "{", "}", "(", ")", ".", "=", "*"];

/// The row, the keys as wide as the row allows: a finger's size at least on the narrowest
/// phone, 360 points, where the row has no margins and no gaps but a hairline; narrower than
/// eight such keys, it wraps into a second row. Returns the key tapped this frame.
pub fn row(ui: &mut Ui, lang: crate::vocabulary::Lang) -> Option<&'static str> {
    let mut tapped = None;
    let gap = 1.0;
    ui.spacing_mut().item_spacing = egui::vec2(gap, gap);
    let least = crate::app::style::target_size(true);
    let fit =
        (((ui.available_width() + gap) / (least + gap)).floor() as usize).clamp(1, KEYS.len());
    let per_row = KEYS.len().div_ceil(KEYS.len().div_ceil(fit));
    let width = ((ui.available_width() - gap * (per_row - 1) as f32) / per_row as f32).floor();
    let size = egui::vec2(width, ui.spacing().interact_size.y);
    for keys in KEYS.chunks(per_row) {
        ui.horizontal(|ui| {
            for key in keys {
                let button = egui::Button::new(egui::RichText::new(*key).monospace().strong());
                let typed = ui
                    .add_sized(size, button)
                    .on_hover_text(lang.t_with("code-keys-types", &[("key", key)]));
                if typed.clicked() {
                    tapped = Some(*key);
                }
            }
        });
    }
    tapped
}

/// Types `text` into `source`, the text of the text edit `id`, where its cursor is (over its
/// selection), the cursor after it, and gives the text edit the keyboard. Returns whether it
/// typed: a source that was never given the cursor takes nothing (where would it go?).
pub(super) fn type_into(ctx: &egui::Context, id: Id, source: &mut String, text: &str) -> bool {
    let Some(mut state) = egui::TextEdit::load_state(ctx, id) else {
        return false;
    };
    let Some(range) = state.cursor.char_range() else {
        return false;
    };
    let [from, to] = range.sorted_cursors().map(|c| c.index.0);
    let byte = |chars: usize| {
        source
            .char_indices()
            .nth(chars)
            .map_or(source.len(), |(b, _)| b)
    };
    let (start, end) = (byte(from), byte(to));
    source.replace_range(start..end, text);
    let after = CCursor::new(from + text.chars().count());
    state.cursor.set_char_range(Some(CCursorRange::one(after)));
    egui::TextEdit::store_state(ctx, id, state);
    // Asked only where it lost it: asking again would end an input method's composition.
    if !ctx.memory(|m| m.has_focus(id)) {
        ctx.memory_mut(|m| m.request_focus(id));
    }
    true
}

#[cfg(test)]
mod tests {
    use super::type_into;

    /// A key goes where the cursor is, over the selection, the cursor then after it; the
    /// indices count characters, not bytes (the Chinese comment before the cursor).
    #[test]
    fn a_key_types_at_the_cursor_over_the_selection() {
        let ctx = egui::Context::default();
        let id = egui::Id::unique("glsl keys test");
        let mut source = "// 注释\nx = 1 2".to_owned();
        assert!(!type_into(&ctx, id, &mut source, ";"), "no cursor yet");
        let mut state = egui::text_edit::TextEditState::default();
        // Between "1" and " 2": character 11 ("// 注释\n" is 6 characters, "x = 1" 5 more).
        state
            .cursor
            .set_char_range(Some(egui::text::CCursorRange::one(
                egui::text::CCursor::new(11),
            )));
        egui::TextEdit::store_state(&ctx, id, state);
        assert!(type_into(&ctx, id, &mut source, ";"));
        assert_eq!(source, "// 注释\nx = 1; 2");
        let state = egui::TextEdit::load_state(&ctx, id).expect("kept");
        let at = state.cursor.char_range().expect("a cursor").primary.index.0;
        assert_eq!(at, 12, "after the key");
        // " 2" selected (characters 12 to 14) becomes "*".
        let mut state = state;
        state
            .cursor
            .set_char_range(Some(egui::text::CCursorRange::two(
                egui::text::CCursor::new(14),
                egui::text::CCursor::new(12),
            )));
        egui::TextEdit::store_state(&ctx, id, state);
        assert!(type_into(&ctx, id, &mut source, "*"));
        assert_eq!(source, "// 注释\nx = 1;*");
        assert!(
            ctx.memory(|m| m.has_focus(id)),
            "the source has the keyboard"
        );
    }
}
