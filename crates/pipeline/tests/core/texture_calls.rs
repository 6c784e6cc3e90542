//! GLSL's texture functions with their extra arguments honoured, each against the texel worked
//! out by hand on a texture whose texel (i, j) is (4·i², 4·j², 0)/255 (not linear, so that two
//! levels differ): `textureOffset` and its kin move the lookup by whole texels of the level read
//! (GLSL 3.30 §8.7; OpenGL 3.3 §3.8.11, u = s·w + δu), `textureGrad` takes its level of detail
//! from the derivatives given instead of the quad's, and `textureProj` divides by the last
//! coordinate first.

use glam::Vec3;
use pipeline::shader::{Stage, Uniforms};
use pipeline::texture::{Level, Texture};

use crate::shader::{compile, run};

/// Level 0's red (or green) at column (or row) `i`: 4·i²/255, exact in 8 bits.
fn r0(i: i32) -> f32 {
    let i = i.rem_euclid(8);
    4.0 * (i * i) as f32 / 255.0
}

/// Level 1's red (or green) at column `a` of 4: the mean of level 0's columns 2a and 2a + 1.
fn r1(a: i32) -> f32 {
    let a = a.rem_euclid(4);
    (r0(2 * a) + r0(2 * a + 1)) / 2.0
}

/// The 8×8 texture: texel (i, j) = (r0(i), r0(j), 0).
fn squares() -> Texture {
    let texels = (0..8)
        .flat_map(|j| (0..8).map(move |i| Vec3::new(r0(i), r0(j), 0.0)))
        .collect();
    Texture::from_level(
        "squares",
        Level {
            width: 8,
            height: 8,
            texels,
        },
    )
}

/// Level 0's texel (i, j), wrapped (the sampler repeats).
fn texel0(i: i32, j: i32) -> [f32; 3] {
    [r0(i), r0(j), 0.0]
}

/// Level 1's texel (a, b) of 4×4.
fn texel1(a: i32, b: i32) -> [f32; 3] {
    [r1(a), r1(b), 0.0]
}

/// Level 1 read bilinearly at the centre of level 0's column `i`: x = u·4 − ½ = i/2 − ¼, so
/// an even i = 2a lies ¾ on column a and ¼ on a − 1, an odd one ¾ on a and ¼ on a + 1.
fn r1_at_centre0(i: i32) -> f32 {
    let a = i.div_euclid(2);
    if i % 2 == 0 {
        0.25 * r1(a - 1) + 0.75 * r1(a)
    } else {
        0.75 * r1(a) + 0.25 * r1(a + 1)
    }
}

/// One quad of lanes at the centres of level 0's texels (i, j), (i + 1, j), (i, j + 1),
/// (i + 1, j + 1): one texel apart, so `texture()`'s own λ is 0.
fn quad(i: i32, j: i32) -> Vec<Vec<f32>> {
    [(0, 0), (1, 0), (0, 1), (1, 1)]
        .iter()
        .map(|(di, dj)| {
            vec![
                (i + di) as f32 / 8.0 + 1.0 / 16.0,
                (j + dj) as f32 / 8.0 + 1.0 / 16.0,
            ]
        })
        .collect()
}

fn shade(call: &str, lanes: &[Vec<f32>]) -> Vec<Vec<f32>> {
    let src = format!(
        "#version 330 core\nuniform sampler2D tex;\nin vec2 uv;\nout vec4 color;\nvoid main() {{\n    color = {call};\n}}\n"
    );
    let t = squares();
    run(
        &compile(Stage::Fragment, &src),
        &Uniforms::default(),
        &[lanes.to_vec()],
        &[Some(&t)],
    )
    .expect("runs")
    .0
}

fn assert_texels(got: &[Vec<f32>], want: &[[f32; 3]], what: &str) {
    for (l, (g, w)) in got.iter().zip(want).enumerate() {
        let near = g[..3].iter().zip(w).all(|(a, b)| (a - b).abs() < 1e-5);
        assert!(near, "{what}, lane {l}: {:?} != {w:?}", &g[..3]);
    }
}

#[test]
fn texture_offset_moves_the_lookup_by_whole_texels_and_wraps() {
    let lanes = quad(6, 0);
    let got = shade("textureOffset(tex, uv, ivec2(2, -1))", &lanes);
    // Lanes at texels (6, 0), (7, 0), (6, 1), (7, 1), each read 2 right and 1 down (repeat).
    let want = [texel0(8, -1), texel0(9, -1), texel0(8, 0), texel0(9, 0)];
    assert_texels(&got, &want, "textureOffset");
    // Without the offset, the texels themselves: the offset is what moved them.
    let plain = shade("texture(tex, uv)", &lanes);
    assert_texels(
        &plain,
        &[texel0(6, 0), texel0(7, 0), texel0(6, 1), texel0(7, 1)],
        "texture",
    );
}

#[test]
fn texture_lod_offset_moves_by_texels_of_the_level_read() {
    // Lanes at the centres of level 1's texels (0, 1), (1, 1), (0, 2), (1, 2): one offset texel
    // there is 1/4 of the texture, two of level 0's.
    let lanes: Vec<Vec<f32>> = [(0, 1), (1, 1), (0, 2), (1, 2)]
        .iter()
        .map(|&(a, b)| vec![(a as f32 + 0.5) / 4.0, (b as f32 + 0.5) / 4.0])
        .collect();
    let got = shade("textureLodOffset(tex, uv, 1.0, ivec2(1, 0))", &lanes);
    let want = [texel1(1, 1), texel1(2, 1), texel1(1, 2), texel1(2, 2)];
    assert_texels(&got, &want, "textureLodOffset");
}

