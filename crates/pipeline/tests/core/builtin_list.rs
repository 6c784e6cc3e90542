//! GLSL 3.30's built-in functions (its chapter 8), every one of pipelens' list
//! (`glsl330::FUNCTIONS`) called as a student would: each either runs — and the scalar ones give
//! what Rust's `f32` gives for the same argument — or is refused at its call with "pipelens does
//! not run `name` yet", never as a misspelt name nor with naga's wording.

use pipeline::shader::{self, Complaint, Stage, Uniforms, glsl330};

use crate::shader::run;

/// A float function of one float as Rust computes it.
type Rust = fn(f32) -> f32;

/// The float functions of one float, with what Rust computes for each.
const UNARY: [(&str, Rust); 27] = [
    ("radians", f32::to_radians),
    ("degrees", f32::to_degrees),
    ("sin", f32::sin),
    ("cos", f32::cos),
    ("tan", f32::tan),
    ("asin", f32::asin),
    ("acos", f32::acos),
    ("atan", f32::atan),
    ("sinh", f32::sinh),
    ("cosh", f32::cosh),
    ("tanh", f32::tanh),
    ("asinh", f32::asinh),
    ("atanh", f32::atanh),
    ("exp", f32::exp),
    ("log", f32::ln),
    ("exp2", f32::exp2),
    ("log2", f32::log2),
    ("sqrt", f32::sqrt),
    ("inversesqrt", |x| 1.0 / x.sqrt()),
    ("abs", f32::abs),
    ("sign", f32::signum),
    ("floor", f32::floor),
    ("trunc", f32::trunc),
    ("round", f32::round),
    ("roundEven", f32::round_ties_even),
    ("ceil", f32::ceil),
    ("fract", |x| x - x.floor()),
];

