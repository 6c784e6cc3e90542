//! A vertex shader and a fragment shader linked into one program, as `glLinkProgram` does: each
//! fragment input takes the vertex output of the same name. Either may be left out; pipelens
//! then uses its own ([`BUILTIN_VERTEX`], [`BUILTIN_FRAGMENT`]), shipped as GLSL a student can
//! start from.

use std::sync::Arc;

use super::{Program, ShaderError, Stage, compile};

/// pipelens' vertex stage as GLSL: `gl_Position = mvp·p`, and the world position and normal,
/// uv and colour for the fragment stage (`w_pos`, `w_nrm`, `v_uv`, `v_color`).
pub const BUILTIN_VERTEX: &str = include_str!("builtin/pipelens.vert");

/// pipelens' per-pixel Blinn-Phong lighting as GLSL.
pub const BUILTIN_FRAGMENT: &str = include_str!("builtin/blinn_phong.frag");

/// pipelens' per-pixel lighting with Phong's `r·v` as GLSL.
pub const BUILTIN_PHONG_FRAGMENT: &str = include_str!("builtin/phong.frag");

/// pipelens' unlit shading as GLSL: the texel or the vertex colour.
pub const BUILTIN_UNLIT_FRAGMENT: &str = include_str!("builtin/unlit.frag");

/// pipelens' Gouraud shading as GLSL, the vertex half: Blinn-Phong at each vertex.
pub const BUILTIN_GOURAUD_VERTEX: &str = include_str!("builtin/gouraud.vert");

/// pipelens' Gouraud shading as GLSL, the fragment half: the interpolated lighting, the texel.
pub const BUILTIN_GOURAUD_FRAGMENT: &str = include_str!("builtin/gouraud.frag");

/// pipelens' flat shading as GLSL, the vertex half: the provoking vertex's position and colour.
pub const BUILTIN_FLAT_VERTEX: &str = include_str!("builtin/flat.vert");

/// pipelens' flat shading as GLSL, the fragment half: the face normal from the derivatives of
/// the world position, lit at the provoking vertex.
pub const BUILTIN_FLAT_FRAGMENT: &str = include_str!("builtin/flat.frag");

/// pipelens' per-pixel Blinn-Phong lighting with a bump or normal map, as GLSL.
pub const BUILTIN_NORMAL_MAPPED_FRAGMENT: &str = include_str!("builtin/normal_mapped.frag");

/// pipelens' per-pixel Blinn-Phong lighting of a mirror (environment mapping), as GLSL.
pub const BUILTIN_MIRROR_FRAGMENT: &str = include_str!("builtin/mirror.frag");

/// pipelens' shipped vertex shaders.
pub const SHIPPED_VERTEX: [&str; 3] = [BUILTIN_VERTEX, BUILTIN_GOURAUD_VERTEX, BUILTIN_FLAT_VERTEX];

/// pipelens' shipped fragment shaders.
pub const SHIPPED_FRAGMENT: [&str; 7] = [
    BUILTIN_FRAGMENT,
    BUILTIN_PHONG_FRAGMENT,
    BUILTIN_UNLIT_FRAGMENT,
    BUILTIN_GOURAUD_FRAGMENT,
    BUILTIN_FLAT_FRAGMENT,
    BUILTIN_NORMAL_MAPPED_FRAGMENT,
    BUILTIN_MIRROR_FRAGMENT,
];

/// What of an object decides which of pipelens' shipped shader pairs draws it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Surface {
    /// The lights reach it (else it is drawn unlit).
    pub lit: bool,
    /// It has a bump or normal map and texture coordinates to read it with.
    pub detail: bool,
    /// It mirrors its environment.
    pub mirror: bool,
}

