//! A lesson's text read and checked: the `[lesson]` table, then each step against the scene as
//! the steps before it left it — its views, its values and targets, its focus — every problem
//! with its position.

use std::path::Path;

use crate::lesson::folder::Folder;

use pipeline::buffers::BufferKind;
use toml::Spanned;

use super::super::param::{self, Value};
use super::super::raw::{RawLessonFile, RawStep, RawValue};
use super::super::validate::Checker;
use super::super::{Diagnostics, SceneSpec};
use super::{LAYOUTS, Layout, Lesson, OVERLAYS, Overlay, Step};
use crate::vocabulary::{Comparison, Lang, Stage};

/// A warning for each of a new lesson's placeholders left in `raw` (the lesson's title and
/// summary, a step's title and narration), naming the languages it was left in.
fn placeholders_left(raw: &RawLessonFile, file: &str, text: &str) -> Vec<super::super::Diagnostic> {
    let meta = raw.lesson.get_ref();
    let mut out = Vec::new();
    let placeholders = [
        (
            "the lesson's title",
            &meta.title,
            super::super::PLACEHOLDER_LESSON[0],
        ),
        (
            "the lesson's summary",
            &meta.summary,
            super::super::PLACEHOLDER_LESSON[1],
        ),
    ];
    let numbered: Vec<_> = raw
        .steps
        .iter()
        .enumerate()
        .flat_map(|(k, s)| {
            let s = s.get_ref();
            [
                (
                    format!("step {}'s title", k + 1),
                    &s.title,
                    super::super::PLACEHOLDER_STEP_TITLE,
                ),
                (
                    format!("step {}'s narration", k + 1),
                    &s.narration,
                    super::super::PLACEHOLDER_NARRATION,
                ),
            ]
        })
        .collect();
    for (what, said, placeholder) in placeholders
        .into_iter()
        .map(|(w, s, p)| (w.to_owned(), s, p))
        .chain(numbered)
    {
        let kept: Vec<&str> = [
            ("English", &said.get_ref().en),
            ("Chinese", &said.get_ref().zh),
        ]
        .into_iter()
        .filter(|(_, t)| placeholder.contains(&t.trim()))
        .map(|(lang, _)| lang)
        .collect();
        if !kept.is_empty() {
            out.push(
                super::super::Diagnostic::at(
                    file,
                    text,
                    said.span(),
                    format!(
                        "{what} is still the new lesson's placeholder in {}: write the lesson's own words",
                        kept.join(" and ")
                    ),
                )
                .warning(),
            );
        }
    }
    out
}

/// Whether TOML text is a lesson (it has a `[lesson]` table) rather than a bare scene.
#[must_use]
pub fn is_lesson(text: &str) -> bool {
    text.parse::<toml::Table>()
        .is_ok_and(|t| t.contains_key("lesson"))
}

/// Parses and validates lesson text. `file` names it in messages; `base` resolves paths.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_lesson(text: &str, file: &str, base: &Path) -> Result<Lesson, Diagnostics> {
    parse_lesson_in(text, file, &Folder::on_disk(base))
}

/// Parses and validates lesson text, the files it names read from `base`.
///
/// # Errors
/// Every problem found, each with its position.
pub fn parse_lesson_in(text: &str, file: &str, base: &Folder) -> Result<Lesson, Diagnostics> {
    let raw: RawLessonFile = super::super::parse_toml(text, file)?;
    let scene = super::super::validate::scene(&raw.scene, text, file, base);
    let mut c = Checker::new(text, file);
    let meta = raw.lesson.get_ref();
    let id = meta.id.get_ref().trim().to_owned();
    if id.is_empty() {
        c.error(meta.id.span(), "`id` must not be empty");
    }
    let mut warnings = Vec::new();
    let stem = Path::new(file).file_stem().and_then(|s| s.to_str());
    if let Some(stem) = stem.filter(|s| !id.is_empty() && *s != id) {
        warnings.push(
            super::super::Diagnostic::at(
                file,
                text,
                meta.id.span(),
                format!(
                    "the id \"{id}\" differs from the file's name \"{stem}\": prerequisites name \
                     lessons by id and a reader looks for the file of that name, so keep the two the same"
                ),
            )
            .warning(),
        );
    }
    let title = c.text_of("title", &meta.title);
    let summary = c.text_of("summary", &meta.summary);
    let prerequisites = meta
        .prerequisites
        .iter()
        .map(|p| p.get_ref().clone())
        .collect();
    if raw.steps.is_empty() {
        c.error(
            raw.lesson.span(),
            "the lesson has no steps: add at least one [[steps]] with a `title` and `narration`",
        );
    }
    warnings.extend(placeholders_left(&raw, file, text));
    let mut steps = Vec::new();
    if let Ok(base_spec) = &scene {
        let mut spec = base_spec.clone();
        for s in &raw.steps {
            steps.push(c.step(s, &mut spec, base));
        }
    }
    warnings.extend(c.incomplete_languages());
    let mut found = c.found;
    let scene = match scene {
        Ok(s) => s,
        Err(Diagnostics(mut d)) => {
            d.extend(found);
            return Err(Diagnostics(d));
        }
    };
    if !found.is_empty() {
        found.sort_by_key(|d| (d.line, d.column));
        return Err(Diagnostics(found));
    }
    Ok(Lesson {
        warnings,
        comments: raw.comments.zh,
        id,
        title,
        summary,
        prerequisites,
        scene,
        steps,
    })
}

