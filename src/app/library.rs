//! Opening another lesson: the Lessons menu (every built-in lesson, by title in the interface's
//! language) and a lesson or scene file dropped on the window (on the desktop its path is then
//! watched for live reload; in the browser its bytes are read, and nothing is watched).

use crate::app::views::shader::Tab;
use pipeline::shader::HookKind;
use std::sync::OnceLock;

use egui::RichText;

use super::PipelensApp;
use crate::lesson::{self, Document, library};
use crate::vocabulary::{Lang, Text};

/// The built-in lessons' titles and how many of their questions ask for a typed value, read
/// once.
fn titles() -> &'static [(Text, usize)] {
    static TITLES: OnceLock<Vec<(Text, usize)>> = OnceLock::new();
    TITLES.get_or_init(|| {
        library::LESSONS
            .iter()
            .map(|(file, text)| (library::title(text, file), library::typed_questions(text)))
            .collect()
    })
}

impl PipelensApp {
    /// The Lessons ▾ menu: every built-in lesson; the one open is marked.
    pub(super) fn lessons_menu(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let open_id = self.session.lesson.as_ref().map(|p| p.lesson.id.clone());
        let mut chosen = None;
        ui.menu_button(lang.t("library-lessons"), |ui| {
            for ((file, _), (title, asks)) in library::LESSONS.iter().zip(titles()) {
                let id = file.trim_end_matches(".toml");
                let title = title.get(lang);
                let number = id.split('-').next().unwrap_or_default();
                // The questions answered right, of those with a value to type.
                let done = self
                    .session
                    .progress
                    .of(id)
                    .map_or(0, |p| p.answered.union(&p.passed).count());
                let label = match (*asks, done) {
                    (0, _) => format!("{number}  {title}"),
                    (n, d) if d >= n => format!(
                        "{number}  {title}   {n}/{n} {}",
                        lang.t("library-all-right")
                    ),
                    (n, d) => format!("{number}  {title}   {d}/{n}"),
                };
                if ui
                    .selectable_label(open_id.as_deref() == Some(id), label)
                    .on_hover_text(lang.t("library-d-n-questions-you-answered"))
                    .clicked()
                {
                    chosen = Some(*file);
                    ui.close();
                }
            }
            ui.separator();
            // In the menu, not the bar: the bar must stay one row at 1366 points.
            if ui
                .button(lang.t("library-edit-this-lesson-or-make"))
                .on_hover_text(lang.t("library-record-what-is-on-screen"))
                .clicked()
            {
                self.editor.open = true;
                ui.close();
            }
            let hint = if super::platform::WATCHES_FILES {
                lang.t("library-your-own-lesson-or-scene")
            } else {
                lang.t("library-your-own-lesson-or-scene-2")
            };
            ui.label(RichText::new(hint).small());
        })
        .response
        .on_hover_text(lang.t("library-open-another-built-in-lesson"));
        if let Some(file) = chosen {
            match library::lesson(file) {
                Ok(l) => self.open(
                    Document::Lesson(Box::new(l)),
                    &library::source_name(file),
                    None,
                ),
                Err(e) => self.session.error = Some(e.to_string()),
            }
        }
    }

    /// Opens a lesson or scene file dropped on the window: on the desktop from its path (and
    /// watches it); in the browser from its bytes, read in the background and opened on a later
    /// frame. A file that does not load keeps the current one running and says why. A shader
    /// (`.vert`, `.frag`) goes into the shader panel instead — a student's saved exercise code
    /// loaded back — and runs when it compiles. A mesh (`.obj`) becomes a new lesson in the
    /// editor; in the browser it is also kept for the lessons dropped with it or after it that
    /// name it, as a texture (`.png`, `.jpg`) is.
    pub(super) fn open_dropped(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        for file in dropped {
            let path = file.path().to_path_buf();
            let name = path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            if let Some(why) = not_opened(&name, self.session.lang) {
                self.refused(&name, &why);
            } else if path.is_absolute() && is_texture(&name) {
                // On the desktop a lesson reads its texture from beside it.
                let why = self
                    .session
                    .lang
                    .t_with("library-a-texture-on-the-desktop", &[("name", &name)]);
                self.refused(&name, &why);
            } else if path.is_absolute() && is_mesh(&name) {
                // A mesh of one's own: a new lesson on it, in the editor.
                self.offer_lesson_from_mesh(&path.display().to_string());
            } else if path.is_absolute() && shader_stage(&path.display().to_string()).is_some() {
                let name = path.display().to_string();
                let text = std::fs::read(&path).map_err(|e| cannot_read(&e, self.session.lang));
                self.load_shader(&name, text);
            } else if path.is_absolute() {
                let loaded = lesson::load_file(&path);
                self.opened(loaded, &path.display().to_string(), Some(path));
            } else {
                self.inbox.read(file, ctx);
            }
        }
        let mut read = self.inbox.take();
        // The meshes and textures first: a lesson dropped with them names them.
        let named = |name: &str| is_mesh(name) || is_texture(name);
        read.sort_by_key(|(name, _)| !named(name));
        let with_lesson = read.iter().any(|(name, _)| !named(name));
        for (name, bytes) in read {
            if is_mesh(&name) {
                self.keep_mesh(&name, bytes, !with_lesson);
                continue;
            }
            if is_texture(&name) {
                self.keep_texture(&name, bytes, !with_lesson);
                continue;
            }
            if shader_stage(&name).is_some() {
                self.load_shader(&name, bytes.map_err(|e| cannot_read(&e, self.session.lang)));
                continue;
            }
            let text = bytes
                .map_err(|e| cannot_read(&e, self.session.lang))
                .and_then(|b| {
                    String::from_utf8(b)
                        .map_err(|_| self.session.lang.t("library-not-text").to_owned())
                })
                .map_err(|e| lesson::Diagnostics(vec![lesson::Diagnostic::whole_file(&name, e)]));
            let folder = lesson::Folder::of_page(self.session.given.clone());
            let loaded = text
                .as_ref()
                .map_err(Clone::clone)
                .and_then(|text| lesson::parse_document_in(text, &name, &folder));
            let is_lesson = matches!(loaded, Ok(Document::Lesson(_)));
            self.opened(loaded, &name, None);
            // In the browser the editor edits the dropped text; saving it is a download.
            if let (true, Ok(text)) = (is_lesson, text) {
                let lang = self.session.lang;
                self.editor
                    .adopt(&name, None, text, &self.session.given, lang);
            }
        }
    }

