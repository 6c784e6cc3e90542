//! Text in exported pictures and slides: the embedded CJK font (Latin, Greek and the math
//! symbols included), with egui's Hack for the few symbols it lacks (⁻ ⌊ ⌋), rasterized by
//! `ab_glyph` straight onto an RGBA image. Lines break where the app's cards break them
//! (`vocabulary::line_breaks`).

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};
use image::{Rgba, RgbaImage};

use crate::vocabulary::line_breaks;
use crate::vocabulary::notation::{self, Node};

/// The fonts, first the one tried first; parsed once. After the CJK font, the fallbacks the app's
/// egui has too (Hack, Ubuntu Light), so a handout has every glyph the app shows.
fn fonts() -> &'static [FontRef<'static>; 3] {
    static FONTS: std::sync::OnceLock<[FontRef<'static>; 3]> = std::sync::OnceLock::new();
    FONTS.get_or_init(|| {
        // All are fonts shipped in the binary; a test draws text with each.
        let parse =
            |bytes: &'static [u8]| FontRef::try_from_slice(bytes).expect("an embedded font");
        [
            parse(crate::vocabulary::cjk_font()),
            parse(egui_font("Hack")),
            parse(egui_font("Ubuntu-Light")),
        ]
    })
}

/// egui's own copy of its font `name`. Naming the bytes again (`epaint_default_fonts`'
/// constants) would put a second copy of each font into the binary: 0.7 MB of the page's
/// download.
fn egui_font(name: &str) -> &'static [u8] {
    static EGUI: std::sync::OnceLock<egui::FontDefinitions> = std::sync::OnceLock::new();
    EGUI.get_or_init(egui::FontDefinitions::default)
        .font_data
        .get(name)
        .map_or(&[], |d| (*d.font).as_ref())
}

/// A run of text of one colour, on the line or as a script.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// The text.
    pub text: String,
    /// Its colour.
    pub color: [u8; 3],
    /// On the baseline, or a subscript or superscript.
    pub script: Script,
}

/// Where a run sits: scripts are [`SCRIPT_SCALE`] of the type size, lowered or raised.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Script {
    /// On the baseline.
    #[default]
    Base,
    /// Below it.
    Sub,
    /// Above it.
    Sup,
}

/// A script's size relative to the text's.
const SCRIPT_SCALE: f32 = 0.7;

impl Script {
    /// The size and the baseline's shift (down positive) of this script in text of `size`.
    fn placed(self, size: f32) -> (f32, f32) {
        match self {
            Self::Base => (size, 0.0),
            Self::Sub => (size * SCRIPT_SCALE, size * 0.22),
            Self::Sup => (size * SCRIPT_SCALE, -size * 0.38),
        }
    }
}

