//! How a colour reads to colour-blind eyes, and how far apart two colours look.
//!
//! A dichromat's view of a colour is the linear sRGB colour times the matrix of Machado,
//! Oliveira & Fernandes, "A Physiologically-based Model for Simulation of Color Vision
//! Deficiency" (IEEE TVCG 15(6), 2009), table of severity 1.0 — protanopia, deuteranopia,
//! tritanopia — clamped to [0, 1]. Two colours look as far apart as their CIELAB distance
//! ΔE*ab = ‖(L*, a*, b*)₁ − (L*, a*, b*)₂‖ (CIE 1976), L*a*b* from CIE XYZ under D65.

use super::Rgb;

/// The distance every pair of meanings keeps, and each meaning from its ground, in ΔE*ab:
/// about nine just-noticeable differences (a JND is about 2.3), enough to tell two thin lines
/// apart at a glance. Okabe & Ito's palette for colour-blind readers keeps 16 at its closest
/// pair under these simulations, with eight colours to place; a set of three or four keeps
/// much more.
pub const APART: f32 = 20.0;

/// A way of seeing colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Vision {
    /// Three kinds of cones.
    Normal,
    /// No long-wavelength (red) cones.
    Protanopia,
    /// No medium-wavelength (green) cones.
    Deuteranopia,
    /// No short-wavelength (blue) cones.
    Tritanopia,
}

impl Vision {
    /// Every way of seeing colour checked.
    pub const ALL: [Vision; 4] = [
        Vision::Normal,
        Vision::Protanopia,
        Vision::Deuteranopia,
        Vision::Tritanopia,
    ];

    /// Machado et al.'s matrix for linear sRGB, rows by rows (severity 1.0).
    #[must_use]
    pub fn matrix(self) -> [[f32; 3]; 3] {
        match self {
            Vision::Normal => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            Vision::Protanopia => [
                [0.152_286, 1.052_583, -0.204_868],
                [0.114_503, 0.786_281, 0.099_216],
                [-0.003_882, -0.048_116, 1.051_998],
            ],
            Vision::Deuteranopia => [
                [0.367_322, 0.860_646, -0.227_968],
                [0.280_085, 0.672_501, 0.047_413],
                [-0.011_820, 0.042_940, 0.968_881],
            ],
            Vision::Tritanopia => [
                [1.255_528, -0.076_749, -0.178_779],
                [-0.078_411, 0.930_809, 0.147_602],
                [0.004_733, 0.691_367, 0.303_900],
            ],
        }
    }

    /// The English name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Vision::Normal => "normal vision",
            Vision::Protanopia => "protanopia",
            Vision::Deuteranopia => "deuteranopia",
            Vision::Tritanopia => "tritanopia",
        }
    }

    /// `c` as seen this way, in linear sRGB within [0, 1].
    #[must_use]
    pub fn sees(self, c: Rgb) -> [f32; 3] {
        let l = c.map(linear);
        self.matrix()
            .map(|row| (row[0] * l[0] + row[1] * l[1] + row[2] * l[2]).clamp(0.0, 1.0))
    }

    /// How far apart `a` and `b` look this way, ΔE*ab.
    #[must_use]
    pub fn distance(self, a: Rgb, b: Rgb) -> f32 {
        let (p, q) = (lab(self.sees(a)), lab(self.sees(b)));
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
    }

    /// `c` as this way of seeing shows it on a screen: back to 8-bit sRGB.
    #[must_use]
    pub fn shown(self, c: Rgb) -> Rgb {
        self.sees(c).map(|v| {
            let s = if v <= 0.003_130_8 {
                12.92 * v
            } else {
                1.055 * v.powf(1.0 / 2.4) - 0.055
            };
            (s * 255.0).round().clamp(0.0, 255.0) as u8
        })
    }
}

/// WCAG's relative luminance of `c`: `0.2126 R + 0.7152 G + 0.0722 B` of its linear channels
/// (the Y of CIE XYZ under sRGB's primaries).
#[must_use]
pub fn luminance(c: Rgb) -> f32 {
    let [r, g, b] = c.map(linear);
    0.2126 * r + 0.7152 * g + 0.0722 * b
}

