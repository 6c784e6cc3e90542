//! The quantity a texture lab asks the student to compute, against pipelens' own at the
//! inspected pixel: the lesson names a value of the student's fragment shader
//! (`exercise.compare.yours`: a variable, or a function's return as `name()`) and the quantity it
//! stands for (`uv`, `lod`, `texel`). pipelens' own comes from its texture lookup at the pixel,
//! which every frame with the pixel inspected keeps.

use pipeline::capture::{FrameCapture, PixelTexture};

use crate::lesson::answer::{Compare, Quantity};
use crate::vocabulary::Lang;

/// The student's value of the lab's quantity where it is not pipelens'.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantityMismatch {
    /// The value's name as the lesson gives it (`level_of_detail()`).
    pub name: String,
    /// Its line in the student's fragment shader.
    pub line: usize,
    /// Which quantity.
    pub quantity: Quantity,
    /// The student's value's numbers.
    pub yours: Vec<f64>,
    /// pipelens' lookup at the pixel.
    pub theirs: PixelTexture,
    /// The texture's level 0 in texels, `(w, h)`, where the quantity is a texel (to say where
    /// the bilinear filter reads).
    pub size: Option<(u32, u32)>,
    /// The inspected pixel, where both were read.
    pub pixel: (u32, u32),
}

/// pipelens' value of `quantity` in `lookup`, as numbers.
fn pipelens_value(quantity: Quantity, lookup: &PixelTexture) -> Vec<f64> {
    match quantity {
        Quantity::Uv => lookup.uv.iter().map(|&x| f64::from(x)).collect(),
        Quantity::Lod => vec![f64::from(lookup.lod)],
        Quantity::Texel => lookup.texel.iter().map(|&x| f64::from(x)).collect(),
    }
}

/// How far the student's value may be from pipelens' and still agree: a tenth of a texel's
/// width at 4096 texels in uv, a hundredth of a level in λ, half an 8-bit step in a colour.
fn tolerance(quantity: Quantity) -> f64 {
    match quantity {
        Quantity::Uv => 2.5e-5,
        Quantity::Lod => 0.01,
        Quantity::Texel => 0.5 / 255.0,
    }
}

/// The student's value named by `compare` at the inspected pixel of `mine` (the run of the
/// fragment that owns it) against pipelens' lookup there (from `reference`, drawn with the same
/// pixel inspected): `None` where they agree, or either is missing.
#[must_use]
pub fn quantity_mismatch(
    compare: &Compare,
    (mine, reference): (&FrameCapture, &FrameCapture),
    scene: &pipeline::scene::Scene,
) -> Option<QuantityMismatch> {
    let (x, y) = mine.settings.capture.pixel?;
    let i = mine.grid().checked_index(x, y)?;
    let owner = *mine.pixels.primitive.get(i)?;
    // pipelens' lookup is its owning fragment's: compared only where that is the student's too.
    if reference.pixels.primitive.get(i) != Some(&owner) {
        return None;
    }
    let lookup = reference.pixels.texture_at(i)?;
    let fragment = mine
        .shaders
        .as_ref()?
        .pixel
        .iter()
        .find(|f| f.primitive == owner)?;
    // The last value written under the name the lesson gives (a function's return as `name()`).
    let (line, value) = fragment.trace.iter().rev().find_map(|l| {
        let (name, value) = l.step.written()?;
        (name == compare.yours).then_some((l.line, value))
    })?;
    let theirs = pipelens_value(compare.pipelens, &lookup);
    // A colour's fourth component (alpha) is not compared.
    let yours: Vec<f64> = value.numbers.iter().copied().take(theirs.len()).collect();
    let agrees = yours.len() == theirs.len()
        && yours
            .iter()
            .zip(&theirs)
            .all(|(a, b)| (a - b).abs() <= tolerance(compare.pipelens));
    if agrees {
        return None;
    }
    let object = mine.primitives.get(owner as usize)?.object as usize;
    let size = scene
        .objects
        .get(object)
        .and_then(|o| o.texture.as_ref())
        .and_then(|t| t.levels.first())
        .map(|l| (l.width, l.height));
    Some(QuantityMismatch {
        name: compare.yours.clone(),
        line,
        quantity: compare.pipelens,
        yours,
        theirs: lookup,
        size,
        pixel: (x, y),
    })
}

impl QuantityMismatch {
    /// The finding in words: the student's value and pipelens' at the inspected pixel, and for
    /// a texel where pipelens' bilinear filter reads.
    #[must_use]
    pub fn words(&self, lang: Lang) -> String {
        let numbers = |v: &[f64]| {
            let parts: Vec<String> = v.iter().map(|x| format!("{x:.3}")).collect();
            match parts.as_slice() {
                [one] => one.clone(),
                _ => format!("({})", parts.join(", ")),
            }
        };
        let (name, line, yours) = (&self.name, self.line, numbers(&self.yours));
        let t = &self.theirs;
        let theirs = numbers(&pipelens_value(self.quantity, t));
        let uv = numbers(&t.uv.map(f64::from));
        let pixel = super::words::pixel(self.pixel);
        let args = [
            ("name", name as &dyn std::fmt::Display),
            ("line", &line),
            ("yours", &yours),
            ("theirs", &theirs),
            ("pixel", &pixel),
        ];
        match self.quantity {
            Quantity::Uv => lang.t_with("quantity-uv-differs", &args),
            Quantity::Lod => {
                let footprint = format!("{:.2}", 2f64.powf(f64::from(t.lod)));
                let mut args = args.to_vec();
                args.extend([
                    ("footprint", &footprint as &dyn std::fmt::Display),
                    ("uv", &uv),
                ]);
                lang.t_with("quantity-lod-differs", &args)
            }
            Quantity::Texel => self.texel_words([&yours, &theirs, &uv, &pixel], lang),
        }
    }

