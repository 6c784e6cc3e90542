//! The desktop app (eframe + egui): a stage navigator, the selected stage in the main view, the
//! observer view, the parameters and the inspector. It reads `FrameCapture`s and never computes
//! pipeline results itself.

mod chrome;
mod export_task;
mod reload;
pub mod session;
mod style;
pub mod views;
pub mod worker;

pub use style::{CJK_FONT, apply_style, install_fonts, setup_context};

use std::path::PathBuf;
use std::sync::mpsc::Receiver;

use egui::RichText;

use self::session::{Command, Session};
use self::views::{
    compare::CompareView, geometry::GeometryView, inspector, observer::ObserverView, params,
    pixels::PixelView,
};
use self::worker::RenderWorker;
use crate::vocabulary::Lang;
use crate::vocabulary::Stage;

/// The app.
pub struct PipelensApp {
    /// State with no egui in it.
    pub session: Session,
    pixel_view: PixelView,
    geometry_view: GeometryView,
    observer_view: ObserverView,
    compare_view: CompareView,
    inspector: inspector::Inspector,
    classroom: bool,
    export_dir: String,
    export_result: Option<Receiver<Result<Vec<PathBuf>, String>>>,
    export_message: Option<(bool, String)>,
    /// Stops the export under way.
    export_cancel: Option<crate::export::Cancel>,
    commands: Vec<Command>,
    /// The file shown, watched for changes (live reload): its path and last modification.
    watched: Option<reload::Watched>,
}

impl PipelensApp {
    /// An app on `session` (call [`setup_context`] once on its egui context).
    #[must_use]
    pub fn new(session: Session) -> Self {
        Self {
            session,
            pixel_view: PixelView::default(),
            geometry_view: GeometryView::default(),
            observer_view: ObserverView::default(),
            compare_view: CompareView::default(),
            inspector: inspector::Inspector::default(),
            classroom: false,
            export_dir: "pipelens-export".to_owned(),
            export_result: None,
            export_message: None,
            export_cancel: None,
            commands: Vec::new(),
            watched: None,
        }
    }

    /// Draws one frame and applies the commands it produced.
    pub fn frame(&mut self, ui: &mut egui::Ui) {
        self.session.poll();
        self.reload_if_changed(ui.ctx());
        self.keyboard(ui.ctx());
        self.top_bar(ui);
        self.status_bar(ui);
        let lang = self.session.lang;
        egui::Panel::left("parameters")
            .default_size(if self.session.lesson.is_some() {
                340.0
            } else {
                270.0
            })
            .resizable(true)
            .show(ui, |ui| {
                if let Some(player) = &self.session.lesson {
                    self.commands.extend(views::lesson::ui(ui, player, lang));
                    ui.separator();
                    egui::CollapsingHeader::new(
                        RichText::new(lang.tr("Parameters", "参数")).strong(),
                    )
                    .id_salt("params-section")
                    .show(ui, |ui| {
                        self.commands.extend(params::ui(ui, &self.session));
                    });
                } else {
                    ui.heading(lang.tr("Parameters", "参数"));
                    self.commands.extend(params::ui(ui, &self.session));
                }
            });
        if let Some(capture) = self.session.capture.clone() {
            egui::Panel::right("inspector")
                .default_size(380.0)
                .resizable(true)
                .show(ui, |ui| {
                    self.commands.extend(inspector::ui(
                        ui,
                        &mut self.inspector,
                        &self.session,
                        &capture,
                    ));
                });
            egui::CentralPanel::default().show(ui, |ui| self.main_view(ui, &capture));
        } else {
            egui::CentralPanel::default().show(ui, |ui| {
                ui.centered_and_justified(|ui| {
                    ui.label(
                        self.session
                            .error
                            .clone()
                            .unwrap_or_else(|| lang.tr("Rendering…", "渲染中…").to_owned()),
                    );
                });
            });
        }
        self.animate(ui.ctx());
        for cmd in std::mem::take(&mut self.commands) {
            self.session.apply(cmd);
        }
        // A buffer or a pixel chosen that the capture shown did not keep: render it.
        self.session.ensure_captured();
    }

