//! The shader panel's tabs: a tab for each function of the pipeline the scene runs and for the
//! vertex and the fragment shader, marked "(!)" when its source does not compile, their names
//! and what each says when hovered.

use egui::Ui;
use pipeline::shader::{HookKind, Stage};

use crate::vocabulary::Lang;

/// A tab of the panel: a shader, or a function the pipeline calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    /// A shader stage.
    Shader(Stage),
    /// The rasterizer's inside or depth test.
    Hook(HookKind),
}

/// What a function's tab says when hovered, in English and Chinese.
fn hook_tip(kind: HookKind, lang: Lang) -> String {
    let what = match kind {
        HookKind::Inside => lang.t("shader-the-rasterizer-calls-it-for"),
        HookKind::DepthTest => lang.t("shader-the-rasterizer-calls-it-for-2"),
        HookKind::Curve => lang.t("shader-a-b-zier-curve-s"),
        HookKind::ShadowMatrix => lang.t("shader-the-shadow-pass-calls-it"),
        HookKind::Patch => lang.t("shader-a-b-zier-patch-s"),
    };
    format!("{}\n{what}", kind.signature())
}

/// A function's tab's name.
fn hook_label(kind: HookKind, lang: Lang) -> &'static str {
    match kind {
        HookKind::Inside => lang.t("shader-inside-test"),
        HookKind::DepthTest => lang.t("shader-depth-test"),
        HookKind::Curve => lang.t("shader-de-casteljau"),
        HookKind::ShadowMatrix => lang.t("shader-shadow-matrix"),
        HookKind::Patch => lang.t("shader-b-zier-patch"),
    }
}

/// The tabs `tabs` (the functions the pipeline calls that the scene runs, the vertex and the
/// fragment shader), each with whether its source does not compile (marked "(!)"); `shown`
/// the one chosen.
pub(super) fn tabs(ui: &mut Ui, shown: &mut Tab, tabs: &[(Tab, bool)], lang: Lang) {
    ui.horizontal(|ui| {
        for &(tab, failed) in tabs {
            let name = tab_name(tab, lang);
            let label = if failed { format!("{name} (!)") } else { name };
            let response = ui.selectable_value(shown, tab, label);
            if let Tab::Hook(kind) = tab {
                response.on_hover_text(hook_tip(kind, lang));
            }
        }
    });
}

/// A tab's name, as its button shows it and a screen reader names its source.
pub(super) fn tab_name(tab: Tab, lang: Lang) -> String {
    match tab {
        Tab::Hook(kind) => hook_label(kind, lang).to_owned(),
        Tab::Shader(Stage::Vertex) => lang.t("shader-vertex-shader").to_owned(),
        Tab::Shader(Stage::Fragment) => lang.t("shader-fragment-shader").to_owned(),
    }
}