/// The font that has `c`, and its glyph.
fn glyph_of(fonts: &[FontRef<'static>], c: char) -> (usize, ab_glyph::GlyphId) {
    glyph_in(fonts, [0, 1, 2], c)
}

/// The first font in `order` (indices into `fonts`) that has `c`, and its glyph; the first
/// font's `.notdef` when none has it.
fn glyph_in(fonts: &[FontRef<'static>], order: [usize; 3], c: char) -> (usize, ab_glyph::GlyphId) {
    order
        .iter()
        .map(|&i| (i, fonts[i].glyph_id(c)))
        .find(|(_, g)| g.0 != 0)
        .unwrap_or((order[0], fonts[order[0]].glyph_id(c)))
}

/// Whether the embedded fonts have a glyph for `c` (whitespace needs none).
#[must_use]
pub fn covers(c: char) -> bool {
    c.is_whitespace() || glyph_of(fonts(), c).1.0 != 0
}

/// The width of `text` at `size` pixels.
#[must_use]
pub fn width(text: &str, size: f32) -> f32 {
    width_in(text, size, [0, 1, 2])
}

/// The width of source code at `size` pixels, as [`draw_code`] draws it.
#[must_use]
pub fn code_width(text: &str, size: f32) -> f32 {
    width_in(text, size, [1, 0, 2])
}

/// The width of `text` at `size` pixels, each character from the first font of `order` that
/// has it.
fn width_in(text: &str, size: f32, order: [usize; 3]) -> f32 {
    let fonts = fonts();
    text.chars()
        .map(|c| {
            let (f, g) = glyph_in(fonts, order, c);
            fonts[f].as_scaled(PxScale::from(size)).h_advance(g)
        })
        .sum()
}

/// Draws `text` with its baseline at `y`, starting at `x`; returns the x after it.
pub fn draw(img: &mut RgbaImage, x: f32, y: f32, size: f32, color: [u8; 3], text: &str) -> f32 {
    draw_in(img, (x, y, size), color, text, [0, 1, 2])
}

/// Draws source code as [`draw`] draws text, in the monospace font (Hack) where it has the
/// glyph, so columns line up; returns the x after it.
pub fn draw_code(
    img: &mut RgbaImage,
    x: f32,
    y: f32,
    size: f32,
    color: [u8; 3],
    text: &str,
) -> f32 {
    draw_in(img, (x, y, size), color, text, [1, 0, 2])
}

/// Draws `text` at `(x, baseline y, size)` with each character from the first font of `order`
/// that has it.
fn draw_in(
    img: &mut RgbaImage,
    (x, y, size): (f32, f32, f32),
    color: [u8; 3],
    text: &str,
    order: [usize; 3],
) -> f32 {
    let fonts = fonts();
    let scale = PxScale::from(size);
    let mut pen = x;
    for c in text.chars() {
        let (f, id) = glyph_in(fonts, order, c);
        let font = &fonts[f];
        let glyph = id.with_scale_and_position(scale, ab_glyph::point(pen, y));
        pen += font.as_scaled(scale).h_advance(id);
        let Some(outline) = font.outline_glyph(glyph) else {
            continue;
        };
        let b = outline.px_bounds();
        outline.draw(|gx, gy, coverage| {
            let (px, py) = (
                b.min.x as i64 + i64::from(gx),
                b.min.y as i64 + i64::from(gy),
            );
            if px < 0 || py < 0 || px >= i64::from(img.width()) || py >= i64::from(img.height()) {
                return;
            }
            let p = img.get_pixel_mut(px as u32, py as u32);
            let a = coverage.clamp(0.0, 1.0);
            for (channel, ink) in p.0.iter_mut().zip(color) {
                *channel = (f32::from(*channel) * (1.0 - a) + f32::from(ink) * a).round() as u8;
            }
            p.0[3] = p.0[3].max((a * 255.0) as u8);
        });
    }
    pen
}

/// Draws runs one after another on one line (scripts smaller, lowered or raised); returns the x
/// after them.
pub fn draw_runs(img: &mut RgbaImage, x: f32, y: f32, size: f32, runs: &[Run]) -> f32 {
    runs.iter().fold(x, |pen, r| {
        let (size, shift) = r.script.placed(size);
        draw(img, pen, y + shift, size, r.color, &r.text)
    })
}

/// The width of a run in text of `size`.
fn run_width(text: &str, script: Script, size: f32) -> f32 {
    width(text, script.placed(size).0)
}

/// `text` typeset as runs ([`marked_runs`]: its `**formulas**` in `accent`, the rest in
/// `color`) in lines no wider than `max` at `size` (a piece wider than a line stays whole),
/// broken where the app's cards break them ([`line_breaks`]): after a space or beside a Chinese
/// character, never before closing punctuation nor inside a formula's atom, an operator kept
/// with its operands where the line has room.
#[must_use]
pub fn wrap_marked(
    text: &str,
    (color, accent): ([u8; 3], [u8; 3]),
    size: f32,
    max: f32,
) -> Vec<Vec<Run>> {
    let pieces = line_breaks::pieces(&notation::parse_paragraph(text));
    let runs: Vec<Vec<Run>> = pieces
        .iter()
        .map(|p| {
            let mut out = Vec::new();
            push_nodes(&mut out, p, color, accent, Script::Base);
            out
        })
        .collect();
    let widths: Vec<(f32, f32)> = runs
        .iter()
        .map(|piece| {
            let advance = piece.iter().map(|r| run_width(&r.text, r.script, size));
            let ink = piece.iter().enumerate().map(|(k, r)| {
                let text = if k + 1 == piece.len() {
                    r.text.trim_end()
                } else {
                    &r.text
                };
                run_width(text, r.script, size)
            });
            (advance.sum(), ink.sum())
        })
        .collect();
    line_breaks::lines(&widths, &line_breaks::keeps_with_next(&pieces), max)
        .into_iter()
        .map(|line| {
            let mut out = Vec::new();
            for r in line.iter().flat_map(|&k| &runs[k]) {
                push(&mut out, &r.text, r.color, r.script);
            }
            out
        })
        .collect()
}

/// `text` typeset as runs ([`notation::parse_paragraph`]): its `**formulas**` in `accent`, the
/// rest in `color`; subscripts and superscripts as script runs; a fraction on one line,
/// `num/den`, each part bracketed when it is more than one symbol; `code` as written, without
/// its backticks.
#[must_use]
pub fn marked_runs(text: &str, color: [u8; 3], accent: [u8; 3]) -> Vec<Run> {
    let mut out: Vec<Run> = Vec::new();
    push_nodes(
        &mut out,
        &notation::parse_paragraph(text),
        color,
        accent,
        Script::Base,
    );
    out
}

/// Appends `text` of `color` at `script`, continuing the last run when it is of the same colour
/// and place.
fn push(out: &mut Vec<Run>, text: &str, color: [u8; 3], script: Script) {
    match out.last_mut() {
        Some(last) if (last.color, last.script) == (color, script) => last.text.push_str(text),
        _ if text.is_empty() => {}
        _ => out.push(Run {
            text: text.to_owned(),
            color,
            script,
        }),
    }
}

/// Appends `nodes` as runs of `color` at `script` (a formula's in `accent`), merging text that
/// continues a run of the same colour and place.
fn push_nodes(out: &mut Vec<Run>, nodes: &[Node], color: [u8; 3], accent: [u8; 3], script: Script) {
    for n in nodes {
        match n {
            Node::Text(t) | Node::Code(t) => push(out, t, color, script),
            // Scripts of scripts stay at the script's size.
            Node::Script { base, sub, sup } => {
                push_nodes(out, base, color, accent, script);
                let inner = |s: Script| if script == Script::Base { s } else { script };
                for (part, place) in [(sub, Script::Sub), (sup, Script::Sup)] {
                    if let Some(part) = part {
                        push_nodes(out, part, color, accent, inner(place));
                    }
                }
            }
            Node::Frac { num, den } => {
                for (k, part) in [num, den].into_iter().enumerate() {
                    if k == 1 {
                        push(out, "/", color, script);
                    }
                    let bracket = notation::needs_brackets(part);
                    if bracket {
                        push(out, "(", color, script);
                    }
                    push_nodes(out, part, color, accent, script);
                    if bracket {
                        push(out, ")", color, script);
                    }
                }
            }
            Node::Formula(inner) => push_nodes(out, inner, accent, accent, script),
        }
    }
}

/// Fills a rectangle.
pub fn fill(img: &mut RgbaImage, x: u32, y: u32, w: u32, h: u32, color: [u8; 3]) {
    for py in y..(y + h).min(img.height()) {
        for px in x..(x + w).min(img.width()) {
            img.put_pixel(px, py, Rgba([color[0], color[1], color[2], 255]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `covers` answers from the fonts: log₂'s subscript is in Ubuntu Light, a superscript ᵀ in
    /// none of them (lessons write M^T), so the lesson test that relies on it can fail.
    #[test]
    fn coverage_is_looked_up_in_the_fonts() {
        assert!(covers('₂') && covers('透') && covers('⌊') && covers(' '));
        assert!(!covers('ᵀ'));
    }

    /// The attributes' and uniforms' meanings (in the shader checker's messages) are drawable.
    #[test]
    fn the_shader_interface_has_glyphs() {
        use pipeline::shader::interface::{ATTRIBUTES, UNIFORMS};
        let texts = ATTRIBUTES.iter().map(|a| a.meaning);
        for text in texts.chain(UNIFORMS.iter().map(|u| u.meaning)) {
            let missing: String = text.chars().filter(|&c| !covers(c)).collect();
            assert!(missing.is_empty(), "{text:?}: no glyph for {missing:?}");
        }
    }

    #[test]
    fn chinese_latin_and_the_symbols_the_cjk_font_lacks_draw_ink() {
        for text in ["Phong", "透视投影", "⌊λ⌋", "M⁻¹"] {
            let mut img = RgbaImage::from_pixel(200, 40, Rgba([0, 0, 0, 255]));
            draw(&mut img, 2.0, 30.0, 24.0, [255, 255, 255], text);
            let lit = img.pixels().filter(|p| p.0[0] > 128).count();
            assert!(lit > 20, "{text}: {lit} lit pixels");
        }
    }

    #[test]
    fn lines_wrap_at_spaces_and_between_chinese_characters() {
        let plain = ([0; 3], [0; 3]);
        let lines = wrap_marked(
            "one two three four five six",
            plain,
            20.0,
            width("one two three", 20.0) + 1.0,
        );
        let texts: Vec<String> = lines
            .iter()
            .map(|l| l.iter().map(|r| r.text.as_str()).collect::<String>())
            .collect();
        assert_eq!(texts[0].trim_end(), "one two three");
        assert_eq!(texts.len(), 2);
        let four = width("透视投影", 20.0) + 1.0;
        let lines = wrap_marked("透视投影把视锥变成立方体", plain, 20.0, four);
        assert_eq!(lines.len(), 3);
        // Chinese punctuation never begins a line: it goes with the character before it.
        let lines = wrap_marked("透视投影。视锥", plain, 20.0, four);
        let first: String = lines[0].iter().map(|r| r.text.as_str()).collect();
        assert_eq!(first, "透视投");
        // Nor does an opening bracket end one: it goes with the character after it.
        let lines = wrap_marked("透视投（影）", plain, 20.0, width("透视投（", 20.0) + 1.0);
        let texts: Vec<String> = lines
            .iter()
            .map(|l| l.iter().map(|r| r.text.as_str()).collect::<String>())
            .collect();
        assert_eq!(texts, ["透视投", "（影）"]);
    }

    /// Slides typeset as the app and the handout do: scripts smaller and shifted, a fraction on
    /// one line with its parts bracketed where they are more than one symbol.
    #[test]
    fn scripts_are_runs_of_their_own_and_fractions_keep_their_brackets() {
        let (ink, accent) = ([1; 3], [2; 3]);
        let r = marked_runs("so **z_ndc = (f+n)/(f−n)** and x^2", ink, accent);
        let got: Vec<(&str, [u8; 3], Script)> = r
            .iter()
            .map(|r| (r.text.as_str(), r.color, r.script))
            .collect();
        assert_eq!(
            got,
            [
                ("so ", ink, Script::Base),
                ("z", accent, Script::Base),
                ("ndc", accent, Script::Sub),
                (" = (f+n)/(f−n)", accent, Script::Base),
                (" and x", ink, Script::Base),
                ("2", ink, Script::Sup),
            ]
        );
        // A script is drawn smaller: narrower than the same text on the line.
        assert!(run_width("ndc", Script::Sub, 40.0) < width("ndc", 40.0) * 0.8);
        let mut img = RgbaImage::from_pixel(200, 80, Rgba([0, 0, 0, 255]));
        draw_runs(&mut img, 2.0, 50.0, 40.0, &r[1..3]);
        let lowest = img
            .enumerate_pixels()
            .filter(|(_, _, p)| p.0[0] > 0)
            .map(|(_, y, _)| y)
            .max();
        assert!(
            lowest.is_some_and(|y| y > 50),
            "the subscript goes below the baseline"
        );
        // A line never breaks between a symbol, its subscript and the full stop after them.
        let lines = wrap_marked(
            "then apply M_ortho.",
            (ink, accent),
            20.0,
            width("then apply M", 20.0) + 1.0,
        );
        let texts: Vec<String> = lines
            .iter()
            .map(|l| l.iter().map(|r| r.text.as_str()).collect::<String>())
            .collect();
        assert_eq!(texts, ["then apply ", "Mortho."]);
    }

    #[test]
    fn formulas_are_runs_of_their_own() {
        let code = marked_runs("set `normals = \"average\"` here", [1; 3], [2; 3]);
        assert_eq!(code[0].text, "set normals = \"average\" here");
        let r = marked_runs("a **x/w** b", [1; 3], [2; 3]);
        assert_eq!(r.len(), 3);
        assert_eq!((r[1].text.as_str(), r[1].color), ("x/w", [2; 3]));
    }
}
