//! The product's vocabulary: the words the app, the lessons and the exports share — the stages
//! and spaces of the pipeline, the comparisons, the buffers' names, the interface's languages
//! (the message catalogs of `locales/`), the matrices' formulas in Chinese, how numbers are
//! written, and the lessons' words on a touch screen. It sits below all three and uses
//! only the core: `lesson`, `export` and `app` import it; it imports none of them.

pub mod alt_text;
mod buffers;
mod comparison;
pub mod compile;
mod explain;
mod formulas;
pub mod glsl;
pub mod lang;
pub mod line_breaks;
mod names;
pub mod notation;
mod numbers;
pub mod profile;
pub mod run;
mod stage;
pub mod touch;
pub mod trace;

pub use buffers::{buffer_name, gain_note};
pub use comparison::{Comparison, variant_label};
pub use explain::{lighting_legend, remark, section_name};
pub use lang::{Lang, PSEUDO, Text};
pub use names::{light_name, part_name, shadow_of, upper_first};
pub use numbers::{num, short, vec3, vec4};
pub use stage::{Space, Stage};

/// The Chinese font (with Latin, Greek and the math symbols), embedded so that Chinese renders
/// on any machine: in the app and in exported pictures and slides. It is kept compressed with
/// brotli (2.1 MB in the binary and the page's download instead of 3.0) and unpacked on first
/// use, in a few milliseconds.
#[must_use]
pub fn cjk_font() -> &'static [u8] {
    static PACKED: &[u8] = include_bytes!("../../assets/fonts/NotoSansSC-subset.otf.br");
    static FONT: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    FONT.get_or_init(|| {
        let mut font = Vec::with_capacity(3 << 20);
        // Embedded and unpacked by a test: an error here is a broken build.
        let unpacked = std::io::Read::read_to_end(
            &mut brotli_decompressor::Decompressor::new(PACKED, 1 << 16),
            &mut font,
        );
        assert!(unpacked.is_ok(), "the embedded font unpacks: {unpacked:?}");
        font
    })
}
