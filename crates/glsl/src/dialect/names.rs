//! The names pipelens puts into a student's shader: the texture and sampler behind each
//! `sampler2D` or `samplerCube`, and the output that a GLSL 1.x `gl_FragColor` becomes (its
//! light type and constants are `interface::light_declarations`).

/// The combined samplers a student may declare, with the separate texture type naga reads
/// behind each: a 2D texture, and a cube map looked up by direction.
pub(super) const SAMPLERS: [(&str, &str); 2] =
    [("sampler2D", "texture2D"), ("samplerCube", "textureCube")];

/// The sampler type `name` and its texture type, if it is one pipelens binds.
pub(super) fn sampler_kind(name: &str) -> Option<(&'static str, &'static str)> {
    SAMPLERS.iter().copied().find(|(s, _)| *s == name)
}

/// Prefix of the names pipelens gives the texture and sampler behind a `sampler2D`.
pub const TEXTURE_PREFIX: &str = "pl_texture_";
/// See [`TEXTURE_PREFIX`].
pub const SAMPLER_PREFIX: &str = "pl_sampler_";
/// The output a GLSL 1.x fragment shader's `gl_FragColor` becomes.
pub const FRAG_COLOR: &str = "pl_FragColor";
