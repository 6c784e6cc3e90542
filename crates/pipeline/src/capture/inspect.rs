//! Everything about one pixel: every fragment that reached it with the outcome of its depth test
//! at each sample (replayed from the raster triangles), the owning fragment's lighting terms,
//! texture lookup and lighting vectors; and the intensity profile along a line of pixels.

use glam::{I64Vec2, Vec3};
use serde::Serialize;

use super::{FrameCapture, PixelExplanation, PixelLighting, PixelTexture};
use crate::raster::{NONE, ONE, RasterTriangle, snap};

/// One fragment that reached a pixel: a raster triangle covering at least one of its samples,
/// replayed in drawing order against the pixel's depth values.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FragmentRecord {
    /// The primitive (input triangle).
    pub primitive: u32,
    /// The raster triangle (index into [`FrameCapture::triangles`]).
    pub triangle: u32,
    /// Per sample of the pixel: `None` not covered; `Some(true)` covered and passed the depth
    /// test against what was stored then; `Some(false)` covered and failed it.
    pub samples: Vec<Option<bool>>,
    /// Per sample: the fragment's window depth there (`None` where not covered).
    pub sample_depths: Vec<Option<f32>>,
    /// Window depth at the pixel centre.
    pub depth: f32,
    /// Affine (screen-space) barycentrics at the pixel centre.
    pub bary_affine: [f32; 3],
    /// Perspective-correct barycentrics at the pixel centre.
    pub bary_perspective: [f32; 3],
    /// Whether the fragment owns the pixel in the final image (most of its samples).
    pub visible: bool,
    /// The inside test: the triangle's edge functions at the pixel centre and at each sample.
    pub edges: EdgeTest,
}

/// The inside test of one raster triangle at one pixel. The triangle's corners are
/// counter-clockwise in window coordinates (y up); `E_i` is the edge function of the edge
/// opposite corner `i`, `E_i(p) = (b − a) × (p − a)` for that edge `a → b`: twice the area of the
/// triangle the edge makes with `p`, positive inside. A sample is inside when every `E_i > 0`,
/// or `E_i = 0` on a top or left edge (the top-left fill rule). Values are in square pixels,
/// exact: they are computed on the 1/256-pixel grid the corners were snapped to.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EdgeTest {
    /// The snapped corners `(x, y)` in window coordinates, counter-clockwise.
    pub corners: [[f64; 2]; 3],
    /// Whether edge `i` (opposite corner `i`) is a top or a left edge.
    pub top_left: [bool; 3],
    /// `E_0 + E_1 + E_2`: twice the triangle's area, the same at every point.
    pub area2: f64,
    /// The pixel centre `(x + ½, y + ½)`.
    pub centre_position: [f64; 2],
    /// `(E_0, E_1, E_2)` at the pixel centre.
    pub centre: [f64; 3],
    /// `λ_i = E_i / (E_0 + E_1 + E_2)` at the pixel centre: the screen-space barycentrics.
    pub lambda: [f64; 3],
    /// Per sample: its position in window coordinates and `(E_0, E_1, E_2)` there.
    pub samples: Vec<SampleTest>,
}

/// The inside test at one sample.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SampleTest {
    /// The sample's position `(x, y)` in window coordinates.
    pub position: [f64; 2],
    /// `(E_0, E_1, E_2)` there, square pixels.
    pub e: [f64; 3],
    /// The edges the sample lies exactly on (`E_i = 0`), where the fill rule decides.
    pub on_edges: Vec<usize>,
    /// Whether it is covered.
    pub inside: bool,
}

impl EdgeTest {
    /// The test of `tri` at the pixel whose bottom-left corner is `corner` (fixed point), with
    /// samples at `offsets` from it.
    #[must_use]
    pub fn of(tri: &RasterTriangle, corner: I64Vec2, offsets: &[I64Vec2]) -> Self {
        let unit = (ONE * ONE) as f64;
        let px = |e: [i64; 3]| e.map(|v| v as f64 / unit);
        let centre_fixed = corner + I64Vec2::splat(ONE / 2);
        let centre = px(tri.edge_values(centre_fixed));
        let area2 = tri.area2() as f64 / unit;
        let samples = offsets
            .iter()
            .map(|off| {
                let p = corner + *off;
                let e = tri.edge_values(p);
                SampleTest {
                    position: [p.x as f64 / ONE as f64, p.y as f64 / ONE as f64],
                    e: px(e),
                    on_edges: (0..3).filter(|&k| e[k] == 0).collect(),
                    inside: tri.covers(p),
                }
            })
            .collect();
        Self {
            corners: tri.window.map(|w| {
                let s = |v: f32| snap(v) as f64 / ONE as f64;
                [s(w.x), s(w.y)]
            }),
            top_left: tri.top_left(),
            area2,
            centre_position: [
                centre_fixed.x as f64 / ONE as f64,
                centre_fixed.y as f64 / ONE as f64,
            ],
            centre,
            lambda: centre.map(|e| e / area2),
            samples,
        }
    }
}

