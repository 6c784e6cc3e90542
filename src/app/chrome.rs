//! The window's chrome: one bar along the top (a lesson's step controls and list, the stage
//! navigator, the panels to show, the language, classroom mode, the snapshot export in a menu),
//! the status line (frame and stage times, errors; hidden in classroom mode) and the keyboard.

use egui::{Color32, RichText};

use super::PipelensApp;
use super::session::Command;
use super::shortcuts::{self, Action, IN_A_PICTURE, MOUSE, SHORTCUTS};
use super::views::navigator;
use crate::app::command::{LessonCommand, ViewCommand};
use crate::vocabulary::Lang;

impl PipelensApp {
    pub(super) fn top_bar(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        // One point above and below its controls (egui's two): the controls grew to the 24
        // points a mouse needs, and the picture keeps its room.
        let frame =
            egui::Frame::side_top_panel(ui.style()).inner_margin(egui::Margin::symmetric(8, 1));
        egui::Panel::top("top").frame(frame).show(ui, |ui| {
            super::style::chrome_style(ui);
            ui.spacing_mut().item_spacing.x = 6.0;
            ui.horizontal_wrapped(|ui| {
                self.lessons_menu(ui, lang);
                if self.session.lesson.is_none() {
                    ui.label(RichText::new("pipelens").strong())
                        .on_hover_text(&self.session.source);
                }
                self.step_controls(ui, lang);
                ui.separator();
                if let Some(c) = navigator::ui(ui, &self.session) {
                    self.commands.push(c);
                }
                ui.separator();
                self.panel_toggles(ui, lang);
                ui.separator();
                // Beside a narration band (1366 points, the code open) these two are in the
                // Show menu, and the bar keeps one row with a step's Play button.
                if !self.band {
                    self.language_and_classroom(ui, lang);
                }
                self.export_menu(ui, lang);
                let keys = self.panels.keys;
                let help = ui.add(super::style::glyph_button(ui, "?", Some(keys)));
                if help.clicked() {
                    self.panels.keys = !keys;
                }
                help.accessible_name(lang.t("chrome-help-keyboard-shortcuts"))
                    .on_hover_text(lang.t("chrome-keyboard-shortcuts-f1"));
            });
            self.bar_messages(ui, lang);
        });
    }

    /// The languages to choose from: every catalog's, then those the open lesson gives beyond
    /// them (named by their tags; their interface is English).
    fn languages(&self) -> Vec<Lang> {
        let mut all = Lang::all();
        if let Some(p) = &self.session.lesson {
            for tag in p.lesson.title.others.keys() {
                let l = Lang::uncatalogued(tag);
                if !all.contains(&l) {
                    all.push(l);
                }
            }
        }
        all
    }

    /// A button for each language of [`Self::languages`] other than `lang`, named in its own
    /// words; the one clicked.
    pub(super) fn language_list(&self, ui: &mut egui::Ui, lang: Lang) -> Option<Lang> {
        let mut chosen = None;
        for l in self.languages().into_iter().filter(|l| *l != lang) {
            if ui.button(l.name()).clicked() {
                chosen = Some(l);
            }
        }
        chosen
    }

    /// The language switch and the classroom toggle. The switch names the other language
    /// where there are two ([`Self::languages`]), and is a menu of them all where there are
    /// more.
    fn language_and_classroom(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let others: Vec<Lang> = self
            .languages()
            .into_iter()
            .filter(|l| *l != lang)
            .collect();
        let mut chosen = None;
        if let [other] = others[..] {
            if ui
                .button(other.name())
                .on_hover_text(lang.t("chrome-switch-the-language"))
                .clicked()
            {
                chosen = Some(other);
            }
        } else {
            ui.menu_button(format!("{} ▾", lang.name()), |ui| {
                chosen = self.language_list(ui, lang);
            })
            .response
            .on_hover_text(lang.t("chrome-switch-the-language"));
        }
        if let Some(l) = chosen {
            self.commands.push(Command::View(ViewCommand::SetLang(l)));
        }
        if ui
            .selectable_label(self.classroom, lang.t("chrome-classroom"))
            .on_hover_text(lang.t("chrome-large-type-and-high-contrast"))
            .clicked()
        {
            let on = !self.classroom;
            self.set_classroom(ui.ctx(), on);
        }
    }

