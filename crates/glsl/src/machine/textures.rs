//! What the host binds for a program's texture lookups: a texture by its slot, read through
//! the [`Textures`] trait, and what `texelFetch` finds at an address.

use glam::{IVec2, Vec2, Vec3};

/// What `texelFetch` finds at an address.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Texel {
    /// The texel's colour.
    At(glam::Vec3),
    /// The address lies outside the level (or the level outside the texture): a run-time error.
    Outside,
    /// Nothing is bound there, or the texture has no such level: black.
    Unbound,
}

/// The textures a run reads, bound by slot (the order the shader declared its samplers in) by
/// the engine's host. A lookup in a slot with nothing of its kind bound reads black. The sampler
/// state (filter, mipmaps, wrap, bias, anisotropy) is the host's, bound with the texture.
pub trait Textures {
    /// `texture(s, uv)` and its kin on the 2D texture in `slot`, the level of detail from the
    /// footprint's derivatives `dx`, `dy` (in uv a pixel) and the extra `bias`, each level's
    /// read moved by `offset` texels of that level.
    fn sample(
        &self,
        slot: u32,
        uv: Vec2,
        dx: Vec2,
        dy: Vec2,
        bias: f32,
        offset: IVec2,
    ) -> Option<Vec3>;
    /// `textureLod(s, uv, lod)`: the level of detail given.
    fn sample_lod(&self, slot: u32, uv: Vec2, lod: f32, offset: IVec2) -> Option<Vec3>;
    /// `texture(s, r)` of the cube map in `slot`, by direction.
    fn sample_cube(&self, slot: u32, direction: Vec3) -> Option<Vec3>;
    /// `texelFetch(s, ij, level)`: the texel at the integer address.
    fn texel(&self, slot: u32, level: i32, i: i32, j: i32) -> Texel;
    /// `textureSize(s, level)`: the level's width and height, (0, 0) past the last level or
    /// with nothing bound (a cube map has one level, its face's).
    fn size(&self, slot: u32, level: usize) -> (u32, u32);
}

/// No textures: every lookup reads black (a program that declares none).
impl Textures for () {
    fn sample(&self, _: u32, _: Vec2, _: Vec2, _: Vec2, _: f32, _: IVec2) -> Option<Vec3> {
        None
    }
    fn sample_lod(&self, _: u32, _: Vec2, _: f32, _: IVec2) -> Option<Vec3> {
        None
    }
    fn sample_cube(&self, _: u32, _: Vec3) -> Option<Vec3> {
        None
    }
    fn texel(&self, _: u32, _: i32, _: i32, _: i32) -> Texel {
        Texel::Unbound
    }
    fn size(&self, _: u32, _: usize) -> (u32, u32) {
        (0, 0)
    }
}
