//! Texture sampling against values computed by hand.

use glam::{Vec2, Vec3};
use pipeline::camera::{Camera, Projection};
use pipeline::mesh::Mesh;
use pipeline::scene::{Object, Scene};
use pipeline::settings::RenderSettings;
use pipeline::texture::{Filter, Level, Mipmap, Sampler, Texture, Wrap};

use crate::support::render;

pub(crate) fn grey(v: f32) -> Vec3 {
    Vec3::splat(v)
}

#[test]
fn bilinear_on_a_two_by_two_texture() {
    // Texels (row 0 at the bottom): (0,0) = 0, (1,0) = 1, (0,1) = 2, (1,1) = 3.
    let level = Level {
        width: 2,
        height: 2,
        texels: vec![grey(0.0), grey(1.0), grey(2.0), grey(3.0)],
    };
    let at = |u: f32, v: f32| level.bilinear(Vec2::new(u, v), Wrap::Clamp).x;
    // Texel centres are at (i + ½)/2: (0.25, 0.25) is exactly texel (0, 0).
    assert_eq!(at(0.25, 0.25), 0.0);
    assert_eq!(at(0.75, 0.75), 3.0);
    // Half-way between texels: x = u·w − ½ = 0.5 → ½(0 + 1).
    assert!((at(0.5, 0.25) - 0.5).abs() < 1e-6);
    // The middle: the mean of all four.
    assert!((at(0.5, 0.5) - 1.5).abs() < 1e-6);
    // s = 0.3, t = 0.6 from texel (0, 0): (1−t)((1−s)·0 + s·1) + t((1−s)·2 + s·3).
    let (s, t) = (0.3f32, 0.6f32);
    let expect = (1.0 - t) * s + t * ((1.0 - s) * 2.0 + s * 3.0);
    assert!((at((s + 0.5) / 2.0, (t + 0.5) / 2.0) - expect).abs() < 1e-5);
    // Clamp keeps the edge texel; repeat wraps to the other side.
    assert_eq!(at(0.0, 0.25), 0.0);
    let wrapped = level.bilinear(Vec2::new(0.0, 0.25), Wrap::Repeat).x;
    assert!(
        (wrapped - 0.5).abs() < 1e-6,
        "half of texel (1,0) and half of (0,0) across the seam"
    );
    // Nearest: the texel containing the point.
    assert_eq!(level.nearest(Vec2::new(0.49, 0.51), Wrap::Clamp).x, 2.0);
}

#[test]
fn each_mip_level_is_the_box_filter_of_the_one_before() {
    let t = Texture::checkerboard(16, 4);
    assert_eq!(t.levels.len(), 5, "16, 8, 4, 2, 1");
    for k in 1..t.levels.len() {
        let (fine, coarse) = (&t.levels[k - 1], &t.levels[k]);
        assert_eq!(coarse.width, fine.width / 2);
        for j in 0..coarse.height {
            for i in 0..coarse.width {
                let mut sum = Vec3::ZERO;
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    sum += fine.texels[((2 * j + dy) * fine.width + 2 * i + dx) as usize];
                }
                let got = coarse.texels[(j * coarse.width + i) as usize];
                assert!(
                    (got - sum / 4.0).length() < 1e-6,
                    "level {k} texel ({i}, {j})"
                );
            }
        }
    }
    // Level 2 is 4×4: one texel per square, the squares' own values.
    assert_eq!(t.levels[2].texels[0], t.levels[0].texels[0]);
    // The 1×1 level is the mean of everything: half light, half dark.
    assert!((t.levels[4].texels[0].x - (0.95 + 0.1) / 2.0).abs() < 1e-6);
    // Odd sizes: a 5×3 level goes to 2×1 with the last column in the last box.
    let odd = Level {
        width: 5,
        height: 3,
        texels: (0..15).map(|v| grey(v as f32)).collect(),
    };
    let next = odd.box_filtered();
    assert_eq!((next.width, next.height), (2, 1));
    // Box 0: columns 0–1, rows 0–2 (the odd row joins): values 0,1,5,6,10,11.
    assert!((next.texels[0].x - (0.0 + 1.0 + 5.0 + 6.0 + 10.0 + 11.0) / 6.0).abs() < 1e-6);
}

