//! What a compile message says, as data: naga's GLSL front end reports a missing `;` as
//! "Expected Comma or Semicolon, found TypeName(Type { name: None, inner: Vector { … } })" at the
//! token after it. A [`Complaint`] names the mistake (a `;` missing at the end of line 20, a
//! name not declared, two types an operator cannot combine) so that the interface can say it as
//! a sentence in its own language (`vocabulary::compile` in the app); the English `message` of
//! [`crate::ShaderError`] stays beside it for whatever no complaint covers.

use std::ops::Range;

use naga::front::glsl::{ErrorKind, ExpectedToken, TokenValue};

/// A compile message's mistake, with what the sentence needs.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum Complaint {
    /// A `;` is missing at the end of the line the message is at.
    MissingSemicolon,
    /// The parser met `found` where it expected one of `expected` (written as the source
    /// writes them: `)`, `,`, `a name`…).
    Unexpected {
        /// The text found, as the student wrote it (empty at the end of the file).
        found: String,
        /// What could stand there.
        expected: Vec<String>,
    },
    /// The file ended inside a block or a call: a `}` or `)` is missing.
    UnexpectedEnd,
    /// A name used before it was declared (or misspelt).
    UnknownVariable(String),
    /// A type GLSL does not have.
    UnknownType(String),
    /// A field or swizzle the value does not have (`.w` of a vec3, `.pos` of a struct).
    UnknownField(String),
    /// A function no declaration or built-in matches, by name or by its arguments.
    UnknownFunction(String),
    /// A name declared twice in the same scope.
    AlreadyDeclared(String),
    /// A function defined twice.
    FunctionAlreadyDefined,
    /// An operator between values whose types it cannot combine (`vec3 * vec4`, `int + float`).
    CannotCombine,
    /// A constructor given more numbers than its type holds.
    TooManyArguments,
    /// A constructor that cannot build its type from these arguments.
    BadConstructor,
    /// An array size or a `const` that must be known when compiling and is not.
    NotConstant,
    /// An assignment to what cannot be written: a uniform, an input, a constant.
    NotAssignable,
    /// A value of type `void` used (a function that returns nothing, used in an expression).
    VoidValue,
    /// `#version` not on the first line.
    VersionNotFirst,
    /// A `#version` GLSL does not have (as written after `#version`: `999 core`, `3.30`).
    InvalidVersion(String),
    /// `%` between floats: GLSL's `%` takes integers (`mod` is the float form).
    FloatModulo,
    /// A swizzle with a component twice on the left of `=` (`v.xx = …`), or too many.
    BadSwizzle,
    /// A value stored into a variable of another type (`vec3 c = vec4(…)`).
    TypeMismatch,
    /// A returned value of another type than the function's, or a value-returning function
    /// that may end without `return`.
    ReturnType,
    /// A whole number too large for 32 bits.
    IntegerOverflow,
    /// A form naga's front end does not take yet.
    NotImplemented(String),
    /// A built-in function of GLSL that pipelens does not run yet (as GLSL spells it).
    NotRunYet(String),
    /// A sampler pipelens does not bind (`sampler3D`, as GLSL spells its type) declared as a
    /// function's parameter.
    SamplerParameter(String),
    /// A function that calls itself (GLSL allows no recursion).
    Recursion(String),
    /// A function called above its definition, with no prototype before the call.
    DefinedBelow(String),
    /// A call of a function defined above whose arguments' types match none of its
    /// definitions: the function's name and its parameter list as the student wrote it.
    ArgumentTypes {
        /// The function called.
        name: String,
        /// Its parameters, `(sampler2D s, vec2 at)`.
        parameters: String,
    },
    /// pipelens' own checks: a uniform pipelens does not set, with the nearest name it sets.
    UnknownUniform {
        /// The name declared.
        name: String,
        /// The uniform meant, when one is close.
        suggestion: Option<String>,
    },
    /// A uniform of the student's own whose comment starts like its control
    /// (`// MIN..MAX = VALUE`) but is not one.
    OwnUniformControl {
        /// The uniform.
        name: String,
        /// What is wrong with the comment, in English.
        why: String,
    },
    /// A uniform pipelens sets (its type is in [`super::interface::UNIFORMS`]), declared with
    /// another type.
    UniformType {
        /// The uniform.
        name: String,
        /// The type declared.
        written: String,
    },
    /// A texture pipelens binds, declared with the other sampler type (`sampler2D` for a cube
    /// map, `samplerCube` for a 2D texture).
    TextureType {
        /// The texture.
        name: String,
        /// The sampler type declared.
        written: String,
        /// The sampler type pipelens binds it as.
        expected: &'static str,
    },
    /// A texture pipelens does not bind (it binds `tex` and `detail`).
    UnknownTexture {
        /// The name declared.
        name: String,
        /// The texture meant, when one is close.
        suggestion: Option<String>,
    },
    /// A vertex attribute pipelens does not feed.
    UnknownAttribute {
        /// The name declared.
        name: String,
        /// The attribute meant, when one is close.
        suggestion: Option<String>,
    },
    /// More than one fragment output (pipelens draws into one colour buffer).
    OneColourOutput,
    /// A uniform assigned to.
    UniformWritten(String),
    /// A vertex shader that never writes `gl_Position`.
    NoPosition,
    /// A fragment shader with no output.
    NoOutput,
    /// A fragment shader that never writes its output.
    OutputNotWritten(String),
    /// A fragment input whose vertex output has another number of components.
    VaryingComponents {
        /// The varying.
        name: String,
        /// Its components in the fragment shader.
        here: u32,
        /// In the vertex shader.
        vertex: u32,
    },
    /// A fragment input no vertex output feeds.
    NoVaryingSource {
        /// The input.
        name: String,
        /// The vertex shader's outputs.
        outputs: Vec<String>,
    },
    /// A pipeline function (`inside`, `depth_test`, …) not defined with the signature pipelens
    /// calls.
    HookSignature(String),
    /// At run time: a loop ran more than the budget's steps (an endless loop?).
    EndlessLoop {
        /// The budget, in steps.
        budget: u32,
    },
    /// At run time: an index outside an array.
    IndexOutOfRange {
        /// The index.
        index: i64,
        /// The last index there is.
        last: u32,
        /// The array, where it has a name.
        name: Option<String>,
    },
    /// At run time: a `texelFetch` outside its texture's level.
    TexelOutside {
        /// The texel's column.
        i: i32,
        /// Its row.
        j: i32,
        /// The level.
        level: i32,
    },
    /// At run time: an integer divided by zero (`%`: its remainder).
    DivisionByZero {
        /// Whether it was `%`.
        remainder: bool,
    },
    /// Anything else: the English message says it.
    #[default]
    Other,
}