/// Everything the capture knows about one pixel: what reached it and what it computed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelRecord {
    /// Window column.
    pub x: u32,
    /// Window row (0 at the bottom).
    pub y: u32,
    /// Covered samples.
    pub coverage: u8,
    /// Mean window depth of the samples.
    pub depth: f32,
    /// The final colour.
    pub color: [f32; 3],
    /// The owning primitive, if any.
    pub primitive: Option<u32>,
    /// The owning fragment's lighting terms (when lit).
    pub lighting: Option<PixelLighting>,
    /// The owning fragment's texture lookup (when textured).
    pub texture: Option<PixelTexture>,
    /// The lighting vectors there (when lit).
    pub vectors: Option<PixelVectors>,
    /// Every fragment that reached the pixel, in drawing order.
    pub fragments: Vec<FragmentRecord>,
    /// The pixel's colour derived step by step, when something was drawn there.
    pub explanation: Option<PixelExplanation>,
}

/// The vectors of the lighting at a pixel, in world coordinates: where the surface is, its unit
/// normal, and the unit vectors to the key light, to the eye and halfway between them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PixelVectors {
    /// The surface point `p = Σ b_i·p_i` of the owning fragment.
    pub position: Vec3,
    /// `n`, as lit.
    pub normal: Vec3,
    /// `l`, towards the key light (the first light that is not ambient).
    pub light: Vec3,
    /// `v = normalize(eye − p)`.
    pub view: Vec3,
    /// `h = normalize(l + v)`.
    pub half: Vec3,
    /// `r = 2(n·l)n − l`, the mirror direction of `l` (Phong's specular term compares it with
    /// `v`).
    pub reflected: Vec3,
}

/// A lighting vector drawn at the inspected pixel: its name, its arrow in image pixels (the
/// world vector from the surface point, 0.15 of the distance to the eye long), and its colour.
#[derive(Clone, Debug, PartialEq)]
pub struct LightingArrow {
    /// `n`, `l`, `v`, `h` or `r`.
    pub name: &'static str,
    /// Tail and head in image pixels (x right, y down).
    pub from: [f32; 2],
    /// Head.
    pub to: [f32; 2],
    /// Colour.
    pub color: [u8; 4],
}

impl FrameCapture {
    /// The lighting vectors at window pixel `(x, y)` as arrows in the image: the normal (white),
    /// to the light (amber), to the eye (grey), the half vector (cyan) and the mirror direction
    /// (pink). The app and the exported pictures draw these.
    #[must_use]
    pub fn lighting_arrows(&self, x: u32, y: u32) -> Vec<LightingArrow> {
        let Some(v) = self.pixel_vectors(x, y) else {
            return Vec::new();
        };
        let length = 0.15 * (self.camera.eye - v.position).length();
        [
            (v.normal, "n", [255, 255, 255, 255]),
            (v.light, "l", [255, 210, 60, 255]),
            (v.view, "v", [150, 150, 150, 255]),
            (v.half, "h", [90, 220, 255, 255]),
            (v.reflected, "r", [255, 120, 200, 255]),
        ]
        .into_iter()
        .filter_map(|(vector, name, color)| {
            let [from, to] =
                self.world_segment_to_image(v.position, v.position + vector * length)?;
            Some(LightingArrow {
                name,
                from,
                to,
                color,
            })
        })
        .collect()
    }
}

/// One sample of an intensity profile along a line of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ProfileSample {
    /// Position along the line, 0 at its start, 1 at its end.
    pub t: f32,
    /// Image column.
    pub x: u32,
    /// Image row (0 at the top).
    pub y: u32,
    /// The final colour there.
    pub rgb: [f32; 3],
    /// Luminance `0.2126·R + 0.7152·G + 0.0722·B` (Rec. 709 weights).
    pub intensity: f32,
}

