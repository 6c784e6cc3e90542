//! "New lesson": a lesson file of one's own, started from the scene on screen (with one step
//! recorded from what it shows), from a built-in lesson, or from a mesh file (the template with
//! the mesh in place of its sphere; a `.obj` dropped on the window fills it in). On the desktop
//! the file is written (never over an existing one) and opened, watched and edited; in the
//! browser it is opened and edited, and saving it is a download.

use std::path::{Path, PathBuf};

use egui::RichText;

use crate::app::session::Session;
use crate::lesson::{self, Document, library, start};
use crate::vocabulary::{Lang, Text};

/// What a new lesson starts from.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum From {
    /// The scene on screen and a step recorded from it.
    #[default]
    Screen,
    /// A built-in lesson, by the session's name for it (`lessons/05-perspective.toml (built in)`).
    Builtin(String),
    /// The template, with a mesh file.
    Mesh,
}

/// The "New lesson" part of the editor.
#[derive(Default)]
pub struct NewLesson {
    /// Whether it is unfolded.
    pub show: bool,
    /// What it starts from.
    pub from: From,
    /// Where it is written (a file name in the browser).
    pub path: String,
    /// The mesh file, for [`From::Mesh`].
    pub mesh: String,
}

/// A lesson made: the app opens it and the editor takes it up.
pub struct Made {
    /// The lesson, read back from its text.
    pub doc: Document,
    /// The session's name for it.
    pub source: String,
    /// The file it was written to (the desktop).
    pub file: Option<PathBuf>,
    /// Its text.
    pub text: String,
    /// What to tell the teacher.
    pub said: String,
}

impl NewLesson {
    /// The part, folded under its header; `Some` when a lesson was made (or failed to be).
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        current: Option<&str>,
    ) -> Option<Result<Made, String>> {
        if self.path.is_empty() {
            self.path = default_path();
        }
        let header = egui::CollapsingHeader::new(RichText::new(lang.t("new-new-lesson")).strong())
            .id_salt("new-lesson")
            .open(self.show.then_some(true))
            .show(ui, |ui| self.contents(ui, session, lang, current));
        if header.header_response.clicked() {
            self.show = !self.show;
        }
        header.body_returned.flatten()
    }

    fn contents(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        current: Option<&str>,
    ) -> Option<Result<Made, String>> {
        ui.radio_value(
            &mut self.from,
            From::Screen,
            lang.t("new-from-the-scene-on-screen"),
        );
        let builtin = matches!(self.from, From::Builtin(_));
        if ui
            .radio(builtin, lang.t("new-from-a-built-in-lesson"))
            .clicked()
            && !builtin
        {
            self.from = From::Builtin(session.source.clone());
        }
        if let From::Builtin(name) = &mut self.from {
            let shown = library::named(name).map_or("—", |(file, _)| file);
            egui::ComboBox::from_id_salt("new-lesson-builtin")
                .selected_text(shown)
                .show_ui(ui, |ui| {
                    for (file, _) in library::LESSONS {
                        ui.selectable_value(name, library::source_name(file), file);
                    }
                });
        }
        // A page cannot read a mesh from a path: it offers the meshes dropped on it.
        let on_disk = crate::app::platform::WRITES_FILES;
        if on_disk || !session.given.is_empty() {
            ui.radio_value(
                &mut self.from,
                From::Mesh,
                lang.t(if on_disk {
                    "new-from-a-mesh-of-your"
                } else {
                    "new-from-a-mesh-dropped"
                }),
            );
        }
        if self.from == From::Mesh && on_disk {
            ui.add(
                egui::TextEdit::singleline(&mut self.mesh)
                    .hint_text("/path/to/model.obj")
                    .desired_width(f32::INFINITY),
            );
        } else if self.from == From::Mesh {
            egui::ComboBox::from_id_salt("new-lesson-mesh")
                .selected_text(self.mesh.as_str())
                .show_ui(ui, |ui| {
                    for name in session.given.keys() {
                        ui.selectable_value(&mut self.mesh, name.clone(), name);
                    }
                });
        }
        ui.horizontal(|ui| {
            ui.label(if crate::app::platform::WRITES_FILES {
                lang.t("new-write-it-to")
            } else {
                lang.t("new-name")
            });
            ui.add(egui::TextEdit::singleline(&mut self.path).desired_width(f32::INFINITY));
        });
        ui.button(lang.t("new-make-the-lesson"))
            .clicked()
            .then(|| self.make(session, current))
    }

    /// The lesson's text, written (the desktop) and read back.
    fn make(&self, session: &Session, current: Option<&str>) -> Result<Made, String> {
        let lang = session.lang;
        let file = PathBuf::from(self.path.trim());
        let text = match &self.from {
            From::Screen => {
                let source = current.ok_or(lang.t("new-nothing-on-screen"))?;
                start::from_scene(source, &file, &first_step(session)?)?
            }
            // The lesson open, as it is on screen.
            From::Builtin(name) if *name == session.source && current.is_some() => {
                start::renamed(current.unwrap_or_default(), &file)?
            }
            From::Builtin(name) => {
                let (_, text) =
                    library::named(name).ok_or(lang.t("new-choose-a-built-in-lesson"))?;
                start::renamed(text, &file)?
            }
            From::Mesh => {
                let mesh = Path::new(self.mesh.trim());
                if self.mesh.trim().is_empty() {
                    return Err(lang.t("new-name-the-mesh-file").to_owned());
                }
                if crate::app::platform::WRITES_FILES {
                    start::from_mesh(&file, &super::file::mesh_from(&file, mesh))?
                } else if session.given.contains_key(self.mesh.trim()) {
                    start::from_mesh(&file, self.mesh.trim())?
                } else {
                    return Err(lang.t("new-drop-the-mesh").to_owned());
                }
            }
        };
        let (doc, file) = if crate::app::platform::WRITES_FILES {
            if file.exists() {
                return Err(lang.t_with("new-exists-already", &[("file", &file.display())]));
            }
            if let Some(dir) = file.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir).map_err(|e| {
                    lang.t_with("new-cannot-create", &[("dir", &dir.display()), ("why", &e)])
                })?;
            }
            let doc = lesson::parse_document(
                &text,
                &file.display().to_string(),
                file.parent().unwrap_or(Path::new(".")),
            )
            .map_err(|e| e.to_string())?;
            crate::export::write_atomically(&file, text.as_bytes(), lang)
                .map_err(|e| format!("{e:#}"))?;
            (doc, Some(file))
        } else {
            let folder = lesson::Folder::of_page(session.given.clone());
            let doc = lesson::parse_document_in(&text, &file.display().to_string(), &folder)
                .map_err(|e| e.to_string())?;
            (doc, None)
        };
        let source = file
            .as_ref()
            .map_or_else(|| self.path.trim().to_owned(), |f| f.display().to_string());
        Ok(Made {
            said: lang.t_with("new-made", &[("source", &source)]),
            doc,
            source,
            file,
            text,
        })
    }
}

