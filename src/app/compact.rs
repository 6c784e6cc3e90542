//! The layout of a phone, a tablet in portrait, or any small window: the picture first. The
//! desktop's bar (lessons, eleven stages, panel toggles) would wrap into a column of buttons and
//! its card would cover the picture, so here the bar is one row — a Menu with everything else,
//! the step arrows, the stage as a drop-down — and the narration is a sheet under the picture
//! (beside it on a phone held sideways; never over it), swiped left or right for the next or
//! previous step. The picture itself pans
//! with a drag and zooms with a pinch (the views read egui's zoom), and a tap inspects a pixel.
//! A desktop window narrower than 1600 points with the shader panel open runs the narration in
//! a band across its foot, under the picture and the code both, for the same reason.

use egui::{Context, RichText};

use super::PipelensApp;
use super::session::Command;
use crate::app::command::{LessonCommand, ViewCommand};
use crate::vocabulary::{Lang, Stage};

/// The least a swipe moves across (points), and how much more across than down it goes.
const SWIPE: f32 = 60.0;

impl PipelensApp {
    /// The bar in one row: Menu (lessons, panels, language, classroom, export, keys), the step's
    /// arrows, the stage as a drop-down; a message under it when there is one.
    pub(super) fn compact_bar(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        let tabs = self.code_tab_offered();
        let screen = ui.ctx().content_rect();
        let wide = screen.width() > screen.height();
        egui::Panel::top("top").show(ui, |ui| {
            super::style::chrome_style(ui);
            ui.spacing_mut().item_spacing.x = 4.0;
            ui.horizontal(|ui| {
                ui.menu_button(lang.t("compact-menu"), |ui| {
                    self.lessons_menu(ui, lang);
                    self.panel_toggles(ui, lang);
                    if let Some(l) = self.language_list(ui, lang) {
                        self.commands.push(Command::View(ViewCommand::SetLang(l)));
                    }
                    self.export_menu(ui, lang);
                    ui.toggle_value(&mut self.panels.keys, lang.t("compact-keys"));
                });
                self.step_controls(ui, lang);
                self.stage_menu(ui, lang);
                // On a phone held sideways the tabs share the bar's row: height is what the
                // picture lacks there.
                if tabs && wide {
                    self.picture_or_code(ui, lang);
                }
            });
            if tabs && !wide {
                self.picture_or_code(ui, lang);
            }
            self.bar_messages(ui, lang);
        });
    }

    /// Whether the step has code to show: a lab, a scene that runs GLSL (a step of lesson 24
    /// whose narration asks for an edit), a step that names the shader's lines or draws a
    /// variable over the frame or opens the shader panel, or the code already open.
    fn code_tab_offered(&self) -> bool {
        let step = self.session.lesson.as_ref().map(|p| p.current());
        self.panels.shader
            || self.session.current_exercise().is_some()
            || self.session.spec.scene.has_shaders()
            || self.session.selection.watch.is_some()
            || step.is_some_and(|s| {
                s.shader_lines.is_some()
                    || s.panels.contains(&crate::lesson::script::StepPanel::Shader)
            })
    }

    /// The picture and the code as two tabs across the screen, one tap apart: the Code tab
    /// is the shader panel over the whole screen (`code_screen`), marked "(!)" while the code
    /// does not compile.
    fn picture_or_code(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let failed = !self.shader_editor.compiles();
        ui.horizontal(|ui| {
            let gap = ui.spacing().item_spacing.x;
            let size = egui::vec2(
                (ui.available_width() - gap) / 2.0,
                ui.spacing().interact_size.y,
            );
            let code = if failed {
                format!("{} (!)", lang.t("compact-code"))
            } else {
                lang.t("compact-code").to_owned()
            };
            let tabs = [(false, lang.t("compact-picture").to_owned()), (true, code)];
            for (shader, name) in tabs {
                let tab = ui.add_sized(
                    size,
                    egui::Button::selectable(self.panels.shader == shader, name),
                );
                if tab.clicked() {
                    self.panels.shader = shader;
                }
            }
        });
    }

    /// The stage on screen, and the others to go to, in a drop-down.
    fn stage_menu(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let now = self.session.selection.stage;
        egui::ComboBox::from_id_salt("stage-menu")
            .selected_text(RichText::new(now.name(lang)).strong())
            .show_ui(ui, |ui| {
                for stage in Stage::ALL {
                    if ui
                        .selectable_label(stage == now, stage.name(lang))
                        .on_hover_text(stage.explanation(lang))
                        .clicked()
                    {
                        self.commands
                            .push(Command::View(ViewCommand::SelectStage(stage)));
                    }
                }
            })
            .response
            .widget_info(|| {
                egui::WidgetInfo::labeled(egui::Role::ComboBox, true, lang.t("compact-stage"))
            });
    }

