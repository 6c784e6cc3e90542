//! The shader debugger in the shader panel: the run of the inspected fragment (or of the
//! selected vertex) drives the source. The step shown is highlighted, each line shows the
//! value it last wrote, colours with a swatch; the run is stepped forward and back, over, into
//! and out of calls, to the cursor's line or to the next breakpoint (a line, and optionally
//! which of its hits). Nothing runs again: the frame already kept the whole run, so stepping
//! back is as cheap as stepping forward (`pipelens_glsl::stepping`).

use egui::{RichText, Ui};
use pipeline::capture::FrameCapture;
use pipeline::shader::stepping;
use pipeline::shader::{Stage, TraceLine};

use super::shader_source::Marks;
use crate::app::session::{Command, Session};
use crate::app::shortcuts::{self, Action};
use crate::vocabulary::Lang;

/// What the debugger keeps: the step shown, the breakpoints of each stage, which of the
/// pixel's fragments it follows, the cursor's line (for "run to line").
#[derive(Default)]
pub struct Debugger {
    /// The step shown, an index into the run (`None`: not stepping; the source shows each
    /// line's value at the end of the run).
    pub at: Option<usize>,
    /// The breakpoints, by stage, with their conditions.
    pub breakpoints: super::breakpoints::Breakpoints,
    /// Which of the inspected pixel's fragments is followed (from 0).
    pub fragment: usize,
    /// The line the text cursor is on, from 1.
    pub cursor_line: Option<usize>,
    /// Why the last step did not move (the run never reaches the line …), in words.
    pub note: Option<String>,
    /// The variable picture's row on the fragment shader's tab.
    pub watch: super::watch_picture::WatchPanel,
    /// The variable picture's row on the vertex shader's tab.
    pub vertex_watch: super::watch_picture::WatchPanel,
    /// The watch list: expressions read at the step.
    pub list: super::watch_list::WatchList,
    /// The cost view's picture.
    pub cost: super::watch_picture::WatchPanel,
    /// A line whose last step to show once the run of the pixel just inspected arrives (a
    /// condition's first pixel).
    pub show_line: Option<usize>,
    /// The lesson step's lines of the fragment shader (`shader_lines`), first and last, and
    /// for how many more frames they are scrolled to ([`REVEAL_FRAMES`] on entering the step).
    pub lines: Option<((usize, usize), u8)>,
}

/// For how many frames a step's lines are scrolled to on entering it: the panel's layout
/// settles over the first few (the code's scroll area learns its size, a watch's legend and
/// the narration band take their rows), and a scroll asked in the first alone can be undone.
pub const REVEAL_FRAMES: u8 = 8;

/// A move of the step shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Move {
    /// One step back.
    Back,
    /// The next step, into a call.
    Into,
    /// The next step in this function (a call run through).
    Over,
    /// Out of this function, to its caller's next step.
    Out,
    /// To the next step on the cursor's line.
    ToCursor,
    /// To the next breakpoint.
    Continue,
    /// Back to the previous breakpoint.
    ContinueBack,
}

/// The run the tab shown can step: the fragment shader's at the inspected pixel (the fragment
/// followed), or the vertex shader's at the selected vertex.
pub fn run_of(
    stage: Stage,
    debugger: &mut Debugger,
    session: &Session,
    capture: &FrameCapture,
) -> Option<Vec<TraceLine>> {
    match stage {
        Stage::Fragment => {
            let pixel = &capture.shaders.as_ref()?.pixel;
            debugger.fragment = debugger.fragment.min(pixel.len().saturating_sub(1));
            pixel.get(debugger.fragment).map(|f| f.trace.clone())
        }
        Stage::Vertex => {
            let row = session.selection.vertex? as usize;
            pipeline::trace_vertex(&session.spec.scene, capture, row)
                .ok()
                .flatten()
                .map(|t| t.trace)
        }
    }
}

impl Debugger {
    /// Keeps the step shown inside `run` (an edit or another pixel gives another run; the
    /// step stays where it was as far as the new run reaches).
    pub fn follow(&mut self, run: &[TraceLine]) {
        self.at = self.at.map(|a| a.min(run.len().saturating_sub(1)));
        if run.is_empty() {
            self.at = None;
        }
    }

