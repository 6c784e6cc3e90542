//! The app's window: the panels that can be hidden, the main view showing the selected stage,
//! the observer beside or below it and the share of the window the picture gets; the frame
//! eframe calls each time it paints.

use std::{path::PathBuf, sync::mpsc::Receiver};

use super::layout::{Room, lab_split, split};
use super::session::{Command, Session};
use super::style::apply_style;
use super::views::{
    compare::CompareView, geometry::GeometryView, inspector, observer::ObserverView, params,
    pixels::PixelView,
};
use super::{editor, platform, progress, views, watched, window_size};
use crate::app::command::{LessonCommand, SceneCommand, SelectionCommand, ViewCommand};
use crate::vocabulary::Stage;

/// What the window shows around the picture. In a lesson or classroom mode the picture comes
/// first: the narration lies over it and can be folded (N), the parameters (P) and the
/// inspector (I) are opened when wanted; otherwise both panels are open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Panels {
    /// The lesson's narration card over the picture.
    pub narration: bool,
    /// The parameters on the left.
    pub parameters: bool,
    /// The inspector on the right.
    pub inspector: bool,
    /// The card with the stage's matrix over the geometry views.
    pub matrix_card: bool,
    /// The list of keyboard shortcuts (F1 or ?).
    pub keys: bool,
    /// The shader editor (S).
    pub shader: bool,
}

impl Panels {
    /// For a lesson or a classroom (`presenting`), or for exploring.
    #[must_use]
    pub fn for_mode(presenting: bool) -> Self {
        Self {
            narration: true,
            parameters: !presenting,
            inspector: !presenting,
            matrix_card: true,
            keys: false,
            shader: false,
        }
    }
}

/// The app.
pub struct PipelensApp {
    /// State with no egui in it.
    pub session: Session,
    /// What is shown around the picture.
    pub panels: Panels,
    /// Where this frame drew the picture of the stage (the buffer, the geometry, the observer,
    /// the compared images and their plot): what a presentation is for, measured by the tests.
    pub picture: Vec<egui::Rect>,
    /// Where this frame drew the step's subject, which the narration card must leave clear.
    pub subject: Vec<egui::Rect>,
    /// Where this frame drew words over the picture (a view's header, matrix card, legend),
    /// which must leave the subject clear too.
    pub overlays: Vec<egui::Rect>,
    /// This frame's smallest text and control (`sizes`), which a page reports.
    pub least: super::sizes::Least,
    pub(super) pixel_view: PixelView,
    pub(super) geometry_view: GeometryView,
    pub(super) observer_view: ObserverView,
    pub(super) compare_view: CompareView,
    pub(super) exercise_view: views::exercise::ExerciseView,
    pub(super) inspector: inspector::Inspector,
    /// The shader panel: its sources, their messages and the debugger.
    pub shader_editor: views::shader::ShaderEditor,
    pub(super) classroom: bool,
    pub(super) export_dir: String,
    pub(super) export_result: Option<Receiver<Result<Vec<PathBuf>, String>>>,
    /// Under the bar, what an export or a kept file did: done (green) or not (red), until
    /// closed or the next lesson opens.
    pub(super) note: Option<(bool, String)>,
    /// Stops the export under way.
    pub(super) export_cancel: Option<crate::export::Cancel>,
    pub(super) commands: Vec<Command>,
    /// The step whose panels were last opened on entering it (`Session::step_entered`).
    pub(super) step_opened: u64,
    /// This frame, the narration runs in a band across the window's foot (see
    /// `narration_in_band`); the stage's view controls are then in the bar's Show menu.
    pub(super) band: bool,
    /// A keystroke or pixel click waiting for its picture, timed with the frame log on.
    waiting: Option<super::latency::Waiting>,
    /// The progress as last saved: when the session's differs, a frame is asked for after the
    /// save interval, so that eframe saves it even if nothing else moves (a browser tab).
    pub(super) saved_progress: progress::Progress,
    /// The file shown, watched for changes (live reload): its path and last modification.
    pub(super) watched: Option<watched::Watched>,
    /// The "Add step" window (R).
    /// The lesson editor (R).
    pub(super) editor: editor::Editor,
    /// Dropped files read in the background (in the browser).
    pub(super) inbox: platform::Inbox,
}

