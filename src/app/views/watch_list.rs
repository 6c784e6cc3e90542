//! The debugger's watch list: expressions of the student's, each read just after the line of
//! the step shown, in the very run the debugger steps through — the fragment followed at the
//! inspected pixel, or the selected vertex, run again with the shader compiled with the watch
//! (`pipeline::watch_fragment`, `pipeline::watch_vertex`). A value stands from its store on,
//! so stepping back and forth shows each expression as the run had it at that step.

use std::sync::Arc;

use egui::{RichText, Ui};
use pipeline::shader::probe::WatchKind;
use pipeline::shader::{Stage, TraceLine};
use pipeline::{ReplayError, WatchRun};

use crate::app::session::Session;
use crate::vocabulary::Lang;

/// The expressions watched and what they were last read as.
#[derive(Default)]
pub struct WatchList {
    /// The expressions, as typed.
    pub entries: Vec<String>,
    /// The expression being typed.
    pub draft: String,
    /// What each entry read, with the run and line it was read in (read again only when
    /// those change).
    read: Option<(Key, Vec<Result<WatchRun, String>>)>,
}

/// What a reading depends on: the frame, the run followed, the line, the expressions.
#[derive(Clone, PartialEq, Eq)]
struct Key {
    /// The capture on screen: where it is and its generation (an address alone could be a
    /// new frame's where the old one was freed).
    frame: (usize, u64),
    stage: Stage,
    fragment: usize,
    vertex: Option<u32>,
    line: usize,
    entries: Vec<String>,
}

/// What the list shows of one entry at step `at`.
#[derive(Debug, PartialEq)]
pub enum Reading {
    /// Its value at the step: the value's type and components.
    Value(WatchKind, [f32; 4]),
    /// Up to the step, the run has not run the line.
    NotYet,
    /// It cannot be read there, and why.
    Cannot(String),
}

impl WatchList {
    /// Each entry as it stands at step `at` of `run` (the run of `stage` the debugger follows:
    /// fragment `fragment` of the inspected pixel, or the selected vertex), read just after
    /// the step's line.
    pub fn readings(
        &mut self,
        session: &Session,
        (stage, fragment): (Stage, usize),
        run: &[TraceLine],
        at: usize,
    ) -> Vec<Reading> {
        let Some(capture) = session.capture.clone() else {
            return Vec::new();
        };
        let Some(step) = run.get(at) else {
            return Vec::new();
        };
        let key = Key {
            frame: (Arc::as_ptr(&capture) as usize, session.shown_generation),
            stage,
            fragment,
            vertex: session.selection.vertex,
            line: step.line,
            entries: self.entries.clone(),
        };
        if self.read.as_ref().is_none_or(|(k, _)| *k != key) {
            let lang = session.lang;
            let scene = &session.spec.scene;
            let read = self
                .entries
                .iter()
                .map(|expression| {
                    let watched = (step.line, expression.as_str());
                    let ran = match stage {
                        Stage::Fragment => capture
                            .shaders
                            .as_ref()
                            .and_then(|s| s.pixel.get(fragment))
                            .ok_or(ReplayError::NotKept)
                            .and_then(|f| pipeline::watch_fragment(scene, &capture, f, watched)),
                        Stage::Vertex => session
                            .selection
                            .vertex
                            .ok_or(ReplayError::NotKept)
                            .and_then(|row| {
                                pipeline::watch_vertex(scene, &capture, row as usize, watched)
                            }),
                    };
                    ran.map_err(|e| why(&e, step.line, lang))
                })
                .collect();
            self.read = Some((key, read));
        }
        let Some((_, read)) = &self.read else {
            return Vec::new();
        };
        read.iter()
            .map(|r| match r {
                Err(why) => Reading::Cannot(why.clone()),
                Ok(run) => match (
                    run.kind,
                    run.stores.iter().rev().find(|(k, _)| *k <= at + 1),
                ) {
                    (Some(kind), Some((_, v))) => Reading::Value(kind, *v),
                    _ => Reading::NotYet,
                },
            })
            .collect()
    }
}