    /// Keeps a file dropped on the page in the session's `given`, for the lessons dropped with
    /// it or after it that name it, when `reads` reads its bytes (a mesh, a texture); says why
    /// not otherwise. Whether it was kept.
    fn keep_given(
        &mut self,
        name: &str,
        bytes: Result<Vec<u8>, String>,
        reads: impl FnOnce(&[u8]) -> Result<(), String>,
    ) -> bool {
        let lang = self.session.lang;
        let read = bytes
            .map_err(|e| cannot_read(&e, lang))
            .and_then(|b| reads(&b).map(|()| b));
        match read {
            Ok(bytes) => {
                self.session.given.insert(name.to_owned(), bytes.into());
                true
            }
            Err(e) => {
                self.refused(name, &e);
                false
            }
        }
    }

    /// Keeps a mesh dropped on the page when it reads as one; `offer`: the editor opens on a
    /// new lesson made from it (it was dropped alone).
    fn keep_mesh(&mut self, name: &str, bytes: Result<Vec<u8>, String>, offer: bool) {
        let parse = |b: &[u8]| {
            let mesh = pipeline::mesh::Mesh::parse_obj(&mut &b[..], name, name);
            mesh.map(|_| ()).map_err(|e| e.to_string())
        };
        if self.keep_given(name, bytes, parse) && offer {
            self.offer_lesson_from_mesh(name);
        }
    }

    /// Keeps a texture (PNG, JPEG) dropped on the page when it decodes; `alone` (no lesson
    /// dropped with it): a note under the bar says so, since nothing else on the screen changes.
    fn keep_texture(&mut self, name: &str, bytes: Result<Vec<u8>, String>, alone: bool) {
        let decode = |b: &[u8]| {
            let texture = pipeline::texture::Texture::decode(name, b);
            texture.map(|_| ()).map_err(|e| e.to_string())
        };
        if self.keep_given(name, bytes, decode) && alone {
            let words = (self.session.lang).t_with("library-texture-kept", &[("name", &name)]);
            self.note = Some((true, words));
        }
    }

    /// Opens the editor on "New lesson" from the mesh `mesh` (a path on the desktop, the name
    /// of a mesh dropped on a page), for the teacher to name the lesson and make it.
    fn offer_lesson_from_mesh(&mut self, mesh: &str) {
        self.editor.new.from = super::editor::From::Mesh;
        self.editor.new.mesh = mesh.to_owned();
        self.editor.new.show = true;
        self.editor.open = true;
    }

    /// Puts a dropped shader file's source in the shader panel's tab for its stage and runs it
    /// (when it does not compile, the panel shows where, and the picture stays).
    fn load_shader(&mut self, name: &str, bytes: Result<Vec<u8>, String>) {
        let Some(tab) = shader_stage(name) else {
            return;
        };
        let lang = self.session.lang;
        let text = bytes.and_then(|b| {
            String::from_utf8(b)
                .map_err(|_| lang.t_with("library-shader-not-text", &[("name", &name)]))
        });
        match text {
            Ok(text) => {
                let editor = &mut self.shader_editor;
                // The other stage stays what the scene runs (an exercise's starter, say).
                editor.load(&self.session);
                match tab {
                    Tab::Shader(pipeline::shader::Stage::Vertex) => editor.vertex = text,
                    Tab::Shader(pipeline::shader::Stage::Fragment) => editor.fragment = text,
                    Tab::Hook(kind) => editor.set_hook(kind, text),
                }
                if let Tab::Shader(_) = tab {
                    editor.shaders_in_use = true;
                }
                editor.tab = tab;
                self.panels.shader = true;
                if let Some(c) = editor.apply(&self.session) {
                    self.commands.push(c);
                }
            }
            Err(e) => self.refused(name, &e),
        }
    }

