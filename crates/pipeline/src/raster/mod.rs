//! Rasterization: from a triangle in window coordinates to the samples it covers.
//!
//! **Window coordinates** have their origin at the bottom-left corner of the viewport, x to the
//! right, y up (OpenGL's convention); pixel `(i, j)` is the square `[i, i+1] × [j, j+1]` and its
//! centre is `(i + ½, j + ½)`. Images are stored top row first, so pixel row `j` is image row
//! `height − 1 − j`.
//!
//! **Snapping.** Vertex positions are snapped to a grid of 1/256 pixel ([`SUBPIXEL_BITS`] = 8) and
//! every inside test is done on integers, exactly: two triangles that share an edge see the same
//! edge function with opposite signs, so each sample on the edge goes to exactly one of them.
//!
//! **Edge functions.** For the edge `a → b`, `E(p) = (b.x − a.x)·(p.y − a.y) − (b.y − a.y)·(p.x − a.x)`,
//! twice the signed area of the triangle `a, b, p`. Triangles are made counter-clockwise first,
//! so that `E ≥ 0` on the inside of all three edges; `E_i` is the edge opposite vertex `i`, and the
//! screen-space barycentric weights are `λ_i = E_i / (E_0 + E_1 + E_2)`.
//!
//! **Fill rule (top-left).** A sample exactly on an edge (`E = 0`) belongs to the triangle only if
//! that edge is a *top* edge (horizontal, the triangle below it) or a *left* edge (the triangle to
//! its right), as seen on screen. For a counter-clockwise triangle with y up: a top edge has
//! `Δy = 0, Δx < 0`; a left edge has `Δy < 0`.
//!
//! **Depth** is `z_w = λ_0·z_0 + λ_1·z_1 + λ_2·z_2`, linear in screen space (NDC z is an affine
//! function of screen x, y across a triangle). **Attributes** are interpolated perspective-correctly,
//! `b_i = (λ_i / w_i) / Σ_k (λ_k / w_k)`, or affinely (`b_i = λ_i`) for comparison.
//!
//! Triangle setup and the inside test are here; the sample patterns in [`samples`]; the sample
//! buffers (the z-buffer), the depth test and rasterizing into them in [`zbuffer`].

mod bins;
mod cleared;
mod covered;
mod samples;
mod student_functions;
mod zbuffer;

pub use bins::RasterCounts;
pub(crate) use covered::CoveredRows;
pub use samples::*;
pub use zbuffer::*;

use glam::{I64Vec2, Vec2, Vec3};

use crate::clip::ClipVertex;
use serde::Serialize;

/// Bits of sub-pixel precision of snapped vertex positions.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed-point units.
pub const ONE: i64 = 1 << SUBPIXEL_BITS;
// A position within a pixel fits a byte (`RasterTriangle::box_within`).
const _: () = assert!(ONE == 256);
/// The primitive / triangle id of a sample nothing covered.
pub const NONE: u32 = u32::MAX;

/// Snaps a window coordinate to the sub-pixel grid: the nearest multiple of 1/256 pixel, a tie
/// going to the even one (the processor's default rounding, which Mesa's llvmpipe snaps with;
/// rounding ties away from zero would move a vertex at exactly k + ½ of 1/256 pixel one step
/// further and change a pixel's coverage against it).
#[must_use]
#[inline]
pub fn snap(v: f32) -> i64 {
    // 1.5·2⁵²: adding it leaves no bits below the units, so the sum is rounded to an integer
    // by the processor's rounding (to nearest, ties to even), and subtracting it is exact —
    // `round_ties_even` without a call to libm's `rint` (x86-64's baseline has no `roundsd`).
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    let x = f64::from(v) * ONE as f64;
    if x.abs() < ROUNDER / 3.0 {
        (x + ROUNDER - ROUNDER) as i64
    } else {
        x.round_ties_even() as i64
    }
}

/// A window position's `x` and `y` snapped to the sub-pixel grid ([`snap`]), in fixed point.
#[must_use]
#[inline]
pub fn snap_xy(p: Vec3) -> I64Vec2 {
    I64Vec2::new(snap(p.x), snap(p.y))
}