/// The others: the result's type, the name, the call.
const OTHERS: [(&str, &str, &str); 84] = [
    ("float", "pow", "pow(f, 2.5)"),
    ("float", "mod", "mod(f, 0.25)"),
    ("float", "modf", "modf(1.0 + f, whole)"),
    ("float", "min", "min(f, 0.2)"),
    ("float", "max", "max(f, 0.2)"),
    ("float", "clamp", "clamp(f, 0.1, 0.2)"),
    ("float", "mix", "mix(0.0, 2.0, f)"),
    ("float", "step", "step(0.5, f)"),
    ("float", "smoothstep", "smoothstep(0.0, 1.0, f)"),
    ("bool", "isnan", "isnan(f)"),
    ("bool", "isinf", "isinf(f)"),
    ("int", "floatBitsToInt", "floatBitsToInt(f)"),
    ("uint", "floatBitsToUint", "floatBitsToUint(f)"),
    ("float", "intBitsToFloat", "intBitsToFloat(1050253722)"),
    ("float", "uintBitsToFloat", "uintBitsToFloat(1050253722u)"),
    ("float", "length", "length(v3)"),
    ("float", "distance", "distance(v3, vec3(1.0))"),
    ("float", "dot", "dot(v3, v3)"),
    ("vec3", "cross", "cross(v3, vec3(0.0, 0.0, 1.0))"),
    ("vec3", "normalize", "normalize(v3)"),
    ("vec4", "ftransform", "ftransform()"),
    ("vec3", "faceforward", "faceforward(v3, v3, -v3)"),
    ("vec3", "reflect", "reflect(v3, vec3(0.0, 1.0, 0.0))"),
    (
        "vec3",
        "refract",
        "refract(normalize(v3), vec3(0.0, 1.0, 0.0), 0.9)",
    ),
    ("mat2", "matrixCompMult", "matrixCompMult(m2, m2)"),
    ("mat3", "outerProduct", "outerProduct(v3, v3)"),
    ("mat2", "transpose", "transpose(m2)"),
    ("float", "determinant", "determinant(m2)"),
    ("mat2", "inverse", "inverse(m2)"),
    ("bvec3", "lessThan", "lessThan(v3, vec3(0.4))"),
    ("bvec3", "lessThanEqual", "lessThanEqual(v3, vec3(0.4))"),
    ("bvec3", "greaterThan", "greaterThan(v3, vec3(0.4))"),
    (
        "bvec3",
        "greaterThanEqual",
        "greaterThanEqual(v3, vec3(0.4))",
    ),
    ("bvec3", "equal", "equal(v3, v3)"),
    ("bvec3", "notEqual", "notEqual(v3, v3)"),
    ("bool", "any", "any(b3)"),
    ("bool", "all", "all(b3)"),
    ("bvec3", "not", "not(b3)"),
    ("ivec2", "textureSize", "textureSize(tex, 0)"),
    ("vec4", "texture", "texture(tex, uv)"),
    ("vec4", "textureProj", "textureProj(tex, vec3(uv, 1.0))"),
    ("vec4", "textureLod", "textureLod(tex, uv, 1.0)"),
    (
        "vec4",
        "textureOffset",
        "textureOffset(tex, uv, ivec2(1, 0))",
    ),
    ("vec4", "texelFetch", "texelFetch(tex, ivec2(1, 2), 0)"),
    (
        "vec4",
        "texelFetchOffset",
        "texelFetchOffset(tex, ivec2(1, 2), 0, ivec2(1, 0))",
    ),
    (
        "vec4",
        "textureProjOffset",
        "textureProjOffset(tex, vec3(uv, 1.0), ivec2(1, 0))",
    ),
    (
        "vec4",
        "textureLodOffset",
        "textureLodOffset(tex, uv, 1.0, ivec2(1, 0))",
    ),
    (
        "vec4",
        "textureProjLod",
        "textureProjLod(tex, vec3(uv, 1.0), 1.0)",
    ),
    (
        "vec4",
        "textureProjLodOffset",
        "textureProjLodOffset(tex, vec3(uv, 1.0), 1.0, ivec2(1, 0))",
    ),
    (
        "vec4",
        "textureGrad",
        "textureGrad(tex, uv, vec2(0.01), vec2(0.01))",
    ),
    (
        "vec4",
        "textureGradOffset",
        "textureGradOffset(tex, uv, vec2(0.01), vec2(0.01), ivec2(1, 0))",
    ),
    (
        "vec4",
        "textureProjGrad",
        "textureProjGrad(tex, vec3(uv, 1.0), vec2(0.01), vec2(0.01))",
    ),
    (
        "vec4",
        "textureProjGradOffset",
        "textureProjGradOffset(tex, vec3(uv, 1.0), vec2(0.01), vec2(0.01), ivec2(1, 0))",
    ),
    ("vec4", "texture1D", "texture1D(tex, f)"),
    ("vec4", "texture1DProj", "texture1DProj(tex, v2)"),
    ("vec4", "texture1DLod", "texture1DLod(tex, f, 1.0)"),
    ("vec4", "texture1DProjLod", "texture1DProjLod(tex, v2, 1.0)"),
    ("vec4", "texture2D", "texture2D(tex, uv)"),
    ("vec4", "texture2DProj", "texture2DProj(tex, vec3(uv, 1.0))"),
    ("vec4", "texture2DLod", "texture2DLod(tex, uv, 1.0)"),
    (
        "vec4",
        "texture2DProjLod",
        "texture2DProjLod(tex, vec3(uv, 1.0), 1.0)",
    ),
    ("vec4", "texture3D", "texture3D(tex, v3)"),
    ("vec4", "texture3DProj", "texture3DProj(tex, vec4(v3, 1.0))"),
    ("vec4", "texture3DLod", "texture3DLod(tex, v3, 1.0)"),
    (
        "vec4",
        "texture3DProjLod",
        "texture3DProjLod(tex, vec4(v3, 1.0), 1.0)",
    ),
    ("vec4", "textureCube", "textureCube(environment, v3)"),
    (
        "vec4",
        "textureCubeLod",
        "textureCubeLod(environment, v3, 0.0)",
    ),
    ("vec4", "shadow1D", "shadow1D(tex, v3)"),
    ("vec4", "shadow2D", "shadow2D(tex, v3)"),
    ("vec4", "shadow1DProj", "shadow1DProj(tex, vec4(v3, 1.0))"),
    ("vec4", "shadow2DProj", "shadow2DProj(tex, vec4(v3, 1.0))"),
    ("vec4", "shadow1DLod", "shadow1DLod(tex, v3, 0.0)"),
    ("vec4", "shadow2DLod", "shadow2DLod(tex, v3, 0.0)"),
    (
        "vec4",
        "shadow1DProjLod",
        "shadow1DProjLod(tex, vec4(v3, 1.0), 0.0)",
    ),
    (
        "vec4",
        "shadow2DProjLod",
        "shadow2DProjLod(tex, vec4(v3, 1.0), 0.0)",
    ),
    ("float", "dFdx", "dFdx(f)"),
    ("float", "dFdy", "dFdy(f)"),
    ("float", "fwidth", "fwidth(f)"),
    ("float", "noise1", "noise1(f)"),
    ("vec2", "noise2", "noise2(f)"),
    ("vec3", "noise3", "noise3(f)"),
    ("vec4", "noise4", "noise4(f)"),
    ("void", "EmitVertex", "EmitVertex()"),
    ("void", "EndPrimitive", "EndPrimitive()"),
];

/// One built-in's call: the result's type, the name, the call, what Rust gives (if known).
type Call = (&'static str, &'static str, String, Option<f32>);

