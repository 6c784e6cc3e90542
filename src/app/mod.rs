//! The desktop app (eframe + egui): a stage navigator, the selected stage in the main view, the
//! observer view, the parameters and the inspector. It reads `FrameCapture`s and never computes
//! pipeline results itself.

pub mod i18n;
pub mod session;
pub mod views;
pub mod worker;

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, channel};

use pipeline::buffers::Capture;
use pipeline::settings::RenderSettings;

use egui::{FontData, FontFamily, RichText};

use self::i18n::Lang;
use self::session::{Command, Session, Stage};
use self::views::{
    compare::CompareView, geometry::GeometryView, inspector, navigator, observer::ObserverView,
    params, pixels::PixelView,
};
use self::worker::RenderWorker;

/// The Chinese font, embedded so that Chinese renders on any machine.
pub const CJK_FONT: &[u8] = include_bytes!("../../assets/fonts/NotoSansSC-subset.otf");

/// Adds the Chinese font after egui's own fonts (which have no CJK glyphs), and egui's Hack as
/// the last fallback of the proportional family: it has symbols the others lack (⁻ ⌊ ⌋).
pub fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        "noto-sans-sc".to_owned(),
        std::sync::Arc::new(FontData::from_static(CJK_FONT)),
    );
    for (family, extra) in [
        (FontFamily::Proportional, &["noto-sans-sc", "Hack"][..]),
        (FontFamily::Monospace, &["noto-sans-sc"][..]),
    ] {
        let list = fonts.families.entry(family).or_default();
        list.extend(extra.iter().map(|s| (*s).to_owned()));
    }
    ctx.set_fonts(fonts);
}

/// Prepares an egui context for the app: the Chinese font and the normal style.
pub fn setup_context(ctx: &egui::Context) {
    install_fonts(ctx);
    apply_style(ctx, false);
}

/// Text sizes and contrast: normal, or classroom (large type, high contrast, for a projector).
pub fn apply_style(ctx: &egui::Context, classroom: bool) {
    use egui::{FontId, TextStyle};
    let scale = if classroom { 1.35 } else { 1.0 };
    ctx.set_theme(egui::Theme::Dark);
    ctx.global_style_mut(|style| {
        style.text_styles = [
            (TextStyle::Heading, FontId::proportional(22.0 * scale)),
            (TextStyle::Body, FontId::proportional(15.0 * scale)),
            (TextStyle::Button, FontId::proportional(15.0 * scale)),
            (TextStyle::Small, FontId::proportional(12.0 * scale)),
            (TextStyle::Monospace, FontId::monospace(13.5 * scale)),
        ]
        .into();
        style.visuals = egui::Visuals::dark();
        if classroom {
            style.visuals.override_text_color = Some(egui::Color32::WHITE);
            style.visuals.panel_fill = egui::Color32::BLACK;
            style.visuals.window_fill = egui::Color32::BLACK;
            style.visuals.widgets.noninteractive.bg_stroke.width = 1.5;
            style.visuals.selection.bg_fill = egui::Color32::from_rgb(0, 90, 200);
        }
    });
}

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
    watched: Option<Watched>,
}

/// A file watched for changes.
struct Watched {
    path: PathBuf,
    modified: Option<std::time::SystemTime>,
    checked: std::time::Instant,
}

impl Watched {
    fn modified(path: &std::path::Path) -> Option<std::time::SystemTime> {
        std::fs::metadata(path).and_then(|m| m.modified()).ok()
    }
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

    /// Watches `path` (the file the session was loaded from): when it changes on disk, it is
    /// loaded again; a broken edit shows its error and the last good version keeps running.
    #[must_use]
    pub fn watching(mut self, path: PathBuf) -> Self {
        self.watched = Some(Watched {
            modified: Watched::modified(&path),
            path,
            checked: std::time::Instant::now(),
        });
        self
    }

