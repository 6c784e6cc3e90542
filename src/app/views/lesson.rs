//! The lesson's narration, in a card over the picture: the step's title, the narration with its
//! formulas typeset, what is moving, and the self-study question with its answer. It can be
//! folded away (N) and brought back.

use egui::{Align2, Color32, Frame, RichText, Ui, Vec2};

use super::typeset::{self, Style};
use crate::app::command::LessonCommand;
use crate::app::player::LessonPlayer;
use crate::app::session::{Command, Session};
use crate::lesson::param;
use crate::vocabulary::Lang;
use crate::vocabulary::touch::for_device;

/// What the card asked for.
pub struct CardOutput {
    /// Commands (show the answer, …).
    pub commands: Vec<Command>,
    /// The card's fold button was pressed.
    pub fold: bool,
    /// A pixel to inspect was chosen (an exercise's first wrong pixel): open the Inspector.
    pub inspect: bool,
}

/// Draws the narration card at the bottom-left of the picture's area (below the stage's
/// toolbar, as the views last laid out; `central` before they have).
pub fn card(ctx: &egui::Context, central: egui::Rect, session: &Session) -> CardOutput {
    let over = super::card_placement::picture_area(ctx).unwrap_or(central);
    let mut out = CardOutput {
        commands: Vec::new(),
        fold: false,
        inspect: false,
    };
    // In the corner, or a band or a column when the corner card would shrink the subject.
    let shape = super::card_placement::shape(ctx, over, session);
    let (width, least, most) = super::card_placement::card_size(
        shape,
        over,
        super::card_placement::content_aspect(session),
    );
    // A card whose words do not fit once their type is at the normal size (a lab's verdict in
    // classroom mode on a 1366×768 projector cut its buttons off) grows to what they need: a
    // band or a corner card taller, up to half or four fifths of the area, a column wider, up
    // to 45 % of it (its words' height goes as the inverse of its width). The growth is kept
    // for the step, so that a card that fits once grown stays grown.
    let grown_id = egui::Id::unique("narration-card-grown");
    let (for_step, grown) = ctx
        .data(|d| d.get_temp::<(u64, f32)>(grown_id))
        .filter(|(step, _)| *step == session.step_entered)
        .unwrap_or((session.step_entered, 1.0));
    let (width, most) = match shape {
        super::card_placement::Shape::Band => (width, (most * grown).min(over.height() * 0.5)),
        super::card_placement::Shape::Corner => (width, (most * grown).min(over.height() * 0.8)),
        super::card_placement::Shape::Column => ((width * grown).min(over.width() * 0.45), most),
    };
    let shown = egui::Area::new(egui::Id::unique("narration-card"))
        .order(egui::Order::Foreground)
        .pivot(Align2::LEFT_BOTTOM)
        .fixed_pos(over.left_bottom() + Vec2::new(12.0, -12.0))
        .show(ctx, |ui| {
            Frame::new()
                .fill(Color32::from_black_alpha(215))
                .corner_radius(8.0)
                .inner_margin(12.0)
                .stroke(egui::Stroke::new(1.0, Color32::from_gray(90)))
                .show(ui, |ui| {
                    ui.set_width(width);
                    ui.set_min_height(least);
                    ui.set_max_height(most);
                    let (needed, smallest) =
                        fit_contents(ui, session, &mut out, ("narration-card-fit", None));
                    let more = (grown * (needed / most.max(1.0)).min(1.5)).min(2.0);
                    if smallest && needed > most + 1.0 && more > grown + 1e-3 {
                        ctx.data_mut(|d| d.insert_temp(grown_id, (for_step, more)));
                        ctx.request_repaint();
                    }
                });
        });
    super::card_placement::set_narration_card(ctx, Some(shown.response.rect));
    out
}

/// The card's words in `ui` (the narration sheet of a small window, under the picture), in the
/// card's type at its normal size.
pub fn sheet(ui: &mut Ui, session: &Session) -> CardOutput {
    let mut out = CardOutput {
        commands: Vec::new(),
        fold: false,
        inspect: false,
    };
    contents(ui, session, &mut out);
    out
}

/// The narration in a band across the window's foot, at most `most` points high (see
/// `PipelensApp::narration_band`): its type shrinks as the card's does until its words fit
/// (never below the normal size; beyond it they scroll). Returns what it asked for and the
/// height it needs, title and words.
pub fn band(ui: &mut Ui, session: &Session, most: f32) -> (CardOutput, f32) {
    let mut out = CardOutput {
        commands: Vec::new(),
        fold: false,
        inspect: false,
    };
    let (needed, _) = fit_contents(ui, session, &mut out, ("narration-band-fit", Some(most)));
    (out, needed)
}

