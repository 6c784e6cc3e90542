//! A fragment shaded, as the reference path does it pixel by pixel: the surface colour at its
//! barycentric weights, its texture lookup, its lighting terms (a mirror's reflection among
//! them), or the student's fragment shader's colour; and a whole pixel resolved from its samples
//! (`pixel`), which the runs and the blocks must equal bit for bit.

use glam::{I64Vec2, Vec2, Vec3};

use super::{BlockShade, ResolveContext, ResolvedPixel, Shaded};
use crate::capture::FrameCapture;
use crate::lighting::{self, Frequency, ShadeTerms};
use crate::raster::{NONE, ONE, RasterTriangle};
use crate::texture::{Environment, Lookup};

impl ResolveContext<'_> {
    /// The surface colour of triangle `t` at original-triangle weights `b`: `Σ b_k·c_k`.
    pub(in crate::render) fn color_of(&self, t: &RasterTriangle, b: Vec3) -> Vec3 {
        let rows = self.primitives[t.primitive as usize].vertices;
        let c = rows.map(|r| self.vertices[r as usize].color);
        c[0] * b.x + c[1] * b.y + c[2] * b.z
    }

    /// The texture lookup of `t` at pixel centre `centre` (a textured object, a mesh with uvs):
    /// `uv` and its 2×2 quad's differences, as a GPU takes them ([`RasterTriangle::uv_at`]).
    pub(in crate::render) fn texture_lookup(
        &self,
        t: &RasterTriangle,
        centre: I64Vec2,
    ) -> Option<(Vec2, Lookup)> {
        let prim = &self.primitives[t.primitive as usize];
        let texture = self.scene.objects[prim.object as usize].texture.as_ref()?;
        let uvs = prim.vertices.map(|r| self.vertices[r as usize].uv);
        let [Some(a), Some(b), Some(c)] = uvs else {
            return None;
        };
        // Neither the colour (one level, one tap) nor a kept buffer may need the footprint.
        let (uv, dx, dy) = t.uv_at(
            &prim.bary_corners(t),
            [a, b, c],
            centre,
            self.settings.height,
            self.settings.perspective_correct,
            self.derivatives,
        );
        let sampler = &self.settings.sampler;
        if !self.derivatives {
            return Some((uv, texture.sample_level0(uv, sampler)));
        }
        Some((uv, texture.sample(uv, dx, dy, sampler)))
    }

    /// The lighting of triangle `t` at weights `b` with surface colour `surface`, by the shading
    /// frequency: the face's own terms (flat) or the vertices' terms interpolated (Gouraud) — a
    /// texture then modulates their ambient and diffuse terms, as OpenGL's `GL_MODULATE` does — or
    /// lighting evaluated here with the interpolated position and normal (Phong). `None` when unlit.
    pub(in crate::render) fn terms_of(
        &self,
        t: &RasterTriangle,
        b: Vec3,
        surface: Vec3,
        textured: bool,
    ) -> Option<ShadeTerms> {
        let prim = &self.primitives[t.primitive as usize];
        let v = prim.vertices.map(|r| &self.vertices[r as usize]);
        if !self.scene.objects[prim.object as usize].lit {
            return None;
        }
        match self.settings.shading {
            Frequency::Unlit => None,
            Frequency::Flat | Frequency::Gouraud => {
                let mut terms = if self.settings.shading == Frequency::Flat {
                    self.face_shading[t.primitive as usize]
                } else {
                    let s = prim.vertices.map(|r| &self.vertex_shading[r as usize]);
                    ShadeTerms::blend(s, b)
                };
                if textured {
                    terms.ambient *= surface;
                    terms.diffuse *= surface;
                }
                Some(terms)
            }
            Frequency::Phong => {
                let p = v[0].world.truncate() * b.x
                    + v[1].world.truncate() * b.y
                    + v[2].world.truncate() * b.z;
                let mut n =
                    v[0].normal_world * b.x + v[1].normal_world * b.y + v[2].normal_world * b.z;
                let object = &self.scene.objects[prim.object as usize];
                if let (Some(detail), [Some(a), Some(bb), Some(c)]) =
                    (&object.detail, v.map(|v| v.uv))
                {
                    let world = v.map(|v| v.world.truncate());
                    if let Some((tangent, bitangent)) =
                        crate::texture::tangent_frame(world, [a, bb, c])
                    {
                        let uv = a * b.x + bb * b.y + c * b.z;
                        n = detail.perturb(n, tangent, bitangent, uv);
                    }
                }
                let mut terms = lighting::shade(
                    p,
                    n,
                    self.scene.camera.eye,
                    surface,
                    &self.scene.lights,
                    &object.material,
                    self.settings.reflection,
                );
                if let Some(env) = &object.environment {
                    self.mirror(&mut terms, env, p);
                }
                Some(terms)
            }
        }
    }

    /// Environment mapping at world point `p`, lit with `terms`: `r = 2(n·v)n − v`, the mirror
    /// direction of the view vector; a mirror of reflectivity k shows k of what it reflects and
    /// keeps 1 − k of its own ambient and diffuse light.
    pub(in crate::render) fn mirror(&self, terms: &mut ShadeTerms, env: &Environment, p: Vec3) {
        let (n, v) = (
            terms.normal,
            (self.scene.camera.eye - p).normalize_or_zero(),
        );
        let k = env.reflectivity.clamp(0.0, 1.0);
        terms.reflected = env.cube.sample(2.0 * n.dot(v) * n - v) * k;
        terms.ambient *= 1.0 - k;
        terms.diffuse *= 1.0 - k;
    }

    /// The colour of triangle `t` at the fixed-point position `at`, with its lighting terms and
    /// texture lookup: the surface colour is the texel (textured) or the interpolated vertex
    /// colour, then lit by the shading frequency.
    /// An object with shaders gets no colour here (the fragment shaders add it), only its
    /// terms and lookup where the frame keeps them (what pipelens' own shading would give).
    pub(in crate::render) fn shade_at(&self, t: &RasterTriangle, at: I64Vec2) -> Shaded {
        let shader = self.has_shader(t);
        if shader && !self.keeps_terms() {
            return (Vec3::ZERO, None, None);
        }
        let bary = self.primitives[t.primitive as usize].bary_corners(t);
        let b = t.original_bary(&bary, t.lambda(at), self.settings.perspective_correct);
        let texel = self.texture_lookup(t, at);
        let surface = texel.map_or_else(|| self.color_of(t, b), |(_, l)| l.color);
        let terms = self.terms_of(t, b, surface, texel.is_some());
        let color = if shader {
            Vec3::ZERO
        } else {
            terms.map_or(surface, |t| t.color())
        };
        (color, terms, texel)
    }

    /// Whether raster triangle `t`'s object runs the student's shaders.
    pub(in crate::render) fn has_shader(&self, t: &RasterTriangle) -> bool {
        let prim = &self.primitives[t.primitive as usize];
        self.scene.objects[prim.object as usize]
            .code
            .shader
            .is_some()
    }

    /// Whether the frame keeps any pixel's lighting terms or texture lookup.
    pub(in crate::render) fn keeps_terms(&self) -> bool {
        let c = self.settings.capture;
        c.lighting || c.texturing || c.pixel.is_some()
    }

    /// Resolves window pixel `(x, y)`, whose image index is `i`; with coarse shading, `block`
    /// is the shading its 2×2 block has so far.
    pub(in crate::render) fn pixel(
        &self,
        x: u32,
        y: u32,
        i: usize,
        block: Option<&mut Option<BlockShade>>,
    ) -> ResolvedPixel {
        let s = self.settings.samples.count();
        let tris = self.samples.triangles(i * s..(i + 1) * s);
        let background = self.settings.background;
        let mut out = ResolvedPixel {
            terms: None,
            texture: None,
            coverage: 0,
            depth: self.mean_depth(i),
            primitive: NONE,
            owner: NONE,
            color: background.to_array(),
        };
        let covered = tris.iter().filter(|&&t| t != NONE).count();
        if covered == 0 {
            return out;
        }
        out.coverage = covered as u8;
        let centre = FrameCapture::pixel_centre_fixed(x, y);
        if covered == s && !self.settings.per_sample_shading && tris.iter().all(|&t| t == tris[0]) {
            // Inside a triangle (the usual case): it owns the pixel and is shaded once. The
            // general path below gives the same, (0·background + c·s)/s = c exactly, s being a
            // power of two.
            let owner = &self.triangles[tris[0] as usize];
            let (color, terms, texel) = match block {
                Some(Some(b)) if b.triangle == tris[0] => b.shaded,
                Some(b) => {
                    let shaded = self.shade_at(owner, centre);
                    b.get_or_insert(BlockShade {
                        triangle: tris[0],
                        shaded,
                    });
                    shaded
                }
                None => self.shade_at(owner, centre),
            };
            return ResolvedPixel {
                terms,
                texture: texel,
                primitive: owner.primitive,
                owner: tris[0],
                color: color.to_array(),
                ..out
            };
        }
        out.owner = self.owner_of(tris);
        let owner = &self.triangles[out.owner as usize];
        out.primitive = owner.primitive;
        // Colour. Multisampling: each distinct triangle once, at the centre, weighted by its
        // samples. Supersampling: every covered sample shaded at its own position.
        let mut sum = background * (s - covered) as f32;
        let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
        for (k, &t) in tris.iter().enumerate() {
            let per_sample = self.settings.per_sample_shading;
            if t == NONE || (!per_sample && tris[..k].contains(&t)) {
                continue;
            }
            let tri = &self.triangles[t as usize];
            let (at, weight) = if per_sample {
                (corner + self.samples.offset(k), 1.0)
            } else {
                (centre, tris.iter().filter(|&&u| u == t).count() as f32)
            };
            let (color, terms, texel) = self.shade_at(tri, at);
            sum += crate::render::stored_color(color) * weight;
            if tri.primitive == owner.primitive && out.terms.is_none() && out.texture.is_none() {
                out.terms = terms;
                out.texture = texel;
            }
        }
        out.color = (sum / s as f32).to_array();
        out
    }
}