    /// Checks the watched file about twice a second and reloads it when it changed.
    fn reload_if_changed(&mut self, ctx: &egui::Context) {
        let Some(w) = &mut self.watched else {
            return;
        };
        ctx.request_repaint_after(std::time::Duration::from_millis(500));
        if w.checked.elapsed() < std::time::Duration::from_millis(400) {
            return;
        }
        w.checked = std::time::Instant::now();
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
                    for c in session::Comparison::ALL {
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

    fn top_bar(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        egui::Panel::top("top").show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new("pipelens").strong().size(20.0));
                ui.label(RichText::new(&self.session.source).weak());
                ui.separator();
                if ui
                    .button(lang.other().name())
                    .on_hover_text(lang.tr("Switch the language", "切换语言"))
                    .clicked()
                {
                    self.commands.push(Command::SetLang(lang.other()));
                }
                if ui
                    .selectable_label(self.classroom, lang.tr("Classroom mode", "课堂模式"))
                    .on_hover_text(lang.tr("Large type and high contrast for a projector. F11: full screen, Ctrl +/−: text size, ←/→: stages, Space: replay.", "投影用的大字号与高对比度。F11：全屏，Ctrl +/−：字号，←/→：切换阶段，空格：重播。"))
                    .clicked()
                {
                    self.classroom = !self.classroom;
                    apply_style(ui.ctx(), self.classroom);
                }
                ui.separator();
                let label = ui.label(lang.tr("Export to", "导出到"));
                ui.add(egui::TextEdit::singleline(&mut self.export_dir).desired_width(160.0))
                    .labelled_by(label.id)
                    .on_hover_text(lang.tr("The folder the snapshot is written to (created if missing).", "快照写入的文件夹（不存在时创建）。"));
                let busy = self.export_result.is_some();
                if ui
                    .add_enabled(!busy, egui::Button::new(lang.tr("Export snapshot", "导出快照")))
                    .on_hover_text(lang.tr("Every buffer as PNG and capture.json, as `pipelens export` writes them.", "每个缓冲的 PNG 与 capture.json，与 `pipelens export` 相同。"))
                    .clicked()
                {
                    self.start_export();
                }
                if let Some(cancel) = self.export_cancel.as_ref().filter(|_| busy)
                    && ui
                        .button(lang.tr("Cancel export", "取消导出"))
                        .on_hover_text(lang.tr("Stops between two files: those written stay whole.", "在两个文件之间停止：已写入的文件保持完整。"))
                        .clicked()
                {
                    cancel.cancel();
                }
            });
            if let Some(e) = &self.session.reload_error {
                ui.label(
                    RichText::new(format!(
                        "{}\n{e}",
                        lang.tr(
                            "The file changed on disk and no longer loads; the last good version keeps running:",
                            "文件在磁盘上被修改后无法加载；继续运行上一个正确的版本："
                        )
                    ))
                    .monospace()
                    .color(egui::Color32::LIGHT_RED),
                );
            }
            if let Some((ok, msg)) = &self.export_message {
                ui.label(RichText::new(msg).color(if *ok { egui::Color32::LIGHT_GREEN } else { egui::Color32::LIGHT_RED }));
            }
            ui.separator();
            if let Some(c) = navigator::ui(ui, &self.session) {
                self.commands.push(c);
            }
        });
    }

    fn status_bar(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        egui::Panel::bottom("status").show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                if let Some(e) = &self.session.error {
                    ui.label(
                        RichText::new(format!("{}: {e}", lang.tr("Error", "错误")))
                            .color(egui::Color32::LIGHT_RED),
                    );
                    ui.label(
                        RichText::new(
                            lang.tr("(showing the last good frame)", "（显示上一个正确的帧）"),
                        )
                        .weak(),
                    );
                }
                if let (Some(c), Some(t)) = (&self.session.capture, &self.session.times) {
                    let ms = |d: std::time::Duration| format!("{:.1}", d.as_secs_f64() * 1e3);
                    ui.label(format!(
                        "{}×{} · {}× · {} {} · {} {} ms ({} {} · {} {} · {} {} · {} {})",
                        c.width(),
                        c.height(),
                        c.settings.samples.count(),
                        c.primitives.len(),
                        lang.tr("triangles", "个三角形"),
                        lang.tr("frame", "帧"),
                        ms(t.total()),
                        lang.tr("vertex", "顶点"),
                        ms(t.vertex),
                        lang.tr("clip", "裁剪"),
                        ms(t.clip_setup),
                        lang.tr("raster", "光栅化"),
                        ms(t.raster),
                        lang.tr("resolve", "解析"),
                        ms(t.resolve),
                    ));
                }
                if self.session.rendering() {
                    ui.spinner();
                }
            });
        });
    }

    fn keyboard(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let (left, right, space, f11) = ctx.input(|i| {
            (
                i.key_pressed(egui::Key::ArrowLeft) || i.key_pressed(egui::Key::PageUp),
                i.key_pressed(egui::Key::ArrowRight) || i.key_pressed(egui::Key::PageDown),
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::F11),
            )
        });
        // With a lesson the arrows (and a presenter's Page Up/Down) step it and Space plays its
        // animations; without one they move through the stages and replay the transition.
        let lesson = self.session.lesson.is_some();
        if left {
            self.commands.push(if lesson {
                Command::PreviousStep
            } else {
                Command::PreviousStage
            });
        }
        if right {
            self.commands.push(if lesson {
                Command::NextStep
            } else {
                Command::NextStage
            });
        }
        if space {
            self.commands.push(if lesson {
                Command::TogglePlay
            } else {
                Command::PlayTransition
            });
        }
        if f11 {
            let full = ctx.input(|i| i.viewport().fullscreen.unwrap_or(false));
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(!full));
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
        if let Some(rx) = &self.export_result
            && let Ok(result) = rx.try_recv()
        {
            let lang = self.session.lang;
            self.export_message = Some(match result {
                Ok(files) => (
                    true,
                    format!(
                        "{} {}: {}",
                        lang.tr("Exported to", "已导出到"),
                        self.export_dir,
                        files
                            .iter()
                            .filter_map(|p| p.file_name())
                            .map(|n| n.to_string_lossy())
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                ),
                Err(e) => (false, e),
            });
            self.export_result = None;
        }
        if self.export_result.is_some() || self.session.rendering() {
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
        }
    }

    fn start_export(&mut self) {
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
    pub compare: Option<session::Comparison>,
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
