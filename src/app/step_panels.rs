//! The side panels a lesson's step calls for: those it opens on entering it (the code where it
//! draws a variable over the frame or names its lines, the inspector where there is room),
//! where the narration goes beside the code, and the shader panel itself.

use super::PipelensApp;
use super::layout::Room;

impl PipelensApp {
    /// The shader panel on the right: the student's GLSL, its debugger and own uniforms (the
    /// variable picture left out while the view draws it).
    pub(super) fn shader_panel(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        self.variable_picture_in_view(self.pixel_view.drew_watch);
        // Wide enough for an 80-column line of code where the window allows it (at 1920
        // points, 760 leave the picture more than half), narrower in a smaller one. A lab shows
        // three pictures (the student's frame, pipelens' own and their difference), so its code
        // starts narrower, at 33 %: on a 1366-point projector with the narration band they
        // keep more than a third of the window. Beside the inspector or the lesson editor it
        // starts narrower again, for the two to leave the view half of the window, and beside
        // them in a lab at 23 %. Each arrangement has its own id, so a drag sets the width
        // for it alone.
        let window = ui.ctx().content_rect().width();
        let lab = self.session.current_exercise().is_some();
        let (id, share, most) = match (lab, self.room()) {
            (true, Room::Alone) => ("shader-lab", 0.33, 760.0),
            (false, Room::Alone) => ("shader", 0.4, 760.0),
            (_, Room::Beside) => ("shader-beside", 0.3, 600.0),
            (_, Room::Crowded) => ("shader-crowded", 0.23, 480.0),
        };
        let wide = (window * share).clamp(440.0, most);
        egui::Panel::right(id)
            .default_size(wide)
            .resizable(true)
            .show(ui, |ui| {
                // The code at the chrome's size in classroom mode too: the picture and the
                // narration are what the room reads, and the code's type stays no larger
                // than the narration's.
                crate::app::style::chrome_style(ui);
                ui.heading(lang.t("step-panels-shaders-glsl"));
                self.commands.extend(crate::app::views::shader::ui(
                    ui,
                    &mut self.shader_editor,
                    &self.session,
                    (std::path::Path::new(self.export_dir.trim()), None),
                ));
            });
        super::layout::name_divider(ui, id, lang.t("chrome-shader"), lang);
    }

    /// A small screen's Code tab (`compact.rs`): the code over the whole screen, a lab's verdict
    /// above it, always in sight, and on a touch screen the keys GLSL needs below it (above the
    /// phone's keyboard).
    pub(super) fn code_screen(&mut self, ui: &mut egui::Ui) {
        // No view is drawn here: the panel shows the variable picture itself.
        self.variable_picture_in_view(false);
        if self.session.current_exercise().is_some() {
            egui::Panel::top("verdict-strip").show(ui, |ui| {
                crate::app::style::chrome_style(ui);
                crate::app::views::exercise::strip(ui, &self.session);
            });
        }
        // The keys across the whole width (a finger's size each on a 360-point phone), read
        // before the source they type into.
        let lang = self.session.lang;
        let key = crate::app::style::is_touch(ui.ctx())
            .then(|| {
                egui::Panel::bottom("glsl-keys")
                    .frame(egui::Frame::NONE.inner_margin(egui::Margin::symmetric(0, 4)))
                    .show(ui, |ui| crate::app::views::glsl_keys::row(ui, lang))
                    .inner
            })
            .flatten();
        egui::CentralPanel::default().show(ui, |ui| {
            crate::app::style::chrome_style(ui);
            self.commands.extend(crate::app::views::shader::ui(
                ui,
                &mut self.shader_editor,
                &self.session,
                (std::path::Path::new(self.export_dir.trim()), Some(key)),
            ));
        });
    }

    /// The variable picture the view draws (`drawn`: it did last frame) is left out of the
    /// shader panel.
    fn variable_picture_in_view(&mut self, drawn: bool) {
        let sel = &self.session.selection;
        let in_view = drawn && sel.stage.space().is_none();
        let debugger = &mut self.shader_editor.debugger;
        debugger.watch.in_view = in_view && sel.watch.is_some();
        debugger.vertex_watch.in_view = debugger.watch.in_view;
        debugger.cost.in_view = in_view && sel.watch.is_none() && sel.cost;
    }

    /// On entering a step, the panels it needs: a step that draws a variable over the frame
    /// or names its shader lines opens the shader panel on the watched shader's tab (the
    /// fragment shader's, where its lines are scrolled to), and a step's `panels` are opened
    /// (the inspector where there is room; one left open folds when the step opens the code
    /// where there is none). Not in a small window, where a panel covers the picture.
    pub(super) fn open_for_step(&mut self, ctx: &egui::Context, compact: bool) {
        if self.step_opened == self.session.step_entered {
            return;
        }
        self.step_opened = self.session.step_entered;
        if compact {
            return;
        }
        let step = self.session.lesson.as_ref().map(|p| p.current());
        let lines = step.and_then(|s| s.shader_lines);
        let panels = step.map(|s| s.panels.clone()).unwrap_or_default();
        let had_shader = self.panels.shader;
        if self.session.selection.watch.is_some() || lines.is_some() {
            self.panels.shader = true;
            // The tab of the watched shader (a vertex shader's watch opens its own).
            let stage = match &self.session.selection.watch {
                Some(w) if lines.is_none() => w.stage,
                _ => pipeline::shader::Stage::Fragment,
            };
            self.shader_editor.tab = crate::app::views::shader::Tab::Shader(stage);
        }
        self.shader_editor.debugger.lines =
            lines.map(|l| (l, crate::app::views::debugger::REVEAL_FRAMES));
        for p in panels {
            match p {
                crate::lesson::script::StepPanel::Inspector => {
                    self.panels.inspector |= self.room_for_inspector(ctx);
                }
                crate::lesson::script::StepPanel::Shader => self.panels.shader = true,
            }
        }
        // The code opened by the step beside an inspector left open in a narrow window: the
        // inspector folds (I brings it back), so that the picture is not crushed between them.
        if self.panels.shader && !had_shader && !self.room_for_inspector(ctx) {
            self.panels.inspector = false;
        }
    }

    /// Whether the inspector can open beside what is open without crushing the picture: the
    /// shader panel and the inspector together need a wide window (a 1366-point projector
    /// keeps the picture and the code; the inspector then opens when asked, with I).
    pub(super) fn room_for_inspector(&self, ctx: &egui::Context) -> bool {
        !self.panels.shader || ctx.content_rect().width() >= 1600.0
    }

    /// Whether the narration runs in a band across the window's foot rather than in a card over
    /// the picture: with the shader panel open in a window narrower than 1600 points (a
    /// 1366×768 projector), where a card under the picture would leave it a fifth of the
    /// window; across both the picture and the code its words take fewer lines.
    pub(super) fn narration_in_band(&self, ctx: &egui::Context) -> bool {
        self.panels.shader && ctx.content_rect().width() < 1600.0
    }
}