    /// A texel's finding: both colours, and the four texels and weights pipelens mixes.
    /// `yours`, `theirs`, `uv` and `pixel` as [`Self::words`] wrote them.
    fn texel_words(&self, [yours, theirs, uv, pixel]: [&str; 4], lang: Lang) -> String {
        let (name, line) = (&self.name, self.line);
        // The filter reads one level (bilinear): its size; a blend of two levels (trilinear) is
        // said without the texels.
        let level = self.theirs.level;
        let size = self
            .size
            .filter(|_| level.fract() == 0.0)
            .map(|(w, h)| ((w >> level as u32).max(1), (h >> level as u32).max(1)));
        let Some((w, h)) = size else {
            return lang.t_with(
                "quantity-texel-differs",
                &[
                    ("name", name),
                    ("line", &line),
                    ("yours", &yours),
                    ("theirs", &theirs),
                    ("uv", &uv),
                    ("pixel", &pixel),
                ],
            );
        };
        // x = u·w − ½, y = v·h − ½; the texels around (x, y) and the weights between them.
        let x = f64::from(self.theirs.uv[0]) * f64::from(w) - 0.5;
        let y = f64::from(self.theirs.uv[1]) * f64::from(h) - 0.5;
        let (i, j) = (x.floor(), y.floor());
        let (s, t) = (x - i, y - j);
        let on = match level as u32 {
            0 => lang.t_with("quantity-the-texture", &[("w", &w), ("h", &h)]),
            k => lang.t_with("quantity-the-level", &[("k", &k), ("w", &w), ("h", &h)]),
        };
        let (x, y, s, t) = (
            format!("{x:.3}"),
            format!("{y:.3}"),
            format!("{s:.3}"),
            format!("{t:.3}"),
        );
        let (i1, j1) = (i + 1.0, j + 1.0);
        lang.t_with(
            "quantity-bilinear-differs",
            &[
                ("name", name),
                ("line", &line),
                ("yours", &yours),
                ("theirs", &theirs),
                ("uv", &uv),
                ("on", &on),
                ("x", &x),
                ("y", &y),
                ("i", &i),
                ("j", &j),
                ("i1", &i1),
                ("j1", &j1),
                ("s", &s),
                ("t", &t),
                ("pixel", &pixel),
            ],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mismatch(quantity: Quantity, yours: Vec<f64>, level: f32) -> QuantityMismatch {
        QuantityMismatch {
            name: "texel".to_owned(),
            line: 12,
            quantity,
            yours,
            theirs: PixelTexture {
                uv: [0.25, 0.5],
                footprint: [0.0; 4],
                lod: 2.0,
                level,
                texel: [0.5, 0.25, 0.0],
            },
            size: Some((64, 32)),
            pixel: (120, 45),
        }
    }

    /// The findings as a student should read them, the texels and weights worked by hand:
    /// level 1 of 64 × 32 is 32 × 16, x = 0.25·32 − ½ = 7.5, y = 0.5·16 − ½ = 7.5.
    #[test]
    fn a_finding_says_both_values_and_where_the_filter_reads() {
        let texel = mismatch(Quantity::Texel, vec![1.0, 0.0, 0.0], 1.0);
        assert_eq!(
            texel.words(Lang::EN),
            "At the inspected pixel (120, 45) your `texel` (line 12) gives (1.000, 0.000, 0.000); pipelens' \
             bilinear filter reads (0.500, 0.250, 0.000) there: uv (0.250, 0.500) on level 1 \
             (32 × 16) is (x, y) = (7.500, 7.500) (x = u·w − ½, y = v·h − ½), between texels \
             (7, 7) and (8, 8), mixed by s = 0.500 and t = 0.500."
        );
        // Level 0 of 64 × 32: x = 0.25·64 − ½ = 15.5, y = 0.5·32 − ½ = 15.5.
        let level0 = mismatch(Quantity::Texel, vec![1.0, 0.0, 0.0], 0.0);
        assert_eq!(
            level0.words(Lang::ZH),
            "在所检查的像素 (120, 45) 处，你的 `texel`（第 12 行）给出 (1.000, 0.000, 0.000)；pipelens 的双线性\
             过滤在此处读出 (0.500, 0.250, 0.000)：uv (0.250, 0.500) 在 64 × 32 的纹理上是 (x, y) = \
             (15.500, 15.500)（x = u·w − ½，y = v·h − ½），位于纹素 (15, 15) 与 (16, 16) 之间，按 \
             s = 0.500、t = 0.500 混合。"
        );
        // A blend of two levels: said without the texels.
        let blend = mismatch(Quantity::Texel, vec![1.0, 0.0, 0.0], 1.5);
        assert_eq!(
            blend.words(Lang::EN),
            "At the inspected pixel (120, 45) your `texel` (line 12) gives (1.000, 0.000, 0.000); pipelens' \
             filter reads (0.500, 0.250, 0.000) there (uv (0.250, 0.500))."
        );
        let lod = mismatch(Quantity::Lod, vec![1.0], 1.0);
        assert_eq!(
            lod.words(Lang::EN),
            "At the inspected pixel (120, 45) your `texel` (line 12) gives λ = 1.000; pipelens' λ there is \
             2.000: the footprint is L = 2^λ = 4.00 texels a pixel step (uv (0.250, 0.500))."
        );
    }
}