    /// Under the bar: why the file on disk no longer loads, why a dropped file did not open,
    /// what an export or a kept file did — each with × to close it.
    pub(super) fn bar_messages(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let bad = (Color32::LIGHT_RED, true);
        // A dropped file's message names the file itself (`library.rs`).
        let said = [
            self.session.reload_error.as_ref().map(|e| {
                (
                    format!("{}\n{e}", lang.t("chrome-the-file-changed-on-disk")),
                    bad,
                )
            }),
            self.session.dropped_error.clone().map(|e| (e, bad)),
            self.note.as_ref().map(|(ok, words)| {
                let color = if *ok {
                    Color32::LIGHT_GREEN
                } else {
                    Color32::LIGHT_RED
                };
                (words.clone(), (color, false))
            }),
        ];
        for (k, said) in said.into_iter().enumerate() {
            let Some((words, (color, mono))) = said else {
                continue;
            };
            let closed = ui
                .horizontal_top(|ui| {
                    let close = ui
                        .add(crate::app::style::glyph_button(ui, "×", None))
                        .on_hover_text(lang.t("chrome-close-this-message"))
                        .clicked();
                    // Wrapped to the window: on a phone a line of it was cut off at the edge.
                    let text = RichText::new(words).color(color);
                    let text = if mono { text.monospace() } else { text };
                    ui.add(egui::Label::new(text).wrap());
                    close
                })
                .inner;
            if closed {
                match k {
                    0 => self.session.reload_error = None,
                    1 => self.session.dropped_error = None,
                    _ => self.note = None,
                }
            }
        }
    }