    /// Moves the step shown through `run` as `m` says; when it cannot, the step stays and
    /// [`Debugger::note`] says why.
    pub fn step(&mut self, run: &[TraceLine], stage: Stage, m: Move, lang: Lang) {
        self.note = None;
        if run.is_empty() {
            return;
        }
        let at = self.at;
        let here = at.unwrap_or(0);
        let to = match (m, at) {
            // Not yet stepping: the first move shows the first step (or the first stop).
            (Move::Into | Move::Over, None) => Some(0),
            (Move::Back, _) => here.checked_sub(1),
            (Move::Into, Some(a)) => (a + 1 < run.len()).then_some(a + 1),
            (Move::Over, Some(a)) => stepping::over(run, a),
            (Move::Out, _) => stepping::out(run, here),
            (Move::ToCursor, _) => self.cursor_line.and_then(|line| {
                if at.is_none() && run[0].line == line {
                    Some(0)
                } else {
                    stepping::to_line(run, here, line)
                }
            }),
            (Move::Continue, _) => stepping::next_break(run, at, self.breakpoints.of(stage)),
            (Move::ContinueBack, _) => {
                stepping::previous_break(run, here, self.breakpoints.of(stage))
            }
        };
        match to {
            Some(k) => self.at = Some(k),
            None => {
                self.note = Some(
                    match m {
                        Move::Back | Move::ContinueBack if at.is_none() || here == 0 => {
                            lang.t("debugger-this-is-the-run-s")
                        }
                        Move::ContinueBack => lang.t("debugger-no-breakpoint-stops-the-run"),
                        Move::Continue if self.breakpoints.of(stage).is_empty() => {
                            lang.t("debugger-no-breakpoint-is-set-click")
                        }
                        Move::Continue => lang.t("debugger-no-breakpoint-stops-the-rest"),
                        Move::ToCursor if self.cursor_line.is_none() => {
                            lang.t("debugger-put-the-text-cursor-on")
                        }
                        Move::ToCursor => lang.t("debugger-the-rest-of-this-run"),
                        Move::Out => lang.t("debugger-this-step-is-in-main"),
                        Move::Into | Move::Over | Move::Back => {
                            lang.t("debugger-this-is-the-run-s-2")
                        }
                    }
                    .to_owned(),
                );
            }
        }
    }

    /// What the source shows of `run` at the step shown (at its end when not stepping): beside
    /// each line its last step in words, a colour written with its swatch.
    #[must_use]
    pub fn marks(&self, run: &[TraceLine], stage: Stage, lang: Lang) -> Marks {
        let breakpoints = self.breakpoints.of(stage).iter().map(|b| b.line).collect();
        let Some(last) = run.len().checked_sub(1) else {
            return Marks {
                breakpoints,
                ..Marks::default()
            };
        };
        let at = self.at.unwrap_or(last).min(last);
        let beside = stepping::beside_lines(run, at)
            .into_iter()
            .map(|(line, k)| {
                let swatch = run[k]
                    .step
                    .written()
                    .and_then(|(_, v)| stepping::colour(v))
                    .map(super::palette::swatch);
                (line, crate::vocabulary::trace::words(&run[k], lang), swatch)
            })
            .collect();
        Marks {
            current: self.at.map(|a| run[a.min(last)].line),
            breakpoints,
            beside,
            reveal: false,
            watched: None,
            lines: None,
        }
    }
}

/// The keys of the debugger pressed this frame, as moves.
#[must_use]
pub fn keys(ctx: &egui::Context) -> Option<Move> {
    [
        (Action::StepBack, Move::Back),
        (Action::StepOver, Move::Over),
        (Action::StepInto, Move::Into),
        (Action::StepOut, Move::Out),
        (Action::RunToCursor, Move::ToCursor),
        (Action::Continue, Move::Continue),
        (Action::ContinueBack, Move::ContinueBack),
    ]
    .into_iter()
    .find(|(a, _)| shortcuts::pressed(ctx, *a))
    .map(|(_, m)| m)
}