/// How each built-in is called: the result's type, the call (with `f` = 0.3 and the locals of
/// [`shader`] in scope), and for a float function of one float what Rust computes for it.
fn calls() -> Vec<Call> {
    let f = 0.3f32;
    let mut out: Vec<_> = UNARY
        .iter()
        .map(|&(name, rust)| ("float", name, format!("{name}(f)"), Some(rust(f))))
        .collect();
    // acosh is defined from 1: called at 1 + f.
    out.push((
        "float",
        "acosh",
        "acosh(1.0 + f)".into(),
        Some((1.0 + f).acosh()),
    ));
    out.extend(
        OTHERS
            .iter()
            .map(|&(ty, name, call)| (ty, name, call.to_owned(), None)),
    );
    out
}

/// A fragment shader that calls `call` on line 8 (column 5 for a `void` call, else after
/// `TYPE r = `) and writes `r`'s first component, as a float, to the colour.
fn shader(ty: &str, call: &str) -> (String, usize) {
    let head = "#version 330 core\nuniform sampler2D tex;\nuniform samplerCube environment;\nin vec2 uv;\nout vec4 color;\nvoid main() {\n    float f = 0.3; float whole; vec2 v2 = vec2(0.3, 1.0); vec3 v3 = vec3(0.3, 0.5, 0.7); mat2 m2 = mat2(1.0, 2.0, 3.0, 4.0); bvec3 b3 = bvec3(true, false, true);\n";
    let (line, column, first) = match ty {
        "void" => (format!("    {call};\n"), 5, "0.0".to_owned()),
        _ => {
            let first = match ty {
                "float" | "int" | "uint" | "bool" => "float(r)".to_owned(),
                "mat2" | "mat3" => "float(r[0][0])".to_owned(),
                _ => "float(r.x)".to_owned(),
            };
            (
                format!("    {ty} r = {call};\n"),
                4 + ty.len() + 5 + 1,
                first,
            )
        }
    };
    (
        format!("{head}{line}    color = vec4({first}, 0.0, 0.0, 1.0);\n}}\n"),
        column,
    )
}

#[test]
fn every_built_in_of_glsl_330_runs_or_is_refused_at_its_call() {
    let calls = calls();
    // The table is the list: every name once, none missing.
    let mut names: Vec<&str> = calls.iter().map(|c| c.1).collect();
    names.sort_unstable();
    let mut list = glsl330::FUNCTIONS.to_vec();
    list.sort_unstable();
    assert_eq!(names, list);
    let (mut ran, mut refused) = (Vec::new(), Vec::new());
    for (ty, name, call, rust) in &calls {
        let (src, column) = shader(ty, call);
        match shader::compile(Stage::Fragment, &src) {
            Ok(p) => {
                let lanes: Vec<Vec<f32>> = (0..4).map(|l| vec![0.25 * l as f32, 0.5]).collect();
                let (out, _) = run(&p, &Uniforms::default(), &[lanes], &[])
                    .unwrap_or_else(|e| panic!("{name}: {e}"));
                if let Some(want) = rust {
                    let got = out[0][0];
                    assert!(
                        (got - want).abs() <= 1e-6 * (1.0 + want.abs()),
                        "{name}(0.3): pipelens {got}, Rust {want}"
                    );
                }
                ran.push(*name);
            }
            Err(e) => {
                assert_eq!(
                    (e[0].complaint.clone(), e[0].line, e[0].column),
                    (Complaint::NotRunYet((*name).to_owned()), 8, column),
                    "{name}: {e:?}"
                );
                assert_eq!(e[0].message, format!("pipelens does not run `{name}` yet"));
                refused.push(*name);
            }
        }
    }
    // What is refused, and why: a geometry shader's (EmitVertex, EndPrimitive) and the
    // compatibility profile's vertex-only ftransform; noise1–4 (0 on every driver, removed
    // from later GLSL); the shadow lookups and the 1D and 3D ones (pipelens binds no shadow,
    // 1D or 3D sampler); texelFetchOffset (naga's front end drops its offset).
    refused.sort_unstable();
    let refused: Vec<String> = refused.into_iter().map(String::from).collect();
    let mut want: Vec<String> = [
        "EmitVertex",
        "EndPrimitive",
        "ftransform",
        "noise1",
        "noise2",
        "noise3",
        "noise4",
        "texelFetchOffset",
    ]
    .map(String::from)
    .to_vec();
    for (kind, d) in [
        ("shadow", "1D"),
        ("shadow", "2D"),
        ("texture", "1D"),
        ("texture", "3D"),
    ] {
        for form in ["", "Lod", "Proj", "ProjLod"] {
            want.push(format!("{kind}{d}{form}"));
        }
    }
    want.sort_unstable();
    assert_eq!(refused, want, "ran: {ran:?}");
    assert_eq!(ran.len(), glsl330::FUNCTIONS.len() - want.len());
}
