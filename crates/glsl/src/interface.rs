//! What pipelens hands a shader and takes back: the vertex attributes, the uniforms it sets by
//! name, the textures (their values for one object are the pipeline's `shader::Uniforms`).
//!
//! The names are those of the OpenGL course (`model`, `view`, `projection`, `normal_matrix`),
//! GAMES101's letters (`M`, `V`, `P`) and the llvmpipe peer's (`mvp`, `in_pos`, `light_pos`),
//! so that one source runs unchanged in pipelens and in a real OpenGL.

/// A vertex attribute pipelens feeds the vertex shader: its names and its fixed location.
#[derive(Clone, Copy, Debug)]
pub struct Attribute {
    /// The name pipelens documents, and the other names it answers to.
    pub names: &'static [&'static str],
    /// Its type.
    pub glsl: &'static str,
    /// Its location (the order of [`ATTRIBUTES`]).
    pub location: u32,
    /// What it holds.
    pub meaning: &'static str,
}

/// The vertex attributes, at locations 0 to 3.
pub const ATTRIBUTES: [Attribute; 4] = [
    Attribute {
        names: &["position", "in_pos", "aPos"],
        glsl: "vec3",
        location: 0,
        meaning: "the vertex position in object coordinates",
    },
    Attribute {
        names: &["normal", "in_nrm", "aNormal"],
        glsl: "vec3",
        location: 1,
        meaning: "the vertex normal in object coordinates",
    },
    Attribute {
        names: &["uv", "in_uv", "aTexCoord"],
        glsl: "vec2",
        location: 2,
        meaning: "the texture coordinates (0, 0 where the mesh has none)",
    },
    Attribute {
        names: &["color", "in_color", "aColor"],
        glsl: "vec3",
        location: 3,
        meaning: "the vertex colour (the normal as a colour where the mesh has none)",
    },
];

/// The location of the attribute called `name`, if it is one.
#[must_use]
pub fn attribute_location(name: &str) -> Option<u32> {
    ATTRIBUTES
        .iter()
        .find(|a| a.names.contains(&name))
        .map(|a| a.location)
}

/// A uniform pipelens sets.
#[derive(Clone, Copy, Debug)]
pub struct UniformSpec {
    /// The name pipelens documents, and the other names it answers to.
    pub names: &'static [&'static str],
    /// Its GLSL type (`Light[MAX_LIGHTS]` for the lights).
    pub glsl: &'static str,
    /// What it holds, with its formula.
    pub meaning: &'static str,
}

impl UniformSpec {
    /// Its type as a declaration must write it, `MAX_LIGHTS` counted out (`Light[8]`): what
    /// naga reports for the global.
    #[must_use]
    pub fn declared_type(&self) -> String {
        self.glsl.replace("MAX_LIGHTS", &MAX_LIGHTS.to_string())
    }
}

