//! The images of a capture: each buffer's colour mapping (see `BufferKind::mapping`), the depth
//! buffer over a chosen range or as eye distance, the 16-bit depth, overlays drawn by tiny-skia,
//! and where a world point lands in the image.

use glam::Vec3;
use half::f16;
use image::{ImageBuffer, Luma, Rgba, RgbaImage};

use super::{FrameCapture, ShadingBuffers, TextureBuffers};
use crate::buffers::BufferKind;
use crate::overlay::{self, Overlay, OverlayKind, Shape};
use crate::raster::{NONE, RasterTriangle};

fn to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn hue_color(id: u32) -> [u8; 3] {
    hue((id as f32 * 0.618_034).fract()).map(to_u8)
}

/// The fully saturated colour of hue `h ∈ [0, 1)` (red, yellow, green, cyan, blue, magenta).
fn hue(h: f32) -> [f32; 3] {
    let h = h.rem_euclid(1.0) * 6.0;
    let x = 1.0 - ((h % 2.0) - 1.0).abs();
    match h as u32 {
        0 => [1.0, x, 0.0],
        1 => [x, 1.0, 0.0],
        2 => [0.0, 1.0, x],
        3 => [0.0, x, 1.0],
        4 => [x, 0.0, 1.0],
        _ => [1.0, 0.0, x],
    }
}

/// The colour of a lighting buffer at pixel `i`, a term's radiance multiplied by `gain`.
fn lighting_rgb(sh: &ShadingBuffers, kind: BufferKind, i: usize, gain: f32) -> [u8; 3] {
    let rgb = |v: [f16; 3]| v.map(|c| to_u8(c.to_f32() * gain));
    match kind {
        BufferKind::Ambient => rgb(sh.ambient[i]),
        BufferKind::Diffuse => rgb(sh.diffuse[i]),
        BufferKind::Specular => rgb(sh.specular[i]),
        BufferKind::Normal => sh.normal[i].map(|v| to_u8((v.to_f32() + 1.0) / 2.0)),
        BufferKind::NDotL => [to_u8(sh.n_dot_l[i].to_f32()); 3],
        BufferKind::NDotH => [to_u8(sh.n_dot_h[i].to_f32()); 3],
        BufferKind::Reflected => rgb(sh.reflected[i]),
        _ => [0; 3],
    }
}

/// The footprint colour: the long axis' angle `θ ∈ [0°, 180°)` as hue (a line has no sign, so
/// hue = 2θ), the anisotropy `a = major/minor` as saturation `min(log₂ a / 3, 1)`.
fn footprint_rgb([sx, tx, sy, ty]: [f32; 4]) -> [u8; 3] {
    let (lx, ly) = (sx.hypot(tx), sy.hypot(ty));
    if lx == 0.0 && ly == 0.0 {
        return [0; 3];
    }
    let (major, minor, (s, t)) = if lx >= ly {
        (lx, ly, (sx, tx))
    } else {
        (ly, lx, (sy, ty))
    };
    let angle = t.atan2(s).rem_euclid(std::f32::consts::PI);
    let saturation = ((major / minor.max(1e-6)).log2() / 3.0).clamp(0.0, 1.0);
    hue(angle / std::f32::consts::PI).map(|c| to_u8(1.0 - saturation * (1.0 - c)))
}

/// Where a covered pixel's surface has no texture, in the texturing buffers' images.
const UNTEXTURED: [u8; 3] = [48, 48, 56];

/// The colour of a texturing buffer at pixel `i`.
fn texturing_rgb(tb: &TextureBuffers, kind: BufferKind, i: usize) -> [u8; 3] {
    if tb.level[i].to_f32() < 0.0 {
        return UNTEXTURED;
    }
    match kind {
        BufferKind::Uv => {
            let [u, v] = tb.uv[i];
            [to_u8(u.rem_euclid(1.0)), to_u8(v.rem_euclid(1.0)), 0]
        }
        BufferKind::MipLevel => {
            let l = tb.level[i].to_f32();
            let k = l.floor().max(0.0) as u32;
            crate::texture::level_color(k)
                .lerp(crate::texture::level_color(k + 1), l.fract())
                .to_array()
                .map(to_u8)
        }
        BufferKind::Texel => tb.texel[i].map(|c| to_u8(c.to_f32())),
        BufferKind::Footprint => footprint_rgb(tb.footprint[i].map(f16::to_f32)),
        _ => [0; 3],
    }
}

