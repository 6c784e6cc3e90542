//! The second tier: resolves what the file says into a scene, checking every range and
//! reference, and collecting every problem with its position (not just the first).
//!
//! The checker and the scene as a whole are here; `[scene.render]` and `[scene.projection]` in
//! [`render`]; objects, meshes, materials and textures in [`objects`]; lights, the planar shadow
//! and figures in [`lights`].

mod lights;
mod objects;
mod render;
pub mod shaders;
mod shapes;

use super::folder::{File, Folder};
use std::ops::Range;

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::lighting::{Frequency, Reflection};
use pipeline::mesh::NormalAveraging;
use pipeline::raster::{CullMode, DepthTest};
use pipeline::scene::Scene;
use pipeline::settings::RenderSettings;
use pipeline::texture::{Filter, Mipmap, Wrap};
use toml::Spanned;

use super::raw::{RawScale, RawScene, RawText, RawVec3};
use super::{Diagnostic, Diagnostics, SceneSpec};
use crate::vocabulary::Text;

/// The names of `cull` in files.
pub(super) const CULL: &[(&str, CullMode)] = &[
    ("none", CullMode::None),
    ("back", CullMode::Back),
    ("front", CullMode::Front),
];

/// The names of `depth_test` in files.
pub(super) const DEPTH_TEST: &[(&str, DepthTest)] = &[
    ("less", DepthTest::Less),
    ("less_equal", DepthTest::LessEqual),
    ("greater", DepthTest::Greater),
    ("greater_equal", DepthTest::GreaterEqual),
    ("always", DepthTest::Always),
];

/// The names of `shading` in files.
pub(super) const SHADING: &[(&str, Frequency)] = &[
    ("unlit", Frequency::Unlit),
    ("flat", Frequency::Flat),
    ("gouraud", Frequency::Gouraud),
    ("phong", Frequency::Phong),
];

/// The names of `reflection` in files.
pub(super) const REFLECTION: &[(&str, Reflection)] = &[
    ("phong", Reflection::Phong),
    ("blinn_phong", Reflection::BlinnPhong),
];

/// The names of `mipmap` in files.
pub(super) const MIPMAP: &[(&str, Mipmap)] = &[
    ("none", Mipmap::None),
    ("nearest", Mipmap::Nearest),
    ("linear", Mipmap::Linear),
    ("ripmap", Mipmap::Ripmap),
    ("summed_area", Mipmap::SummedArea),
    ("ewa", Mipmap::Ewa),
];