    /// Says under the bar that the dropped file `name` did not open, and `why`: "lesson.toml
    /// could not be opened; what was open keeps running:" over the reader's words.
    fn refused(&mut self, name: &str, why: &str) {
        let file = std::path::Path::new(name)
            .file_name()
            .map_or_else(|| name.to_owned(), |n| n.to_string_lossy().into_owned());
        let heading = self
            .session
            .lang
            .t_with("library-could-not-be-opened", &[("file", &file)]);
        self.session.dropped_error = Some(format!(
            "{heading}
{why}"
        ));
    }

    /// Opens what was loaded, or shows why it was not.
    fn opened(
        &mut self,
        loaded: Result<Document, lesson::Diagnostics>,
        name: &str,
        path: Option<std::path::PathBuf>,
    ) {
        match loaded {
            Ok(doc) => self.open(doc, name, path),
            Err(e) => self.refused(name, &e.to_string()),
        }
    }

    /// The editor's part of a frame: a drag that ended recorded, the lesson open followed, the
    /// window, and a lesson just made opened.
    pub(super) fn edit_lesson(&mut self, ui: &mut egui::Ui) {
        if !self.session.drafting
            && let Some(from) = self.session.drag_from.take()
        {
            self.editor.dragged(&from, &self.session.spec);
        }
        let file = self.watched.as_ref().map(|w| w.path().to_path_buf());
        self.editor.follow(&self.session, file.as_deref());
        let room = self.room();
        let commands = self.editor.ui(ui, &self.session, room);
        self.commands.extend(commands);
        if let Some(made) = self.editor.made.take() {
            self.open(made.doc, &made.source, made.file.clone());
            self.editor.adopt(
                &made.source,
                made.file.as_deref(),
                made.text,
                &self.session.given,
                self.session.lang,
            );
        }
    }
    /// Puts `doc` (named `source`) in place of what is open; a file on disk is watched.
    pub(super) fn open(&mut self, doc: Document, source: &str, path: Option<std::path::PathBuf>) {
        self.session.open(doc, source);
        self.note = None;
        self.panels = super::Panels::for_mode(self.presenting());
        self.watched = None;
        if let Some(path) = path {
            self.watch(path);
        }
    }
}

/// Why a file named `name` dropped on the window is not opened, when its kind is one pipelens
/// does not open: a lesson or scene is a `.toml` file, a shader a `.vert`, `.frag` or
/// pipeline-function `.glsl`, a mesh (`.obj`) becomes a new lesson in the editor, and a page
/// keeps a texture (`.png`, `.jpg`) for the lesson that names it. A name without an extension
/// is read as a lesson. Said in `lang`.
fn not_opened(name: &str, lang: Lang) -> Option<String> {
    let lower = name.to_ascii_lowercase();
    let extension = std::path::Path::new(&lower)
        .extension()
        .and_then(|e| e.to_str())?
        .to_owned();
    match extension.as_str() {
        "toml" | "vert" | "frag" | "glsl" | "obj" | "png" | "jpg" | "jpeg" => None,
        _ => Some(lang.t_with(
            "library-not-a-kind-pipelens-opens",
            &[("name", &name), ("extension", &extension)],
        )),
    }
}

/// Whether the file named `name` is a texture pipelens decodes (`.png`, `.jpg`, `.jpeg`).
fn is_texture(name: &str) -> bool {
    std::path::Path::new(name)
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| {
            ["png", "jpg", "jpeg"]
                .iter()
                .any(|t| e.eq_ignore_ascii_case(t))
        })
}

/// Whether the file named `name` is a mesh (`.obj`).
fn is_mesh(name: &str) -> bool {
    std::path::Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

/// The shader stage a file's name says (`.vert`, `.frag`), if it names one.
fn shader_stage(name: &str) -> Option<Tab> {
    let lower = name.to_ascii_lowercase();
    let stem = std::path::Path::new(&lower)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or_default()
        .to_owned();
    if lower.ends_with(".vert") {
        Some(Tab::Shader(pipeline::shader::Stage::Vertex))
    } else if lower.ends_with(".frag") {
        Some(Tab::Shader(pipeline::shader::Stage::Fragment))
    } else if lower.ends_with(".glsl") {
        // A function the pipeline calls, saved by the panel as `inside.glsl`, `depth_test.glsl`.
        HookKind::ALL
            .into_iter()
            .find(|k| stem == k.key())
            .map(Tab::Hook)
    } else {
        None
    }
}

/// "cannot read the file: why", in `lang`.
fn cannot_read(e: &impl std::fmt::Display, lang: Lang) -> String {
    lang.t_with("library-cannot-read-the-file", &[("why", &e.to_string())])
}
