//! Minification beyond the mipmap (GAMES101's texture queries): a **ripmap** (levels halved
//! along u and v separately, for axis-aligned elongated footprints), a **summed-area table**
//! (the exact average over any axis-aligned rectangle of texels), and **EWA** (elliptical
//! weighted average: a Gaussian over the footprint's own ellipse, on the level where its minor
//! axis is a texel or two). Ripmap and SAT see the footprint's axis-aligned bounding box, so a
//! diagonal footprint is over-blurred; EWA follows it.

use glam::{Vec2, Vec3};

use super::{Level, Texture, Wrap};

/// The tables built from level 0 on first use.
#[derive(Clone, Debug, PartialEq)]
pub struct Prefiltered {
    /// Ripmap level `(i, j)` (width halved i times, height j times) at `i·rows + j`.
    ripmap: Vec<Level>,
    /// How many halvings of the height there are, plus one.
    rows: usize,
    /// `S(a, b)`, the sum of the texels in columns `[0, a)` and rows `[0, b)`, at `b·(w + 1) + a`.
    sat: Vec<[f64; 3]>,
    /// Level 0's size.
    width: u32,
    height: u32,
}

impl Prefiltered {
    fn build(base: &Level) -> Self {
        let mut column = vec![base.clone()];
        while column.last().is_some_and(|l| l.height > 1) {
            let next = column[column.len() - 1].halved(false, true);
            column.push(next);
        }
        let rows = column.len();
        // by_height[j][i]: level 0 halved j times in y, then i times in x.
        let by_height: Vec<Vec<Level>> = column
            .into_iter()
            .map(|mut level| {
                let mut row = vec![level.clone()];
                while level.width > 1 {
                    level = level.halved(true, false);
                    row.push(level.clone());
                }
                row
            })
            .collect();
        let columns = by_height[0].len();
        let flat = (0..columns)
            .flat_map(|i| by_height.iter().map(move |row| row[i].clone()))
            .collect();
        let (w, h) = (base.width as usize, base.height as usize);
        let mut sat = vec![[0.0f64; 3]; (w + 1) * (h + 1)];
        for b in 1..=h {
            for a in 1..=w {
                let t = base.texels[(b - 1) * w + (a - 1)];
                let at = |a: usize, b: usize| sat[b * (w + 1) + a];
                let (left, below, diagonal) = (at(a - 1, b), at(a, b - 1), at(a - 1, b - 1));
                sat[b * (w + 1) + a] =
                    std::array::from_fn(|c| f64::from(t[c]) + left[c] + below[c] - diagonal[c]);
            }
        }
        Self {
            ripmap: flat,
            rows,
            sat,
            width: base.width,
            height: base.height,
        }
    }

    /// The sum of the texels in columns `[0, x)` and rows `[0, y)` of the texture repeated
    /// without end (any integers): whole periods times the total, plus the partial strips.
    fn prefix(&self, x: i64, y: i64) -> [f64; 3] {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let s = |a: i64, b: i64| self.sat[(b * (w + 1) + a) as usize];
        let (qx, rx, qy, ry) = (
            x.div_euclid(w),
            x.rem_euclid(w),
            y.div_euclid(h),
            y.rem_euclid(h),
        );
        let (total, strip_x, strip_y, corner) = (s(w, h), s(w, ry), s(rx, h), s(rx, ry));
        let (qx, qy) = (qx as f64, qy as f64);
        std::array::from_fn(|c| qx * qy * total[c] + qx * strip_x[c] + qy * strip_y[c] + corner[c])
    }
}

/// The footprint's axis-aligned bounding box in level-0 texels: `(|∂u/∂x| + |∂u/∂y|)·w` by
/// `(|∂v/∂x| + |∂v/∂y|)·h`, at least one texel each way.
#[must_use]
pub fn bounding_box(size: Vec2, duv_dx: Vec2, duv_dy: Vec2) -> Vec2 {
    ((duv_dx.abs() + duv_dy.abs()) * size).max(Vec2::ONE)
}

impl Texture {
    fn prefiltered(&self) -> &Prefiltered {
        self.prefiltered
            .get_or_init(|| Box::new(Prefiltered::build(&self.levels[0])))
    }

    /// Ripmap: level `(i, j)` with `i = round(log₂ box_u)`, `j = round(log₂ box_v)` of the
    /// footprint's bounding box, read bilinearly. Returns the colour and `(i, j)`.
    #[must_use]
    pub fn sample_ripmap(
        &self,
        uv: Vec2,
        duv_dx: Vec2,
        duv_dy: Vec2,
        wrap: Wrap,
    ) -> (Vec3, [u32; 2]) {
        let p = self.prefiltered();
        let extent = bounding_box(self.levels[0].size(), duv_dx, duv_dy);
        let columns = p.ripmap.len() / p.rows;
        let i = (extent.x.log2().round().max(0.0) as usize).min(columns - 1);
        let j = (extent.y.log2().round().max(0.0) as usize).min(p.rows - 1);
        (
            p.ripmap[i * p.rows + j].bilinear(uv, wrap),
            [i as u32, j as u32],
        )
    }