/// The square [−1, 1]² in the plane z = 0 facing +z, uv from (0, 0) to (1, 1) along x and y.
pub(crate) fn quad_mesh() -> Mesh {
    Mesh {
        name: "quad".into(),
        positions: vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ],
        normals: vec![Vec3::Z; 4],
        uvs: vec![
            Vec2::new(0.0, 0.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.0, 1.0),
        ],
        colors: Vec::new(),
        indices: vec![[0, 1, 2], [0, 2, 3]],
        labels: Vec::new(),
    }
}

/// A square [−1, 1]² facing the camera at distance `d`, tilted by `tilt` degrees about x,
/// uv from (0, 0) to (1, 1), with a 256×256 texture; fovy 90°, a 65×65 window (odd, so that
/// the centre pixel's centre is on the view axis).
fn textured_quad(d: f32, tilt: f32, sampler: Sampler) -> pipeline::capture::FrameCapture {
    let mesh = quad_mesh();
    let mut quad = Object::new("quad", mesh);
    quad.rotate_deg = Vec3::new(-tilt, 0.0, 0.0);
    quad.texture = Some(std::sync::Arc::new(Texture::checkerboard(256, 16)));
    let scene = Scene {
        uniforms: Default::default(),
        objects: vec![quad],
        camera: Camera {
            eye: Vec3::new(0.0, 0.0, d),
            at: Vec3::ZERO,
            up: Vec3::Y,
        },
        projection: Projection::Perspective {
            fovy_deg: 90.0,
            aspect: None,
            near: 0.1,
            far: 100.0,
        },
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: 65,
        height: 65,
        sampler,
        ..RenderSettings::default()
    };
    render(&scene, &settings)
}

