//! Live reload: the file the app was opened on, and the shader files beside it, are checked
//! about twice a second, and the file is loaded again when one of them changes; a broken edit
//! shows its error while the last good version keeps running.

use std::path::PathBuf;

use web_time::Instant;

use super::PipelensApp;
use super::session::Command;

/// A file watched for changes.
pub(super) struct Watched {
    path: PathBuf,
    modified: Option<std::time::SystemTime>,
    checked: Instant,
}

impl Watched {
    /// The file watched.
    pub(super) fn path(&self) -> &std::path::Path {
        &self.path
    }

    /// The latest change to `path` or to a shader file (`.vert`, `.frag`, …) in its folder or
    /// a folder within it: a lesson reads its shaders from there.
    fn modified(path: &std::path::Path) -> Option<std::time::SystemTime> {
        let stamp = |p: &std::path::Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
        let is_shader = |p: &std::path::Path| {
            let name = p.to_string_lossy();
            crate::lesson::SHADER_FILE_ENDINGS
                .iter()
                .any(|e| name.ends_with(e))
        };
        let entries = |dir: &std::path::Path| {
            std::fs::read_dir(dir)
                .into_iter()
                .flatten()
                .filter_map(|e| e.ok().map(|e| e.path()))
                .collect::<Vec<_>>()
        };
        let folder = path
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(std::path::Path::new("."));
        let mut latest = stamp(path);
        for entry in entries(folder) {
            let inner = if entry.is_dir() {
                entries(&entry)
            } else {
                vec![entry]
            };
            for p in inner.iter().filter(|p| is_shader(p)) {
                latest = latest.max(stamp(p));
            }
        }
        latest
    }
}

impl PipelensApp {
    /// Watches `path` (the file the session was loaded from): when it changes on disk, it is
    /// loaded again; a broken edit shows its error and the last good version keeps running.
    #[must_use]
    pub fn watching(mut self, path: PathBuf) -> Self {
        self.watch(path);
        self
    }

    /// Starts watching `path` in place of any file watched before.
    pub(super) fn watch(&mut self, path: PathBuf) {
        self.watched = Some(Watched {
            modified: Watched::modified(&path),
            path,
            checked: Instant::now(),
        });
    }

    /// Checks the watched file about twice a second and reloads it when it changed.
    pub(super) fn reload_if_changed(&mut self, ctx: &egui::Context) {
        let Some(w) = &mut self.watched else {
            return;
        };
        ctx.request_repaint_after(std::time::Duration::from_millis(500));
        if w.checked.elapsed() < std::time::Duration::from_millis(400) {
            return;
        }
        w.checked = Instant::now();
        let now = Watched::modified(&w.path);
        if now == w.modified {
            return;
        }
        w.modified = now;
        // A lesson being edited with unsaved changes is not replaced: the editor says the file
        // changed, and a save asks before overwriting it.
        if let Some(doc) = &mut self.editor.doc
            && doc.file.as_deref() == Some(w.path.as_path())
            && let Ok(text) = std::fs::read_to_string(&w.path)
            && !doc.changed_on_disk(&text)
        {
            self.editor.open = true;
            return;
        }
        let loaded = crate::lesson::load_file(&w.path);
        self.commands.extend(match loaded {
            Ok(crate::lesson::Document::Lesson(l)) => vec![Command::ReloadLesson(l)],
            Ok(crate::lesson::Document::Scene(s)) => {
                vec![Command::SetReloadError(None), Command::SetSpec(s)]
            }
            Err(e) => vec![Command::SetReloadError(Some(e.to_string()))],
        });
    }
}
