//! The entry point of pipelens in the browser: `scripts/build-web.sh` compiles this crate to
//! WebAssembly twice — single-threaded, and with threads (the `threads` feature: atomics, shared
//! memory, a rayon pool on Web Workers through `wasm-bindgen-rayon`) — and writes `dist/` (the
//! page, both builds and their JavaScript glue, the service worker). The page picks the threaded
//! build where it is cross-origin isolated, starts its pool (`initThreadPool`), then calls
//! `start` (wasm32 only). If that fails, the page says why instead of staying blank. On the desktop the
//! crate is empty: the app is the `pipelens` binary.

/// The rayon pool on Web Workers: the page awaits `initThreadPool(n)` before `start`.
#[cfg(all(target_arch = "wasm32", feature = "threads"))]
pub use wasm_bindgen_rayon::init_thread_pool;

#[cfg(target_arch = "wasm32")]
mod web {
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::wasm_bindgen;

    /// Starts the app in the page's `<canvas id="pipelens">`; `threads` is the size of the pool
    /// the page started (0: none, frames render on the UI thread). Not a `start` function run
    /// at instantiation: the pool's workers instantiate the same module.
    #[wasm_bindgen]
    pub fn start(threads: usize) {
        wasm_bindgen_futures::spawn_local(async move {
            let document = web_sys::window().and_then(|w| w.document());
            let canvas = document
                .as_ref()
                .and_then(|d| d.get_element_by_id("pipelens"))
                .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok());
            let Some(canvas) = canvas else {
                show_error(
                    document.as_ref(),
                    "the page has no <canvas id=\"pipelens\">",
                );
                return;
            };
            if let Err(e) = pipelens::app::start(canvas, threads).await {
                let message = e.as_string().unwrap_or_else(|| format!("{e:?}"));
                show_error(document.as_ref(), &message);
            }
        });
    }

    /// Replaces the loading message with `message`.
    fn show_error(document: Option<&web_sys::Document>, message: &str) {
        if let Some(el) = document.and_then(|d| d.get_element_by_id("status")) {
            el.set_text_content(Some(&format!("pipelens could not start: {message}")));
        }
        if let Some(d) = document {
            d.set_title("pipelens — error");
        }
    }
}
