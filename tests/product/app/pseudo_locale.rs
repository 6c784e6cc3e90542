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

/// The words of `text` outside every bracket: runs of two or more ASCII letters.
fn unbracketed_words(text: &str) -> Vec<String> {
    let mut depth = 0usize;
    let mut words = Vec::new();
    let mut word = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        match c {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            _ => {}
        }
        if depth == 0 && c.is_alphabetic() {
            word.push(c);
        } else {
            if word.chars().count() >= 2 && word.is_ascii() {
                words.push(std::mem::take(&mut word));
            }
            word.clear();
        }
    }
    words
}

/// Words that are notation, not interface: Angel's `mat.h` functions as the formula card writes
/// them (`V = LookAt(eye, at, up)`, `P = Perspective(fovy, aspect, near, far)`) and GLSL's type
/// names in the debugger's trace (`· bool`). They read the same in every language.
const NOTATION: [&str; 3] = ["LookAt", "Perspective", "bool"];

/// Every step of every lesson at 1366×768 in `en-XA`. What the frame paints fails when:
/// - a word outside every bracket is plain English that is not the lesson's own (its TOML) nor
///   notation: the code wrote it, not a catalog;
/// - egui elided a text (it ends in "…" because its room was too narrow);
/// - an interface text is cut at the left or right by its clip rect (a label wider than its
///   room); cut at the top or bottom is allowed, as that is a scroll area's edge;
/// - the painted part of a text lies past the window's edge.
#[test]
fn every_step_of_every_lesson_in_the_pseudo_locale_has_no_stray_word_and_nothing_cut_off() {
    let pseudo = Lang::find(PSEUDO).expect("the pseudo-locale");
    let window = Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1366.0, 768.0)).expand(1.0);
    let mut found = BTreeSet::new();
    for path in crate::support::lesson_files() {
        let source = std::fs::read_to_string(&path).expect("lesson");
        let own: BTreeSet<String> = unbracketed_words(&source.replace(['[', ']'], " "))
            .into_iter()
            .chain(NOTATION.map(String::from))
            .collect();
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
            let step = format!("{name} step {}", k + 1);
            for (clip, at, text, elided) in texts(&h) {
                let stray: Vec<String> = unbracketed_words(&text)
                    .into_iter()
                    .filter(|w| !own.contains(w))
                    .collect();
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
                let interface = text.chars().any(|c| c.is_alphabetic() && !c.is_ascii());
                if interface && (at.left() < clip.left() - 1.0 || at.right() > clip.right() + 1.0) {
                    found.insert(format!(
                        "cut sideways: {text:?} at {at:?} in {clip:?} ({step})"
                    ));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "{}",
        found.into_iter().collect::<Vec<_>>().join("\n")
    );
}
