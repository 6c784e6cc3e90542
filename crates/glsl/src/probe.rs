//! A watch: the value of an expression just after a line of the student's shader runs, in
//! every invocation of a batch — what the debugger draws over the whole frame, and what finds
//! the first fragment where a condition holds.
//!
//! The shader is compiled again with two additions that move none of the student's lines.
//! Before their code, with the other declarations pipelens puts there: globals that keep what
//! the watch saw (its value as a `vec4`, its type, whether the line ran) and one function per
//! type the expression may have, which GLSL's overloading picks. At the end of the watched
//! line, after its last statement and before any comment: the expression stored through that
//! function. The program computes what the student's does and, in each invocation, leaves the
//! value of the expression the last time the line ran.

use std::ops::Range;

use crate::error::ShaderError;
use crate::lexeme::{self, Kind};
use crate::program::Program;
use crate::register_form::Root;
use crate::stage::Stage;
use crate::watched::WATCH;
pub use crate::watched::{WatchKind, WatchPlaces, Watched};

/// What pipelens puts before the student's code for a watch (one line each, for reading; the
/// preamble is not the student's text, so its lines count for nothing).
const DECLARATIONS: &str = "
vec4 pipelens_watch = vec4(0.0);
float pipelens_watch_kind = 0.0;
vec4 pipelens_as_watch(float x) { pipelens_watch_kind = 1.0; return vec4(x, 0.0, 0.0, 0.0); }
vec4 pipelens_as_watch(vec2 x) { pipelens_watch_kind = 2.0; return vec4(x, 0.0, 0.0); }
vec4 pipelens_as_watch(vec3 x) { pipelens_watch_kind = 3.0; return vec4(x, 0.0); }
vec4 pipelens_as_watch(vec4 x) { pipelens_watch_kind = 4.0; return x; }
vec4 pipelens_as_watch(int x) { pipelens_watch_kind = 5.0; return vec4(float(x), 0.0, 0.0, 0.0); }
vec4 pipelens_as_watch(uint x) { pipelens_watch_kind = 5.0; return vec4(float(x), 0.0, 0.0, 0.0); }
vec4 pipelens_as_watch(bool x) { pipelens_watch_kind = 6.0; return vec4(x ? 1.0 : 0.0, 0.0, 0.0, 0.0); }
";

/// A watch as a lesson, the command line and the debugger name it: whose shader, the line
/// after which the expression is read, and the expression.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct WatchSpec {
    /// The shader watched: the fragment shader's value is each pixel's own; the vertex
    /// shader's is each vertex's, interpolated over the triangle as a varying is.
    pub stage: Stage,
    /// The line after which the expression is read, from 1.
    pub line: usize,
    /// The expression, as typed.
    pub expression: String,
}

impl WatchSpec {
    /// A watch of the fragment shader.
    #[must_use]
    pub fn fragment(line: usize, expression: &str) -> Self {
        Self {
            stage: Stage::Fragment,
            line,
            expression: expression.to_owned(),
        }
    }

    /// A watch of the vertex shader.
    #[must_use]
    pub fn vertex(line: usize, expression: &str) -> Self {
        Self {
            stage: Stage::Vertex,
            ..Self::fragment(line, expression)
        }
    }
}

impl std::fmt::Display for WatchSpec {
    /// As [`parse`] reads it: `EXPR@LINE`, `EXPR@vertex:LINE` for the vertex shader.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.stage {
            Stage::Fragment => write!(f, "{}@{}", self.expression, self.line),
            Stage::Vertex => write!(f, "{}@vertex:{}", self.expression, self.line),
        }
    }
}