impl PipelensApp {
    /// An app on `session` (call [`setup_context`](super::setup_context) once on its egui context).
    #[must_use]
    pub fn new(session: Session) -> Self {
        let presenting = session.lesson.is_some();
        Self {
            session,
            panels: Panels::for_mode(presenting),
            picture: Vec::new(),
            subject: Vec::new(),
            overlays: Vec::new(),
            least: super::sizes::Least::default(),
            pixel_view: PixelView::default(),
            geometry_view: GeometryView::default(),
            observer_view: ObserverView::default(),
            compare_view: CompareView::default(),
            exercise_view: views::exercise::ExerciseView::default(),
            inspector: inspector::Inspector::default(),
            shader_editor: views::shader::ShaderEditor::default(),
            saved_progress: progress::Progress::default(),
            classroom: false,
            export_dir: "pipelens-export".to_owned(),
            export_result: None,
            note: None,
            export_cancel: None,
            commands: Vec::new(),
            step_opened: 0,
            band: false,
            waiting: None,
            watched: None,
            editor: editor::Editor::default(),
            inbox: platform::Inbox::default(),
        }
    }

    /// Whether the app presents (a lesson is open, or classroom mode is on): the picture first.
    #[must_use]
    pub fn presenting(&self) -> bool {
        self.classroom || self.session.lesson.is_some()
    }

    /// What the window (or the browser tab) is titled, in the language shown: `pipelens — lesson
    /// id — step k/n` (第 k/n 步 in Chinese), or `pipelens — file` for a scene. A screen reader
    /// says it when the window is entered, and a test in the browser reads where the app is from it.
    #[must_use]
    pub fn title(&self) -> String {
        match &self.session.lesson {
            Some(p) => self.session.lang.t_with(
                "window-title-lesson-step",
                &[
                    ("lesson", &p.lesson.id),
                    ("step", &(p.step + 1)),
                    ("steps", &p.lesson.steps.len()),
                ],
            ),
            None => format!("pipelens — {}", self.session.source),
        }
    }

    /// Whether classroom mode (large type, high contrast) is on.
    #[must_use]
    pub fn classroom(&self) -> bool {
        self.classroom
    }

    /// Turns classroom mode on or off; turning it on folds the side panels away.
    pub fn set_classroom(&mut self, ctx: &egui::Context, on: bool) {
        if on == self.classroom {
            return;
        }
        self.classroom = on;
        apply_style(ctx, on, self.session.touch);
        let narration = self.panels.narration;
        self.panels = Panels {
            narration,
            ..Panels::for_mode(self.presenting())
        };
    }

    /// How much room the panels at the right (the inspector, the code, the lesson editor)
    /// start with: two or more open start narrower, so that the view keeps about half of the
    /// window, and narrower still beside a lab, whose three pictures need more.
    pub(super) fn room(&self) -> Room {
        let inspector = self.panels.inspector && self.session.capture.is_some();
        let open = [inspector, self.panels.shader, self.editor.open]
            .into_iter()
            .filter(|&open| open)
            .count();
        match (open > 1, self.session.current_exercise().is_some()) {
            (false, _) => Room::Alone,
            (true, false) => Room::Beside,
            (true, true) => Room::Crowded,
        }
    }

    /// The share of `screen` the picture covers (the area of the union of [`Self::picture`]).
    #[must_use]
    pub fn picture_share(&self, screen: egui::Rect) -> f32 {
        views::card_placement::share(&self.picture, screen)
    }