/// The step on screen as a new lesson's first step: the step as it starts, with what the
/// teacher changed on screen, as `set` against the lesson's scene; the step's animations that
/// the teacher did not override, which it plays (a value an animation was passing through when
/// the lesson was made is the animation's, not one the teacher set); placeholder words for the
/// teacher to replace (`check` warns of each one left).
fn first_step(session: &Session) -> Result<lesson::Step, String> {
    let no_lesson = || session.lang.t("new-no-lesson-open").to_owned();
    let player = session.lesson.as_ref().ok_or_else(no_lesson)?;
    // What the teacher changed: what differs from the step as it plays now.
    let mut step = crate::app::record::recorded_step(session).ok_or_else(no_lesson)?;
    let mut start = player.lesson.spec_playing(player.step, 0.0);
    for (name, value) in &step.set {
        lesson::param::apply(&mut start, name, value)?;
    }
    step.animate = player
        .current()
        .animate
        .iter()
        .filter(|a| !step.set.iter().any(|(name, _)| *name == a.param))
        .cloned()
        .collect();
    step.set = lesson::param::differences(&player.lesson.scene, &start);
    let words = |[en, zh]: [&str; 2]| Text::new(en, zh);
    step.title = words(lesson::PLACEHOLDER_STEP_TITLE);
    step.narration = words(lesson::PLACEHOLDER_NARRATION);
    Ok(step)
}

/// `my-lesson.toml` in the folder the app was started in (a name only in the browser).
fn default_path() -> String {
    let name = "my-lesson.toml";
    if crate::app::platform::WRITES_FILES {
        std::env::current_dir()
            .map_or_else(|_| name.to_owned(), |d| d.join(name).display().to_string())
    } else {
        name.to_owned()
    }
}
