//! What differs between the desktop and the browser once the app runs, and only that (how it
//! starts is `start.rs`): how a dropped file's bytes are read (at once, or in
//! the background as browsers require), and where the title goes (the window's, or the tab's:
//! `document.title`), and how the render thread is woken. Everything else runs the same. In a
//! page that is cross-origin isolated, the threaded build's rayon pool runs on Web Workers over
//! shared memory, and the render worker is one of them; elsewhere rayon runs on one thread and
//! frames render on the UI thread. Clocks come from `web-time`. Live reload watches files on
//! disk, so the browser has none (the Lessons menu says how to open a file there).

use std::sync::{Arc, Mutex};

use crate::vocabulary::Lang;

/// A dropped file's name and its bytes (or why they could not be read).
type Read = (String, Result<Vec<u8>, String>);

/// Dropped files read in the background, collected for the next frame.
#[derive(Clone, Default)]
pub struct Inbox(Arc<Mutex<Vec<Read>>>);

impl Inbox {
    /// Reads `file`: at once on the desktop; in the browser in the background, waking `ctx`
    /// when done.
    pub fn read(&self, file: Arc<dyn egui::DroppedFile + Send + Sync>, ctx: &egui::Context) {
        let name = file.path().display().to_string();
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = ctx;
            self.push((name, file.bytes()));
        }
        #[cfg(target_arch = "wasm32")]
        {
            let inbox = self.clone();
            let ctx = ctx.clone();
            wasm_bindgen_futures::spawn_local(async move {
                let bytes = file.bytes_async().await;
                inbox.push((name, bytes));
                ctx.request_repaint();
            });
        }
    }

    fn push(&self, read: Read) {
        if let Ok(mut v) = self.0.lock() {
            v.push(read);
        }
    }

    /// The files read since the last call.
    #[must_use]
    pub fn take(&self) -> Vec<Read> {
        self.0
            .lock()
            .map(|mut v| std::mem::take(&mut *v))
            .unwrap_or_default()
    }
}

/// Shows `title` as the window's title (the browser tab's in a page) when it changed; in a page
/// also the latest frame's render time in milliseconds, the share of the page the picture
/// covers and the frame's smallest text and control in CSS pixels, as `<html
/// data-frame-ms="…" data-picture-share="…" data-least-text="…" data-least-target="…">`, for
/// the browser test and the benchmark to read.
pub fn report(
    ctx: &egui::Context,
    title: &str,
    frame_ms: Option<f64>,
    share: f32,
    least: super::sizes::Least,
) {
    #[cfg(target_arch = "wasm32")]
    if let Some(root) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.document_element())
    {
        if let Some(ms) = frame_ms {
            let _ = root.set_attribute("data-frame-ms", &format!("{ms:.1}"));
        }
        let _ = root.set_attribute("data-picture-share", &format!("{share:.2}"));
        let _ = root.set_attribute("data-least-text", &format!("{:.1}", least.text));
        let r = least.target_rect;
        let _ = root.set_attribute(
            "data-least-target",
            &format!(
                "{:.1} at {:.0},{:.0} {:.0}×{:.0}",
                least.target,
                r.min.x,
                r.min.y,
                r.width(),
                r.height()
            ),
        );
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = (share, least);
        log_frame(ctx, title, frame_ms);
    }
    let id = egui::Id::unique("pipelens-title");
    if ctx.data(|d| d.get_temp::<String>(id)).as_deref() == Some(title) {
        return;
    }
    ctx.data_mut(|d| d.insert_temp(id, title.to_owned()));
    #[cfg(not(target_arch = "wasm32"))]
    ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
    #[cfg(target_arch = "wasm32")]
    if let Some(document) = web_sys::window().and_then(|w| w.document()) {
        document.set_title(title);
    }
}

