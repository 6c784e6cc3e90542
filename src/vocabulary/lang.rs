//! The interface's languages. Every word the interface shows is a message of a Fluent catalog,
//! one file per language in `locales/` (`locales/en.ftl`, `locales/zh-Hans.ftl`, named by the
//! language's BCP 47 tag) that `build.rs` embeds; the code names a message by its id,
//! `lang.t("stage-depth")`. English is the fallback: a message a catalog lacks is shown in
//! English. A language is added by adding its file; `pipelens --lang` and the menu list the
//! catalogs found.
//!
//! Besides the catalogs there is a pseudo-locale, `en-XA`: English with every letter accented,
//! each message lengthened by about 40 % and bracketed, `[Ðéép·ţh~~]`, so that a word written in
//! the code instead of a catalog, or a label too narrow for a longer language, shows at a glance.
//!
//! A lesson's own words are a [`Text`].

use std::collections::{BTreeMap, HashMap};
use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource};

mod embedded {
    include!(concat!(env!("OUT_DIR"), "/catalogs.rs"));
}

/// The pseudo-locale's tag: "English, accented" (the tag Android and Chromium use for it).
pub const PSEUDO: &str = "en-XA";

/// A language of the interface, named by its BCP 47 tag.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Lang(&'static str);

impl Default for Lang {
    fn default() -> Self {
        Self::EN
    }
}

/// One language's messages.
struct Catalog {
    tag: &'static str,
    /// Every message's id, in the file's order.
    ids: Vec<&'static str>,
    /// Each message without variables, formatted once.
    plain: HashMap<&'static str, &'static str>,
    /// The ids of the messages without variables by their text, in the file's order: how
    /// [`Lang::from_english`] finds a message by its English words without a scan.
    by_text: HashMap<&'static str, Vec<&'static str>>,
    /// The catalog, for messages with variables.
    bundle: FluentBundle<FluentResource>,
    pseudo: bool,
}

/// Every catalog, the fallback English first, then the pseudo-locale.
fn catalogs() -> &'static [Catalog] {
    static ALL: OnceLock<Vec<Catalog>> = OnceLock::new();
    ALL.get_or_init(|| {
        let mut all: Vec<Catalog> = embedded::CATALOGS
            .iter()
            .map(|(tag, text)| catalog(tag, text, false))
            .collect();
        if let Some((_, en)) = embedded::CATALOGS.iter().find(|(t, _)| *t == "en") {
            all.push(catalog(PSEUDO, en, true));
        }
        all
    })
}

/// Reads one catalog. A message that does not parse is left out (and so shown in English);
/// [`catalog_problems`] names it, and a test asserts there are none.
fn catalog(tag: &'static str, text: &str, pseudo: bool) -> Catalog {
    let resource = FluentResource::try_new(text.to_owned()).unwrap_or_else(|(partial, _)| partial);
    let ids: Vec<&'static str> = message_ids(&resource)
        .into_iter()
        .map(|id| &*Box::leak(id.into_boxed_str()))
        .collect();
    let langid = tag.parse().unwrap_or_default();
    let mut bundle = FluentBundle::new_concurrent(vec![langid]);
    bundle.set_use_isolating(false);
    if pseudo {
        bundle.set_transform(Some(pseudo_text));
    }
    // A message defined twice keeps its first definition (the error is reported by
    // `catalog_problems`).
    let _ = bundle.add_resource(resource);
    let mut plain = HashMap::new();
    let mut by_text: HashMap<&'static str, Vec<&'static str>> = HashMap::new();
    for &id in &ids {
        let mut errors = Vec::new();
        let Some(pattern) = bundle.get_message(id).and_then(|m| m.value()) else {
            continue;
        };
        let text = bundle.format_pattern(pattern, None, &mut errors);
        if errors.is_empty() {
            let text = if pseudo {
                format!("[{text}]")
            } else {
                text.into_owned()
            };
            let text: &'static str = Box::leak(text.into_boxed_str());
            plain.insert(id, text);
            by_text.entry(text).or_default().push(id);
        }
    }
    Catalog {
        tag,
        ids,
        plain,
        by_text,
        bundle,
        pseudo,
    }
}

/// The ids of a catalog's messages, in the file's order.
fn message_ids(resource: &FluentResource) -> Vec<String> {
    resource
        .entries()
        .filter_map(|e| match e {
            fluent_syntax::ast::Entry::Message(m) => Some(m.id.name.to_owned()),
            _ => None,
        })
        .collect()
}