/// The debugger's bar over the source: the moves as buttons (each with its key), where the
/// run stands, the fragment followed, and the variables in scope at the step.
pub fn bar(
    ui: &mut Ui,
    debugger: &mut Debugger,
    run: &[TraceLine],
    (fragments, watch): (usize, Option<&Watching<'_>>),
    lang: Lang,
) -> Option<Move> {
    let mut pressed = None;
    ui.horizontal_wrapped(|ui| {
        let buttons = [
            (
                Move::Back,
                "debugger-back",
                Action::StepBack,
                "debugger-step-back",
            ),
            (
                Move::Over,
                "debugger-over",
                Action::StepOver,
                "debugger-step-over-a-call-run",
            ),
            (
                Move::Into,
                "debugger-into",
                Action::StepInto,
                "debugger-step-into-a-call",
            ),
            (
                Move::Out,
                "debugger-out",
                Action::StepOut,
                "debugger-step-out-of-this-function",
            ),
            (
                Move::ToCursor,
                "debugger-to-cursor",
                Action::RunToCursor,
                "debugger-run-to-the-cursor-s",
            ),
            (
                Move::ContinueBack,
                "debugger-breakpoint",
                Action::ContinueBack,
                "debugger-back-to-the-previous-breakpoint",
            ),
            (
                Move::Continue,
                "debugger-breakpoint-2",
                Action::Continue,
                "debugger-on-to-the-next-breakpoint",
            ),
        ];
        for (m, label, action, does) in buttons {
            let tip = format!(
                "{} ({})",
                lang.t(does),
                shortcuts::keys_written(shortcuts::of(action))
            );
            if ui.button(lang.t(label)).on_hover_text(tip).clicked() {
                pressed = Some(m);
            }
        }
        let position = match debugger.at {
            Some(a) => format!(
                "{} {} / {} · {} {}",
                lang.t("debugger-step"),
                a + 1,
                run.len(),
                lang.t("debugger-line"),
                run[a.min(run.len() - 1)].line
            ),
            None => format!(
                "{} {}",
                run.len(),
                lang.t("debugger-steps-f10-steps-through-them")
            ),
        };
        ui.label(RichText::new(position).monospace());
        if fragments > 1 {
            fragment_chooser(ui, debugger, fragments, lang);
        }
    });
    if let Some(note) = &debugger.note {
        ui.label(RichText::new(note).color(ui.visuals().warn_fg_color));
    }
    if let Some(a) = debugger.at.filter(|&a| a < run.len()) {
        scope(ui, run, a, lang);
        if let Some(w) = watch {
            ui.label(RichText::new(w.at_step(a, lang)).monospace());
        }
    }
    pressed
}

/// The variable picture's watch as the followed fragment's run stored it, to say its value at
/// the step shown.
pub struct Watching<'a> {
    /// The expression and its line.
    pub picture: &'a pipeline::capture::WatchPicture,
    /// Each store of the run: the steps before it, the value.
    pub stored: &'a [(usize, [f32; 4])],
}

impl Watching<'_> {
    /// "watch `expr` after line L = value" at step `at`: the last store at or before it.
    fn at_step(&self, at: usize, lang: Lang) -> String {
        let (expression, line) = (&self.picture.expression, self.picture.line);
        let kind = self.picture.kind;
        match (self.stored.iter().rev().find(|(k, _)| *k <= at + 1), kind) {
            (Some((_, v)), Some(kind)) => format!(
                "{} `{expression}` {} {line} = {}",
                lang.t("debugger-watch"),
                lang.t("debugger-after-line"),
                super::watch_picture::value_words(kind, *v)
            ),
            _ => lang.t_with(
                "debugger-watch-not-run-yet",
                &[("expression", expression), ("line", &line)],
            ),
        }
    }
}

/// The variables of the step's function as they stand at the step, a colour with its swatch.
fn scope(ui: &mut Ui, run: &[TraceLine], at: usize, lang: Lang) {
    egui::CollapsingHeader::new(lang.t("debugger-variables-at-this-step"))
        .id_salt("debugger scope")
        .default_open(true)
        .show(ui, |ui| {
            ui.label(RichText::new(&run[at].text).monospace().strong());
            for held in stepping::in_scope(run, at) {
                ui.horizontal(|ui| {
                    if let Some(c) = stepping::colour(held.value) {
                        let (rect, _) =
                            ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
                        ui.painter()
                            .rect_filled(rect, 2.0, super::palette::swatch(c));
                    }
                    ui.label(
                        RichText::new(format!(
                            "{} = {}   ({} {})",
                            held.name,
                            run[held.step].value.as_deref().unwrap_or_default(),
                            lang.t("debugger-line"),
                            held.line
                        ))
                        .monospace(),
                    );
                });
            }
        });
}