/// The names of `filter` in files.
pub(super) const FILTER: &[(&str, Filter)] =
    &[("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)];

/// The names of `normals` in files: how vertex normals are made from the faces around them.
pub(crate) const NORMALS: &[(&str, NormalAveraging)] = &[
    ("average", NormalAveraging::Plain),
    ("area_weighted", NormalAveraging::AreaWeighted),
];

/// The names of `wrap` in files.
pub(super) const WRAP: &[(&str, Wrap)] = &[("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp)];

/// Collects diagnostics against one source text (the scene's checks here, the lesson's in
/// `script`).
pub(super) struct Checker<'a> {
    pub(super) text: &'a str,
    pub(super) file: &'a str,
    pub(super) found: Vec<Diagnostic>,
    /// Each text read: where it is, its key, and the languages it gives beyond `en` and `zh`.
    pub(super) texts: Vec<(Range<usize>, String, Vec<String>)>,
}

impl<'a> Checker<'a> {
    /// Text in both languages, neither empty.
    pub(in crate::lesson) fn text_of(&mut self, key: &str, t: &Spanned<RawText>) -> Text {
        let r = t.get_ref();
        if r.en.trim().is_empty() || r.zh.trim().is_empty() {
            self.error(
                t.span(),
                format!("`{key}` needs both `en` and `zh` text, neither empty"),
            );
        }
        let mut text = r.text();
        for tag in r.others.keys() {
            if tag.parse::<unic_langid::LanguageIdentifier>().is_err() {
                self.error(
                    t.span(),
                    format!(
                        "`{key}` has `{tag}`, which is not a language tag: a text takes `en`, `zh` and other languages by their BCP 47 tags (`fr`, `pt-BR`)"
                    ),
                );
                text.others.remove(tag);
            }
        }
        self.texts.push((
            t.span(),
            key.to_owned(),
            text.others.keys().cloned().collect(),
        ));
        text
    }

    /// A warning for each language beyond English and Chinese that some of the lesson's texts
    /// give and others lack (those are shown in English): at the first text that lacks it.
    pub(in crate::lesson) fn incomplete_languages(&self) -> Vec<Diagnostic> {
        let mut tags: Vec<&String> = self.texts.iter().flat_map(|(_, _, t)| t).collect();
        tags.sort_unstable();
        tags.dedup();
        tags.into_iter()
            .filter_map(|tag| {
                let lacking: Vec<&(Range<usize>, String, Vec<String>)> =
                    self.texts.iter().filter(|(_, _, t)| !t.contains(tag)).collect();
                let (span, key, _) = lacking.first()?;
                Some(
                    Diagnostic::at(
                        self.file,
                        self.text,
                        span.clone(),
                        format!(
                            "the language `{tag}` is incomplete: {} of the lesson's {} texts lack it, the first this `{key}` (a text without it is shown in English)",
                            lacking.len(),
                            self.texts.len()
                        ),
                    )
                    .warning(),
                )
            })
            .collect()
    }

    /// A checker of `text`, named `file` in messages, with nothing found yet.
    pub(super) fn new(text: &'a str, file: &'a str) -> Self {
        Self {
            text,
            file,
            found: Vec::new(),
            texts: Vec::new(),
        }
    }

    pub(super) fn error(&mut self, span: Range<usize>, message: impl Into<String>) {
        self.found
            .push(Diagnostic::at(self.file, self.text, span, message));
    }

    /// The 1-based line of byte `at`.
    pub(super) fn line_of(&self, at: usize) -> usize {
        Diagnostic::at(self.file, self.text, at..at, "").line
    }

    /// The file `written` names, read from `base` (the lesson's folder, or the files a page
    /// was given); if there is none, a diagnostic saying where it was looked for, the rule, and
    /// a similar name there if there is one.
    pub(super) fn read_beside(
        &mut self,
        span: Range<usize>,
        base: &Folder,
        written: &str,
    ) -> Option<File> {
        base.read(written).map_err(|e| self.error(span, e)).ok()
    }

    /// A finite number, else a diagnostic naming the key.
    fn finite(&mut self, key: &str, v: &Spanned<f64>) -> Option<f32> {
        let x = *v.get_ref();
        if x.is_finite() && x.abs() <= f64::from(f32::MAX) {
            Some(x as f32)
        } else {
            self.error(
                v.span(),
                format!("`{key}` must be a finite number, got {x}"),
            );
            None
        }
    }

    fn vec3(&mut self, key: &str, v: &RawVec3) -> Option<Vec3> {
        let [x, y, z] = *v.get_ref();
        if [x, y, z].iter().all(|c| c.is_finite() && c.abs() <= 1e15) {
            Some(Vec3::new(x as f32, y as f32, z as f32))
        } else {
            self.error(
                v.span(),
                format!("`{key}` must be three finite numbers of magnitude at most 1e15, got [{x}, {y}, {z}]"),
            );
            None
        }
    }

    /// The option named by `v`, else a diagnostic listing the names.
    pub(super) fn choice<T: Copy>(
        &mut self,
        key: &str,
        v: &Spanned<String>,
        options: &[(&str, T)],
    ) -> Option<T> {
        let found = options
            .iter()
            .find(|(name, _)| *name == v.get_ref().as_str());
        if found.is_none() {
            let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
            self.error(
                v.span(),
                format!(
                    "`{key}` must be one of {}, got \"{}\"",
                    names.join(", "),
                    v.get_ref()
                ),
            );
        }
        found.map(|(_, t)| *t)
    }
}

/// Validates `[scene]` into a renderable scene.
///
/// # Errors
/// Every problem found.
pub fn scene(
    raw: &Spanned<RawScene>,
    text: &str,
    file: &str,
    base: &Folder,
) -> Result<SceneSpec, Diagnostics> {
    let mut c = Checker::new(text, file);
    let s = raw.get_ref();
    let mut camera = Camera::default();
    if let Some(cam) = &s.camera {
        let cam_ref = cam.get_ref();
        for (key, v, slot) in [
            ("eye", &cam_ref.eye, &mut camera.eye),
            ("at", &cam_ref.at, &mut camera.at),
            ("up", &cam_ref.up, &mut camera.up),
        ] {
            if let Some(v) = v.as_ref().and_then(|v| c.vec3(key, v)) {
                *slot = v;
            }
        }
        if let Err(e) = pipeline::transform::camera_frame(camera.eye, camera.at, camera.up) {
            c.error(cam.span(), format!("the camera is degenerate: {e}"));
        }
    }
    let settings = s
        .render
        .as_ref()
        .map_or_else(RenderSettings::default, |r| render::render(&mut c, r));
    let projection = s
        .projection
        .as_ref()
        .map_or_else(Projection::default, |p| render::projection(&mut c, p));
    if s.objects.is_empty() {
        c.error(
            raw.span().start..raw.span().start,
            "the scene has no objects: add at least one [[scene.objects]] with a `mesh`",
        );
    }
    let mut labels = std::collections::BTreeMap::new();
    let objects = s
        .objects
        .iter()
        .enumerate()
        .filter_map(|(i, o)| objects::object(&mut c, o, i, base))
        .map(|(o, label)| {
            if let Some(l) = label {
                labels.insert(o.name.clone(), l);
            }
            o
        })
        .collect();
    let lights = s
        .lights
        .iter()
        .filter_map(|l| lights::light(&mut c, l))
        .collect();
    let mut objects: Vec<pipeline::scene::Object> = objects;
    // The values of the shaders' own uniforms: each object's shader's, then the scene's.
    let mut uniforms: std::collections::BTreeMap<String, Vec<f32>> = objects
        .iter()
        .flat_map(|o| o.code.uniforms.clone())
        .collect();
    if let Some(code) = s
        .shader
        .as_ref()
        .and_then(|sh| shaders::shader(&mut c, sh, base))
    {
        shaders::give(&mut objects, &code);
        uniforms.extend(code.uniforms);
    }
    let light_names = lights::names(&mut c, &s.lights);
    let shadow = s.shadow.as_ref().and_then(|sh| lights::shadow(&mut c, sh));
    let figures = s
        .figures
        .iter()
        .filter_map(|f| lights::figure(&mut c, f))
        .map(|(f, label)| {
            if let Some(l) = label {
                labels.insert(f.name.clone(), l);
            }
            f
        })
        .collect();
    if c.found.is_empty() {
        Ok(SceneSpec {
            scene: Scene {
                uniforms,
                objects,
                camera,
                projection,
                lights,
                shadow,
                figures,
            },
            settings,
            labels,
            light_names,
        })
    } else {
        Err(Diagnostics(c.found))
    }
}

/// One number or three, each finite and not negative, as a colour-like triple.
pub(super) fn triple(c: &mut Checker<'_>, key: &str, v: &Spanned<RawScale>) -> Option<Vec3> {
    let a = match *v.get_ref() {
        RawScale::Uniform(k) => [k; 3],
        RawScale::Axes(a) => a,
    };
    let t = c.vec3(key, &Spanned::new(v.span(), a))?;
    if t.min_element() < 0.0 {
        c.error(v.span(), format!("`{key}` must not be negative"));
        return None;
    }
    Some(t)
}
