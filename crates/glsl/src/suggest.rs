//! "Did you mean …?": the one rule by which every message of pipelens — a shader's uniform,
//! texture, attribute or type, a lesson's key, parameter, mesh, file or object — proposes the
//! name that was meant, and the one way it says so, at the message's end.

/// How the message quotes a name: code and keys in backticks, values in double quotes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quote {
    /// `` `model` ``: a name in GLSL, a key of a lesson file.
    Code,
    /// `"cube"`: a value a lesson file writes in quotes.
    Value,
}

/// The known name nearest `name`, when one is close enough to be what was meant: within
/// `max(2, ⌊len/3⌋)` edits (Damerau–Levenshtein: a typo, a swapped pair), or sharing enough of
/// its beginning (Jaro–Winkler similarity ≥ 0.85: `fov` → `fovy`). Of those, the fewest edits,
/// then the most similar, then the first.
#[must_use]
pub fn nearest<'a>(name: &str, known: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    known
        .into_iter()
        .filter(|k| *k != name)
        .map(|k| {
            let edits = strsim::damerau_levenshtein(name, k);
            let similar = strsim::jaro_winkler(name, k);
            (edits, similar, k)
        })
        .filter(|(edits, similar, k)| *edits <= 2.max(k.chars().count() / 3) || *similar >= 0.85)
        .min_by(|a, b| a.0.cmp(&b.0).then(b.1.total_cmp(&a.1)))
        .map(|(_, _, k)| k)
}

/// `; did you mean X?` with `meant` quoted as `quote` says: the end of a message.
#[must_use]
pub fn hint(meant: &str, quote: Quote) -> String {
    match quote {
        Quote::Code => format!("; did you mean `{meant}`?"),
        Quote::Value => format!("; did you mean \"{meant}\"?"),
    }
}

/// [`hint`] of the known name nearest `name`, or nothing when none is close.
#[must_use]
pub fn did_you_mean<'a>(
    name: &str,
    known: impl IntoIterator<Item = &'a str>,
    quote: Quote,
) -> String {
    nearest(name, known).map_or_else(String::new, |k| hint(k, quote))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_name_meant_is_found_by_its_typo_or_its_beginning() {
        let known = ["model", "view", "projection", "fovy", "shininess"];
        // One swap, one letter short, one extra: a typo.
        assert_eq!(nearest("modle", known), Some("model"));
        assert_eq!(nearest("veiw", known), Some("view"));
        assert_eq!(nearest("projections", known), Some("projection"));
        // A shared beginning: more than 2 edits, but 0.85 similar (Jaro–Winkler).
        assert_eq!(nearest("shinyness", known), Some("shininess"));
        assert_eq!(nearest("fov", known), Some("fovy"));
        // Nothing near, and a known name itself needs no hint.
        assert_eq!(nearest("colour", known), None);
        assert_eq!(nearest("view", known), None);
        assert_eq!(
            did_you_mean("modle", known, Quote::Code),
            "; did you mean `model`?"
        );
        assert_eq!(
            did_you_mean("cub", ["cube"], Quote::Value),
            "; did you mean \"cube\"?"
        );
        assert_eq!(did_you_mean("xyz", known, Quote::Code), "");
    }
}