    /// Summed-area table: the mean of the texels in the footprint's bounding box (rounded to
    /// whole texels), `(S(x1, y1) − S(x0, y1) − S(x1, y0) + S(x0, y0)) / area`. Repeating, the
    /// table repeats too; clamped, the box is cut to the texture.
    #[must_use]
    pub fn sample_summed_area(&self, uv: Vec2, duv_dx: Vec2, duv_dy: Vec2, wrap: Wrap) -> Vec3 {
        let p = self.prefiltered();
        let size = self.levels[0].size();
        let (centre, half) = (uv * size, bounding_box(size, duv_dx, duv_dy) / 2.0);
        let mut lo = (centre - half).round().as_i64vec2();
        let mut hi = (centre + half).round().as_i64vec2();
        hi = hi.max(lo + 1);
        if wrap == Wrap::Clamp {
            let max = glam::I64Vec2::new(i64::from(p.width), i64::from(p.height));
            lo = lo.clamp(glam::I64Vec2::ZERO, max - 1);
            hi = hi.clamp(lo + 1, max);
        }
        let (a, b, c, d) = (
            p.prefix(hi.x, hi.y),
            p.prefix(lo.x, hi.y),
            p.prefix(hi.x, lo.y),
            p.prefix(lo.x, lo.y),
        );
        let area = ((hi.x - lo.x) * (hi.y - lo.y)) as f64;
        Vec3::from_array(std::array::from_fn(|k| {
            ((a[k] - b[k] - c[k] + d[k]) / area) as f32
        }))
    }

    /// EWA (Heckbert): on the level `l` where the footprint's minor axis is about a texel, the
    /// ellipse `Q(d) = A·du² + B·du·dv + C·dv² ≤ F` with `A = a_v² + b_v² + 1`,
    /// `B = −2(a_u·a_v + b_u·b_v)`, `C = a_u² + b_u² + 1`, `F = A·C − B²/4` (a, b the footprint's
    /// axes in level-l texels, the +1 a texel's own reconstruction), each texel inside weighted
    /// by `exp(−2·Q/F)`. Returns the colour, the level and the texels read.
    #[must_use]
    pub fn sample_ewa(&self, uv: Vec2, duv_dx: Vec2, duv_dy: Vec2, wrap: Wrap) -> (Vec3, u32, u32) {
        let size0 = self.levels[0].size();
        let (a0, b0) = (duv_dx * size0, duv_dy * size0);
        // Singular values of the footprint [a b]: the ellipse's axes.
        let (p, q, r) = (
            a0.x * a0.x + b0.x * b0.x,
            a0.y * a0.y + b0.y * b0.y,
            a0.x * a0.y + b0.x * b0.y,
        );
        let mid = (p + q) / 2.0;
        let spread = (((p - q) / 2.0).powi(2) + r * r).sqrt();
        let (major, minor) = ((mid + spread).sqrt(), (mid - spread).max(0.0).sqrt());
        let last = self.levels.len() - 1;
        // The minor axis about a texel, and at most 32 texels along the major one.
        let by_minor = minor.max(1.0).log2().floor();
        let by_major = (major / 32.0).max(1.0).log2().ceil();
        let l = (by_minor.max(by_major) as usize).min(last);
        let level = &self.levels[l];
        let size = level.size();
        let (a, b) = (duv_dx * size, duv_dy * size);
        let big_a = a.y * a.y + b.y * b.y + 1.0;
        let big_b = -2.0 * (a.x * a.y + b.x * b.y);
        let big_c = a.x * a.x + b.x * b.x + 1.0;
        let f = big_a * big_c - big_b * big_b / 4.0;
        let centre = uv * size - 0.5;
        let (ru, rv) = (big_c.sqrt(), big_a.sqrt());
        let (u0, u1) = (
            (centre.x - ru).ceil() as i64,
            (centre.x + ru).floor() as i64,
        );
        let (v0, v1) = (
            (centre.y - rv).ceil() as i64,
            (centre.y + rv).floor() as i64,
        );
        let (mut sum, mut weight, mut read) = (Vec3::ZERO, 0.0, 0);
        for v in v0..=v1 {
            for u in u0..=u1 {
                let d = Vec2::new(u as f32 - centre.x, v as f32 - centre.y);
                let qd = big_a * d.x * d.x + big_b * d.x * d.y + big_c * d.y * d.y;
                if qd < f {
                    let w = (-2.0 * qd / f).exp();
                    sum += level.texel(u, v, wrap) * w;
                    weight += w;
                    read += 1;
                }
            }
        }
        let color = if weight > 0.0 {
            sum / weight
        } else {
            level.bilinear(uv, wrap)
        };
        (color, l as u32, read)
    }
}