impl FrameCapture {
    /// The lighting vectors at window pixel `(x, y)`: `None` where nothing is drawn, lighting
    /// is off, or no light has a direction.
    #[must_use]
    pub fn pixel_vectors(&self, x: u32, y: u32) -> Option<PixelVectors> {
        let i = self.grid().checked_index(x, y)?;
        let prim = self.primitives.get(self.pixels.primitive[i] as usize)?;
        let normal = Vec3::from(self.pixels.lighting_at(i)?.normal);
        let b = self.barycentrics(i)?.perspective;
        let position = prim
            .vertices
            .iter()
            .zip(b)
            .map(|(&r, w)| self.vertices[r as usize].world.truncate() * w)
            .sum::<Vec3>();
        let light = self
            .lights
            .iter()
            .find_map(|l| crate::lighting::light_vector(l, position))?;
        let view = (self.camera.eye - position).normalize_or_zero();
        Some(PixelVectors {
            position,
            normal,
            light,
            view,
            half: (light + view).normalize_or_zero(),
            reflected: 2.0 * normal.dot(light) * normal - light,
        })
    }

    /// Everything about window pixel `(x, y)` (y up): its buffers' values, the owning
    /// fragment's lighting terms and texture lookup, and every fragment that reached it (see
    /// [`Self::fragments_at`]); `None` outside the viewport.
    #[must_use]
    pub fn pixel_record(&self, x: u32, y: u32) -> Option<PixelRecord> {
        let i = self.grid().checked_index(x, y)?;
        let px = &self.pixels;
        let owned = px.primitive[i] != NONE;
        Some(PixelRecord {
            x,
            y,
            coverage: px.coverage[i],
            depth: px.depth[i],
            color: px.color[i],
            primitive: owned.then_some(px.primitive[i]),
            lighting: px.lighting_at(i).filter(|_| owned),
            texture: px.texture_at(i).filter(|_| owned),
            vectors: self.pixel_vectors(x, y),
            fragments: self.fragments_at(x, y),
            explanation: self.explain(x, y),
        })
    }

    /// Every fragment that reached window pixel `(x, y)` (y up), in drawing order, with the
    /// outcome of the depth test at each sample: the raster triangles are replayed against the
    /// pixel's depth values exactly as the rasterizer ran them.
    #[must_use]
    pub fn fragments_at(&self, x: u32, y: u32) -> Vec<FragmentRecord> {
        if x >= self.width() || y >= self.height() {
            return Vec::new();
        }
        let offsets = crate::raster::sample_offsets_fixed(self.settings.samples);
        let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
        let centre = Self::pixel_centre_fixed(x, y);
        let mut stored = vec![self.settings.depth_test.clear_value(); offsets.len()];
        let owner = self.pixels.primitive[self.grid().index(x, y)];
        let mut out = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            let [x0, y0, x1, y1] = tri.bbox.map(u32::from);
            if x < x0 || x > x1 || y < y0 || y > y1 {
                continue;
            }
            let mut samples = vec![None; offsets.len()];
            let mut sample_depths = vec![None; offsets.len()];
            for (s, off) in offsets.iter().enumerate() {
                let p = corner + *off;
                if tri.covers(p) {
                    let z = tri.depth_at(p);
                    let pass = self.settings.depth_test.passes(z, stored[s]);
                    if pass {
                        stored[s] = z;
                    }
                    samples[s] = Some(pass);
                    sample_depths[s] = Some(z);
                }
            }
            if samples.iter().all(Option::is_none) {
                continue;
            }
            let l = tri.lambda(centre);
            let bary = self.primitives[tri.primitive as usize].bary_corners(tri);
            out.push(FragmentRecord {
                primitive: tri.primitive,
                triangle: t as u32,
                samples,
                sample_depths,
                depth: tri.depth_at(centre),
                bary_affine: tri.original_bary(&bary, l, false).to_array(),
                bary_perspective: tri.original_bary(&bary, l, true).to_array(),
                visible: tri.primitive == owner,
                edges: EdgeTest::of(tri, corner, &offsets),
            });
        }
        out
    }

    /// The intensity profile along the segment `from → to` (image pixel coordinates, y down):
    /// one sample per pixel step, each the pixel the point falls in (points off the image are
    /// skipped). This is what the Mach band comparison plots.
    #[must_use]
    pub fn profile(&self, from: [f32; 2], to: [f32; 2]) -> Vec<ProfileSample> {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let steps = dx.abs().max(dy.abs()).ceil().max(1.0) as u32;
        (0..=steps)
            .filter_map(|k| {
                let t = k as f32 / steps as f32;
                let (px, py) = (from[0] + dx * t, from[1] + dy * t);
                if !(px >= 0.0
                    && py >= 0.0
                    && px < self.width() as f32
                    && py < self.height() as f32)
                {
                    return None;
                }
                let (x, y) = (px as u32, py as u32);
                let rgb = self.pixels.color[(y * self.width() + x) as usize];
                let intensity = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
                Some(ProfileSample {
                    t,
                    x,
                    y,
                    rgb,
                    intensity,
                })
            })
            .collect()
    }
}