/// The pseudo-locale's text: each ASCII letter accented, and the text lengthened by about
/// 40 % (rounded up) by doubling vowels, then padding with `~`.
fn pseudo_text(text: &str) -> std::borrow::Cow<'_, str> {
    const FROM: &str = "aeiouAEIOUcCnNyYsSzZdDgGtT";
    const TO: &str = "áéíóúÁÉÍÓÚçÇñÑýÝşŞžŽđĐğĞţŢ";
    let mut extra = (text.chars().count() * 2).div_ceil(5);
    let mut out = String::with_capacity(text.len() * 2);
    for c in text.chars() {
        let accented = FROM.find(c).and_then(|i| TO.chars().nth(i)).unwrap_or(c);
        out.push(accented);
        if extra > 0 && "aeiouAEIOU".contains(c) {
            out.push(accented);
            extra -= 1;
        }
    }
    out.extend(std::iter::repeat_n('~', extra));
    out.into()
}

impl Lang {
    /// English: the fallback.
    pub const EN: Self = Self("en");
    /// 简体中文: Chinese in simplified characters, as the course notes are written.
    pub const ZH: Self = Self("zh-Hans");

    /// The message `id` in this language (in English where this language lacks it; the id
    /// itself where no catalog has it, which a test rules out).
    #[must_use]
    pub fn t(self, id: &'static str) -> &'static str {
        [self, Self::EN]
            .iter()
            .filter_map(|l| l.catalog())
            .find_map(|c| c.plain.get(id).copied())
            .unwrap_or(id)
    }

    /// The message `FAMILY-KEY` for a key read from data (a part's name, a parameter's key):
    /// `keyed("part", "left_upper_arm")` is the message `part-left-upper-arm`, the key in
    /// lower case with spaces and `_` written `-`. `None` where no catalog has it.
    #[must_use]
    pub fn keyed(self, family: &str, key: &str) -> Option<&'static str> {
        let id: String = format!("{family}-{key}")
            .chars()
            .map(|c| {
                if c == ' ' || c == '_' {
                    '-'
                } else {
                    c.to_ascii_lowercase()
                }
            })
            .collect();
        [self, Self::EN]
            .iter()
            .filter_map(|l| l.catalog())
            .find_map(|c| c.plain.get(id.as_str()).copied())
    }

    /// The message of `family` (`formula`, `glsl`) whose English is `english` — words the core
    /// or a shipped shader writes in English, looked up by those words — in this language.
    /// `None` where no message of the family has them (they stay as they are).
    #[must_use]
    pub fn from_english(self, family: &str, english: &str) -> Option<&'static str> {
        let en = Self::EN.catalog()?;
        let id = en.by_text.get(english)?.iter().find(|id| {
            id.strip_prefix(family)
                .is_some_and(|rest| rest.starts_with('-'))
        })?;
        Some(self.t(id))
    }

    /// The message `id` with its variables, `{ $name }`, given as `(name, value)` pairs. A
    /// value written as a whole number (digits only) is passed as a number, so that a message
    /// can choose its words by it (`{ $n -> [one] … *[other] … }`, the language's plural
    /// rules); every other value is passed as the text it displays as.
    #[must_use]
    pub fn t_with(
        self,
        id: &'static str,
        args: &[(&'static str, &dyn std::fmt::Display)],
    ) -> String {
        let mut fluent = FluentArgs::new();
        for (name, value) in args {
            let text = value.to_string();
            match text.parse::<u64>() {
                Ok(n) if text.bytes().all(|b| b.is_ascii_digit()) => fluent.set(*name, n),
                _ => fluent.set(*name, text),
            }
        }
        for c in [self, Self::EN].iter().filter_map(|l| l.catalog()) {
            if let Some(pattern) = c.bundle.get_message(id).and_then(|m| m.value()) {
                let mut errors = Vec::new();
                let text = c.bundle.format_pattern(pattern, Some(&fluent), &mut errors);
                return if c.pseudo {
                    format!("[{text}]")
                } else {
                    text.into_owned()
                };
            }
        }
        id.to_owned()
    }

    fn catalog(self) -> Option<&'static Catalog> {
        catalogs().iter().find(|c| c.tag == self.0)
    }

    /// The language a tag names: a catalog's tag (letter case aside), or its language alone
    /// (`zh` finds `zh-Hans`), or the pseudo-locale. `None` for a language with no catalog.
    #[must_use]
    pub fn find(tag: &str) -> Option<Self> {
        let all = catalogs();
        all.iter()
            .find(|c| c.tag.eq_ignore_ascii_case(tag))
            .or_else(|| {
                all.iter()
                    .find(|c| !c.pseudo && primary(c.tag).eq_ignore_ascii_case(tag))
            })
            .map(|c| Self(c.tag))
    }

    /// A language with no catalog, by its tag (a lesson's own language, `fr`): its interface
    /// is English, a lesson's words its own where the lesson gives them. A catalog's tag
    /// gives that catalog's language.
    #[must_use]
    pub fn uncatalogued(tag: &str) -> Self {
        static TAGS: std::sync::Mutex<Vec<&'static str>> = std::sync::Mutex::new(Vec::new());
        if let Some(l) = Self::find(tag) {
            return l;
        }
        let mut tags = TAGS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let kept = match tags.iter().find(|t| t.eq_ignore_ascii_case(tag)) {
            Some(t) => *t,
            None => {
                let t: &'static str = Box::leak(tag.to_owned().into_boxed_str());
                tags.push(t);
                t
            }
        };
        Self(kept)
    }

    /// Every language with a catalog, English first; the pseudo-locale is not among them.
    #[must_use]
    pub fn all() -> Vec<Self> {
        catalogs()
            .iter()
            .filter(|c| !c.pseudo)
            .map(|c| Self(c.tag))
            .collect()
    }

    /// The language's BCP 47 tag, as a document's `lang` attribute takes it: `en`, `zh-Hans`.
    #[must_use]
    pub fn tag(self) -> &'static str {
        self.0
    }

    /// The language's own name, for the switch (its catalog's `language-name`; its tag where
    /// it has no catalog).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self.catalog() {
            Some(_) => self.t("language-name"),
            None => self.0,
        }
    }

    /// Whether a lesson's text under `tag` is in this language: the same tag (letter case
    /// aside), or its language alone (`fr` for `fr-CA`).
    #[must_use]
    pub fn matches(self, tag: &str) -> bool {
        tag.eq_ignore_ascii_case(self.0) || tag.eq_ignore_ascii_case(primary(self.0))
    }

    /// Whether the interface has a catalog in this language (else it is in English).
    #[must_use]
    pub fn has_catalog(self) -> bool {
        self.catalog().is_some()
    }

    /// Whether this is Chinese, whose words are set without spaces between them.
    #[must_use]
    pub fn is_chinese(self) -> bool {
        primary(self.0) == "zh"
    }
}

