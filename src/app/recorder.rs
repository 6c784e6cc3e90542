//! "Add step" (issue 36, a first slice): the teacher sets up the view by clicking — stage,
//! buffer, overlays, a pixel, parameters — opens this window (R), words the step in both
//! languages, and records it. The step on screen (`record::recorded_step`) is written into the
//! lesson file after the current step, whole or not at all, the rest of the file kept line for
//! line; live reload then shows it as the next step. Only a lesson opened from a file on disk
//! can be recorded into.

use egui::{Context, RichText};

use crate::app::session::Session;
use crate::vocabulary::{Lang, Text};

/// The window's state: open or not, the words typed, what the last recording said.
#[derive(Default)]
pub struct Recorder {
    /// Whether the window is shown.
    pub open: bool,
    title: Text,
    narration: Text,
    said: Option<Result<String, String>>,
}

impl Recorder {
    /// The window, when open; `file` is the lesson file on disk, if the lesson came from one.
    pub fn ui(&mut self, ctx: &Context, session: &Session, file: Option<&std::path::Path>) {
        if !self.open {
            return;
        }
        let lang = session.lang;
        let mut open = self.open;
        // Over the narration card (a foreground layer too), at the top-right, off the picture's
        // subject side the card keeps.
        egui::Window::new(lang.tr("Add a step", "添加步骤"))
            .open(&mut open)
            .order(egui::Order::Foreground)
            .anchor(egui::Align2::RIGHT_TOP, egui::vec2(-16.0, 64.0))
            .default_width(560.0)
            .show(ctx, |ui| self.contents(ui, session, file, lang));
        self.open = open;
    }

    fn contents(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        file: Option<&std::path::Path>,
        lang: Lang,
    ) {
        let Some(player) = &session.lesson else {
            ui.label(lang.tr(
                "Open a lesson to add steps to it.",
                "打开一个课程后才能向其中添加步骤。",
            ));
            return;
        };
        ui.label(lang.tr(
            "What is on screen becomes a step after this one: the stage, the buffer, the layout, the overlays, the inspected pixel, the selected vertex and every parameter changed since this step began.",
            "屏幕上的内容成为当前步骤之后的新步骤：阶段、缓冲、布局、叠加层、所检查的像素、选中的顶点，以及本步骤开始以来改动过的每个参数。",
        ));
        let Some(step) = super::record::recorded_step(session) else {
            return;
        };
        if step.set.is_empty() {
            ui.label(lang.tr("No parameter changed.", "没有改动参数。"));
        } else {
            for (name, value) in &step.set {
                ui.monospace(format!("{name} = {value}"));
            }
        }
        ui.separator();
        self.words(ui, lang);
        let k = player.step + 1;
        let button = ui.add_enabled(
            file.is_some(),
            egui::Button::new(match lang {
                Lang::En => format!("Record as step {}", k + 1),
                Lang::Zh => format!("记录为第 {} 步", k + 1),
            }),
        );
        let button = if file.is_none() {
            button.on_disabled_hover_text(lang.tr(
                "Only a lesson opened from a file on disk can be recorded into.",
                "只有从磁盘文件打开的课程才能记录步骤。",
            ))
        } else {
            button
        };
        if button.clicked()
            && let Some(file) = file
        {
            let mut step = step;
            // Untitled, it keeps the stage's name `recorded_step` gave it.
            if crate::lesson::record::unworded(&self.title).len() < 2 {
                step.title = self.title.clone();
            }
            step.narration = self.narration.clone();
            self.said = Some(
                write(file, k, &step)
                    .map(|()| format!("{} {}", lang.tr("Written into", "已写入"), file.display())),
            );
            if matches!(self.said, Some(Ok(_))) {
                self.title = Text::default();
                self.narration = Text::default();
            }
        }
        match &self.said {
            Some(Ok(m)) => {
                ui.label(RichText::new(m).color(egui::Color32::LIGHT_GREEN));
            }
            Some(Err(e)) => {
                ui.label(RichText::new(e).color(ui.visuals().error_fg_color));
            }
            None => {}
        }
    }

    /// The title and the narration, English and Chinese side by side, and what is still missing.
    fn words(&mut self, ui: &mut egui::Ui, lang: Lang) {
        for (label, text, rows) in [
            (lang.tr("Title", "标题"), &mut self.title, 1),
            (lang.tr("Narration", "讲解"), &mut self.narration, 4),
        ] {
            ui.label(RichText::new(label).strong());
            ui.columns(2, |cols| {
                for (col, (name, words)) in cols
                    .iter_mut()
                    .zip([("English", &mut text.en), ("中文", &mut text.zh)])
                {
                    col.label(name);
                    col.add(egui::TextEdit::multiline(words).desired_rows(rows));
                }
            });
        }
        let missing: Vec<&str> = crate::lesson::record::unworded(&self.narration)
            .into_iter()
            .map(|l| if l == Lang::En { "English" } else { "中文" })
            .collect();
        if !missing.is_empty() {
            ui.label(
                RichText::new(format!(
                    "{} {}",
                    lang.tr("The narration still needs:", "讲解还缺少："),
                    missing.join(", ")
                ))
                .color(ui.visuals().warn_fg_color),
            );
        }
    }
}

/// `step` inserted into the lesson file `file` as its step `at`, the file written whole or not
/// at all.
fn write(file: &std::path::Path, at: usize, step: &crate::lesson::Step) -> Result<(), String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let out = crate::lesson::record::insert_step(&text, at, step)?;
    crate::export::write_atomically(file, out.as_bytes()).map_err(|e| format!("{e:#}"))
}