/// Why an expression cannot be read after `line`, in the reader's language (the compiler's
/// own message kept as it is).
fn why(e: &ReplayError, line: usize, lang: Lang) -> String {
    match e {
        ReplayError::NotKept => lang.t("watch-list-no-run-is-kept-here").to_owned(),
        ReplayError::Input(name) => lang.t_with("watch-list-undeclared-input", &[("name", name)]),
        ReplayError::Watch(e) => {
            lang.t_with("watch-list-not-readable", &[("line", &line), ("why", e)])
        }
        ReplayError::Run(e) => e.to_string(),
    }
}

/// The watch list under the variables at the step: each entry with its value (a colour with
/// its swatch) or why it has none, a button to take it off, and a field to add one (Enter).
pub fn ui(
    ui: &mut Ui,
    list: &mut WatchList,
    session: &Session,
    (stage, fragment): (Stage, usize),
    run: &[TraceLine],
    at: usize,
) {
    let lang = session.lang;
    let line = run.get(at).map_or(0, |t| t.line);
    let readings = list.readings(session, (stage, fragment), run, at);
    egui::CollapsingHeader::new(format!(
        "{} ({} {line})",
        lang.t("watch-list-watch-list"),
        lang.t("watch-list-after-line")
    ))
    .id_salt("debugger watch list")
    .default_open(true)
    .show(ui, |ui| {
        let mut remove = None;
        for (i, (expression, reading)) in list.entries.iter().zip(&readings).enumerate() {
            ui.horizontal(|ui| {
                if ui
                    .add(crate::app::style::glyph_button(ui, "×", None))
                    .on_hover_text(lang.t("watch-list-take-it-off-the-list"))
                    .clicked()
                {
                    remove = Some(i);
                }
                match reading {
                    Reading::Value(kind, v) => {
                        let value = pipeline::shader::Value {
                            ty: kind.glsl().to_owned(),
                            numbers: v[..kind.components()]
                                .iter()
                                .map(|c| f64::from(*c))
                                .collect(),
                        };
                        if let Some(c) = pipeline::shader::stepping::colour(&value) {
                            let (rect, _) = ui
                                .allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
                            ui.painter()
                                .rect_filled(rect, 2.0, super::palette::swatch(c));
                        }
                        ui.label(
                            RichText::new(format!(
                                "{expression} = {}",
                                super::watch_picture::value_words(*kind, *v)
                            ))
                            .monospace(),
                        );
                    }
                    Reading::NotYet => {
                        ui.label(
                            RichText::new(format!(
                                "{expression}: {}",
                                lang.t("watch-list-up-to-this-step-the")
                            ))
                            .monospace()
                            .weak(),
                        );
                    }
                    Reading::Cannot(why) => {
                        ui.label(RichText::new(expression).monospace());
                        ui.label(RichText::new(why).color(ui.visuals().warn_fg_color));
                    }
                }
            });
        }
        if let Some(i) = remove {
            list.entries.remove(i);
        }
        ui.horizontal(|ui| {
            let label = ui.label(lang.t("watch-list-add"));
            // Wide enough for its hint in any language (220 points at least), within the row.
            let hint = lang.t("watch-list-an-expression-e-g-dot");
            let mono = egui::TextStyle::Monospace.resolve(ui.style());
            let hint_width = ui
                .painter()
                .layout_no_wrap(hint.to_owned(), mono, egui::Color32::WHITE)
                .size()
                .x;
            let width = (hint_width + 2.0 * ui.spacing().button_padding.x)
                .max(220.0)
                .min(ui.available_width());
            let field = ui
                .add(
                    egui::TextEdit::singleline(&mut list.draft)
                        .id_salt("watch list expression")
                        .hint_text(hint)
                        .font(egui::TextStyle::Monospace)
                        .desired_width(width),
                )
                .labelled_by(label.id)
                .on_hover_text(lang.t("watch-list-any-expression-of-this-shader"));
            let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            let added = ui.button(lang.t("watch-list-watch")).clicked();
            if (entered || added) && !list.draft.trim().is_empty() {
                list.entries.push(list.draft.trim().to_owned());
                list.draft.clear();
                if entered {
                    field.request_focus();
                }
            }
        });
    });
}