/// A tag's language subtag: `zh` of `zh-Hans`.
fn primary(tag: &str) -> &str {
    tag.split(['-', '_']).next().unwrap_or(tag)
}

/// What is wrong with the catalogs: a message that does not parse or is defined twice, and a
/// message of English that another catalog lacks (shown in English there). Each entry names
/// the catalog's file.
#[must_use]
pub fn catalog_problems() -> Vec<String> {
    let mut problems = Vec::new();
    let mut english: Vec<String> = Vec::new();
    for (tag, text) in embedded::CATALOGS {
        let file = format!("locales/{tag}.ftl");
        let resource = match FluentResource::try_new((*text).to_owned()) {
            Ok(r) => r,
            Err((r, errors)) => {
                for e in errors {
                    let line = text[..e.pos.start.min(text.len())].lines().count();
                    problems.push(format!("{file}:{line}: {}", e.kind));
                }
                r
            }
        };
        let ids = message_ids(&resource);
        let mut seen = std::collections::HashSet::new();
        for id in &ids {
            if !seen.insert(id) {
                problems.push(format!("{file}: `{id}` is defined twice"));
            }
        }
        if *tag == "en" {
            english = ids;
        } else {
            let missing: Vec<&String> = english.iter().filter(|id| !seen.contains(id)).collect();
            if !missing.is_empty() {
                problems.push(format!(
                    "{file}: {} of English's messages missing, the first `{}`",
                    missing.len(),
                    missing[0]
                ));
            }
        }
    }
    problems
}

/// Every message id of the English catalog.
#[must_use]
pub fn english_ids() -> Vec<&'static str> {
    Lang::EN
        .catalog()
        .map(|c| c.ids.clone())
        .unwrap_or_default()
}

/// A lesson's words: English and Chinese, which every lesson has, and any other language a
/// lesson gives by its BCP 47 tag (`fr = "…"`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Text {
    /// English.
    pub en: String,
    /// Chinese.
    pub zh: String,
    /// Every other language: its tag as the lesson writes it, and the text.
    pub others: BTreeMap<String, String>,
}

impl Text {
    /// English and Chinese.
    #[must_use]
    pub fn new(en: impl Into<String>, zh: impl Into<String>) -> Self {
        Self {
            en: en.into(),
            zh: zh.into(),
            others: BTreeMap::new(),
        }
    }

    /// The text in `lang`: Chinese for Chinese; another language's own where the lesson has
    /// it (its tag, or its language alone: `fr` for `fr-CA`); English for the rest.
    #[must_use]
    pub fn get(&self, lang: Lang) -> &str {
        if lang.is_chinese() {
            return &self.zh;
        }
        self.other(lang).unwrap_or(&self.en)
    }