    /// ◀ Step k / n ▾ ▶ and Play/Pause, with the list of steps in the menu.
    pub(super) fn step_controls(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let Some(player) = &self.session.lesson else {
            return;
        };
        let (k, n) = (player.step, player.lesson.steps.len());
        if ui
            .add_enabled(k > 0, super::style::glyph_button(ui, "◀", None))
            .accessible_name(lang.t("chrome-previous-step"))
            .on_hover_text(lang.t("chrome-previous-step-or-page-up"))
            .clicked()
        {
            self.commands
                .push(Command::Lesson(LessonCommand::PreviousStep));
        }
        // A phone's bar has room for the numbers alone (a screen reader still hears "Step").
        let step = format!("{} {} / {n}", lang.t("chrome-step"), k + 1);
        let shown = if super::window_size::is_compact(ui.ctx()) {
            format!("{} / {n}", k + 1)
        } else {
            step.clone()
        };
        ui.menu_button(shown, |ui| {
            ui.label(RichText::new(player.lesson.title.get(lang)).strong());
            for (i, s) in player.lesson.steps.iter().enumerate() {
                if ui
                    .selectable_label(i == k, format!("{}. {}", i + 1, s.title.get(lang)))
                    .clicked()
                {
                    self.commands
                        .push(Command::Lesson(LessonCommand::GoToStep(i)));
                    ui.close();
                }
            }
        })
        .response
        .on_hover_text(player.lesson.title.get(lang))
        .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, &step));
        if ui
            .add_enabled(k + 1 < n, super::style::glyph_button(ui, "▶", None))
            .accessible_name(lang.t("chrome-next-step"))
            .on_hover_text(lang.t("chrome-next-step-or-page-down"))
            .clicked()
        {
            self.commands.push(Command::Lesson(LessonCommand::NextStep));
        }
        if !player.current().animate.is_empty() {
            let label = if player.playing {
                lang.t("chrome-pause")
            } else {
                lang.t("chrome-play")
            };
            if ui
                .button(label)
                .on_hover_text(lang.t("chrome-play-or-pause-the-animation"))
                .clicked()
            {
                self.commands
                    .push(Command::Lesson(LessonCommand::TogglePlay));
            }
        }
    }

    /// Which panels are shown: narration (N), parameters (P), inspector (I), the matrix card (M);
    /// as buttons where there is room, in a menu otherwise.
    pub(super) fn panel_toggles(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let lesson = self.session.lesson.is_some();
        // A copy, set back after: the menu's view controls need the app too.
        let mut panels = self.panels;
        let p = &mut panels;
        let toggles: [(&mut bool, &str, &str); 5] = [
            (
                &mut p.narration,
                lang.t("chrome-narration"),
                lang.t("chrome-show-or-fold-the-narration"),
            ),
            (
                &mut p.parameters,
                lang.t("chrome-parameters"),
                lang.t("chrome-the-camera-projection-rasterizer-and"),
            ),
            (
                &mut p.inspector,
                lang.t("chrome-inspector"),
                lang.t("chrome-matrices-the-vertex-table-the"),
            ),
            (
                &mut p.matrix_card,
                lang.t("chrome-matrix"),
                lang.t("chrome-the-stage-s-matrix-over"),
            ),
            (
                &mut p.shader,
                lang.t("chrome-shader"),
                lang.t("chrome-write-the-vertex-and-fragment"),
            ),
        ];
        // Chinese names are short enough for one row at 1366 points, but not at classroom
        // mode's larger type: there the toggles go into a menu, and the bar keeps one row.
        // Beside a narration band the menu also holds the stage's view controls.
        let roomy = !self.band
            && (ui.ctx().content_rect().width() > 1500.0 || (lang.is_chinese() && !self.classroom));
        if roomy {
            for (k, (on, name, tip)) in toggles.into_iter().enumerate() {
                if k > 0 || lesson {
                    ui.toggle_value(on, name).on_hover_text(tip);
                }
            }
        } else {
            ui.menu_button(lang.t("chrome-show"), |ui| {
                for (k, (on, name, tip)) in toggles.into_iter().enumerate() {
                    if k > 0 || lesson {
                        ui.checkbox(on, name).on_hover_text(tip);
                    }
                }
                if self.band {
                    ui.separator();
                    ui.horizontal(|ui| self.language_and_classroom(ui, lang));
                }
                if self.band
                    && let Some(capture) = self.session.capture.clone()
                {
                    ui.separator();
                    ui.label(RichText::new(self.session.selection.stage.name(lang)).strong());
                    self.view_controls(ui, &capture);
                }
            });
        }
        self.panels = panels;
    }

    /// The snapshot export, in a menu: the folder, the button, Cancel while it runs.
    pub(super) fn export_menu(&mut self, ui: &mut egui::Ui, lang: Lang) {
        if !super::platform::WRITES_FILES {
            // In the browser: no folders to write to, the handout downloads.
            if self.session.lesson.is_some()
                && ui
                    .button(lang.t("chrome-download-handout"))
                    .on_hover_text(lang.t("chrome-the-lesson-s-handout-in"))
                    .clicked()
            {
                self.download_handout();
            }
            if self.session.lesson.is_some()
                && ui
                    .button(lang.t("chrome-download-my-work"))
                    .on_hover_text(lang.t("chrome-one-file-with-this-lesson"))
                    .clicked()
            {
                self.export_work();
            }
            return;
        }
        let busy = self.export_result.is_some();
        ui.menu_button(lang.t("chrome-export"), |ui| {
            let label = ui.label(lang.t("chrome-folder"));
            ui.add(egui::TextEdit::singleline(&mut self.export_dir).desired_width(200.0))
                .labelled_by(label.id)
                .on_hover_text(lang.t("chrome-the-folder-the-snapshot-is"));
            if ui
                .add_enabled(!busy, egui::Button::new(lang.t("chrome-export-snapshot")))
                .on_hover_text(lang.t("chrome-every-buffer-as-png-and"))
                .clicked()
            {
                self.start_export();
            }
            if self.session.lesson.is_some()
                && ui
                    .add_enabled(
                        !busy,
                        egui::Button::new(lang.t("chrome-export-handout-and-slides")),
                    )
                    .on_hover_text(lang.t("chrome-the-lesson-s-handout-in-2"))
                    .clicked()
            {
                self.start_handout_export();
            }
            if self.session.lesson.is_some()
                && ui
                    .button(lang.t("chrome-export-my-work"))
                    .on_hover_text(lang.t("chrome-one-file-with-this-lesson-2"))
                    .clicked()
            {
                self.export_work();
            }
        });
        if let Some(cancel) = self.export_cancel.as_ref().filter(|_| busy)
            && ui
                .button(lang.t("chrome-cancel-export"))
                .on_hover_text(lang.t("chrome-stops-between-two-files-those"))
                .clicked()
        {
            cancel.cancel();
        }
    }

    pub(super) fn status_bar(&mut self, ui: &mut egui::Ui) {
        let lang = self.session.lang;
        egui::Panel::bottom("status").show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                if let Some(e) = &self.session.error {
                    ui.label(
                        RichText::new(lang.t_with("chrome-error", &[("message", e)]))
                            .color(Color32::LIGHT_RED),
                    );
                    ui.label(lang.t("chrome-showing-the-last-good-frame"));
                }
                if let (Some(c), Some(t)) = (&self.session.capture, &self.session.times) {
                    let ms = |d: std::time::Duration| format!("{:.1}", d.as_secs_f64() * 1e3);
                    ui.label(format!(
                        "{}×{} · {}× · {} {} · {} {} ms ({} {} · {} {} · {} {} · {} {})",
                        c.width(),
                        c.height(),
                        c.settings.samples.count(),
                        c.primitives.len(),
                        lang.t("chrome-triangles"),
                        lang.t("chrome-frame"),
                        ms(t.total()),
                        lang.t("chrome-vertex"),
                        ms(t.vertex),
                        lang.t("chrome-clip"),
                        ms(t.clip_setup),
                        lang.t("chrome-raster"),
                        ms(t.raster),
                        lang.t("chrome-resolve"),
                        ms(t.resolve),
                    ));
                    if let Some(s) = &c.shaders {
                        shader_counts(ui, s, c.not_finite_primitives(), lang);
                    }
                }
                if self.session.rendering() {
                    ui.spinner();
                }
            });
        });
    }

    /// The keyboard shortcuts ([`SHORTCUTS`]), the keys of a focused picture ([`IN_A_PICTURE`])
    /// and what the mouse does, in a window F1 (or ?) opens and closes; it scrolls where the
    /// window is too low for the whole list.
    pub(super) fn keys_help(&mut self, ctx: &egui::Context) {
        let lang = self.session.lang;
        if !self.panels.keys {
            return;
        }
        let mut open = true;
        let keys = |ui: &mut egui::Ui, written: &str| {
            ui.label(RichText::new(written).monospace().strong());
        };
        egui::Window::new(lang.t("chrome-keyboard-shortcuts"))
            // Over the narration card (a foreground area), opened after it: nothing covers
            // the list.
            .order(egui::Order::Foreground)
            .collapsible(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                // Chrome, at its normal size in classroom mode too: in classroom type the
                // table was wider than a 1366-point window and its keys were cut off.
                super::style::chrome_style(ui);
                // Its own close button, a target's size (egui's in the title bar is 14 points).
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Min), |ui| {
                    if ui
                        .add(super::style::glyph_button(ui, "×", None))
                        .accessible_name(lang.t("chrome-close-the-keyboard-shortcuts"))
                        .on_hover_text(lang.t("chrome-close-the-keyboard-shortcuts"))
                        .clicked()
                    {
                        open = false;
                    }
                });
                // As tall as the list, up to most of the window (egui would keep a scrolled
                // area far lower).
                let most = ctx.content_rect().height() * 0.8;
                egui::ScrollArea::vertical()
                    .max_height(most)
                    .min_scrolled_height(most)
                    .show(ui, |ui| {
                        egui::Grid::new("keys")
                            .striped(true)
                            .spacing([24.0, 6.0])
                            .show(ui, |ui| {
                                for s in &SHORTCUTS {
                                    keys(ui, &shortcuts::keys_written(s));
                                    ui.label(lang.t(s.does));
                                    ui.end_row();
                                }
                                for (written, does) in IN_A_PICTURE {
                                    keys(ui, written);
                                    ui.label(lang.t(does));
                                    ui.end_row();
                                }
                                for (written, does) in MOUSE {
                                    keys(ui, lang.t(written));
                                    ui.label(lang.t(does));
                                    ui.end_row();
                                }
                            });
                    });
            });
        self.panels.keys = open;
    }

    /// The window's shortcuts acted on: the steps or stages, the animation, the panels, the
    /// editors, classroom mode, full screen and the help (the lesson editor's Save, Undo and
    /// Redo are its own, in `editor/window.rs`; the shader editor's Apply in `views/shader.rs`).
    pub(super) fn keyboard(&mut self, ctx: &egui::Context) {
        let pressed = |a: Action| shortcuts::pressed(ctx, a);
        // With a lesson the arrows (and a presenter's Page Up/Down) step it and Space plays its
        // animations; without one they move through the stages and replay the transition.
        let lesson = self.session.lesson.is_some();
        if pressed(Action::Previous) {
            self.commands.push(if lesson {
                Command::Lesson(LessonCommand::PreviousStep)
            } else {
                Command::View(ViewCommand::PreviousStage)
            });
        }
        if pressed(Action::Next) {
            self.commands.push(if lesson {
                Command::Lesson(LessonCommand::NextStep)
            } else {
                Command::View(ViewCommand::NextStage)
            });
        }
        if pressed(Action::Play) {
            self.commands.push(if lesson {
                Command::Lesson(LessonCommand::TogglePlay)
            } else {
                Command::View(ViewCommand::PlayTransition)
            });
        }
        let p = &mut self.panels;
        for (action, shown) in [
            (Action::Narration, &mut p.narration),
            (Action::Parameters, &mut p.parameters),
            (Action::Inspector, &mut p.inspector),
            (Action::MatrixCard, &mut p.matrix_card),
            (Action::ShaderEditor, &mut p.shader),
            (Action::Keys, &mut p.keys),
            (Action::LessonEditor, &mut self.editor.open),
        ] {
            if pressed(action) {
                *shown = !*shown;
            }
        }
        if pressed(Action::Classroom) {
            let on = !self.classroom;
            self.set_classroom(ctx, on);
        }
        if pressed(Action::FocusView) {
            super::views::picture_keys::cycle(ctx);
        }
        if pressed(Action::FullScreen) {
            let full = ctx.input(|i| i.viewport().fullscreen.unwrap_or(false));
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(!full));
        }
    }
}

