//! The pseudo-locale through every step of every lesson (issue "Every student can use it"):
//! in `en-XA` every word of the interface is accented, lengthened by about 40 % and bracketed,
//! so a word the code writes itself shows as plain English, and a label too narrow for a
//! longer language shows cut off.

use std::collections::BTreeSet;

use egui::{Rect, Shape};
use pipelens::app::command::{Command, ViewCommand};
use pipelens::vocabulary::{Lang, PSEUDO};

/// Every run of words the frame paints, with its clip rect, where it is painted (its rect
/// turned by its angle: the y axes' titles are upright), what it says and whether it was elided.
fn texts(
    h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>,
) -> Vec<(Rect, Rect, String, bool)> {
    super::flatten(h)
        .into_iter()
        .filter_map(|(clip, s)| {
            let Shape::Text(t) = s else { return None };
            let r = t.galley.rect;
            let rot = egui::emath::Rot2::from_angle(t.angle);
            let corners = [
                r.left_top(),
                r.right_top(),
                r.left_bottom(),
                r.right_bottom(),
            ];
            let at = Rect::from_points(&corners.map(|c| t.pos + rot * c.to_vec2()));
            Some((clip, at, t.galley.job.text.clone(), t.galley.elided))
        })
        .collect()
}

/// The runs of `text` outside every bracket, each cut at its line breaks: what no catalog
/// wrote.
fn unbracketed_runs(text: &str) -> Vec<String> {
    let mut depth = 0usize;
    let mut runs = vec![String::new()];
    for c in text.chars() {
        match c {
            '[' => {
                depth += 1;
                runs.push(String::new());
            }
            ']' => depth = depth.saturating_sub(1),
            '\n' => runs.push(String::new()),
            _ if depth == 0 => runs.last_mut().expect("a run").push(c),
            _ => {}
        }
    }
    runs.into_iter()
        .map(|r| r.trim().to_owned())
        .filter(|r| !r.is_empty())
        .collect()
}

/// The English words of `run`: its names (letters, digits and `_`) that are ASCII with two
/// letters or more — `vec3`, `w_pos`, not the `pp` of a lengthened `úúppéér`.
fn words(run: &str) -> Vec<&str> {
    run.split(|c: char| !c.is_alphanumeric() && c != '_')
        .filter(|w| w.is_ascii() && w.chars().filter(char::is_ascii_alphabetic).count() >= 2)
        .collect()
}

/// Notation, not interface: Angel's `mat.h` functions as the formula card writes them
/// (`V = LookAt(eye, at, up)`, `P = Perspective(fovy, aspect, near, far)`), which read the same
/// in every language.
const NOTATION: [&str; 2] = [
    "LookAt(eye, at, up)",
    "Perspective(fovy, aspect, near, far)",
];

/// Names that read the same in every language: the keys as the keyboard writes them
/// (`Ctrl+Shift+Z`, `Page Up`), the pixel's unit, the shading models and filters named after
/// their authors or by their acronyms (`Gouraud`, `Blinn-Phong`, `EWA`, `ripmap`), and the
/// rotation matrices (`Rx`, `Ry`, `Rz`).
const NAMES: [&str; 17] = [
    "Ctrl", "Shift", "Alt", "Page", "Up", "Down", "Enter", "Esc", "px", "Phong", "Blinn",
    "Gouraud", "EWA", "ripmap", "Rx", "Ry", "Rz",
];

/// GLSL's names of types and values, as the debugger writes a value (`vec3(0.2, 0.4, 0.9)`,
/// `· bool`).
const GLSL: [&str; 12] = [
    "bool", "int", "uint", "float", "vec2", "vec3", "vec4", "mat3", "mat4", "ivec2", "true",
    "false",
];

/// Whether `run` is the debugger's value beside a line, `// name = value`: the name one of the
/// lesson's GLSL, the value GLSL notation.
fn is_traced_value(run: &str, lesson: &str) -> bool {
    run.strip_prefix("// ")
        .and_then(|r| r.split_once(" = "))
        .is_some_and(|(name, value)| {
            lesson.contains(name) && words(value).iter().all(|w| GLSL.contains(w))
        })
}

