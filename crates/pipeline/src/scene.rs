//! What is drawn: objects (a mesh placed in the world by its model transform), the camera and
//! projection, the lights, a planar shadow and articulated figures. Plain data;
//! [`Scene::problems`] says what is wrong with it in words.

use std::sync::Arc;

use glam::{Mat4, Vec3};
use serde::Serialize;

use crate::buffers::BufferKind;
use crate::camera::{Camera, Projection};
use crate::hierarchy::{self, Figure};
use crate::light::{Light, Material};
use crate::lighting::Frequency;
use crate::mesh::{BuiltinMesh, Mesh};
use crate::settings::RenderSettings;
use crate::texture::{Displacement, Environment, SurfaceDetail, Texture};
use crate::transform::{self, NamedMatrix, TransformError};

/// Where a fragment's colour comes from, before lighting exists.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ColorSource {
    /// The mesh's vertex colours, interpolated (meshes without colours use [`ColorSource::Normal`]).
    Vertex,
    /// The object-space normal shown as a colour, `(n + 1)/2`.
    Normal,
    /// One colour for the whole object.
    Uniform(Vec3),
}

/// A mesh placed in the world by its model transform `M = T·Rz·Ry·Rx·S`.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Name shown in the app and the capture.
    pub name: String,
    /// The mesh, shared (meshes can be large).
    pub mesh: Arc<Mesh>,
    /// Translation `T(tx, ty, tz)`.
    pub translate: Vec3,
    /// Rotation angles about x, y, z in degrees, applied x first: `Rz·Ry·Rx`.
    pub rotate_deg: Vec3,
    /// Scale `S(sx, sy, sz)`.
    pub scale: Vec3,
    /// The colour of its fragments.
    pub color: ColorSource,
    /// Its reflection coefficients (used by lighting).
    pub material: Material,
    /// Its texture: the surface colour where the mesh has texture coordinates.
    pub texture: Option<Arc<Texture>>,
    /// Bump or normal mapping (per-pixel lighting only).
    pub detail: Option<SurfaceDetail>,
    /// Displacement mapping: vertices moved along their normals.
    pub displacement: Option<Displacement>,
    /// Environment mapping: the surface mirrors a cube map.
    pub environment: Option<Environment>,
    /// A matrix applied after the object's own transform, `M = parent·T·Rz·Ry·Rx·S` (a shadow
    /// projection, a parent node's composite).
    pub parent: Option<NamedMatrix>,
    /// Whether lighting applies (shadow geometry is drawn in its flat colour).
    pub lit: bool,
    /// Whether it casts a planar shadow (when the scene has one).
    pub casts_shadow: bool,
    /// A rotation by an angle (degrees) about an arbitrary axis through the object's origin,
    /// applied after its Euler rotations: `M = T·R(n, θ)·Rz·Ry·Rx·S`, with `R(n, θ)` built as the
    /// notes do (`Rx(−θx)·Ry(−θy)·Rz(θ)·Ry(θy)·Rx(θx)`).
    pub axis_rotation: Option<(Vec3, f32)>,
    /// With an axis rotation: the orientation moves by slerp from it to a second one, and
    /// `R(slerp(q₀, q₁, t))` takes the axis rotation's place in `M`.
    pub slerp: Option<transform::SlerpTo>,
    /// How the mesh was generated, when it is built in: lets a lesson change a parameter of the
    /// shape itself (a Bézier curve's `t`) and build it again.
    pub builtin: Option<BuiltinMesh>,
    /// The code the student gave it: shaders that replace the vertex stage's transform and the
    /// shading, and functions the pipeline calls in place of its own — the rasterizer's inside
    /// and depth tests for this object's triangles, a Bézier curve's or patch's points, the
    /// shadow matrix for this object's shadow (see [`crate::shader`] and
    /// [`crate::shader::hook`]).
    pub code: StudentCode,
}

/// An object's shaders and the time their `time` uniform reads.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectShader {
    /// The linked vertex and fragment shaders.
    pub programs: Arc<crate::shader::Programs>,
    /// Seconds into the step's animation (`uniform float time;`).
    pub time: f32,
}

/// The code a student gives a scene: shaders for its objects, an inside test and a depth test
/// for its rasterizer, de Casteljau for a Bézier curve, a shadow matrix, a Bézier patch's point
/// (a lesson's `shader = { vertex, fragment, inside, depth_test, de_casteljau, shadow_matrix,
/// bezier_patch }`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StudentCode {
    /// The vertex and fragment shaders (`None`: pipelens' own stages).
    pub shader: Option<ObjectShader>,
    /// The functions of the pipeline the student wrote, by kind (`None`: pipelens' own).
    pub hooks: crate::shader::Hooks,
    /// Values given to the shaders' own uniforms (`shader.uniforms`), by name: they go into
    /// [`Scene::uniforms`].
    pub uniforms: std::collections::BTreeMap<String, Vec<f32>>,
}

