//! The functions of the pipeline a student may write, as one table ([`HOOKS`]): for each kind
//! its lesson key, its signature, who calls it and when, the inputs pipelens passes and the
//! `main` it appends to call it. Everything that differs between the kinds is a row here.

/// The signature the rasterizer calls for the inside test, as the student writes it.
pub const INSIDE_SIGNATURE: &str = "bool inside(vec2 p, vec2 a, vec2 b, vec2 c)";

/// The signature the rasterizer calls for the depth test, as the student writes it.
pub const DEPTH_SIGNATURE: &str = "bool depth_test(float z, float stored)";

/// The signature a Bézier curve's drawing calls for each curve point, as the student writes it.
pub const CURVE_SIGNATURE: &str = "vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t)";

/// The signature a Bézier patch's drawing calls for each surface point, as the student writes it.
pub const PATCH_SIGNATURE: &str = "vec3 bezier_patch(vec3 p[16], float u, float v)";

/// The signature the shadow pass calls for its projection, as the student writes it.
pub const SHADOW_SIGNATURE: &str = "mat4 shadow_matrix(vec3 light)";

/// Which function of the pipeline the student writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum HookKind {
    /// `bool inside(vec2 p, vec2 a, vec2 b, vec2 c)`: which samples a triangle covers.
    Inside,
    /// `bool depth_test(float z, float stored)`: which covered samples it writes.
    DepthTest,
    /// `vec2 de_casteljau(vec2 p0, vec2 p1, vec2 p2, vec2 p3, float t)`: a Bézier curve's point.
    Curve,
    /// `mat4 shadow_matrix(vec3 light)`: the planar shadow's projection onto `y = 0`.
    ShadowMatrix,
    /// `vec3 bezier_patch(vec3 p[16], float u, float v)`: a Bézier patch's point.
    Patch,
}

/// What pipelens knows of one kind of function.
#[derive(Debug)]
pub struct HookSpec {
    /// The kind this row describes (the row's place is the kind's, a test checks it).
    pub kind: HookKind,
    /// Its name as the lesson's key and the messages say it: `inside`, `depth_test`.
    pub key: &'static str,
    /// The signature the pipeline calls, as the student writes it.
    pub signature: &'static str,
    /// Who calls it, and when, for the messages.
    pub when: (&'static str, &'static str),
    /// The inputs pipelens passes, in the signature's order.
    pub inputs: &'static [&'static str],
    /// What pipelens appends to the student's function: its arguments as inputs, the answer
    /// (1 true, 0 false) as the output.
    pub caller: &'static str,
}