/// Whether `run` is a formula, notation in every language (`T(tx, ty, tz)`,
/// `S(2·near/(r−l), …`, `normalize(eye − p)`, `round(255·c)`): it has an operator or a
/// bracket, no two of its words stand apart by spaces alone (as a sentence's do), and no word
/// is a label before a number (`near 0.500`, as a legend composed in code would be).
fn is_formula(run: &str) -> bool {
    if !run.contains(['(', '=', '·', '/', '^']) {
        return false;
    }
    let mut last_end: Option<usize> = None;
    let mut at = 0;
    while let Some(start) = run[at..].find(|c: char| c.is_ascii_alphabetic()) {
        let begin = at + start;
        let end = run[begin..]
            .find(|c: char| !c.is_alphanumeric() && c != '_')
            .map_or(run.len(), |n| begin + n);
        if last_end.is_some_and(|prev| run[prev..begin].trim().is_empty()) {
            return false;
        }
        let after = &run[end..];
        if after.starts_with(' ') && after[1..].starts_with(|c: char| c.is_ascii_digit()) {
            return false;
        }
        last_end = Some(end);
        at = end;
    }
    true
}

/// The English words of `text` that neither a catalog nor the lesson wrote: for each run
/// outside the brackets, its words unless the run (less its numbering and punctuation at
/// either end) is one the lesson's file writes as it is — a step's title, an object's name, a
/// line of its GLSL — or the debugger's value of one of its variables, or a formula, or a
/// symbol of one or two letters alone (a formula's piece as typeset, `sy, `). A run
/// the code composes of the lesson's words, as `near 0.5, far 30` of a depth curve's legend,
/// is not in the file and fails.
fn stray_words(text: &str, lesson: &str) -> Vec<String> {
    unbracketed_runs(text)
        .iter()
        .map(|run| NOTATION.iter().fold(run.clone(), |r, n| r.replace(n, " ")))
        .filter(|run| {
            let core = run.trim_matches(|c: char| !c.is_alphabetic());
            let symbol = matches!(words(run).as_slice(), [w] if w.len() <= 2);
            !lesson.contains(core) && !is_traced_value(run, lesson) && !is_formula(run) && !symbol
        })
        .flat_map(|run| {
            words(&run)
                .into_iter()
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
        .filter(|w| {
            !GLSL.contains(&w.as_str()) && !NAMES.contains(&w.as_str()) && !is_subscripted(w)
        })
        .collect()
}

/// Whether `word` is a symbol with its subscript, as the course writes them (`f_s`, `z_w`,
/// `k_d`, `f_spot`, `win_0`, `RGB_8`): one or two letters, `_`, the subscript; or a name and a
/// subscript of one character. A figure's label says `f = 3.0, f_s = 20.0` in every language.
fn is_subscripted(word: &str) -> bool {
    word.split_once('_').is_some_and(|(base, sub)| {
        !sub.is_empty() && ((1..=2).contains(&base.len()) || sub.chars().count() == 1)
    })
}

/// What the frame of `h` paints that fails, each named with `step`. It fails when:
/// - a word outside every bracket is plain English that is not notation, in a run the lesson's
///   TOML (`source`) does not write as it is: the code wrote it, not a catalog;
/// - egui elided a text (it ends in "…" because its room was too narrow);
/// - an interface text is cut at the left or right by its clip rect (a label wider than its
///   room); cut at the top or bottom is allowed, as that is a scroll area's edge;
/// - the painted part of a text lies past the window's edge.
fn faults(
    h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>,
    source: &str,
    step: &str,
    found: &mut BTreeSet<String>,
) {
    let window = Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1366.0, 768.0)).expand(1.0);
    for (clip, at, text, elided) in texts(h) {
        let stray = stray_words(&text, source);
        if !stray.is_empty() {
            found.insert(format!("stray words {stray:?} in {text:?} ({step})"));
        }
        if elided {
            found.insert(format!("elided {text:?} ({step})"));
        }
        let seen = at.intersect(clip);
        if !seen.is_positive() {
            continue;
        }
        if !window.contains_rect(seen) {
            found.insert(format!("past the window: {text:?} at {at:?} ({step})"));
        }
        // A shader's source scrolls sideways in its editor, by design.
        let interface = text.chars().any(|c| c.is_alphabetic() && !c.is_ascii())
            && !text.starts_with("#version");
        if interface && (at.left() < clip.left() - 1.0 || at.right() > clip.right() + 1.0) {
            found.insert(format!(
                "cut sideways: {text:?} at {at:?} in {clip:?} ({step})"
            ));
        }
    }
}

/// Fails with every fault found.
fn assert_none(found: BTreeSet<String>) {
    assert!(
        found.is_empty(),
        "{}",
        found.into_iter().collect::<Vec<_>>().join("\n")
    );
}