    /// Draws one frame and applies the commands it produced.
    pub fn frame(&mut self, ui: &mut egui::Ui) {
        let started = web_time::Instant::now();
        self.session.poll();
        if self.session.progress != self.saved_progress {
            ui.ctx()
                .request_repaint_after(SAVE_INTERVAL + std::time::Duration::from_millis(500));
        }
        self.take_input(ui.ctx());
        self.picture.clear();
        self.subject.clear();
        self.overlays.clear();
        let narrated = self.panels.narration && self.session.lesson.is_some();
        self.band =
            narrated && !window_size::is_compact(ui.ctx()) && self.narration_in_band(ui.ctx());
        let compact = self.bar(ui);
        self.open_for_step(ui.ctx(), compact);
        self.keys_help(ui.ctx());
        // Presenting, the status line shows only to say what went wrong.
        if !self.presenting() || self.session.error.is_some() {
            self.status_bar(ui);
        }
        let lang = self.session.lang;
        let band = self.band;
        if band {
            self.narration_band(ui);
        }
        // A small screen's Code tab: the code fills the screen under the verdict.
        let code_screen = compact && self.panels.shader;
        if self.panels.parameters && !code_screen {
            egui::Panel::left("parameters")
                .default_size(300.0)
                .resizable(true)
                .show(ui, |ui| {
                    ui.heading(lang.t("window-parameters"));
                    self.commands.extend(params::ui(ui, &self.session));
                });
            super::layout::name_divider(ui, "parameters", lang.t("chrome-parameters"), lang);
        }
        // The lesson editor outermost at the right: the view frames its subject beside it.
        self.edit_lesson(ui);
        let capture = self.session.capture.clone();
        if self.panels.inspector
            && !code_screen
            && let Some(capture) = &capture
        {
            // Beside another panel, narrower: a fifth of the window, 320 points beside a lab
            // (its own id keeps the width a drag gives it in each arrangement).
            let window = ui.ctx().content_rect().width();
            let (id, wide) = match self.room() {
                Room::Alone => ("inspector", 400.0),
                Room::Beside => ("inspector-beside", (window * 0.2).clamp(320.0, 400.0)),
                Room::Crowded => ("inspector-crowded", 320.0),
            };
            egui::Panel::right(id)
                .default_size(wide)
                .resizable(true)
                .show(ui, |ui| {
                    self.commands.extend(inspector::ui(
                        ui,
                        &mut self.inspector,
                        &self.session,
                        capture,
                    ));
                });
            super::layout::name_divider(ui, id, lang.t("chrome-inspector"), lang);
        }
        if code_screen {
            self.code_screen(ui);
            views::card_placement::set_narration_card(ui.ctx(), None);
        } else {
            self.picture_screen(ui, capture.as_ref(), (compact, narrated, band));
        }
        self.animate(ui.ctx());
        self.page_words(ui.ctx());
        self.least = super::sizes::least(ui.ctx());
        // A parameter dragged (a slider, a number): drafts until the pointer is let go, then the
        // full frame.
        if !ui.ctx().input(|i| i.pointer.any_down()) {
            self.session.set_drafting(false);
        } else if self
            .commands
            .iter()
            .any(|c| matches!(c, Command::Scene(SceneCommand::SetSpec(_))))
        {
            self.session.set_drafting(true);
        }
        self.apply_commands(ui.ctx(), started);
    }

    /// The picture's screen: the shader panel at the right where it is open, a small screen's
    /// narration sheet, the views, and the narration's card over them (`narrated`: a lesson
    /// with its narration shown; `band`: the narration is in a band across the foot).
    fn picture_screen(
        &mut self,
        ui: &mut egui::Ui,
        capture: Option<&std::sync::Arc<pipeline::capture::FrameCapture>>,
        (compact, narrated, band): (bool, bool, bool),
    ) {
        let lang = self.session.lang;
        if self.panels.shader {
            self.shader_panel(ui);
        }
        if compact && narrated {
            self.narration_sheet(ui);
        }
        let central = egui::CentralPanel::default()
            .show(ui, |ui| match capture {
                Some(capture) => self.main_view(ui, capture),
                None => {
                    ui.centered_and_justified(|ui| {
                        ui.label(
                            self.session
                                .error
                                .clone()
                                .unwrap_or_else(|| lang.t("window-rendering").to_owned()),
                        );
                    });
                }
            })
            .response
            .rect;
        if !narrated || compact || band {
            views::card_placement::set_narration_card(ui.ctx(), None);
        } else {
            let out = views::lesson::card(ui.ctx(), central, &self.session);
            self.narrated(out);
        }
    }

    /// Applies the frame's commands, then renders what the view needs that the capture shown
    /// did not keep (a buffer, a pixel). With the frame log on, a keystroke or a pixel click
    /// among them is timed until its picture is drawn (`latency`).
    fn apply_commands(&mut self, ctx: &egui::Context, started: web_time::Instant) {
        let typed = ctx.input(|i| {
            i.events
                .iter()
                .any(|e| matches!(e, egui::Event::Key { .. } | egui::Event::Text(_)))
        });
        let timed = super::latency::logging()
            .then(|| {
                self.commands
                    .iter()
                    .find_map(|c| super::latency::timed(c, typed))
            })
            .flatten();
        let before = self.session.generation;
        for cmd in std::mem::take(&mut self.commands) {
            self.session.apply(cmd);
        }
        // A buffer or a pixel chosen that the capture shown did not keep: render it.
        self.session.ensure_captured();
        if let Some(what) = timed {
            self.waiting =
                super::latency::wait(what, started, before, &self.session).or(self.waiting);
        }
    }

