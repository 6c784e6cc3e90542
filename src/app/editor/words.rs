//! The words of the current step, edited in place: title, narration, question and answer, each
//! in English and Chinese side by side, with the typeset preview the student's card shows
//! (formulas included) and a note when one language is missing. What is typed goes into the
//! lesson file's text at once (typing on in one box is one change to undo) and onto the card.

use egui::RichText;

use super::window::Editor;
use crate::app::command::EditorCommand;
use crate::app::session::{Command, Session};
use crate::app::views::lesson::{card_style, narration};
use crate::lesson::edit::Words;
use crate::vocabulary::{Lang, Text};

/// Every text the editor types: the lesson's title and summary, then the step's four.
const EDITED: [Words; 6] = [
    Words::LessonTitle,
    Words::Summary,
    Words::Title,
    Words::Narration,
    Words::Question,
    Words::Answer,
];

impl Editor {
    /// The lesson's title and summary (folded) and the current step's words, read from the
    /// file's text when the step or the text changed; what is typed goes into the text and onto
    /// the card.
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
            self.words = EDITED.map(|w| doc.draft.words(k, w));
            self.words_for = Some((k, doc.draft.revision()));
        }
        let mut typed = Vec::new();
        egui::CollapsingHeader::new(RichText::new(lang.t("words-the-lesson-s-title-and")).strong())
            .id_salt("lesson-words")
            .show(ui, |ui| {
                for (which, text) in EDITED.iter().zip(&mut self.words).take(2) {
                    typed.extend(boxes(ui, lang, *which, text));
                }
            });
        ui.label(RichText::new(lang.t_with("words-of-step", &[("step", &(k + 1))])).strong());
        for (which, text) in EDITED.iter().zip(&mut self.words).skip(2) {
            typed.extend(boxes(ui, lang, *which, text));
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
        let [title, summary, step_title, narration, question, answer] = self.words.clone();
        lesson.title = title;
        lesson.summary = summary;
        if let Some(step) = lesson.steps.get_mut(k) {
            step.title = step_title;
            step.narration = narration;
            let optional =
                |t: Text| (!(t.en.trim().is_empty() && t.zh.trim().is_empty())).then_some(t);
            step.question = optional(question);
            step.answer = optional(answer);
        }
        out.push(Command::Editor(EditorCommand::ReviseLesson {
            lesson: Box::new(lesson),
            step: k,
            enter: false,
        }));
    }
}

/// The boxes of one text, with its preview and the note of a missing language; what was typed.
fn boxes(
    ui: &mut egui::Ui,
    lang: Lang,
    which: Words,
    text: &mut Text,
) -> Vec<(Words, Lang, String)> {
    let (label, rows) = match which {
        Words::LessonTitle | Words::Title => (lang.t("words-title"), 1),
        Words::Summary => (lang.t("words-summary"), 2),
        Words::Narration => (lang.t("words-narration"), 4),
        Words::Question => (lang.t("words-question-optional"), 2),
        Words::Answer => (lang.t("words-answer-optional"), 2),
    };
    let changed = pair(ui, label, text, rows);
    if matches!(which, Words::Narration | Words::Question | Words::Answer) {
        preview(ui, text);
    }
    if which.required() {
        missing_note(ui, lang, text);
    }
    [(Lang::EN, changed.0), (Lang::ZH, changed.1)]
        .into_iter()
        .filter(|(_, on)| *on)
        .map(|(l, _)| (which, l, text.get(l).to_owned()))
        .collect()
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
                    narration(ui, words, &card_style(ui));
                });
        }
    });
}

/// "Still needs: English" when a language has no words, else "Worded: English, 中文": a line either
/// way, so that the buttons under it stay where they were when the last word is typed.
pub(super) fn missing_note(ui: &mut egui::Ui, lang: Lang, text: &Text) {
    let missing: Vec<&str> = crate::lesson::record::unworded(text)
        .into_iter()
        .map(|l| if l == Lang::EN { "English" } else { "中文" })
        .collect();
    if missing.is_empty() {
        ui.label(RichText::new(lang.t("words-worded-english")).weak());
    } else {
        ui.label(
            RichText::new(format!(
                "{} {}",
                lang.t("words-still-needs"),
                missing.join(", ")
            ))
            .color(ui.visuals().warn_fg_color),
        );
    }
}
