//! `[[scene.objects]]`: each object's mesh (built in or an OBJ file), transform, colour, material,
//! texture and surface maps.

use std::ops::Range;
use std::path::Path;

use glam::Vec3;
use pipeline::light::Material;
use pipeline::mesh::{BuiltinMesh, Mesh};
use pipeline::scene::{ColorSource, Object};
use pipeline::texture::{CubeMap, Displacement, Environment, SurfaceDetail, Texture};
use toml::Spanned;

use super::{Checker, triple};
use crate::lesson::folder::Folder;
use crate::lesson::raw::{RawColor, RawMaterial, RawMesh, RawMeshTable, RawObject, RawScale};
use crate::vocabulary::Text;

pub(super) fn object(
    c: &mut Checker<'_>,
    o: &Spanned<RawObject>,
    index: usize,
    base: &Folder,
) -> Option<(Object, Option<Text>)> {
    let raw = o.get_ref();
    let (mut mesh, source) = mesh(c, &raw.mesh, base)?;
    if raw.fit == Some(true) {
        mesh.fit_unit_sphere();
    }
    if let Some(n) = &raw.normals
        && let Some(averaging) = c.choice("normals", n, super::NORMALS)
    {
        mesh.compute_vertex_normals(averaging);
    }
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
    if let Some(r) = &raw.slerp_to {
        slerp_to(c, &mut object, raw.rotate_axis.is_some(), r);
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
    let label = raw.label.as_ref().map(|l| c.text_of("label", l));
    if let Some(sh) = &raw.shader
        && let Some(code) = super::shaders::shader(c, sh, base)
    {
        object.code = code;
    }
    Some((object, label))
}

/// Bump, normal and displacement maps of an object.
fn surface_maps(c: &mut Checker<'_>, o: &Spanned<RawObject>, object: &mut Object, base: &Folder) {
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
    base: &Folder,
) -> Option<(Mesh, Option<BuiltinMesh>)> {
    let span = m.span();
    let table = match m.get_ref() {
        RawMesh::Name(n) if n.to_ascii_lowercase().ends_with(".obj") => {
            return load_obj(c, span, base, n).map(|m| (m, None));
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
            levels: None,
            heights: None,
            u: None,
            v: None,
            shape: None,
            gap: None,
            smooth: None,
            resolution: None,
            cloud: None,
            frequency: None,
            rate: None,
            blur: None,
            spokes: None,
            step: None,
            frames: None,
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
        (None, Some(path)) => load_obj(c, span, base, path).map(|m| (m, None)),
        (Some(name), None) => builtin(c, span, name, table).map(|b| (b.build(), Some(b))),
    }
}

/// The OBJ file `written`, relative to the lesson's folder `base`.
fn load_obj(c: &mut Checker<'_>, span: Range<usize>, base: &Folder, written: &str) -> Option<Mesh> {
    let file = c.read_beside(span.clone(), base, written)?;
    let name = Path::new(&file.shown)
        .file_name()
        .map_or_else(|| file.shown.clone(), |n| n.to_string_lossy().into_owned());
    match Mesh::parse_obj(&mut &*file.bytes, &file.shown, &name) {
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
        "bezier" => super::shapes::bezier(c, span.clone(), t)?,
        "bezier_patch" => super::shapes::bezier_patch(c, span.clone(), t)?,
        "implicit" => super::shapes::implicit(c, span.clone(), t)?,
        "signal" => super::shapes::signal(c, span.clone(), t)?,
        "wheel" => super::shapes::wheel(c, span.clone(), t)?,
        other => {
            let suggestion = pipeline::shader::suggest::did_you_mean(
                other,
                BuiltinMesh::NAMES,
                pipeline::shader::suggest::Quote::Value,
            );
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

/// A built-in texture by name, or an image file relative to the scene file.
fn texture(c: &mut Checker<'_>, t: &Spanned<String>, base: &Folder) -> Option<Texture> {
    match t.get_ref().as_str() {
        "checkerboard" => Some(Texture::checkerboard(512, 16)),
        "checkerboard_wide" => Some(Texture::checker_cells("checkerboard_wide", (512, 128), 32)),
        "uv_grid" => Some(Texture::uv_grid(512)),
        "mip_levels" => Some(Texture::mip_levels(512)),
        "bumps" => Some(Texture::bumps(512, 8)),
        "relief" => Some(Texture::relief(512, 256, 64)),
        "relief_normals" => Some(Texture::relief_normals(512, 256, 64, 6.0)),
        "bump_normals" => Some(Texture::bump_normals(512, 8, 6.0)),
        written => match c
            .read_beside(t.span(), base, written)
            .map(|f| Texture::decode(&f.shown, &f.bytes))?
        {
            Ok(t) => Some(t),
            Err(e) => {
                c.error(
                    t.span(),
                    format!("{e} (a texture is \"checkerboard\", \"checkerboard_wide\", \"uv_grid\", \"mip_levels\", \"bumps\", \"relief\", \"bump_normals\", \"relief_normals\" or a PNG/JPEG path)"),
                );
                None
            }
        },
    }
}

/// `slerp_to`: the second orientation (its axis must have a length, `t` in [0, 1]); it needs
/// `rotate_axis`, the first.
fn slerp_to(
    c: &mut Checker,
    object: &mut Object,
    has_first: bool,
    r: &Spanned<crate::lesson::raw::RawSlerpTo>,
) {
    if !has_first {
        c.error(
            r.span(),
            "`slerp_to` needs `rotate_axis` on the same object: that rotation is the first orientation, this table the second",
        );
    }
    let raw = r.get_ref();
    let t = raw.t.as_ref().map_or(Some(0.0), |t| c.finite("t", t));
    if let (Some(axis), Some(angle), Some(t)) =
        (c.vec3("axis", &raw.axis), c.finite("angle", &raw.angle), t)
    {
        if axis.length() < 1e-6 {
            c.error(
                raw.axis.span(),
                "`axis` must not be the zero vector: it gives the direction to rotate about",
            );
        }
        if !(0.0..=1.0).contains(&t) {
            let span = raw.t.as_ref().map_or(r.span(), Spanned::span);
            c.error(
                span,
                format!("`t` runs from 0 (the first orientation) to 1 (the second), got {t}"),
            );
        }
        object.slerp = Some(pipeline::transform::SlerpTo {
            axis,
            angle_deg: angle,
            t,
        });
    }
}
