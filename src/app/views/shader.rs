//! The shader panel: the vertex and fragment shaders of the scene as source the student edits,
//! and the functions of the rasterizer the scene runs (an exercise of the inside or depth test), with
//! line numbers, highlighting and each message under the tabs with its line. A source that
//! compiles is applied as one types (or on Ctrl+Enter); one that does not keeps the last good
//! picture on screen. The source lives in the app (in the browser too, in the page).

use std::sync::Arc;

use egui::{Color32, RichText, Ui};
use pipeline::scene::ObjectShader;
use pipeline::shader::{
    self, BUILTIN_FRAGMENT, BUILTIN_VERTEX, HookKind, Programs, ShaderError, Stage, StageError,
};

use crate::app::command::SceneCommand;
use crate::app::session::{Command, Session};
use crate::vocabulary::Lang;

pub use super::shader_tabs::Tab;

/// The panel's state: the sources, the tab shown, the messages of the last compile.
pub struct ShaderEditor {
    /// The tab shown.
    pub tab: Tab,
    /// The vertex shader's source.
    pub vertex: String,
    /// The fragment shader's source.
    pub fragment: String,
    /// The functions the pipeline calls that the scene runs, with their sources.
    pub hooks: Vec<HookEdit>,
    /// Whether the shaders draw the picture (the scene ran them, or the student applied or
    /// edited them): an exercise of the inside test alone leaves pipelens' own shading.
    pub shaders_in_use: bool,
    /// The messages of the last compile (empty: it compiled).
    pub errors: Vec<StageError>,
    /// What the last Save did: the files written (or downloaded), or why it failed.
    saved: Option<Result<String, String>>,
    /// The programs the sources were last taken from or applied as: when the scene's differ (a
    /// lesson step brought its own), the sources are taken from the scene again.
    shown: Option<Arc<Programs>>,
    /// The language the sources' comments were last put in: when the interface's changes, the
    /// sources not edited since are shown in the new one.
    shown_in: Option<Lang>,
    /// The debugger: the step shown of the run at the inspected pixel or vertex, breakpoints.
    pub debugger: super::debugger::Debugger,
    /// The student's sources before "pipelens' own" replaced them, until they edit again.
    pub before_own: Option<(String, String)>,
}

/// A function the pipeline calls, as the student edits it.
pub struct HookEdit {
    /// Which function.
    pub kind: HookKind,
    /// Its source.
    pub source: String,
    /// Its messages of the last compile.
    pub errors: Vec<ShaderError>,
    /// The source last taken from the scene or applied.
    shown: String,
}

impl HookEdit {
    /// The function `kind` as the scene runs it (`running`), shown as `source` (its comments
    /// in the interface's language).
    fn new(kind: HookKind, running: &str, source: String) -> Self {
        Self {
            kind,
            shown: running.to_owned(),
            source,
            errors: Vec::new(),
        }
    }
}

impl Default for ShaderEditor {
    fn default() -> Self {
        Self {
            tab: Tab::Shader(Stage::Fragment),
            vertex: BUILTIN_VERTEX.to_owned(),
            fragment: BUILTIN_FRAGMENT.to_owned(),
            hooks: Vec::new(),
            shaders_in_use: false,
            errors: Vec::new(),
            saved: None,
            shown: None,
            shown_in: None,
            debugger: super::debugger::Debugger::default(),
            before_own: None,
        }
    }
}

impl ShaderEditor {
    /// Compiles the sources in use; when they all compile (and the shaders link), the command
    /// that gives every object of the scene this code, else the messages are kept and nothing
    /// changes.
    pub fn apply(&mut self, session: &Session) -> Option<Command> {
        let mut spec = session.spec.clone();
        self.errors.clear();
        for h in &mut self.hooks {
            h.errors.clear();
        }
        if self.shaders_in_use || spec.scene.has_shaders() {
            match shader::link(Some(&self.vertex), Some(&self.fragment)) {
                Ok(programs) => {
                    let programs = Arc::new(programs);
                    self.shown = Some(Arc::clone(&programs));
                    self.shaders_in_use = true;
                    spec.scene.set_shaders(&ObjectShader {
                        programs,
                        time: 0.0,
                    });
                }
                Err(e) => self.errors = e,
            }
        }
        for h in &mut self.hooks {
            match shader::compile_hook(h.kind, &h.source) {
                Ok(hook) => {
                    h.shown.clone_from(&h.source);
                    spec.scene.set_hook(&hook);
                }
                Err(e) => h.errors = e,
            }
        }
        self.compiles()
            .then(|| Command::Scene(SceneCommand::SetSpec(Box::new(spec))))
    }

