//! The texture lookups of a batch: `texture()` and its kin with the level of detail from the
//! quad's differences (lanes `4q`…`4q + 3`), a bias, explicit derivatives or an explicit level,
//! and a texel offset; a cube map by direction; `texelFetch` by integer address; `textureSize`.
//! Each reads the host's textures through [`Textures`], the texture's slot from its register
//! (the same in every lane: a uniform's, or one a call passed on).

use glam::{IVec2, Vec2, Vec3};

use super::textures::{Texel, Textures};
use crate::complaint::Complaint;
use crate::lanes::{LANES, bit};
use crate::register_form::{Level, Op};

/// Runs the lookup `op` over lanes `0..n`, its operands' rows given by `row(register,
/// component)`, into `out` (component `k` of lane `l` at `k·LANES + l`).
///
/// # Errors
/// A `texelFetch` outside its level in a live lane: the message and its complaint.
pub(super) fn lookup<'a>(
    op: &Op,
    row: &impl Fn(u32, u32) -> &'a [u32],
    out: &mut [u32],
    n: usize,
    live: u64,
    b: &dyn Textures,
) -> Result<(), (String, Complaint)> {
    match op {
        Op::Sample {
            texture,
            coordinate,
            level,
            offset,
        } => {
            let slot = row(*texture, 0)[0];
            let uv = |l: usize| vec2_at(&row, coordinate.first, l);
            for l in 0..n {
                let shift = offset.map_or(IVec2::ZERO, |o| {
                    IVec2::new(row(o, 0)[l] as i32, row(o, 1)[l] as i32)
                });
                let color = match level {
                    Level::Auto | Level::Bias(_) => {
                        let q = l & !3;
                        let (dx, dy) = if q + 3 < n {
                            (uv(q + 1) - uv(q), uv(q + 2) - uv(q))
                        } else {
                            (Vec2::ZERO, Vec2::ZERO)
                        };
                        let bias = match level {
                            Level::Bias(r) => f32::from_bits(row(*r, 0)[l]),
                            _ => 0.0,
                        };
                        b.sample(slot, uv(l), dx, dy, bias, shift)
                    }
                    Level::Gradient { x, y } => {
                        let (dx, dy) = (vec2_at(&row, *x, l), vec2_at(&row, *y, l));
                        b.sample(slot, uv(l), dx, dy, 0.0, shift)
                    }
                    Level::Exact(r) => {
                        let lod = f32::from_bits(row(*r, 0)[l]);
                        b.sample_lod(slot, uv(l), lod, shift)
                    }
                    Level::Zero => b.sample_lod(slot, uv(l), 0.0, shift),
                }
                .unwrap_or(Vec3::ZERO);
                for (k, v) in color.extend(1.0).to_array().iter().enumerate() {
                    out[k * LANES + l] = v.to_bits();
                }
            }
        }
        Op::SampleCube { texture, direction } => {
            let slot = row(*texture, 0)[0];
            for l in 0..n {
                let d = Vec3::new(
                    f32::from_bits(row(direction.first, 0)[l]),
                    f32::from_bits(row(direction.first, 1)[l]),
                    f32::from_bits(row(direction.first, 2)[l]),
                );
                let color = b.sample_cube(slot, d).unwrap_or(Vec3::ZERO);
                for (k, v) in color.extend(1.0).to_array().iter().enumerate() {
                    out[k * LANES + l] = v.to_bits();
                }
            }
        }
        Op::Fetch {
            texture,
            coordinate,
            level,
        } => {
            let slot = row(*texture, 0)[0];
            for l in 0..n {
                let (i, j) = (
                    row(coordinate.first, 0)[l] as i32,
                    row(coordinate.first, 1)[l] as i32,
                );
                let k = level.map_or(0, |r| row(r, 0)[l] as i32);
                let texel = match b.texel(slot, k, i, j) {
                    Texel::At(c) => c.extend(1.0),
                    Texel::Outside if live & bit(l) != 0 => {
                        return Err((
                            format!("texelFetch at ({i}, {j}) level {k} is outside the texture"),
                            Complaint::TexelOutside { i, j, level: k },
                        ));
                    }
                    _ => glam::Vec4::ZERO,
                };
                for (c, v) in texel.to_array().iter().enumerate() {
                    out[c * LANES + l] = v.to_bits();
                }
            }
        }
        Op::Size { texture, level } => {
            let slot = row(*texture, 0)[0];
            for l in 0..n {
                let k = level.map_or(0, |r| row(r, 0)[l] as usize);
                let (w, h) = b.size(slot, k);
                out[l] = w;
                out[LANES + l] = h;
            }
        }
        _ => {}
    }
    Ok(())
}

/// Lane `l` of the vec2 at register `r`, its rows given by `row(register, component)`.
fn vec2_at<'a>(row: &impl Fn(u32, u32) -> &'a [u32], r: u32, l: usize) -> Vec2 {
    Vec2::new(f32::from_bits(row(r, 0)[l]), f32::from_bits(row(r, 1)[l]))
}