    /// The text of a language other than English and Chinese, by tag (letter case aside) or
    /// by the tag's language alone.
    fn other(&self, lang: Lang) -> Option<&str> {
        let exact = self
            .others
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(lang.0));
        exact
            .or_else(|| self.others.iter().find(|(k, _)| lang.matches(k)))
            .map(|(_, v)| v.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_catalog_parses_and_holds_every_message_of_english() {
        assert_eq!(catalog_problems(), Vec::<String>::new());
        assert!(english_ids().len() > 600, "{}", english_ids().len());
    }

    #[test]
    fn a_language_is_found_by_its_tag_or_by_its_language_alone() {
        assert_eq!(Lang::find("en"), Some(Lang::EN));
        assert_eq!(Lang::find("zh-Hans"), Some(Lang::ZH));
        assert_eq!(Lang::find("ZH-hans"), Some(Lang::ZH));
        assert_eq!(Lang::find("zh"), Some(Lang::ZH));
        assert_eq!(Lang::find("fr"), None);
        assert_eq!(Lang::find(PSEUDO).map(Lang::tag), Some(PSEUDO));
        assert_eq!(Lang::all()[0], Lang::EN);
        assert!(Lang::all().contains(&Lang::ZH));
        assert!(!Lang::all().iter().any(|l| l.tag() == PSEUDO));
        assert_eq!(Lang::ZH.name(), "中文");
        assert_eq!(Lang::EN.name(), "English");
    }

    #[test]
    fn a_message_is_in_its_language_with_english_behind_it() {
        assert_eq!(Lang::EN.t("chrome-classroom"), "Classroom");
        assert_eq!(Lang::ZH.t("chrome-classroom"), "课堂模式");
        // A message no catalog has shows its id: visible, and ruled out by the test below.
        assert_eq!(Lang::ZH.t("no-such-message"), "no-such-message");
        // Variables, and a language's own punctuation around them.
        let both = |l: Lang| l.t_with("spaces-fate-and-line", &[("fate", &"a"), ("line", &"b")]);
        assert_eq!(both(Lang::EN), "a: b");
        assert_eq!(both(Lang::ZH), "a：b");
    }

    /// The pseudo-locale, worked by hand: "Classroom" has 9 characters, so 4 more
    /// (⌈9 × 0.4⌉): its first three vowels doubled, then one `~`; C, a, s, o accented.
    #[test]
    fn the_pseudo_locale_accents_lengthens_and_brackets() {
        let pseudo = Lang::find(PSEUDO).expect("the pseudo-locale");
        assert_eq!(pseudo.t("chrome-classroom"), "[Çlááşşróóóóm~]");
        // Text around a variable is changed, the variable's value is not: ": " is 2
        // characters, so one `~`.
        assert_eq!(
            pseudo.t_with("spaces-fate-and-line", &[("fate", &"a"), ("line", &"b")]),
            "[a: ~b]"
        );
    }

    /// Every message the code names is in English's catalog, and every message there is
    /// named somewhere in the code: a typo in an id, or a message left behind by a change,
    /// fails here.
    #[test]
    fn the_code_and_the_english_catalog_name_the_same_messages() {
        let mut code = String::new();
        let mut dirs = vec![std::path::PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/src"
        ))];
        while let Some(dir) = dirs.pop() {
            for entry in std::fs::read_dir(&dir).expect("src/ is read").flatten() {
                let path = entry.path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|e| e == "rs")
                    && !path.ends_with("vocabulary/lang.rs")
                {
                    code.push_str(&std::fs::read_to_string(&path).expect("a source file is read"));
                }
            }
        }
        let ids = english_ids();
        // Every string written like an id (`words-joined-by-hyphens`) whose first word starts
        // some message's id: the calls `lang.t("…")` and the tables that name messages.
        let prefixes: std::collections::HashSet<&str> =
            ids.iter().filter_map(|id| id.split('-').next()).collect();
        let named: Vec<&str> = code
            .split('"')
            .skip(1)
            .step_by(2)
            .filter(|s| {
                s.contains('-')
                    && s.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
                    && s.split('-').next().is_some_and(|p| prefixes.contains(p))
            })
            .collect();
        let missing: Vec<&&str> = named.iter().filter(|id| !ids.contains(id)).collect();
        assert!(
            missing.is_empty(),
            "named in the code, missing from locales/en.ftl: {missing:?}"
        );
        let unused: Vec<&&str> = ids
            .iter()
            .filter(|id| **id != "language-name" && !code.contains(&format!("\"{id}\"")))
            // The families looked up by a key read from data (`Lang::keyed`).
            .filter(|id| !id.starts_with("part-") && !id.starts_with("param-"))
            // The families looked up by their English words (`Lang::from_english`).
            .filter(|id| !id.starts_with("formula-") && !id.starts_with("glsl-"))
            .collect();
        assert!(
            unused.is_empty(),
            "in locales/en.ftl, named nowhere in the code: {unused:?}"
        );
    }
}
