//! The keys a picture takes while it has the keyboard's focus, so that everything a mouse does
//! in a view can be done without one: Tab reaches each picture, and V (`Action::FocusView`)
//! puts the focus on the main view, then on the picture beside it, then gives it back.
//!
//! While a picture has the focus the arrows are its own (egui would otherwise move the focus
//! with them, and the steps would not see them either): a pixel view moves the inspected pixel
//! one pixel a press, ten with Shift; a geometry view and the observer orbit; `+` and `−`
//! zoom; `[` and `]` pick the previous and next vertex. Escape gives the arrows back to the
//! steps (egui surrenders the focus on it). A ring in the focus colour shows which picture has
//! the keys (WCAG 2.4.7, focus visible).

use egui::{Color32, Context, EventFilter, Id, Key, Rect, Response, Stroke, StrokeKind, Ui, Vec2};

/// Which picture V puts the focus on: the stage's view, then the one beside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// The stage's own picture (a pixel view, a geometry view).
    Main,
    /// The picture beside it: the observer, or a lab's first companion.
    Beside,
}

/// What the keys pressed this frame ask of a focused picture.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Keys {
    /// Whether the picture has the keyboard's focus (its view draws [`ring`] last, over the
    /// picture).
    pub focused: bool,
    /// The arrows: x to the right, y up, in steps (a press 1, with Shift 10).
    pub arrows: Vec2,
    /// `+` (or `=`) one step in, `−` one step out.
    pub zoom: i32,
    /// `]` the next vertex, `[` the previous (Shift: 10).
    pub vertex: i32,
}

impl Keys {}

/// How many steps a press of `shift` moves: Shift moves ten (the "×10").
const SHIFTED: f32 = 10.0;

/// Allocates `rect` for the picture called `name` (click and drag), under an id of its own:
/// an id counted from the widgets before it would change as panels open and a button comes or
/// goes, and the keyboard's focus, kept by id, would fall off the picture.
pub fn allocate(ui: &mut Ui, rect: Rect, name: &'static str) -> Response {
    ui.advance_cursor_after_rect(rect);
    ui.interact(
        rect,
        Id::unique(("picture", name)),
        egui::Sense::click_and_drag(),
    )
}

/// [`allocate`] over the rest of `ui`'s space; returns that rect too.
pub fn allocate_rest(ui: &mut Ui, name: &'static str) -> (Rect, Response) {
    let rect = ui.available_rect_before_wrap();
    (rect, allocate(ui, rect, name))
}

/// Records `response`'s picture as the one at `place` (for V; a picture Tab alone reaches has
/// none), takes the focus if V asked for it, and reads its keys while it has the focus.
pub fn take(ui: &Ui, response: &Response, place: Option<Place>) -> Keys {
    let ctx = ui.ctx();
    if let Some(place) = place {
        ctx.data_mut(|d| d.insert_temp(place_id(place), response.id));
        let asked = ctx.data(|d| d.get_temp::<Place>(request_id()));
        if asked == Some(place) {
            ctx.data_mut(|d| d.remove::<Place>(request_id()));
            response.request_focus();
        }
    }
    if !response.has_focus() {
        return Keys::default();
    }
    ctx.memory_mut(|m| {
        m.set_focus_lock_filter(
            response.id,
            EventFilter {
                horizontal_arrows: true,
                vertical_arrows: true,
                ..EventFilter::default()
            },
        );
    });
    Keys {
        focused: true,
        ..read(ctx)
    }
}

/// The keys of this frame, as a focused picture reads them: arrows, `+`/`=`/`−`, `[`/`]`,
/// alone or with Shift (with Ctrl, `+` and `−` are the text size and are left alone).
fn read(ctx: &Context) -> Keys {
    let mut keys = Keys::default();
    ctx.input(|i| {
        for e in &i.events {
            let egui::Event::Key {
                key,
                pressed: true,
                modifiers,
                ..
            } = e
            else {
                continue;
            };
            if modifiers.ctrl || modifiers.command || modifiers.alt {
                continue;
            }
            let n = if modifiers.shift { SHIFTED } else { 1.0 };
            match key {
                Key::ArrowRight => keys.arrows.x += n,
                Key::ArrowLeft => keys.arrows.x -= n,
                Key::ArrowUp => keys.arrows.y += n,
                Key::ArrowDown => keys.arrows.y -= n,
                Key::Plus | Key::Equals => keys.zoom += 1,
                Key::Minus => keys.zoom -= 1,
                // Shift+[ is `{` on many layouts: the key as typed, ten vertices on.
                Key::CloseBracket => keys.vertex += n as i32,
                Key::OpenBracket => keys.vertex -= n as i32,
                Key::CloseCurlyBracket => keys.vertex += SHIFTED as i32,
                Key::OpenCurlyBracket => keys.vertex -= SHIFTED as i32,
                _ => {}
            }
        }
    });
    keys
}

/// The ring that shows which picture has the keys, drawn over the picture when `keys` say it
/// is focused: the theme's focus colour, 3 points wide, inside the picture's edge, over a dark
/// line so that it reads on a light picture too.
pub fn ring(ui: &Ui, rect: Rect, keys: Keys) {
    if !keys.focused {
        return;
    }
    let painter = ui.painter_at(rect);
    let colour = ui.visuals().selection.stroke.color;
    painter.rect_stroke(
        rect,
        0.0,
        Stroke::new(5.0, Color32::BLACK),
        StrokeKind::Inside,
    );
    painter.rect_stroke(rect, 0.0, Stroke::new(3.0, colour), StrokeKind::Inside);
}

