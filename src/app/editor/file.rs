//! The lesson being edited and its file: which text the editor starts from (the file on disk,
//! a built-in lesson, a file dropped on the page), saving it whole or not at all, the recovery
//! copy that keeps unsaved changes beside the file until they are saved, and a file changed on
//! disk while it was being edited, which is not overwritten without asking.

use std::path::{Path, PathBuf};

use crate::app::platform;
use crate::lesson::edit::Draft;
use crate::lesson::{Folder, Given, library};
use crate::vocabulary::Lang;

/// A lesson being edited, with where it is saved.
pub struct Edited {
    /// The text and its changes.
    pub draft: Draft,
    /// The session's name for what is open (the editor follows it).
    pub source: String,
    /// The file a save writes (the desktop); `None` for a built-in lesson, which is saved as a
    /// copy, and in the browser, where a save is a download.
    pub file: Option<PathBuf>,
    /// The file's text on disk as last read or written: another text there at saving means the
    /// file was changed by someone else.
    pub disk: Option<String>,
    /// The file changed on disk while there were unsaved edits (shown, and asked at saving).
    pub disk_changed: bool,
    /// A save was asked over a file changed on disk: the question is shown.
    pub ask_overwrite: bool,
    /// Unsaved changes of an earlier run, found beside the file: offered.
    pub recovery: Option<String>,
    /// Where the recovery copy is kept: beside the file, or (in the browser) in the page's
    /// storage under the dropped file's name; none for a built-in lesson (not edited in place).
    recovery_key: Option<PathBuf>,
    /// The text last written to the recovery copy.
    kept: Option<String>,
}

/// Where the unsaved changes to `file` are kept until they are saved: `lesson.toml.unsaved`,
/// beside it (not a `.toml`: `pipelens check lessons/` does not read it).
#[must_use]
pub(super) fn recovery_path(file: &Path) -> PathBuf {
    let mut name = file.file_name().unwrap_or_default().to_os_string();
    name.push(".unsaved");
    file.with_file_name(name)
}

impl Edited {
    /// The lesson named `source` as the editor starts from it: the file `file` on disk (a
    /// recovery copy beside it offered), or the built-in lesson of that name, or `text` (a
    /// file dropped on the page, or a lesson just made: the meshes it names are among those
    /// `given` to the page).
    ///
    /// # Errors
    /// When there is no text to edit, or it is not a lesson file's.
    pub fn open(
        source: &str,
        file: Option<&Path>,
        text: Option<String>,
        given: &Given,
        lang: Lang,
    ) -> Result<Self, String> {
        let disk = match file {
            Some(f) if text.is_none() => {
                Some(std::fs::read_to_string(f).map_err(|e| cannot_read(f, &e, lang))?)
            }
            _ => None,
        };
        let text = text
            .or_else(|| disk.clone())
            .or_else(|| builtin_text(source).map(str::to_owned))
            .ok_or_else(|| lang.t_with("file-no-text-to-edit", &[("source", &source)]))?;
        let base = match file {
            Some(f) => Folder::on_disk(f.parent().unwrap_or(Path::new("."))),
            None if builtin_text(source).is_some() => Folder::on_disk(Path::new(".")),
            None => Folder::of_page(given.clone()),
        };
        let name = file.map_or_else(|| source.to_owned(), |f| f.display().to_string());
        let draft = Draft::in_folder(&text, &name, base)?;
        let recovery_key = match file {
            Some(f) => Some(recovery_path(f)),
            None if builtin_text(source).is_none() => Some(recovery_path(Path::new(source))),
            None => None,
        };
        let recovery = recovery_key
            .as_deref()
            .and_then(platform::unsaved)
            .filter(|kept| *kept != text);
        Ok(Self {
            draft,
            source: source.to_owned(),
            file: file.map(Path::to_path_buf),
            disk: disk.or_else(|| file.map(|_| text.clone())),
            disk_changed: false,
            ask_overwrite: false,
            recovery,
            recovery_key,
            kept: None,
        })
    }

    /// Whether this is a built-in lesson (saved as a copy, elsewhere).
    #[must_use]
    pub fn builtin(&self) -> bool {
        self.file.is_none() && builtin_text(&self.source).is_some()
    }