/// What the shaders did this frame, in the status line: triangles dropped for a `gl_Position`
/// that is not finite, fragments run, fragments discarded, and pixels whose colour came out NaN
/// or infinite (drawn black; the inspector marks the value).
fn shader_counts(
    ui: &mut egui::Ui,
    s: &pipeline::capture::ShaderRecord,
    dropped: usize,
    lang: Lang,
) {
    if dropped > 0 {
        ui.label(
            RichText::new(format!(
                "· {dropped} {}",
                lang.t("chrome-triangles-dropped-gl-position-nan")
            ))
            .color(Color32::LIGHT_RED),
        )
        .on_hover_text(lang.t("chrome-a-vertex-shader-wrote-a"));
    }
    ui.label(format!(
        "· {} {} · {} {}",
        s.fragments,
        lang.t("chrome-fragments-shaded"),
        s.discarded,
        lang.t("chrome-discarded"),
    ))
    .on_hover_text(lang.t("chrome-the-fragment-shader-ran-once"));
    if s.not_finite > 0 {
        ui.label(
            RichText::new(format!(
                "· {} {}",
                s.not_finite,
                lang.t("chrome-pixels-nan-or-drawn-black")
            ))
            .color(Color32::LIGHT_RED),
        )
        .on_hover_text(lang.t("chrome-a-shader-s-colour-was"));
    }
}
