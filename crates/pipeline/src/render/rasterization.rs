//! Rasterization with the depth test into the sample buffers: pipelens' own, banded and in
//! parallel, or — where an object carries the student's inside test or depth test — triangle
//! after triangle, each sample asked of the student's function. Each primitive's counts (the
//! samples its raster triangles covered and wrote) are recorded either way ([`record_counts`]).

use super::{CodePart, RenderError};
use crate::capture::PrimitiveRecord;
use crate::raster::{RasterCounts, RasterTriangle, SampleBuffers};
use crate::scene::Scene;
use crate::settings::RenderSettings;
use crate::shader::HookKind;

/// Rasterization with the depth test into the sample buffers (`spare`'s storage, cleared).
/// What each raster triangle drew — the samples it covered and wrote — is returned where the
/// student's tests drew the frame, and left in the samples ([`SampleBuffers::drawn`])
/// otherwise: [`record_counts`] adds them up for each primitive.
///
/// # Errors
/// A run-time error of an object's inside test (the student's `inside`).
pub(super) fn rasterize(
    scene: &Scene,
    settings: &RenderSettings,
    spare: Option<SampleBuffers>,
    triangles: &[RasterTriangle],
    primitives: &[PrimitiveRecord],
) -> Result<(SampleBuffers, Option<Vec<RasterCounts>>), RenderError> {
    let mut samples = cleared_samples(settings, spare);
    if has_hooks(scene) {
        let counts = rasterize_with_hooks(scene, settings, triangles, primitives, &mut samples)?;
        return Ok((samples, Some(counts)));
    }
    samples.rasterize_all(triangles, settings.depth_test);
    Ok((samples, None))
}

/// The sample buffers of a frame of `settings`, in `spare`'s storage, cleared.
pub(super) fn cleared_samples(
    settings: &RenderSettings,
    spare: Option<SampleBuffers>,
) -> SampleBuffers {
    let clear = settings.depth_test.clear_value();
    let (width, height) = (settings.width, settings.height);
    match spare {
        Some(s) => s.cleared(width, height, settings.samples, clear),
        None => SampleBuffers::new(width, height, settings.samples, clear),
    }
}

/// Whether an object carries the student's inside test or depth test (so that its triangles
/// are drawn one after another, each sample asked of the student's function).
pub(super) fn has_hooks(scene: &Scene) -> bool {
    scene.objects.iter().any(|o| {
        o.code.hooks.get(HookKind::Inside).is_some()
            || o.code.hooks.get(HookKind::DepthTest).is_some()
    })
}

/// Each primitive's counts: the sum of what its raster triangles drew (`counts`, one a raster
/// triangle).
pub(super) fn record_counts(primitives: &mut [PrimitiveRecord], counts: &[RasterCounts]) {
    use rayon::prelude::*;
    primitives.par_iter_mut().with_min_len(1024).for_each(|p| {
        let own = &counts[p.triangles[0] as usize..p.triangles[1] as usize];
        p.counts = own
            .iter()
            .fold(RasterCounts::default(), |a, c| RasterCounts {
                covered: a.covered + c.covered,
                written: a.written + c.written,
            });
    });
}

/// Rasterization where some objects carry the student's inside test or depth test: triangle
/// after triangle, each sample of its box asked of the object's `inside` (in batches, see
/// [`crate::shader::Hook::covers`]) or of pipelens' edge functions, each covered sample of the
/// object's `depth_test` (see [`crate::shader::Hook::passes`]) or of the settings' comparison.
fn rasterize_with_hooks(
    scene: &Scene,
    settings: &RenderSettings,
    triangles: &[RasterTriangle],
    primitives: &[PrimitiveRecord],
    samples: &mut SampleBuffers,
) -> Result<Vec<RasterCounts>, RenderError> {
    let pixels = |v: i64| (v as f64 / crate::raster::ONE as f64) as f32;
    let failed = |part: CodePart, object: &crate::scene::Object, error| RenderError::Code {
        part,
        object: object.name.clone(),
        error: Box::new(error),
        file: None,
    };
    // Each object's inside and depth tests, their calls allowed the frame's loop budget.
    let budgeted = |o: &crate::scene::Object, kind| {
        o.code.hooks.get(kind).map(|h| h.within(settings.max_steps))
    };
    let tests: Vec<_> = scene
        .objects
        .iter()
        .map(|o| {
            (
                budgeted(o, HookKind::Inside),
                budgeted(o, HookKind::DepthTest),
            )
        })
        .collect();
    let mut counts = Vec::with_capacity(triangles.len());
    for (i, tri) in triangles.iter().enumerate() {
        let Some((object, (inside_test, depth_test))) =
            primitives.get(tri.primitive as usize).and_then(|p| {
                Some((
                    scene.objects.get(p.object as usize)?,
                    &tests[p.object as usize],
                ))
            })
        else {
            counts.push(samples.rasterize_reference(tri, i as u32, settings.depth_test));
            continue;
        };
        let inside = match inside_test {
            Some(test) => {
                let points: Vec<[f32; 2]> = samples
                    .box_samples(tri)
                    .iter()
                    .map(|p| [pixels(p.x), pixels(p.y)])
                    .collect();
                let corners = tri.window.map(|c| {
                    let f = crate::raster::snap_xy(c);
                    [pixels(f.x), pixels(f.y)]
                });
                let answers = test.covers(&points, corners);
                Some(answers.map_err(|e| failed(CodePart::Function(HookKind::Inside), object, e))?)
            }
            None => None,
        };
        let covers = |k: usize, p| inside.as_ref().map_or_else(|| tri.covers(p), |a| a[k]);
        let Some(test) = depth_test else {
            counts.push(samples.rasterize_where(tri, i as u32, settings.depth_test, covers));
            continue;
        };
        let covered = samples.covered_samples(tri, covers);
        let z: Vec<f32> = covered.iter().map(|&(_, z)| z).collect();
        let stored: Vec<f32> = covered.iter().map(|&(s, _)| samples.depth[s]).collect();
        let passes = test
            .passes(&z, &stored)
            .map_err(|e| failed(CodePart::Function(HookKind::DepthTest), object, e))?;
        counts.push(samples.write_samples(&covered, &passes, i as u32));
    }
    Ok(counts)
}