#[test]
fn level_of_detail_is_log2_of_texels_per_pixel() {
    // Facing the camera at distance d with fovy 90°, the view is 2d units high over 65 pixels;
    // the texture has 256 texels over 2 units: L = 128 · 2d/65 texels a pixel, λ = log₂ L.
    let texels_per_pixel = |d: f32| 128.0 * 2.0 * d / 65.0;
    let centre = 32 * 65 + 32;
    for d in [4.0, 1.0, 9.0] {
        let c = textured_quad(d, 0.0, Sampler::default());
        let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
        let expect = texels_per_pixel(d).log2();
        assert!(
            (tb.at(centre).lod - expect).abs() < 0.01,
            "d = {d}: λ = {} vs {expect}",
            tb.at(centre).lod
        );
        // Trilinear reads levels ⌊λ⌋ and ⌊λ⌋ + 1 with weight fract(λ).
        assert!((tb.at(centre).level - expect).abs() < 0.01);
    }
    // Tilted by θ about x (top away from the camera), the derivative is a difference within
    // the pixel's 2×2 quad, as GPUs take it: the ray through screen height s (tan of its
    // angle) hits the plane at t = s·d/(cos θ − s·sin θ) along it. The centre pixel (32, 32)
    // of 65 rows is image row 32, the upper row of its quad, whose lower row is one pixel
    // down (s = −2/65): ∂v/∂y spans 128·(t(0) − t(−s1)) texels, and along x the quad's
    // lower row, at depth d·cos θ/(cos θ + s1·sin θ), spans texels_per_pixel of that depth.
    let (theta, d, s1) = (70f32.to_radians(), 4.0f32, 2.0f32 / 65.0);
    let along_y = 128.0 * s1 * d / (theta.cos() + s1 * theta.sin());
    let along_x = texels_per_pixel(d * theta.cos() / (theta.cos() + s1 * theta.sin()));
    let c = textured_quad(d, 70.0, Sampler::default());
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    // The footprint's axes, in texels: one pixel right moves along s only, one pixel up along
    // t only.
    let [s_x, t_x, s_y, t_y] = tb.at(centre).footprint;
    assert!(
        (s_x.abs() - along_x).abs() < 0.01 * along_x && t_x.abs() < 0.02,
        "∂/∂x = ({s_x}, {t_x}) vs ({along_x}, 0)"
    );
    assert!(
        s_y.abs() < 0.02 && (t_y.abs() - along_y).abs() < 0.01 * along_y,
        "∂/∂y = ({s_y}, {t_y}) vs (0, {along_y})"
    );
    // Its image: the long axis along t is cyan (hue 180°), saturation log₂(major/minor)/3.
    let img = c.image(pipeline::buffers::BufferKind::Footprint);
    let [r, g, b, _] = img.get_pixel(32, 32).0;
    let sat = ((along_y / along_x).log2() / 3.0).min(1.0);
    let red = (255.0 * (1.0 - sat)).round() as u8;
    assert!(
        r.abs_diff(red) <= 2 && g == 255 && b == 255,
        "({r}, {g}, {b}) vs ({red}, 255, 255)"
    );
    assert!(
        (tb.at(centre).lod - along_y.log2()).abs() < 0.01,
        "λ = {} vs {}",
        tb.at(centre).lod,
        along_y.log2()
    );
    // Anisotropic filtering: N = min(⌈major/minor⌉, max) taps along the major axis and
    // λ = log₂(major/N).
    let taps = (along_y / along_x).ceil();
    assert_eq!(taps, 3.0, "{along_y} / {along_x}");
    let aniso = Sampler {
        anisotropy: 16,
        ..Sampler::default()
    };
    let c = textured_quad(d, 70.0, aniso);
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    let expect = (along_y / taps).log2();
    assert!(
        (tb.at(centre).lod - expect).abs() < 0.01,
        "λ = {} vs {expect}",
        tb.at(centre).lod
    );
    // At most `anisotropy` taps.
    let two = Sampler {
        anisotropy: 2,
        ..Sampler::default()
    };
    let c = textured_quad(d, 70.0, two);
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    assert!((tb.at(centre).lod - (along_y / 2.0).log2()).abs() < 0.01);
    // A bias moves λ; without mipmaps level 0 is read whatever λ is.
    let biased = Sampler {
        lod_bias: 1.0,
        mipmap: Mipmap::Nearest,
        filter: Filter::Nearest,
        ..Sampler::default()
    };
    let c = textured_quad(4.0, 0.0, biased);
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    let expect = texels_per_pixel(4.0).log2() + 1.0;
    assert!((tb.at(centre).lod - expect).abs() < 0.01 && tb.at(centre).level == expect.round());
    let none = Sampler {
        mipmap: Mipmap::None,
        ..Sampler::default()
    };
    let c = textured_quad(4.0, 0.0, none);
    assert_eq!(
        c.pixels.texturing.as_ref().map(|t| t.at(centre).level),
        Some(0.0)
    );
}