/// The gains a dim lighting term's picture may be drawn with ([`FrameCapture::term_gain`]):
/// one and a half and the powers of two, each doubled, up to 16 — a step of at most 1.5, so
/// that a term is shown at ⅔ or more of full brightness, in factors that read at a glance.
pub const TERM_GAINS: [f32; 9] = [1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0];

/// The faint grey-blue of an object's outline over a lighting term's picture
/// ([`FrameCapture::outline_objects`]).
pub const OUTLINE: [u8; 3] = [70, 78, 96];

impl FrameCapture {
    /// The image of one buffer (see [`BufferKind`] for each colour mapping).
    #[must_use]
    pub fn image(&self, kind: BufferKind) -> RgbaImage {
        self.image_gained(kind, 1.0)
    }

    /// How much brighter a lighting term's picture is drawn than its values, so that a dim
    /// term can be seen on a projector: the largest of [`TERM_GAINS`] (1, 1.5, 2, 3, … 16)
    /// with `g·max ≤ 1`, where `max` is the term's largest channel over the covered pixels
    /// (1 when `max > ⅔`, for a buffer that is not a term, or for an empty one). The ambient
    /// term `k_a·I_a = 0.16` is shown ×6, as 0.96; lesson 10's diffuse term, whose reddest
    /// channel peaks at 0.54, ×1.5, as 0.81.
    #[must_use]
    pub fn term_gain(&self, kind: BufferKind) -> f32 {
        let Some(sh) = &self.pixels.shading else {
            return 1.0;
        };
        let term = match kind {
            BufferKind::Ambient => &sh.ambient,
            BufferKind::Diffuse => &sh.diffuse,
            BufferKind::Specular => &sh.specular,
            _ => return 1.0,
        };
        let max = term
            .iter()
            .zip(&self.pixels.primitive)
            .filter(|(_, p)| **p != NONE)
            .flat_map(|(v, _)| v.iter().map(|c| c.to_f32()))
            .fold(0.0_f32, f32::max);
        if !(max > 0.0) {
            return 1.0;
        }
        TERM_GAINS
            .iter()
            .copied()
            .filter(|g| g * max <= 1.0)
            .fold(1.0, f32::max)
    }

