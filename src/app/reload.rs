//! Live reload: the file the app was opened on is checked about twice a second and loaded again
//! when it changes; a broken edit shows its error while the last good version keeps running.

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
    fn modified(path: &std::path::Path) -> Option<std::time::SystemTime> {
        std::fs::metadata(path).and_then(|m| m.modified()).ok()
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