/// A triangle ready to be rasterized: snapped, counter-clockwise, with its edge equations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct RasterTriangle {
    /// The primitive (input triangle) this piece belongs to.
    pub primitive: u32,
    /// Window coordinates `(x, y, z_w)` of the corners, counter-clockwise.
    pub window: [Vec3; 3],
    /// `1/w_clip` of the corners (for perspective-correct interpolation).
    pub inv_w: [f32; 3],
    /// Where the corners lie in the original triangle (their barycentric weights, from
    /// [`Self::bary_corners`]): an index per corner, of the primitive's own corners or of its
    /// clipped polygon's vertices — 4 bytes instead of 36 weights, of which an unclipped
    /// triangle, nearly every one, has no need.
    #[serde(skip)]
    corners: Corners,
    /// Pixel bounding box `[x_min, y_min, x_max, y_max]` (inclusive, window pixels, y up),
    /// clamped to the viewport, whose sides (at most 16 384 pixels) fit 16 bits: 8 bytes less
    /// of the memory a million triangles are written, moved and read through.
    pub bbox: [u16; 4],
    #[serde(skip)]
    edges: [Edge; 3],
    #[serde(skip)]
    area2: i64,
    /// Which edges are top or left edges (see [`Self::top_left`]).
    #[serde(skip)]
    top_left: [bool; 3],
    /// Where the snapped corners' box starts and ends within the first and last pixels of
    /// `bbox` (`x_lo, y_lo, x_hi, y_hi`, in 1/256 pixel; see [`Self::box_holds_a_sample`]).
    #[serde(skip)]
    box_within: [u8; 4],
}

/// Which points of its primitive a raster triangle's corners are: `of[i]` indexes the
/// primitive's corners (weights `(1, 0, 0)`, `(0, 1, 0)`, `(0, 0, 1)`) or, when `clipped`, the
/// vertices of its clipped polygon, whose weights [`ClipVertex::bary`] holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Corners {
    /// The index of each corner.
    pub of: [u8; 3],
    /// Whether they index the clipped polygon rather than the primitive's corners.
    pub clipped: bool,
}

impl Corners {
    /// The primitive's own corners, in order.
    pub const ORIGINAL: Self = Self {
        of: [0, 1, 2],
        clipped: false,
    };

    /// The fan triangle `(0, k, k + 1)` of a clipped polygon.
    #[must_use]
    pub fn fan(k: u8) -> Self {
        Self {
            of: [0, k, k + 1],
            clipped: true,
        }
    }
}

impl Default for Corners {
    fn default() -> Self {
        Self::ORIGINAL
    }
}

/// One edge equation `E(p) = a·p.x + b·p.y + c`. `a` and `b` are differences of two corners'
/// fixed-point coordinates, which [`MAX_FIXED`] keeps within 32 bits: a million triangles are
/// written, moved and read once each a frame, so their size is the rasterizer's memory traffic.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Edge {
    a: i32,
    b: i32,
    c: i64,
}

impl Edge {
    /// The edge `p → q` (corners within [`MAX_FIXED`]), and whether it is a top or left edge:
    /// `Δy = 0, Δx < 0`, or `Δy < 0`.
    fn new(p: I64Vec2, q: I64Vec2) -> (Self, bool) {
        let d = q - p;
        let (a, b) = (-d.y, d.x);
        let top_left = (d.y == 0 && d.x < 0) || d.y < 0;
        let edge = Self {
            a: a as i32,
            b: b as i32,
            c: -(a * p.x + b * p.y),
        };
        (edge, top_left)
    }

    #[inline]
    fn at(&self, p: I64Vec2) -> i64 {
        i64::from(self.a) * p.x + i64::from(self.b) * p.y + self.c
    }
}

/// The largest fixed-point coordinate a corner may have, `2³⁰ − 1` (4 194 304 pixels, far beyond
/// the largest viewport; the pipeline clips every triangle to its viewport first): the difference
/// of two such coordinates fits an `i32`.
pub const MAX_FIXED: i64 = (1 << 30) - 1;

/// A triangle's depth as a plane over fixed-point window positions: `z = c + a·X + b·Y`
/// (see [`RasterTriangle::depth_plane`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthPlane {
    a: f64,
    b: f64,
    c: f64,
}