/// The card's words in `ui`, their type scaled to fit as [`fitted`] says, the scale kept under
/// `fit.0`; the room for the words is what `ui` leaves below the title, or what `fit.1` (a
/// height for the whole) leaves. Returns the height title and words need at this scale, and
/// whether the type is as small as it goes.
fn fit_contents(
    ui: &mut Ui,
    session: &Session,
    out: &mut CardOutput,
    fit: (&str, Option<f32>),
) -> (f32, bool) {
    let ctx = ui.ctx().clone();
    let fit_id = egui::Id::unique(fit.0);
    let scale = ctx.data(|d| d.get_temp::<f32>(fit_id)).unwrap_or(1.0);
    let normal = crate::app::style::text_styles(1.0)[&egui::TextStyle::Body].size;
    let body = ui.style().text_styles[&egui::TextStyle::Body].size;
    for font in ui.style_mut().text_styles.values_mut() {
        font.size *= scale;
    }
    let top = ui.available_height();
    let (room, needed) = contents(ui, session, out);
    let title = top - room;
    let room = fit.1.map_or(room, |whole| whole - title);
    let least = (normal / body).min(1.0);
    let next = fitted(scale, room, needed, least);
    if next != scale {
        ctx.data_mut(|d| d.insert_temp(fit_id, next));
        ctx.request_repaint();
    }
    (title + needed, scale <= least + 1e-3)
}

/// The card's type scale for the next frame, so that what it says fits without scrolling
/// (classroom type on a 1366×768 projector): from `fit`, the text needed `needed` points of
/// height where `card_placement` were left. Text area grows as the square of the type size at a fixed
/// width, so the size changes by `√(room/needed)`; it grows back only when there is a fifth
/// to spare (no flicker between two sizes), never above the style's size nor below `least`
/// (the normal size: below it the card scrolls instead).
fn fitted(fit: f32, room: f32, needed: f32, least: f32) -> f32 {
    if !(room > 0.0 && needed > 0.0) {
        return fit;
    }
    let least = least.min(1.0);
    let ratio = (room / needed).sqrt();
    if needed > room + 1.0 && fit > least {
        (fit * ratio * 0.99).max(least)
    } else if needed < room * 0.8 && fit < 1.0 {
        (fit * ratio * 0.97).min(1.0)
    } else {
        fit
    }
}

/// The card's type: near-white on its dark ground, formulas in the accent colour.
#[must_use]
pub fn card_style(ui: &Ui) -> Style {
    Style {
        color: Color32::from_gray(245),
        ..Style::body(ui)
    }
}

/// The card's words; returns the height left for them below the title and the height they took.
fn contents(ui: &mut Ui, session: &Session, out: &mut CardOutput) -> (f32, f32) {
    let Some(player) = &session.lesson else {
        return (0.0, 0.0);
    };
    let (spec, lang) = (&session.spec, session.lang);
    let step = player.current();
    let style = card_style(ui);
    // The fold button at the right first, then the title wrapped in the width it leaves (a
    // narrow column has no room for it on one line; classroom mode's button is wider).
    let title = RichText::new(heading(player, lang))
        .strong()
        .size(style.size * 1.25)
        .color(Color32::WHITE);
    let width = ui.available_width();
    ui.allocate_ui_with_layout(
        egui::vec2(width, 0.0),
        egui::Layout::right_to_left(egui::Align::Min),
        |ui| {
            if ui
                .add(crate::app::style::glyph_button(ui, "—", None))
                .accessible_name(lang.t("lesson-fold-the-narration-away"))
                .on_hover_text(lang.t("lesson-fold-the-narration-away-n"))
                .clicked()
            {
                out.fold = true;
            }
            ui.with_layout(egui::Layout::left_to_right(egui::Align::Min), |ui| {
                // Read out on each new step (and its language): the card's words follow it.
                let words = title.text().to_owned();
                let shown = ui.add(egui::Label::new(title).wrap());
                super::alt::announce(&shown, (super::alt::Part::Title, &words));
            });
        },
    );
    let room = ui.available_height();
    let words = egui::ScrollArea::vertical()
        .id_salt("narration")
        .auto_shrink([false, true])
        .show(ui, |ui| {
            let said = |text| for_device(text, session.touch);
            narration(ui, &said(step.narration.get(lang)), &style);
            if step.predicts() && !player.playing && player.time == 0.0 {
                ui.label(
                    RichText::new(said(lang.t("lesson-predict-first-the-question-below")))
                        .strong()
                        .color(Color32::from_rgb(255, 214, 120)),
                );
            }
            for a in &step.animate {
                let line = lang.t_with(
                    "lesson-animation-line",
                    &[
                        (
                            "param",
                            &crate::vocabulary::upper_first(&param::describe(spec, &a.param, lang)),
                        ),
                        ("from", &a.from),
                        ("to", &a.to),
                    ],
                );
                typeset::paragraph(ui, &line, &style.sized(style.size * 0.85));
            }
            if let Some(e) = &step.exercise {
                out.inspect |=
                    super::exercise::card_part(ui, (e, session), &style, &mut out.commands);
            }
            if let Some(q) = &step.question {
                ui.add_space(6.0);
                ui.label(
                    RichText::new(lang.t("lesson-question"))
                        .strong()
                        .color(Color32::WHITE),
                );
                narration(ui, &said(q.get(lang)), &style);
                super::answer::field(
                    ui,
                    (player, &session.progress),
                    &style,
                    lang,
                    &mut out.commands,
                );
                if let Some(a) = &step.answer {
                    let shown = player.show_answer;
                    let label = if shown {
                        lang.t("lesson-hide-the-answer")
                    } else {
                        lang.t("lesson-show-the-answer")
                    };
                    if ui.button(label).clicked() {
                        out.commands
                            .push(Command::Lesson(LessonCommand::ShowAnswer(!shown)));
                    }
                    if shown {
                        narration(ui, &said(a.get(lang)), &style);
                    }
                }
            }
        });
    (room, words.content_size.y)
}

