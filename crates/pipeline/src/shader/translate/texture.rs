//! The texture lookups of naga's IR in register form: `texture`, `textureLod`, `textureGrad`,
//! `textureProj` and their `*Offset` kin on a `sampler2D`, `texture` on a `samplerCube`,
//! `texelFetch`, `textureSize`.

use naga::{Expression, Handle};

use super::super::code::{Level, Op, OpError, Reg};
use super::Translator;

impl Translator<'_> {
    /// Whether `image` is a cube map's texture (`samplerCube`).
    fn is_cube(&self, f: &naga::Function, image: Handle<Expression>) -> bool {
        match f.expressions[image] {
            Expression::GlobalVariable(g) => matches!(
                self.module.types[self.module.global_variables[g].ty].inner,
                naga::TypeInner::Image {
                    dim: naga::ImageDimension::Cube,
                    ..
                }
            ),
            _ => false,
        }
    }

    fn texture_slot(&self, f: &naga::Function, image: Handle<Expression>) -> Result<u32, String> {
        match f.expressions[image] {
            Expression::GlobalVariable(g) => self
                .textures
                .iter()
                .find(|(h, _)| *h == g)
                .map(|(_, s)| *s)
                .ok_or_else(|| "a texture pipelens does not bind".to_owned()),
            _ => Err(
                "a texture passed to a function: use the `sampler2D` (or `samplerCube`) by its name"
                    .to_owned(),
            ),
        }
    }

    /// The lookup `e` (an `ImageSample`, `ImageLoad` or `ImageQuery`), its operands' registers
    /// from `reg`.
    pub(super) fn texture_op(
        &self,
        f: &naga::Function,
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
            } if self.is_cube(f, image) => Op::SampleCube {
                texture: self.texture_slot(f, image)?,
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
                texture: self.texture_slot(f, image)?,
                coordinate: reg(coordinate),
                level: match level {
                    naga::SampleLevel::Auto => Level::Auto,
                    naga::SampleLevel::Zero => Level::Zero,
                    naga::SampleLevel::Exact(l) => Level::Exact(reg(l).at),
                    naga::SampleLevel::Bias(b) => Level::Bias(reg(b).at),
                    naga::SampleLevel::Gradient { x, y } => Level::Gradient {
                        x: reg(x).at,
                        y: reg(y).at,
                    },
                },
                offset: offset.map(|o| reg(o).at),
            },
            Expression::ImageLoad {
                image,
                coordinate,
                level,
                array_index: None,
                sample: None,
            } => Op::Fetch {
                texture: self.texture_slot(f, image)?,
                coordinate: reg(coordinate),
                level: level.map(|l| reg(l).at),
            },
            Expression::ImageQuery {
                image,
                query: naga::ImageQuery::Size { level },
            } => Op::Size {
                texture: self.texture_slot(f, image)?,
                level: level.map(|l| reg(l).at),
            },
            ref other => {
                return Err(format!(
                    "a texture operation pipelens does not run yet ({})",
                    super::describe(other)
                )
                .into());
            }
        })
    }
}
