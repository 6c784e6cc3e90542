//! The language pipelens reads: the built-in functions of GLSL 3.30, to tell one pipelens does
//! not run yet from a misspelt name, and those naga's front end lacks written in GLSL.

/// The built-in functions of GLSL 3.30 (its chapter 8, the deprecated texture functions of
/// GLSL 1.20 among them): a call of one naga does not know is one pipelens does not run yet,
/// not a misspelt name.
pub const FUNCTIONS: [&str; 112] = [
    // 8.1 Angle and trigonometry.
    "radians",
    "degrees",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "sinh",
    "cosh",
    "tanh",
    "asinh",
    "acosh",
    "atanh",
    // 8.2 Exponential.
    "pow",
    "exp",
    "log",
    "exp2",
    "log2",
    "sqrt",
    "inversesqrt",
    // 8.3 Common.
    "abs",
    "sign",
    "floor",
    "trunc",
    "round",
    "roundEven",
    "ceil",
    "fract",
    "mod",
    "modf",
    "min",
    "max",
    "clamp",
    "mix",
    "step",
    "smoothstep",
    "isnan",
    "isinf",
    "floatBitsToInt",
    "floatBitsToUint",
    "intBitsToFloat",
    "uintBitsToFloat",
    // 8.4 Geometric.
    "length",
    "distance",
    "dot",
    "cross",
    "normalize",
    "ftransform",
    "faceforward",
    "reflect",
    "refract",
    // 8.5 Matrix.
    "matrixCompMult",
    "outerProduct",
    "transpose",
    "determinant",
    "inverse",
    // 8.6 Vector relational.
    "lessThan",
    "lessThanEqual",
    "greaterThan",
    "greaterThanEqual",
    "equal",
    "notEqual",
    "any",
    "all",
    "not",
    // 8.7 Texture lookup.
    "textureSize",
    "texture",
    "textureProj",
    "textureLod",
    "textureOffset",
    "texelFetch",
    "texelFetchOffset",
    "textureProjOffset",
    "textureLodOffset",
    "textureProjLod",
    "textureProjLodOffset",
    "textureGrad",
    "textureGradOffset",
    "textureProjGrad",
    "textureProjGradOffset",
    "texture1D",
    "texture1DProj",
    "texture1DLod",
    "texture1DProjLod",
    "texture2D",
    "texture2DProj",
    "texture2DLod",
    "texture2DProjLod",
    "texture3D",
    "texture3DProj",
    "texture3DLod",
    "texture3DProjLod",
    "textureCube",
    "textureCubeLod",
    "shadow1D",
    "shadow2D",
    "shadow1DProj",
    "shadow2DProj",
    "shadow1DLod",
    "shadow2DLod",
    "shadow1DProjLod",
    "shadow2DProjLod",
    // 8.8 Fragment processing.
    "dFdx",
    "dFdy",
    "fwidth",
    // 8.9 Noise.
    "noise1",
    "noise2",
    "noise3",
    "noise4",
    // 8.10 Geometry shader functions.
    "EmitVertex",
    "EndPrimitive",
];

/// The built-ins of GLSL 3.30 that naga's front end does not know, written in GLSL with their
/// overloads (§8.3, §8.5): each is put before the student's code when the student calls it
/// (and does not define it), and runs as pipelens' own — no step of it in the trace, only the
/// call's result and its `out` argument.
pub const WRITTEN_IN_GLSL: [(&str, &str); 2] = [
    (
        "modf",
        // "Returns the fractional part of x and sets i to the integer part (as a whole number
        // floating-point value). Both the return value and the output parameter will have the
        // same sign as x."
        "float modf(float x, out float i) { i = trunc(x); return x - i; }\n\
         vec2 modf(vec2 x, out vec2 i) { i = trunc(x); return x - i; }\n\
         vec3 modf(vec3 x, out vec3 i) { i = trunc(x); return x - i; }\n\
         vec4 modf(vec4 x, out vec4 i) { i = trunc(x); return x - i; }\n",
    ),
    (
        "matrixCompMult",
        // "Multiply matrix x by matrix y component-wise, i.e., result[i][j] is the scalar
        // product of x[i][j] and y[i][j]."
        "mat2 matrixCompMult(mat2 x, mat2 y) { return mat2(x[0] * y[0], x[1] * y[1]); }\n\
         mat3 matrixCompMult(mat3 x, mat3 y) { return mat3(x[0] * y[0], x[1] * y[1], x[2] * y[2]); }\n\
         mat4 matrixCompMult(mat4 x, mat4 y) { return mat4(x[0] * y[0], x[1] * y[1], x[2] * y[2], x[3] * y[3]); }\n\
         mat2x3 matrixCompMult(mat2x3 x, mat2x3 y) { return mat2x3(x[0] * y[0], x[1] * y[1]); }\n\
         mat2x4 matrixCompMult(mat2x4 x, mat2x4 y) { return mat2x4(x[0] * y[0], x[1] * y[1]); }\n\
         mat3x2 matrixCompMult(mat3x2 x, mat3x2 y) { return mat3x2(x[0] * y[0], x[1] * y[1], x[2] * y[2]); }\n\
         mat3x4 matrixCompMult(mat3x4 x, mat3x4 y) { return mat3x4(x[0] * y[0], x[1] * y[1], x[2] * y[2]); }\n\
         mat4x2 matrixCompMult(mat4x2 x, mat4x2 y) { return mat4x2(x[0] * y[0], x[1] * y[1], x[2] * y[2], x[3] * y[3]); }\n\
         mat4x3 matrixCompMult(mat4x3 x, mat4x3 y) { return mat4x3(x[0] * y[0], x[1] * y[1], x[2] * y[2], x[3] * y[3]); }\n",
    ),
];

/// The GLSL of [`WRITTEN_IN_GLSL`] that `src` calls and does not define itself.
pub(super) fn written_in_glsl(src: &str) -> impl Iterator<Item = &'static str> + '_ {
    let calls = super::lexeme::calls(src);
    WRITTEN_IN_GLSL
        .into_iter()
        .filter(move |(name, _)| {
            calls.iter().any(|l| src[l.span.clone()] == **name)
                && super::lexeme::definition(src, name).is_none()
        })
        .map(|(_, glsl)| glsl)
}