    /// The narration in a sheet under the picture (upright: at most two fifths of the height) or
    /// beside it (on its side, where height is what the picture lacks), scrolled when longer; a
    /// swipe across it goes to the next step (leftwards) or the one before.
    pub(super) fn narration_sheet(&mut self, ui: &mut egui::Ui) {
        let screen = ui.ctx().content_rect();
        let panel = if screen.width() > screen.height() {
            egui::Panel::right("narration-sheet")
                .resizable(true)
                .min_size(160.0)
                .default_size(screen.width() * 0.36)
                .max_size(screen.width() * 0.5)
        } else {
            egui::Panel::bottom("narration-sheet")
                .resizable(true)
                .min_size(60.0)
                .default_size(screen.height() * 0.3)
                .max_size(screen.height() * 0.4)
        };
        let sheet = panel.show(ui, |ui| {
            egui::ScrollArea::vertical()
                .id_salt("narration-sheet-scroll")
                .auto_shrink([false, false])
                .show(ui, |ui| super::views::lesson::sheet(ui, &self.session))
                .inner
        });
        let lang = self.session.lang;
        super::layout::name_divider(ui, "narration-sheet", lang.t("chrome-narration"), lang);
        self.narrated(sheet.inner);
        if let Some(step) = swiped(ui.ctx(), sheet.response.rect) {
            self.commands.push(step);
        }
    }

    /// The narration in a band across the window's foot, under the picture and the shader
    /// panel both (see `narration_in_band`): as high as its words, their type shrunk as the
    /// card's is to fit a quarter of the window (never below the normal size); words that
    /// still do not fit take up to a third, and scroll beyond.
    pub(super) fn narration_band(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let fit = ctx.content_rect().height() / 4.0;
        let most = ctx.content_rect().height() / 3.0;
        // As high as its words were last frame (a panel keeps the size it was given).
        let words_id = egui::Id::unique("narration-band-words");
        let words = ctx.data(|d| d.get_temp::<f32>(words_id)).unwrap_or(most);
        // The panel's frame around its words, as measured last frame.
        let margin_id = egui::Id::unique("narration-band-margin");
        let margin = ctx.data(|d| d.get_temp::<f32>(margin_id)).unwrap_or(16.0);
        let band = egui::Panel::bottom("narration-band")
            .resizable(false)
            .exact_size((words + margin).min(most))
            .show(ui, |ui| {
                let inner = ui.available_height();
                (
                    super::views::lesson::band(ui, &self.session, fit - margin),
                    inner,
                )
            });
        let ((out, height), inner) = band.inner;
        let framed = band.response.rect.height() - inner;
        if (framed - margin).abs() > 0.5 {
            ctx.data_mut(|d| d.insert_temp(margin_id, framed));
            ctx.request_repaint();
        }
        if (height - words).abs() > 0.5 {
            ctx.data_mut(|d| d.insert_temp(words_id, height));
            ctx.request_repaint();
        }
        self.narrated(out);
    }
}

/// A swipe across `rect` let go this frame: leftwards the next step, rightwards the one before.
/// Read from the press and release events (a finger's too), kept from one frame to the next, so
/// that the sheet's scrolling and buttons keep their own drags and taps.
fn swiped(ctx: &Context, rect: egui::Rect) -> Option<Command> {
    let id = egui::Id::unique("narration-sheet-press");
    let (pressed, released) = ctx.input(|i| {
        let (mut pressed, mut released) = (None, None);
        for e in &i.events {
            if let egui::Event::PointerButton {
                pos,
                pressed: down,
                button: egui::PointerButton::Primary,
                ..
            } = e
            {
                if *down {
                    pressed = Some(*pos);
                } else {
                    released = Some(*pos);
                }
            }
        }
        (pressed, released)
    });
    if let Some(p) = pressed {
        ctx.data_mut(|d| d.insert_temp(id, p));
    }
    let to = released?;
    let from: egui::Pos2 = ctx.data_mut(|d| d.remove_temp(id))?;
    let d = to - from;
    (rect.contains(from) && d.x.abs() > SWIPE && d.x.abs() > 2.0 * d.y.abs()).then_some(
        if d.x < 0.0 {
            Command::Lesson(LessonCommand::NextStep)
        } else {
            Command::Lesson(LessonCommand::PreviousStep)
        },
    )
}
