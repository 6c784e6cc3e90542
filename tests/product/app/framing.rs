//! Where things go in the picture: the step's subject clear of the narration card and of the
//! words over it, a label beside its point.
use pipelens::app::command::ViewCommand;

/// The narration card and the words a view draws over its picture (its header, the matrix
/// card, the legend) never cover the step's subject (issue: the card hid a vertex of lesson
/// 07's triangle at 1920×1080 in Chinese, half of lesson 17's arm in classroom mode at
/// 1366×768, one of lesson 23's five compared images; the legend covered lesson 17's arm and
/// the matrix card a cube vertex of lesson 25): in every step of every lesson, at 1920×1080 in
/// Chinese, at 1366×768 in classroom mode in English and at 1920×1080 in classroom mode in
/// Chinese, the image, the compared images and the focused objects' wireframe lie clear of
/// the card and of the overlays. In classroom mode every word drawn over a geometry stage's
/// pictures (labels, legend, the matrix card's digits) is at least the narration's size.
#[test]
fn the_narration_and_the_overlays_leave_the_subject_clear() {
    use pipelens::app::session::Command;
    use pipelens::vocabulary::Lang;
    let mut covered = Vec::new();
    let mut small = Vec::new();
    let mut hidden = Vec::new();
    let mut checked = (0, 0);
    for (size, classroom, lang) in [
        ([1920.0, 1080.0], false, Lang::ZH),
        ([1366.0, 768.0], true, Lang::EN),
        ([1920.0, 1080.0], true, Lang::ZH),
    ] {
        for path in crate::support::lesson_files() {
            let mut h = super::sized_lesson_harness(&path, size);
            let ctx = h.ctx.clone();
            h.state_mut().set_classroom(&ctx, classroom);
            h.state_mut()
                .session
                .apply(Command::View(ViewCommand::SetLang(lang)));
            for k in 0..super::step_count(&h) {
                super::go_to_step(&mut h, k);
                let place = format!(
                    "{} step {} at {}×{}{}",
                    path.file_stem().unwrap_or_default().to_string_lossy(),
                    k + 1,
                    size[0],
                    size[1],
                    if classroom { " classroom" } else { "" }
                );
                let card = pipelens::app::views::card_placement::narration_card(&h.ctx);
                let state = h.state();
                for r in &state.subject {
                    checked.0 += 1;
                    let over = card.iter().chain(&state.overlays).find(|o| overlap(r, o));
                    if let Some(o) = over {
                        covered.push(format!("{place}: {r:?} under {o:?}"));
                    }
                }
                // The card does not hide the words over the picture either (the tour's NDC
                // legend sat under it at 1920 points with the inspector open).
                for o in &state.overlays {
                    if let Some(c) = card.filter(|c| overlap(o, c)) {
                        hidden.push(format!("{place}: {o:?} under the narration {c:?}"));
                    }
                }
                if card.is_none() {
                    // With the shader panel open at 1366 points the narration is a band at
                    // the window's foot, a panel the views lie above.
                    assert!(
                        state.panels.shader && size[0] < 1600.0,
                        "{place}: a lesson shows its card"
                    );
                }
                let geometry = state.session.selection.stage.space().is_some();
                if let (true, true, Some(card)) = (classroom, geometry, card) {
                    let texts = texts(&h);
                    let narration = most_common(texts.iter().filter(|t| card.contains_rect(t.0)));
                    let scripts = scripted(&texts);
                    for ((at, size, text), script) in texts.iter().zip(scripts) {
                        if state.picture.iter().any(|p| p.contains_rect(*at)) && !script {
                            checked.1 += 1;
                            if *size < narration - 0.01 {
                                small.push(format!("{place}: {text:?} {size} < {narration}"));
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(checked.0 > 150, "only {} subjects were checked", checked.0);
    assert!(checked.1 > 500, "only {} words were measured", checked.1);
    assert!(covered.is_empty(), "{}", covered.join("\n"));
    assert!(hidden.is_empty(), "{}", hidden.join("\n"));
    assert!(small.is_empty(), "{}", small.join("\n"));
}

/// Whether two rects share some area (touching edges do not count).
fn overlap(a: &egui::Rect, b: &egui::Rect) -> bool {
    let i = a.intersect(*b);
    i.width() > 0.5 && i.height() > 0.5
}

/// Every run of words the last frame painted: where, at what font size (its least), what it
/// says.
pub(super) fn texts(
    h: &egui_kittest::Harness<'_, pipelens::app::PipelensApp>,
) -> Vec<(egui::Rect, f32, String)> {
    fn walk(shape: &egui::Shape, out: &mut Vec<(egui::Rect, f32, String)>) {
        match shape {
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(s, out)),
            egui::Shape::Text(t) if !t.galley.text().trim().is_empty() => {
                let size = t
                    .galley
                    .job
                    .sections
                    .iter()
                    .map(|s| s.format.font_id.size)
                    .fold(f32::INFINITY, f32::min);
                let at = t.galley.rect.translate(t.pos.to_vec2());
                out.push((at, size, t.galley.text().to_owned()));
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    for c in &h.output().shapes {
        walk(&c.shape, &mut out);
    }
    out
}

/// Which runs of words are a formula's scripts or a fraction's parts, set smaller than their
/// base by the typesetting's ratios (0.7 for a script, 0.82 for a fraction, their product for
/// a script in one): beside a larger run at one of those ratios, or beside such a part of the
/// same size (the rest of a numerator). Their base is measured instead.
fn scripted(all: &[(egui::Rect, f32, String)]) -> Vec<bool> {
    let near = |t: &(egui::Rect, f32, String), u: &(egui::Rect, f32, String)| {
        u.0.expand(u.1.max(t.1)).intersects(t.0)
    };
    let mut out: Vec<bool> = all
        .iter()
        .map(|t| {
            all.iter().any(|u| {
                let ratio = t.1 / u.1;
                [0.7, 0.82, 0.7 * 0.82]
                    .iter()
                    .any(|r| (ratio - r).abs() < 0.005)
                    && near(t, u)
            })
        })
        .collect();
    loop {
        let next: Vec<bool> = all
            .iter()
            .enumerate()
            .map(|(i, t)| {
                out[i]
                    || all
                        .iter()
                        .zip(&out)
                        .any(|(u, s)| *s && (u.1 - t.1).abs() < 0.01 && near(t, u))
            })
            .collect();
        if next == out {
            return out;
        }
        out = next;
    }
}

/// The font size most of these words are set in (the narration's body, not its title).
fn most_common<'a>(texts: impl Iterator<Item = &'a (egui::Rect, f32, String)>) -> f32 {
    let mut counts: Vec<(f32, usize)> = Vec::new();
    for (_, size, text) in texts {
        let n = text.chars().count();
        match counts.iter_mut().find(|(s, _)| (s - size).abs() < 0.01) {
            Some(c) => c.1 += n,
            None => counts.push((*size, n)),
        }
    }
    counts.into_iter().max_by_key(|c| c.1).map_or(0.0, |c| c.0)
}

/// The tour's NDC step at 1920×1080 with the inspector open: the view is 570 points wide, the
/// narration card spans its foot, and the legend, which leaves the largest square for the
/// subject at the bottom-right, went under the card there. It goes where the card leaves it
/// in sight.
#[test]
fn the_legend_is_not_hidden_under_the_narration_card() {
    let path = crate::support::repo().join("lessons/00-tour.toml");
    let mut h = super::sized_lesson_harness(&path, [1920.0, 1080.0]);
    h.state_mut().panels.inspector = true;
    super::go_to_step(&mut h, 5);
    h.run_steps(4);
    let state = h.state();
    assert_eq!(
        state.session.selection.stage,
        pipelens::vocabulary::Stage::Ndc
    );
    let card = pipelens::app::views::card_placement::narration_card(&h.ctx).expect("the card");
    assert!(state.overlays.len() >= 3, "{:?}", state.overlays);
    for o in &state.overlays {
        assert!(
            !overlap(o, &card),
            "{o:?} under the narration card {card:?}"
        );
    }
}

#[test]
fn a_label_keeps_off_the_subject_and_the_cards() {
    use egui::{Pos2, Rect, vec2};
    use pipelens::app::views::place_label;
    let view = Rect::from_min_size(Pos2::ZERO, vec2(800.0, 600.0));
    let subject = Rect::from_min_max(Pos2::new(200.0, 150.0), Pos2::new(600.0, 450.0));
    let card = Rect::from_min_max(Pos2::new(560.0, 0.0), Pos2::new(800.0, 200.0));
    let size = vec2(160.0, 24.0);
    // An anchor on the subject's edge: the label goes next to it, off both.
    let r = place_label(Pos2::new(600.0, 300.0), size, &[subject, card], view);
    assert!(view.contains_rect(r));
    assert!(!r.intersects(subject) && !r.intersects(card), "{r:?}");
    assert!(r.center().distance(Pos2::new(600.0, 300.0)) < 200.0);
    // No room around the anchor off the subject: still beside the anchor, over the subject
    // but off the card (not pinned in a far corner with a leader line across the picture).
    let whole = Rect::from_min_max(Pos2::new(20.0, 100.0), Pos2::new(700.0, 580.0));
    let r = place_label(Pos2::new(400.0, 300.0), size, &[whole, card], view);
    assert!(view.contains_rect(r));
    assert!(!r.intersects(card), "{r:?}");
    assert!(
        r.center().distance(Pos2::new(400.0, 300.0)) < 150.0,
        "{r:?}"
    );
    // No room anywhere near the anchor: a corner, the farthest from the subject that the card
    // leaves free (the top-right is farthest, and the card's; the bottom-right comes next).
    let tall = Rect::from_min_max(Pos2::new(250.0, 0.0), Pos2::new(560.0, 600.0));
    let r = place_label(Pos2::new(400.0, 300.0), size, &[whole, card, tall], view);
    assert!(view.contains_rect(r));
    assert!(!r.intersects(card) && !r.intersects(tall), "{r:?}");
    assert!(
        r.right() > 799.0 && r.bottom() > 599.0,
        "the bottom-right corner: {r:?}"
    );
    // With no card, the farthest corner.
    let r = place_label(Pos2::new(400.0, 300.0), size, &[whole, tall], view);
    assert!(
        r.right() > 799.0 && r.top() < 1.0,
        "the top-right corner: {r:?}"
    );
    // A card in every corner (a small view: the header, the matrix card, the legend, the
    // narration) and a vertex far off the view at its upper left: along an edge, clear of
    // every card, as near the vertex as that allows — the left edge just under the header
    // (which ends at y = 60; the places along an edge are 25 points apart, so the first free
    // one is centred at y = 75: 63 to 87 for 24 high). The top edge's first free place, right
    // of the header, is farther from the vertex: its centre (280, 12) is 712 away, against
    // 553 for (80, 75).
    let header = Rect::from_min_max(Pos2::ZERO, Pos2::new(200.0, 60.0));
    let legend = Rect::from_min_max(Pos2::new(600.0, 480.0), Pos2::new(800.0, 600.0));
    let narration = Rect::from_min_max(Pos2::new(0.0, 450.0), Pos2::new(300.0, 600.0));
    let cards = [subject, header, card, legend, narration];
    let r = place_label(Pos2::new(-400.0, -200.0), size, &cards, view);
    assert!(view.contains_rect(r), "{r:?}");
    assert!(
        cards[1..].iter().all(|c| !r.intersects(*c)),
        "{r:?} over a card"
    );
    assert!(
        r.left() < 1.0 && (r.top() - 63.0).abs() < 0.5,
        "on the left edge just under the header: {r:?}"
    );
}

/// In an upright window a mouse drives (a portrait monitor, a browser window 768 points wide:
/// the desktop's card, not a phone's sheet) a lab's three pictures stand one over two, and the
/// narration card in the bottom-left corner lay over pipelens' own picture (lesson 07's lab at
/// 768×1024: the whole companion under it). The card leaves each of the three clear, in
/// every lab of lessons 07 and 10, at 768×1024 and 900×1200.
#[test]
fn in_an_upright_window_the_card_leaves_a_lab_s_pictures_clear() {
    let mut covered = Vec::new();
    let mut labs = 0;
    for size in [[768.0, 1024.0], [900.0, 1200.0]] {
        for name in ["07-rasterization", "10-blinn-phong"] {
            let path = crate::support::repo().join(format!("lessons/{name}.toml"));
            let mut h = super::sized_lesson_harness(&path, size);
            for k in 0..super::step_count(&h) {
                super::go_to_step(&mut h, k);
                if h.state().session.current_exercise().is_none() {
                    continue;
                }
                h.run_steps(6);
                labs += 1;
                let card = pipelens::app::views::card_placement::narration_card(&h.ctx);
                let state = h.state();
                assert!(card.is_some(), "{name} step {}: the card", k + 1);
                // The student's frame's subject (its image may run under the card where it
                // shows nothing: the view frames its subject clear of the card) and the two
                // companions, pictures whole.
                assert_eq!(
                    state.subject.len(),
                    3,
                    "{name} step {}: three subjects",
                    k + 1
                );
                for p in &state.subject {
                    if let Some(c) = card.filter(|c| overlap(p, c)) {
                        covered.push(format!(
                            "{name} step {} at {size:?}: {p:?} under {c:?}",
                            k + 1
                        ));
                    }
                }
            }
        }
    }
    assert!(labs >= 4, "only {labs} labs were seen");
    assert!(covered.is_empty(), "{}", covered.join("\n"));
}