#[test]
fn texture_grad_takes_its_level_from_the_derivatives_given() {
    // Lanes one texel apart: texture()'s own λ is 0. Derivatives of two texels a pixel give
    // λ = 1: level 1 read at the centres of level 0's texels.
    let lanes = quad(2, 5);
    let cells = [(2, 5), (3, 5), (2, 6), (3, 6)];
    let got = shade(
        "textureGrad(tex, uv, vec2(0.25, 0.0), vec2(0.0, 0.25))",
        &lanes,
    );
    let want: Vec<[f32; 3]> = cells
        .iter()
        .map(|&(i, j)| [r1_at_centre0(i), r1_at_centre0(j), 0.0])
        .collect();
    assert_texels(&got, &want, "textureGrad at λ = 1");
    // The texels themselves, which texture() reads there, differ: the derivatives chose.
    assert!(
        want.iter()
            .zip(&cells)
            .any(|(w, &(i, j))| (w[0] - texel0(i, j)[0]).abs() > 1e-3),
        "the two levels should differ at these lanes"
    );
    // Lanes two texels apart (texture()'s λ = 1), derivatives of one texel: level 0.
    let apart: Vec<Vec<f32>> = cells
        .iter()
        .map(|&(i, j)| {
            vec![
                (2 * i) as f32 / 8.0 + 1.0 / 16.0,
                j as f32 / 8.0 + 1.0 / 16.0,
            ]
        })
        .collect();
    let got = shade(
        "textureGrad(tex, uv, vec2(0.125, 0.0), vec2(0.0, 0.125))",
        &apart,
    );
    let want: Vec<[f32; 3]> = cells.iter().map(|&(i, j)| texel0(2 * i, j)).collect();
    assert_texels(&got, &want, "textureGrad at λ = 0");
    // textureGradOffset: λ = 0 and one texel up.
    let got = shade(
        "textureGradOffset(tex, uv, vec2(0.125, 0.0), vec2(0.0, 0.125), ivec2(0, 1))",
        &quad(2, 3),
    );
    let want = [texel0(2, 4), texel0(3, 4), texel0(2, 5), texel0(3, 5)];
    assert_texels(&got, &want, "textureGradOffset");
}

#[test]
fn texture_proj_divides_by_the_last_coordinate() {
    let lanes = quad(3, 5);
    let got = shade("textureProj(tex, vec3(uv * 2.0, 2.0))", &lanes);
    let want = [texel0(3, 5), texel0(4, 5), texel0(3, 6), texel0(4, 6)];
    assert_texels(&got, &want, "textureProj");
    let got = shade(
        "textureProjOffset(tex, vec4(uv * 4.0, 0.0, 4.0), ivec2(-1, 0))",
        &lanes,
    );
    let want = [texel0(2, 5), texel0(3, 5), texel0(2, 6), texel0(3, 6)];
    assert_texels(&got, &want, "textureProjOffset");
}

/// The second texture of the sampler-parameter test: texel (i, j) = (0, 0, (8·i + j)/64).
fn ramp() -> Texture {
    let texels = (0..8)
        .flat_map(|j| (0..8).map(move |i| Vec3::new(0.0, 0.0, (8 * i + j) as f32 / 64.0)))
        .collect();
    Texture::from_level(
        "ramp",
        Level {
            width: 8,
            height: 8,
            texels,
        },
    )
}

#[test]
fn a_sampler_passed_to_a_function_reads_the_texture_each_call_passes() {
    // `through(a, b, at)` = look(a) + 2·look(b) + (0, 0, 0, width of b): called with the two
    // textures one way round, then the other, passing each on to `look`.
    let src = "#version 330 core\nuniform sampler2D tex;\nuniform sampler2D detail;\nin vec2 uv;\nout vec4 color;\n\
               vec4 look(sampler2D s, vec2 at) {\n    return texture(s, at);\n}\n\
               vec4 through(sampler2D a, sampler2D b, vec2 at) {\n    return look(a, at) + 2.0 * look(b, at) + vec4(0.0, 0.0, 0.0, float(textureSize(b, 0).x));\n}\n\
               void main() {\n    color = CALL;\n}\n";
    let (squares, ramp) = (squares(), ramp());
    let lanes = quad(3, 5);
    let cells = [(3, 5), (4, 5), (3, 6), (4, 6)];
    for swapped in [false, true] {
        let call = if swapped {
            "through(detail, tex, uv)"
        } else {
            "through(tex, detail, uv)"
        };
        let got = run(
            &compile(Stage::Fragment, &src.replace("CALL", call)),
            &Uniforms::default(),
            std::slice::from_ref(&lanes),
            &[Some(&squares), Some(&ramp)],
        )
        .expect("runs")
        .0;
        // At the centres of level 0's texels (λ = 0): the texels themselves. Each alpha is 1.
        let (k_tex, k_detail) = if swapped { (2.0, 1.0) } else { (1.0, 2.0) };
        for (l, &(i, j)) in cells.iter().enumerate() {
            let want = [
                k_tex * r0(i),
                k_tex * r0(j),
                k_detail * (8 * i + j) as f32 / 64.0,
                1.0 + 2.0 + 8.0,
            ];
            let near = got[l].iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-5);
            assert!(
                near,
                "swapped {swapped}, lane {l}: {:?} != {want:?}",
                got[l]
            );
        }
    }
}
