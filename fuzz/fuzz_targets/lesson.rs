//! The lesson and scene parser and validator on arbitrary text: never a panic, and every error
//! a diagnostic with a line and a column inside the text.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(d) =
        pipelens::lesson::parse_document(text, "fuzz.toml", std::path::Path::new("/nonexistent"))
    {
        let lines = text.lines().count().max(1);
        for e in &d.0 {
            assert!(e.line >= 1 && e.line <= lines + 1, "{e}");
            assert!(e.column >= 1, "{e}");
        }
    }
});