    /// The bar at the top: the desktop's, or a small window's one row; whether the window is
    /// small (see [`window_size::is_compact`]).
    fn bar(&mut self, ui: &mut egui::Ui) -> bool {
        let compact = window_size::is_compact(ui.ctx());
        if compact {
            self.compact_bar(ui);
        } else {
            self.top_bar(ui);
        }
        compact
    }

    /// What the narration (the card, a small window's sheet, or the band) asked for.
    pub(super) fn narrated(&mut self, out: views::lesson::CardOutput) {
        self.commands.extend(out.commands);
        if out.fold {
            self.panels.narration = false;
        }
        if out.inspect {
            self.panels.inspector = true;
        }
    }

    /// The stage's toolbar (one row) and its picture below it.
    fn main_view(
        &mut self,
        ui: &mut egui::Ui,
        capture: &std::sync::Arc<pipeline::capture::FrameCapture>,
    ) {
        let sel = self.session.selection.clone();
        let lang = self.session.lang;
        if !self.presenting() {
            views::typeset::paragraph(
                ui,
                sel.stage.explanation(lang),
                &views::typeset::Style::body(ui),
            );
        }
        let space = sel.stage.space();
        // Beside a band, the top bar names the stage and its Show menu holds the view's
        // controls: the picture keeps the toolbar's row.
        if !self.band {
            self.stage_toolbar(ui, capture);
        }
        let observer = sel.show_observer && (space.is_some() || sel.comparison.is_none());
        // A narration band or column leaves the views the part above or beside it.
        let card = views::card_placement::narration_card(ui.ctx());
        let above =
            views::card_placement::free_recorded(ui.ctx(), ui.available_rect_before_wrap(), card);
        ui.scope_builder(egui::UiBuilder::new().max_rect(above), |ui| {
            self.views(ui, capture, observer);
        });
        ui.advance_cursor_after_rect(above);
    }

    /// The compared images, or the stage's view with the observer or the exercise beside it.
    fn views(
        &mut self,
        ui: &mut egui::Ui,
        capture: &std::sync::Arc<pipeline::capture::FrameCapture>,
        observer: bool,
    ) {
        let sel = self.session.selection.clone();
        let space = sel.stage.space();
        if sel.comparison.is_some() && space.is_none() {
            let c = self.compare_view.ui(ui, &self.session);
            self.commands.extend(c);
            self.picture
                .extend(self.compare_view.picture.iter().copied());
            self.subject
                .extend(self.compare_view.picture.iter().copied());
            return;
        }
        let exercise = space.is_none() && self.session.current_exercise().is_some();
        let (area, main, side) = if observer || exercise {
            let aspect = space
                .is_none()
                .then(|| capture.width() as f32 / capture.height() as f32);
            let (area, left, right) = match aspect.filter(|_| exercise) {
                Some(aspect) => {
                    let caption = views::exercise::caption_height(ui.ctx(), &self.session);
                    lab_split(ui, aspect, &caption)
                }
                None => split(ui, aspect),
            };
            (area, left, Some(right))
        } else {
            let area = ui.available_rect_before_wrap();
            (area, area, None)
        };
        ui.scope_builder(egui::UiBuilder::new().max_rect(main), |ui| {
            ui.set_clip_rect(main.intersect(ui.clip_rect()));
            if let Some(space) = space {
                let from = sel
                    .stage
                    .previous()
                    .space()
                    .filter(|_| sel.transition < 1.0 && sel.stage != Stage::Model);
                let c = self.geometry_view.ui(
                    ui,
                    &self.session,
                    capture,
                    space,
                    from,
                    sel.transition,
                    self.panels.matrix_card,
                );
                self.commands.extend(c);
                self.picture.extend(self.geometry_view.picture);
                self.subject.extend(self.geometry_view.subject);
                self.overlays
                    .extend(self.geometry_view.cards.iter().filter(|r| r.is_positive()));
            } else {
                let c = self.pixel_view.ui(ui, &self.session, capture);
                // A pixel clicked is a pixel to read: the inspector opens with its derivation
                // (not in a small window, where it would cover the picture, nor beside the
                // shader panel in a narrow one).
                let picked = c.iter().any(|c| {
                    matches!(
                        c,
                        Command::Selection(SelectionCommand::SelectPixel(Some(_)))
                    )
                });
                if picked && !window_size::is_compact(ui.ctx()) && self.room_for_inspector(ui.ctx())
                {
                    self.panels.inspector = true;
                }
                self.commands.extend(c);
                self.picture.extend(self.pixel_view.picture.iter().copied());
                self.subject.extend(self.pixel_view.subject.iter().copied());
                self.overlays.extend(self.pixel_view.words.iter().copied());
            }
        });
        if let Some(side) = side {
            ui.scope_builder(egui::UiBuilder::new().max_rect(side), |ui| {
                ui.set_clip_rect(side.intersect(ui.clip_rect()));
                if exercise {
                    let c = self.exercise_view.ui(ui, &self.session, capture, side);
                    self.commands.extend(c);
                    self.picture
                        .extend(self.exercise_view.picture.iter().copied());
                    self.subject
                        .extend(self.exercise_view.picture.iter().copied());
                    self.overlays
                        .extend(self.exercise_view.captions.iter().copied());
                } else {
                    let c = self.observer_view.ui(ui, &self.session, capture);
                    self.commands.extend(c);
                    self.picture.extend(self.observer_view.picture);
                }
            });
        } else {
            views::picture_keys::nothing_beside(ui.ctx());
        }
        ui.advance_cursor_after_rect(area);
    }