/// Every uniform pipelens sets. A shader declares those it uses (`uniform mat4 model;`).
pub const UNIFORMS: [UniformSpec; 33] = [
    UniformSpec {
        names: &["model", "M"],
        glsl: "mat4",
        meaning: "the model matrix M (object → world)",
    },
    UniformSpec {
        names: &["view", "V"],
        glsl: "mat4",
        meaning: "the view matrix V (world → eye), LookAt",
    },
    UniformSpec {
        names: &["projection", "P"],
        glsl: "mat4",
        meaning: "the projection matrix P (eye → clip)",
    },
    UniformSpec {
        names: &["mvp", "MVP"],
        glsl: "mat4",
        meaning: "P·V·M (object → clip)",
    },
    UniformSpec {
        names: &["model_view", "MV", "ModelView"],
        glsl: "mat4",
        meaning: "V·M (object → eye)",
    },
    UniformSpec {
        names: &["normal_matrix"],
        glsl: "mat3",
        meaning: "transpose(inverse(mat3(model))): object normals → world normals",
    },
    UniformSpec {
        names: &["eye", "eye_pos"],
        glsl: "vec3",
        meaning: "the eye position in world coordinates",
    },
    UniformSpec {
        names: &["light_pos"],
        glsl: "vec3",
        meaning: "the position of the scene's first point or spot light (world)",
    },
    UniformSpec {
        names: &["light_color"],
        glsl: "vec3",
        meaning: "that light's intensity I",
    },
    UniformSpec {
        names: &["ambient_light"],
        glsl: "vec3",
        meaning: "the ambient light's intensity I_a: the sum of the scene's ambient lights",
    },
    UniformSpec {
        names: &["lights"],
        glsl: "Light[MAX_LIGHTS]",
        meaning: "every light: kind, position, direction, intensity, attenuation (a, b, c), cutoff_cos, exponent",
    },
    UniformSpec {
        names: &["light_count"],
        glsl: "int",
        meaning: "how many of `lights` are set",
    },
    UniformSpec {
        names: &["ka"],
        glsl: "vec3",
        meaning: "the material's ambient coefficient k_a",
    },
    UniformSpec {
        names: &["kd"],
        glsl: "vec3",
        meaning: "the material's diffuse coefficient k_d",
    },
    UniformSpec {
        names: &["ks"],
        glsl: "vec3",
        meaning: "the material's specular coefficient k_s",
    },
    UniformSpec {
        names: &["shininess"],
        glsl: "float",
        meaning: "the material's shininess (Phong's α, Blinn-Phong's β)",
    },
    UniformSpec {
        names: &["use_tex"],
        glsl: "bool",
        meaning: "whether the object has a texture",
    },
    UniformSpec {
        names: &["detail_kind"],
        glsl: "int",
        meaning: "the object's surface detail: 0 none, 1 a bump (height) map, 2 a normal map, in `detail`",
    },
    UniformSpec {
        names: &["bump_strength"],
        glsl: "float",
        meaning: "k_h·k_n of bump mapping: dU = k_h·k_n·(h(u + 1/w, v) − h(u, v))",
    },
    UniformSpec {
        names: &["displacement_scale"],
        glsl: "float",
        meaning: "k of displacement mapping p' = p + k·h(u, v)·n (0 without a displacement map)",
    },
    UniformSpec {
        names: &["reflectivity"],
        glsl: "float",
        meaning: "k of environment mapping: (1 − k)·(ambient + diffuse) + specular + k·env(r), r = reflect(−v, n) (0 without an environment)",
    },
    UniformSpec {
        names: &["time"],
        glsl: "float",
        meaning: "seconds into the step's animation",
    },
    UniformSpec {
        names: &["fovy", "eye_fov"],
        glsl: "float",
        meaning: "the view volume's vertical angle in degrees, 2·atan((t − b)/(2·near)) (Perspective's fovy)",
    },
    UniformSpec {
        names: &["aspect", "aspect_ratio"],
        glsl: "float",
        meaning: "the view volume's width over height, (r − l)/(t − b)",
    },
    UniformSpec {
        names: &["near", "zNear"],
        glsl: "float",
        meaning: "the distance to the near plane (positive, as OpenGL writes it)",
    },
    UniformSpec {
        names: &["far", "zFar"],
        glsl: "float",
        meaning: "the distance to the far plane (positive)",
    },
    UniformSpec {
        names: &["at", "center"],
        glsl: "vec3",
        meaning: "the point the camera looks at (LookAt's at, world coordinates)",
    },
    UniformSpec {
        names: &["up"],
        glsl: "vec3",
        meaning: "the camera's up vector (LookAt's up, world coordinates)",
    },
    UniformSpec {
        names: &["rotation", "rotation_angles"],
        glsl: "vec3",
        meaning: "the object's rotation angles in degrees about x, y, z: M = T·Rz·Ry·Rx·S",
    },
    UniformSpec {
        names: &["axis"],
        glsl: "vec3",
        meaning: "the axis of the object's rotation R(n, θ), as the lesson gives it (not normalized; zero without one)",
    },
    UniformSpec {
        names: &["angle"],
        glsl: "float",
        meaning: "the angle θ of the object's rotation about its axis, in degrees",
    },
    UniformSpec {
        names: &["resolution", "viewport_size"],
        glsl: "vec2",
        meaning: "the viewport's width and height in pixels (W, H of the viewport transform)",
    },
    UniformSpec {
        names: &["scale"],
        glsl: "vec3",
        meaning: "the object's scale factors: S = diag(sx, sy, sz)",
    },
];

/// The uniform called `name`, if pipelens sets one.
#[must_use]
pub fn uniform(name: &str) -> Option<&'static UniformSpec> {
    UNIFORMS.iter().find(|u| u.names.contains(&name))
}

/// A texture pipelens binds to a `uniform sampler2D`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureSlot {
    /// The object's texture, sampled as the settings say (filter, mipmaps, anisotropy, bias).
    Surface,
    /// The object's bump (height) or normal map, sampled as the built-in bump mapping reads it:
    /// bilinear, repeating, level 0 (`detail_kind` says which map it is).
    Detail,
    /// The object's displacement (height) map, sampled as the built-in displacement reads it:
    /// bilinear, repeating, level 0.
    Displacement,
    /// The cube map the object mirrors (`uniform samplerCube environment;`), looked up by
    /// direction as the built-in environment mapping reads it.
    Environment,
}

impl TextureSlot {
    /// The sampler type a shader declares it with: `sampler2D`, or `samplerCube` for the
    /// environment.
    #[must_use]
    pub fn sampler(self) -> &'static str {
        match self {
            Self::Environment => "samplerCube",
            _ => "sampler2D",
        }
    }
}

