//! The field under a question with a value to type (`expect`): one box per number (a matrix
//! cell by cell), the tolerance said beside it, Check (or Enter), and the verdict — right, or
//! which entry is off and by how much — after which the worked answer is offered.

use egui::{Color32, RichText, Ui};

use super::typeset::Style;
use crate::app::command::LessonCommand;
use crate::app::progress::Progress;
use crate::app::session::{Command, LessonPlayer};
use crate::lesson::answer::{Expect, Shape, Verdict};
use crate::vocabulary::Lang;

/// Green for right, amber for not yet.
const RIGHT: Color32 = Color32::from_rgb(120, 220, 120);
const NOT_YET: Color32 = Color32::from_rgb(255, 170, 90);

/// Draws the field of the current step's `expect`, if it has one; typing and checking are
/// returned as commands.
pub fn field(
    ui: &mut Ui,
    (player, progress): (&LessonPlayer, &Progress),
    style: &Style,
    lang: Lang,
    commands: &mut Vec<Command>,
) {
    let Some(expect) = &player.current().expect else {
        return;
    };
    let (rows, cols) = expect.shape.size();
    let typed = progress.typed(&player.lesson, player.step, expect.shape.cells());
    ui.label(
        RichText::new(prompt(expect, lang))
            .size(style.size * 0.85)
            .color(style.color),
    );
    let mut check = false;
    let cell_width = style.size * 4.2;
    egui::Grid::new("answer-field")
        .min_col_width(0.0)
        .spacing([style.size * 0.3, style.size * 0.3])
        .show(ui, |ui| {
            // Names the step gives stay before their boxes once a box is typed in (the grey
            // hint goes), on the boxes' own row; a vector's x, y, z are the hints alone.
            let named = style.sized(style.size * 0.85);
            for r in 0..rows {
                for c in 0..cols {
                    let label = (!expect.names.is_empty()).then(|| {
                        let name = expect.entry_name((r, c)).unwrap_or_default();
                        super::typeset::formula(ui, name, &named).id
                    });
                    let i = r * cols + c;
                    let mut text = typed[i].clone();
                    let mut edit = egui::TextEdit::singleline(&mut text)
                        .font(egui::FontId::monospace(style.size * 0.9))
                        .background_color(Color32::from_gray(45));
                    if let Some(hint) = hint(expect, (r, c)) {
                        edit = edit.hint_text(hint);
                    }
                    let mut response = ui
                        .add_sized([cell_width, style.size * 1.5], edit)
                        .on_hover_text(lang.t("answer-a-number-or-an-expression"));
                    if let Some(label) = label {
                        // A screen reader names the box by the name beside it.
                        response = response.labelled_by(label);
                    }
                    if response.changed() {
                        commands.push(Command::Lesson(LessonCommand::TypeAnswer { cell: i, text }));
                    }
                    check |= response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                }
                ui.end_row();
            }
        });
    ui.horizontal(|ui| {
        check |= ui
            .button(lang.t("answer-check"))
            .on_hover_text(lang.t("answer-compare-with-the-expected-value"))
            .clicked();
        if player.verdict.is_none() && progress.answered(&player.lesson, player.step) {
            ui.label(RichText::new(lang.t("answer-answered-right-before")).color(RIGHT));
        }
    });
    if check {
        commands.push(Command::Lesson(LessonCommand::CheckAnswer));
    }
    if let Some(v) = &player.verdict {
        let color = if *v == Verdict::Right { RIGHT } else { NOT_YET };
        ui.label(
            RichText::new(v.describe(expect, lang))
                .size(style.size * 0.9)
                .color(color),
        );
    }
}

/// What the field asks for, with the tolerance stated.
fn prompt(expect: &Expect, lang: Lang) -> String {
    let tolerance = expect.tolerance_words(lang);
    let what = match expect.shape {
        Shape::Number => lang.t("answer-type-the-value").to_owned(),
        // Named entries are values of their own, not a vector's components.
        Shape::Vector(n) if !expect.names.is_empty() => {
            lang.t_with("answer-type-the-values", &[("n", &n)])
        }
        Shape::Vector(n) => lang.t_with("answer-type-the-components", &[("n", &n)]),
        Shape::Matrix(r, c) => {
            lang.t_with("answer-type-the-matrix", &[("rows", &r), ("columns", &c)])
        }
    };
    lang.t_with(
        "answer-prompt",
        &[("what", &what), ("tolerance", &tolerance)],
    )
}

/// The grey hint in an empty cell: `x`, `y`, … for a vector, `m11` … for a matrix's cell;
/// none where the step names its entries (each name is beside its box).
fn hint(expect: &Expect, (r, c): (usize, usize)) -> Option<String> {
    if !expect.names.is_empty() {
        return None;
    }
    Some(match (expect.entry_name((r, c)), expect.shape) {
        (Some(name), _) => name.to_owned(),
        (None, Shape::Matrix(..)) => format!("m{}{}", r + 1, c + 1),
        (None, _) => "?".to_owned(),
    })
}