/// V: the focus to the main picture; from it, to the one beside it; from that, off (the arrows
/// step the lesson again). The pictures read the request as they are drawn.
pub fn cycle(ctx: &Context) {
    let focused = ctx.memory(egui::Memory::focused);
    let at = |p: Place| ctx.data(|d| d.get_temp::<Id>(place_id(p)));
    let next = if focused.is_some() && focused == at(Place::Main) {
        at(Place::Beside).map(|_| Place::Beside)
    } else if focused.is_some() && focused == at(Place::Beside) {
        None
    } else {
        Some(Place::Main)
    };
    if let Some(p) = next {
        ctx.data_mut(|d| d.insert_temp(request_id(), p));
    } else if let Some(id) = focused {
        ctx.memory_mut(|m| m.surrender_focus(id));
    }
    ctx.request_repaint();
}

/// Forgets the picture beside the main one (a frame that draws none), so that V does not
/// look for one that is gone.
pub fn nothing_beside(ctx: &Context) {
    ctx.data_mut(|d| d.remove::<Id>(place_id(Place::Beside)));
}

fn place_id(place: Place) -> Id {
    Id::unique(("picture-keys", place as u8))
}

fn request_id() -> Id {
    Id::unique("picture-keys-request")
}

/// The new zoom after `steps` presses of `+`/`−`: ×1.25 a press, within `range`.
#[must_use]
pub fn zoomed(zoom: f32, steps: i32, range: (f32, f32)) -> f32 {
    (zoom * 1.25f32.powi(steps)).clamp(range.0, range.1)
}

/// The pixel the arrows move `from` to (window coordinates, y up, as the selection keeps them),
/// kept inside a `width` × `height` image.
#[must_use]
pub fn moved_pixel(from: (u32, u32), arrows: Vec2, (width, height): (u32, u32)) -> (u32, u32) {
    let x = (from.0 as f32 + arrows.x).clamp(0.0, width.saturating_sub(1) as f32);
    let y = (from.1 as f32 + arrows.y).clamp(0.0, height.saturating_sub(1) as f32);
    (x as u32, y as u32)
}

/// The pixel a focused picture's arrows inspect: `from` moved ([`moved_pixel`]), or, on the
/// first press with none inspected, `start` (the middle of what the picture shows); none
/// without an arrow.
pub fn arrowed_pixel(
    keys: Keys,
    from: Option<(u32, u32)>,
    size: (u32, u32),
    start: impl FnOnce() -> (u32, u32),
) -> Option<(u32, u32)> {
    (keys.arrows != Vec2::ZERO).then(|| match from {
        Some(from) => moved_pixel(from, keys.arrows, size),
        None => start(),
    })
}

/// The vertex `]`/`[` pick, `steps` on from `from` (none yet: the first, or the last going
/// back), wrapping round the `count` vertices.
#[must_use]
pub fn stepped_vertex(from: Option<u32>, steps: i32, count: usize) -> Option<u32> {
    if count == 0 || steps == 0 {
        return from;
    }
    let n = count as i64;
    let start = match from {
        Some(v) => i64::from(v),
        None if steps > 0 => -1,
        None => n,
    };
    Some((start + i64::from(steps)).rem_euclid(n) as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Up is +y in window coordinates (the selection's), and the edges hold the pixel.
    #[test]
    fn the_arrows_move_a_pixel_within_the_image() {
        assert_eq!(moved_pixel((5, 5), Vec2::new(1.0, 0.0), (10, 10)), (6, 5));
        assert_eq!(moved_pixel((5, 5), Vec2::new(0.0, 1.0), (10, 10)), (5, 6));
        assert_eq!(
            moved_pixel((5, 5), Vec2::new(-10.0, -10.0), (10, 10)),
            (0, 0)
        );
        assert_eq!(moved_pixel((5, 5), Vec2::new(10.0, 10.0), (10, 10)), (9, 9));
    }

    /// `]` from none is the first vertex, `[` the last; both wrap round.
    #[test]
    fn the_brackets_step_through_the_vertices_and_wrap() {
        assert_eq!(stepped_vertex(None, 1, 8), Some(0));
        assert_eq!(stepped_vertex(None, -1, 8), Some(7));
        assert_eq!(stepped_vertex(Some(7), 1, 8), Some(0));
        assert_eq!(stepped_vertex(Some(2), -10, 8), Some(0));
        assert_eq!(stepped_vertex(Some(3), 10, 8), Some(5));
        assert_eq!(stepped_vertex(Some(3), 1, 0), Some(3));
    }

    /// Two presses in are 1.25² = 1.5625; the range holds.
    #[test]
    fn plus_and_minus_zoom_by_a_quarter_within_the_range() {
        assert!((zoomed(2.0, 2, (0.1, 10.0)) - 3.125).abs() < 1e-6);
        assert!((zoomed(2.0, -1, (0.1, 10.0)) - 1.6).abs() < 1e-6);
        assert_eq!(zoomed(8.0, 3, (0.1, 10.0)), 10.0);
    }
}