/// Writes the page's words that changed — each the id of its element beside the canvas in
/// `web/index.html` and its new words (the views' `PageWords`) — their language marked (`lang`,
/// on the words' container and the document), and names eframe's text agent — the hidden
/// `<input>` beside the canvas that takes the keys typed — in that language (WCAG 4.1.2: a form
/// field has a name); nothing on the desktop, whose screen readers read AccessKit's tree.
pub fn show_page_words(changed: &[(&'static str, String)], lang: Lang) {
    #[cfg(target_arch = "wasm32")]
    if let Some(document) = web_sys::window()
        .and_then(|w| w.document())
        .filter(|_| !changed.is_empty())
    {
        let tag = lang.tag();
        let agent = document
            .get_element_by_id("pipelens")
            .and_then(|canvas| canvas.next_element_sibling())
            .filter(|e| e.tag_name().eq_ignore_ascii_case("input"));
        if let Some(input) = agent {
            let name = lang.t("platform-pipelens-the-keys-typed-into");
            if input.get_attribute("aria-label").as_deref() != Some(name) {
                let _ = input.set_attribute("aria-label", name);
            }
        }
        for element in [
            document.document_element(),
            document.get_element_by_id("pipelens-words"),
        ]
        .into_iter()
        .flatten()
        {
            if element.get_attribute("lang").as_deref() != Some(tag) {
                let _ = element.set_attribute("lang", tag);
            }
        }
        for (id, words) in changed {
            if let Some(element) = document.get_element_by_id(id) {
                element.set_text_content(Some(words));
            }
        }
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = (changed, lang);
}

/// With `PIPELENS_FRAME_LOG` set, each new frame's render time goes to standard error as
/// `frame: 23.1 ms (title)`: the desktop's counterpart of the page's `data-frame-ms`, read by
/// `scripts/native-frames.sh` to measure the app as it runs, its window painting.
#[cfg(not(target_arch = "wasm32"))]
fn log_frame(ctx: &egui::Context, title: &str, frame_ms: Option<f64>) {
    let Some(ms) = frame_ms.filter(|_| frame_log()) else {
        return;
    };
    let id = egui::Id::unique("pipelens-frame-logged");
    if ctx.data(|d| d.get_temp::<f64>(id)) != Some(ms) {
        ctx.data_mut(|d| d.insert_temp(id, ms));
        eprintln!("frame: {ms:.1} ms ({title})");
    }
}

/// Whether the frame log is on: `PIPELENS_FRAME_LOG` set, on the desktop (the page reports its
/// frame times in the document instead).
#[must_use]
pub fn frame_log() -> bool {
    #[cfg(not(target_arch = "wasm32"))]
    {
        static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        *ON.get_or_init(|| std::env::var_os("PIPELENS_FRAME_LOG").is_some())
    }
    #[cfg(target_arch = "wasm32")]
    false
}

/// Whether the app writes files (the desktop) rather than offering downloads (the browser).
pub const WRITES_FILES: bool = cfg!(not(target_arch = "wasm32"));

/// Whether a file opened from disk is watched for live reload (the desktop; a page cannot).
pub const WATCHES_FILES: bool = WRITES_FILES;

/// Hands `bytes` over as the file `name`: in the browser a download (a Blob behind a clicked
/// link); on the desktop the file written into `dir`.
///
/// # Errors
/// When the browser refuses the Blob, or the file cannot be written.
pub fn download(
    name: &str,
    bytes: &[u8],
    mime: &str,
    (dir, lang): (&std::path::Path, Lang),
) -> Result<String, String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = mime;
        std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
        let path = dir.join(name);
        crate::export::write_atomically(&path, bytes, lang).map_err(|e| format!("{e:#}"))?;
        Ok(path.display().to_string())
    }
    #[cfg(target_arch = "wasm32")]
    {
        use wasm_bindgen::JsCast as _;
        let _ = dir;
        let fail = |e: wasm_bindgen::JsValue| {
            lang.t_with(
                "platform-the-browser-refused-the-download",
                &[("why", &format!("{e:?}"))],
            )
        };
        let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
        let options = web_sys::BlobPropertyBag::new();
        options.set_type(mime);
        let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
            .map_err(fail)?;
        let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(fail)?;
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or_else(|| "no document".to_owned())?;
        let a = document
            .create_element("a")
            .map_err(fail)?
            .dyn_into::<web_sys::HtmlAnchorElement>()
            .map_err(|_| "no link element".to_owned())?;
        a.set_href(&url);
        a.set_download(name);
        a.click();
        let _ = web_sys::Url::revoke_object_url(&url);
        Ok(name.to_owned())
    }
}

/// Keeps `text` as the unsaved edits `key` names (`None`: nothing is unsaved any more): on the
/// desktop the file `key`, beside the lesson, written whole or not at all; in the browser the
/// page's local storage under that name.
///
/// # Errors
/// When the file cannot be written, or the page refuses its storage.
pub fn keep_unsaved(key: &std::path::Path, text: Option<&str>) -> Result<(), String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        match text {
            Some(t) => {
                // The recovery copy's failure is not shown (the edits stay in the editor).
                crate::export::write_atomically(key, t.as_bytes(), Lang::EN)
                    .map_err(|e| format!("{e:#}"))
            }
            None if key.exists() => std::fs::remove_file(key).map_err(|e| e.to_string()),
            None => Ok(()),
        }
    }
    #[cfg(target_arch = "wasm32")]
    {
        let storage = web_sys::window()
            .and_then(|w| w.local_storage().ok().flatten())
            .ok_or_else(|| "the page has no local storage".to_owned())?;
        let name = format!("pipelens-unsaved:{}", key.display());
        match text {
            Some(t) => storage.set_item(&name, t),
            None => storage.remove_item(&name),
        }
        .map_err(|e| format!("the page refused its storage: {e:?}"))
    }
}