impl Object {
    /// What decides which of pipelens' shipped shader pairs draws this object
    /// ([`crate::shader::builtin_sources`]).
    #[must_use]
    pub fn surface(&self) -> crate::shader::Surface {
        crate::shader::Surface {
            lit: self.lit,
            detail: self.detail.is_some() && !self.mesh.uvs.is_empty(),
            mirror: self.environment.is_some(),
        }
    }

    /// An object with the identity transform and its mesh's own colours.
    #[must_use]
    pub fn new(name: &str, mesh: Mesh) -> Self {
        Self {
            name: name.to_owned(),
            mesh: Arc::new(mesh),
            translate: Vec3::ZERO,
            rotate_deg: Vec3::ZERO,
            scale: Vec3::ONE,
            color: ColorSource::Vertex,
            material: Material::default(),
            texture: None,
            detail: None,
            displacement: None,
            environment: None,
            parent: None,
            lit: true,
            casts_shadow: true,
            axis_rotation: None,
            slerp: None,
            builtin: None,
            code: StudentCode::default(),
        }
    }

    /// The model matrix `M = T·Rz(θz)·Ry(θy)·Rx(θx)·S` with its factors.
    #[must_use]
    pub fn model_matrix(&self) -> NamedMatrix {
        let r = self.rotate_deg * (std::f32::consts::PI / 180.0);
        let mut factors: Vec<NamedMatrix> = self.parent.iter().cloned().collect();
        factors.push(NamedMatrix::new(
            "T",
            "T(tx, ty, tz)",
            transform::translate(self.translate),
        ));
        let about_axis = self.axis_rotation.and_then(|(axis, deg)| match self.slerp {
            Some(s) => s.matrix(axis, deg).ok(),
            None => transform::rotate_axis_aligned(axis, deg.to_radians()).ok(),
        });
        factors.extend(about_axis);
        factors.extend([
            NamedMatrix::new("Rz", "Rz(θz)", transform::rotate_z(r.z)),
            NamedMatrix::new("Ry", "Ry(θy)", transform::rotate_y(r.y)),
            NamedMatrix::new("Rx", "Rx(θx)", transform::rotate_x(r.x)),
            NamedMatrix::new("S", "S(sx, sy, sz)", transform::scale(self.scale)),
        ]);
        let m = factors.iter().fold(Mat4::IDENTITY, |m, f| m * f.matrix);
        let formula = match (self.parent.is_some(), self.axis_rotation.is_some()) {
            (true, _) => "M = parent·T·Rz·Ry·Rx·S: the object's own transform, then its parent's",
            (false, false) => "M = T·Rz·Ry·Rx·S: scale, rotate about x, y, z, then translate",
            (false, true) if self.slerp.is_some() => {
                "M = T·R(slerp(q₀, q₁, t))·Rz·Ry·Rx·S: scale, rotate about x, y, z, then part way between two orientations, then translate"
            }
            (false, true) => {
                "M = T·R(n, θ)·Rz·Ry·Rx·S: scale, rotate about x, y, z, then about the axis n, then translate"
            }
        };
        NamedMatrix::new(&format!("M_model({})", self.name), formula, m).with_factors(factors)
    }
}

/// A planar projected shadow (Angel's shadow matrix): every object that casts one is drawn a
/// second time, projected from the point light `light` onto the plane `y = plane_y`, in `color`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PlanarShadow {
    /// The light the shadow is cast from.
    pub light: Vec3,
    /// The height of the receiving plane.
    pub plane_y: f32,
    /// The shadow's colour.
    pub color: Vec3,
    /// The projection onto `y = 0` the student's `shadow_matrix` gave for this light, in place
    /// of pipelens' own (set by the render before the shadow pass).
    pub yours: Option<Mat4>,
}

/// How far above its plane shadow geometry is lifted so that it wins the depth test against
/// the plane itself (the polygon offset of fixed-function OpenGL).
pub const SHADOW_LIFT: f32 = 2e-3;

impl PlanarShadow {
    /// The light relative to the receiving plane, `l − (0, h, 0)`: where it is when the plane
    /// is moved to `y = 0`, as the notes' matrix (and the student's `shadow_matrix`) take it.
    #[must_use]
    pub fn light_over_plane(&self) -> Vec3 {
        self.light - Vec3::new(0.0, self.plane_y, 0.0)
    }