    /// Whether every source compiled when last applied (no messages).
    #[must_use]
    pub fn compiles(&self) -> bool {
        self.errors.is_empty() && self.hooks.iter().all(|h| h.errors.is_empty())
    }

    /// Puts `source` in the tab of the function `kind` (opening it), to be applied.
    pub fn set_hook(&mut self, kind: HookKind, source: String) {
        match self.hooks.iter_mut().find(|h| h.kind == kind) {
            Some(h) => h.source = source,
            None => {
                let mut h = HookEdit::new(kind, &source, source.clone());
                // Not yet what the scene runs: `load` must not take it back.
                h.shown = String::new();
                self.hooks.push(h);
                self.hooks.sort_by_key(|h| h.kind as u8);
            }
        }
    }

    /// Takes the scene's own code (its first object's) when it is not the code shown, its
    /// comments in the interface's language.
    pub(crate) fn load(&mut self, session: &Session) {
        let objects = &session.spec.scene.objects;
        let none = std::collections::BTreeMap::new();
        let table = session
            .lesson
            .as_ref()
            .map_or(&none, |p| &p.lesson.comments);
        let local = |source: &str| crate::vocabulary::glsl::localize(source, session.lang, table);
        // The sources start as pipelens' own in English; when the language changes, what was
        // not edited is shown in the new one.
        let before = self.shown_in.unwrap_or(Lang::EN);
        if before != session.lang {
            let was = |source: &str| crate::vocabulary::glsl::localize(source, before, table);
            let (vertex, fragment) = self
                .shown
                .as_ref()
                .map_or((BUILTIN_VERTEX, BUILTIN_FRAGMENT), |p| {
                    (p.vertex.source.as_str(), p.fragment.source.as_str())
                });
            for (text, source) in [(&mut self.vertex, vertex), (&mut self.fragment, fragment)] {
                if *text == was(source) {
                    *text = local(source);
                }
            }
            for h in &mut self.hooks {
                if h.source == was(&h.shown) {
                    h.source = local(&h.shown);
                }
            }
        }
        self.shown_in = Some(session.lang);
        for kind in HookKind::ALL {
            let running = session.spec.scene.hook(kind).map(|h| h.source.clone());
            let at = self.hooks.iter().position(|h| h.kind == kind);
            match (running, at) {
                // A step without this function: its tab goes.
                (None, Some(k)) => {
                    self.hooks.remove(k);
                    if self.tab == Tab::Hook(kind) {
                        self.tab = Tab::Shader(Stage::Fragment);
                    }
                }
                (Some(source), Some(k)) if self.hooks[k].shown != source => {
                    self.hooks[k] = HookEdit::new(kind, &source, local(&source));
                    self.tab = Tab::Hook(kind);
                }
                (Some(source), None) => {
                    self.hooks
                        .push(HookEdit::new(kind, &source, local(&source)));
                    self.hooks.sort_by_key(|h| h.kind as u8);
                    self.tab = Tab::Hook(kind);
                }
                _ => {}
            }
        }
        let Some(sh) = objects.iter().find_map(|o| o.code.shader.as_ref()) else {
            if self.shown.take().is_some() {
                // Back to pipelens' own shading (a step without shaders).
                self.shaders_in_use = false;
            }
            return;
        };
        if self
            .shown
            .as_ref()
            .is_some_and(|p| Arc::ptr_eq(p, &sh.programs))
        {
            return;
        }
        self.vertex = local(&sh.programs.vertex.source);
        self.fragment = local(&sh.programs.fragment.source);
        self.errors.clear();
        self.shaders_in_use = true;
        // Open on the stage the step wrote: a vertex shader of its own beside pipelens'
        // fragment stage (a matrix lab) is on the vertex tab, and so is a lab whose TODO is in
        // its vertex shader only (Gouraud shading).
        if matches!(self.tab, Tab::Shader(_)) {
            // The sources as written, not as shown (their comments are in the reader's
            // language).
            let own = |source: &str, shipped: &[&str]| shipped.contains(&source);
            let vertex_shipped = own(&sh.programs.vertex.source, &shader::SHIPPED_VERTEX);
            let fragment_shipped = own(&sh.programs.fragment.source, &shader::SHIPPED_FRAGMENT);
            let todo_in_vertex = self.vertex.contains("TODO") && !self.fragment.contains("TODO");
            self.tab = Tab::Shader(if (!vertex_shipped && fragment_shipped) || todo_in_vertex {
                Stage::Vertex
            } else {
                Stage::Fragment
            });
        }
        self.shown = Some(Arc::clone(&sh.programs));
    }
}

