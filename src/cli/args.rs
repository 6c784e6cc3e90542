//! The values the command line takes, read with a clear message for each mistake: a stage by
//! name, a window pixel `X,Y`, a line `X0,Y0,X1,Y1`, a viewport size `WIDTHxHEIGHT`.

use std::str::FromStr;

use pipeline::settings::MAX_VIEWPORT_SIDE;

/// A stage by its name.
pub(super) fn parse_stage(s: &str) -> Result<crate::vocabulary::Stage, String> {
    crate::vocabulary::Stage::from_name(s).ok_or_else(|| {
        "expected one of model, world, view, clip, ndc, viewport, rasterization, depth, shading, texturing, output"
            .to_owned()
    })
}

/// A language by its BCP 47 tag: one of the catalogs in `locales/` (`en`, `zh-Hans`; `zh` for
/// short), the pseudo-locale `en-XA`, or any other tag — a lesson's own language, whose
/// interface is English.
pub(super) fn parse_lang(s: &str) -> Result<crate::vocabulary::Lang, String> {
    use crate::vocabulary::{Lang, lang::PSEUDO};
    if let Some(l) = Lang::find(s) {
        return Ok(l);
    }
    if s.parse::<unic_langid::LanguageIdentifier>().is_ok() {
        return Ok(Lang::uncatalogued(s));
    }
    let found: Vec<&str> = Lang::all().iter().map(|l| l.tag()).collect();
    Err(format!(
        "\"{s}\" is not a language tag (BCP 47, such as fr or pt-BR); the catalogs found are {} (and the pseudo-locale {PSEUDO})",
        found.join(", ")
    ))
}

/// A window pixel `X,Y` (y up).
pub(super) fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s
        .split_once(',')
        .ok_or_else(|| format!("expected X,Y such as 120,80, got \"{s}\""))?;
    let n = |p: &str| {
        p.trim()
            .parse::<u32>()
            .map_err(|_| format!("\"{p}\" is not a whole pixel coordinate"))
    };
    Ok((n(x)?, n(y)?))
}

/// A watch `EXPR@LINE` (`probe::parse`).
pub(super) fn parse_watch(s: &str) -> Result<pipeline::shader::probe::WatchSpec, String> {
    pipeline::shader::probe::parse(s)
}

/// A line `X0,Y0,X1,Y1` of image pixels.
pub(super) fn parse_line(s: &str) -> Result<[f32; 4], String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|p| {
            p.trim()
                .parse::<f32>()
                .map_err(|_| format!("\"{p}\" is not a number"))
        })
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        [a, b, c, d] if v.iter().all(|x| x.is_finite()) => Ok([*a, *b, *c, *d]),
        _ => Err(format!("expected four numbers X0,Y0,X1,Y1, got \"{s}\"")),
    }
}

/// A viewport size `WIDTHxHEIGHT`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let (w, h) = s
            .split_once(['x', 'X', '×'])
            .ok_or_else(|| format!("expected WIDTHxHEIGHT such as 1280x720, got \"{s}\""))?;
        let side = |v: &str| -> Result<u32, String> {
            v.trim()
                .parse::<u32>()
                .ok()
                .filter(|n| (1..=MAX_VIEWPORT_SIDE).contains(n))
                .ok_or_else(|| format!("each side must be a whole number from 1 to {MAX_VIEWPORT_SIDE}, got \"{v}\""))
        };
        Ok(Self {
            width: side(w)?,
            height: side(h)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{Size, parse_lang};

    #[test]
    fn a_language_is_a_catalogs_tag_or_any_other_tag() {
        use crate::vocabulary::Lang;
        assert_eq!(parse_lang("zh"), Ok(Lang::ZH));
        assert_eq!(parse_lang("en"), Ok(Lang::EN));
        assert_eq!(parse_lang("en-XA").map(Lang::tag), Ok("en-XA"));
        // A lesson's own language, with no catalog: kept by its tag.
        let fr = parse_lang("fr").expect("a tag");
        assert_eq!((fr.tag(), fr.has_catalog()), ("fr", false));
        let refused = parse_lang("fr!").expect_err("not a tag");
        assert!(refused.contains("not a language tag"), "{refused}");
        assert!(refused.contains("en, zh-Hans"), "{refused}");
    }

    #[test]
    fn sizes_parse_and_reject() {
        assert_eq!(
            "640x480".parse::<Size>(),
            Ok(Size {
                width: 640,
                height: 480
            })
        );
        assert_eq!("1280×720".parse::<Size>().map(|s| s.width), Ok(1280));
        for bad in ["640", "0x10", "10x0", "100000x100000", "axb", "-5x5"] {
            assert!(bad.parse::<Size>().is_err(), "{bad} should be rejected");
        }
    }
}
