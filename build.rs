//! Embeds every message catalog found in `locales/` (one Fluent file per language,
//! `locales/<BCP 47 tag>.ftl`), so that a language is added by adding its file.

use std::{env, fs, path::Path};

fn main() {
    println!("cargo:rerun-if-changed=locales");
    // Read when the script runs, not when it was compiled: a build script compiled in another
    // checkout (a target folder copied or shared) would embed that checkout's catalogs.
    let manifest = env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let dir = Path::new(&manifest).join("locales");
    let mut found: Vec<(String, String)> = fs::read_dir(&dir)
        .expect("the locales/ folder is read")
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "ftl"))
        .filter_map(|p| {
            let tag = p.file_stem()?.to_str()?.to_owned();
            println!("cargo:rerun-if-changed={}", p.display());
            Some((tag, p.display().to_string()))
        })
        .collect();
    // English first: the fallback, and the language a missing message is shown in.
    found.sort_by(|a, b| (a.0 != "en", &a.0).cmp(&(b.0 != "en", &b.0)));
    let mut code = String::from("/// Every catalog in `locales/`: its tag and its text.\n");
    code.push_str("pub static CATALOGS: &[(&str, &str)] = &[\n");
    for (tag, path) in &found {
        code.push_str(&format!("    ({tag:?}, include_str!({path:?})),\n"));
    }
    code.push_str("];\n");
    let out = Path::new(&env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("catalogs.rs");
    fs::write(out, code).expect("the catalogs' list is written");
}