    fn main_view(
        &mut self,
        ui: &mut egui::Ui,
        capture: &std::sync::Arc<pipeline::capture::FrameCapture>,
    ) {
        let sel = self.session.selection.clone();
        let lang = self.session.lang;
        ui.horizontal_wrapped(|ui| {
            ui.heading(sel.stage.name(lang));
            ui.label(RichText::new(sel.stage.explanation(lang)).weak());
        });
        if let Some(space) = sel.stage.space() {
            ui.horizontal(|ui| {
                let mut obs = sel.show_observer;
                if ui
                    .checkbox(&mut obs, lang.tr("Observer view", "观察者视图"))
                    .changed()
                {
                    self.commands.push(Command::ToggleObserver);
                }
            });
            let from = sel
                .stage
                .previous()
                .space()
                .filter(|_| sel.transition < 1.0 && sel.stage != Stage::Model);
            if sel.show_observer {
                let (area, left, right) = halves(ui);
                ui.scope_builder(egui::UiBuilder::new().max_rect(left), |ui| {
                    ui.set_clip_rect(left);
                    let c = self.geometry_view.ui(
                        ui,
                        &self.session,
                        capture,
                        space,
                        from,
                        sel.transition,
                    );
                    self.commands.extend(c);
                });
                ui.scope_builder(egui::UiBuilder::new().max_rect(right), |ui| {
                    ui.set_clip_rect(right);
                    let c = self.observer_view.ui(ui, &self.session, capture);
                    self.commands.extend(c);
                });
                ui.advance_cursor_after_rect(area);
            } else {
                let c =
                    self.geometry_view
                        .ui(ui, &self.session, capture, space, from, sel.transition);
                self.commands.extend(c);
            }
        } else {
            let c = self
                .pixel_view
                .toolbar(ui, &sel, &self.session.buffers, lang);
            self.commands.extend(c);
            if sel.buffer == pipeline::buffers::BufferKind::Depth
                && let Some(c) = PixelView::depth_controls(ui, &sel, capture, lang)
            {
                self.commands.push(c);
            }
            self.comparison_choice(ui);
            if sel.comparison.is_some() {
                let c = self.compare_view.ui(ui, &self.session);
                self.commands.extend(c);
            } else if sel.show_observer {
                // The image beside the scene seen from outside (a lesson's "observer" layout).
                let (area, left, right) = halves(ui);
                ui.scope_builder(egui::UiBuilder::new().max_rect(left), |ui| {
                    ui.set_clip_rect(left);
                    let c = self.pixel_view.ui(ui, &self.session, capture);
                    self.commands.extend(c);
                });
                ui.scope_builder(egui::UiBuilder::new().max_rect(right), |ui| {
                    ui.set_clip_rect(right);
                    let c = self.observer_view.ui(ui, &self.session, capture);
                    self.commands.extend(c);
                });
                ui.advance_cursor_after_rect(area);
            } else {
                let c = self.pixel_view.ui(ui, &self.session, capture);
                self.commands.extend(c);
            }
        }
    }

    /// Side by side: none, or one of the comparisons.
    fn comparison_choice(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        let current = self.session.selection.comparison;
        let mut choice = current;
        ui.horizontal(|ui| {
            egui::ComboBox::new("comparison", lang.tr("side by side", "并排对比"))
                .selected_text(current.map_or(lang.tr("off", "关"), |c| c.name(lang)))
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut choice, None, lang.tr("off", "关"));
                    for c in crate::vocabulary::Comparison::ALL {
                        ui.selectable_value(&mut choice, Some(c), c.name(lang));
                    }
                })
                .response
                .on_hover_text(lang.tr(
                    "Render the scene with different settings and show them side by side, with an intensity profile.",
                    "用不同设置渲染场景并并排显示，附亮度剖面曲线。",
                ));
            if current.is_none() {
                let mut obs = self.session.selection.show_observer;
                if ui
                    .checkbox(&mut obs, lang.tr("Observer view", "观察者视图"))
                    .changed()
                {
                    self.commands.push(Command::ToggleObserver);
                }
            }
        });
        if choice != current {
            self.commands.push(Command::SetComparison(choice));
        }
    }

    fn animate(&mut self, ctx: &egui::Context) {
        if self.session.lesson.as_ref().is_some_and(|p| p.playing) {
            let dt = ctx.input(|i| i.stable_dt).min(0.1);
            self.commands.push(Command::Tick(dt));
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

/// The space left in `ui` cut into two fixed halves with a gap: `(all, left, right)`.
fn halves(ui: &egui::Ui) -> (egui::Rect, egui::Rect, egui::Rect) {
    let area = ui.available_rect_before_wrap();
    let gap = 8.0;
    let half = (area.width() - gap) / 2.0;
    let left = egui::Rect::from_min_size(area.min, egui::vec2(half, area.height()));
    let right = egui::Rect::from_min_size(
        area.min + egui::vec2(half + gap, 0.0),
        egui::vec2(half, area.height()),
    );
    (area, left, right)
}

impl eframe::App for PipelensApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame(ui);
    }
}

/// How the app starts: language, stage, comparison.
#[derive(Clone, Copy, Debug, Default)]
pub struct Start {
    /// The interface language.
    pub lang: Lang,
    /// The stage shown first (World when `None`).
    pub stage: Option<Stage>,
    /// Settings compared side by side from the start.
    pub compare: Option<crate::vocabulary::Comparison>,
}

/// Opens the window on `spec` and runs until it is closed.
///
/// # Errors
/// When no window can be opened (no display, no OpenGL).
pub fn run(
    doc: crate::lesson::Document,
    source: String,
    path: Option<PathBuf>,
    start: Start,
) -> anyhow::Result<()> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("pipelens")
            .with_inner_size([1366.0, 768.0])
            .with_min_inner_size([800.0, 500.0]),
        ..Default::default()
    };
    eframe::run_native(
        "pipelens",
        options,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let worker = RenderWorker::start(move || ctx.request_repaint()).ok();
            let mut session = Session::with_document(doc, &source, worker);
            session.lang = start.lang;
            if let Some(stage) = start.stage {
                session.apply(Command::SelectStage(stage));
            }
            if start.compare.is_some() {
                session.apply(Command::SetComparison(start.compare));
            }
            setup_context(&cc.egui_ctx);
            let app = PipelensApp::new(session);
            Ok(Box::new(match path {
                Some(p) => app.watching(p),
                None => app,
            }))
        }),
    )
    .map_err(|e| {
        anyhow::anyhow!(
            "cannot open the window: {e}\n(with no display, `pipelens export --out DIR` renders and writes every stage headless)"
        )
    })
}

/// The language a fresh session starts in, from `PIPELENS_LANG` (`zh` or `en`).
#[must_use]
pub fn initial_lang() -> Lang {
    match std::env::var("PIPELENS_LANG").as_deref() {
        Ok("zh") => Lang::Zh,
        _ => Lang::En,
    }
}