    /// `T(0, h + ε, 0)·M_shadow(l − (0, h, 0))·T(0, −h, 0)`: the notes' matrix for the plane
    /// `y = 0`, moved to `y = h` and lifted by [`SHADOW_LIFT`].
    #[must_use]
    pub fn matrix(&self) -> NamedMatrix {
        let h = Vec3::new(0.0, self.plane_y, 0.0);
        let m = match self.yours {
            Some(m) => NamedMatrix::new("M_shadow (yours)", "your shadow_matrix(l)", m),
            None => transform::planar_shadow(self.light_over_plane()),
        };
        let up = transform::translate(h + Vec3::new(0.0, SHADOW_LIFT, 0.0));
        let down = transform::translate(-h);
        NamedMatrix::new(
            "M_shadow",
            "T(0, h+ε, 0)·[T(l)·M_p·T(−l)]·T(0, −h, 0): project from the light onto y = h",
            up * m.matrix * down,
        )
        .with_factors(vec![
            NamedMatrix::new("T(0, h+ε, 0)", "back up to the plane, lifted by ε", up),
            m,
            NamedMatrix::new("T(0, −h, 0)", "the plane to y = 0", down),
        ])
    }
}

/// Everything that is drawn: objects, camera and projection.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Scene {
    /// The objects, drawn in this order (primitive ids count across them in this order).
    pub objects: Vec<Object>,
    /// The viewing camera.
    pub camera: Camera,
    /// The projection.
    pub projection: Projection,
    /// The lights (used by lighting).
    pub lights: Vec<Light>,
    /// A planar projected shadow, drawn as a second pass.
    pub shadow: Option<PlanarShadow>,
    /// Articulated figures (robot arm, humanoid), drawn part by part by a matrix-stack traversal.
    pub figures: Vec<Figure>,
    /// The values of the student's own uniforms (`crate::shader::own_uniform`), by name — a
    /// lesson's `shader.uniforms`, the shader panel's controls; one not here starts at the
    /// value its comment gives.
    pub uniforms: std::collections::BTreeMap<String, Vec<f32>>,
}

impl Scene {
    /// Whether any object runs the student's shaders.
    #[must_use]
    pub fn has_shaders(&self) -> bool {
        self.objects.iter().any(|o| o.code.shader.is_some())
    }

    /// The uniforms of the student's own the objects' shaders declare (each name once, the
    /// first declaration's control), with the scene's value where it has one.
    #[must_use]
    pub fn own_uniforms(&self) -> Vec<crate::shader::own_uniform::OwnUniform> {
        let mut own: Vec<crate::shader::own_uniform::OwnUniform> = Vec::new();
        for sh in self.objects.iter().filter_map(|o| o.code.shader.as_ref()) {
            for stage in [&sh.programs.vertex, &sh.programs.fragment] {
                for mut u in stage.own_uniforms() {
                    if own.iter().all(|o| o.name != u.name) {
                        if let Some(v) = self.uniforms.get(&u.name) {
                            u.value.clone_from(v);
                        }
                        own.push(u);
                    }
                }
            }
        }
        own
    }

    /// Every object runs `shader` (a lesson step's, the shader panel's).
    pub fn set_shaders(&mut self, shader: &ObjectShader) {
        for o in &mut self.objects {
            o.code.shader = Some(shader.clone());
        }
    }

    /// This scene with every object's shader of `watch.stage` watching its expression just
    /// after its line (`Programs::watching`): the frame it draws keeps the value at every pixel
    /// (`ShaderRecord::watch`; a vertex shader's interpolated over each triangle).
    ///
    /// # Errors
    /// No object has shaders, the line ends no statement, or the expression does not compile
    /// there.
    pub fn watching(
        &self,
        watch: &crate::shader::probe::WatchSpec,
    ) -> Result<Self, crate::shader::probe::WatchError> {
        if !self.has_shaders() {
            return Err(crate::shader::probe::WatchError::NoShader);
        }
        let mut scene = self.clone();
        // One compile for each program the objects share.
        let mut made: Vec<(
            std::sync::Arc<crate::shader::Programs>,
            std::sync::Arc<crate::shader::Programs>,
        )> = Vec::new();
        for o in &mut scene.objects {
            let Some(sh) = &mut o.code.shader else {
                continue;
            };
            let watched = match made
                .iter()
                .find(|(from, _)| std::sync::Arc::ptr_eq(from, &sh.programs))
            {
                Some((_, to)) => std::sync::Arc::clone(to),
                None => {
                    let to = std::sync::Arc::new(sh.programs.watching(
                        watch.stage,
                        watch.line,
                        &watch.expression,
                    )?);
                    made.push((
                        std::sync::Arc::clone(&sh.programs),
                        std::sync::Arc::clone(&to),
                    ));
                    to
                }
            };
            sh.programs = watched;
        }
        Ok(scene)
    }

