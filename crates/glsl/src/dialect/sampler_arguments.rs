//! A `sampler2D` (or `samplerCube`) passed to a function, rewritten into the form naga reads.
//!
//! GLSL 3.30 lets a function take a sampler (§6.1: samplers are "opaque types" and may only be
//! function parameters or uniforms): `vec4 look(sampler2D s, vec2 uv) { return texture(s, uv); }`
//! called as `look(tex, uv)`. naga's front end reads Vulkan GLSL, where a texture and its
//! sampler are apart and a combined `sampler2D` is only ever built on the spot
//! (`sampler2D(t, s)`). So, in the student's text:
//!
//! - the parameter's type `sampler2D s` becomes `texture2D s` (the same length, so nothing
//!   moves); `samplerCube` becomes `textureCube`;
//! - a use of the parameter inside its function, `texture(s, uv)`, becomes
//!   `texture(sampler2D(s, pl_parameter_sampler), uv)`: the texture joined with a sampler
//!   pipelens declares for it ([`PARAMETER_SAMPLER`]). The texture's own sampling state is
//!   bound with the texture, by its slot, so which sampler naga sees does not matter;
//! - an argument in a sampler's place, `look(tex, uv)`, names the texture behind the uniform:
//!   `look(pl_texture_tex, uv)`; a sampler parameter passed on (`look(s, uv)` inside another
//!   function that takes `s`) is left as it is.
//!
//! Each rewrite is an [`Edit`], so a message about the rewritten text maps back to the
//! student's. The machine passes a texture as a value: its slot (see `translate::texture`).

use std::collections::HashMap;
use std::ops::Range;

use super::names::TEXTURE_PREFIX;
use crate::lexeme::{Kind, Lexeme, lex};
use crate::lowering::Edit;

/// The sampler pipelens declares to join a texture parameter with (`sampler2D(s, …)`).
pub const PARAMETER_SAMPLER: &str = "pl_parameter_sampler";

/// The combined sampler types a function may take, with the texture type naga reads instead
/// (each the same length as its sampler, so the rewrite moves nothing).
const PASSED: [(&str, &str); 2] = super::names::SAMPLERS;