/// The debugger over the source of a shader's `stage` (none: a pipeline function's tab): its
/// keys and bar when the stage has a run to step (a hint where to click when it has none), the
/// breakpoints, the fragment shader's variable picture, and what the source shows of the run;
/// the command the breakpoints or the picture ask for.
pub fn panel(
    ui: &mut Ui,
    debugger: &mut Debugger,
    stage: Option<Stage>,
    session: &Session,
) -> (Marks, Option<Command>) {
    let Some(stage) = stage else {
        return (Marks::default(), None);
    };
    let (mut marks, step_line) = stepped(ui, debugger, stage, session);
    marks.watched = session
        .selection
        .watch
        .as_ref()
        .filter(|w| w.stage == stage)
        .map(|w| w.line);
    if stage == Stage::Fragment
        && let Some((lines, frames)) = &mut debugger.lines
    {
        marks.lines = Some((*lines, *frames > 0));
        *frames = frames.saturating_sub(1);
    }
    let mut command = super::breakpoints::list(
        ui,
        &mut debugger.breakpoints,
        &mut debugger.watch,
        stage,
        session,
    );
    if stage == Stage::Vertex && session.spec.scene.has_shaders() {
        let asked =
            super::watch_picture::ui(ui, &mut debugger.vertex_watch, session, step_line, stage);
        command = command.or(asked.command);
    }
    if stage == Stage::Fragment && session.spec.scene.has_shaders() {
        let asked = super::watch_picture::ui(ui, &mut debugger.watch, session, step_line, stage);
        command = command.or(asked.command);
        command = command.or(super::watch_picture::cost(ui, &mut debugger.cost, session));
        let (found, show_line) = super::breakpoints::found(&mut debugger.breakpoints, session);
        command = command.or(found);
        if let Some(line) = asked.show_line.or(show_line) {
            debugger.show_line = Some(line);
        }
    }
    (marks, command)
}

/// [`panel`]'s stepping on a shader's tab: what the source shows, and the step's line.
fn stepped(
    ui: &mut Ui,
    debugger: &mut Debugger,
    stage: Stage,
    session: &Session,
) -> (Marks, Option<usize>) {
    let lang = session.lang;
    let capture = session.capture.clone();
    let run = capture
        .as_deref()
        .and_then(|c| run_of(stage, debugger, session, c));
    let Some(run) = run.filter(|r| !r.is_empty()) else {
        if session.spec.scene.has_shaders() {
            ui.label(
                RichText::new(match stage {
                    Stage::Fragment => lang.t("debugger-debugger-click-a-pixel-of"),
                    Stage::Vertex => lang.t("debugger-debugger-select-a-vertex-a"),
                })
                .italics(),
            );
        }
        debugger.at = None;
        return (debugger.marks(&[], stage, lang), None);
    };
    debugger.follow(&run);
    // The first pixel where a condition holds was inspected: once its run is here, show its
    // last step on the watched line.
    let this_pixel = capture
        .as_deref()
        .is_some_and(|c| c.settings.capture.pixel == session.selection.pixel);
    if let Some(line) = debugger.show_line.filter(|_| this_pixel) {
        debugger.show_line = None;
        debugger.at = run.iter().rposition(|t| t.line == line);
    }
    let fragments = match stage {
        Stage::Fragment => capture
            .as_deref()
            .and_then(|c| c.shaders.as_ref())
            .map_or(0, |s| s.pixel.len()),
        Stage::Vertex => 1,
    };
    let before = debugger.at;
    if shortcuts::pressed(ui.ctx(), Action::Breakpoint) {
        match debugger.cursor_line {
            Some(line) => debugger.breakpoints.toggle(stage, line),
            None => {
                debugger.note = Some(lang.t("debugger-put-the-text-cursor-on").to_owned());
            }
        }
    }
    if let Some(m) = keys(ui.ctx()) {
        debugger.step(&run, stage, m, lang);
    }
    let picture = capture
        .as_deref()
        .and_then(|c| c.shaders.as_ref())
        .and_then(|r| {
            r.watch
                .as_ref()
                .map(|w| (w, r.pixel.get(debugger.fragment)))
        });
    let watching = match (stage, picture) {
        (Stage::Fragment, Some((picture, Some(f)))) => Some(Watching {
            picture,
            stored: &f.watch,
        }),
        _ => None,
    };
    if let Some(m) = bar(ui, debugger, &run, (fragments, watching.as_ref()), lang) {
        debugger.step(&run, stage, m, lang);
        // The bar above already showed the step before the click.
        ui.ctx().request_repaint();
    }
    let at = debugger.at.unwrap_or(run.len() - 1);
    super::watch_list::ui(
        ui,
        &mut debugger.list,
        session,
        (stage, debugger.fragment),
        &run,
        at,
    );
    let mut marks = debugger.marks(&run, stage, lang);
    marks.reveal = debugger.at != before;
    let step_line = marks.current;
    (marks, step_line)
}

/// Which of the `fragments` that reached the pixel the debugger follows, from 1.
fn fragment_chooser(ui: &mut Ui, debugger: &mut Debugger, fragments: usize, lang: Lang) {
    let label = ui.label(lang.t("debugger-fragment"));
    let mut k = debugger.fragment + 1;
    if ui
        .add(egui::DragValue::new(&mut k).range(1..=fragments))
        .labelled_by(label.id)
        .on_hover_text(lang.t("debugger-several-fragments-reached-this-pixel"))
        .changed()
    {
        debugger.fragment = k - 1;
        debugger.at = None;
    }
}
