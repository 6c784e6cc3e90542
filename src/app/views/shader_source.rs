//! The shader panel's source: line numbers (a line with a message marked, a breakpoint with a
//! dot, the debugger's step with an arrow), the text highlighted as C-like code, each message
//! written in red at the end of its line, else the line's last step of the run (a colour with
//! its swatch). The line numbers stay in place when the text scrolls sideways.

use egui::{Color32, RichText, Ui};

/// What the source shows of the run at the step shown: the line highlighted, the breakpoints,
/// and beside each line the value it last wrote (with a swatch for a colour).
#[derive(Default)]
pub struct Marks {
    /// The line of the step shown.
    pub current: Option<usize>,
    /// The lines with a breakpoint.
    pub breakpoints: Vec<usize>,
    /// `(line, "name = value", swatch)`.
    pub beside: Vec<(usize, String, Option<Color32>)>,
    /// The step moved this frame: its line is scrolled into view.
    pub reveal: bool,
    /// The line after which the variable picture reads its expression (outlined).
    pub watched: Option<usize>,
    /// The lesson step's lines, first and last (marked with a bar), and whether to scroll to
    /// them this frame.
    pub lines: Option<((usize, usize), bool)>,
}

/// What the reader did in the source this frame.
pub(super) struct Touched {
    /// The text was edited.
    pub changed: bool,
    /// A line number was clicked (a breakpoint set or cleared there).
    pub gutter: Option<usize>,
    /// The line the text cursor is on, from 1, while the source has the keyboard.
    pub cursor_line: Option<usize>,
    /// The start of the line to bring into view (the step's lines on entering the step, the
    /// debugger's line when it moved).
    scroll_to: Option<egui::Rect>,
    /// The text cursor, where the keys moved it this frame: kept in sight (Ctrl+End, the
    /// arrows, typing past the last line seen) by as little a scroll as does it.
    cursor_moved_to: Option<egui::Rect>,
}

/// The line numbers as a screen reader says them: how many, then the lines marked — the
/// breakpoints, the debugger's line, the lines with a message — instead of every number.
fn gutter_said(
    lines: usize,
    errors: &[(usize, &str)],
    marks: &Marks,
    lang: crate::vocabulary::Lang,
) -> String {
    let list = |mut at: Vec<usize>| {
        at.sort_unstable();
        at.dedup();
        let words: Vec<String> = at.iter().map(ToString::to_string).collect();
        words.join(lang.t("list-separator"))
    };
    let mut said = lang.t_with("shader-source-gutter", &[("lines", &lines)]);
    let breakpoints: Vec<usize> = (1..=lines)
        .filter(|n| marks.breakpoints.contains(n))
        .collect();
    if !breakpoints.is_empty() {
        said += &lang.t_with(
            "shader-source-gutter-breakpoints",
            &[("lines", &list(breakpoints))],
        );
    }
    if let Some(line) = marks.current {
        said += &lang.t_with("shader-source-gutter-current", &[("line", &line)]);
    }
    if !errors.is_empty() {
        said += &lang.t_with(
            "shader-source-gutter-messages",
            &[("lines", &list(errors.iter().map(|(l, _)| *l).collect()))],
        );
    }
    said
}