/// The GLSL of pipelens' own shading of a `surface` with `shading` and `reflection`, `(vertex,
/// fragment)`: running it gives the built-in pixels. An object the lights do not reach is
/// drawn unlit; a bump or normal map takes normal_mapped.frag, a mirror mirror.frag. `None`
/// where no shipped pair models the built-in path: Gouraud or flat shading with Phong's `r·v`
/// (change `n·h` in gouraud.vert or flat.frag), a surface detail with `r·v`, and a mirror
/// lit with `r·v` or with a bump map.
#[must_use]
pub fn builtin_sources(
    shading: crate::lighting::Frequency,
    reflection: crate::lighting::Reflection,
    surface: Surface,
) -> Option<(&'static str, &'static str)> {
    use crate::lighting::{Frequency, Reflection};
    let Surface {
        lit,
        detail,
        mirror,
    } = surface;
    match (shading, reflection) {
        (Frequency::Unlit, _) => Some((BUILTIN_VERTEX, BUILTIN_UNLIT_FRAGMENT)),
        _ if !lit => Some((BUILTIN_VERTEX, BUILTIN_UNLIT_FRAGMENT)),
        (_, Reflection::Phong) if detail && shading == Frequency::Phong => None,
        (Frequency::Phong, Reflection::BlinnPhong) if mirror && !detail => {
            Some((BUILTIN_VERTEX, BUILTIN_MIRROR_FRAGMENT))
        }
        (Frequency::Phong, _) if mirror => None,
        (Frequency::Phong, Reflection::BlinnPhong) if detail => {
            Some((BUILTIN_VERTEX, BUILTIN_NORMAL_MAPPED_FRAGMENT))
        }
        (Frequency::Phong, Reflection::BlinnPhong) => Some((BUILTIN_VERTEX, BUILTIN_FRAGMENT)),
        (Frequency::Phong, Reflection::Phong) => Some((BUILTIN_VERTEX, BUILTIN_PHONG_FRAGMENT)),
        (Frequency::Gouraud, Reflection::BlinnPhong) => {
            Some((BUILTIN_GOURAUD_VERTEX, BUILTIN_GOURAUD_FRAGMENT))
        }
        (Frequency::Flat, Reflection::BlinnPhong) => {
            Some((BUILTIN_FLAT_VERTEX, BUILTIN_FLAT_FRAGMENT))
        }
        (Frequency::Gouraud | Frequency::Flat, Reflection::Phong) => None,
    }
}

/// Where a fragment input comes from: the vertex output's first component in the vertex
/// shader's result, and how many.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link {
    /// First component of the vertex output in the vertex shader's result.
    pub from: u32,
    /// Components.
    pub components: u32,
}

/// A linked pair of shaders.
#[derive(Clone, Debug)]
pub struct Programs {
    /// The vertex shader.
    pub vertex: Arc<Program>,
    /// The fragment shader.
    pub fragment: Arc<Program>,
    /// For each fragment input (in the fragment shader's input order), its vertex output;
    /// `None` for built-ins (`gl_FragCoord`, `gl_FrontFacing`).
    pub links: Vec<Option<Link>>,
    /// The first component of `gl_Position` in the vertex shader's result.
    pub position: u32,
}

impl Programs {
    /// These programs with each stage's source placed in its file (see [`super::Origin`]), so
    /// that a run-time error names the file and the line there.
    #[must_use]
    pub fn placed(
        mut self,
        vertex: Option<super::Origin>,
        fragment: Option<super::Origin>,
    ) -> Self {
        if vertex.is_some() {
            Arc::make_mut(&mut self.vertex).origin = vertex;
        }
        if fragment.is_some() {
            Arc::make_mut(&mut self.fragment).origin = fragment;
        }
        self
    }
}

impl Programs {
    /// These programs with `stage`'s shader watching `expression` just after `line` (see
    /// [`super::probe`]): the frame they draw is the same, and every invocation keeps the value
    /// (a fragment its own; a vertex its own, which the fragment stage interpolates as a
    /// varying).
    ///
    /// # Errors
    /// A line that ends no statement, or an expression that does not compile there.
    pub fn watching(
        &self,
        stage: Stage,
        line: usize,
        expression: &str,
    ) -> Result<Self, super::probe::WatchError> {
        let program = match stage {
            Stage::Vertex => &self.vertex,
            Stage::Fragment => &self.fragment,
        };
        let mut watched = super::probe::watch(stage, &program.source, line, expression)?;
        watched.origin.clone_from(&program.origin);
        match stage {
            // The watch's value is a private global: the outputs and the links stay.
            Stage::Vertex => Ok(Self {
                vertex: Arc::new(watched),
                ..self.clone()
            }),
            // Linked again: the expression may read an input the shader did not (gl_FragCoord).
            Stage::Fragment => linked(Arc::clone(&self.vertex), watched).map_err(|e| {
                super::probe::WatchError::Compile(e.into_iter().map(|e| e.error).collect())
            }),
        }
    }
}

impl PartialEq for Programs {
    /// Two programs are the same when their sources are.
    fn eq(&self, other: &Self) -> bool {
        self.vertex.source == other.vertex.source && self.fragment.source == other.fragment.source
    }
}

/// A message about one of the two shaders.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StageError {
    /// Which shader.
    pub stage: Stage,
    /// The message, at its line.
    pub error: ShaderError,
}

impl std::fmt::Display for StageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} shader, {}", self.stage.name(), self.error)
    }
}