    /// Writes the draft into its file, whole or not at all, unless the file changed on disk
    /// since it was read and `overwrite` is not given (then the question is asked); in the
    /// browser, hands it over as a download. Refused, with `check`'s messages, while the text
    /// is not a valid lesson: the recovery copy keeps it meanwhile.
    ///
    /// # Errors
    /// What went wrong, in words.
    pub fn save(&mut self, overwrite: bool, lang: Lang) -> Result<String, String> {
        if let Err(e) = self.draft.lesson() {
            return Err(lang.t_with("file-not-saved", &[("why", &e)]));
        }
        let text = self.draft.text().to_owned();
        let Some(file) = self.file.clone() else {
            let name = Path::new(self.draft.name()).file_name().map_or_else(
                || "lesson.toml".into(),
                |n| n.to_string_lossy().into_owned(),
            );
            let name = name.trim_end_matches(" (built in)").to_owned();
            let done = platform::download(
                &name,
                text.as_bytes(),
                "application/toml",
                (Path::new("."), lang),
            )?;
            self.draft.mark_saved();
            self.drop_recovery();
            return Ok(done);
        };
        let on_disk = std::fs::read_to_string(&file).ok();
        if !overwrite && on_disk.is_some() && on_disk != self.disk {
            self.ask_overwrite = true;
            return Err(lang.t_with("file-changed-since-opened", &[("file", &file.display())]));
        }
        crate::export::write_atomically(&file, text.as_bytes(), lang)
            .map_err(|e| format!("{e:#}"))?;
        self.disk = Some(text);
        self.disk_changed = false;
        self.ask_overwrite = false;
        self.draft.mark_saved();
        self.drop_recovery();
        Ok(file.display().to_string())
    }

    /// The file changed on disk and reads `text` now: whether the app reloads it. With no
    /// unsaved edits the draft becomes it; with unsaved edits it is not taken (the editor says
    /// so, and a save asks). The same text (the editor's own save, or a shader file beside it
    /// changed) reloads as it is.
    pub fn changed_on_disk(&mut self, text: &str) -> bool {
        if self.disk.as_deref() == Some(text) {
            return true;
        }
        if self.draft.is_dirty() {
            self.disk_changed = true;
            return false;
        }
        if self.draft.replace_text(text).is_ok() {
            self.draft.mark_saved();
        }
        self.disk = Some(text.to_owned());
        true
    }

    /// The file's text on disk taken in place of the edits (which can be undone).
    ///
    /// # Errors
    /// When the file cannot be read or is not a lesson file's.
    pub fn load_from_disk(&mut self, lang: Lang) -> Result<(), String> {
        let file = self.file.clone().ok_or(lang.t("file-no-file"))?;
        let text = std::fs::read_to_string(&file).map_err(|e| cannot_read(&file, &e, lang))?;
        self.draft.replace_text(&text)?;
        self.draft.mark_saved();
        self.disk = Some(text);
        self.disk_changed = false;
        self.ask_overwrite = false;
        self.drop_recovery();
        Ok(())
    }

    /// Keeps the unsaved edits in the recovery copy beside the file (removed once nothing is
    /// unsaved: saved, or undone to the file's text), written whole or not at all, each text
    /// once.
    pub fn keep_recovery(&mut self) {
        let Some(key) = &self.recovery_key else {
            return;
        };
        // A copy of an earlier run stays until the teacher restores or discards it.
        if self.recovery.is_some() {
            return;
        }
        if self.draft.is_dirty() {
            if self.kept.as_deref() != Some(self.draft.text())
                && platform::keep_unsaved(key, Some(self.draft.text())).is_ok()
            {
                self.kept = Some(self.draft.text().to_owned());
            }
        } else if self.kept.take().is_some() {
            let _ = platform::keep_unsaved(key, None);
        }
    }

    /// The recovery copy's text taken in place of the file's (as a change that can be undone).
    ///
    /// # Errors
    /// When it is not a lesson file's text.
    pub fn restore(&mut self) -> Result<(), String> {
        if let Some(text) = self.recovery.take() {
            self.draft.replace_text(&text)?;
        }
        Ok(())
    }

    /// The recovery copy put away unread: the file's text stays.
    pub fn discard_recovery(&mut self) {
        self.recovery = None;
        self.drop_recovery();
    }

    /// Nothing is unsaved: no recovery copy.
    fn drop_recovery(&mut self) {
        self.kept = None;
        if let Some(key) = &self.recovery_key {
            let _ = platform::keep_unsaved(key, None);
        }
    }
}

/// The text of the built-in lesson the session names `source`, if it is one.
fn builtin_text(source: &str) -> Option<&'static str> {
    library::named(source).map(|(_, text)| text)
}

/// `mesh` as the lesson file `lesson` names it: from the lesson's folder when it is inside it,
/// else as given.
#[must_use]
pub fn mesh_from(lesson: &Path, mesh: &Path) -> String {
    let folder = lesson.parent().unwrap_or(Path::new(""));
    mesh.strip_prefix(folder)
        .unwrap_or(mesh)
        .to_string_lossy()
        .replace('\\', "/")
}

/// "cannot read FILE: why", in `lang`.
fn cannot_read(file: &Path, e: &std::io::Error, lang: Lang) -> String {
    let file = file.display();
    lang.t_with(
        "file-cannot-read",
        &[("file", &file), ("why", &e.to_string())],
    )
}
