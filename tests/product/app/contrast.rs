//! Text contrast (issue "Every student can use it", WCAG 2.1 AA, success criterion 1.4.3): every
//! run of words the app paints stands out from what it is painted on by at least 4.5:1, or 3:1
//! at 24 points and larger (WCAG's "large text", 18 pt), in the normal theme and in classroom
//! mode, at every step of every lesson.
//!
//! What a run is painted on is read from the frame's shapes in paint order: the fills before it
//! that cover its middle, composed from the lowest opaque one up. Where a picture (a textured
//! shape) lies under it, the run must stand out from the picture at both extremes, black and
//! white, through whatever box lies between.

use egui::{Color32, Pos2, Rect, Shape};

/// WCAG's relative luminance of an sRGB colour: `0.2126 R + 0.7152 G + 0.0722 B` of the
/// linear channels.
fn luminance(c: [f32; 3]) -> f32 {
    let lin = |v: f32| {
        if v <= 0.040_45 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
}

/// WCAG's contrast ratio `(L₁ + 0.05)/(L₂ + 0.05)`, the lighter over the darker.
fn contrast(a: [f32; 3], b: [f32; 3]) -> f32 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// `c` (premultiplied, as egui keeps colours) laid over `under`.
fn over(c: Color32, under: [f32; 3]) -> [f32; 3] {
    let a = f32::from(c.a()) / 255.0;
    let rgb = [c.r(), c.g(), c.b()].map(|v| f32::from(v) / 255.0);
    [0, 1, 2].map(|k| rgb[k] + under[k] * (1.0 - a))
}

/// What covers `p` in one shape: a fill, a picture, or nothing.
enum Cover {
    Fill(Color32),
    Picture,
}

fn covers(shape: &Shape, p: Pos2) -> Option<Cover> {
    match shape {
        Shape::Rect(r) if r.rect.contains(p) && r.blur_width == 0.0 => {
            if r.brush.is_some() {
                Some(Cover::Picture)
            } else if r.fill.a() > 0 {
                Some(Cover::Fill(r.fill))
            } else {
                None
            }
        }
        Shape::Mesh(m) if m.texture_id != egui::TextureId::default() => {
            m.calc_bounds().contains(p).then_some(Cover::Picture)
        }
        Shape::Circle(c) if c.fill.a() > 0 && c.center.distance(p) <= c.radius => {
            Some(Cover::Fill(c.fill))
        }
        Shape::Path(path) if path.closed && path.fill.a() > 0 && inside(&path.points, p) => {
            Some(Cover::Fill(path.fill))
        }
        _ => None,
    }
}

/// Whether `p` lies inside the polygon `pts` (crossings of a ray to the right).
fn inside(pts: &[Pos2], p: Pos2) -> bool {
    let mut odd = false;
    for (i, a) in pts.iter().enumerate() {
        let b = pts[(i + 1) % pts.len()];
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            odd = !odd;
        }
    }
    odd
}

/// Each run of words in the frame whose contrast is below WCAG AA: what it says, its size, its
/// colour and the ratio.
fn too_faint(shapes: &[(Rect, Shape)], disabled: f32) -> Vec<(String, f32, Color32, f32)> {
    let mut out = Vec::new();
    for (i, (clip, shape)) in shapes.iter().enumerate() {
        let Shape::Text(t) = shape else { continue };
        let at = t.galley.rect.translate(t.pos.to_vec2()).intersect(*clip);
        if !at.is_positive() || t.angle != 0.0 {
            continue;
        }
        let p = at.center();
        // The fills under the run, topmost first, down to an opaque one or a picture.
        let mut layers = Vec::new();
        let mut picture = false;
        for (c, s) in shapes[..i].iter().rev() {
            if !c.contains(p) {
                continue;
            }
            match covers(s, p) {
                Some(Cover::Fill(f)) => {
                    layers.push(f);
                    if f.a() == 255 {
                        break;
                    }
                }
                Some(Cover::Picture) => {
                    picture = true;
                    break;
                }
                None => {}
            }
        }
        let bottoms: &[[f32; 3]] = if picture {
            &[[0.0; 3], [1.0; 3]]
        } else {
            &[[0.0; 3]]
        };
        let job = &t.galley.job;
        for section in &job.sections {
            let words = &job.text[section.byte_range.start.0..section.byte_range.end.0];
            if words.trim().is_empty() {
                continue;
            }
            let colour =
                t.override_text_color
                    .unwrap_or(if section.format.color == Color32::PLACEHOLDER {
                        t.fallback_color
                    } else {
                        section.format.color
                    });
            let colour = colour.gamma_multiply(t.opacity_factor);
            // An inactive widget's words, faded to egui's `disabled_alpha`: WCAG 1.4.3 exempts
            // inactive components (the step arrows at the first and last step).
            if (f32::from(colour.a()) - 255.0 * disabled).abs() <= 1.0 {
                continue;
            }
            let size = section.format.font_id.size;
            let needed = if size >= 24.0 { 3.0 } else { 4.5 };
            for bottom in bottoms {
                let ground = layers.iter().rev().fold(*bottom, |g, f| over(*f, g));
                let ratio = contrast(over(colour, ground), ground);
                if ratio < needed - 0.005 {
                    let ground = ground.map(|v| (v * 255.0).round() as u8);
                    out.push((format!("{words} on {ground:?}"), size, colour, ratio));
                }
            }
        }
    }
    out
}

/// WCAG's own examples: black on white is 21:1, white on white 1:1, and #767676 on white
/// 4.54:1 (the lightest grey that passes AA on white, as WebAIM's checker gives it).
#[test]
fn the_contrast_ratio_is_wcags() {
    assert!((contrast([0.0; 3], [1.0; 3]) - 21.0).abs() < 1e-3);
    assert!((contrast([1.0; 3], [1.0; 3]) - 1.0).abs() < 1e-6);
    let grey = 118.0 / 255.0;
    assert!((contrast([grey; 3], [1.0; 3]) - 4.54).abs() < 0.01);
}

#[test]
fn every_word_stands_out_from_its_ground() {
    let mut faint = Vec::new();
    let mut runs = 0;
    for classroom in [false, true] {
        for path in crate::support::lesson_files() {
            let mut h = super::sized_lesson_harness(&path, [1366.0, 768.0]);
            let ctx = h.ctx.clone();
            h.state_mut().set_classroom(&ctx, classroom);
            for k in 0..super::step_count(&h) {
                super::go_to_step(&mut h, k);
                let shapes = super::flatten(&h);
                runs += shapes
                    .iter()
                    .filter(|(_, s)| matches!(s, Shape::Text(_)))
                    .count();
                let disabled = h.ctx.global_style().visuals.disabled_alpha();
                for (words, size, colour, ratio) in too_faint(&shapes, disabled) {
                    faint.push(format!(
                        "{} step {}{}: {words:?} ({size} pt, {colour:?}) {ratio:.2}:1",
                        path.file_stem().unwrap_or_default().to_string_lossy(),
                        k + 1,
                        if classroom { " classroom" } else { "" },
                    ));
                }
            }
        }
    }
    assert!(runs > 5000, "only {runs} runs of words were read");
    faint.sort();
    faint.dedup();
    assert!(
        faint.is_empty(),
        "{} runs too faint:\n{}",
        faint.len(),
        faint.join("\n")
    );
}