/// Compiles and links a vertex and a fragment shader (`None`: pipelens' own).
///
/// # Errors
/// Every message of either shader, and each fragment input no vertex output feeds (at the
/// input's declaration).
pub fn link(vertex: Option<&str>, fragment: Option<&str>) -> Result<Programs, Vec<StageError>> {
    let tag = |stage: Stage| {
        move |errors: Vec<ShaderError>| -> Vec<StageError> {
            errors
                .into_iter()
                .map(|error| StageError { stage, error })
                .collect()
        }
    };
    let vs = compile(Stage::Vertex, vertex.unwrap_or(BUILTIN_VERTEX)).map_err(tag(Stage::Vertex));
    let fs = compile(Stage::Fragment, fragment.unwrap_or(BUILTIN_FRAGMENT))
        .map_err(tag(Stage::Fragment));
    let (vs, fs) = match (vs, fs) {
        (Ok(v), Ok(f)) => (v, f),
        (v, f) => {
            let mut all = v.err().unwrap_or_default();
            all.extend(f.err().unwrap_or_default());
            return Err(all);
        }
    };
    linked(Arc::new(vs), fs)
}

/// Links two compiled shaders: each fragment input to the vertex output of its name.
///
/// # Errors
/// Each fragment input no vertex output feeds, or feeds with another number of components.
fn linked(vs: Arc<Program>, fs: Program) -> Result<Programs, Vec<StageError>> {
    let mut offsets = Vec::with_capacity(vs.outputs.len());
    let mut at = 0;
    for o in &vs.outputs {
        offsets.push(at);
        at += o.components;
    }
    let position = vs
        .outputs
        .iter()
        .zip(&offsets)
        .find(|(o, _)| o.name == "gl_Position")
        .map_or(0, |(_, &at)| at);
    let mut links = Vec::with_capacity(fs.inputs.len());
    let mut errors = Vec::new();
    for input in &fs.inputs {
        if input.builtin.is_some() {
            links.push(None);
            continue;
        }
        let found = vs
            .outputs
            .iter()
            .zip(&offsets)
            .find(|(o, _)| o.name == input.name && o.builtin.is_none());
        match found {
            Some((o, &from)) if o.components == input.components => {
                links.push(Some(Link { from, components: o.components }));
            }
            Some((o, _)) => errors.push(StageError {
                stage: Stage::Fragment,
                error: super::complain(
                    fs.error_at_name(
                        &input.name,
                        format!(
                            "`{}` has {} components here but {} in the vertex shader: declare it with the same type in both",
                            input.name, input.components, o.components
                        ),
                    ),
                    super::Complaint::VaryingComponents {
                        name: input.name.clone(),
                        here: input.components,
                        vertex: o.components,
                    },
                ),
            }),
            None => {
                let outputs: Vec<&str> =
                    vs.outputs.iter().filter(|o| o.builtin.is_none()).map(|o| o.name.as_str()).collect();
                errors.push(StageError {
                    stage: Stage::Fragment,
                    error: super::complain(
                        fs.error_at_name(
                            &input.name,
                            format!(
                                "the vertex shader has no output `{}` to interpolate into this input; its outputs: {}",
                                input.name,
                                if outputs.is_empty() { "none".to_owned() } else { outputs.join(", ") }
                            ),
                        ),
                        super::Complaint::NoVaryingSource {
                            name: input.name.clone(),
                            outputs: outputs.iter().map(|o| (*o).to_owned()).collect(),
                        },
                    ),
                });
            }
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    Ok(Programs {
        vertex: vs,
        fragment: Arc::new(fs),
        links,
        position,
    })
}

/// A shipped pair ([`builtin_sources`]) linked once for the whole process: a lab compares every
/// frame with pipelens' own shaders, and compiling them again for each frame cost the app's UI
/// thread a compile per frame received.
///
/// # Errors
/// The messages of a shipped pair that does not compile (a defect the tests catch); nothing is
/// kept then.
pub fn builtin_programs(
    vertex: &'static str,
    fragment: &'static str,
) -> Result<Arc<Programs>, Vec<StageError>> {
    type Linked = Vec<((usize, usize), Arc<Programs>)>;
    static LINKED: std::sync::Mutex<Linked> = std::sync::Mutex::new(Vec::new());
    // The shipped sources are static: their addresses name them.
    let key = (vertex.as_ptr() as usize, fragment.as_ptr() as usize);
    let found = LINKED.lock().ok().and_then(|l| {
        l.iter()
            .find(|(k, _)| *k == key)
            .map(|(_, p)| Arc::clone(p))
    });
    if let Some(p) = found {
        return Ok(p);
    }
    let p = Arc::new(link(Some(vertex), Some(fragment))?);
    if let Ok(mut l) = LINKED.lock() {
        l.push((key, Arc::clone(&p)));
    }
    Ok(p)
}