/// The panel. Returns the command that applies the shaders, when they changed and compile,
/// and the debugger's (a watch, a pixel inspected). Save writes the sources into `save_dir`
/// (in the browser: downloads them). `small`: on a small screen's Code tab, with the key of
/// the GLSL row tapped this frame (`glsl_keys`), typed into the source shown.
pub fn ui(
    ui: &mut Ui,
    editor: &mut ShaderEditor,
    session: &Session,
    (save_dir, small): (&std::path::Path, Option<Option<&str>>),
) -> Vec<Command> {
    let key = small.flatten();
    let small = small.is_some();
    let lang = session.lang;
    editor.load(session);
    let mut apply = false;
    let tabs: Vec<(Tab, bool)> = (editor.hooks.iter())
        .map(|h| (Tab::Hook(h.kind), !h.errors.is_empty()))
        .chain([Stage::Vertex, Stage::Fragment].map(|stage| {
            let failed = editor.errors.iter().any(|e| e.stage == stage);
            (Tab::Shader(stage), failed)
        }))
        .collect();
    super::shader_tabs::tabs(ui, &mut editor.tab, &tabs, lang);
    ui.horizontal(|ui| {
        apply |= ui
            .button(lang.t("shader-apply"))
            .on_hover_text(lang.t("shader-compile-and-draw-with-these"))
            .clicked();
        apply |= own_or_back(ui, editor, session);
        if ui
            .button(lang.t("shader-save"))
            .on_hover_text(lang.t("shader-writes-shader-vert-and-shader"))
            .clicked()
        {
            editor.saved = Some(save(editor, save_dir, lang));
        }
    });
    message_space(ui, editor, session);
    let tuned = super::own_uniforms::controls(ui, session);
    let tab = editor.tab;
    let hook = match tab {
        Tab::Hook(kind) => editor.hooks.iter().position(|h| h.kind == kind),
        Tab::Shader(_) => None,
    };
    // Each message as a sentence in the interface's language, at its line.
    let said = |e: &pipeline::shader::ShaderError| {
        crate::vocabulary::compile::complaint(&e.complaint, lang)
            .unwrap_or_else(|| e.message.clone())
    };
    let (source, errors): (&mut String, Vec<(usize, String)>) = match hook {
        Some(k) => {
            let h = &mut editor.hooks[k];
            let errors = h.errors.iter().map(|e| (e.line, said(e))).collect();
            (&mut h.source, errors)
        }
        None => {
            // A function's tab whose function is gone (never shown so): the fragment shader.
            let stage = match tab {
                Tab::Shader(stage) => stage,
                Tab::Hook(_) => Stage::Fragment,
            };
            let source = match stage {
                Stage::Vertex => &mut editor.vertex,
                Stage::Fragment => &mut editor.fragment,
            };
            let errors = editor
                .errors
                .iter()
                .filter(|e| e.stage == stage)
                .map(|e| (e.error.line, said(&e.error)))
                .collect();
            (source, errors)
        }
    };
    let errors: Vec<(usize, &str)> = errors.iter().map(|(l, m)| (*l, m.as_str())).collect();
    let stage = match tab {
        Tab::Shader(stage) => Some(stage),
        Tab::Hook(_) => None,
    };
    let (marks, watched) = debugger(ui, &mut editor.debugger, (stage, session), small);
    let name = format!(
        "{}{}",
        super::shader_tabs::tab_name(tab, session.lang),
        session.lang.t("shader-source")
    );
    let (touched, typed) = typed_code(
        ui,
        (source, &format!("{tab:?}"), &name),
        (&errors, &marks),
        key,
        session.lang,
    );
    let edited = touched.changed || typed;
    if touched.cursor_line.is_some() {
        editor.debugger.cursor_line = touched.cursor_line;
    }
    if let (Some(line), Tab::Shader(stage)) = (touched.gutter, tab) {
        editor.debugger.breakpoints.toggle(stage, line);
    }
    if edited {
        // Their own edit: what "pipelens' own" replaced is no longer one click away.
        editor.before_own = None;
    }
    if edited && matches!(tab, Tab::Shader(_)) {
        editor.shaders_in_use = true;
    }
    apply |= crate::app::shortcuts::pressed(ui.ctx(), crate::app::shortcuts::Action::ApplyShaders);
    let applied = if edited || apply {
        editor.apply(session)
    } else {
        None
    };
    applied.into_iter().chain(watched).chain(tuned).collect()
}

