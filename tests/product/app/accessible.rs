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
    for lang in [Lang::EN, Lang::ZH] {
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
                missing.push(format!("{lang:?} {}: {n}", stage.name(Lang::EN)));
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

/// Each panel's divider (a splitter: its arrow keys resize the panel) is named in the language
/// shown, with the panel it resizes: egui alone calls every one "Resize panel", in English.
#[test]
fn every_divider_says_which_panel_it_resizes_in_the_language_shown() {
    for (lang, names) in [
        (
            Lang::EN,
            [
                "Resize panel: Parameters",
                "Resize panel: Inspector",
                "Resize panel: Shader",
                "Resize panel: Lesson editor",
            ],
        ),
        (
            Lang::ZH,
            [
                "调整面板大小：参数",
                "调整面板大小：检查器",
                "调整面板大小：着色器",
                "调整面板大小：课程编辑器",
            ],
        ),
    ] {
        let mut h = super::harness();
        open_everything(&mut h, lang);
        h.run();
        // R opens the lesson editor, as a teacher does.
        h.key_press(egui::Key::R);
        h.run();
        let mut dividers: Vec<String> = h
            .query_all(by().predicate(|n: &NodeRef| n.role() == accesskit::Role::Splitter))
            .map(|n| n.accesskit_node().label().unwrap_or_default())
            .collect();
        dividers.sort();
        let mut expected: Vec<String> = names.iter().map(|n| (*n).to_owned()).collect();
        expected.sort();
        assert_eq!(dividers, expected, "{lang:?}");
        // On a phone, the narration's sheet under the picture.
        let path = crate::support::repo().join("lessons/00-tour.toml");
        let mut phone = super::sized_lesson_harness(&path, [390.0, 844.0]);
        phone
            .state_mut()
            .session
            .apply(Command::View(ViewCommand::SetLang(lang)));
        phone.run_steps(3);
        let sheet: Vec<String> = phone
            .query_all(by().predicate(|n: &NodeRef| n.role() == accesskit::Role::Splitter))
            .map(|n| n.accesskit_node().label().unwrap_or_default())
            .collect();
        let said = if lang == Lang::ZH {
            "调整面板大小：讲解"
        } else {
            "Resize panel: Narration"
        };
        assert_eq!(sheet, [said], "{lang:?} on a phone");
    }
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

/// The live regions' words in this frame: each node that a screen reader reads out now.
fn announced(h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>) -> Vec<String> {
    // A label's text run inherits its liveness: the label's own words are what is read.
    h.query_all(by().predicate(|n: &NodeRef| {
        n.live() == accesskit::Live::Polite && n.role() != accesskit::Role::TextRun
    }))
    .filter_map(|n| {
        let a = n.accesskit_node();
        a.label().or_else(|| a.value())
    })
    .collect()
}

/// What is read out over `frames` frames, frame by frame: each time a live region's words
/// are said.
fn said_over(
    h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>,
    frames: usize,
) -> Vec<String> {
    let mut said = Vec::new();
    for _ in 0..frames {
        h.step();
        said.extend(announced(h));
    }
    said
}

/// The narration card's title and a lab's verdict are live regions, said once each time
/// their words are new: the step's number and title on each new step (the card's words follow
/// them), the verdict on entering the lab and when the student's code changes it — never again
/// frame after frame while they stand (lesson 10's light casters lab animates its lights).
#[test]
fn the_narration_and_the_verdict_are_announced_once_as_they_change() {
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    let lesson = crate::app::lesson_of(&h);
    let title = |k: usize| format!("{}. {}", k + 1, lesson.steps[k].title.en);
    // The harness drew the first frame as it was built: whatever it said, not said again.
    assert!(said_over(&mut h, 8).is_empty());
    let go = |h: &mut egui_kittest::Harness<'_, pipelens::app::PipelensApp>, k: usize| {
        h.state_mut()
            .session
            .apply(pipelens::app::session::Command::Lesson(
                pipelens::app::command::LessonCommand::GoToStep(k),
            ));
    };
    go(&mut h, 1);
    assert_eq!(said_over(&mut h, 8), vec![title(1)]);
    go(&mut h, 0);
    assert_eq!(said_over(&mut h, 8), vec![title(0)]);
    let lab = lesson
        .steps
        .iter()
        .position(|s| s.title.en == crate::app::SPECULAR_LAB)
        .expect("the lab");
    for k in [lab + 1, lab] {
        go(&mut h, k);
        let said = said_over(&mut h, 30);
        assert_eq!(said.len(), 2, "step {}: {said:?}", k + 1);
        assert_eq!(said[0], title(k));
        assert!(said[1].starts_with("Not yet: "), "{said:?}");
    }
    // Solved: the verdict's words change, and are said once.
    let solved = crate::labs::solved_source(&h.state().session, true);
    h.state_mut().panels.shader = true;
    h.run_steps(3);
    h.get_by_role(accesskit::Role::MultilineTextInput).focus();
    h.run_steps(2);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role(accesskit::Role::MultilineTextInput)
        .type_text(&solved);
    // The panel runs the code as it is typed; Ctrl+Enter runs it again, to the same words.
    let mut said = said_over(&mut h, 12);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Enter);
    said.extend(said_over(&mut h, 12));
    let passed = |s: &String| s.starts_with("Passed: all 172800 pixels match");
    assert_eq!(said.iter().filter(|s| passed(s)).count(), 1, "{said:?}");
    assert!(said.last().is_some_and(passed), "{said:?}");
}

