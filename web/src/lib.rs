//! The entry point of pipelens in the browser: `scripts/build-web.sh` compiles this crate to
//! WebAssembly and writes `dist/` (this page, the wasm and its JavaScript glue). On load it starts
//! the app in the page's `<canvas id="pipelens">`; if that fails, the page says why instead of
//! staying blank. On the desktop the crate is empty: the app is the `pipelens` binary.

#[cfg(target_arch = "wasm32")]
mod web {
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::wasm_bindgen;

    /// Runs when the module is instantiated.
    #[wasm_bindgen(start)]
    pub fn main() {
        wasm_bindgen_futures::spawn_local(async {
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
            if let Err(e) = pipelens::app::platform::start(canvas).await {
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