    /// Every object's triangles are covered where the student's `inside` says.
    pub fn set_inside(&mut self, inside: &crate::shader::InsideTest) {
        self.set_hook(inside);
    }

    /// Every object runs the student's function `hook` (of its kind).
    pub fn set_hook(&mut self, hook: &crate::shader::Hook) {
        for o in &mut self.objects {
            o.code.hooks.set(hook.clone());
        }
    }

    /// The student's function of kind `kind` the scene runs (its first object's with one).
    #[must_use]
    pub fn hook(&self, kind: crate::shader::HookKind) -> Option<&crate::shader::Hook> {
        self.objects.iter().find_map(|o| o.code.hooks.get(kind))
    }

    /// Every object's covered samples are written where the student's `depth_test` says.
    pub fn set_depth_test(&mut self, test: &crate::shader::Hook) {
        self.set_hook(test);
    }

    /// Every object runs pipelens' own stages again: no shaders, no functions of the student's.
    pub fn clear_code(&mut self) {
        for o in &mut self.objects {
            o.code = StudentCode::default();
        }
    }

    /// Every object runs what of `code` is given; what is not given stays as it is.
    pub fn run_code(&mut self, code: &StudentCode) {
        if let Some(shader) = &code.shader {
            self.set_shaders(shader);
        }
        self.uniforms.extend(code.uniforms.clone());
        for hook in code.hooks.iter() {
            self.set_hook(hook);
        }
    }

    /// This scene with each object running pipelens' own shading at `settings` written as
    /// GLSL ([`crate::shader::builtin_sources`]), which draws the built-in pixels. An object
    /// whose shading has no shipped pair (a mirror) keeps the built-in stages; `Ok(None)` when no
    /// object has one.
    ///
    /// # Errors
    /// The messages of a shipped pair that does not compile (a defect the tests catch).
    pub fn with_builtin_shaders(
        &self,
        settings: &RenderSettings,
    ) -> Result<Option<Self>, Vec<crate::shader::StageError>> {
        let mut scene = self.clone();
        let mut any = false;
        for o in &mut scene.objects {
            let Some((vs, fs)) =
                crate::shader::builtin_sources(settings.shading, settings.reflection, o.surface())
            else {
                continue;
            };
            o.code.shader = Some(ObjectShader {
                programs: crate::shader::builtin_programs(vs, fs)?,
                time: 0.0,
            });
            any = true;
        }
        Ok(any.then_some(scene))
    }

    /// Whether a full capture of this scene at `settings` has buffer `kind` to show: the
    /// lighting buffers when lighting is on (the reflected term when an object mirrors its
    /// environment), the texturing buffers when an object is textured. Known before rendering,
    /// so that a view can offer a buffer that the capture it shows did not keep.
    #[must_use]
    pub fn offers(&self, settings: &RenderSettings, kind: BufferKind) -> bool {
        let lit = settings.shading != Frequency::Unlit;
        if kind == BufferKind::Reflected {
            lit && self
                .objects
                .iter()
                .any(|o| o.lit && o.environment.is_some())
        } else if kind.is_lighting() {
            lit
        } else if kind.is_texturing() {
            self.objects
                .iter()
                .any(|o| o.texture.is_some() && !o.mesh.uvs.is_empty())
        } else {
            true
        }
    }

    /// The scene with its figures and planar shadow turned into plain objects (see
    /// [`Self::drawn_objects`]), and the figures' traversal; `None` when it has neither, so
    /// that the same pipeline draws them all.
    #[must_use]
    pub fn expanded(&self) -> Option<(Self, Vec<hierarchy::Step>)> {
        if self.shadow.is_none() && self.figures.is_empty() {
            return None;
        }
        let (objects, steps) = self.drawn_objects();
        let scene = Self {
            objects,
            shadow: None,
            figures: Vec::new(),
            ..self.clone()
        };
        Some((scene, steps))
    }