/// The debugger over the source of `stage` (see `debugger::panel`); on a small screen's Code
/// tab (`small`) folded away, one tap to open: the code is what that screen is for.
fn debugger(
    ui: &mut Ui,
    debugger: &mut super::debugger::Debugger,
    (stage, session): (Option<Stage>, &Session),
    small: bool,
) -> (super::shader_source::Marks, Option<Command>) {
    if !small {
        return super::debugger::panel(ui, debugger, stage, session);
    }
    egui::CollapsingHeader::new(session.lang.t("shader-debugger"))
        .id_salt("debugger-fold")
        .default_open(false)
        .show(ui, |ui| {
            super::debugger::panel(ui, debugger, stage, session)
        })
        .body_returned
        .unwrap_or_default()
}

/// The source of the tab `tab` (named `name`), with its messages and marks; `key`, a key of
/// the GLSL row tapped this frame, typed into it first where its cursor is. The tap on the key
/// is not a tap away from the source: it keeps the keyboard. Returns what the reader did in
/// the source, and whether the key typed.
fn typed_code(
    ui: &mut Ui,
    (source, tab, name): (&mut String, &str, &str),
    (errors, marks): (&[(usize, &str)], &super::shader_source::Marks),
    key: Option<&str>,
    lang: Lang,
) -> (super::shader_source::Touched, bool) {
    let id = super::shader_source::source_id(tab);
    let typed = key.is_some_and(|k| super::glsl_keys::type_into(ui.ctx(), id, source, k));
    let surrender = ui.ctx().options(|o| o.input_options.surrender_focus_on);
    if key.is_some() {
        ui.ctx().options_mut(|o| {
            o.input_options.surrender_focus_on = egui::SurrenderFocusOn::Never;
        });
    }
    let touched = super::shader_source::code(ui, (source, tab, name), errors, marks, lang);
    ui.ctx()
        .options_mut(|o| o.input_options.surrender_focus_on = surrender);
    (touched, typed)
}

/// The messages (a Save's, the last compile's) in a space of their own, two lines high and
/// scrolled beyond: the code under them never moves as they come and go, and a tap lands on
/// the line it aims at.
fn message_space(ui: &mut Ui, editor: &ShaderEditor, session: &Session) {
    let lang = session.lang;
    let height = 2.0 * ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
    let (space, _) = ui.allocate_exact_size(
        egui::vec2(ui.available_width(), height),
        egui::Sense::hover(),
    );
    ui.scope_builder(egui::UiBuilder::new().max_rect(space), |ui| {
        egui::ScrollArea::vertical()
            .id_salt("shader messages")
            .auto_shrink([false, false])
            .show(ui, |ui| {
                match &editor.saved {
                    Some(Ok(files)) => {
                        ui.label(format!("{} {files}", lang.t("shader-saved")));
                    }
                    Some(Err(e)) => {
                        ui.colored_label(ui.visuals().error_fg_color, e);
                    }
                    None => {}
                }
                messages(ui, editor, session, lang);
            });
    });
}

