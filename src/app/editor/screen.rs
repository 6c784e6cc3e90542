//! What is on screen, recorded: the parameters changed since the step began (as `set`), the
//! sliders dragged while the editor was open (as `animate`, their seconds editable), added as a
//! new step after the current one — its words typed first — or written into the current one.

use egui::RichText;

use super::window::Editor;
use super::words;
use crate::app::session::{Command, Session};
use crate::lesson::param;
use crate::vocabulary::Lang;

impl Editor {
    /// What is on screen: the parameters changed since the step began, the drags recorded as
    /// animations (their seconds editable), added as a new step after this one (its words typed
    /// first) or written into this one.
    pub(super) fn on_screen(
        &mut self,
        ui: &mut egui::Ui,
        session: &Session,
        lang: Lang,
        out: &mut Vec<Command>,
    ) {
        let (Some(player), Some(mut step)) =
            (&session.lesson, crate::app::record::recorded_step(session))
        else {
            return;
        };
        let k = player.step;
        ui.label(RichText::new(lang.t("screen-what-is-on-screen")).strong());
        ui.label(RichText::new(lang.t("screen-the-stage-buffer-layout-overlays")).small());
        if step.set.is_empty() {
            ui.label(lang.t("screen-no-parameter-changed"));
        }
        for (name, value) in &step.set {
            ui.monospace(format!("set {name} = {value}"));
        }
        self.drags_ui(ui, lang);
        step.animate.clone_from(&self.drags);
        let Some(doc) = &mut self.doc else {
            return;
        };
        let mut result = None;
        let mut go = k;
        if ui
            .button(lang.t_with("screen-update-step", &[("step", &(k + 1))]))
            .on_hover_text(lang.t("screen-its-words-shaders-and-exercise"))
            .clicked()
        {
            // `set` counts from the scene the step before leaves, its own animations where they
            // are now (they are the step's, not changes); without new drags, they stay.
            let own = &player.current().animate;
            let mut base = player.lesson.spec_before(k);
            for a in own {
                let _ = param::apply(&mut base, &a.param, &a.value_at(player.time));
            }
            step.set = param::differences(&base, &session.spec);
            if self.drags.is_empty() {
                step.animate.clone_from(own);
            }
            result = Some(doc.draft.update(k, &step));
            self.drags.clear();
        }
        ui.add_space(6.0);
        ui.label(
            RichText::new(lang.t_with("screen-new-step-words", &[("step", &(k + 2))])).strong(),
        );
        words::pair(ui, lang.t("screen-title"), &mut self.fresh[0], 1);
        words::pair(ui, lang.t("screen-narration"), &mut self.fresh[1], 3);
        words::missing_note(ui, lang, &self.fresh[1]);
        if ui
            .button(lang.t_with("screen-add-as-step", &[("step", &(k + 2))]))
            .clicked()
        {
            if crate::lesson::record::unworded(&self.fresh[0]).len() < 2 {
                step.title = self.fresh[0].clone();
            }
            step.narration = self.fresh[1].clone();
            result = Some(doc.draft.insert(k + 1, &step).map(|()| {
                self.fresh = Default::default();
                self.drags.clear();
            }));
            go = k + 1;
        }
        match result {
            Some(Ok(())) => {
                self.said = None;
                self.refused_on_screen = None;
                self.revised(session, Some(go), true, out);
            }
            Some(Err(e)) => {
                self.refused_on_screen = Some((e.clone(), true));
                self.said = Some(Err(e));
            }
            None => {}
        }
        // Why the button did nothing, where the teacher is looking: under it, scrolled to.
        if let (Some((refusal, reveal)), Some(Err(e))) = (&mut self.refused_on_screen, &self.said)
            && e == refusal
        {
            let shown = super::window::said(ui, &Err(e.clone()));
            if *reveal {
                shown.scroll_to_me(Some(egui::Align::Center));
                *reveal = false;
            }
        }
    }

    /// The drags recorded as animations: each with its seconds to edit, or dropped (×).
    fn drags_ui(&mut self, ui: &mut egui::Ui, lang: Lang) {
        let mut drop = None;
        for (i, a) in self.drags.iter_mut().enumerate() {
            ui.horizontal(|ui| {
                ui.monospace(format!("animate {} : {} → {}", a.param, a.from, a.to));
                ui.add(
                    egui::DragValue::new(&mut a.seconds)
                        .range(0.5..=60.0)
                        .speed(0.1)
                        .suffix(" s"),
                )
                .on_hover_text(lang.t("screen-seconds-from-the-first-value"));
                if ui
                    .add(crate::app::style::glyph_button(ui, "×", None))
                    .on_hover_text(lang.t("screen-not-an-animation"))
                    .clicked()
                {
                    drop = Some(i);
                }
            });
        }
        if let Some(i) = drop {
            self.drags.remove(i);
        }
    }
}