/// The source with its line numbers, highlighted, with `errors` (`(line, message)`) and the
/// debugger's `marks`; `tab` names the tab, which keeps its own scroll position. The line
/// numbers' tooltip is in `lang`.
pub(super) fn code(
    ui: &mut Ui,
    (source, tab, name): (&mut String, &str, &str),
    errors: &[(usize, &str)],
    marks: &Marks,
    lang: crate::vocabulary::Lang,
) -> Touched {
    let mut touched = Touched {
        changed: false,
        gutter: None,
        cursor_line: None,
        scroll_to: None,
        cursor_moved_to: None,
    };
    // A finger's drag on the code is the vertical area's (the sideways one inside it takes
    // none, or it would swallow every drag and move only sideways); its sideways part moves
    // the sideways area the next frame.
    let sideways_id = egui::Id::unique(("shader source sideways", tab));
    let sideways_to: Option<f32> = ui.data_mut(|d| d.remove_temp(sideways_id));
    let mut sideways = (0.0, 0.0);
    let vertical = egui::ScrollArea::vertical()
        .id_salt(("shader source", tab))
        .show(ui, |ui| {
            ui.horizontal_top(|ui| {
                let lines = source.lines().count().max(1) + usize::from(source.ends_with('\n'));
                // The numbers right-aligned in a column a target wide at least (a finger's
                // on a touch screen): the mark, the arrow, then the digits.
                let font = egui::TextStyle::Monospace.resolve(ui.style());
                let char_width = ui.fonts_mut(|f| f.glyph_width(&font, '0')).max(1.0);
                let digits = ((ui.spacing().interact_size.y / char_width).ceil() as usize)
                    .saturating_sub(2)
                    .max(3);
                let gutter: String = (1..=lines)
                    .map(|n| {
                        let dot = if marks.breakpoints.contains(&n) {
                            '●'
                        } else {
                            ' '
                        };
                        let arrow = if marks.current == Some(n) {
                            '▶'
                        } else if errors.iter().any(|(line, _)| *line == n) {
                            '!'
                        } else {
                            ' '
                        };
                        format!("{dot}{arrow}{n:>digits$}\n")
                    })
                    .collect();
                let numbers = ui
                    .add(
                        egui::Label::new(
                            RichText::new(gutter.trim_end())
                                .monospace()
                                .color(ui.visuals().weak_text_color()),
                        )
                        .selectable(false)
                        .sense(egui::Sense::click()),
                    )
                    .on_hover_text(lang.t(
                        crate::app::shortcuts::of(crate::app::shortcuts::Action::Breakpoint).does,
                    ));
                let said = gutter_said(lines, errors, marks, lang);
                // Named by its marks, and its numbers' text (the label's value) left unsaid.
                numbers.widget_info(|| egui::WidgetInfo {
                    current_text_value: Some(String::new()),
                    ..egui::WidgetInfo::labeled(egui::Role::Button, true, &said)
                });
                // The text scrolls sideways by itself: a long line never hides the numbers.
                let mut columns = egui::ScrollArea::horizontal()
                    .id_salt(("shader source columns", tab))
                    .scroll_source(egui::containers::scroll_area::ScrollSource {
                        drag: egui::containers::scroll_area::DragScroll::Never,
                        ..Default::default()
                    });
                if let Some(x) = sideways_to {
                    columns = columns.horizontal_scroll_offset(x);
                }
                let shown = columns.show(ui, |ui| {
                    text(
                        ui,
                        (source, tab, name),
                        errors,
                        marks,
                        &mut touched,
                        &numbers,
                    );
                });
                sideways = (
                    shown.state.clamped_offset().x,
                    (shown.content_size.x - shown.inner_rect.width()).max(0.0),
                );
                // Asked here, outside the sideways area: a scroll area takes both axes'
                // targets, so one asked inside it would never reach this vertical one.
                if let Some(start) = touched.scroll_to.take() {
                    ui.scroll_to_rect(start, Some(egui::Align::Center));
                } else if let Some(cursor) = touched.cursor_moved_to.take() {
                    ui.scroll_to_rect(cursor, None);
                }
            });
        });
    if ui.ctx().is_being_dragged(vertical.id.with("area")) {
        let dx = ui.input(|i| i.pointer.delta().x);
        if dx != 0.0 {
            let (at, most) = sideways;
            ui.data_mut(|d| d.insert_temp(sideways_id, (at - dx).clamp(0.0, most)));
            ui.ctx().request_repaint();
        }
    }
    touched
}

/// Where the text cursor is when the keys moved it since the last frame (and the source has
/// the keyboard). egui keeps the cursor in sight of the nearest scroll area only, the sideways
/// one; the vertical one is asked with this.
fn cursor_moved(ui: &Ui, out: &egui::text_edit::TextEditOutput) -> Option<egui::Rect> {
    let seen = out.response.response.id.with("cursor seen");
    let cursor = out.cursor_range.map(|r| r.primary.index.0);
    let last = ui.data_mut(|d| {
        let last = d.get_temp::<Option<usize>>(seen);
        d.insert_temp(seen, cursor);
        last
    });
    let r = out.cursor_range?;
    (out.response.response.has_focus() && last.is_some_and(|l| l != cursor)).then(|| {
        let at = out.galley.pos_from_cursor(r.primary);
        at.translate(out.galley_pos.to_vec2()).expand(4.0)
    })
}

/// The id of the text edit of the source of `tab` (a tab's name), the same from frame to frame
/// whatever is drawn before it (the keys of `glsl_keys` type into it by this id).
pub(super) fn source_id(tab: &str) -> egui::Id {
    egui::Id::unique(("shader source", tab))
}