type Views = (
    Option<Stage>,
    Layout,
    Option<Comparison>,
    Option<BufferKind>,
    Option<Vec<Overlay>>,
);
type Targets = (Option<(u32, u32)>, Option<u32>, Option<[f32; 4]>);

/// The lesson's own checks, on the scene's checker: the steps are checked against the scene as
/// the steps before them left it.
impl Checker<'_> {
    pub(super) fn value(&mut self, v: &Spanned<RawValue>) -> Option<Value> {
        Some(match v.get_ref() {
            RawValue::Bool(b) => Value::Bool(*b),
            RawValue::Number(x) if x.is_finite() && x.abs() <= 1e15 => Value::Number(*x as f32),
            RawValue::Vec2(a) if a.iter().all(|x| x.is_finite() && x.abs() <= 1e15) => {
                Value::Vec2(glam::Vec2::new(a[0] as f32, a[1] as f32))
            }
            RawValue::Vec3(a) if a.iter().all(|x| x.is_finite() && x.abs() <= 1e15) => {
                Value::Vec3(glam::Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32))
            }
            RawValue::Vec4(a) if a.iter().all(|x| x.is_finite() && x.abs() <= 1e15) => Value::Vec4(
                glam::Vec4::new(a[0] as f32, a[1] as f32, a[2] as f32, a[3] as f32),
            ),
            RawValue::Name(n) => Value::Name(n.clone()),
            _ => {
                self.error(
                    v.span(),
                    "expected finite numbers of magnitude at most 1e15",
                );
                return None;
            }
        })
    }

    fn step(&mut self, s: &Spanned<RawStep>, spec: &mut SceneSpec, base: &Folder) -> Step {
        let r = s.get_ref();
        let title = self.text_of("title", &r.title);
        let narration = self.text_of("narration", &r.narration);
        let question = r.question.as_ref().map(|q| self.text_of("question", q));
        let answer = r.answer.as_ref().map(|a| self.text_of("answer", a));
        let expect = self.expect(r);
        let exercise = r.exercise.as_ref().and_then(|e| self.exercise(e, base));
        let (stage, layout, compare, buffer, overlays) = self.views(s);
        let mut set = Vec::new();
        // In the order written (a `projection.kind` before the keys of that kind).
        let mut written: Vec<_> = r.set.iter().collect();
        written.sort_by_key(|(name, _)| name.span().start);
        for (name, v) in written {
            let Some(value) = self.value(v) else { continue };
            match param::apply(spec, name.get_ref(), &value) {
                Ok(()) => set.push((name.get_ref().clone(), value)),
                Err(e) => self.error(name.span(), e),
            }
        }
        let shader = r
            .shader
            .as_ref()
            .and_then(|sh| super::super::validate::shaders::shader(self, sh, base));
        if let Some(code) = &shader {
            spec.scene.run_code(code);
        }
        let animate = r
            .animate
            .iter()
            .filter_map(|a| self.animation(a, spec))
            .collect();
        let (pixel, vertex, profile) = self.targets(r, spec);
        let focus = r.focus.as_ref().map(|names| self.focus(names, spec));
        let orbit = r.orbit.as_ref().and_then(|o| self.orbit(o));
        let watch = r.watch.as_ref().and_then(|w| self.watch(w, spec));
        let shader_lines = r
            .shader_lines
            .as_ref()
            .and_then(|l| self.shader_lines(l, spec));
        let panels = r
            .panels
            .iter()
            .flatten()
            .filter_map(|p| self.choice("panels", p, &super::StepPanel::NAMES))
            .collect();
        let depth_range = r.depth_range.as_ref().and_then(|d| {
            let [a, b] = *d.get_ref();
            if (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) && a < b {
                Some([a as f32, b as f32])
            } else {
                self.error(
                    d.span(),
                    format!("`depth_range` = [black, white] must be window depths with 0 ≤ black < white ≤ 1, got [{a}, {b}]"),
                );
                None
            }
        });
        Step {
            title,
            narration,
            stage,
            layout,
            compare,
            buffer,
            overlays,
            set,
            animate,
            pixel,
            vertex,
            profile,
            focus,
            orbit,
            depth_range,
            watch,
            shader_lines,
            panels,
            shader,
            question,
            expect,
            answer,
            exercise,
        }
    }

    /// What a step shows: stage, layout, compared settings, buffer, overlays.
    fn views(&mut self, s: &Spanned<RawStep>) -> Views {
        let r = s.get_ref();
        let stages: Vec<(String, Stage)> = Stage::ALL
            .into_iter()
            .map(|st| (st.name(Lang::EN).to_lowercase(), st))
            .collect();
        let stage_options: Vec<(&str, Stage)> =
            stages.iter().map(|(n, st)| (n.as_str(), *st)).collect();
        let stage = r
            .stage
            .as_ref()
            .and_then(|v| self.choice("stage", v, &stage_options));
        let compare_options: Vec<(&str, Comparison)> =
            Comparison::ALL.into_iter().map(|c| (c.key(), c)).collect();
        let compare = r
            .compare
            .as_ref()
            .and_then(|v| self.choice("compare", v, &compare_options));
        let layout = match &r.layout {
            Some(v) => self.choice("layout", v, &LAYOUTS).unwrap_or(Layout::Single),
            None if compare.is_some() => Layout::Compare,
            None => Layout::Single,
        };
        if let (Some(c), Some(l)) = (&r.compare, &r.layout)
            && layout != Layout::Compare
        {
            self.error(
                l.span(),
                format!(
                    "`compare = \"{}\"` shows settings side by side, which needs `layout = \"compare\"` (or no `layout`)",
                    c.get_ref()
                ),
            );
        }
        if layout == Layout::Compare && compare.is_none() {
            let span = r.layout.as_ref().map_or(s.span(), Spanned::span);
            self.error(
                span,
                "`layout = \"compare\"` needs `compare = \"shading\" | \"interpolation\" | \"samples\" | \"filtering\"`",
            );
        }
        let buffer_options: Vec<(&str, BufferKind)> =
            BufferKind::ALL.into_iter().map(|b| (b.name(), b)).collect();
        let buffer = r
            .buffer
            .as_ref()
            .and_then(|v| self.choice("buffer", v, &buffer_options));
        let overlays = r.overlays.as_ref().map(|list| {
            list.iter()
                .filter_map(|o| self.choice("overlays", o, &OVERLAYS))
                .collect()
        });
        (stage, layout, compare, buffer, overlays)
    }

    /// What a step points at: a pixel, a vertex-table row, a profile line, each inside the
    /// scene as the step leaves it.
    fn targets(&mut self, r: &RawStep, spec: &SceneSpec) -> Targets {
        let pixel = r.pixel.as_ref().and_then(|p| {
            let [x, y] = *p.get_ref();
            let (w, h) = (spec.settings.width, spec.settings.height);
            match (u32::try_from(x), u32::try_from(y)) {
                (Ok(x), Ok(y)) if x < w && y < h => Some((x, y)),
                _ => {
                    self.error(
                        p.span(),
                        format!("`pixel` must be inside the {w}×{h} viewport: 0 ≤ x < {w}, 0 ≤ y < {h} (y up), got [{x}, {y}]"),
                    );
                    None
                }
            }
        });
        let vertex = r.vertex.as_ref().and_then(|v| {
            let rows: usize = spec
                .scene
                .drawn_objects()
                .0
                .iter()
                .map(|o| o.mesh.positions.len())
                .sum();
            match usize::try_from(*v.get_ref()) {
                Ok(n) if n < rows => Some(n as u32),
                _ => {
                    self.error(
                        v.span(),
                        format!(
                            "`vertex` must be a row of the vertex table, 0 to {}, got {}",
                            rows.saturating_sub(1),
                            v.get_ref()
                        ),
                    );
                    None
                }
            }
        });
        let profile = r.profile.as_ref().and_then(|p| {
            let [a, b, c, d] = *p.get_ref();
            let (w, h) = (
                f64::from(spec.settings.width),
                f64::from(spec.settings.height),
            );
            if [a, c].iter().all(|x| (0.0..w).contains(x))
                && [b, d].iter().all(|y| (0.0..h).contains(y))
            {
                Some([a as f32, b as f32, c as f32, d as f32])
            } else {
                self.error(
                    p.span(),
                    format!(
                        "`profile` = [x0, y0, x1, y1] must lie inside the {w}×{h} image (y down)"
                    ),
                );
                None
            }
        });
        (pixel, vertex, profile)
    }

    /// A step's `shader_lines = [first, last]` (or `[line]`): lines of the fragment shader
    /// the scene runs at this step, the first not after the last.
    fn shader_lines(&mut self, l: &Spanned<Vec<i64>>, spec: &SceneSpec) -> Option<(usize, usize)> {
        let lines = spec
            .scene
            .objects
            .iter()
            .find_map(|o| o.code.shader.as_ref())
            .map(|sh| sh.programs.fragment.source.lines().count());
        let Some(count) = lines else {
            self.error(
                l.span(),
                "`shader_lines`: no object runs a shader of the student's at this step",
            );
            return None;
        };
        let (first, last) = match l.get_ref().as_slice() {
            [a] => (*a, *a),
            [a, b] => (*a, *b),
            _ => {
                self.error(l.span(), "`shader_lines` is [first, last] or [line]");
                return None;
            }
        };
        if first < 1 || first > last || last > count as i64 {
            self.error(
                l.span(),
                format!("`shader_lines` = [{first}, {last}] must be lines 1 to {count} of the fragment shader, the first not after the last"),
            );
            return None;
        }
        Some((first as usize, last as usize))
    }

    /// A step's watch, `"EXPR@LINE"` (or `"EXPR@vertex:LINE"`): read, and compiled against
    /// the shaders the scene runs at this step.
    fn watch(
        &mut self,
        w: &Spanned<String>,
        spec: &SceneSpec,
    ) -> Option<pipeline::shader::probe::WatchSpec> {
        let parsed = pipeline::shader::probe::parse(w.get_ref())
            .map_err(|e| format!("`watch`: {e}"))
            .and_then(|watch| {
                spec.scene
                    .watching(&watch)
                    .map(|_| watch)
                    .map_err(|e| format!("`watch`: {e}"))
            });
        match parsed {
            Ok(w) => Some(w),
            Err(e) => {
                self.error(w.span(), e);
                None
            }
        }
    }

    /// The names a step frames: each an object or a figure of the scene as the step leaves it.
    /// The observer's direction `[yaw, pitch]`: any finite yaw, a pitch strictly between −90°
    /// and 90° (at ±90° the orbit's camera would look along its own up vector).
    fn orbit(&mut self, o: &Spanned<[f64; 2]>) -> Option<[f32; 2]> {
        let [yaw, pitch] = *o.get_ref();
        if yaw.is_finite() && pitch.is_finite() && pitch.abs() < 90.0 {
            return Some([yaw as f32, pitch as f32]);
        }
        self.error(
            o.span(),
            format!("`orbit` = [yaw, pitch] in degrees needs a finite yaw and −90 < pitch < 90, got [{yaw}, {pitch}]"),
        );
        None
    }

    fn focus(&mut self, names: &[Spanned<String>], spec: &SceneSpec) -> Vec<String> {
        let known: Vec<&str> = spec
            .scene
            .objects
            .iter()
            .map(|o| o.name.as_str())
            .chain(spec.scene.figures.iter().map(|f| f.name.as_str()))
            .chain([crate::spaces::CAMERA])
            .collect();
        names
            .iter()
            .filter_map(|n| {
                let name = n.get_ref();
                if known.contains(&name.as_str()) {
                    return Some(name.clone());
                }
                let hint = pipeline::shader::suggest::did_you_mean(
                    name,
                    known.iter().copied(),
                    pipeline::shader::suggest::Quote::Value,
                );
                self.error(
                    n.span(),
                    format!(
                        "`focus` names objects or figures of the scene ({}), got \"{name}\"{hint}",
                        known
                            .iter()
                            .map(|k| format!("\"{k}\""))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                );
                None
            })
            .collect()
    }
}