    /// What the frame showed, in words beside a page's canvas (`views::alt::PageWords`): the
    /// step's heading and narration added to what the views said, those that changed written.
    fn page_words(&self, ctx: &egui::Context) {
        views::lesson::for_the_page(ctx, &self.session);
        let changed: Vec<_> = views::alt::settle_page_words(ctx)
            .into_iter()
            .map(|(part, words)| (part.id(), words))
            .collect();
        platform::show_page_words(&changed, self.session.lang);
    }

    fn animate(&mut self, ctx: &egui::Context) {
        if self.session.lesson.as_ref().is_some_and(|p| p.playing) {
            let dt = ctx.input(|i| i.stable_dt).min(0.1);
            self.commands.push(Command::Lesson(LessonCommand::Tick(dt)));
            ctx.request_repaint();
        }
        let t = self.session.selection.transition;
        if t < 1.0 {
            let dt = ctx.input(|i| i.stable_dt).min(0.1);
            self.session.selection.transition = (t + dt / 1.5).min(1.0);
            ctx.request_repaint();
        }
        self.poll_export();
        if self.export_result.is_some() || self.session.rendering() {
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
        }
    }
}

impl eframe::App for PipelensApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame(ui);
        if let Some((ms, what)) = super::latency::arrived(&mut self.waiting, &self.session) {
            super::latency::log(ms, what);
        }
        let ms = self.session.times.map(|t| t.total().as_secs_f64() * 1e3);
        let share = self.picture_share(ui.ctx().content_rect());
        platform::report(ui.ctx(), &self.title(), ms, share, self.least);
    }

    /// Keeps the student's progress (eframe calls this on closing and every
    /// [`eframe::App::auto_save_interval`]).
    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        self.session.progress.save(storage);
        self.saved_progress.clone_from(&self.session.progress);
    }

    /// Progress is saved within seconds of an answer (a lab in a browser tab may be closed
    /// without a goodbye).
    fn auto_save_interval(&self) -> std::time::Duration {
        SAVE_INTERVAL
    }

    /// Only the progress is kept: the app opens the same way every time.
    fn persist_egui_memory(&self) -> bool {
        false
    }
}

/// How often eframe saves the progress (and on closing).
const SAVE_INTERVAL: std::time::Duration = std::time::Duration::from_secs(5);

impl PipelensApp {
    /// What came in since the last frame: the watched file changed on disk, a file dropped,
    /// keys, and a finger — the lessons' words are a touch screen's from the first touch on (a
    /// phone's page says so from the start; a tablet's keyboard, typed on later, does not take
    /// it back).
    fn take_input(&mut self, ctx: &egui::Context) {
        self.reload_if_changed(ctx);
        self.open_dropped(ctx);
        self.keyboard(ctx);
        if !self.session.touch && ctx.input(egui::InputState::has_touch_screen) {
            apply_style(ctx, self.classroom, true);
            self.commands
                .push(Command::View(ViewCommand::SetTouch(true)));
        }
    }
}
