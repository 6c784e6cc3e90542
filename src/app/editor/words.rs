//! The words of the current step, edited in place: title, narration, question and answer, each
//! in English and Chinese side by side, with the typeset preview the student's card shows
//! (formulas included) and a note when one language is missing. What is typed goes into the
//! lesson file's text at once (typing on in one box is one change to undo) and onto the card.

use egui::RichText;

use super::Editor;
use crate::app::session::{Command, Session};
use crate::app::views::{lesson::narration, typeset::Style};
use crate::lesson::edit::Words;
use crate::vocabulary::{Lang, Text};

impl Editor {
    /// The current step's words, read from the file's text when the step or the text changed.
    pub(super) fn step_words(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        let (Some(doc), Some(player)) = (&mut self.doc, &session.lesson) else {
            return;
        };
        let k = player.step;
        if self.words_for != Some((k, doc.draft.revision())) {
            self.words = Words::ALL.map(|w| doc.draft.words(k, w));
            self.words_for = Some((k, doc.draft.revision()));
        }
        ui.label(
            RichText::new(match lang {
                Lang::En => format!("The words of step {}", k + 1),
                Lang::Zh => format!("第 {} 步的文字", k + 1),
            })
            .strong(),
        );
        let mut typed = Vec::new();
        for (i, which) in Words::ALL.into_iter().enumerate() {
            let (label, rows) = match which {
                Words::Title => (lang.tr("Title", "标题"), 1),
                Words::Narration => (lang.tr("Narration", "讲解"), 4),
                Words::Question => (lang.tr("Question (optional)", "思考题（可选）"), 2),
                Words::Answer => (lang.tr("Answer (optional)", "答案（可选）"), 2),
            };
            let changed = pair(ui, label, &mut self.words[i], rows);
            if which != Words::Title {
                preview(ui, &self.words[i]);
            }
            for (lang, on) in [(Lang::En, changed.0), (Lang::Zh, changed.1)] {
                if on {
                    typed.push((which, lang, self.words[i].get(lang).to_owned()));
                }
            }
            if which.required() {
                missing_note(ui, lang, &self.words[i]);
            }
        }
        if typed.is_empty() {
            return;
        }
        for (which, lang, words) in typed {
            if let Err(e) = doc.draft.set_words(k, which, lang, &words) {
                self.said = Some(Err(e));
                return;
            }
        }
        self.words_for = Some((k, doc.draft.revision()));
        // On the card at once, the screen kept as it is (no parsing of the file per key).
        let mut lesson = (*player.lesson).clone();
        if let Some(step) = lesson.steps.get_mut(k) {
            let [title, narration, question, answer] = self.words.clone();
            step.title = title;
            step.narration = narration;
            let optional =
                |t: Text| (!(t.en.trim().is_empty() && t.zh.trim().is_empty())).then_some(t);
            step.question = optional(question);
            step.answer = optional(answer);
        }
        out.push(Command::ReviseLesson {
            lesson: Box::new(lesson),
            step: k,
            enter: false,
        });
    }
}

/// A label over two boxes, English and 中文, side by side; whether each was typed in.
pub(super) fn pair(ui: &mut egui::Ui, label: &str, text: &mut Text, rows: usize) -> (bool, bool) {
    ui.label(RichText::new(label).strong());
    let mut changed = (false, false);
    ui.columns(2, |cols| {
        let [en, zh] = cols else {
            return;
        };
        for (ui, name, words, on) in [
            (en, "English", &mut text.en, &mut changed.0),
            (zh, "中文", &mut text.zh, &mut changed.1),
        ] {
            let named = ui.label(name).id;
            *on = ui
                .add(
                    egui::TextEdit::multiline(words)
                        .desired_rows(rows)
                        .desired_width(f32::INFINITY),
                )
                .labelled_by(named)
                .changed();
        }
    });
    changed
}

/// The words as the student's card typesets them (`**…**` formulas, `- ` bullets), in both
/// languages side by side, on the card's dark ground.
fn preview(ui: &mut egui::Ui, text: &Text) {
    if text.en.trim().is_empty() && text.zh.trim().is_empty() {
        return;
    }
    ui.columns(2, |cols| {
        for (col, words) in cols.iter_mut().zip([&text.en, &text.zh]) {
            egui::Frame::new()
                .fill(egui::Color32::from_black_alpha(215))
                .corner_radius(6.0)
                .inner_margin(8.0)
                .show(col, |ui| {
                    ui.set_width(ui.available_width());
                    let style = Style::body(ui);
                    narration(ui, words, &style);
                });
        }
    });
}

/// "Still needs: English" when a language has no words.
pub(super) fn missing_note(ui: &mut egui::Ui, lang: Lang, text: &Text) {
    let missing: Vec<&str> = crate::lesson::record::unworded(text)
        .into_iter()
        .map(|l| if l == Lang::En { "English" } else { "中文" })
        .collect();
    if !missing.is_empty() {
        ui.label(
            RichText::new(format!(
                "{} {}",
                lang.tr("Still needs:", "还缺少："),
                missing.join(", ")
            ))
            .color(ui.visuals().warn_fg_color),
        );
    }
}