/// A parse error's complaint, and the span it is best reported at: a missing `;` belongs to the
/// end of the line before the token the parser met, not to that token.
#[must_use]
pub fn of_parse(kind: &ErrorKind, source: &str, span: Range<usize>) -> (Complaint, Range<usize>) {
    match kind {
        ErrorKind::EndOfFile => (Complaint::UnexpectedEnd, span),
        ErrorKind::InvalidVersion(v) => (Complaint::InvalidVersion(v.to_string()), span),
        ErrorKind::NotImplemented(what) => (Complaint::NotImplemented((*what).to_owned()), span),
        ErrorKind::UnknownVariable(n) => (Complaint::UnknownVariable(n.clone()), span),
        ErrorKind::UnknownType(n) => (Complaint::UnknownType(n.clone()), span),
        ErrorKind::UnknownField(n) => (Complaint::UnknownField(n.clone()), span),
        ErrorKind::VariableAlreadyDeclared(n) => (Complaint::AlreadyDeclared(n.clone()), span),
        ErrorKind::InvalidToken(found, expected) => {
            let semicolon = expected
                .iter()
                .any(|e| matches!(e, ExpectedToken::Token(TokenValue::Semicolon)));
            if semicolon && !matches!(found, TokenValue::Semicolon) {
                let at = before(source, span.start);
                return (Complaint::MissingSemicolon, at..at);
            }
            // What was found, as written (a long run of garbage cut short).
            let written = source.get(span.clone()).unwrap_or_default();
            let found = match written.char_indices().nth(24) {
                Some((cut, _)) => format!("{}…", &written[..cut]),
                None => written.to_owned(),
            };
            let expected = expected.iter().map(expected_text).collect();
            (Complaint::Unexpected { found, expected }, span)
        }
        ErrorKind::SemanticError(text) => (of_text(text), span),
        ErrorKind::PreprocessorError(e) if format!("{e:?}") == "UnexpectedCharacter" => {
            let found = source
                .get(span.start..)
                .and_then(|s| s.chars().next())
                .map(String::from)
                .unwrap_or_default();
            (
                Complaint::Unexpected {
                    found,
                    expected: Vec::new(),
                },
                span,
            )
        }
        _ => (of_text(&kind.to_string()), span),
    }
}