impl DepthPlane {
    /// The window depth at fixed-point position `p`, clamped to the depth range [0, 1] as
    /// OpenGL clamps a fragment's depth.
    #[must_use]
    #[inline]
    pub fn at(&self, p: I64Vec2) -> f32 {
        (self.c + self.a * p.x as f64 + self.b * p.y as f64).clamp(0.0, 1.0) as f32
    }
}

/// Why a triangle produced no raster triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetupRejection {
    /// Zero area after snapping.
    Degenerate,
    /// Clockwise on screen (a back face) with back-face culling on.
    BackFace,
    /// Counter-clockwise (a front face) with front-face culling on.
    FrontFace,
    /// A corner lies further than [`MAX_FIXED`] from the origin (never, for a triangle clipped
    /// to a viewport).
    OutOfRange,
}

impl RasterTriangle {
    /// Sets up a triangle from window coordinates. Returns the signed orientation test result
    /// through `Err` when it is degenerate or culled.
    ///
    /// # Errors
    /// [`SetupRejection`] when the triangle has no area or is culled.
    pub fn setup(
        primitive: u32,
        window: [Vec3; 3],
        inv_w: [f32; 3],
        corners: Corners,
        cull: CullMode,
        size: (u32, u32),
    ) -> Result<Self, SetupRejection> {
        let fixed = window.map(snap_xy);
        Self::setup_snapped(primitive, (window, fixed), inv_w, corners, cull, size)
    }

    /// [`Self::setup`] of corners whose window positions are already snapped, `fixed[k]` being
    /// [`snap_xy`]`(window[k])`: a vertex shared by several triangles is snapped once.
    ///
    /// # Errors
    /// [`SetupRejection`] when the triangle has no area or is culled.
    pub fn setup_snapped(
        primitive: u32,
        (window, fixed): ([Vec3; 3], [I64Vec2; 3]),
        inv_w: [f32; 3],
        corners: Corners,
        cull: CullMode,
        size: (u32, u32),
    ) -> Result<Self, SetupRejection> {
        debug_assert!((0..3).all(|k| fixed[k] == snap_xy(window[k])));
        if fixed.iter().any(|f| f.abs().max_element() > MAX_FIXED) {
            return Err(SetupRejection::OutOfRange);
        }
        let area2 = (fixed[1] - fixed[0]).perp_dot(fixed[2] - fixed[0]);
        if area2 == 0 {
            return Err(SetupRejection::Degenerate);
        }
        let front = area2 > 0;
        match cull {
            CullMode::Back if !front => return Err(SetupRejection::BackFace),
            CullMode::Front if front => return Err(SetupRejection::FrontFace),
            _ => {}
        }
        // Counter-clockwise: a clockwise triangle's last two corners swapped, each array read
        // once in that order (swapped in place instead, the 1M sphere's setup measured up to
        // 7 ms slower a frame in the same build; BENCHMARKS.md, session 67).
        let order = if front { [0, 1, 2] } else { [0, 2, 1] };
        let fixed = order.map(|k| fixed[k]);
        let window = order.map(|k| window[k]);
        let inv_w = order.map(|k| inv_w[k]);
        let corners = Corners {
            of: order.map(|k| corners.of[k]),
            ..corners
        };
        let [(e0, t0), (e1, t1), (e2, t2)] = [
            Edge::new(fixed[1], fixed[2]),
            Edge::new(fixed[2], fixed[0]),
            Edge::new(fixed[0], fixed[1]),
        ];
        let lo = fixed[0].min(fixed[1]).min(fixed[2]);
        let hi = fixed[0].max(fixed[1]).max(fixed[2]);
        let clamp = |v: i64, max: u32| v.div_euclid(ONE).clamp(0, i64::from(max) - 1) as u16;
        let bbox = [
            clamp(lo.x, size.0),
            clamp(lo.y, size.1),
            clamp(hi.x, size.0),
            clamp(hi.y, size.1),
        ];
        // The box within the viewport's pixels: from `lo` (or the first pixel's start, when
        // `lo` lies before it) to `hi` (or the last pixel's end). A box wholly outside keeps
        // `lo` past `hi` in its one pixel (start 255, end 0), so that it holds no sample.
        let start = |v: i64, pixel: u16| (v - i64::from(pixel) * ONE).clamp(0, ONE - 1);
        let end = |v: i64, pixel: u16| (v - i64::from(pixel) * ONE).clamp(-1, ONE - 1);
        let within = |lo: i64, hi: i64, (first, last): (u16, u16)| {
            let (a, b) = (start(lo, first), end(hi, last));
            if lo >= (i64::from(last) + 1) * ONE || b < 0 {
                (ONE - 1, 0)
            } else {
                (a, b)
            }
        };
        let (x_lo, x_hi) = within(lo.x, hi.x, (bbox[0], bbox[2]));
        let (y_lo, y_hi) = within(lo.y, hi.y, (bbox[1], bbox[3]));
        let box_within = [x_lo, y_lo, x_hi, y_hi].map(|v| v as u8);
        Ok(Self {
            primitive,
            window,
            inv_w,
            corners,
            bbox,
            edges: [e0, e1, e2],
            area2: area2.abs(),
            top_left: [t0, t1, t2],
            box_within,
        })
    }

