//! Runs: up to eight consecutive pixels of a row whose samples all lie on one textured triangle
//! (the inside of every such triangle larger than a few pixels), resolved together. What belongs to the
//! triangle — its primitive, vertices, object, texture — is looked up once for the run; the
//! texture coordinates' x derivative is the next pixel's `uv` minus this one's (the same
//! evaluation one pixel over, which [`RasterTriangle::uv_at`] repeats for each pixel); and Phong
//! shading lights the run's pixels in SIMD lanes ([`shade_lanes`]). Every value equals what
//! [`ResolveContext::pixel`] gives for the same pixel, bit for bit: the tests compare the two.

use glam::{I64Vec2, Vec2, Vec3};

use super::resolve::{ResolveContext, ResolvedPixel};
use crate::capture::FrameCapture;
use crate::raster::{NONE, ONE, RasterTriangle};
use crate::shade::lanes::{LANES, shade_lanes};
use crate::shade::{Frequency, ShadeTerms};
use crate::texture::Lookup;

impl ResolveContext<'_> {
    /// The textured triangle that owns every sample of the pixels from image index `i` on, and
    /// how many consecutive pixels (at most `room`, at most [`LANES`]) it owns so wholly; `None`
    /// when the pixel at `i` is not wholly inside one textured triangle.
    pub(super) fn run_at(&self, i: usize, room: usize) -> Option<(u32, usize)> {
        let s = self.settings.samples.count();
        let tris = &self.samples.triangle[i * s..];
        let t = tris[0];
        let whole = |k: usize| tris[k * s..(k + 1) * s].iter().all(|&u| u == t);
        if t == NONE || !self.textured(t) || !whole(0) {
            return None;
        }
        let n = (1..room.min(LANES))
            .find(|&k| !whole(k))
            .unwrap_or(room.min(LANES));
        Some((t, n))
    }

    /// Whether raster triangle `t`'s object is textured (a texture and uvs). Only such runs
    /// are resolved together: measured on the bunny (untextured, its triangles a few pixels
    /// wide), lighting runs in lanes cost ~10 % more than the per-pixel path, while on Spot
    /// (textured) sharing the uv evaluation and lighting in lanes saves 5–9 %.
    fn textured(&self, t: u32) -> bool {
        let prim = &self.primitives[self.triangles[t as usize].primitive as usize];
        self.scene.objects[prim.object as usize].texture.is_some()
            && prim
                .vertices
                .iter()
                .all(|&r| self.vertices[r as usize].uv.is_some())
    }

    /// Resolves the pixels from window `(x, y)` (image index `i`) on, one per element of `out`,
    /// every sample of which lies on raster triangle `owner`: as [`Self::pixel`] resolves each.
    pub(super) fn resolve_run(
        &self,
        owner: u32,
        (x, y): (u32, u32),
        i: usize,
        out: &mut [ResolvedPixel],
    ) {
        let n = out.len();
        let t = &self.triangles[owner as usize];
        let prim = &self.primitives[t.primitive as usize];
        let object = &self.scene.objects[prim.object as usize];
        let pc = self.settings.perspective_correct;
        let weights = |at: I64Vec2| t.original_bary(t.lambda(at), pc);
        let centre = |k: usize| FrameCapture::pixel_centre_fixed(x + k as u32, y);
        let mut b = [Vec3::ZERO; LANES];
        for (k, b) in b.iter_mut().enumerate().take(n) {
            *b = weights(centre(k));
        }
        let texels = self.run_texels(t, &b[..n], centre);
        let surface: [Vec3; LANES] = std::array::from_fn(|k| match &texels[k] {
            Some((_, l)) => l.color,
            None => self.color_of(t, b[k]),
        });
        let mut terms = [None; LANES];
        let v = prim.vertices.map(|r| &self.vertices[r as usize]);
        if self.settings.shading == Frequency::Phong && object.lit && object.detail.is_none() {
            let interpolate = |f: fn(&crate::vertex::VertexRecord) -> Vec3, b: Vec3| {
                f(v[0]) * b.x + f(v[1]) * b.y + f(v[2]) * b.z
            };
            let p: [Vec3; LANES] =
                std::array::from_fn(|k| interpolate(|v| v.world.truncate(), b[k]));
            let normal: [Vec3; LANES] =
                std::array::from_fn(|k| interpolate(|v| v.normal_world, b[k]));
            let mut lit = [ShadeTerms::default(); LANES];
            shade_lanes(
                &p[..n],
                &normal[..n],
                self.scene.camera.eye,
                &surface[..n],
                &self.scene.lights,
                &object.material,
                self.settings.reflection,
                &mut lit[..n],
            );
            for k in 0..n {
                if let Some(env) = &object.environment {
                    self.mirror(&mut lit[k], env, p[k]);
                }
                terms[k] = Some(lit[k]);
            }
        } else {
            for k in 0..n {
                terms[k] = self.terms_of(t, b[k], surface[k], texels[k].is_some());
            }
        }
        for (k, out) in out.iter_mut().enumerate() {
            *out = ResolvedPixel {
                terms: terms[k],
                texture: texels[k],
                coverage: self.settings.samples.count() as u8,
                depth: self.mean_depth(i + k),
                primitive: t.primitive,
                owner,
                color: terms[k].map_or(surface[k], |t| t.color()).to_array(),
            };
        }
    }

    /// The texture lookups of a run's pixels at original-triangle weights `b` (pixel `k` at
    /// fixed-point `centre(k)`), as [`Self::texture_lookup`] makes each: `uv` interpolated from
    /// the same weights, its x derivative the next pixel's `uv` minus this one's.
    fn run_texels(
        &self,
        t: &RasterTriangle,
        b: &[Vec3],
        centre: impl Fn(usize) -> I64Vec2,
    ) -> [Option<(Vec2, Lookup)>; LANES] {
        let mut out = [None; LANES];
        let prim = &self.primitives[t.primitive as usize];
        let Some(texture) = self.scene.objects[prim.object as usize].texture.as_ref() else {
            return out;
        };
        let [Some(u0), Some(u1), Some(u2)] = prim.vertices.map(|r| self.vertices[r as usize].uv)
        else {
            return out;
        };
        let pc = self.settings.perspective_correct;
        let uv_of = |w: Vec3| u0 * w.x + u1 * w.y + u2 * w.z;
        let uv_at = |at: I64Vec2| uv_of(t.original_bary(t.lambda(at), pc));
        let uv: [Vec2; LANES] = std::array::from_fn(|k| b.get(k).map_or(Vec2::ZERO, |&w| uv_of(w)));
        let sampler = &self.settings.sampler;
        for k in 0..b.len() {
            out[k] = Some(if self.derivatives {
                let right = if k + 1 < b.len() {
                    uv[k + 1]
                } else {
                    uv_at(centre(k) + I64Vec2::new(ONE, 0))
                };
                let up = uv_at(centre(k) + I64Vec2::new(0, ONE));
                (
                    uv[k],
                    texture.sample(uv[k], right - uv[k], up - uv[k], sampler),
                )
            } else {
                (uv[k], texture.sample_level0(uv[k], sampler))
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use glam::Vec3;

    use super::*;
    use crate::buffers::Capture;
    use crate::camera::{Camera, Projection};
    use crate::light::Light;
    use crate::mesh::BuiltinMesh;
    use crate::raster::Samples;
    use crate::scene::{Object, Scene};
    use crate::settings::RenderSettings;
    use crate::shade::Reflection;
    use crate::texture::{CubeMap, Environment, Mipmap, SurfaceDetail, Texture};

    /// A textured floor and sphere, a mirror torus and a bump-mapped cube, under every kind of
    /// light, seen in perspective: runs with and without a texture, an environment, a detail map
    /// (which the lanes leave to the per-pixel path), and an unlit object.
    fn scene() -> Scene {
        let checker = Arc::new(Texture::checkerboard(64, 8));
        let mut floor = Object::new(
            "floor",
            BuiltinMesh::Plane {
                divisions: 2,
                repeat: 4.0,
            }
            .build(),
        );
        (floor.texture, floor.scale, floor.translate) = (
            Some(checker.clone()),
            Vec3::splat(4.0),
            Vec3::new(0.0, -1.0, 0.0),
        );
        let mut ball = Object::new(
            "ball",
            BuiltinMesh::UvSphere {
                segments: 24,
                rings: 12,
            }
            .build(),
        );
        ball.texture = Some(checker);
        let mut torus = Object::new(
            "torus",
            BuiltinMesh::Torus {
                minor: 0.3,
                segments: 24,
                sides: 12,
            }
            .build(),
        );
        torus.translate = Vec3::new(2.0, 0.0, -1.0);
        torus.environment = Some(Environment {
            cube: Arc::new(CubeMap::room(16)),
            reflectivity: 0.6,
        });
        let mut cube = Object::new("cube", BuiltinMesh::Cube.build());
        (cube.translate, cube.scale) = (Vec3::new(-2.2, 0.0, -1.0), Vec3::splat(0.7));
        cube.detail = Some(SurfaceDetail::Bump {
            height: Arc::new(Texture::bumps(32, 4)),
            strength: 0.5,
        });
        let mut unlit = Object::new("unlit", BuiltinMesh::Triangle.build());
        (unlit.translate, unlit.lit) = (Vec3::new(0.0, 1.6, -2.0), false);
        Scene {
            objects: vec![floor, ball, torus, cube, unlit],
            camera: Camera {
                eye: Vec3::new(0.5, 1.5, 5.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
            },
            projection: Projection::Perspective {
                fovy_deg: 50.0,
                aspect: None,
                near: 0.5,
                far: 30.0,
            },
            figures: Vec::new(),
            shadow: None,
            lights: vec![
                Light::Ambient {
                    intensity: Vec3::splat(0.2),
                },
                Light::Point {
                    position: Vec3::new(3.0, 4.0, 3.0),
                    intensity: Vec3::new(9.0, 8.0, 7.0),
                    attenuation: Vec3::new(0.0, 0.0, 1.0),
                },
                Light::Directional {
                    direction: Vec3::new(-1.0, -2.0, -0.5),
                    intensity: Vec3::splat(0.3),
                },
                Light::Spot {
                    position: Vec3::new(-2.0, 3.0, 2.0),
                    direction: Vec3::new(0.6, -1.0, -0.6),
                    cutoff_deg: 30.0,
                    exponent: 2.0,
                    intensity: Vec3::splat(0.8),
                    attenuation: Vec3::new(1.0, 0.1, 0.0),
                },
            ],
        }
    }

    /// Asserts that the frame's buffers hold `want` at pixel `i`: its colour, depth, owner,
    /// coverage and primitive, and, when every buffer is kept, its texture coordinates and
    /// (as half floats) its normal.
    fn assert_kept(
        px: &crate::capture::PixelBuffers,
        i: usize,
        want: &ResolvedPixel,
        settings: &RenderSettings,
        at: &str,
    ) {
        assert_eq!(
            (px.color[i], px.depth[i], px.owner[i], px.coverage[i]),
            (want.color, want.depth, want.owner, want.coverage),
            "setting {at}"
        );
        assert_eq!(px.primitive[i], want.primitive, "setting {at}");
        if settings.capture == Capture::FULL {
            let uv = want.texture.map(|(uv, _)| uv.to_array());
            assert_eq!(px.texture_at(i).map(|t| t.uv), uv, "setting {at}");
            let normal = want.terms.map_or([0.0; 3], |t| t.normal.to_array());
            let half = |v: [f32; 3]| v.map(|c| half::f16::from_f32(c).to_f32());
            let lit = settings.shading != Frequency::Unlit;
            let kept = px.lighting_at(i).map(|l| l.normal);
            assert_eq!(kept, lit.then(|| half(normal)), "setting {at}");
        }
    }

    /// Every pixel of frames rendered with runs and background spans equals the per-pixel
    /// resolve of the same pixel, bit for bit: colour, depth, owner, primitive, and the kept
    /// lighting terms and texture lookup; and every run's resolve equals it too.
    #[test]
    fn runs_resolve_every_pixel_as_the_per_pixel_path_does() {
        let scene = scene();
        let (mut runs, mut background) = (0, 0);
        for (k, (shading, reflection, mipmap, samples)) in [
            (
                Frequency::Phong,
                Reflection::BlinnPhong,
                Mipmap::Linear,
                Samples::X1,
            ),
            (
                Frequency::Phong,
                Reflection::Phong,
                Mipmap::None,
                Samples::X4,
            ),
            (
                Frequency::Phong,
                Reflection::BlinnPhong,
                Mipmap::Ewa,
                Samples::X1,
            ),
            (
                Frequency::Gouraud,
                Reflection::BlinnPhong,
                Mipmap::Linear,
                Samples::X4,
            ),
            (
                Frequency::Flat,
                Reflection::Phong,
                Mipmap::Nearest,
                Samples::X1,
            ),
            (
                Frequency::Unlit,
                Reflection::BlinnPhong,
                Mipmap::None,
                Samples::X1,
            ),
        ]
        .into_iter()
        .enumerate()
        {
            let mut settings = RenderSettings {
                width: 160,
                height: 96,
                samples,
                shading,
                reflection,
                capture: if k % 2 == 0 {
                    Capture::FULL
                } else {
                    Capture::COLOR
                },
                ..RenderSettings::default()
            };
            settings.sampler.mipmap = mipmap;
            let frame = crate::render::render(&scene, &settings).expect("renders");
            let ctx = ResolveContext {
                derivatives: settings.capture.texturing || settings.sampler.uses_footprint(),
                vertex_shading: &frame.vertex_shading,
                face_shading: &frame.face_shading,
                scene: &scene,
                settings: &settings,
                samples: &frame.samples,
                triangles: &frame.triangles,
                primitives: &frame.primitives,
                vertices: &frame.vertices,
            };
            let (w, h) = (settings.width as usize, settings.height as usize);
            for row in 0..h {
                let y = (h - 1 - row) as u32;
                for x in 0..w {
                    let i = row * w + x;
                    let want = ctx.pixel(x as u32, y, i, None);
                    assert_kept(
                        &frame.pixels,
                        i,
                        &want,
                        &settings,
                        &format!("{k} ({x}, {y})"),
                    );
                    background += usize::from(want.coverage == 0);
                    let Some((owner, n)) = ctx.run_at(i, w - x) else {
                        continue;
                    };
                    let mut got = [ResolvedPixel::default(); LANES];
                    ctx.resolve_run(owner, (x as u32, y), i, &mut got[..n]);
                    for (j, got) in got[..n].iter().enumerate() {
                        let want = ctx.pixel((x + j) as u32, y, i + j, None);
                        assert_eq!(*got, want, "setting {k}, run at ({x}, {y}), pixel {j}");
                    }
                    runs += usize::from(n > 1);
                }
            }
        }
        assert!(runs > 10_000, "only {runs} runs of two pixels or more");
        assert!(background > 5_000, "only {background} background pixels");
    }
}
