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
        egui::Panel::top("top").show(ui, |ui| {
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
                ui.toggle_value(&mut self.panels.keys, "?")
                    .accessible_name(lang.tr("Help: keyboard shortcuts", "帮助：键盘快捷键"))
                    .on_hover_text(lang.tr("Keyboard shortcuts (F1)", "键盘快捷键（F1）"));
            });
            self.bar_messages(ui, lang);
        });
    }

    /// The language switch and the classroom toggle.
    fn language_and_classroom(&mut self, ui: &mut egui::Ui, lang: Lang) {
        if ui
            .button(lang.other().name())
            .on_hover_text(lang.tr("Switch the language", "切换语言"))
            .clicked()
        {
            self.commands
                .push(Command::View(ViewCommand::SetLang(lang.other())));
        }
        if ui
            .selectable_label(self.classroom, lang.tr("Classroom", "课堂模式"))
            .on_hover_text(lang.tr(
                "Large type and high contrast for a projector; the picture first (C). F11: full screen, Ctrl +/−: text size, ←/→: steps or stages, Space: play.",
                "投影用的大字号与高对比度，画面优先（C）。F11：全屏，Ctrl +/−：字号，←/→：步骤或阶段，空格：播放。",
            ))
            .clicked()
        {
            let on = !self.classroom;
            self.set_classroom(ui.ctx(), on);
        }
    }

    /// Under the bar: why the file on disk no longer loads, why a dropped file did not open
    /// (each with × to close it), what an export did.
    pub(super) fn bar_messages(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let said = [
            (
                self.session.reload_error.clone(),
                lang.tr(
                    "The file changed on disk and no longer loads; the last good version keeps running:",
                    "文件在磁盘上被修改后无法加载；继续运行上一个正确的版本：",
                ),
            ),
            (
                self.session.dropped_error.clone(),
                lang.tr(
                    "The dropped file did not open; what was open keeps running:",
                    "拖入的文件未能打开；继续运行原来打开的内容：",
                ),
            ),
        ];
        for (k, (error, heading)) in said.into_iter().enumerate() {
            let Some(e) = error else { continue };
            let closed = ui
                .horizontal_top(|ui| {
                    let close = ui
                        .small_button("×")
                        .on_hover_text(lang.tr("Close this message", "关闭此消息"))
                        .clicked();
                    ui.label(
                        RichText::new(format!("{heading}\n{e}"))
                            .monospace()
                            .color(Color32::LIGHT_RED),
                    );
                    close
                })
                .inner;
            if closed {
                match k {
                    0 => self.session.reload_error = None,
                    _ => self.session.dropped_error = None,
                }
            }
        }
        if let Some((ok, msg)) = &self.export_message {
            ui.label(RichText::new(msg).color(if *ok {
                Color32::LIGHT_GREEN
            } else {
                Color32::LIGHT_RED
            }));
        }
    }

    /// ◀ Step k / n ▾ ▶ and Play/Pause, with the list of steps in the menu.
    pub(super) fn step_controls(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let Some(player) = &self.session.lesson else {
            return;
        };
        let (k, n) = (player.step, player.lesson.steps.len());
        if ui
            .add_enabled(k > 0, egui::Button::new("◀"))
            .accessible_name(lang.tr("Previous step", "上一步"))
            .on_hover_text(lang.tr("Previous step (← or Page Up)", "上一步（← 或 Page Up）"))
            .clicked()
        {
            self.commands
                .push(Command::Lesson(LessonCommand::PreviousStep));
        }
        ui.menu_button(
            format!("{} {} / {n}", lang.tr("Step", "步骤"), k + 1),
            |ui| {
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
            },
        )
        .response
        .on_hover_text(player.lesson.title.get(lang));
        if ui
            .add_enabled(k + 1 < n, egui::Button::new("▶"))
            .accessible_name(lang.tr("Next step", "下一步"))
            .on_hover_text(lang.tr("Next step (→ or Page Down)", "下一步（→ 或 Page Down）"))
            .clicked()
        {
            self.commands.push(Command::Lesson(LessonCommand::NextStep));
        }
        if !player.current().animate.is_empty() {
            let label = if player.playing {
                lang.tr("‖ Pause", "‖ 暂停")
            } else {
                lang.tr("▶ Play", "▶ 播放")
            };
            if ui
                .button(label)
                .on_hover_text(lang.tr(
                    "Play or pause the animation (Space)",
                    "播放或暂停动画（空格）",
                ))
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
                lang.tr("Narration", "讲解"),
                lang.tr(
                    "Show or fold the narration over the picture (N)",
                    "显示或收起画面上的讲解（N）",
                ),
            ),
            (
                &mut p.parameters,
                lang.tr("Parameters", "参数"),
                lang.tr(
                    "The camera, projection, rasterizer and objects (P)",
                    "相机、投影、光栅化与物体（P）",
                ),
            ),
            (
                &mut p.inspector,
                lang.tr("Inspector", "检查器"),
                lang.tr(
                    "Matrices, the vertex table, the pixel inspector (I)",
                    "矩阵、顶点表、像素检查器（I）",
                ),
            ),
            (
                &mut p.matrix_card,
                lang.tr("Matrix", "矩阵卡片"),
                lang.tr(
                    "The stage's matrix over the geometry (M)",
                    "在几何视图上显示本阶段的矩阵（M）",
                ),
            ),
            (
                &mut p.shader,
                lang.tr("Shader", "着色器"),
                lang.tr(
                    "Write the vertex and fragment shaders in GLSL; Ctrl+Enter applies (S)",
                    "用 GLSL 编写顶点与片元着色器；Ctrl+Enter 应用（S）",
                ),
            ),
        ];
        // Chinese names are short enough for one row at 1366 points, but not at classroom
        // mode's larger type: there the toggles go into a menu, and the bar keeps one row.
        // Beside a narration band the menu also holds the stage's view controls.
        let roomy = !self.band
            && (ui.ctx().content_rect().width() > 1500.0 || (lang == Lang::Zh && !self.classroom));
        if roomy {
            for (k, (on, name, tip)) in toggles.into_iter().enumerate() {
                if k > 0 || lesson {
                    ui.toggle_value(on, name).on_hover_text(tip);
                }
            }
        } else {
            ui.menu_button(lang.tr("Show ▾", "显示 ▾"), |ui| {
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
                    .button(lang.tr("Download handout", "下载讲义"))
                    .on_hover_text(lang.tr(
                        "The lesson's handout in this language as one HTML file, every image in it, printable (it takes a few seconds to render every step). Snapshots of every buffer: the desktop app or `pipelens export`.",
                        "以当前语言下载本课讲义：一个 HTML 文件，图片都在其中，可打印（渲染每一步需要几秒）。各缓冲的快照：请用桌面版或 `pipelens export`。",
                    ))
                    .clicked()
            {
                self.download_handout();
            }
            if self.session.lesson.is_some()
                && ui
                    .button(lang.tr("Download my work", "下载我的作业"))
                    .on_hover_text(lang.tr(
                        "One file with this lesson's code you last ran at each step and the answers you typed (LESSON-work.toml): hand it in; a teacher grades it with `pipelens grade LESSON FILE`.",
                        "一个文件，包含你在本课每一步最后运行的代码和填写的答案（LESSON-work.toml）：交上这个文件；老师用 `pipelens grade 课程 文件` 评分。",
                    ))
                    .clicked()
            {
                self.export_work();
            }
            return;
        }
        let busy = self.export_result.is_some();
        ui.menu_button(lang.tr("Export ▾", "导出 ▾"), |ui| {
            let label = ui.label(lang.tr("Folder", "文件夹"));
            ui.add(egui::TextEdit::singleline(&mut self.export_dir).desired_width(200.0))
                .labelled_by(label.id)
                .on_hover_text(lang.tr(
                    "The folder the snapshot is written to (created if missing).",
                    "快照写入的文件夹（不存在时创建）。",
                ));
            if ui
                .add_enabled(
                    !busy,
                    egui::Button::new(lang.tr("Export snapshot", "导出快照")),
                )
                .on_hover_text(lang.tr(
                    "Every buffer as PNG and capture.json, as `pipelens export` writes them.",
                    "每个缓冲的 PNG 与 capture.json，与 `pipelens export` 相同。",
                ))
                .clicked()
            {
                self.start_export();
            }
            if self.session.lesson.is_some()
                && ui
                    .add_enabled(
                        !busy,
                        egui::Button::new(lang.tr(
                            "Export handout and slides",
                            "导出讲义与幻灯片",
                        )),
                    )
                    .on_hover_text(lang.tr(
                        "The lesson's handout in this language (index.html, every image in it, printable) and one 1920×1080 slide per step (slides/), as `pipelens export LESSON --slides` writes them.",
                        "用当前语言导出本课的讲义（index.html，图片都在其中，可打印）和每步一张 1920×1080 的幻灯片（slides/），与 `pipelens export 课程 --slides` 相同。",
                    ))
                    .clicked()
            {
                self.start_handout_export();
            }
            if self.session.lesson.is_some()
                && ui
                    .button(lang.tr("Export my work", "导出我的作业"))
                    .on_hover_text(lang.tr(
                        "One file with this lesson's code you last ran at each step and the answers you typed (LESSON-work.toml, into the folder above): hand it in; a teacher grades it with `pipelens grade LESSON FILE`.",
                        "一个文件，包含你在本课每一步最后运行的代码和填写的答案（LESSON-work.toml，写入上面的文件夹）：交上这个文件；老师用 `pipelens grade 课程 文件` 评分。",
                    ))
                    .clicked()
            {
                self.export_work();
            }
        });
        if let Some(cancel) = self.export_cancel.as_ref().filter(|_| busy)
            && ui
                .button(lang.tr("Cancel export", "取消导出"))
                .on_hover_text(lang.tr(
                    "Stops between two files: those written stay whole.",
                    "在两个文件之间停止：已写入的文件保持完整。",
                ))
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
                        RichText::new(format!("{}: {e}", lang.tr("Error", "错误")))
                            .color(Color32::LIGHT_RED),
                    );
                    ui.label(lang.tr("(showing the last good frame)", "（显示上一个正确的帧）"));
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
        let mut open = self.panels.keys;
        let keys = |ui: &mut egui::Ui, written: &str| {
            ui.label(RichText::new(written).monospace().strong());
        };
        egui::Window::new(lang.tr("Keyboard shortcuts", "键盘快捷键"))
            // Over the narration card (a foreground area), opened after it: nothing covers
            // the list.
            .order(egui::Order::Foreground)
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                // Chrome, at its normal size in classroom mode too: in classroom type the
                // table was wider than a 1366-point window and its keys were cut off.
                super::style::chrome_style(ui);
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
                                    ui.label(lang.tr(s.does.0, s.does.1));
                                    ui.end_row();
                                }
                                for ((en_keys, zh_keys), (en, zh)) in
                                    IN_A_PICTURE.iter().chain(&MOUSE)
                                {
                                    keys(ui, lang.tr(en_keys, zh_keys));
                                    ui.label(lang.tr(en, zh));
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
                lang.tr(
                    "triangles dropped: gl_Position NaN or ∞",
                    "个三角形被丢弃：gl_Position 为 NaN 或 ∞"
                )
            ))
            .color(Color32::LIGHT_RED),
        )
        .on_hover_text(lang.tr(
            "A vertex shader wrote a gl_Position that is not a finite number (a division by zero, normalize(vec3(0.0))): nothing can be drawn from it, so its triangles are dropped before clipping. The Vertices tab shows the vertex's run.",
            "顶点着色器写出的 gl_Position 不是有限数（除以零、normalize(vec3(0.0))）：无法据此绘制，所以它的三角形在裁剪之前就被丢弃。顶点表标签页显示该顶点的运行过程。",
        ));
    }
    ui.label(format!(
        "· {} {} · {} {}",
        s.fragments,
        lang.tr("fragments shaded", "个片元已着色"),
        s.discarded,
        lang.tr("discarded", "个被丢弃"),
    ))
    .on_hover_text(lang.tr(
        "The fragment shader ran once per fragment (2×2 quads' helper lanes not counted); `discard` threw these away.",
        "片元着色器对每个片元运行一次（2×2 像素块的辅助通道不计）；这些被 `discard` 丢弃。",
    ));
    if s.not_finite > 0 {
        ui.label(
            RichText::new(format!(
                "· {} {}",
                s.not_finite,
                lang.tr("pixels NaN or ∞ (drawn black)", "个像素为 NaN 或 ∞（画成黑色）")
            ))
            .color(Color32::LIGHT_RED),
        )
        .on_hover_text(lang.tr(
            "A shader's colour was not a finite number, e.g. normalize(vec3(0.0)) or 0.0/0.0: click such a pixel to see the statement that made it.",
            "着色器输出的颜色不是有限数，例如 normalize(vec3(0.0)) 或 0.0/0.0：单击这样的像素，查看产生它的语句。",
        ));
    }
}