/// The four pixels of a 2×2 quad share one footprint and one λ, taken at the quad's lower-left
/// pixel: image rows 2k and 2k + 1 from the top, columns 2i and 2i + 1, for an odd height too
/// (its last quad row is image row h − 1 alone).
#[test]
fn a_quads_four_pixels_share_the_derivatives_of_its_lower_left_pixel() {
    use glam::I64Vec2;
    use pipeline::raster::{ONE, quad_offset};
    let at = |x: i64, y: i64| I64Vec2::new(x * ONE + ONE / 2, y * ONE + ONE / 2);
    // 4 rows: image rows 0, 1 are window rows 3, 2 (quad y 2); image rows 2, 3 are 1, 0.
    assert_eq!(quad_offset(at(0, 0), 4), I64Vec2::ZERO);
    assert_eq!(quad_offset(at(1, 1), 4), I64Vec2::new(ONE, ONE));
    assert_eq!(quad_offset(at(4, 2), 4), I64Vec2::ZERO);
    assert_eq!(quad_offset(at(5, 3), 4), I64Vec2::new(ONE, ONE));
    // 5 rows: image rows 0, 1 are window rows 4, 3 (quad y 3); image row 4, window 0, is the
    // upper row of a quad whose lower row is outside the frame.
    assert_eq!(quad_offset(at(0, 3), 5), I64Vec2::ZERO);
    assert_eq!(quad_offset(at(0, 4), 5), I64Vec2::new(0, ONE));
    assert_eq!(quad_offset(at(0, 0), 5), I64Vec2::new(0, ONE));
    assert_eq!(quad_offset(at(0, 1), 5), I64Vec2::ZERO);
    // On the tilted floor every quad's four pixels read one footprint and one λ, while the
    // footprint grows from quad to quad up the image.
    let c = textured_quad(4.0, 70.0, Sampler::default());
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    let (w, h) = (65usize, 65usize);
    let mut quads = 0;
    for row in (0..h - 1).step_by(2) {
        for x in (0..w - 1).step_by(2) {
            let i = row * w + x;
            let pixels = [i, i + 1, i + w, i + w + 1];
            let four = pixels.map(|i| tb.at(i));
            // One triangle over the quad (the floor's two meet on a diagonal; across it each
            // evaluates its own plane at the lower-left pixel, equal but for rounding).
            let p = c.pixels.primitive[i];
            if pixels
                .iter()
                .any(|&i| c.pixels.coverage[i] == 0 || c.pixels.primitive[i] != p)
            {
                continue;
            }
            quads += 1;
            for t in &four[1..] {
                assert_eq!(t.footprint, four[0].footprint, "quad at image ({x}, {row})");
                assert_eq!(t.lod, four[0].lod, "quad at image ({x}, {row})");
            }
        }
    }
    assert!(quads >= 10, "{quads} quads checked");
    let [above, below] = [30 * w + 32, 34 * w + 32].map(|i| tb.at(i).footprint[3].abs());
    assert!(above > below * 1.05, "∂t/∂y {above} above vs {below} below");
}

/// A sampler that reads one level with one tap needs no footprint: the lookup without
/// derivatives (what a colour-only frame does) reads the colour the full lookup reads, at any
/// uv, any derivatives, both filters and both wraps.
#[test]
fn a_lookup_without_a_footprint_reads_what_the_full_lookup_reads() {
    let texture = Texture::checkerboard(64, 8);
    let mut next = crate::support::uniform(0x9e37_79b9_u32);
    for filter in [Filter::Nearest, Filter::Bilinear] {
        for wrap in [Wrap::Repeat, Wrap::Clamp] {
            let sampler = Sampler {
                filter,
                wrap,
                mipmap: Mipmap::None,
                anisotropy: 1,
                lod_bias: 1.5,
            };
            for _ in 0..500 {
                let uv = Vec2::new(next() * 3.0 - 1.0, next() * 3.0 - 1.0);
                let (dx, dy) = (Vec2::new(next(), next()), Vec2::new(next(), next()));
                let full = texture.sample(uv, dx * 0.2, dy * 0.2, &sampler);
                let base = texture.sample_level0(uv, &sampler);
                assert_eq!(full.color, base.color, "{filter:?} {wrap:?} at {uv}");
                assert_eq!((base.level, base.level_blend, base.taps), (0, 0.0, 1));
            }
        }
    }
}