/// A function that takes samplers: for each, its place among the parameters and its type.
type Takes = Vec<(usize, &'static str)>;

/// A sampler parameter: its name and its sampler type.
type Named = (String, &'static str);

/// Whether `src` has a function that takes a sampler pipelens passes.
#[must_use]
pub fn any(src: &str) -> bool {
    !headers(&code(src), src).0.is_empty()
}

/// The lexemes of `src` that are code (no comments, no spaces).
fn code(src: &str) -> Vec<Lexeme> {
    lex(src)
        .into_iter()
        .filter(|l| !matches!(l.kind, Kind::Comment | Kind::Space))
        .collect()
}

/// A function header's sampler parameters: the function's name, the lexeme of each sampler
/// type, and the parameters' names with their types.
struct Header {
    /// The lexeme index of the `{` of the body that follows, if one does.
    body: Option<usize>,
    /// The parameters that are samplers, by name, with their sampler type.
    names: Vec<Named>,
}

/// The functions of `src` that take samplers, by name, and each header's parameters; the
/// sampler type words to write as texture types.
fn headers(code: &[Lexeme], src: &str) -> (HashMap<String, Takes>, Vec<Header>, Vec<usize>) {
    let text = |k: usize| code.get(k).map_or("", |l| &src[l.span.clone()]);
    let mut takes: HashMap<String, Takes> = HashMap::new();
    let (mut out, mut types) = (Vec::new(), Vec::new());
    let mut braces = 0i32;
    let mut k = 0;
    while k < code.len() {
        match text(k) {
            "{" => braces += 1,
            "}" => braces -= 1,
            "(" if braces == 0 && k > 0 && code[k - 1].kind == Kind::Word => {
                let name = text(k - 1).to_owned();
                let (mut parens, mut index) = (0i32, 0usize);
                let mut header = Header {
                    body: None,
                    names: Vec::new(),
                };
                let mut passed = Vec::new();
                while k < code.len() {
                    match text(k) {
                        "(" => parens += 1,
                        ")" => parens -= 1,
                        "," if parens == 1 => index += 1,
                        word => {
                            if let Some(&(sampler, _)) = PASSED.iter().find(|(s, _)| *s == word) {
                                passed.push((index, sampler));
                                types.push(k);
                                if code.get(k + 1).is_some_and(|l| l.kind == Kind::Word) {
                                    header.names.push((text(k + 1).to_owned(), sampler));
                                }
                            }
                        }
                    }
                    k += 1;
                    if parens == 0 {
                        break;
                    }
                }
                if text(k) == "{" {
                    header.body = Some(k);
                }
                if !passed.is_empty() {
                    takes.insert(name, passed);
                    out.push(header);
                }
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    (takes, out, types)
}

/// `src` with every sampler parameter, its uses and the arguments passed to it rewritten
/// (see the module's text), and the edits; `textures` are the names of the student's
/// `uniform sampler2D` (and `samplerCube`) declarations.
#[must_use]
pub fn rewrite(src: &str, textures: &[String]) -> (String, Vec<Edit>) {
    let code = code(src);
    let (takes, headers, types) = headers(&code, src);
    if takes.is_empty() {
        return (src.to_owned(), Vec::new());
    }
    let text = |k: usize| code.get(k).map_or("", |l| &src[l.span.clone()]);
    let mut replacements: Vec<(Range<usize>, String)> = types
        .iter()
        .map(|&k| {
            let texture = PASSED
                .iter()
                .find(|(s, _)| *s == text(k))
                .map_or("", |p| p.1);
            (code[k].span.clone(), texture.to_owned())
        })
        .collect();
    // Where each body ends, and the sampler parameters in scope there.
    let mut scopes: Vec<(Range<usize>, &[Named])> = Vec::new();
    for h in &headers {
        if let Some(open) = h.body {
            let mut depth = 0i32;
            let close = (open..code.len())
                .find(|&k| {
                    depth += match text(k) {
                        "{" => 1,
                        "}" => -1,
                        _ => 0,
                    };
                    depth == 0
                })
                .unwrap_or(code.len());
            scopes.push((open..close, &h.names));
        }
    }
    // The calls open at each lexeme: the callee's name (None for a plain parenthesis) and the
    // argument being read.
    let mut calls: Vec<(Option<&str>, usize)> = Vec::new();
    let mut braces = 0i32;
    for k in 0..code.len() {
        match text(k) {
            "{" => braces += 1,
            "}" => braces -= 1,
            "(" => {
                let callee = (k > 0 && code[k - 1].kind == Kind::Word).then(|| text(k - 1));
                calls.push((callee, 0));
            }
            ")" => {
                calls.pop();
            }
            "," => {
                if let Some(top) = calls.last_mut() {
                    top.1 += 1;
                }
            }
            word if braces > 0 && code[k].kind == Kind::Word => {
                let alone = matches!(text(k.wrapping_sub(1)), "(" | ",")
                    && matches!(text(k + 1), ")" | ",");
                let passed = alone
                    && calls.last().is_some_and(|&(callee, arg)| {
                        callee
                            .and_then(|c| takes.get(c))
                            .is_some_and(|t| t.iter().any(|(i, _)| *i == arg))
                    });
                let parameter = scopes
                    .iter()
                    .find(|(body, _)| body.contains(&k))
                    .and_then(|(_, names)| names.iter().find(|(n, _)| n == word))
                    .filter(|_| text(k.wrapping_sub(1)) != ".");
                if let Some((_, sampler)) = parameter {
                    if !passed {
                        replacements.push((
                            code[k].span.clone(),
                            format!("{sampler}({word}, {PARAMETER_SAMPLER})"),
                        ));
                    }
                } else if passed && textures.iter().any(|t| t == word) {
                    replacements.push((code[k].span.clone(), format!("{TEXTURE_PREFIX}{word}")));
                }
            }
            _ => {}
        }
    }
    replace(src, replacements)
}

/// `src` with each range replaced by its text, and the edits that map back.
fn replace(src: &str, mut replacements: Vec<(Range<usize>, String)>) -> (String, Vec<Edit>) {
    replacements.sort_by_key(|(r, _)| r.start);
    let mut out = String::with_capacity(src.len() + 64 * replacements.len());
    let mut edits = Vec::new();
    let mut copied = 0;
    for (old, new) in replacements {
        out.push_str(&src[copied..old.start]);
        let start = out.len();
        out.push_str(&new);
        if new.len() != old.len() {
            edits.push(Edit {
                new: start..out.len(),
                old: old.clone(),
            });
        }
        copied = old.end;
    }
    out.push_str(&src[copied..]);
    (out, edits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lowering::before_edits;

    #[test]
    fn a_sampler_parameter_its_uses_and_its_arguments_are_rewritten() {
        let src = "vec4 look(sampler2D s, vec2 uv) { return texture(s, uv) + vec4(textureSize(s, 0), 0, 0); }\n\
                   vec4 twice(sampler2D s) { return look(s, vec2(0.5)); }\n\
                   void main() { c = look(tex, v) + twice(tex) + texture(tex, v); }";
        let (out, edits) = rewrite(src, &["tex".to_owned()]);
        assert_eq!(
            out,
            "vec4 look(texture2D s, vec2 uv) { return texture(sampler2D(s, pl_parameter_sampler), uv) \
             + vec4(textureSize(sampler2D(s, pl_parameter_sampler), 0), 0, 0); }\n\
             vec4 twice(texture2D s) { return look(s, vec2(0.5)); }\n\
             void main() { c = look(pl_texture_tex, v) + twice(pl_texture_tex) + texture(tex, v); }"
        );
        // After the rewrites, a place maps back to the student's.
        let back =
            |s: &str, n: usize| before_edits(&edits, out.match_indices(s).nth(n).expect(s).0);
        assert_eq!(back("uv)", 0), src.find("uv)").expect("uv"));
        assert_eq!(
            back("texture(tex", 0),
            src.find("texture(tex").expect("tex")
        );
        // Inside a rewrite: where the student's name was.
        assert_eq!(
            back("pl_parameter_sampler", 1),
            src.find("(s, 0)").expect("s") + 1
        );
    }

    #[test]
    fn a_cube_map_and_a_prototype_are_rewritten_and_the_rest_left_alone() {
        let src = "vec3 sky(samplerCube c, vec3 r);\nvec3 sky(samplerCube c, vec3 r) { return texture(c, r).rgb; }";
        let (out, _) = rewrite(src, &[]);
        assert_eq!(
            out,
            "vec3 sky(textureCube c, vec3 r);\nvec3 sky(textureCube c, vec3 r) { return texture(samplerCube(c, pl_parameter_sampler), r).rgb; }"
        );
        for same in [
            "void main() { c = texture(tex, uv); }",
            "// vec4 f(sampler2D s)\nvoid main() {}",
        ] {
            assert_eq!(rewrite(same, &["tex".to_owned()]).0, same);
            assert!(!any(same));
        }
    }
}