/// "pipelens' own": the shading of the current settings as GLSL in place of the student's,
/// their code kept one click away ("Back to your code") until they edit again. Returns
/// whether the sources changed.
fn own_or_back(ui: &mut Ui, editor: &mut ShaderEditor, session: &Session) -> bool {
    let lang = session.lang;
    if let Some((vertex, fragment)) = editor.before_own.clone()
        && ui
            .button(lang.t("shader-back-to-your-code"))
            .on_hover_text(lang.t("shader-puts-back-the-code-you"))
            .clicked()
    {
        editor.vertex = vertex;
        editor.fragment = fragment;
        editor.before_own = None;
        return true;
    }
    if !ui
        .button(lang.t("shader-pipelens-own"))
        .on_hover_text(lang.t("shader-start-again-from-pipelens-own"))
        .clicked()
    {
        return false;
    }
    let s = &session.spec.settings;
    // One pair for every object: that of the object the lesson is about (the first with a
    // bump or normal map, else the first the lights reach).
    let objects = &session.spec.scene.objects;
    let subject = objects
        .iter()
        .find(|o| o.detail.is_some())
        .or_else(|| objects.iter().find(|o| o.lit))
        .or(objects.first());
    let (vertex, fragment) = subject
        .and_then(|o| shader::builtin_sources(s.shading, s.reflection, o.surface()))
        .unwrap_or((BUILTIN_VERTEX, BUILTIN_FRAGMENT));
    let none = std::collections::BTreeMap::new();
    let local = |s| crate::vocabulary::glsl::localize(s, session.lang, &none);
    let (vertex, fragment) = (local(vertex), local(fragment));
    if (vertex.as_str(), fragment.as_str()) != (editor.vertex.as_str(), editor.fragment.as_str()) {
        editor.before_own = Some((
            std::mem::replace(&mut editor.vertex, vertex),
            std::mem::replace(&mut editor.fragment, fragment),
        ));
    }
    editor.shaders_in_use = true;
    true
}

/// Both sources as files (downloads in the browser): what was written, or why not.
fn save(editor: &ShaderEditor, dir: &std::path::Path, lang: Lang) -> Result<String, String> {
    let mut written = Vec::new();
    let mut files = vec![
        ("shader.vert".to_owned(), &editor.vertex),
        ("shader.frag".to_owned(), &editor.fragment),
    ];
    for h in &editor.hooks {
        files.push((format!("{}.glsl", h.kind.key()), &h.source));
    }
    for (name, text) in files {
        written.push(crate::app::platform::download(
            &name,
            text.as_bytes(),
            "text/plain",
            (dir, lang),
        )?);
    }
    Ok(written.join(", "))
}

/// The messages of the last compile, each with its stage and line.
fn messages(ui: &mut Ui, editor: &ShaderEditor, session: &Session, lang: Lang) {
    if let (true, Some(e)) = (editor.errors.is_empty(), &session.error) {
        // It compiled, but its run stopped (an endless loop, an index out of range …).
        ui.label(
            RichText::new(format!(
                "{} {e}",
                lang.t("shader-compiles-but-the-run-stopped")
            ))
            .color(ui.visuals().error_fg_color),
        );
        return;
    }
    if editor.compiles() {
        // Until the source is applied (or edited), pipelens' own shading draws the picture.
        let text = if !editor.hooks.is_empty() && !session.spec.scene.has_shaders() {
            lang.t("shader-compiled-the-pipeline-calls-these")
        } else if session.spec.scene.has_shaders() {
            lang.t("shader-compiled-the-picture-is-drawn")
        } else {
            lang.t("shader-the-picture-is-drawn-by")
        };
        ui.label(RichText::new(text).color(Color32::from_rgb(90, 170, 90)));
        return;
    }
    ui.label(
        RichText::new(lang.t("shader-does-not-compile-the-last"))
            .color(ui.visuals().error_fg_color),
    );
    for (h, e) in editor
        .hooks
        .iter()
        .flat_map(|h| h.errors.iter().map(move |e| (h, e)))
    {
        ui.label(
            RichText::new(lang.t_with(
                "compile-file-message",
                &[
                    ("file", &h.kind.key()),
                    ("message", &crate::vocabulary::compile::message(e, lang)),
                ],
            ))
            .monospace()
            .color(ui.visuals().error_fg_color),
        );
    }
    for e in &editor.errors {
        ui.label(
            RichText::new(crate::vocabulary::compile::stage_message(e, lang))
                .monospace()
                .color(ui.visuals().error_fg_color),
        );
    }
}