/// The texture names pipelens binds (`uniform sampler2D tex;`, `uniform samplerCube
/// environment;`), and what each holds.
pub const TEXTURES: [(&str, TextureSlot); 8] = [
    ("tex", TextureSlot::Surface),
    ("texture0", TextureSlot::Surface),
    ("detail", TextureSlot::Detail),
    ("normal_map", TextureSlot::Detail),
    ("height_map", TextureSlot::Detail),
    ("displacement", TextureSlot::Displacement),
    ("environment", TextureSlot::Environment),
    ("skybox", TextureSlot::Environment),
];

/// The texture called `name`, if pipelens binds one.
#[must_use]
pub fn texture_slot(name: &str) -> Option<TextureSlot> {
    TEXTURES.iter().find(|(n, _)| *n == name).map(|&(_, s)| s)
}

/// The most lights a shader sees (`MAX_LIGHTS`).
pub const MAX_LIGHTS: usize = 8;

/// pipelens' `Light` record, field by field in the order its uniform stores them: the GLSL
/// type, the name, and the components it takes (`kind`: 0 ambient, 1 point, 2 directional, 3
/// spot; `attenuation`: a, b, c of `1/(a + b·d + c·d²)`; `cutoff_cos`: the spot's cos of its
/// cutoff angle; `exponent`: its falloff `cos^e`).
pub const LIGHT_FIELDS: [(&str, &str, usize); 7] = [
    ("int", "kind", 1),
    ("vec3", "position", 3),
    ("vec3", "direction", 3),
    ("vec3", "intensity", 3),
    ("vec3", "attenuation", 3),
    ("float", "cutoff_cos", 1),
    ("float", "exponent", 1),
];

/// The light kinds as a shader names them, each the value of its place.
pub const LIGHT_KINDS: [&str; 4] = [
    "LIGHT_AMBIENT",
    "LIGHT_POINT",
    "LIGHT_DIRECTIONAL",
    "LIGHT_SPOT",
];

/// The components of one `Light` record: the sum of [`LIGHT_FIELDS`]' components.
pub const LIGHT_COMPONENTS: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < LIGHT_FIELDS.len() {
        n += LIGHT_FIELDS[i].2;
        i += 1;
    }
    n
};

/// The GLSL every shader starts with: the `Light` struct of [`LIGHT_FIELDS`], a constant for
/// each of [`LIGHT_KINDS`], and `MAX_LIGHTS`; written once.
#[must_use]
pub fn light_declarations() -> &'static str {
    static TEXT: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    TEXT.get_or_init(|| {
        let fields: String = LIGHT_FIELDS
            .iter()
            .map(|(ty, name, _)| format!(" {ty} {name};"))
            .collect();
        let kinds: String = LIGHT_KINDS
            .iter()
            .enumerate()
            .map(|(value, name)| format!("const int {name} = {value}; "))
            .collect();
        format!("struct Light {{{fields} }};\n{kinds}const int MAX_LIGHTS = {MAX_LIGHTS};\n")
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The declarations a shader sees are the course's `Light` record as written by hand.
    #[test]
    fn the_light_declarations_are_the_record_as_written() {
        assert_eq!(
            light_declarations(),
            "struct Light { int kind; vec3 position; vec3 direction; vec3 intensity; \
             vec3 attenuation; float cutoff_cos; float exponent; };\n\
             const int LIGHT_AMBIENT = 0; const int LIGHT_POINT = 1; \
             const int LIGHT_DIRECTIONAL = 2; const int LIGHT_SPOT = 3; const int MAX_LIGHTS = 8;\n"
        );
    }

    /// The light layout is said three times — the `Light` struct and `MAX_LIGHTS` in the text
    /// put before every shader, and these two constants — and must agree: the `lights` array
    /// a shader declares takes `MAX_LIGHTS · LIGHT_COMPONENTS` components in the machine.
    #[test]
    fn the_light_layout_of_the_preamble_agrees_with_the_constants() {
        let src = "#version 330 core\nuniform Light lights[MAX_LIGHTS];\nout vec4 color;\nvoid main() {\n    color = vec4(lights[0].position, lights[MAX_LIGHTS - 1].exponent);\n}\n";
        let p = crate::compile(crate::Stage::Fragment, src).expect("compiles");
        let (_, reg) = p
            .uniforms
            .iter()
            .find(|(n, _)| n == "lights")
            .expect("declared");
        assert_eq!(reg.len as usize, MAX_LIGHTS * LIGHT_COMPONENTS);
        // kind (1) + position, direction, intensity, attenuation (4 × 3) + cutoff_cos,
        // exponent (2).
        assert_eq!(LIGHT_COMPONENTS, 1 + 4 * 3 + 2);
    }
}