/// Simple markdown: paragraphs split by blank lines, lines starting `- ` as bullets, `**…**`
/// formulas typeset and highlighted, `` `code` `` as written.
pub fn narration(ui: &mut Ui, text: &str, style: &Style) {
    for (list, items) in paragraphs(text) {
        if list {
            for item in items {
                ui.horizontal_top(|ui| {
                    ui.label(RichText::new("•").size(style.size).color(style.color));
                    typeset::paragraph(ui, &item, style);
                });
            }
        } else {
            for item in items {
                typeset::paragraph(ui, &item, style);
            }
        }
        ui.add_space(style.size * 0.35);
    }
}

/// The step's number and title, as the card's heading shows them: "3. Specular: the highlight".
#[must_use]
pub fn heading(player: &LessonPlayer, lang: Lang) -> String {
    format!("{}. {}", player.step + 1, player.current().title.get(lang))
}

/// The step's heading and its narration in plain words, for the words a page keeps beside its
/// canvas ([`super::alt::PageWords`]), whether the card is shown or folded away.
pub fn for_the_page(ctx: &egui::Context, session: &Session) {
    let Some(player) = &session.lesson else {
        return;
    };
    if !super::alt::keeps_page_words(ctx) {
        return;
    }
    let lang = session.lang;
    super::alt::for_the_page(ctx, super::alt::Part::Title, &heading(player, lang));
    let narration = plain_narration(&for_device(
        player.current().narration.get(lang),
        session.touch,
    ));
    super::alt::for_the_page(ctx, super::alt::Part::Narration, &narration);
}

/// A narration's paragraphs (split at blank lines), each a list's items (when every line
/// starts with "- ") or its lines joined into one, with a space (none between Chinese
/// characters).
fn paragraphs(text: &str) -> Vec<(bool, Vec<String>)> {
    let is_cjk = crate::vocabulary::notation::is_cjk;
    let mut out = Vec::new();
    for paragraph in text.split("\n\n") {
        let paragraph = paragraph.trim();
        if paragraph.is_empty() {
            continue;
        }
        let lines: Vec<&str> = paragraph.lines().map(str::trim).collect();
        if lines.iter().all(|l| l.starts_with("- ")) {
            out.push((true, lines.iter().map(|l| l[2..].to_owned()).collect()));
            continue;
        }
        let mut joined = String::new();
        for l in lines {
            let cjk_join =
                joined.chars().last().is_some_and(is_cjk) && l.chars().next().is_some_and(is_cjk);
            if !joined.is_empty() && !cjk_join {
                joined.push(' ');
            }
            joined.push_str(l);
        }
        out.push((false, vec![joined]));
    }
    out
}

/// A narration as plain text, its marks taken out (`**L_a = k_a·I_a**` → `La = ka·Ia`): what a
/// page shows a screen reader beside its canvas. Paragraphs are separated by a blank line, a
/// list's items start with "• ".
#[must_use]
pub fn plain_narration(text: &str) -> String {
    let plain = |s: &str| {
        crate::vocabulary::notation::plain_text(&crate::vocabulary::notation::parse_paragraph(s))
    };
    paragraphs(text)
        .into_iter()
        .map(|(list, items)| {
            let items = items.iter().map(|i| plain(i));
            if list {
                items
                    .map(|i| format!("• {i}"))
                    .collect::<Vec<_>>()
                    .join("\n")
            } else {
                items.collect::<Vec<_>>().join("\n")
            }
        })
        .collect::<Vec<_>>()
        .join("\n\n")
}

#[cfg(test)]
mod tests {
    use super::plain_narration;

    /// The page's narration in plain words: marks out, a paragraph's lines joined (no space
    /// between Chinese characters), a list's items each on a line behind a bullet.
    #[test]
    fn a_narration_in_plain_words() {
        let en = "**L_a = k_a·I_a**: the same at every point. Alone\nit draws a flat disc.\n\n- one\n- two";
        assert_eq!(
            plain_narration(en),
            "La = ka·Ia: the same at every point. Alone it draws a flat disc.\n\n• one\n• two"
        );
        assert_eq!(
            plain_narration("光线\n来自各处，\nn·l = 1"),
            "光线来自各处， n·l = 1"
        );
    }
}