/// The cursor where the source was tapped, when that tap gave it the keyboard. On a touch
/// screen egui lets a finger's drag scroll the code until the source has the keyboard, so its
/// first tap is a click that only focuses, and the cursor would start at the end of the file
/// (text typed next landed after the last `}`). With a mouse it is where egui put it already.
fn cursor_where_tapped(
    ctx: &egui::Context,
    id: egui::Id,
    out: &egui::text_edit::TextEditOutput,
    had_keyboard: bool,
) {
    let response = &out.response.response;
    if had_keyboard || !response.clicked() {
        return;
    }
    let Some(at) = response.interact_pointer_pos() else {
        return;
    };
    let cursor = out.galley.cursor_from_pos(at - out.galley_pos);
    let mut state = out.state.clone();
    state
        .cursor
        .set_char_range(Some(egui::text::CCursorRange::one(cursor)));
    egui::TextEdit::store_state(ctx, id, state);
}

/// The text itself, its step highlighted, with the messages and values painted after the lines.
fn text(
    ui: &mut Ui,
    (source, tab, name): (&mut String, &str, &str),
    errors: &[(usize, &str)],
    marks: &Marks,
    touched: &mut Touched,
    numbers: &egui::Response,
) {
    let lines = source.lines().count().max(1) + usize::from(source.ends_with('\n'));
    let mut theme = egui_extras::syntax_highlighting::CodeTheme::from_style(ui.style());
    if theme.is_dark() {
        // egui's grey 120 for comments is 4.4:1 on the editor's ground, under WCAG AA's 4.5:1;
        // the comments here are a lesson's words.
        theme
            .format_mut(egui_extras::syntax_highlighting::TokenType::Comment)
            .color = Color32::from_gray(145);
    }
    // No wrapping: a source line is one line, as its number says.
    let mut layouter = |ui: &Ui, text: &dyn egui::TextBuffer, _wrap_width: f32| {
        let mut job = egui_extras::syntax_highlighting::highlight(
            ui.ctx(),
            ui.style(),
            &theme,
            text.as_str(),
            "c",
        );
        job.wrap.max_width = f32::INFINITY;
        ui.fonts_mut(|f| f.layout_job(job))
    };
    // A fixed id: the messages above come and go as one types, and an id counted from the
    // widgets before it would change with them, taking the focus away.
    let id = source_id(tab);
    let had_keyboard = ui.memory(|m| m.has_focus(id));
    let out = egui::TextEdit::multiline(source)
        .id(id)
        .code_editor()
        .desired_rows(lines.max(24))
        .desired_width(f32::INFINITY)
        .lock_focus(true)
        .layouter(&mut layouter)
        .show(ui);
    // Named after its tab: a screen reader reads "Fragment shader: source".
    let _ = out.response.response.clone().accessible_name(name);
    cursor_where_tapped(ui.ctx(), id, &out, had_keyboard);
    touched.changed = out.response.changed();
    touched.cursor_line = out
        .cursor_range
        .map(|r| out.galley.layout_from_cursor(r.primary).row + 1);
    touched.cursor_moved_to = cursor_moved(ui, &out);
    // Without wrapping, row k of the laid-out text is source line k + 1.
    let row_rect = |line: usize| {
        line.checked_sub(1)
            .and_then(|k| out.galley.rows.get(k))
            .map(|row| row.rect().translate(out.galley_pos.to_vec2()))
    };
    touched.scroll_to = bands(ui, marks, &row_rect, out.response.rect.x_range());
    if numbers.clicked()
        && let Some(y) = numbers.interact_pointer_pos().map(|p| p.y)
    {
        touched.gutter =
            (1..=lines).find(|&l| row_rect(l).is_some_and(|r| r.y_range().contains(y)));
    }
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let error_color = ui.visuals().error_fg_color;
    let mut right = out.response.rect.right();
    for (line, message) in errors {
        if let Some(rect) = row_rect(*line) {
            let painted = ui.painter().text(
                egui::pos2(rect.max.x + 24.0, rect.center().y),
                egui::Align2::LEFT_CENTER,
                format!("◀ {message}"),
                font.clone(),
                error_color,
            );
            right = right.max(painted.right());
        }
    }
    let value_color = ui.visuals().weak_text_color();
    for (line, words, swatch) in &marks.beside {
        if errors.iter().any(|(l, _)| l == line) {
            continue;
        }
        let Some(rect) = row_rect(*line) else {
            continue;
        };
        let mut x = rect.max.x + 24.0;
        if let Some(c) = swatch {
            let side = rect.height() * 0.8;
            let square = egui::Rect::from_center_size(
                egui::pos2(x + side / 2.0, rect.center().y),
                egui::vec2(side, side),
            );
            ui.painter().rect_filled(square, 2.0, *c);
            ui.painter().rect_stroke(
                square,
                2.0,
                egui::Stroke::new(1.0, value_color),
                egui::StrokeKind::Outside,
            );
            x += side + 6.0;
        }
        let painted = ui.painter().text(
            egui::pos2(x, rect.center().y),
            egui::Align2::LEFT_CENTER,
            format!("// {words}"),
            font.clone(),
            value_color,
        );
        right = right.max(painted.right());
    }
    // What is painted after the lines scrolls into view sideways like the text.
    ui.expand_to_include_x(right + 8.0);
}

