//! The lesson panel: the step's title and narration in the chosen language, the step controls
//! (←/→, Space), the list of steps, and the self-study question with its answer.

use egui::text::LayoutJob;
use egui::{Color32, FontId, RichText, TextFormat, Ui};

use crate::app::session::{Command, LessonPlayer};
use crate::vocabulary::Lang;

/// Draws the lesson panel; returns what the user asked for.
pub fn ui(ui: &mut Ui, player: &LessonPlayer, lang: Lang) -> Vec<Command> {
    let mut out = Vec::new();
    let lesson = &player.lesson;
    let step = player.current();
    ui.label(
        RichText::new(lesson.title.get(lang))
            .strong()
            .size(ui.style().text_styles[&egui::TextStyle::Body].size * 1.1),
    )
    .on_hover_text(lesson.summary.get(lang));
    controls(ui, player, lang, &mut out);
    ui.separator();
    egui::ScrollArea::vertical()
        .id_salt("lesson")
        .max_height(ui.available_height() * 0.62)
        .show(ui, |ui| {
            ui.heading(step.title.get(lang));
            narration(ui, step.narration.get(lang));
            for a in &step.animate {
                ui.label(
                    RichText::new(format!(
                        "{} {}: {} → {}",
                        lang.tr("animating", "动画"),
                        a.param,
                        a.from,
                        a.to
                    ))
                    .weak()
                    .small(),
                );
            }
            if let Some(q) = &step.question {
                ui.separator();
                ui.label(RichText::new(lang.tr("Question", "思考题")).strong());
                narration(ui, q.get(lang));
                if let Some(a) = &step.answer {
                    let shown = player.show_answer;
                    let label = if shown {
                        lang.tr("Hide the answer", "隐藏答案")
                    } else {
                        lang.tr("Show the answer", "显示答案")
                    };
                    if ui.button(label).clicked() {
                        out.push(Command::ShowAnswer(!shown));
                    }
                    if shown {
                        narration(ui, a.get(lang));
                    }
                }
            }
        });
    ui.separator();
    egui::CollapsingHeader::new(lang.tr("All steps", "全部步骤"))
        .id_salt("steps")
        .show(ui, |ui| {
            for (k, s) in lesson.steps.iter().enumerate() {
                if ui
                    .selectable_label(
                        k == player.step,
                        format!("{}. {}", k + 1, s.title.get(lang)),
                    )
                    .clicked()
                {
                    out.push(Command::GoToStep(k));
                }
            }
        });
    out
}

/// ◀ Step k / n ▶ and Play/Pause.
fn controls(ui: &mut Ui, player: &LessonPlayer, lang: Lang, out: &mut Vec<Command>) {
    let (step, n) = (player.current(), player.lesson.steps.len());
    ui.horizontal(|ui| {
        if ui
            .add_enabled(player.step > 0, egui::Button::new("◀"))
            .on_hover_text(lang.tr("Previous step (← or Page Up)", "上一步（← 或 Page Up）"))
            .clicked()
        {
            out.push(Command::PreviousStep);
        }
        ui.label(format!(
            "{} {} / {n}",
            lang.tr("Step", "步骤"),
            player.step + 1
        ));
        if ui
            .add_enabled(player.step + 1 < n, egui::Button::new("▶"))
            .on_hover_text(lang.tr("Next step (→ or Page Down)", "下一步（→ 或 Page Down）"))
            .clicked()
        {
            out.push(Command::NextStep);
        }
        if !step.animate.is_empty() {
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
                out.push(Command::TogglePlay);
            }
        }
    });
}

/// Simple markdown: paragraphs split by blank lines, lines starting `- ` as bullets, and
/// `**bold**` spans (the formulas) drawn strong and coloured.
pub fn narration(ui: &mut Ui, text: &str) {
    let body = ui.style().text_styles[&egui::TextStyle::Body].clone();
    let plain = ui.visuals().text_color();
    let accent = Color32::from_rgb(255, 214, 120);
    for paragraph in text.split("\n\n") {
        let paragraph = paragraph.trim();
        if paragraph.is_empty() {
            continue;
        }
        let mut job = LayoutJob::default();
        for (i, line) in paragraph.lines().enumerate() {
            let line = line.trim();
            let (line, sep) = match line.strip_prefix("- ") {
                Some(rest) => (rest, if i == 0 { "• " } else { "\n• " }),
                None => (line, if i == 0 { "" } else { " " }),
            };
            job.append(sep, 0.0, format(&body, plain));
            for (k, part) in line.split("**").enumerate() {
                let f = if k % 2 == 1 {
                    format(&body, accent)
                } else {
                    format(&body, plain)
                };
                job.append(part, 0.0, f);
            }
        }
        job.wrap.max_width = ui.available_width();
        ui.label(job);
        ui.add_space(4.0);
    }
}

fn format(font: &FontId, color: Color32) -> TextFormat {
    TextFormat {
        font_id: font.clone(),
        color,
        ..TextFormat::default()
    }
}
