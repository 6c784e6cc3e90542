//! The Chinese font a handout embeds, cut down to the characters the handout holds: the app's
//! own font ([`crate::vocabulary::cjk_font`], about 3 MB with every GB2312 character) is a
//! fallback for a reader with no Chinese font, and a handout uses a few hundred of its glyphs.
//! The cut is a complete OpenType font with a Unicode `cmap` (what a browser needs to use it as a
//! web font), made by `allsorts`' subsetter.

use allsorts::binary::read::ReadScope;
use allsorts::font::{Font, MatchingPresentation};
use allsorts::font_data::FontData;
use allsorts::subset::{CmapTarget, SubsetProfile, subset};

/// The embedded Chinese font with only the glyphs of `text`'s characters and of printable ASCII
/// (and `.notdef`, glyph 0, which every font must keep).
///
/// # Errors
/// The font could not be read or cut (the caller then embeds the whole font).
pub fn cjk_subset(text: &str) -> Result<Vec<u8>, String> {
    let font = crate::vocabulary::cjk_font();
    let data = ReadScope::new(font)
        .read::<FontData<'_>>()
        .map_err(|e| e.to_string())?;
    let provider = data.table_provider(0).map_err(|e| e.to_string())?;
    let mut face = Font::new(provider).map_err(|e| e.to_string())?;
    let mut chars: Vec<char> = text.chars().chain(' '..='~').collect();
    chars.sort_unstable();
    chars.dedup();
    let mut glyphs = vec![0_u16];
    for c in chars {
        let (glyph, _) = face.lookup_glyph_index(c, MatchingPresentation::NotRequired, None);
        if glyph != 0 && !glyphs.contains(&glyph) {
            glyphs.push(glyph);
        }
    }
    subset(
        &face.font_table_provider,
        &glyphs,
        &SubsetProfile::Minimal,
        CmapTarget::Unicode,
    )
    .map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cut keeps exactly the characters asked for: each maps to a glyph in the new font's
    /// own `cmap`, a character not asked for does not, and the font is a small part of the whole.
    #[test]
    fn the_cut_font_maps_the_text_s_characters_and_no_others() {
        let cut = cjk_subset("着色频率：平面着色").expect("cuts");
        assert!(
            cut.len() * 20 < crate::vocabulary::cjk_font().len(),
            "{} bytes",
            cut.len()
        );
        let data = ReadScope::new(&cut).read::<FontData<'_>>().expect("reads");
        let mut face = Font::new(data.table_provider(0).expect("a face")).expect("a font");
        let mut glyph = |c| {
            face.lookup_glyph_index(c, MatchingPresentation::NotRequired, None)
                .0
        };
        for c in "着色频率：平面A~".chars() {
            assert_ne!(glyph(c), 0, "{c} is kept");
        }
        for c in "光照é".chars() {
            assert_eq!(glyph(c), 0, "{c} is not asked for");
        }
    }
}
