//! The texture lookups of naga's IR in register form: `texture`, `textureLod`, `textureGrad`,
//! `textureProj` and their `*Offset` kin on a `sampler2D`, `texture` on a `samplerCube`,
//! `texelFetch`, `textureSize`.

use naga::valid::FunctionInfo;
use naga::{Expression, Handle};

use super::translator::Translator;
use crate::register_form::{Level, Op, OpError, Reg};

impl Translator<'_> {
    /// Whether `image` is a cube map's texture (`samplerCube`).
    fn is_cube(
        fi: &FunctionInfo,
        types: &naga::UniqueArena<naga::Type>,
        image: Handle<Expression>,
    ) -> bool {
        matches!(
            fi[image].ty.inner_with(types),
            naga::TypeInner::Image {
                dim: naga::ImageDimension::Cube,
                ..
            }
        )
    }

    /// The register that holds the slot of the texture `image`: a uniform's (set by
    /// [`Self::texture_value`]), or a texture passed to the function.
    fn texture_register(
        &self,
        f: &naga::Function,
        image: Handle<Expression>,
        reg: &dyn Fn(Handle<Expression>) -> Reg,
    ) -> Result<u32, String> {
        match f.expressions[image] {
            Expression::GlobalVariable(g) if self.texture_value(g).is_none() => {
                Err("a texture pipelens does not bind".to_owned())
            }
            Expression::GlobalVariable(_) | Expression::FunctionArgument(_) => Ok(reg(image).first),
            _ => Err("a texture chosen at run time: name the `sampler2D` itself".to_owned()),
        }
    }

    /// The value of the texture global `g`, its slot, when pipelens binds it.
    pub(super) fn texture_value(&self, g: Handle<naga::GlobalVariable>) -> Option<u32> {
        self.textures.iter().find(|(h, _)| *h == g).map(|(_, s)| *s)
    }

    /// The lookup `e` (an `ImageSample`, `ImageLoad` or `ImageQuery`), its operands' registers
    /// from `reg`.
    pub(super) fn texture_op(
        &self,
        f: &naga::Function,
        fi: &FunctionInfo,
        e: &Expression,
        reg: &dyn Fn(Handle<Expression>) -> Reg,
    ) -> Result<Op, OpError> {
        Ok(match *e {
            Expression::ImageSample {
                image,
                coordinate,
                gather: None,
                depth_ref: None,
                array_index: None,
                offset: None,
                ..
            } if Self::is_cube(fi, &self.module.types, image) => Op::SampleCube {
                texture: self.texture_register(f, image, reg)?,
                direction: reg(coordinate),
            },
            Expression::ImageSample {
                image,
                coordinate,
                level,
                offset,
                gather: None,
                depth_ref: None,
                array_index: None,
                ..
            } => Op::Sample {
                texture: self.texture_register(f, image, reg)?,
                coordinate: reg(coordinate),
                level: match level {
                    naga::SampleLevel::Auto => Level::Auto,
                    naga::SampleLevel::Zero => Level::Zero,
                    naga::SampleLevel::Exact(l) => Level::Exact(reg(l).first),
                    naga::SampleLevel::Bias(b) => Level::Bias(reg(b).first),
                    naga::SampleLevel::Gradient { x, y } => Level::Gradient {
                        x: reg(x).first,
                        y: reg(y).first,
                    },
                },
                offset: offset.map(|o| reg(o).first),
            },
            Expression::ImageLoad {
                image,
                coordinate,
                level,
                array_index: None,
                sample: None,
            } => Op::Fetch {
                texture: self.texture_register(f, image, reg)?,
                coordinate: reg(coordinate),
                level: level.map(|l| reg(l).first),
            },
            Expression::ImageQuery {
                image,
                query: naga::ImageQuery::Size { level },
            } => Op::Size {
                texture: self.texture_register(f, image, reg)?,
                level: level.map(|l| reg(l).first),
            },
            ref other => {
                return Err(format!(
                    "a texture operation pipelens does not run yet ({})",
                    super::translator::describe(other)
                )
                .into());
            }
        })
    }
}