    /// The edge functions `(E_0, E_1, E_2)` at fixed-point position `p`, in fixed-point units
    /// (`1/ONE²` of a square pixel), without the fill-rule bias; `E_i` belongs to the edge
    /// opposite corner `i` of [`Self::window`].
    #[must_use]
    pub fn edge_values(&self, p: I64Vec2) -> [i64; 3] {
        self.edges.map(|e| e.at(p))
    }

    /// The edge functions at `p` with the fill rule's bias added: `E_i + bias_i ≥ 0` for all
    /// three is the inside test (written out rather than mapped: it runs per row and sample).
    #[must_use]
    #[inline]
    pub(crate) fn biased_edge_values(&self, p: I64Vec2) -> [i64; 3] {
        let (e, t) = (&self.edges, &self.top_left);
        [
            e[0].at(p) + i64::from(t[0]) - 1,
            e[1].at(p) + i64::from(t[1]) - 1,
            e[2].at(p) + i64::from(t[2]) - 1,
        ]
    }

    /// Which edges are top or left edges (`E = 0` on them counts as inside), edge `i` being the
    /// one opposite corner `i`.
    #[must_use]
    pub fn top_left(&self) -> [bool; 3] {
        self.top_left
    }

    /// Twice the triangle's area after snapping, in fixed-point units: `E_0 + E_1 + E_2` at
    /// any point.
    #[must_use]
    pub fn area2(&self) -> i64 {
        self.area2
    }

    /// Whether a sample position of a pixel of the viewport — a pixel corner `(k·ONE, l·ONE)`
    /// plus one of `offsets` — lies in the box of the snapped corners (edges included). When
    /// none does, the triangle covers no sample: of a million triangles at 1280×720 more than
    /// half are such slivers between the pixel centres, and the rasterizer skips them without
    /// scanning their rows. The box is `bbox` with where it starts and ends within its first
    /// and last pixels, kept at setup (not snapped again for every triangle of a frame).
    #[must_use]
    pub fn box_holds_a_sample(&self, offsets: &[I64Vec2]) -> bool {
        let at = |pixel: u16, within: u8| i64::from(pixel) * ONE + i64::from(within);
        let [x0, y0, x1, y1] = self.bbox;
        let [a, b, c, d] = self.box_within;
        let (lo, hi) = (
            I64Vec2::new(at(x0, a), at(y0, b)),
            I64Vec2::new(at(x1, c), at(y1, d)),
        );
        // The first position k·ONE + o at or after `lo` is at or before `hi`.
        let hits = |lo: i64, hi: i64, o: i64| (lo - o + ONE - 1).div_euclid(ONE) * ONE + o <= hi;
        offsets
            .iter()
            .any(|o| hits(lo.x, hi.x, o.x) && hits(lo.y, hi.y, o.y))
    }

    /// Whether the sample at fixed-point position `p` is covered (top-left rule).
    #[must_use]
    #[inline]
    pub fn covers(&self, p: I64Vec2) -> bool {
        self.biased_edge_values(p).iter().all(|&e| e >= 0)
    }

    /// Screen-space barycentric weights `λ` at a fixed-point position (extrapolated outside).
    #[must_use]
    #[inline]
    pub fn lambda(&self, p: I64Vec2) -> Vec3 {
        self.lambda_with(self.inv_area2(), p)
    }

