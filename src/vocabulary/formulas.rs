//! The formulas of the matrices in the interface's language. The core names each matrix with a
//! formula in English words (the pipeline crate has no language); the catalogs hold each one as a
//! `formula-…` message, its English the core's words, the others in the notes' terms. Formulas
//! that are only mathematics read the same in every language and are not listed.

use super::Lang;

impl Lang {
    /// A matrix's formula in this language (formulas that are only mathematics are kept).
    #[must_use]
    pub fn formula(self, en: &str) -> String {
        self.from_english("formula", en)
            .map_or_else(|| en.to_owned(), str::to_owned)
    }
}