/// Every step of every lesson at 1366×768 in `en-XA`, checked for [`faults`].
#[test]
fn every_step_of_every_lesson_in_the_pseudo_locale_has_no_stray_word_and_nothing_cut_off() {
    let pseudo = Lang::find(PSEUDO).expect("the pseudo-locale");
    let mut found = BTreeSet::new();
    for path in crate::support::lesson_files() {
        let source = std::fs::read_to_string(&path).expect("lesson");
        let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
        h.state_mut()
            .session
            .apply(Command::View(ViewCommand::SetLang(pseudo)));
        h.run_steps(2);
        let name = path
            .file_stem()
            .unwrap_or_default()
            .to_string_lossy()
            .to_string();
        for k in 0..super::step_count(&h) {
            super::go_to_step(&mut h, k);
            faults(&h, &source, &format!("{name} step {}", k + 1), &mut found);
        }
    }
    assert_none(found);
}

/// Each panel and the lesson editor open in `en-XA` — the parameters, the inspector or the
/// shader panel, each with the keys' help and the editor (R) — through
/// every step of the shader lesson (24) and the lab lesson (25) at 1366×768, checked for
/// [`faults`]: the panels' words are the catalogs' too.
#[test]
fn the_panels_and_the_editor_in_the_pseudo_locale_have_no_stray_word_and_nothing_cut_off() {
    let pseudo = Lang::find(PSEUDO).expect("the pseudo-locale");
    let mut found = BTreeSet::new();
    for id in ["24-shader-programs", "25-lab-model-projection"] {
        let path = crate::support::repo().join(format!("lessons/{id}.toml"));
        // The shader panel shows pipelens' own shaders too, their lines as shipped.
        let source = std::iter::once(std::fs::read_to_string(&path).expect("lesson"))
            .chain(pipeline::shader::SHIPPED_VERTEX.map(str::to_owned))
            .chain(pipeline::shader::SHIPPED_FRAGMENT.map(str::to_owned))
            .collect::<Vec<_>>()
            .join("\n");
        for panels in ["parameters", "inspector", "shader"] {
            let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
            h.key_press(egui::Key::R);
            h.run_steps(2);
            for k in 0..super::step_count(&h) {
                super::go_to_step(&mut h, k);
                let app = h.state_mut();
                app.session
                    .apply(Command::View(ViewCommand::SetLang(pseudo)));
                app.panels.parameters = panels == "parameters";
                app.panels.inspector = panels == "inspector";
                app.panels.shader = panels == "shader";
                app.panels.keys = true;
                h.run_steps(3);
                let step = format!("{id} step {} with the {panels}", k + 1);
                faults(&h, &source, &step, &mut found);
            }
        }
    }
    assert_none(found);
}

/// The shader panel's code follows the language shown: lesson 25's lab (step 3) runs
/// pipelens' own fragment shader, whose first comment reads in Chinese once the interface is
/// Chinese (zh-Hans.ftl's `glsl-pipelens-per-pixel-phong-frequency-lighting`), in the
/// pseudo-locale's brackets in `en-XA`, and as shipped in English again; a source the student
/// edited keeps what they typed.
#[test]
fn the_shader_panels_comments_follow_the_language() {
    let path = crate::support::repo().join("lessons/25-lab-model-projection.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    super::go_to_step(&mut h, 2);
    h.state_mut().panels.shader = true;
    h.run_steps(3);
    let english = "// pipelens' per-pixel (Phong-frequency) lighting with the Blinn-Phong model";
    let chinese = "// pipelens 的逐像素（Phong 频率）光照，用 Blinn-Phong 模型，写成着色器：";
    let pseudo = Lang::find(PSEUDO).expect("the pseudo-locale");
    for (lang, first) in [
        (Lang::ZH, chinese),
        (pseudo, "// [píípéélééñş' péér-pííxéél"),
        (Lang::EN, english),
    ] {
        h.state_mut()
            .session
            .apply(Command::View(ViewCommand::SetLang(lang)));
        h.run_steps(3);
        let fragment = &h.state().shader_editor.fragment;
        assert!(fragment.contains(first), "{}: {fragment}", lang.tag());
    }
    h.state_mut().shader_editor.fragment.push_str("// mine\n");
    h.state_mut()
        .session
        .apply(Command::View(ViewCommand::SetLang(Lang::ZH)));
    h.run_steps(3);
    let fragment = &h.state().shader_editor.fragment;
    assert!(fragment.contains(english) && fragment.ends_with("// mine\n"));
}
