//! The mistakes a lesson's step can hold, one a line, each with the place its error must point
//! at and the words of the message (`lessons::broken_lessons_are_reported_where_the_mistake_is`).

/// One mistake a line: the line, the text the error must point at, words of the message.
pub(crate) const MISTAKES: &[(&str, &str, &str)] = &[
    // A lab's `compare` names a value its starter's fragment shader has, and one of pipelens'
    // quantities.
    (
        r##"exercise = { task = { en = "x", zh = "x" }, starter = { fragment = "#version 330 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n" }, compare = { yours = "nope()", pipelens = "lod" } }"##,
        "{ yours = \"nope()\"",
        "`compare.yours` names `nope()`, which the starter's fragment shader does not have",
    ),
    (
        r##"exercise = { task = { en = "x", zh = "x" }, starter = { fragment = "#version 330 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n" }, compare = { yours = "color", pipelens = "lambda" } }"##,
        "{ yours = \"color\"",
        "`compare.pipelens` is one of `uv`, `lod`, `texel`; got `lambda`",
    ),
    (
        "stage = \"rasterisation\"",
        "\"rasterisation\"",
        "`stage` must be one of",
    ),
    ("layout = \"compare\"", "\"compare\"", "needs `compare"),
    // `expect_names` names each entry of a vector's value once, beside its `expect`; the
    // names follow on the next lines.
    (
        "expect_names = [\"top\"]\nquestion = { en = \"q\", zh = \"问\" }\nexpect = [1, 1]",
        "[\"top\"]",
        "one name per entry of `expect`: 2, got 1",
    ),
    (
        "expect_names = [\"a\"]\nquestion = { en = \"q\", zh = \"问\" }\nexpect = 0.5",
        "[\"a\"]",
        "a single value needs none",
    ),
    (
        "expect_names = [\"top\", \"\"]",
        "[\"top\"",
        "belongs beside an `expect` value",
    ),
    (
        "expect_names = [\"the top of the near plane\", \"right\"]\nquestion = { en = \"q\", zh = \"问\" }\nexpect = [1, 1]",
        "[\"the top",
        "1 to 12 characters",
    ),
    // The observer cannot look straight down: its camera's up is the vertical axis.
    (
        "orbit = [30, 90]",
        "[30, 90]",
        "−90 < pitch < 90, got [30, 90]",
    ),
    (
        "buffer = \"colour\"",
        "\"colour\"",
        "`buffer` must be one of",
    ),
    (
        "overlays = [\"edges\", \"grid\"]",
        "\"grid\"",
        "`overlays` must be one of",
    ),
    (
        "set = { \"projection.fov\" = 60 }",
        "\"projection.fov\"",
        "did you mean \"projection.fovy\"",
    ),
    (
        "set = { \"objects.sphere.rotate\" = [0, 1, 0] }",
        "\"objects",
        "unknown parameter",
    ),
    (
        "set = { \"projection.fovy\" = 180 }",
        "\"projection",
        "fovy must be between",
    ),
    ("set = { \"projection.near\" = -1 }", "\"projection", "near"),
    (
        "set = { \"camera.eye\" = [0, 0, 0] }",
        "\"camera",
        "degenerate",
    ),
    (
        "set = { \"render.samples\" = 3 }",
        "\"render",
        "1, 4, 8 or 16",
    ),
    (
        "set = { \"render.max_steps\" = 1.5 }",
        "\"render",
        "whole number of loop iterations",
    ),
    (
        "set = { \"render.shading\" = \"phog\" }",
        "\"render",
        "\"phong\"",
    ),
    (
        "set = { projection = { fovy = 60 } }",
        "{ fovy",
        "write the parameter's name in quotes",
    ),
    ("pixel = [800, 10]", "[800", "inside the 640×480 viewport"),
    ("vertex = 24", "24", "0 to 23"),
    (
        "animate = [{ param = \"projection.fovy\", from = 30, to = [1, 2, 3], seconds = 2 }]",
        "[1, 2, 3]",
        "must both be numbers",
    ),
    (
        "animate = [{ param = \"projection.fovy\", from = 30, to = 90, seconds = 0 }]",
        "0 }",
        "`seconds` must be",
    ),
    (
        "animate = [{ param = \"projection.fovy\", from = 30, to = 190, seconds = 2 }]",
        "190",
        "fovy must be between",
    ),
    (
        "animate = [{ param = \"camera.eyes\", from = [1, 1, 1], to = [2, 2, 2], seconds = 2 }]",
        "\"camera.eyes\"",
        "did you mean \"camera.eye\"",
    ),
    (
        "animate = [{ param = \"projection.fovy\", from = 30, to = 90, seconds = 2, easing = \"smooth\" }]",
        "\"smooth\"",
        "`easing` must be one of",
    ),
    (
        "watch = \"n.y > 0.0\"",
        "\"n.y > 0.0\"",
        "`watch`: expected EXPR@LINE",
    ),
    (
        "watch = \"n.y > 0.0@5\"",
        "\"n.y > 0.0@5\"",
        "no object is drawn with shaders of your own",
    ),
    (
        "answr = { en = \"x\", zh = \"y\" }",
        "answr",
        "did you mean `answer`",
    ),
    (
        "question = { en = \"x\" }",
        "{ en",
        "`question` needs both languages",
    ),
    (
        "question = { en = \"x\", zh = \" \" }",
        "{ en",
        "both `en` and `zh`",
    ),
];