    /// The objects drawn and the figures' traversal: the scene's own objects, then every part
    /// of every figure (depth-first, with a matrix stack), then (with a planar shadow) the shadow
    /// pass, one unlit object `shadow of …` per object that casts one.
    #[must_use]
    pub fn drawn_objects(&self) -> (Vec<Object>, Vec<hierarchy::Step>) {
        let mut out = self.objects.clone();
        let mut steps = Vec::new();
        if !self.figures.is_empty() {
            // Every part is an instance of one symbol, the unit cube.
            let cube = Arc::new(BuiltinMesh::Cube.build());
            for figure in &self.figures {
                let (parts, traversal) = hierarchy::traverse(figure, out.len());
                steps.extend(traversal);
                out.extend(parts.into_iter().map(|part| {
                    let mut object = Object::new(&part.name, Mesh::default());
                    object.mesh = Arc::clone(&cube);
                    object.color = ColorSource::Uniform(part.color);
                    object.parent = Some(part.placement);
                    object
                }));
            }
        }
        if let Some(shadow) = &self.shadow {
            let m = shadow.matrix();
            let casting: Vec<Object> = out.iter().filter(|o| o.casts_shadow).cloned().collect();
            for o in casting {
                let mut s = o.clone();
                s.name = format!("shadow of {}", o.name);
                s.parent = Some(match &o.parent {
                    Some(p) => NamedMatrix::new("M_shadow·parent", &m.formula, m.matrix * p.matrix)
                        .with_factors(vec![m.clone(), p.clone()]),
                    None => m.clone(),
                });
                s.color = ColorSource::Uniform(shadow.color);
                s.texture = None;
                s.detail = None;
                s.environment = None;
                // Drawn in the shadow's colour, whatever shaders the object runs.
                s.code.shader = None;
                s.lit = false;
                s.casts_shadow = false;
                out.push(s);
            }
        }
        (out, steps)
    }

    /// The view matrix `LookAt(eye, at, up)`.
    ///
    /// # Errors
    /// When the camera is degenerate (see [`transform::camera_frame`]).
    pub fn view_matrix(&self) -> Result<NamedMatrix, TransformError> {
        let Camera { eye, at, up } = self.camera;
        let m = transform::look_at(eye, at, up)?;
        let gt = transform::look_at_gt(eye, at - eye, up)?;
        Ok(NamedMatrix::new(
            "V = LookAt(eye, at, up)",
            "rows u, v, n and −p·u, −p·v, −p·n with n = (eye−at)/|eye−at|, u = v_up×n/|v_up×n|, \
             v = n×u; equals GAMES101's R_view·T_view with g = at − eye, t = up",
            m,
        )
        .with_factors(gt.factors))
    }

    /// Every problem with the scene and settings; empty when it can be drawn.
    #[must_use]
    pub fn problems(&self, settings: &RenderSettings) -> Vec<SceneProblem> {
        let mut out: Vec<SceneProblem> = (settings.problems().into_iter())
            .map(SceneProblem::Settings)
            .collect();
        out.extend(
            self.projection
                .problems()
                .into_iter()
                .map(SceneProblem::Projection),
        );
        let Camera { eye, at, up } = self.camera;
        if !(eye.is_finite() && at.is_finite() && up.is_finite()) {
            out.push(SceneProblem::CameraNotFinite);
        } else if let Err(e) = transform::camera_frame(eye, at, up) {
            out.push(SceneProblem::Camera(e));
        }
        for o in &self.objects {
            if !(o.translate.is_finite() && o.rotate_deg.is_finite() && o.scale.is_finite()) {
                out.push(SceneProblem::ObjectTransform(o.name.clone()));
            }
            if let ColorSource::Uniform(c) = o.color
                && !c.is_finite()
            {
                out.push(SceneProblem::ObjectColour(o.name.clone()));
            }
        }
        out
    }
}

/// What keeps a scene from being drawn, as data for the interface to say in its language; its
/// English sentence is its `Display`.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneProblem {
    /// A problem with the render settings.
    #[error(transparent)]
    Settings(#[from] crate::settings::SettingsProblem),
    /// A problem with the projection's parameters.
    #[error(transparent)]
    Projection(#[from] crate::camera::ProjectionProblem),
    /// The camera's eye, at or up is NaN or infinite.
    #[error("the camera's eye, at and up must be finite")]
    CameraNotFinite,
    /// The camera's frame is undefined (eye = at, or up along the view direction).
    #[error(transparent)]
    Camera(#[from] TransformError),
    /// An object's translation, rotation or scale is NaN or infinite.
    #[error("object `{0}`: its transform must be finite")]
    ObjectTransform(String),
    /// An object's colour is NaN or infinite.
    #[error("object `{0}`: its colour must be finite")]
    ObjectColour(String),
}
