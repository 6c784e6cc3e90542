//! How long an input takes to reach the picture, the window's end of issue 55's "live": from the
//! start of the frame that handled a keystroke in the shader panel (the code compiled and a
//! render asked for) or a pixel click (a render keeping its trace asked for) to the end of the
//! first frame that draws the capture rendered for it — what the window paints next. With
//! `PIPELENS_FRAME_LOG` set the desktop app writes each to standard error as
//! `latency: 41.2 ms (keystroke)`, beside `frame:` (see `platform::report`); nothing is kept
//! otherwise.

use web_time::Instant;

use super::session::{Command, Session};
use crate::app::command::{SceneCommand, SelectionCommand};

/// An input waiting for its picture: what it was, when its frame started, and the generation
/// of the render it asked for.
#[derive(Clone, Copy, Debug)]
pub struct Waiting {
    what: &'static str,
    since: Instant,
    generation: u64,
}

/// What an input this frame was, among those timed: a keystroke that changed the code (a
/// scene command in a frame with a key or text event), or a pixel picked.
#[must_use]
pub fn timed(command: &Command, typed: bool) -> Option<&'static str> {
    match command {
        Command::Scene(SceneCommand::SetSpec(_)) if typed => Some("keystroke"),
        Command::Selection(SelectionCommand::SelectPixel(Some(_))) => Some("pixel click"),
        _ => None,
    }
}

/// Whether inputs are timed: the frame log is on (`platform::frame_log`).
#[must_use]
pub fn logging() -> bool {
    super::platform::frame_log()
}

/// Writes an input's latency to standard error, `latency: 41.2 ms (keystroke)`, beside the
/// frame log's `frame:` lines.
pub fn log(ms: f64, what: &str) {
    if logging() {
        eprintln!("latency: {ms:.1} ms ({what})");
    }
}

/// The input `what`, handled in the frame that started `since`, waits for the render the
/// session now asks for (none asked: nothing to wait for).
#[must_use]
pub fn wait(what: &'static str, since: Instant, before: u64, session: &Session) -> Option<Waiting> {
    (session.generation > before).then_some(Waiting {
        what,
        since,
        generation: session.generation,
    })
}

/// At a frame's end: when the capture on screen is the one `waiting` asked for (or a later
/// one), its latency in milliseconds and what it was; `waiting` is then cleared.
pub fn arrived(waiting: &mut Option<Waiting>, session: &Session) -> Option<(f64, &'static str)> {
    let w = (*waiting)?;
    if session.shown_generation < w.generation || session.capture.is_none() {
        return None;
    }
    *waiting = None;
    Some((w.since.elapsed().as_secs_f64() * 1e3, w.what))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn session() -> Session {
        let spec = crate::lesson::default_scene().expect("the built-in scene");
        Session::new(spec, "test", None)
    }

    #[test]
    fn a_keystroke_is_a_scene_change_in_a_frame_with_keys_and_a_click_a_pixel_picked() {
        let spec = Command::Scene(SceneCommand::SetSpec(Box::new(session().spec)));
        assert_eq!(timed(&spec, true), Some("keystroke"));
        // A slider dragged changes the scene too, with no key pressed.
        assert_eq!(timed(&spec, false), None);
        let pick = Command::Selection(SelectionCommand::SelectPixel(Some((3, 4))));
        assert_eq!(timed(&pick, false), Some("pixel click"));
        let unpick = Command::Selection(SelectionCommand::SelectPixel(None));
        assert_eq!(timed(&unpick, false), None);
    }

    #[test]
    fn an_input_that_asked_for_no_render_waits_for_none() {
        let mut s = session();
        s.request_render();
        assert!(s.generation >= 1);
        assert!(wait("keystroke", Instant::now(), s.generation, &s).is_none());
        let mut waiting = wait("keystroke", Instant::now(), s.generation - 1, &s);
        assert!(waiting.is_some());
        // With no worker the session renders as it asks: the capture shown is that
        // generation's, so the input has arrived, and is counted once.
        assert_eq!(s.shown_generation, s.generation);
        assert!(arrived(&mut waiting, &s).is_some());
        assert!(arrived(&mut waiting, &s).is_none());
    }
}