/// An 8-bit sRGB channel as linear light: `c/12.92` up to 0.04045, else `((c + 0.055)/1.055)^2.4`.
fn linear(c: u8) -> f32 {
    let c = f32::from(c) / 255.0;
    if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Linear sRGB as CIELAB under D65: XYZ = M·rgb with sRGB's primaries, then
/// `L* = 116 f(Y/Yn) − 16`, `a* = 500 (f(X/Xn) − f(Y/Yn))`, `b* = 200 (f(Y/Yn) − f(Z/Zn))`,
/// `f(t) = ∛t` above (6/29)³, `t/(3·(6/29)²) + 4/29` below.
#[must_use]
pub fn lab(rgb: [f32; 3]) -> [f32; 3] {
    const M: [[f32; 3]; 3] = [
        [0.4124, 0.3576, 0.1805],
        [0.2126, 0.7152, 0.0722],
        [0.0193, 0.1192, 0.9505],
    ];
    const WHITE: [f32; 3] = [0.950_47, 1.0, 1.088_83];
    let d = 6.0f32 / 29.0;
    let f = |t: f32| {
        if t > d * d * d {
            t.cbrt()
        } else {
            t / (3.0 * d * d) + 4.0 / 29.0
        }
    };
    let [x, y, z] = [0, 1, 2].map(|k| {
        let row = M[k];
        f((row[0] * rgb[0] + row[1] * rgb[1] + row[2] * rgb[2]) / WHITE[k])
    });
    [116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)]
}

/// The closest pair of `meanings` and the meaning closest to one of `grounds`, as `vision`
/// sees them: `(distance, first name, second name)` each, the ground named "ground".
#[must_use]
pub fn closest(
    vision: Vision,
    meanings: &[(&'static str, Rgb)],
    grounds: &[Rgb],
) -> [(f32, &'static str, &'static str); 2] {
    let mut pair = (f32::INFINITY, "", "");
    let mut ground = (f32::INFINITY, "", "ground");
    for (i, (a, ca)) in meanings.iter().enumerate() {
        for (b, cb) in &meanings[i + 1..] {
            let d = vision.distance(*ca, *cb);
            if d < pair.0 {
                pair = (d, a, b);
            }
        }
        for g in grounds {
            let d = vision.distance(*ca, *g);
            if d < ground.0 {
                ground = (d, a, "ground");
            }
        }
    }
    [pair, ground]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: [f32; 3], b: [f32; 3], tol: f32) -> bool {
        (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
    }

    /// White is L* = 100 with no colour, black 0; sRGB's red is (53.24, 80.09, 67.20), the
    /// value colour references print (Lindbloom's calculator, sRGB D65).
    #[test]
    fn cielab_of_known_colours() {
        assert!(
            near(lab([1.0; 3]), [100.0, 0.0, 0.0], 0.05),
            "{:?}",
            lab([1.0; 3])
        );
        assert!(near(lab([0.0; 3]), [0.0, 0.0, 0.0], 1e-4));
        let red = lab(Vision::Normal.sees([255, 0, 0]));
        assert!(near(red, [53.24, 80.09, 67.20], 0.1), "{red:?}");
    }

    /// Each of Machado's matrices leaves white white (its rows sum to 1), so greys stay grey:
    /// a dichromat loses hue, not lightness, on the neutral axis.
    #[test]
    fn a_dichromat_sees_greys_as_they_are() {
        for v in Vision::ALL {
            for row in v.matrix() {
                assert!((row.iter().sum::<f32>() - 1.0).abs() < 1e-5, "{v:?}");
            }
            assert!(v.distance([128, 128, 128], [128, 128, 128]).abs() < 1e-6);
            assert_eq!(v.shown([90, 90, 90]), [90, 90, 90], "{v:?}");
        }
    }

    /// Pure red and pure green, far apart to normal eyes, come close to a deuteranope's: red's
    /// linear (1, 0, 0) becomes the matrix's first column (0.367, 0.280, −0.012 → 0), green's
    /// (0.861, 0.673, 0.043) — about the same hue, green the lighter.
    #[test]
    fn red_and_green_merge_for_a_deuteranope() {
        let (red, green) = ([255, 0, 0], [0, 255, 0]);
        assert!(near(
            Vision::Deuteranopia.sees(red),
            [0.367_322, 0.280_085, 0.0],
            1e-6
        ));
        assert!(Vision::Normal.distance(red, green) > 150.0);
        let d = Vision::Deuteranopia.distance(red, green);
        assert!(d < Vision::Normal.distance(red, green) / 3.0, "{d}");
    }
}
