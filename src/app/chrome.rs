//! The window's chrome: the top bar (language, classroom mode, export, the stage navigator),
//! the status line (frame and stage times, errors) and the keyboard.

use egui::RichText;

use super::session::Command;
use super::views::navigator;
use super::{PipelensApp, apply_style};

impl PipelensApp {
    pub(super) fn top_bar(&mut self, ui: &mut egui::Ui) {
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

    pub(super) fn status_bar(&mut self, ui: &mut egui::Ui) {
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

    pub(super) fn keyboard(&mut self, ctx: &egui::Context) {
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
}