#[test]
fn the_texel_colour_is_the_surface_colour() {
    // Magnified (d = 0.3: about 0.6 texels a pixel), nearest filtering: every pixel shows one of
    // the checkerboard's two values.
    let s = Sampler {
        filter: Filter::Nearest,
        mipmap: Mipmap::None,
        ..Sampler::default()
    };
    let c = textured_quad(0.3, 0.0, s);
    let tb = c.pixels.texturing.as_ref().expect("texturing buffers");
    for (i, col) in c.pixels.color.iter().enumerate() {
        if c.pixels.coverage[i] > 0 {
            // The texel buffer keeps half floats: 11 significant bits.
            let texel = tb.at(i).texel;
            assert!(
                col.iter()
                    .zip(texel)
                    .all(|(c, t)| (c - t).abs() <= c.abs() / 2048.0),
                "unlit: the colour is the texel, {col:?} vs {texel:?}"
            );
            assert!(col[0] == 0.95 || col[0] == 0.1, "{col:?}");
        }
    }
}

#[test]
fn wrapping_a_texel_index_is_the_modulo_or_the_clamp() {
    // The fast paths (no division inside the level, the neighbour from the first index) agree
    // with the definitions on every index around several levels' edges.
    for n in [1u32, 2, 3, 7, 64] {
        for i in -200i64..200 {
            let m = i64::from(n);
            let repeat = i.rem_euclid(m) as usize;
            let clamp = i.clamp(0, m - 1) as usize;
            assert_eq!(Wrap::Repeat.index(i, n), repeat, "repeat {i} mod {n}");
            assert_eq!(Wrap::Clamp.index(i, n), clamp, "clamp {i} to {n}");
            assert_eq!(
                Wrap::Repeat.pair(i, n),
                (repeat, (i + 1).rem_euclid(m) as usize),
                "repeat pair at {i}, {n}"
            );
            assert_eq!(
                Wrap::Clamp.pair(i, n),
                (clamp, (i + 1).clamp(0, m - 1) as usize),
                "clamp pair at {i}, {n}"
            );
        }
    }
}

/// An 8-bit image's level 0 is also kept in 8 bits, and its lookups read the same values as
/// the `f32` texels give, bit for bit; a level whose texels are not all `k/255` (a generated
/// texture, a 16-bit image) is not.
#[test]
fn the_8_bit_copy_of_level_0_reads_what_the_texels_give() {
    let img = image::RgbImage::from_fn(37, 23, |x, y| {
        image::Rgb([(x * 7 + y) as u8, (y * 11) as u8, ((x * y) % 256) as u8])
    });
    let t = Texture::from_image("rgb8", &image::DynamicImage::ImageRgb8(img.clone()))
        .expect("not empty");
    assert!(t.has_8_bit_level0());
    assert!(!Texture::checkerboard(16, 4).has_8_bit_level0());
    let deep = image::DynamicImage::ImageRgb16(image::ImageBuffer::from_fn(4, 4, |x, _| {
        image::Rgb([x as u16 * 1000 + 1, 0, 0])
    }));
    let deep = Texture::from_image("rgb16", &deep).expect("not empty");
    assert!(!deep.has_8_bit_level0());
    let level = &t.levels[0];
    for k in 0..2000 {
        // uv inside and outside [0, 1], on a grid that hits texel centres and edges too.
        let uv = Vec2::new((k % 50) as f32 / 17.0 - 0.6, (k / 50) as f32 / 13.0 - 0.4);
        for wrap in [Wrap::Repeat, Wrap::Clamp] {
            let bilinear = t.read_level(0, uv, Filter::Bilinear, wrap);
            assert_eq!(
                bilinear,
                level.bilinear(uv, wrap),
                "bilinear at {uv} {wrap:?}"
            );
            let nearest = t.read_level(0, uv, Filter::Nearest, wrap);
            assert_eq!(nearest, level.nearest(uv, wrap), "nearest at {uv} {wrap:?}");
        }
    }
    // Level 1 (box-filtered, not 8-bit) is read from its own texels.
    let uv = Vec2::new(0.3, 0.7);
    assert_eq!(
        t.read_level(1, uv, Filter::Bilinear, Wrap::Repeat),
        t.levels[1].bilinear(uv, Wrap::Repeat)
    );
}