    /// `1 / area2`, what [`Self::lambda_with`] multiplies the edge values by.
    #[must_use]
    #[inline]
    pub fn inv_area2(&self) -> f64 {
        1.0 / self.area2 as f64
    }

    /// [`Self::lambda`] with the inverse of the doubled area, `inv` ([`Self::inv_area2`]), computed
    /// once for the many positions of one triangle (the same bits: the same operations).
    #[must_use]
    #[inline]
    pub fn lambda_with(&self, inv: f64, p: I64Vec2) -> Vec3 {
        let l1 = self.edges[1].at(p) as f64 * inv;
        let l2 = self.edges[2].at(p) as f64 * inv;
        Vec3::new((1.0 - l1 - l2) as f32, l1 as f32, l2 as f32)
    }

    /// The depth plane `z = c + a·X + b·Y` over fixed-point window positions `(X, Y)`, through
    /// the three window positions **as computed** (not snapped): the triangle's own plane, as
    /// OpenGL interpolates z from the vertices' window coordinates, and as Mesa's llvmpipe
    /// does, so the two agree to float rounding even on steep and sliver triangles (snapping
    /// moves a vertex up to 1/512 pixel, which on a plane rising 0.03 per pixel is 6e-5).
    /// Snapping decides coverage only. A triangle whose unsnapped positions are collinear (or
    /// turn the other way, so that snapping alone gave it its area) takes the plane through
    /// its snapped corners instead.
    #[must_use]
    pub fn depth_plane(&self) -> DepthPlane {
        let plane = |p: [glam::DVec3; 3]| {
            let (d1, d2) = (p[1] - p[0], p[2] - p[0]);
            let det = d1.x * d2.y - d2.x * d1.y;
            (det > 0.0).then(|| {
                let a = (d1.z * d2.y - d2.z * d1.y) / det;
                let b = (d1.x * d2.z - d2.x * d1.z) / det;
                (a, b, p[0].z - a * p[0].x - b * p[0].y)
            })
        };
        let exact = self
            .window
            .map(|w| glam::DVec3::new(w.x.into(), w.y.into(), w.z.into()));
        let snapped = || {
            self.window.map(|w| {
                let f = snap_xy(w).as_dvec2() / ONE as f64;
                glam::DVec3::new(f.x, f.y, w.z.into())
            })
        };
        let (a, b, c) = plane(exact).or_else(|| plane(snapped())).unwrap_or((
            0.0,
            0.0,
            f64::from(self.window[0].z),
        ));
        let unit = 1.0 / ONE as f64;
        DepthPlane {
            a: a * unit,
            b: b * unit,
            c,
        }
    }

    /// Window depth at a fixed-point position, on [`Self::depth_plane`] (clamped to the depth
    /// range [0, 1]).
    #[must_use]
    pub fn depth_at(&self, p: I64Vec2) -> f32 {
        self.depth_plane().at(p)
    }

    /// The corners' barycentric weights with respect to the original triangle, `bary_i`:
    /// unit weights for the primitive's own corners, the clipped polygon's weights for a piece
    /// of it (`polygon`: the primitive's clipped polygon, `None` when it was not clipped).
    #[must_use]
    #[inline]
    pub fn bary_corners(&self, polygon: Option<&[ClipVertex]>) -> [Vec3; 3] {
        match polygon {
            Some(poly) if self.corners.clipped => self.corners.of.map(|i| poly[i as usize].bary),
            _ => self.corners.of.map(|i| Vec3::AXES[i as usize % 3]),
        }
    }

    /// Barycentric weights of the **original** triangle at screen-space weights `λ`, the
    /// corners' weights being `bary` ([`Self::bary_corners`]): perspective-correct,
    /// `b = Σ (λ_i/w_i)·bary_i / Σ (λ_i/w_i)`, or affine, `b = Σ λ_i·bary_i`.
    #[must_use]
    #[inline]
    pub fn original_bary(&self, bary: &[Vec3; 3], l: Vec3, perspective_correct: bool) -> Vec3 {
        let k = if perspective_correct {
            let k = l * Vec3::from(self.inv_w);
            k / (k.x + k.y + k.z)
        } else {
            l
        };
        bary[0] * k.x + bary[1] * k.y + bary[2] * k.z
    }