    /// One gain for captures shown side by side, so that their terms stay comparable: the
    /// smallest of their [`Self::term_gain`]s (1 for none).
    #[must_use]
    pub fn shared_term_gain<'a>(
        captures: impl IntoIterator<Item = &'a FrameCapture>,
        kind: BufferKind,
    ) -> f32 {
        captures
            .into_iter()
            .map(|c| c.term_gain(kind))
            .reduce(f32::min)
            .unwrap_or(1.0)
    }

    /// The image of `kind` with the lighting terms' radiance multiplied by `gain` (see
    /// [`Self::term_gain`]; other buffers ignore it) — what the app and a lesson's pictures
    /// show, saying so, while the exported buffers keep the values (`gain` 1).
    #[must_use]
    pub fn image_gained(&self, kind: BufferKind, gain: f32) -> RgbaImage {
        if kind == BufferKind::Depth {
            return self.depth_image(false, None);
        }
        let (w, h) = (self.width(), self.height());
        let px = &self.pixels;
        let samples = self.settings.samples.count() as f32;
        ImageBuffer::from_fn(w, h, |x, y| {
            let i = (y * w + x) as usize;
            let covered = px.primitive[i] != NONE;
            let rgb = match kind {
                BufferKind::Color => px.color[i].map(to_u8),
                BufferKind::Depth => [255; 3], // drawn by depth_image
                BufferKind::Coverage => [to_u8(f32::from(px.coverage[i]) / samples); 3],
                BufferKind::PrimitiveId if covered => hue_color(px.primitive[i]),
                BufferKind::BaryPerspective if covered => self
                    .barycentrics(i)
                    .map_or([0; 3], |b| b.perspective.map(to_u8)),
                BufferKind::BaryAffine if covered => {
                    self.barycentrics(i).map_or([0; 3], |b| b.affine.map(to_u8))
                }
                BufferKind::PrimitiveId | BufferKind::BaryPerspective | BufferKind::BaryAffine => {
                    [0; 3]
                }
                k if k.is_texturing() => match (&px.texturing, covered) {
                    (Some(tb), true) => texturing_rgb(tb, k, i),
                    _ => [0; 3],
                },
                k => match (&px.shading, covered) {
                    (Some(sh), true) => lighting_rgb(sh, k, i, gain),
                    _ => [0; 3],
                },
            };
            Rgba([rgb[0], rgb[1], rgb[2], 255])
        })
    }

    /// The picture of buffer `kind` as the app and a lesson's pictures show it: its terms
    /// ×`gain` ([`Self::image_gained`]) and, for a lighting term, each object's outline
    /// ([`Self::outline_objects`]), so that a highlight reads as on a sphere and a side facing
    /// away keeps its edge. The exported buffers keep the values alone ([`Self::image`]).
    #[must_use]
    pub fn image_shown(&self, kind: BufferKind, gain: f32) -> RgbaImage {
        let mut img = self.image_gained(kind, gain);
        if matches!(
            kind,
            BufferKind::Ambient | BufferKind::Diffuse | BufferKind::Specular
        ) {
            self.outline_objects(&mut img);
        }
        img
    }

    /// Draws each object's silhouette into `img` (this capture's size): a covered pixel with a
    /// 4-neighbour not covered or covered by another object is made at least [`OUTLINE`] in
    /// each channel — faint, under any term brighter than it. The frame's border is no edge.
    pub fn outline_objects(&self, img: &mut RgbaImage) {
        let (w, h) = (self.width(), self.height());
        if img.dimensions() != (w, h) {
            return;
        }
        let object = |x: u32, y: u32| {
            let p = self.pixels.primitive[(y * w + x) as usize];
            (p != NONE).then(|| self.primitives.get(p as usize).map(|r| r.object))
        };
        for y in 0..h {
            for x in 0..w {
                let Some(me) = object(x, y) else {
                    continue;
                };
                let edge = [(-1, 0), (1, 0), (0, -1), (0, 1)].iter().any(|(dx, dy)| {
                    let (nx, ny) = (x as i64 + dx, y as i64 + dy);
                    (0..i64::from(w)).contains(&nx)
                        && (0..i64::from(h)).contains(&ny)
                        && object(nx as u32, ny as u32) != Some(me)
                });
                if edge {
                    let px = img.get_pixel_mut(x, y);
                    for (c, o) in px.0.iter_mut().zip(OUTLINE) {
                        *c = (*c).max(o);
                    }
                }
            }
        }
    }

    /// The eye-space distance along −z of window depth `z_w` (see `Projection::eye_distance`).
    #[must_use]
    pub fn eye_depth(&self, z_w: f32) -> f32 {
        self.projection.eye_distance(z_w)
    }

    /// The depth buffer as grey over `range` (black at its start, white at its end), of window
    /// depth `z_w`, or of eye distance ([`Self::eye_depth`]) when `linear`. Without a range, the
    /// nearest and farthest covered values. Background white.
    #[must_use]
    pub fn depth_image(&self, linear: bool, range: Option<[f32; 2]>) -> RgbaImage {
        let value = |z: f32| if linear { self.eye_depth(z) } else { z };
        let [lo, hi] = range.unwrap_or_else(|| {
            self.depth_range()
                .map_or([0.0, 1.0], |[a, b]| [value(a), value(b)])
        });
        let span = (hi - lo).abs().max(f32::EPSILON);
        let w = self.width();
        ImageBuffer::from_fn(w, self.height(), |x, y| {
            let i = (y * w + x) as usize;
            let g = if self.pixels.primitive[i] == NONE {
                255
            } else {
                to_u8((value(self.pixels.depth[i]) - lo) / span)
            };
            Rgba([g, g, g, 255])
        })
    }

    /// The depth buffer as 16-bit grey, `round(z_w·65535)`, with no stretching.
    #[must_use]
    pub fn depth16(&self) -> ImageBuffer<Luma<u16>, Vec<u16>> {
        let w = self.width();
        ImageBuffer::from_fn(w, self.height(), |x, y| {
            let d = self.pixels.depth[(y * w + x) as usize];
            Luma([(d.clamp(0.0, 1.0) * 65535.0).round() as u16])
        })
    }

    /// The window depth of every pixel as 32-bit floats, exactly as resolved (the mean of the
    /// pixel's sample depths), in a Portable Float Map: the header `Pf\n{width} {height}\n-1.0\n`
    /// (one channel; the negative scale says little-endian), then the rows from the **bottom**
    /// up, which is window order (y up).
    #[must_use]
    pub fn depth_pfm(&self) -> Vec<u8> {
        let (w, h) = (self.width() as usize, self.height() as usize);
        let mut bytes = format!("Pf\n{w} {h}\n-1.0\n").into_bytes();
        bytes.reserve(w * h * 4);
        for row in self.pixels.depth.chunks(w.max(1)).rev() {
            bytes.extend(row.iter().flat_map(|d| d.to_le_bytes()));
        }
        bytes
    }

    /// Converts window coordinates (y up) to image pixel coordinates (y down).
    #[must_use]
    pub fn window_to_image(&self, p: Vec3) -> [f32; 2] {
        [p.x, self.height() as f32 - p.y]
    }

    /// The shapes of one overlay, in image pixel coordinates.
    #[must_use]
    pub fn overlay(&self, kind: OverlayKind) -> Overlay {
        Overlay {
            kind,
            shapes: self.overlay_shapes(kind).collect(),
        }
    }

    /// The shapes of one overlay, made one raster triangle at a time (a view that draws only
    /// some of a million need not build them all).
    pub fn overlay_shapes(&self, kind: OverlayKind) -> impl Iterator<Item = Shape> + '_ {
        self.triangles
            .iter()
            .map(move |t| self.overlay_shape(kind, t, Emphasis::Normal))
    }

    /// The shapes of one overlay as a picture of the rasterizer shows them: only the triangles
    /// that own a sample after the depth test (`visible`, from [`Self::visible_triangles`]; all
    /// when `None`), the pieces of primitive `focus` (the one under the pointer, or the
    /// inspected pixel's) strongly and the rest faintly (all of them, without a focus).
    pub fn overlay_shapes_focused<'a>(
        &'a self,
        kind: OverlayKind,
        visible: Option<&'a [bool]>,
        focus: Option<u32>,
    ) -> impl Iterator<Item = Shape> + 'a {
        self.triangles
            .iter()
            .enumerate()
            .filter(move |(i, _)| visible.is_none_or(|v| v.get(*i).copied().unwrap_or(true)))
            .map(move |(_, t)| {
                let emphasis = match focus {
                    Some(p) if p == t.primitive => Emphasis::Strong,
                    _ => Emphasis::Faint,
                };
                self.overlay_shape(kind, t, emphasis)
            })
    }

    /// The smallest box of image pixels holding every covered pixel, `[x0, y0, x1, y1)` with
    /// rows counted from the top (as in [`Self::image`]); `None` when nothing is covered.
    #[must_use]
    pub fn covered_box(&self) -> Option<[u32; 4]> {
        let w = self.width() as usize;
        let mut b: Option<[u32; 4]> = None;
        for (i, _) in self
            .pixels
            .primitive
            .iter()
            .enumerate()
            .filter(|(_, p)| **p != NONE)
        {
            let (x, y) = ((i % w) as u32, (i / w) as u32);
            b = Some(match b {
                None => [x, y, x + 1, y + 1],
                Some([x0, y0, x1, y1]) => [x0.min(x), y0.min(y), x1.max(x + 1), y1.max(y + 1)],
            });
        }
        b
    }

    /// Which raster triangles own at least one sample after the depth test (indexed as
    /// [`Self::triangles`]); `None` when the frame kept no per-sample owners. The others are
    /// hidden (the back of a closed mesh) or cover no sample.
    #[must_use]
    pub fn visible_triangles(&self) -> Option<Vec<bool>> {
        if self.samples.triangle.is_empty() {
            return None;
        }
        let mut visible = vec![false; self.triangles.len()];
        for &t in &self.samples.triangle {
            if let Some(v) = visible.get_mut(t as usize) {
                *v = true;
            }
        }
        Some(visible)
    }

    /// Where each object's name goes in the image (pixels, y down): above the top of its world
    /// bounding box, at the box's centre in x and z; `None` for an object with no vertex in
    /// front of the camera or whose point falls outside the image.
    #[must_use]
    pub fn object_label_points(&self) -> Vec<Option<[f32; 2]>> {
        let mut boxes: Vec<Option<(Vec3, Vec3)>> = vec![None; self.objects.len()];
        for v in &self.vertices {
            let Some(b) = boxes.get_mut(v.object as usize) else {
                continue;
            };
            let p = v.world.truncate();
            *b = Some(b.map_or((p, p), |(lo, hi)| (lo.min(p), hi.max(p))));
        }
        let (w, h) = (self.width() as f32, self.height() as f32);
        boxes
            .into_iter()
            .map(|b| {
                let (lo, hi) = b?;
                let top = Vec3::new((lo.x + hi.x) / 2.0, hi.y, (lo.z + hi.z) / 2.0);
                self.world_to_image(top)
                    .filter(|&[x, y]| (0.0..w).contains(&x) && (0.0..h).contains(&y))
            })
            .collect()
    }

    /// The primitive whose fragment pixel `(x, y)` (window, y up) shows, if any.
    #[must_use]
    pub fn primitive_at(&self, x: u32, y: u32) -> Option<u32> {
        let i = self.grid().checked_index(x, y)?;
        let p = *self.pixels.primitive.get(i)?;
        (p != NONE).then_some(p)
    }

    /// One raster triangle's shape in overlay `kind`, drawn with `emphasis`.
    fn overlay_shape(&self, kind: OverlayKind, t: &RasterTriangle, emphasis: Emphasis) -> Shape {
        let h = self.height() as f32;
        let (alpha, width) = match emphasis {
            Emphasis::Normal => (1.0, 1.0),
            Emphasis::Strong => (1.0, 2.5),
            Emphasis::Faint => (0.3, 1.0),
        };
        let fade = |a: u8| (f32::from(a) * alpha) as u8;
        match kind {
            OverlayKind::TriangleEdges => Shape::Polyline {
                points: t.window.iter().map(|p| self.window_to_image(*p)).collect(),
                closed: true,
                color: [255, 255, 255, fade(220)],
                width,
            },
            OverlayKind::BoundingBoxes => {
                let [x0, y0, x1, y1] = t.bbox.map(f32::from);
                Shape::Rect {
                    min: [x0, h - (y1 + 1.0)],
                    max: [x1 + 1.0, h - y0],
                    color: [255, 200, 40, fade(200)],
                    width,
                }
            }
        }
    }

    /// `kind`'s image magnified `zoom` times (nearest neighbour, so pixels stay crisp) with the
    /// given overlays drawn over it by tiny-skia.
    #[must_use]
    pub fn image_with_overlays(
        &self,
        kind: BufferKind,
        overlays: &[OverlayKind],
        zoom: u32,
    ) -> RgbaImage {
        let shapes: Vec<Shape> = overlays
            .iter()
            .flat_map(|&k| self.overlay(k).shapes)
            .collect();
        self.image_with_shapes(kind, 1.0, &shapes, zoom)
    }

    /// Where world point `p` lands in the image (pixels, y down): `P·V·p`, divided by `w`, through
    /// the viewport; `None` behind the camera (`w ≤ 1e-5`).
    #[must_use]
    pub fn world_to_image(&self, p: Vec3) -> Option<[f32; 2]> {
        let clip = self.matrices.projection.matrix * self.matrices.view.matrix * p.extend(1.0);
        self.clip_to_image(clip)
    }

    fn clip_to_image(&self, clip: glam::Vec4) -> Option<[f32; 2]> {
        (clip.w > 1e-5).then(|| {
            let (w, h) = (self.width() as f32, self.height() as f32);
            let ndc = clip.truncate() / clip.w;
            [(ndc.x + 1.0) * w / 2.0, h - (ndc.y + 1.0) * h / 2.0]
        })
    }

    /// The world segment `a`–`b` in image pixels, the part behind the camera cut away (at
    /// `w = 1e-5` in clip space, as clipping does); `None` when all of it is behind.
    #[must_use]
    pub fn world_segment_to_image(&self, a: Vec3, b: Vec3) -> Option<[[f32; 2]; 2]> {
        let pv = self.matrices.projection.matrix * self.matrices.view.matrix;
        let (ca, cb) = crate::clip::segment_in_front(pv * a.extend(1.0), pv * b.extend(1.0))?;
        Some([self.clip_to_image(ca)?, self.clip_to_image(cb)?])
    }

    /// The picture of buffer `kind` with its terms ×`gain` ([`Self::image_shown`]), magnified
    /// `zoom`× (nearest), with `shapes` drawn over it.
    #[must_use]
    pub fn image_with_shapes(
        &self,
        kind: BufferKind,
        gain: f32,
        shapes: &[Shape],
        zoom: u32,
    ) -> RgbaImage {
        overlay::magnified_with_shapes(&self.image_shown(kind, gain), shapes, zoom)
    }

    /// The depth buffer as grey over the window-depth range `range` (black at its first end,
    /// white at its second; `None`: the image's own nearest and farthest), magnified `zoom`×
    /// with `shapes` drawn over it — the image a lesson step with `depth_range` shows.
    #[must_use]
    pub fn depth_image_with_shapes(
        &self,
        range: Option<[f32; 2]>,
        shapes: &[Shape],
        zoom: u32,
    ) -> RgbaImage {
        overlay::magnified_with_shapes(&self.depth_image(false, range), shapes, zoom)
    }
}

/// How strongly an overlay draws a triangle.
#[derive(Clone, Copy)]
enum Emphasis {
    Normal,
    Strong,
    Faint,
}