/// The unsaved edits kept under `key` (see [`keep_unsaved`]), if any.
#[must_use]
pub fn unsaved(key: &std::path::Path) -> Option<String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        std::fs::read_to_string(key).ok()
    }
    #[cfg(target_arch = "wasm32")]
    {
        web_sys::window()
            .and_then(|w| w.local_storage().ok().flatten())
            .and_then(|s| {
                s.get_item(&format!("pipelens-unsaved:{}", key.display()))
                    .ok()
                    .flatten()
            })
    }
}

/// The rayon pool's threads the page started (`start`'s `threads`): 0 in the single-threaded
/// build, or where the page is not cross-origin isolated.
#[cfg(target_arch = "wasm32")]
pub(super) static POOL_THREADS: std::sync::atomic::AtomicUsize =
    std::sync::atomic::AtomicUsize::new(0);

/// Whether a page's render worker may run beside its UI thread: only when the page's rayon pool
/// runs on Web Workers (the worker is then one of them, see `worker::spawn`).
#[cfg(target_arch = "wasm32")]
#[must_use]
pub fn render_threads() -> bool {
    POOL_THREADS.load(std::sync::atomic::Ordering::Relaxed) > 0
}

/// What the render thread calls when a job is done: a repaint of the window. On the desktop it
/// asks egui directly. In a page the render thread is a Web Worker, which must not take the
/// context's lock the UI thread holds (a page's UI thread cannot wait for a lock), so it posts
/// on a `BroadcastChannel` the UI thread listens on, and the UI thread asks for the repaint.
pub fn waker(ctx: &egui::Context) -> impl Fn() + Send + 'static {
    #[cfg(all(target_arch = "wasm32", target_feature = "atomics"))]
    {
        use wasm_bindgen::JsCast as _;
        let name = format!("pipelens-wake-{}", js_sys::Math::random());
        if let Ok(channel) = web_sys::BroadcastChannel::new(&name) {
            let ctx = ctx.clone();
            let listener = wasm_bindgen::closure::Closure::<dyn Fn()>::new(move || {
                ctx.request_repaint();
            });
            channel.set_onmessage(Some(listener.as_ref().unchecked_ref()));
            // Both live as long as the page.
            listener.forget();
            std::mem::forget(channel);
        }
        // A channel of its own per wake (once a job): a page's objects belong to one thread.
        move || {
            if let Ok(c) = web_sys::BroadcastChannel::new(&name) {
                let _ = c.post_message(&wasm_bindgen::JsValue::NULL);
                c.close();
            }
        }
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "atomics")))]
    {
        let ctx = ctx.clone();
        move || ctx.request_repaint()
    }
}
