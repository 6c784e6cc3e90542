//! A screen reader reads the app (issue "Every student can use it"): every node of the
//! accessibility tree a user can act on — click, focus — has a name, on every stage with every
//! panel open, through the shader lesson and a lab, in both languages. A picture is named by
//! its text alternative.

use accesskit_consumer::{FilterResult, NodeRef};
use egui_kittest::kittest::{NodeT, Queryable, by};
use pipelens::app::command::{Command, ViewCommand};
use pipelens::vocabulary::{Lang, Stage};

fn include(_: &NodeRef) -> FilterResult {
    FilterResult::Include
}

/// Each node one can act on that has no name: its role, where it is, and its parent.
fn unnamed(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> Vec<String> {
    h.query_all(by().predicate(|n: &NodeRef| {
        (n.is_clickable(&include) || n.is_focusable(&include))
            && !n.is_hidden()
            && n.label().is_none_or(|l| l.trim().is_empty())
            // A label's words are its value.
            && !(n.role() == accesskit::Role::Label
                && n.value().is_some_and(|v| !v.trim().is_empty()))
            // egui's own scroll bars, which the app has no way to name.
            && n.role() != accesskit::Role::ScrollBar
    }))
    .map(|n| {
        let a = n.accesskit_node();
        let parent = a
            .parent()
            .map(|p| format!("{:?} {:?}", p.role(), p.label()))
            .unwrap_or_default();
        format!("{:?} at {:?} in {parent}", a.role(), n.rect())
    })
    .collect()
}

/// Every panel open: the parameters, the inspector, the code, the keys' help.
fn open_everything(h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>, lang: Lang) {
    let app = h.state_mut();
    app.session.apply(Command::View(ViewCommand::SetLang(lang)));
    app.panels.parameters = true;
    app.panels.inspector = true;
    app.panels.shader = true;
    app.panels.keys = true;
}

#[test]
fn every_control_has_a_name() {
    let mut missing = Vec::new();
    let mut named = 0;
    for lang in [Lang::En, Lang::Zh] {
        let mut h = super::harness();
        open_everything(&mut h, lang);
        h.run();
        for stage in Stage::ALL {
            h.state_mut()
                .session
                .apply(Command::View(ViewCommand::SelectStage(stage)));
            h.run();
            named += h
                .query_all(by().predicate(|n: &NodeRef| n.label().is_some()))
                .count();
            for n in unnamed(&h) {
                missing.push(format!("{lang:?} {}: {n}", stage.name(Lang::En)));
            }
        }
        for id in ["24-shader-programs", "25-lab-model-projection"] {
            let path = crate::support::repo().join(format!("lessons/{id}.toml"));
            let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
            open_everything(&mut h, lang);
            for k in 0..super::step_count(&h) {
                super::go_to_step(&mut h, k);
                for n in unnamed(&h) {
                    missing.push(format!("{lang:?} {id} step {}: {n}", k + 1));
                }
            }
        }
    }
    assert!(named > 1000, "only {named} named nodes were read");
    missing.sort();
    missing.dedup();
    assert!(
        missing.is_empty(),
        "{} unnamed:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

/// The picture is named by what it shows: at the output stage of the built-in scene, the stage,
/// the buffer and the objects; once a pixel is inspected, that pixel and its colour's line.
#[test]
fn the_picture_is_named_by_what_it_shows() {
    let mut h = super::harness();
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SelectStage(Stage::Output)));
    h.run();
    let picture = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>| {
        h.query_all(by().role(accesskit::Role::Image))
            .filter_map(|n| n.accesskit_node().label())
            .find(|l| l.starts_with("pixel view: "))
            .unwrap_or_default()
    };
    let name = picture(&h);
    assert!(
        name.starts_with("pixel view: Output stage, Colour buffer, "),
        "{name}"
    );
    h.state_mut().session.apply(Command::Selection(
        pipelens::app::command::SelectionCommand::SelectPixel(Some((320, 200))),
    ));
    h.run();
    let name = picture(&h);
    assert!(name.contains("At pixel (320, 200), "), "{name}");
    assert!(name.contains("RGB_8 = round(255·c) = ("), "{name}");
}

/// The live regions' words: each status node that a screen reader reads out as it changes.
fn announced(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> Vec<String> {
    h.query_all(by().predicate(|n: &NodeRef| {
        n.role() == accesskit::Role::Status && n.live() == accesskit::Live::Polite
    }))
    .filter_map(|n| n.accesskit_node().label())
    .collect()
}

/// The narration card and a lab's verdict are live regions: the step's number, title and
/// words (marks taken out) are announced on each new step, and the verdict as the student's
/// code changes it, without the focus moving.
#[test]
fn the_narration_and_the_verdict_are_announced_as_they_change() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.run_steps(4);
    let lesson = crate::app::lesson_of(&h);
    // Lesson 10's first step says **L_a = k_a·I_a**, its second **L_d = k_d·(I/r²)·…**: each
    // read with its marks taken out, the one on screen only.
    let said = |h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>, k: usize| {
        let all = announced(h);
        let title = format!("{}. {}. ", k + 1, lesson.steps[k].title.en);
        let step: Vec<&String> = all.iter().filter(|s| s.starts_with(&title)).collect();
        assert_eq!(step.len(), 1, "step {k} is announced once: {all:?}");
        step[0].clone()
    };
    let first = said(&h, 0);
    assert!(
        first.contains("La = ka·Ia") && !first.contains("**"),
        "{first}"
    );
    crate::app::go_to_step(&mut h, 1);
    let second = said(&h, 1);
    assert!(second.contains("Ld = kd·(I/r²)·max(0, n·l)"), "{second}");
    assert!(!announced(&h).iter().any(|s| s.starts_with("1. ")));
    let k = crate::app::go_to_step_titled(&mut h, crate::app::SPECULAR_LAB);
    h.run_steps(4);
    assert!(
        announced(&h)
            .iter()
            .any(|s| s.starts_with("Not yet: 162116 of 172800 pixels match")),
        "{:?}",
        announced(&h)
    );
    // Solved: the verdict's words change, and so what is announced.
    let solved = crate::labs::solved_source(&h.state().session, true);
    h.state_mut().panels.shader = true;
    h.run_steps(3);
    let source = h.get_by_role(accesskit::Role::MultilineTextInput);
    source.focus();
    h.run_steps(2);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role(accesskit::Role::MultilineTextInput)
        .type_text(&solved);
    h.run_steps(3);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Enter);
    h.run_steps(6);
    assert_eq!(crate::app::step_of(&h), k);
    assert!(
        announced(&h)
            .iter()
            .any(|s| s.starts_with("Passed: all 172800 pixels match")),
        "{:?}",
        announced(&h)
    );
}