/// A watch as a lesson and the command line write it, `EXPR@LINE` for a line of the fragment
/// shader or `EXPR@vertex:LINE` for one of the vertex shader (`fragment:LINE` is also read):
/// the expression and the line after which it is read (the last `@` separates them, so the
/// expression may hold none).
///
/// # Errors
/// No `@`, a line that is not a whole number from 1, an unknown stage, or no expression before
/// it.
pub fn parse(s: &str) -> Result<WatchSpec, String> {
    let (expression, at) = s.rsplit_once('@').ok_or_else(|| {
        format!(
            "expected EXPR@LINE such as \"max(dot(n, l), 0.0)@22\" (or EXPR@vertex:LINE), got \"{s}\""
        )
    })?;
    let (stage, line) = match at.split_once(':') {
        None => (Stage::Fragment, at),
        Some((stage, line)) => match stage.trim() {
            "vertex" => (Stage::Vertex, line),
            "fragment" => (Stage::Fragment, line),
            other => {
                return Err(format!(
                    "\"{other}\" is not a shader: write EXPR@vertex:LINE or EXPR@fragment:LINE"
                ));
            }
        },
    };
    let line = line
        .trim()
        .parse::<usize>()
        .ok()
        .filter(|&l| l > 0)
        .ok_or_else(|| format!("\"{}\" is not a line number (from 1)", line.trim()))?;
    if expression.trim().is_empty() {
        return Err(format!("no expression before @{at}"));
    }
    Ok(WatchSpec {
        stage,
        line,
        expression: expression.trim().to_owned(),
    })
}

/// Why a watch cannot be made.
#[derive(Clone, Debug, PartialEq)]
pub enum WatchError {
    /// Nothing runs a shader of the student's: there is nothing to watch.
    NoShader,
    /// The source has no such line.
    NoSuchLine(usize),
    /// The line does not end a statement or open or close a block (its last code is not `;`,
    /// `{` or `}`), or closes a function: the watch cannot follow it.
    NotAfterStatement(usize),
    /// The expression is empty.
    Empty,
    /// The shader with the watch does not compile: the messages on the watched line are the
    /// expression's.
    Compile(Vec<ShaderError>),
}

impl std::fmt::Display for WatchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NoShader => write!(
                f,
                "no object is drawn with shaders of your own: there is nothing to watch"
            ),
            Self::NoSuchLine(l) => write!(f, "the shader has no line {l}"),
            Self::NotAfterStatement(l) => write!(
                f,
                "line {l} does not end a statement: watch a line that ends in `;`, `{{` or `}}` inside a function"
            ),
            Self::Empty => write!(f, "type an expression to watch"),
            Self::Compile(errors) => {
                let said: Vec<String> = errors.iter().map(|e| e.message.clone()).collect();
                write!(
                    f,
                    "the expression does not compile here: {}",
                    said.join("; ")
                )
            }
        }
    }
}

impl std::error::Error for WatchError {}

/// Where the watch's statement goes on `line`: after its last code lexeme, which must be `;`,
/// `{` or `}` inside a function.
fn insertion_point(source: &str, line: usize) -> Result<usize, WatchError> {
    let lexemes = lexeme::lex(source);
    if line == 0 || line > source.lines().count() {
        return Err(WatchError::NoSuchLine(line));
    }
    let mut depth = 0i32;
    let mut last: Option<(Range<usize>, i32)> = None;
    for l in &lexemes {
        if l.line > line {
            break;
        }
        if l.kind == Kind::Punctuation {
            match &source[l.span.clone()] {
                "{" => depth += 1,
                "}" => depth -= 1,
                _ => {}
            }
        }
        // A lexeme that starts on the line (a block comment from above is not the line's).
        let code = !matches!(l.kind, Kind::Comment | Kind::Space | Kind::Directive);
        if l.line == line && code {
            last = Some((l.span.clone(), depth));
        }
    }
    match last {
        Some((span, depth)) if depth > 0 && matches!(&source[span.clone()], ";" | "{" | "}") => {
            Ok(span.end)
        }
        _ => Err(WatchError::NotAfterStatement(line)),
    }
}

