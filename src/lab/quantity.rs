//! The quantity a texture lab asks the student to compute, against pipelens' own at the
//! inspected pixel: the lesson names a value of the student's fragment shader
//! (`exercise.compare.yours`: a variable, or a function's return as `name()`) and the quantity it
//! stands for (`uv`, `lod`, `texel`). pipelens' own comes from its texture lookup at the pixel,
//! which every frame with the pixel inspected keeps.

use crate::vocabulary::Written;
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
        match (self.quantity, lang.written()) {
            (Quantity::Uv, Written::English) => format!(
                "At the inspected pixel your `{name}` (line {line}) is {yours}; pipelens' uv there, interpolated perspective-correctly, is {theirs}."
            ),
            (Quantity::Uv, Written::Chinese) => format!(
                "在所检查的像素处，你的 `{name}`（第 {line} 行）是 {yours}；pipelens 在此处经透视校正插值的 uv 是 {theirs}。"
            ),
            (Quantity::Lod, Written::English) => format!(
                "At the inspected pixel your `{name}` (line {line}) gives λ = {yours}; pipelens' λ there is {theirs}: the footprint is L = 2^λ = {:.2} texels a pixel step (uv {uv}).",
                2f64.powf(f64::from(t.lod))
            ),
            (Quantity::Lod, Written::Chinese) => format!(
                "在所检查的像素处，你的 `{name}`（第 {line} 行）给出 λ = {yours}；pipelens 在此处的 λ 是 {theirs}：像素每走一步，覆盖区域是 L = 2^λ = {:.2} 个纹素（uv {uv}）。",
                2f64.powf(f64::from(t.lod))
            ),
            (Quantity::Texel, _) => self.texel_words(&yours, &theirs, &uv, lang),
        }
    }

    /// A texel's finding: both colours, and the four texels and weights pipelens mixes.
    fn texel_words(&self, yours: &str, theirs: &str, uv: &str, lang: Lang) -> String {
        let (name, line) = (&self.name, self.line);
        // The filter reads one level (bilinear): its size; a blend of two levels (trilinear) is
        // said without the texels.
        let level = self.theirs.level;
        let size = self
            .size
            .filter(|_| level.fract() == 0.0)
            .map(|(w, h)| ((w >> level as u32).max(1), (h >> level as u32).max(1)));
        let Some((w, h)) = size else {
            return match lang.written() {
                Written::English => format!(
                    "At the inspected pixel your `{name}` (line {line}) gives {yours}; pipelens' filter reads {theirs} there (uv {uv})."
                ),
                Written::Chinese => format!(
                    "在所检查的像素处，你的 `{name}`（第 {line} 行）给出 {yours}；pipelens 的过滤在此处读出 {theirs}（uv {uv}）。"
                ),
            };
        };
        // x = u·w − ½, y = v·h − ½; the texels around (x, y) and the weights between them.
        let x = f64::from(self.theirs.uv[0]) * f64::from(w) - 0.5;
        let y = f64::from(self.theirs.uv[1]) * f64::from(h) - 0.5;
        let (i, j) = (x.floor(), y.floor());
        let (s, t) = (x - i, y - j);
        let on = match (lang.written(), level as u32) {
            (Written::English, 0) => format!("the {w} × {h} texture"),
            (Written::English, k) => format!("level {k} ({w} × {h})"),
            (Written::Chinese, 0) => format!(" {w} × {h} 的纹理"),
            (Written::Chinese, k) => format!("第 {k} 层（{w} × {h}）"),
        };
        match lang.written() {
            Written::English => format!(
                "At the inspected pixel your `{name}` (line {line}) gives {yours}; pipelens' bilinear filter reads {theirs} there: uv {uv} on {on} is (x, y) = ({x:.3}, {y:.3}) (x = u·w − ½, y = v·h − ½), between texels ({i}, {j}) and ({}, {}), mixed by s = {s:.3} and t = {t:.3}.",
                i + 1.0,
                j + 1.0
            ),
            Written::Chinese => format!(
                "在所检查的像素处，你的 `{name}`（第 {line} 行）给出 {yours}；pipelens 的双线性过滤在此处读出 {theirs}：uv {uv} 在{on}上是 (x, y) = ({x:.3}, {y:.3})（x = u·w − ½，y = v·h − ½），位于纹素 ({i}, {j}) 与 ({}, {}) 之间，按 s = {s:.3}、t = {t:.3} 混合。",
                i + 1.0,
                j + 1.0
            ),
        }
    }
}
