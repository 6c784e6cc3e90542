//! The second tier: resolves what the file says into a scene, checking every range and
//! reference, and collecting every problem with its position (not just the first).

use std::ops::Range;
use std::path::Path;

use glam::Vec3;
use pipeline::camera::{Camera, Projection};
use pipeline::hierarchy::{Figure, Humanoid, Pose, RobotArm};
use pipeline::light::{Light, Material};
use pipeline::mesh::{BuiltinMesh, Mesh};
use pipeline::raster::{CullMode, DepthTest, Samples};
use pipeline::scene::{ColorSource, Object, PlanarShadow, Scene};
use pipeline::settings::{MAX_VIEWPORT_SIDE, RenderSettings};
use pipeline::shade::{Frequency, Reflection};
use pipeline::texture::{
    CubeMap, Displacement, Environment, Filter, Mipmap, SurfaceDetail, Texture, Wrap,
};
use toml::Spanned;

use super::raw::{
    RawColor, RawFigure, RawLight, RawMaterial, RawMesh, RawMeshTable, RawObject, RawProjection,
    RawRender, RawScale, RawScene, RawShadow, RawVec3,
};
use super::{Diagnostic, Diagnostics, SceneSpec};

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
];

/// The names of `filter` in files.
pub(super) const FILTER: &[(&str, Filter)] =
    &[("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)];

/// The names of `wrap` in files.
pub(super) const WRAP: &[(&str, Wrap)] = &[("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp)];

/// Collects diagnostics against one source text (the scene's checks here, the lesson's in
/// `script`).
pub(super) struct Checker<'a> {
    pub(super) text: &'a str,
    pub(super) file: &'a str,
    pub(super) found: Vec<Diagnostic>,
}

impl<'a> Checker<'a> {
    /// A checker of `text`, named `file` in messages, with nothing found yet.
    pub(super) fn new(text: &'a str, file: &'a str) -> Self {
        Self {
            text,
            file,
            found: Vec::new(),
        }
    }

    pub(super) fn error(&mut self, span: Range<usize>, message: impl Into<String>) {
        self.found
            .push(Diagnostic::at(self.file, self.text, span, message));
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
    base: &Path,
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
        .map_or_else(RenderSettings::default, |r| render(&mut c, r));
    let projection = s
        .projection
        .as_ref()
        .map_or_else(Projection::default, |p| projection(&mut c, p));
    if s.objects.is_empty() {
        c.error(
            raw.span().start..raw.span().start,
            "the scene has no objects: add at least one [[scene.objects]] with a `mesh`",
        );
    }
    let objects = s
        .objects
        .iter()
        .enumerate()
        .filter_map(|(i, o)| object(&mut c, o, i, base))
        .collect();
    let lights = s.lights.iter().filter_map(|l| light(&mut c, l)).collect();
    let shadow = s.shadow.as_ref().and_then(|sh| shadow(&mut c, sh));
    let figures = s.figures.iter().filter_map(|f| figure(&mut c, f)).collect();
    if c.found.is_empty() {
        Ok(SceneSpec {
            scene: Scene {
                objects,
                camera,
                projection,
                lights,
                shadow,
                figures,
            },
            settings,
        })
    } else {
        Err(Diagnostics(c.found))
    }
}

fn render(c: &mut Checker<'_>, r: &Spanned<RawRender>) -> RenderSettings {
    let raw = r.get_ref();
    let mut s = RenderSettings::default();
    for (key, v, slot) in [
        ("width", &raw.width, &mut s.width),
        ("height", &raw.height, &mut s.height),
    ] {
        if let Some(v) = v {
            match u32::try_from(*v.get_ref()) {
                Ok(n) if (1..=MAX_VIEWPORT_SIDE).contains(&n) => *slot = n,
                _ => c.error(
                    v.span(),
                    format!("`{key}` must be a whole number of pixels from 1 to {MAX_VIEWPORT_SIDE}, got {}", v.get_ref()),
                ),
            }
        }
    }
    if let Some(v) = &raw.samples {
        match u32::try_from(*v.get_ref())
            .ok()
            .and_then(Samples::from_count)
        {
            Some(n) => s.samples = n,
            None => c.error(
                v.span(),
                format!("`samples` must be 1, 4, 8 or 16, got {}", v.get_ref()),
            ),
        }
    }
    if let Some(p) = s.capture_problem() {
        c.error(r.span(), p);
    }
    render_modes(c, raw, &mut s);
    sampler(c, raw, &mut s);
    if let Some(v) = &raw.background
        && let Some(bg) = c.vec3("background", v)
    {
        if bg.min_element() < 0.0 || bg.max_element() > 1.0 {
            c.error(v.span(), "`background` components must be between 0 and 1");
        }
        s.background = bg;
    }
    s
}

/// The named choices of `[scene.render]`: culling, depth test, interpolation, lighting.
fn render_modes(c: &mut Checker<'_>, raw: &RawRender, s: &mut RenderSettings) {
    if let Some(v) = &raw.cull {
        s.cull = c.choice("cull", v, CULL).unwrap_or_default();
    }
    if let Some(v) = &raw.depth_test {
        s.depth_test = c.choice("depth_test", v, DEPTH_TEST).unwrap_or_default();
    }
    if let Some(b) = raw.perspective_correct {
        s.perspective_correct = b;
    }
    if let Some(b) = raw.per_sample_shading {
        s.per_sample_shading = b;
    }
    if let Some(v) = &raw.shading {
        s.shading = c.choice("shading", v, SHADING).unwrap_or_default();
    }
    if let Some(v) = &raw.reflection {
        s.reflection = c.choice("reflection", v, REFLECTION).unwrap_or_default();
    }
}

fn projection(c: &mut Checker<'_>, p: &Spanned<RawProjection>) -> Projection {
    let raw = p.get_ref();
    let kind = raw
        .kind
        .as_ref()
        .map_or("perspective", |k| k.get_ref().as_str());
    let before = c.found.len();
    let mut num = |key: &str, v: &Option<Spanned<f64>>| v.as_ref().and_then(|v| c.finite(key, v));
    let fovy = num("fovy", &raw.fovy);
    let aspect = num("aspect", &raw.aspect);
    let near = num("near", &raw.near);
    let far = num("far", &raw.far);
    let sides = [
        num("left", &raw.left),
        num("right", &raw.right),
        num("bottom", &raw.bottom),
        num("top", &raw.top),
    ];
    let side_spans = [&raw.left, &raw.right, &raw.bottom, &raw.top];
    let projection = match kind {
        "perspective" => {
            for (key, v) in ["left", "right", "bottom", "top"].iter().zip(side_spans) {
                if let Some(v) = v {
                    c.error(
                        v.span(),
                        format!("`{key}` belongs to kind = \"frustum\" or \"ortho\"; a perspective projection is given by fovy, aspect, near, far"),
                    );
                }
            }
            Projection::Perspective {
                fovy_deg: fovy.unwrap_or(45.0),
                aspect,
                near: near.unwrap_or(0.1),
                far: far.unwrap_or(50.0),
            }
        }
        "frustum" | "ortho" => {
            for (key, v) in [("fovy", &raw.fovy), ("aspect", &raw.aspect)] {
                if let Some(v) = v {
                    c.error(
                        v.span(),
                        format!("`{key}` belongs to kind = \"perspective\""),
                    );
                }
            }
            let missing: Vec<&str> = ["left", "right", "bottom", "top"]
                .iter()
                .zip(side_spans)
                .filter(|(_, v)| v.is_none())
                .map(|(k, _)| *k)
                .collect();
            if !missing.is_empty() {
                c.error(
                    p.span(),
                    format!(
                        "a {kind} projection needs left, right, bottom and top; missing: {}",
                        missing.join(", ")
                    ),
                );
            }
            let [l, r, b, t] = sides.map(|v| v.unwrap_or(0.0));
            let (near, far) = (near.unwrap_or(0.1), far.unwrap_or(50.0));
            if kind == "frustum" {
                Projection::Frustum {
                    left: l,
                    right: r,
                    bottom: b,
                    top: t,
                    near,
                    far,
                }
            } else {
                Projection::Ortho {
                    left: l,
                    right: r,
                    bottom: b,
                    top: t,
                    near,
                    far,
                }
            }
        }
        other => {
            let span = raw.kind.as_ref().map_or(p.span(), Spanned::span);
            c.error(
                span,
                format!(
                    "`kind` must be \"perspective\", \"frustum\" or \"ortho\", got \"{other}\""
                ),
            );
            Projection::default()
        }
    };
    if c.found.len() == before {
        report_ranges(c, p, &projection);
    }
    projection
}

/// Reports the projection's range problems, each pointed at the value that breaks it.
fn report_ranges(c: &mut Checker<'_>, p: &Spanned<RawProjection>, projection: &Projection) {
    let raw = p.get_ref();
    for problem in projection.problems() {
        let value = match problem.split_whitespace().next().unwrap_or("") {
            "fovy" => &raw.fovy,
            "aspect" => &raw.aspect,
            "near" => &raw.near,
            "far" => &raw.far,
            "left" => &raw.left,
            "bottom" => &raw.bottom,
            _ => &None,
        };
        c.error(value.as_ref().map_or(p.span(), Spanned::span), problem);
    }
}

fn object(
    c: &mut Checker<'_>,
    o: &Spanned<RawObject>,
    index: usize,
    base: &Path,
) -> Option<Object> {
    let raw = o.get_ref();
    let (mesh, source) = mesh(c, &raw.mesh, base)?;
    let name = raw
        .name
        .as_ref()
        .map_or_else(|| format!("{}#{index}", mesh.name), |n| n.get_ref().clone());
    let mut object = Object::new(&name, mesh);
    object.builtin = source;
    if let Some(v) = raw.translate.as_ref().and_then(|v| c.vec3("translate", v)) {
        object.translate = v;
    }
    if let Some(v) = raw.rotate.as_ref().and_then(|v| c.vec3("rotate", v)) {
        object.rotate_deg = v;
    }
    if let Some(r) = &raw.rotate_axis {
        let r = r.get_ref();
        if let (Some(axis), Some(angle)) = (c.vec3("axis", &r.axis), c.finite("angle", &r.angle)) {
            if axis.length() < 1e-6 {
                c.error(
                    r.axis.span(),
                    "`axis` must not be the zero vector: it gives the direction to rotate about",
                );
            }
            object.axis_rotation = Some((axis, angle));
        }
    }
    if let Some(s) = &raw.scale {
        let v = match *s.get_ref() {
            RawScale::Uniform(k) => [k; 3],
            RawScale::Axes(a) => a,
        };
        if let Some(v) = c.vec3("scale", &Spanned::new(s.span(), v)) {
            if v.cmpeq(Vec3::ZERO).any() {
                c.error(s.span(), "`scale` must not be zero in any axis (the object would be flattened to nothing)");
            }
            object.scale = v;
        }
    }
    if let Some(m) = &raw.material {
        object.material = material(c, m);
    }
    if let Some(b) = raw.casts_shadow {
        object.casts_shadow = b;
    }
    surface_maps(c, o, &mut object, base);
    if let Some(col) = &raw.color {
        object.color = match col.get_ref() {
            RawColor::Named(n) if n == "vertex" => ColorSource::Vertex,
            RawColor::Named(n) if n == "normal" => ColorSource::Normal,
            RawColor::Named(n) => {
                c.error(
                    col.span(),
                    format!("`color` must be \"vertex\", \"normal\" or [r, g, b], got \"{n}\""),
                );
                ColorSource::Vertex
            }
            RawColor::Rgb(rgb) => {
                let v = c
                    .vec3("color", &Spanned::new(col.span(), *rgb))
                    .unwrap_or(Vec3::ONE);
                if v.min_element() < 0.0 || v.max_element() > 1.0 {
                    c.error(col.span(), "`color` components must be between 0 and 1");
                }
                ColorSource::Uniform(v)
            }
        };
    }
    Some(object)
}

/// Bump, normal and displacement maps of an object.
fn surface_maps(c: &mut Checker<'_>, o: &Spanned<RawObject>, object: &mut Object, base: &Path) {
    let raw = o.get_ref();
    if let Some(bump) = &raw.bump {
        let b = bump.get_ref();
        let strength = b
            .strength
            .as_ref()
            .and_then(|v| c.finite("strength", v))
            .unwrap_or(1.0);
        object.detail = texture(c, &b.texture, base).map(|t| SurfaceDetail::Bump {
            height: std::sync::Arc::new(t),
            strength,
        });
    }
    if let Some(map) = &raw.normal_map {
        if raw.bump.is_some() {
            c.error(
                map.span(),
                "an object takes `bump` or `normal_map`, not both",
            );
        }
        object.detail =
            texture(c, map, base).map(|t| SurfaceDetail::Normal(std::sync::Arc::new(t)));
    }
    if let Some(d) = &raw.displacement {
        let d = d.get_ref();
        let scale = d
            .scale
            .as_ref()
            .and_then(|v| c.finite("scale", v))
            .unwrap_or(0.1);
        object.displacement = texture(c, &d.texture, base).map(|t| Displacement {
            height: std::sync::Arc::new(t),
            scale,
        });
    }
    if let Some(e) = &raw.environment {
        let e = e.get_ref();
        if e.cube.get_ref() != "room" {
            c.error(
                e.cube.span(),
                format!(
                    "`cube` must be \"room\" (the built-in cube map), got \"{}\"",
                    e.cube.get_ref()
                ),
            );
        }
        let k = e
            .reflectivity
            .as_ref()
            .and_then(|v| c.finite("reflectivity", v))
            .unwrap_or(0.5);
        if !(0.0..=1.0).contains(&k) {
            let span = e.reflectivity.as_ref().map_or(o.span(), Spanned::span);
            c.error(
                span,
                format!("`reflectivity` must be between 0 and 1, got {k}"),
            );
        }
        object.environment = Some(Environment {
            cube: std::sync::Arc::new(CubeMap::room(256)),
            reflectivity: k,
        });
    }
    if (object.detail.is_some() || object.displacement.is_some()) && object.mesh.uvs.is_empty() {
        c.error(
            o.span(),
            format!(
                "the mesh `{}` has no texture coordinates for bump or normal mapping",
                object.mesh.name
            ),
        );
    }
    if let Some(t) = &raw.texture {
        object.texture = texture(c, t, base).map(std::sync::Arc::new);
        if object.texture.is_some() && object.mesh.uvs.is_empty() {
            c.error(
                t.span(),
                format!(
                    "the mesh `{}` has no texture coordinates to map a texture with",
                    object.mesh.name
                ),
            );
        }
    }
}

/// The mesh, and how it was generated when built in.
fn mesh(
    c: &mut Checker<'_>,
    m: &Spanned<RawMesh>,
    base: &Path,
) -> Option<(Mesh, Option<BuiltinMesh>)> {
    let span = m.span();
    let table = match m.get_ref() {
        RawMesh::Name(n) if n.to_ascii_lowercase().ends_with(".obj") => {
            return load_obj(c, span, &base.join(n)).map(|m| (m, None));
        }
        RawMesh::Name(n) => &RawMeshTable {
            builtin: Some(n.clone()),
            obj: None,
            segments: None,
            rings: None,
            divisions: None,
            sides: None,
            minor: None,
            repeat: None,
            points: None,
            t: None,
        },
        RawMesh::Table(t) => t,
    };
    match (&table.builtin, &table.obj) {
        (Some(_), Some(_)) | (None, None) => {
            c.error(
                span,
                "a mesh table needs exactly one of `builtin = \"…\"` or `obj = \"path.obj\"`",
            );
            None
        }
        (None, Some(path)) => load_obj(c, span, &base.join(path)).map(|m| (m, None)),
        (Some(name), None) => builtin(c, span, name, table).map(|b| (b.build(), Some(b))),
    }
}

/// `{ builtin = "bezier", points = [[x, y] × 4], t = … }`.
fn bezier(c: &mut Checker<'_>, span: Range<usize>, t: &RawMeshTable) -> Option<BuiltinMesh> {
    let points = t.points.as_deref().unwrap_or(&[]);
    let finite = points
        .iter()
        .flatten()
        .all(|v| v.is_finite() && v.abs() <= 1e6);
    let [a, b, d, e] = points else {
        c.error(
            span,
            format!(
                "a bezier mesh needs `points` = four control points [[x, y], …], got {}",
                points.len()
            ),
        );
        return None;
    };
    if !finite {
        c.error(
            span,
            "the control points must be finite numbers of magnitude at most 1e6",
        );
        return None;
    }
    let param = t.t.unwrap_or(1.0);
    if !(0.0..=1.0).contains(&param) {
        c.error(
            span,
            format!("`t` of a bezier mesh must be from 0 to 1, got {param}"),
        );
        return None;
    }
    let v = |p: &[f64; 2]| glam::Vec2::new(p[0] as f32, p[1] as f32);
    Some(BuiltinMesh::Bezier {
        points: [v(a), v(b), v(d), v(e)],
        t: param as f32,
    })
}

fn load_obj(c: &mut Checker<'_>, span: Range<usize>, path: &Path) -> Option<Mesh> {
    match Mesh::load_obj(path) {
        Ok(m) => Some(m),
        Err(e) => {
            c.error(span, e.to_string());
            None
        }
    }
}

fn builtin(
    c: &mut Checker<'_>,
    span: Range<usize>,
    name: &str,
    t: &RawMeshTable,
) -> Option<BuiltinMesh> {
    let minor = match t.minor {
        None => 0.35,
        Some(v) if v > 0.0 && v < 1.0 => v as f32,
        Some(v) => {
            c.error(
                span.clone(),
                format!("`minor` of a torus must be between 0 and 1 (exclusive), got {v}"),
            );
            0.35
        }
    };
    let repeat = match t.repeat {
        None => 1.0,
        Some(v) if v > 0.0 && v <= 1e4 => v as f32,
        Some(v) => {
            c.error(
                span.clone(),
                format!("`repeat` of a plane must be between 0 (exclusive) and 10000, got {v}"),
            );
            1.0
        }
    };
    let mut count = |key: &str, v: Option<i64>, default: u32, min: u32, max: u32| -> u32 {
        match v {
            None => default,
            Some(n) if (i64::from(min)..=i64::from(max)).contains(&n) => n as u32,
            Some(n) => {
                c.error(
                    span.clone(),
                    format!("`{key}` of a {name} must be from {min} to {max}, got {n}"),
                );
                default
            }
        }
    };
    let mesh = match name {
        "triangle" => BuiltinMesh::Triangle,
        "two_triangles" => BuiltinMesh::TwoTriangles,
        "cube" => BuiltinMesh::Cube,
        "uv_sphere" | "sphere" => BuiltinMesh::UvSphere {
            segments: count("segments", t.segments, 32, 3, 4096),
            rings: count("rings", t.rings, 16, 2, 4096),
        },
        "plane" => BuiltinMesh::Plane {
            divisions: count("divisions", t.divisions, 1, 1, 4096),
            repeat,
        },
        "cylinder" => BuiltinMesh::Cylinder {
            segments: count("segments", t.segments, 32, 3, 4096),
        },
        "torus" => BuiltinMesh::Torus {
            minor,
            segments: count("segments", t.segments, 48, 3, 4096),
            sides: count("sides", t.sides, 24, 3, 4096),
        },
        "bezier" => bezier(c, span.clone(), t)?,
        other => {
            let suggestion = BuiltinMesh::NAMES
                .iter()
                .min_by_key(|n| strsim::damerau_levenshtein(other, n))
                .filter(|n| strsim::damerau_levenshtein(other, n) <= 3)
                .map(|n| format!("; did you mean \"{n}\"?"))
                .unwrap_or_default();
            c.error(
                span,
                format!(
                    "unknown built-in mesh \"{other}\" (expected one of {}, or a path ending in .obj){suggestion}",
                    BuiltinMesh::NAMES.map(|n| format!("\"{n}\"")).join(", ")
                ),
            );
            return None;
        }
    };
    // Refuse a shape too large to build before building it (4096 × 4096 rings and segments
    // would be 33 million triangles).
    let triangles: u64 = match mesh {
        BuiltinMesh::UvSphere { segments, rings } => 2 * u64::from(segments) * u64::from(rings),
        BuiltinMesh::Plane { divisions, .. } => 2 * u64::from(divisions).pow(2),
        BuiltinMesh::Torus {
            segments, sides, ..
        } => 2 * u64::from(segments) * u64::from(sides),
        BuiltinMesh::Cylinder { segments } => 4 * u64::from(segments),
        _ => 0,
    };
    if triangles > MAX_BUILTIN_TRIANGLES {
        c.error(
            span,
            format!(
                "this {name} would have {triangles} triangles; a built-in mesh may have at most {MAX_BUILTIN_TRIANGLES}"
            ),
        );
        return None;
    }
    Some(mesh)
}

/// The most triangles a built-in mesh may be made of.
const MAX_BUILTIN_TRIANGLES: u64 = 4_000_000;

/// One number or three, each finite and not negative, as a colour-like triple.
fn triple(c: &mut Checker<'_>, key: &str, v: &Spanned<RawScale>) -> Option<Vec3> {
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

fn material(c: &mut Checker<'_>, m: &Spanned<RawMaterial>) -> Material {
    let raw = m.get_ref();
    let mut out = Material::default();
    for (key, v, slot) in [
        ("ka", &raw.ka, &mut out.ka),
        ("kd", &raw.kd, &mut out.kd),
        ("ks", &raw.ks, &mut out.ks),
    ] {
        if let Some(t) = v.as_ref().and_then(|v| triple(c, key, v)) {
            *slot = t;
        }
    }
    if let Some(v) = &raw.shininess
        && let Some(x) = c.finite("shininess", v)
    {
        if x < 0.0 {
            c.error(
                v.span(),
                format!("`shininess` must not be negative, got {x}"),
            );
        }
        out.shininess = x;
    }
    out
}

fn light(c: &mut Checker<'_>, l: &Spanned<RawLight>) -> Option<Light> {
    let raw = l.get_ref();
    let intensity = raw
        .intensity
        .as_ref()
        .and_then(|v| triple(c, "intensity", v))
        .unwrap_or(Vec3::ONE);
    let attenuation = raw
        .attenuation
        .as_ref()
        .and_then(|v| c.vec3("attenuation", v))
        .unwrap_or(Vec3::X);
    let needs = |c: &mut Checker<'_>, key: &str, v: &Option<RawVec3>| -> Option<Vec3> {
        match v {
            Some(v) => c.vec3(key, v),
            None => {
                c.error(
                    l.span(),
                    format!("a {} light needs `{key}`", raw.kind.get_ref()),
                );
                None
            }
        }
    };
    match raw.kind.get_ref().as_str() {
        "ambient" => Some(Light::Ambient { intensity }),
        "point" => Some(Light::Point {
            position: needs(c, "position", &raw.position)?,
            intensity,
            attenuation,
        }),
        "directional" => Some(Light::Directional {
            direction: needs(c, "direction", &raw.direction)?,
            intensity,
        }),
        "spot" => {
            let position = needs(c, "position", &raw.position)?;
            let direction = needs(c, "direction", &raw.direction)?;
            let cutoff = raw
                .cutoff
                .as_ref()
                .and_then(|v| c.finite("cutoff", v))
                .unwrap_or(30.0);
            if !(cutoff > 0.0 && cutoff <= 90.0) {
                let span = raw.cutoff.as_ref().map_or(l.span(), Spanned::span);
                c.error(
                    span,
                    format!("`cutoff` is the cone's half-angle: between 0° and 90°, got {cutoff}"),
                );
            }
            let exponent = raw
                .exponent
                .as_ref()
                .and_then(|v| c.finite("exponent", v))
                .unwrap_or(1.0);
            Some(Light::Spot {
                position,
                direction,
                cutoff_deg: cutoff,
                exponent,
                intensity,
                attenuation,
            })
        }
        other => {
            c.error(
                raw.kind.span(),
                format!("`kind` of a light must be \"ambient\", \"point\", \"directional\" or \"spot\", got \"{other}\""),
            );
            None
        }
    }
}

/// A built-in texture by name, or an image file relative to the scene file.
fn texture(c: &mut Checker<'_>, t: &Spanned<String>, base: &Path) -> Option<Texture> {
    match t.get_ref().as_str() {
        "checkerboard" => Some(Texture::checkerboard(512, 16)),
        "uv_grid" => Some(Texture::uv_grid(512)),
        "mip_levels" => Some(Texture::mip_levels(512)),
        "bumps" => Some(Texture::bumps(512, 8)),
        "bump_normals" => Some(Texture::bump_normals(512, 8, 6.0)),
        path => match Texture::load(&base.join(path)) {
            Ok(t) => Some(t),
            Err(e) => {
                c.error(
                    t.span(),
                    format!("{e} (a texture is \"checkerboard\", \"uv_grid\", \"mip_levels\", \"bumps\", \"bump_normals\" or a PNG/JPEG path)"),
                );
                None
            }
        },
    }
}

/// `filter`, `mipmap`, `wrap`, `anisotropy` and `lod_bias` of `[scene.render]`.
fn sampler(c: &mut Checker<'_>, raw: &RawRender, s: &mut RenderSettings) {
    let smp = &mut s.sampler;
    if let Some(v) = &raw.filter {
        smp.filter = c.choice("filter", v, FILTER).unwrap_or_default();
    }
    if let Some(v) = &raw.mipmap {
        smp.mipmap = c.choice("mipmap", v, MIPMAP).unwrap_or_default();
    }
    if let Some(v) = &raw.wrap {
        smp.wrap = c.choice("wrap", v, WRAP).unwrap_or_default();
    }
    if let Some(v) = &raw.anisotropy {
        match u32::try_from(*v.get_ref()) {
            Ok(n) if (1..=16).contains(&n) => smp.anisotropy = n,
            _ => c.error(
                v.span(),
                format!(
                    "`anisotropy` must be from 1 (off) to 16, got {}",
                    v.get_ref()
                ),
            ),
        }
    }
    if let Some(v) = &raw.lod_bias
        && let Some(b) = c.finite("lod_bias", v)
    {
        smp.lod_bias = b;
    }
}

fn shadow(c: &mut Checker<'_>, sh: &Spanned<RawShadow>) -> Option<PlanarShadow> {
    let raw = sh.get_ref();
    let light = c.vec3("light", &raw.light)?;
    let plane_y = raw
        .plane_y
        .as_ref()
        .and_then(|v| c.finite("plane_y", v))
        .unwrap_or(0.0);
    if light.y <= plane_y {
        c.error(
            raw.light.span(),
            format!(
                "the shadow's light must be above its plane y = {plane_y}, got y = {}",
                light.y
            ),
        );
        return None;
    }
    let color = raw
        .color
        .as_ref()
        .and_then(|v| c.vec3("color", v))
        .unwrap_or(Vec3::splat(0.05));
    Some(PlanarShadow {
        light,
        plane_y,
        color,
    })
}

fn figure(c: &mut Checker<'_>, f: &Spanned<RawFigure>) -> Option<Figure> {
    let raw = f.get_ref();
    let mut angle = |key: &str, v: &Option<Spanned<f64>>| {
        v.as_ref().and_then(|v| c.finite(key, v)).unwrap_or(0.0)
    };
    let (pose, misplaced): (_, Vec<(&str, bool)>) = match raw.kind.get_ref().as_str() {
        "robot_arm" => (
            Pose::RobotArm(RobotArm {
                base: angle("base", &raw.base),
                lower: angle("lower", &raw.lower),
                upper: angle("upper", &raw.upper),
            }),
            vec![("torso", raw.torso.is_some()), ("head", raw.head.is_some())],
        ),
        "humanoid" => (
            Pose::Humanoid(Humanoid {
                torso: angle("torso", &raw.torso),
                head: angle("head", &raw.head),
                left_upper_arm: angle("left_upper_arm", &raw.left_upper_arm),
                left_lower_arm: angle("left_lower_arm", &raw.left_lower_arm),
                right_upper_arm: angle("right_upper_arm", &raw.right_upper_arm),
                right_lower_arm: angle("right_lower_arm", &raw.right_lower_arm),
                left_upper_leg: angle("left_upper_leg", &raw.left_upper_leg),
                left_lower_leg: angle("left_lower_leg", &raw.left_lower_leg),
                right_upper_leg: angle("right_upper_leg", &raw.right_upper_leg),
                right_lower_leg: angle("right_lower_leg", &raw.right_lower_leg),
            }),
            vec![
                ("base", raw.base.is_some()),
                ("lower", raw.lower.is_some()),
                ("upper", raw.upper.is_some()),
            ],
        ),
        other => {
            c.error(
                raw.kind.span(),
                format!(
                    "`kind` of a figure must be \"robot_arm\" or \"humanoid\", got \"{other}\""
                ),
            );
            return None;
        }
    };
    for (key, present) in misplaced {
        if present {
            c.error(
                f.span(),
                format!("`{key}` is not a joint of a {}", raw.kind.get_ref()),
            );
        }
    }
    let translate = raw
        .translate
        .as_ref()
        .and_then(|v| c.vec3("translate", v))
        .unwrap_or(Vec3::ZERO);
    Some(Figure {
        name: raw
            .name
            .clone()
            .unwrap_or_else(|| raw.kind.get_ref().replace('_', " ")),
        pose,
        translate,
    })
}