/// `program`'s source compiled again with a watch of `expression` just after `line`.
///
/// # Errors
/// A line that does not exist or ends no statement, an empty expression, or one that does not
/// compile there (a name not in scope at the line, a type with no watch: a matrix, an array).
pub fn watch(
    stage: Stage,
    source: &str,
    line: usize,
    expression: &str,
) -> Result<Program, WatchError> {
    let expression = expression.trim();
    if expression.is_empty() {
        return Err(WatchError::Empty);
    }
    let at = insertion_point(source, line)?;
    let statement = format!(" pipelens_watch = pipelens_as_watch({expression});");
    let watched = format!("{}{statement}{}", &source[..at], &source[at..]);
    let mut program =
        crate::compile::compile_with(stage, &watched, DECLARATIONS).map_err(WatchError::Compile)?;
    let place = |name: &str| {
        program
            .module
            .global_variables
            .iter()
            .find(|(_, g)| g.name.as_deref() == Some(name))
            .and_then(|(h, _)| match program.code.globals[h.index()] {
                Some((Root::Private, reg)) => Some(reg),
                _ => None,
            })
    };
    let (Some(value), Some(kind)) = (place(WATCH), place("pipelens_watch_kind")) else {
        return Err(WatchError::NotAfterStatement(line));
    };
    program.watch = Some(WatchPlaces::new(value, kind, line, expression));
    Ok(program)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::Batch;

    /// A fragment shader whose values are worked by hand for an input `x`: `a = 2x` (line 5),
    /// `b = a > 1` (line 6), then, where b holds, `a = a - 1` (line 8).
    const SOURCE: &str = "#version 330 core
in float x;
out vec4 color;
void main() {
    float a = 2.0 * x;   // twice x
    bool b = a > 1.0;
    if (b) {
        a = a - 1.0;
    }
    color = vec4(a, 0.0, 0.0, 1.0);
}
";

    /// Runs `program` over the inputs `xs`, one lane each; what each lane's watch saw.
    fn seen(program: &Program, xs: &[f32]) -> Vec<Option<Watched>> {
        let mut batch = Batch::new(program);
        batch.start(xs.len());
        for (l, x) in xs.iter().enumerate() {
            batch.set(0, l, &[*x]);
        }
        let mut m = program.machine();
        let ran = m.run_batch(&batch, &()).expect("runs");
        let places = program.watch.as_ref().expect("a watch");
        (0..xs.len()).map(|l| ran.watched(places, l)).collect()
    }

    #[test]
    fn a_watch_is_written_expr_at_line() {
        assert_eq!(parse("a@5"), Ok(WatchSpec::fragment(5, "a")));
        assert_eq!(
            parse(" x.y < 0.0 @ 12"),
            Ok(WatchSpec::fragment(12, "x.y < 0.0"))
        );
        let vertex = WatchSpec {
            stage: Stage::Vertex,
            line: 7,
            expression: "p.z".to_owned(),
        };
        assert_eq!(parse("p.z@vertex:7"), Ok(vertex.clone()));
        assert_eq!(parse("a@fragment:5"), Ok(WatchSpec::fragment(5, "a")));
        // Written back as read.
        assert_eq!(vertex.to_string(), "p.z@vertex:7");
        assert_eq!(WatchSpec::fragment(5, "a").to_string(), "a@5");
        assert!(parse("a").is_err() && parse("a@0").is_err() && parse("@3").is_err());
        assert!(parse("a@two").is_err() && parse("a@geometry:3").is_err());
        assert!(parse("a@vertex:").is_err());
    }

    #[test]
    fn a_float_is_watched_after_its_line_in_every_lane() {
        let p = watch(Stage::Fragment, SOURCE, 5, "a").expect("compiles");
        let v = seen(&p, &[0.25, 1.0]);
        assert_eq!(
            v[0].map(|w| (w.kind, w.value[0])),
            Some((WatchKind::Float, 0.5))
        );
        assert_eq!(v[1].map(|w| w.value[0]), Some(2.0));
    }

    #[test]
    fn a_condition_is_a_mask_and_a_line_not_run_is_none() {
        let p = watch(Stage::Fragment, SOURCE, 6, "b && a < 3.0").expect("compiles");
        let v = seen(&p, &[0.25, 1.0, 2.0]);
        let holds: Vec<Option<f32>> = v.iter().map(|w| w.map(|w| w.value[0])).collect();
        assert_eq!(holds, [Some(0.0), Some(1.0), Some(0.0)], "a = 0.5, 2, 4");
        assert!(
            v.iter()
                .all(|w| w.is_none_or(|w| w.kind == WatchKind::Bool))
        );
        // Line 8 runs only where b holds: x = 0.25 gives a = 0.5, b false.
        let inside = watch(Stage::Fragment, SOURCE, 8, "vec2(a, x)").expect("compiles");
        let v = seen(&inside, &[0.25, 1.0]);
        assert_eq!(v[0], None);
        assert_eq!(
            v[1].map(|w| (w.kind, [w.value[0], w.value[1]])),
            Some((WatchKind::Vec2, [1.0, 1.0])),
            "a = 2 − 1 after line 8"
        );
    }

    #[test]
    fn an_int_and_a_vector_keep_their_type() {
        let p = watch(Stage::Fragment, SOURCE, 5, "int(a) + 1").expect("compiles");
        assert_eq!(
            seen(&p, &[1.0])[0].map(|w| (w.kind, w.value[0])),
            Some((WatchKind::Int, 3.0))
        );
        let p = watch(Stage::Fragment, SOURCE, 10, "color").expect("compiles");
        assert_eq!(
            seen(&p, &[1.0])[0].map(|w| (w.kind, w.value)),
            Some((WatchKind::Vec4, [1.0, 0.0, 0.0, 1.0]))
        );
    }

    #[test]
    fn the_watch_goes_before_a_comment_and_only_after_a_statement() {
        assert_eq!(
            insertion_point(SOURCE, 5),
            Ok(SOURCE.find("x;   //").expect("line 5") + 2),
            "after the `;`, before the comment"
        );
        assert_eq!(
            insertion_point(SOURCE, 2),
            Err(WatchError::NotAfterStatement(2)),
            "a declaration outside any function"
        );
        assert_eq!(
            insertion_point(SOURCE, 11),
            Err(WatchError::NotAfterStatement(11)),
            "main's closing brace"
        );
        assert_eq!(insertion_point(SOURCE, 40), Err(WatchError::NoSuchLine(40)));
        assert!(matches!(
            watch(Stage::Fragment, SOURCE, 5, "nope"),
            Err(WatchError::Compile(_))
        ));
        assert_eq!(
            watch(Stage::Fragment, SOURCE, 5, "  ").err(),
            Some(WatchError::Empty)
        );
    }

    #[test]
    fn the_watched_program_draws_what_the_students_draws_and_traces_no_watch_call() {
        let plain = crate::compile(Stage::Fragment, SOURCE).expect("compiles");
        let watched = watch(Stage::Fragment, SOURCE, 6, "a").expect("compiles");
        for x in [0.25f32, 1.0] {
            let colour = |p: &Program, trace: bool| {
                let mut batch = Batch::new(p);
                batch.start(1);
                batch.set(0, 0, &[x]);
                let mut m = p.machine();
                if trace {
                    m.trace_lane(Some(0));
                }
                let c = m.run_batch(&batch, &()).expect("runs").outputs::<4>(0);
                (c, p.describe(&m.take_trace()))
            };
            let (a, _) = colour(&plain, false);
            let (b, trace) = colour(&watched, true);
            // The store after line 6 follows two steps (a on line 5, b on line 6) and holds
            // a = 2x.
            let mut batch = Batch::new(&watched);
            batch.start(1);
            batch.set(0, 0, &[x]);
            let mut m = watched.machine();
            m.trace_lane(Some(0));
            m.run_batch(&batch, &()).expect("runs");
            assert_eq!(
                watched.watched_values(&m.take_trace()),
                [(2, [2.0 * x, 0.0, 0.0, 0.0])]
            );
            assert_eq!(a, b);
            assert!(
                trace.iter().all(|t| !t.text.contains("pipelens_as_watch")),
                "{trace:#?}"
            );
            assert!(trace.iter().all(|t| t.line <= 11));
        }
    }
}