/// Every kind of function, in [`HookKind::ALL`]'s order.
pub const HOOKS: [HookSpec; 5] = [
    HookSpec {
        kind: HookKind::Inside,
        key: "inside",
        signature: INSIDE_SIGNATURE,
        when: ("the rasterizer", "for every sample"),
        inputs: &["pipelens_p", "pipelens_a", "pipelens_b", "pipelens_c"],
        caller: "
in vec2 pipelens_p;
in vec2 pipelens_a;
in vec2 pipelens_b;
in vec2 pipelens_c;
out vec4 pipelens_answer;
void main() {
    pipelens_answer = inside(pipelens_p, pipelens_a, pipelens_b, pipelens_c) ? vec4(1.0) : vec4(0.0);
}
",
    },
    HookSpec {
        kind: HookKind::DepthTest,
        key: "depth_test",
        signature: DEPTH_SIGNATURE,
        when: ("the rasterizer", "for every sample a triangle covers"),
        inputs: &["pipelens_z", "pipelens_stored"],
        caller: "
in float pipelens_z;
in float pipelens_stored;
out vec4 pipelens_answer;
void main() {
    pipelens_answer = depth_test(pipelens_z, pipelens_stored) ? vec4(1.0) : vec4(0.0);
}
",
    },
    HookSpec {
        kind: HookKind::Curve,
        key: "de_casteljau",
        signature: CURVE_SIGNATURE,
        when: ("a Bézier curve's drawing", "for every point of the curve"),
        inputs: &[
                "pipelens_p0",
                "pipelens_p1",
                "pipelens_p2",
                "pipelens_p3",
                "pipelens_t",
            ],
        caller: "
in vec2 pipelens_p0;
in vec2 pipelens_p1;
in vec2 pipelens_p2;
in vec2 pipelens_p3;
in float pipelens_t;
out vec4 pipelens_answer;
void main() {
    pipelens_answer = vec4(de_casteljau(pipelens_p0, pipelens_p1, pipelens_p2, pipelens_p3, pipelens_t), 0.0, 1.0);
}
",
    },
    HookSpec {
        kind: HookKind::ShadowMatrix,
        key: "shadow_matrix",
        signature: SHADOW_SIGNATURE,
        when: ("the shadow pass", "once a frame, for the plane y = 0"),
        inputs: &["pipelens_light", "pipelens_column"],
        caller: "
in vec3 pipelens_light;
in float pipelens_column;
out vec4 pipelens_answer;
void main() {
    mat4 m = shadow_matrix(pipelens_light);
    int c = int(pipelens_column);
    pipelens_answer = c == 0 ? m[0] : c == 1 ? m[1] : c == 2 ? m[2] : m[3];
}
",
    },
    HookSpec {
        kind: HookKind::Patch,
        key: "bezier_patch",
        signature: PATCH_SIGNATURE,
        when: (
                "a Bézier patch's drawing",
                "for every vertex of the surface grid",
            ),
        inputs: &[
                "pipelens_p0",
                "pipelens_p1",
                "pipelens_p2",
                "pipelens_p3",
                "pipelens_p4",
                "pipelens_p5",
                "pipelens_p6",
                "pipelens_p7",
                "pipelens_p8",
                "pipelens_p9",
                "pipelens_p10",
                "pipelens_p11",
                "pipelens_p12",
                "pipelens_p13",
                "pipelens_p14",
                "pipelens_p15",
                "pipelens_uv",
            ],
        caller: "
in vec3 pipelens_p0;
in vec3 pipelens_p1;
in vec3 pipelens_p2;
in vec3 pipelens_p3;
in vec3 pipelens_p4;
in vec3 pipelens_p5;
in vec3 pipelens_p6;
in vec3 pipelens_p7;
in vec3 pipelens_p8;
in vec3 pipelens_p9;
in vec3 pipelens_p10;
in vec3 pipelens_p11;
in vec3 pipelens_p12;
in vec3 pipelens_p13;
in vec3 pipelens_p14;
in vec3 pipelens_p15;
in vec2 pipelens_uv;
out vec4 pipelens_answer;
void main() {
    vec3 p[16] = vec3[16](pipelens_p0, pipelens_p1, pipelens_p2, pipelens_p3,
                          pipelens_p4, pipelens_p5, pipelens_p6, pipelens_p7,
                          pipelens_p8, pipelens_p9, pipelens_p10, pipelens_p11,
                          pipelens_p12, pipelens_p13, pipelens_p14, pipelens_p15);
    pipelens_answer = vec4(bezier_patch(p, pipelens_uv.x, pipelens_uv.y), 1.0);
}
",
    },
];

impl HookKind {
    /// Every kind, in the order the shader panel shows their tabs.
    pub const ALL: [Self; 5] = [
        Self::Inside,
        Self::DepthTest,
        Self::Curve,
        Self::ShadowMatrix,
        Self::Patch,
    ];

    /// This kind's row of [`HOOKS`].
    #[must_use]
    pub fn spec(self) -> &'static HookSpec {
        &HOOKS[self as usize]
    }

    /// The signature the pipeline calls.
    #[must_use]
    pub fn signature(self) -> &'static str {
        self.spec().signature
    }

    /// Its name as the lesson's key and the messages say it: `inside`, `depth_test`.
    #[must_use]
    pub fn key(self) -> &'static str {
        self.spec().key
    }

    /// The kind whose lesson key is `key`.
    #[must_use]
    pub fn from_key(key: &str) -> Option<Self> {
        HOOKS.iter().find(|h| h.key == key).map(|h| h.kind)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each row stands at its kind's place, its signature and caller name its function, and the
    /// caller declares every input and passes it on.
    #[test]
    fn each_row_is_its_kinds() {
        for (i, kind) in HookKind::ALL.into_iter().enumerate() {
            let spec = &HOOKS[i];
            assert_eq!(spec.kind, kind);
            assert_eq!(kind as usize, i);
            assert_eq!(HookKind::from_key(spec.key), Some(kind));
            assert!(
                spec.signature.contains(&format!(" {}(", spec.key)),
                "{}",
                spec.key
            );
            assert!(
                spec.caller.contains(&format!("{}(", spec.key)),
                "{}",
                spec.key
            );
            for input in spec.inputs {
                // Declared as an input of the caller, and passed on in its `main`.
                let declared = spec.caller.contains(&format!(" {input};"));
                let passed = spec.caller.matches(input).count() >= 2;
                assert!(declared && passed, "{}: {input}", spec.key);
            }
        }
    }
}
