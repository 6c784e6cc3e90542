//! `[scene.render]` and `[scene.projection]`: the viewport, samples, modes and sampler; the
//! projection's kind and view volume, each range problem pointed at the value that breaks it.

use pipeline::camera::Projection;
use pipeline::raster::Samples;
use pipeline::settings::{MAX_MAX_STEPS, MAX_VIEWPORT_SIDE, RenderSettings};
use toml::Spanned;

use super::{CULL, Checker, DEPTH_TEST, FILTER, MIPMAP, REFLECTION, SHADING, WRAP};
use crate::lesson::raw::{RawProjection, RawRender};

pub(super) fn render(c: &mut Checker<'_>, r: &Spanned<RawRender>) -> RenderSettings {
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
        c.error(r.span(), p.to_string());
    }
    render_modes(c, raw, &mut s);
    sampler(c, raw, &mut s);
    if let Some(v) = &raw.max_steps {
        match u32::try_from(*v.get_ref()) {
            Ok(n) if (1..=MAX_MAX_STEPS).contains(&n) => s.max_steps = n,
            _ => c.error(
                v.span(),
                format!(
                    "`max_steps` must be a whole number of loop iterations from 1 to {MAX_MAX_STEPS}, got {}",
                    v.get_ref()
                ),
            ),
        }
    }
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

pub(super) fn projection(c: &mut Checker<'_>, p: &Spanned<RawProjection>) -> Projection {
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
        use pipeline::camera::ProjectionProblem as P;
        let value = match problem {
            P::Fovy(_) => &raw.fovy,
            P::Aspect(_) => &raw.aspect,
            P::Near(_) => &raw.near,
            P::FarNear { .. } => &raw.far,
            P::LeftRight { .. } => &raw.left,
            P::BottomTop { .. } => &raw.bottom,
            P::NotFinite => &None,
        };
        c.error(
            value.as_ref().map_or(p.span(), Spanned::span),
            problem.to_string(),
        );
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