/// The step's line highlighted (over the text: the editor's own background would hide it
/// beneath; light enough to read through, with a bar at its left edge) and scrolled to when it
/// moved, the watched line outlined, and the lesson step's lines marked with a bar at the right
/// (scrolled to on entering the step); `row_rect` is a line's row on screen. Returns the start
/// of the line to scroll to, if any.
fn bands(
    ui: &Ui,
    marks: &Marks,
    row_rect: &dyn Fn(usize) -> Option<egui::Rect>,
    x_range: egui::Rangef,
) -> Option<egui::Rect> {
    let mut scroll_to = None;
    if let Some(((first, last), reveal)) = marks.lines
        && let (Some(top), Some(bottom)) = (row_rect(first), row_rect(last))
    {
        let block = egui::Rect::from_x_y_ranges(x_range, top.top()..=bottom.bottom());
        if reveal && !marks.reveal {
            scroll_to = Some(egui::Rect::from_x_y_ranges(
                block.left()..=block.left(),
                block.y_range(),
            ));
        }
        let teal = Color32::from_rgb(70, 190, 170);
        ui.painter()
            .rect_filled(block, 0.0, teal.gamma_multiply(0.12));
        ui.painter().rect_filled(
            egui::Rect::from_x_y_ranges(block.right() - 4.0..=block.right(), block.y_range()),
            0.0,
            teal,
        );
    }
    if let Some(rect) = marks.current.and_then(row_rect) {
        if marks.reveal {
            // Up or down to the line, not sideways: the line's start is what is asked for.
            scroll_to = Some(egui::Rect::from_x_y_ranges(
                rect.left()..=rect.left(),
                rect.y_range(),
            ));
        }
        let band = egui::Rect::from_x_y_ranges(x_range, rect.y_range());
        let amber = Color32::from_rgb(230, 190, 60);
        ui.painter()
            .rect_filled(band, 0.0, amber.gamma_multiply(0.22));
        ui.painter().rect_filled(
            egui::Rect::from_x_y_ranges(band.left()..=band.left() + 3.0, band.y_range()),
            0.0,
            amber,
        );
    }
    if let Some(rect) = marks.watched.and_then(row_rect) {
        let band = egui::Rect::from_x_y_ranges(x_range, rect.y_range());
        ui.painter().rect_stroke(
            band,
            2.0,
            egui::Stroke::new(1.5, Color32::from_rgb(90, 170, 220)),
            egui::StrokeKind::Inside,
        );
    }
    scroll_to
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vocabulary::Lang;

    /// The line numbers are said as how many and which are marked, in both languages (written
    /// by hand), not as every number; a breakpoint past the last line is not among them.
    #[test]
    fn the_line_numbers_are_said_by_their_marks() {
        let marks = Marks {
            current: Some(8),
            breakpoints: vec![20, 12, 40],
            beside: Vec::new(),
            reveal: false,
            watched: None,
            lines: None,
        };
        let errors = [(4, "a `;` is missing")];
        assert_eq!(
            gutter_said(20, &errors, &marks, Lang::EN),
            "Line numbers 1 to 20 (click one to set or clear a breakpoint); breakpoints at 12, \
             20; the debugger is at line 8; a message at 4"
        );
        assert_eq!(
            gutter_said(20, &errors, &marks, Lang::ZH),
            "行号 1 到 20（单击行号设置或清除断点）；断点在第 12、20 行；调试器在第 8 行；第 4 行有消息"
        );
        let none = Marks {
            current: None,
            breakpoints: Vec::new(),
            ..marks
        };
        assert_eq!(
            gutter_said(3, &[], &none, Lang::EN),
            "Line numbers 1 to 3 (click one to set or clear a breakpoint)"
        );
    }
}