    /// `uv = Σ b_i·uv_i` at fixed-point position `p`, over the original triangle's `uvs`.
    #[inline]
    fn uv_of(
        &self,
        bary: &[Vec3; 3],
        uvs: [Vec2; 3],
        p: I64Vec2,
        perspective_correct: bool,
    ) -> Vec2 {
        let w = self.original_bary(bary, self.lambda(p), perspective_correct);
        uvs[0] * w.x + uvs[1] * w.y + uvs[2] * w.z
    }

    /// The texture coordinates at fixed-point position `p`, `uv = Σ b_i·uv_i` over the original
    /// triangle's `uvs` (perspective-correct or affine), and, when `derivatives`, their screen
    /// derivatives as a GPU takes them, within the pixel's 2×2 quad ([`quad_offset`]; a frame
    /// `height` rows tall): at the same place in the quad's lower-left pixel `o`,
    /// `∂uv/∂x ≈ uv(o + (1, 0)) − uv(o)` and `∂uv/∂y ≈ uv(o + (0, 1)) − uv(o)` — the same
    /// interpolation evaluated there, whether or not the triangle covers those pixels, so the
    /// four pixels of a quad share one footprint and one λ. Zero derivatives otherwise.
    #[must_use]
    pub fn uv_at(
        &self,
        bary: &[Vec3; 3],
        uvs: [Vec2; 3],
        p: I64Vec2,
        height: u32,
        perspective_correct: bool,
        derivatives: bool,
    ) -> (Vec2, Vec2, Vec2) {
        let uv = self.uv_of(bary, uvs, p, perspective_correct);
        if !derivatives {
            return (uv, Vec2::ZERO, Vec2::ZERO);
        }
        let (dx, dy) =
            self.uv_derivatives(bary, uvs, p - quad_offset(p, height), perspective_correct);
        (uv, dx, dy)
    }

    /// The quad differences of the texture coordinates, taken at `o` (a place in a quad's
    /// lower-left pixel): `(uv(o + (1, 0)) − uv(o), uv(o + (0, 1)) − uv(o))`.
    #[must_use]
    pub fn uv_derivatives(
        &self,
        bary: &[Vec3; 3],
        uvs: [Vec2; 3],
        o: I64Vec2,
        perspective_correct: bool,
    ) -> (Vec2, Vec2) {
        let at = |q: I64Vec2| self.uv_of(bary, uvs, q, perspective_correct);
        let here = at(o);
        (
            at(o + I64Vec2::new(ONE, 0)) - here,
            at(o + I64Vec2::new(0, ONE)) - here,
        )
    }
}

/// Fragments are shaded in 2×2 quads, as on a GPU, so that a value's screen derivatives are
/// differences within its quad: pixel columns `2i, 2i + 1`, and image rows `2k, 2k + 1` counted
/// from the top of a frame `height` rows tall — window rows `y_q = height − 2 − 2k` and
/// `y_q + 1` (window y grows upwards). A quad's derivatives are taken at its lower-left pixel
/// `(x_q, y_q)` (OpenGL's coarse derivatives, `dFdxCoarse`):
/// `∂v/∂x ≈ v(x_q + 1, y_q) − v(x_q, y_q)`, `∂v/∂y ≈ v(x_q, y_q + 1) − v(x_q, y_q)`.
/// Returns how far the pixel holding fixed-point position `p` lies from that pixel,
/// `(x − x_q, y − y_q)`, in fixed point (each 0 or [`ONE`]).
#[must_use]
#[inline]
pub fn quad_offset(p: I64Vec2, height: u32) -> I64Vec2 {
    let (x, y) = (p.x.div_euclid(ONE), p.y.div_euclid(ONE));
    // Image row h − 1 − y: an even one is a quad's upper row, its lower row one below.
    let upper = (i64::from(height) - 1 - y).rem_euclid(2) == 0;
    I64Vec2::new(x.rem_euclid(2) * ONE, i64::from(upper) * ONE)
}

/// Which faces are discarded before rasterization. Front faces are counter-clockwise in window
/// coordinates (OpenGL's default `glFrontFace(GL_CCW)`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CullMode {
    /// Draw both sides (OpenGL's default: culling disabled).
    #[default]
    None,
    /// Discard triangles seen from behind.
    Back,
    /// Discard triangles seen from the front.
    Front,
}
