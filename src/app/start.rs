//! How the app starts: its options ([`Start`]), the app eframe creates on a document
//! ([`create`]) and the two ways in: a native window ([`run`]) or a page's canvas (`start`, in
//! the browser build).

use std::path::PathBuf;

use super::session::{Command, Session};
use super::style::setup_context;
use super::window::PipelensApp;
use super::worker::RenderWorker;
use super::{platform, progress};
use crate::app::command::{LessonCommand, ViewCommand};
use crate::vocabulary::{Lang, Stage};

/// How the app starts: language, stage, comparison.
#[derive(Clone, Copy, Debug, Default)]
pub struct Start {
    /// The interface language.
    pub lang: Lang,
    /// The stage shown first (World when `None`).
    pub stage: Option<Stage>,
    /// Settings compared side by side from the start.
    pub compare: Option<crate::vocabulary::Comparison>,
    /// A lesson's step to open on (0-based; past the last, the last; ignored for a scene).
    pub step: Option<usize>,
    /// Whether to open in classroom mode.
    pub classroom: bool,
    /// Whether the screen is a touch screen (the page asks the browser whether its main pointer
    /// is coarse); a touch event says so later where this is false.
    pub touch: bool,
}

/// The app eframe creates (on the desktop and in the browser alike): a session on `doc` (named
/// `source`; `path`, when it came from a file, is watched for live reload) with its render
/// worker (where threads exist; otherwise frames render on the UI thread), opened as `start`
/// says.
pub fn create(
    cc: &eframe::CreationContext<'_>,
    doc: crate::lesson::Document,
    source: &str,
    path: Option<PathBuf>,
    start: Start,
) -> PipelensApp {
    let ctx = cc.egui_ctx.clone();
    let worker = RenderWorker::start(platform::waker(&ctx)).ok();
    let mut session = Session::with_document(doc, source, worker);
    session.lang = start.lang;
    session.touch = start.touch;
    session.progress = progress::Progress::load(cc.storage);
    if let Some(k) = start.step {
        session.apply(Command::Lesson(LessonCommand::GoToStep(k)));
    }
    if let Some(stage) = start.stage {
        session.apply(Command::View(ViewCommand::SelectStage(stage)));
    }
    if start.compare.is_some() {
        session.apply(Command::View(ViewCommand::SetComparison(start.compare)));
    }
    setup_context(&cc.egui_ctx);
    if start.touch {
        super::style::apply_style(&cc.egui_ctx, false, true);
    }
    let mut app = PipelensApp::new(session);
    if start.classroom {
        app.set_classroom(&cc.egui_ctx, true);
    }
    match path {
        Some(p) => app.watching(p),
        None => app,
    }
}

/// The language a fresh session starts in, from `PIPELENS_LANG` (a catalog's tag: `en`,
/// `zh-Hans` or `zh`; English for any other).
#[must_use]
pub fn initial_lang() -> Lang {
    std::env::var("PIPELENS_LANG")
        .ok()
        .and_then(|tag| Lang::find(&tag))
        .unwrap_or(Lang::EN)
}

/// Opens the window on `doc` and runs until it is closed.
///
/// # Errors
/// When no window can be opened (no display, no OpenGL).
#[cfg(not(target_arch = "wasm32"))]
pub fn run(
    doc: crate::lesson::Document,
    source: String,
    path: Option<std::path::PathBuf>,
    start: Start,
) -> anyhow::Result<()> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("pipelens")
            .with_inner_size([1366.0, 768.0])
            .with_min_inner_size([320.0, 320.0]),
        // The app's storage keeps the student's progress, not the window's place.
        persist_window: false,
        ..Default::default()
    };
    eframe::run_native(
        "pipelens",
        options,
        Box::new(move |cc| Ok(Box::new(create(cc, doc, &source, path, start)))),
    )
    .map_err(|e| {
        anyhow::anyhow!(
            "cannot open the window: {e}\n(with no display, `pipelens export --out DIR` renders and writes every stage headless)"
        )
    })
}

/// Starts the app in the page's `canvas` on the built-in tour, in the language the page asks for
/// (`?lang=zh`), on a step if it names one (`&step=3`, counted from 1). `threads` is the size of
/// the rayon pool the page started on Web Workers (`initThreadPool`), 0 when it has none.
///
/// # Errors
/// When the canvas has no WebGL2 or the app cannot start.
#[cfg(target_arch = "wasm32")]
pub async fn start(
    canvas: web_sys::HtmlCanvasElement,
    threads: usize,
) -> Result<(), wasm_bindgen::JsValue> {
    super::platform::POOL_THREADS.store(threads, std::sync::atomic::Ordering::Relaxed);
    let query = web_sys::window()
        .and_then(|w| w.location().search().ok())
        .unwrap_or_default();
    let value = |key: &str| {
        query
            .trim_start_matches('?')
            .split('&')
            .find_map(|kv| kv.strip_prefix(key)?.strip_prefix('='))
            .map(str::to_owned)
    };
    let lang = value("lang")
        .and_then(|tag| crate::vocabulary::Lang::find(&tag))
        .unwrap_or_default();
    let lesson_file = value("lesson");
    let doc = lesson_file
        .as_deref()
        .and_then(|f| crate::lesson::library::lesson(&format!("{f}.toml")).ok())
        .map_or_else(crate::lesson::default_lesson, Ok)
        .map_err(|d| wasm_bindgen::JsValue::from_str(&d.to_string()))?;
    let source = format!("lessons/{}.toml (built in)", doc.id);
    let start = Start {
        lang,
        step: value("step")
            .and_then(|s| s.parse::<usize>().ok())
            .map(|k| k.saturating_sub(1)),
        // A phone's or a tablet's finger: its main pointer is coarse.
        touch: web_sys::window()
            .and_then(|w| w.match_media("(pointer: coarse)").ok().flatten())
            .is_some_and(|m| m.matches()),
        ..Default::default()
    };
    eframe::WebRunner::new()
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(move |cc| {
                // The page's own words beside the canvas, for a screen reader (views::alt).
                super::views::alt::keep_page_words(&cc.egui_ctx);
                Ok(Box::new(create(
                    cc,
                    crate::lesson::Document::Lesson(Box::new(doc)),
                    &source,
                    None,
                    start,
                )))
            }),
        )
        .await
}
