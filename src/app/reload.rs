//! Live reload: the file the app was opened on, and the shader files beside it, are checked
//! about twice a second, and the file is loaded again when one of them changes; a broken edit
//! shows its error while the last good version keeps running.

use std::path::PathBuf;

use super::PipelensApp;
use super::session::Command;
use super::watched::Watched;
use crate::app::command::{EditorCommand, SceneCommand};

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
        self.watched = Some(Watched::new(path));
    }

    /// Checks the watched file about twice a second and reloads it when it changed.
    pub(super) fn reload_if_changed(&mut self, ctx: &egui::Context) {
        let Some(w) = &mut self.watched else {
            return;
        };
        ctx.request_repaint_after(std::time::Duration::from_millis(500));
        if !w.changed() {
            return;
        }
        // A lesson being edited with unsaved changes is not replaced: the editor says the file
        // changed, and a save asks before overwriting it.
        if let Some(doc) = &mut self.editor.doc
            && doc.file.as_deref() == Some(w.path())
            && let Ok(text) = std::fs::read_to_string(w.path())
            && !doc.changed_on_disk(&text)
        {
            self.editor.open = true;
            return;
        }
        let loaded = crate::lesson::load_file(w.path());
        self.commands.extend(match loaded {
            Ok(crate::lesson::Document::Lesson(l)) => {
                vec![Command::Editor(EditorCommand::ReloadLesson(l))]
            }
            Ok(crate::lesson::Document::Scene(s)) => {
                vec![
                    Command::Editor(EditorCommand::SetReloadError(None)),
                    Command::Scene(SceneCommand::SetSpec(s)),
                ]
            }
            Err(e) => vec![Command::Editor(EditorCommand::SetReloadError(Some(
                e.to_string(),
            )))],
        });
    }
}
