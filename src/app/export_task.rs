//! The app's snapshot export: the same files as `pipelens export`, written off the UI thread,
//! with a message when it is done and a Cancel button while it runs.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::channel;

use pipeline::buffers::Capture;
use pipeline::settings::RenderSettings;

use super::PipelensApp;

impl PipelensApp {
    /// Exports go to `dir` (the Export menu's folder; `pipelens-export` by default).
    #[must_use]
    pub fn exporting_to(mut self, dir: &std::path::Path) -> Self {
        self.export_dir = dir.display().to_string();
        self
    }

    /// Whether an export is running.
    #[must_use]
    pub fn exporting(&self) -> bool {
        self.export_result.is_some()
    }

    pub(super) fn start_export(&mut self) {
        let Some(shown) = self.session.capture.clone() else {
            return;
        };
        // The view's capture keeps what it shows; an export writes every buffer.
        let spec = self.session.spec.clone();
        let opts = crate::export::ExportOptions {
            out: PathBuf::from(self.export_dir.trim()),
            overlay_zoom: 0,
            max_records: 200_000,
            pixel: self.session.selection.pixel,
            cancel: crate::export::Cancel::default(),
            lang: self.session.lang,
        };
        self.export_cancel = Some(opts.cancel.clone());
        let (tx, rx) = channel();
        self.export_result = Some(rx);
        std::thread::spawn(move || {
            let full = RenderSettings {
                capture: Capture::FULL,
                ..shown.settings
            };
            let capture = if shown.settings.capture == Capture::FULL {
                Ok(shown)
            } else {
                pipeline::render(&spec.scene, &full).map(Arc::new)
            };
            let r = capture.map_err(|e| e.to_string()).and_then(|c| {
                crate::export::export_capture(&c, &opts, &mut |_, _, _| {})
                    .map_err(|e| format!("{e:#}"))
            });
            let _ = tx.send(r);
        });
    }

    /// The lesson's handout and slides in the interface's language, off the UI thread.
    pub(super) fn start_handout_export(&mut self) {
        let Some((lesson, opts)) = self.handout_export(true) else {
            return;
        };
        self.export_cancel = Some(opts.cancel.clone());
        let (tx, rx) = channel();
        self.export_result = Some(rx);
        std::thread::spawn(move || {
            let r = crate::export::lesson::export_lesson(&lesson, &opts, &mut |_, _, _| {})
                .map(|e| e.written)
                .map_err(|e| format!("{e:#}"));
            let _ = tx.send(r);
        });
    }

    /// The browser's export: the lesson's handout in the interface's language as one HTML file
    /// (every image in it, printable), built on this thread (a page has one; the window waits
    /// the few seconds it takes) and handed over as a download.
    pub(super) fn download_handout(&mut self) {
        let Some((lesson, opts)) = self.handout_export(false) else {
            return;
        };
        let lang = opts.lang;
        let name = format!(
            "{}-{}.html",
            lesson.id,
            if lang.is_chinese() { "zh" } else { lang.tag() }
        );
        let result = crate::export::lesson::handout_html(&lesson, &opts)
            .map_err(|e| format!("{e:#}"))
            .and_then(|html| {
                super::platform::download(&name, html.as_bytes(), "text/html", (&opts.out, lang))
            });
        self.note = Some(match result {
            Ok(file) => (
                true,
                lang.t_with("export-task-handout-saved", &[("file", &file)]),
            ),
            Err(e) => (false, e),
        });
    }

    /// The open lesson and how the app exports its handout: in the interface's language, into
    /// the Export menu's folder, no answers, no data, with `slides` or not.
    fn handout_export(
        &self,
        slides: bool,
    ) -> Option<(
        std::sync::Arc<crate::lesson::Lesson>,
        crate::export::lesson::LessonExport,
    )> {
        let lesson = self.session.lesson.as_ref()?.lesson.clone();
        let opts = crate::export::lesson::LessonExport {
            out: PathBuf::from(self.export_dir.trim()),
            step: None,
            size: None,
            lang: self.session.lang,
            max_records: 200_000,
            answers: false,
            slides,
            data: false,
            pixel: None,
            cancel: crate::export::Cancel::default(),
        };
        Some((lesson, opts))
    }

    /// Takes the export's result when it has finished, as a message in the top bar.
    pub(super) fn poll_export(&mut self) {
        let Some(rx) = &self.export_result else {
            return;
        };
        let Ok(result) = rx.try_recv() else {
            return;
        };
        let lang = self.session.lang;
        self.note = Some(match result {
            Ok(files) => (
                true,
                lang.t_with(
                    "export-task-exported-to",
                    &[
                        ("dir", &self.export_dir),
                        (
                            "files",
                            &files
                                .iter()
                                .filter_map(|p| p.file_name())
                                .map(|n| n.to_string_lossy())
                                .collect::<Vec<_>>()
                                .join(lang.t("list-separator")),
                        ),
                    ],
                ),
            ),
            Err(e) => (false, e),
        });
        self.export_result = None;
    }
}

impl PipelensApp {
    /// **Export my work**: the open lesson's code last run at each step and what was typed into
    /// each answer, as one file (`LESSON-work.toml`) that `pipelens grade` reads — written into
    /// the Export menu's folder, or downloaded in the browser.
    pub(super) fn export_work(&mut self) {
        let lang = self.session.lang;
        let Some(player) = &self.session.lesson else {
            return;
        };
        let work = crate::app::progress::work(&self.session.progress, &player.lesson);
        let name = format!("{}-work.toml", player.lesson.id);
        let dir = PathBuf::from(self.export_dir.trim());
        let result = work.to_text().and_then(|text| {
            super::platform::download(&name, text.as_bytes(), "application/toml", (&dir, lang))
        });
        self.note = Some(match result {
            Ok(file) => (
                true,
                lang.t_with(
                    "export-task-your-work-saved",
                    &[("file", &file), ("steps", &work.steps.len())],
                ),
            ),
            Err(e) => (false, e),
        });
    }
}