/// A semantic or validation message's complaint, read from naga's wording.
#[must_use]
pub fn of_text(text: &str) -> Complaint {
    let quoted = |prefix: &str| {
        text.strip_prefix(prefix).map(|rest| {
            rest.trim_matches(|c| c == '\'' || c == '"' || c == ' ')
                .to_owned()
        })
    };
    if let Some(name) = quoted("Unknown function") {
        return Complaint::UnknownFunction(name);
    }
    if text.starts_with("Ambiguous best function") || text == "Bad call" {
        return Complaint::UnknownFunction(text.split('\'').nth(1).unwrap_or_default().to_owned());
    }
    let table: [(&str, Complaint); 16] = [
        (
            "Function already defined",
            Complaint::FunctionAlreadyDefined,
        ),
        (
            "Prototype already defined",
            Complaint::FunctionAlreadyDefined,
        ),
        ("Cannot apply operation", Complaint::CannotCombine),
        ("Cannot apply operator", Complaint::CannotCombine),
        (
            "Constructor: Too many arguments",
            Complaint::TooManyArguments,
        ),
        ("Bad type constructor", Complaint::BadConstructor),
        ("Expression is not const-expression", Complaint::NotConstant),
        (
            "const values must have an initializer",
            Complaint::NotConstant,
        ),
        ("cannot be in the left hand side", Complaint::NotAssignable),
        (
            "Variable cannot be used in LHS position",
            Complaint::NotAssignable,
        ),
        ("Expression returns void", Complaint::VoidValue),
        ("void type", Complaint::VoidValue),
        ("#version must occur first", Complaint::VersionNotFirst),
        ("swizzle", Complaint::BadSwizzle),
        ("Can't lookup field", Complaint::UnknownField(String::new())),
        ("int constant overflows", Complaint::IntegerOverflow),
    ];
    if let Some((_, c)) = table.into_iter().find(|(needle, _)| text.contains(needle)) {
        return c;
    }
    if text.contains("doesn't match the type stored in") {
        return Complaint::TypeMismatch;
    }
    if text.contains("InvalidReturnType") || text.contains("return type") {
        return Complaint::ReturnType;
    }
    Complaint::Other
}

/// How the source writes an expected token.
fn expected_text(e: &ExpectedToken) -> String {
    match e {
        ExpectedToken::Token(t) => match t {
            TokenValue::Semicolon => ";",
            TokenValue::Comma => ",",
            TokenValue::Colon => ":",
            TokenValue::Dot => ".",
            TokenValue::LeftParen => "(",
            TokenValue::RightParen => ")",
            TokenValue::LeftBrace => "{",
            TokenValue::RightBrace => "}",
            TokenValue::LeftBracket => "[",
            TokenValue::RightBracket => "]",
            TokenValue::Assign => "=",
            TokenValue::Identifier(_) => "a name",
            _ => return format!("{t:?}").to_lowercase(),
        }
        .to_owned(),
        ExpectedToken::TypeName => "a type".to_owned(),
        ExpectedToken::Identifier => "a name".to_owned(),
        ExpectedToken::IntLiteral => "a whole number".to_owned(),
        ExpectedToken::FloatLiteral => "a number".to_owned(),
        ExpectedToken::BoolLiteral => "true or false".to_owned(),
        ExpectedToken::Eof => "the end of the file".to_owned(),
    }
}

/// The byte just after the last character of code before `at` (comments and white space
/// skipped): where a missing `;` goes.
fn before(source: &str, at: usize) -> usize {
    let head = source.get(..at.min(source.len())).unwrap_or(source);
    // Each line without its `//` comment, from the last one back.
    let mut end = head.len();
    for line in head.split('\n').rev() {
        let start = end.saturating_sub(line.len());
        let code = line.split("//").next().unwrap_or("").trim_end();
        if !code.is_empty() {
            return start + code.len();
        }
        // The line and its line break.
        end = start.saturating_sub(1);
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The end of the code before a token, by hand: the `)` of line 1 at byte 13, past a blank
    /// line and a comment.
    #[test]
    fn a_missing_semicolon_goes_after_the_code_before_the_token() {
        let src = "float x = f()\n\n// a comment\n  vec3 y;";
        let at = src.find("vec3").expect("vec3");
        assert_eq!(before(src, at), 13);
        assert_eq!(&src[..before(src, at)], "float x = f()");
        let src = "a = 1 // no ;\nb";
        assert_eq!(before(src, src.len() - 1), 5);
    }

    #[test]
    fn naga_s_wording_is_read_as_a_complaint() {
        assert_eq!(
            of_text("Unknown function 'depth'"),
            Complaint::UnknownFunction("depth".into())
        );
        assert_eq!(
            of_text("Cannot apply operation to Vector { size: Tri } and Vector { size: Quad }"),
            Complaint::CannotCombine
        );
        assert_eq!(of_text("something new"), Complaint::Other);
    }
}