/// A page has no AccessKit, so its words stand beside the canvas (`web/index.html`): the step's
/// number and title, the narration in plain words, each picture's text alternative — the same
/// words AccessKit's tree names the picture by — and a lab's verdict, in the interface's
/// language. Read here as the page's elements get them (`alt::page_words`).
#[test]
fn a_page_keeps_the_step_its_pictures_and_the_verdict_in_words() {
    use pipelens::app::views::alt::{self, Part};
    let path = crate::support::repo().join("lessons/10-blinn-phong.toml");
    let mut h = crate::app::sized_lesson_harness(&path, [1920.0, 1080.0]);
    alt::keep_page_words(&h.ctx);
    crate::app::go_to_step_titled(&mut h, "Ambient: light from everywhere");
    h.run_steps(6);
    let words = alt::page_words(&h.ctx).expect("kept");
    assert_eq!(words.get(Part::Title), "1. Ambient: light from everywhere");
    // The step's narration, its marks taken out (lessons/10-blinn-phong.toml).
    assert!(
        words
            .get(Part::Narration)
            .starts_with("La = ka·Ia: the same at every point, a stand-in for light bounced around the room. Alone it draws"),
        "{}",
        words.get(Part::Narration)
    );
    // Each picture's words are those its node in the tree is named by.
    let named: Vec<String> = h
        .query_all(by().role(accesskit::Role::Image))
        .filter_map(|n| n.accesskit_node().label())
        .filter(|l| l.contains(" view: ") || l.starts_with("observer"))
        .collect();
    assert!(!named.is_empty());
    for n in &named {
        assert!(
            words.get(Part::Picture).lines().any(|l| l == n),
            "{n:?} not in {:?}",
            words.get(Part::Picture)
        );
    }
    assert!(words.get(Part::Verdict).is_empty(), "no lab, no verdict");
    crate::app::go_to_step_titled(&mut h, crate::app::SPECULAR_LAB);
    h.run_steps(30);
    let words = alt::page_words(&h.ctx).expect("kept");
    assert!(
        words.get(Part::Verdict).starts_with("Not yet: "),
        "{}",
        words.get(Part::Verdict)
    );
    // In Chinese.
    h.state_mut().session.lang = Lang::ZH;
    h.run_steps(6);
    let words = alt::page_words(&h.ctx).expect("kept");
    assert_eq!(words.get(Part::Title), "8. 实验：在片元着色器中写出高光项");
    assert!(
        words.get(Part::Picture).starts_with("像素视图："),
        "{}",
        words.get(Part::Picture)
    );
}

/// The accessibility tree below `node` as an indented outline: each shown node's role, then its
/// name and value where it has them (cut at 120 characters).
fn outline(node: &NodeRef, depth: usize, out: &mut String) {
    if node.is_hidden() {
        return;
    }
    let cut = |s: String| s.chars().take(120).collect::<String>();
    let mut line = format!("{}{:?}", "  ".repeat(depth), node.role());
    if let Some(label) = node.label().filter(|l| !l.trim().is_empty()) {
        line.push_str(&format!(" \"{}\"", cut(label)));
    }
    if let Some(value) = node.value().filter(|v| !v.trim().is_empty()) {
        line.push_str(&format!(" = \"{}\"", cut(value)));
    }
    out.push_str(&line);
    out.push('\n');
    for child in node.children() {
        outline(&child, depth + 1, out);
    }
}

/// The tree a screen reader walks, for three views in both languages, written out for a person
/// to read (`target/accesskit/*.txt`): the tour's output stage with a pixel inspected, the
/// shader lesson's code step with its panel open, and the rotation lab. Each outline holds the
/// step's title from the lesson file and the picture's name, in the language shown.
#[test]
fn the_tree_of_three_views_is_written_out_for_a_reader() {
    let dir = crate::support::repo().join("target/accesskit");
    std::fs::create_dir_all(&dir).expect("the folder is made");
    for lang in [Lang::EN, Lang::ZH] {
        let views = [
            ("00-tour", 0, "tour-inspected"),
            ("24-shader-programs", 4, "shader-panel"),
            ("25-lab-model-projection", 2, "rotation-lab"),
        ];
        for (id, k, name) in views {
            let path = crate::support::repo().join(format!("lessons/{id}.toml"));
            let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
            h.state_mut()
                .session
                .apply(Command::View(ViewCommand::SetLang(lang)));
            h.state_mut().panels.inspector = true;
            h.state_mut().panels.shader = name == "shader-panel";
            super::go_to_step(&mut h, k);
            if name == "tour-inspected" {
                h.state_mut().session.apply(Command::Selection(
                    pipelens::app::command::SelectionCommand::SelectPixel(Some((320, 200))),
                ));
                h.run_steps(3);
            }
            let mut text = String::new();
            outline(&h.root().accesskit_node(), 0, &mut text);
            let file = dir.join(format!("{name}-{}.txt", lang.tag()));
            std::fs::write(&file, &text).expect("the outline is written");
            let title = h
                .state()
                .session
                .lesson
                .as_ref()
                .expect("a lesson")
                .lesson
                .steps[k]
                .title
                .get(lang)
                .to_owned();
            assert!(text.contains(&title), "{}: no \"{title}\"", file.display());
            assert!(
                text.contains("Image \""),
                "{}: no picture is named",
                file.display()
            );
            // The lab's step shows the viewport matrix of its 640×400 window (x_w = 320·x + 320,
            // y_w = 200·y + 200), said as one group row by row before its sixteen cells.
            if name == "rotation-lab" {
                let said = if lang == Lang::EN {
                    "Group \"the 4×4 matrix, row by row: row 1: 320, 0, 0, 320; row 2: 0, 200, 0, 200;"
                } else {
                    "Group \"4×4 矩阵，按行：第 1 行：320、0、0、320；第 2 行：0、200、0、200；"
                };
                assert!(text.contains(said), "{}: no \"{said}\"", file.display());
            }
        }
    }
}
