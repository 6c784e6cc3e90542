//! The textures a shader's run reads, bound per slot: the object's texture with the sampler the
//! settings give, its bump or displacement map, the cube map it mirrors. The GLSL engine reads
//! them through its [`Textures`] trait.

use glam::{IVec2, Vec2, Vec3};
use pipelens_glsl::{Texel, Textures};

use crate::texture::{CubeMap, Sampler, Texture, Wrap};

/// What a texture slot holds.
#[derive(Clone, Copy)]
pub enum Bound<'a> {
    /// A 2D texture (`sampler2D`) and how it is sampled.
    Image(&'a Texture, Sampler),
    /// A cube map (`samplerCube`), looked up by direction: bilinear within the face the
    /// direction falls on, one level ([`CubeMap::sample`]).
    Cube(&'a CubeMap),
}

/// The textures and sampler a run reads.
#[derive(Clone, Copy)]
pub struct Bindings<'a> {
    /// What each slot holds (`None`: nothing bound, or not of the slot's kind; lookups return
    /// black).
    pub textures: &'a [Option<Bound<'a>>],
}

impl<'a> Bindings<'a> {
    /// The 2D texture in slot `slot` and its sampler, if one is bound.
    #[must_use]
    pub fn bound(&self, slot: u32) -> Option<(&'a Texture, Sampler)> {
        match self.textures.get(slot as usize).copied().flatten()? {
            Bound::Image(t, s) => Some((t, s)),
            Bound::Cube(_) => None,
        }
    }

    /// The cube map in slot `slot`, if one is bound.
    #[must_use]
    pub fn cube(&self, slot: u32) -> Option<&'a CubeMap> {
        match self.textures.get(slot as usize).copied().flatten()? {
            Bound::Cube(c) => Some(c),
            Bound::Image(..) => None,
        }
    }
}

impl Textures for Bindings<'_> {
    /// The bound sampler's filter, with `bias` added to its own LOD bias.
    fn sample(
        &self,
        slot: u32,
        uv: Vec2,
        dx: Vec2,
        dy: Vec2,
        bias: f32,
        offset: IVec2,
    ) -> Option<Vec3> {
        let (t, mut sampler) = self.bound(slot)?;
        sampler.lod_bias += bias;
        Some(t.sample_shifted(uv, dx, dy, &sampler, offset).color)
    }

    fn sample_lod(&self, slot: u32, uv: Vec2, lod: f32, offset: IVec2) -> Option<Vec3> {
        let (t, sampler) = self.bound(slot)?;
        Some(t.sample_lod(uv, lod, &sampler, offset).0)
    }

    fn sample_cube(&self, slot: u32, direction: Vec3) -> Option<Vec3> {
        Some(self.cube(slot)?.sample(direction))
    }

    /// Level `level`'s texel (i, j), no filtering; outside `[0, w) × [0, h)`,
    /// [`Texel::Outside`] (GLSL leaves the result undefined; pipelens says so); a level the
    /// texture does not have reads black.
    fn texel(&self, slot: u32, level: i32, i: i32, j: i32) -> Texel {
        let level = self
            .bound(slot)
            .and_then(|(t, _)| t.levels.get(usize::try_from(level).ok()?));
        match level {
            Some(lv) if (0..lv.width as i32).contains(&i) && (0..lv.height as i32).contains(&j) => {
                Texel::At(lv.texel(i64::from(i), i64::from(j), Wrap::Clamp))
            }
            Some(_) => Texel::Outside,
            None => Texel::Unbound,
        }
    }

    fn size(&self, slot: u32, level: usize) -> (u32, u32) {
        let face = self.cube(slot).map(|c| &c.faces[0]);
        self.bound(slot)
            .and_then(|(t, _)| t.levels.get(level))
            .or(face.filter(|_| level == 0))
            .map_or((0, 0), |lv| (lv.width, lv.height))
    }
}
