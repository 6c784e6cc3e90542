//! Hierarchical models (Angel, chapter on hierarchical modelling): a tree of parts, each placed
//! relative to its parent, drawn by a depth-first traversal with a matrix stack.
//!
//! Every part is a *symbol* (here the unit cube `[−1, 1]³`) turned into an *instance* by its own
//! `instance` matrix (e.g. `T(0, h/2, 0)·S(w/2, h/2, w/2)`: the cube's base at y = 0). Its
//! `local` matrix places it relative to its parent (e.g. `T(0, h_parent, 0)·Rz(θ)`, a joint).
//! The traversal keeps `M`, the composite of the locals from the root:
//!
//! ```text
//! visit(node, M):  M ← M·local;  draw(M·instance)
//!                  for each child:  push(M);  visit(child, M);  M ← pop()
//! ```
//!
//! The robot arm: `M_base = R_b`, `M_lower = R_b·T_la·R_la`, `M_upper = R_b·T_la·R_la·T_ua·R_ua`.

use glam::{Mat4, Vec3};
use serde::Serialize;

use crate::transform::{self, NamedMatrix};

/// A part of an articulated model.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Its name (shown in the traversal).
    pub name: String,
    /// Placement relative to the parent: a translation to the joint and the joint's rotation.
    pub local: NamedMatrix,
    /// From the symbol (the unit cube) to this part's shape.
    pub instance: NamedMatrix,
    /// Its colour.
    pub color: Vec3,
    /// Its children, visited in order.
    pub children: Vec<Node>,
}

/// One step of the traversal, as the matrix stack sees it.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "op")]
pub enum Step {
    /// `push(M)`: the stack grows to `depth`.
    Push {
        /// Stack depth after the push.
        depth: usize,
    },
    /// `M ← M·local` and the part is drawn with `M·instance`.
    Visit {
        /// The figure the part belongs to.
        figure: String,
        /// The part.
        node: String,
        /// The composite `M` after multiplying by the part's local matrix.
        composite: NamedMatrix,
        /// The index of the object that draws it in the scene's drawn objects.
        object: usize,
    },
    /// `M ← pop()`: back to the parent's matrix.
    Pop {
        /// Stack depth after the pop.
        depth: usize,
    },
}

/// The articulated models of the notes, with their joint angles.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Pose {
    /// The robot arm: base, lower arm, upper arm.
    RobotArm(RobotArm),
    /// The humanoid: torso, head, four two-part limbs.
    Humanoid(Humanoid),
}

impl Pose {
    /// Every joint angle (degrees) by the name scene files use for it.
    pub fn joints_mut(&mut self) -> Vec<(&'static str, &mut f32)> {
        match self {
            Self::RobotArm(a) => vec![
                ("base", &mut a.base),
                ("lower", &mut a.lower),
                ("upper", &mut a.upper),
            ],
            Self::Humanoid(h) => vec![
                ("torso", &mut h.torso),
                ("head", &mut h.head),
                ("left_upper_arm", &mut h.left_upper_arm),
                ("left_lower_arm", &mut h.left_lower_arm),
                ("right_upper_arm", &mut h.right_upper_arm),
                ("right_lower_arm", &mut h.right_lower_arm),
                ("left_upper_leg", &mut h.left_upper_leg),
                ("left_lower_leg", &mut h.left_lower_leg),
                ("right_upper_leg", &mut h.right_upper_leg),
                ("right_lower_leg", &mut h.right_lower_leg),
            ],
        }
    }

    /// The tree of parts in this pose.
    #[must_use]
    pub fn tree(&self) -> Node {
        match self {
            Self::RobotArm(a) => a.tree(),
            Self::Humanoid(h) => h.tree(),
        }
    }
}

/// A posed figure in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Its name.
    pub name: String,
    /// Which model, in which pose.
    pub pose: Pose,
    /// Where the whole figure stands: `T(translate)` before the root.
    pub translate: Vec3,
}

fn part(
    name: &str,
    local: NamedMatrix,
    size: Vec3,
    hanging: bool,
    color: Vec3,
    children: Vec<Node>,
) -> Node {
    // The cube [−1, 1]³ scaled to the part's size, its base (or top, if it hangs) at the joint.
    let offset = if hanging { -size.y / 2.0 } else { size.y / 2.0 };
    let t = transform::translate(Vec3::new(0.0, offset, 0.0));
    let s = transform::scale(size / 2.0);
    Node {
        name: name.to_owned(),
        local,
        instance: NamedMatrix::new(
            "instance",
            if hanging {
                "T(0, −h/2, 0)·S(w/2, h/2, d/2)"
            } else {
                "T(0, h/2, 0)·S(w/2, h/2, d/2)"
            },
            t * s,
        )
        .with_factors(vec![
            NamedMatrix::new("T", "", t),
            NamedMatrix::new("S", "", s),
        ]),
        color,
        children,
    }
}

fn joint(formula: &str, translate: Vec3, rotation: Mat4) -> NamedMatrix {
    let t = transform::translate(translate);
    NamedMatrix::new("local", formula, t * rotation).with_factors(vec![
        NamedMatrix::new("T", "to the joint", t),
        NamedMatrix::new("R", "the joint", rotation),
    ])
}

/// The joint angles of the robot arm, degrees.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct RobotArm {
    /// The base's rotation about y.
    pub base: f32,
    /// The lower arm's rotation about z.
    pub lower: f32,
    /// The upper arm's rotation about z.
    pub upper: f32,
}

impl RobotArm {
    /// Base height, lower and upper arm lengths.
    pub const HEIGHTS: [f32; 3] = [0.4, 1.2, 1.0];

    /// The tree: base → lower arm → upper arm.
    #[must_use]
    pub fn tree(&self) -> Node {
        let [hb, hl, hu] = Self::HEIGHTS;
        let upper = part(
            "upper arm",
            joint(
                "T_ua·R_ua = T(0, h_la, 0)·Rz(θ_ua)",
                Vec3::new(0.0, hl, 0.0),
                transform::rotate_z(self.upper.to_radians()),
            ),
            Vec3::new(0.2, hu, 0.2),
            false,
            Vec3::new(0.95, 0.75, 0.25),
            Vec::new(),
        );
        let lower = part(
            "lower arm",
            joint(
                "T_la·R_la = T(0, h_b, 0)·Rz(θ_la)",
                Vec3::new(0.0, hb, 0.0),
                transform::rotate_z(self.lower.to_radians()),
            ),
            Vec3::new(0.3, hl, 0.3),
            false,
            Vec3::new(0.3, 0.6, 0.9),
            vec![upper],
        );
        part(
            "base",
            joint(
                "R_b = Ry(θ_b)",
                Vec3::ZERO,
                transform::rotate_y(self.base.to_radians()),
            ),
            Vec3::new(1.0, hb, 1.0),
            false,
            Vec3::new(0.5, 0.5, 0.55),
            vec![lower],
        )
    }
}

/// The joint angles of the humanoid figure, degrees (limbs rotate about x: forwards/backwards).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[allow(missing_docs)]
pub struct Humanoid {
    pub torso: f32,
    pub head: f32,
    pub left_upper_arm: f32,
    pub left_lower_arm: f32,
    pub right_upper_arm: f32,
    pub right_lower_arm: f32,
    pub left_upper_leg: f32,
    pub left_lower_leg: f32,
    pub right_upper_leg: f32,
    pub right_lower_leg: f32,
}

impl Humanoid {
    /// The tree: torso → head and four two-part limbs.
    #[must_use]
    pub fn tree(&self) -> Node {
        let rx = |a: f32| transform::rotate_x(a.to_radians());
        let skin = Vec3::new(0.95, 0.8, 0.65);
        let shirt = Vec3::new(0.3, 0.55, 0.85);
        let trousers = Vec3::new(0.3, 0.3, 0.4);
        let limb = |name: &str, upper: f32, lower: f32, at: Vec3, sizes: [f32; 2], color: Vec3| {
            let lower_part = part(
                &format!("{name} lower"),
                joint(
                    "T(0, −h_upper, 0)·Rx(θ)",
                    Vec3::new(0.0, -sizes[0], 0.0),
                    rx(lower),
                ),
                Vec3::new(0.18, sizes[1], 0.18),
                true,
                color,
                Vec::new(),
            );
            part(
                &format!("{name} upper"),
                joint("T(joint on the torso)·Rx(θ)", at, rx(upper)),
                Vec3::new(0.22, sizes[0], 0.22),
                true,
                color,
                vec![lower_part],
            )
        };
        let head = part(
            "head",
            joint(
                "T(0, h_torso, 0)·Ry(θ)",
                Vec3::new(0.0, 1.2, 0.0),
                transform::rotate_y(self.head.to_radians()),
            ),
            Vec3::new(0.4, 0.45, 0.4),
            false,
            skin,
            Vec::new(),
        );
        let children = vec![
            head,
            limb(
                "left arm",
                self.left_upper_arm,
                self.left_lower_arm,
                Vec3::new(-0.45, 1.15, 0.0),
                [0.6, 0.55],
                skin,
            ),
            limb(
                "right arm",
                self.right_upper_arm,
                self.right_lower_arm,
                Vec3::new(0.45, 1.15, 0.0),
                [0.6, 0.55],
                skin,
            ),
            limb(
                "left leg",
                self.left_upper_leg,
                self.left_lower_leg,
                Vec3::new(-0.2, 0.0, 0.0),
                [0.75, 0.7],
                trousers,
            ),
            limb(
                "right leg",
                self.right_upper_leg,
                self.right_lower_leg,
                Vec3::new(0.2, 0.0, 0.0),
                [0.75, 0.7],
                trousers,
            ),
        ];
        part(
            "torso",
            joint(
                "R_torso = Ry(θ)",
                Vec3::ZERO,
                transform::rotate_y(self.torso.to_radians()),
            ),
            Vec3::new(0.7, 1.2, 0.35),
            false,
            shirt,
            children,
        )
    }
}

/// A part to draw: the symbol (the unit cube `[−1, 1]³`) placed by `M·instance`.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// `figure: part`, e.g. `robot arm: base`.
    pub name: String,
    /// `M·instance`: the part's composite times its instance matrix, with both as factors.
    pub placement: NamedMatrix,
    /// Its colour.
    pub color: Vec3,
}

/// Traverses a figure depth-first with a matrix stack: the parts to draw, in order, and the
/// steps of the traversal. `first` is the index the first part will have among the scene's
/// drawn objects (each [`Step::Visit`] names its part's index there).
#[must_use]
pub fn traverse(figure: &Figure, first: usize) -> (Vec<Part>, Vec<Step>) {
    let mut walk = Walk {
        figure: &figure.name,
        first,
        parts: Vec::new(),
        steps: Vec::new(),
    };
    let start = NamedMatrix::new(
        "T",
        "where the figure stands",
        transform::translate(figure.translate),
    );
    walk.visit(&figure.pose.tree(), &start, 0);
    (walk.parts, walk.steps)
}

/// `figure`'s root part in a traversal (the first figure's when `None`) and its composite: the
/// matrix its chain starts from, `M(base)` for the robot arm, `M(torso)` for the humanoid.
#[must_use]
pub fn root_composite<'a>(
    steps: &'a [Step],
    figure: Option<&str>,
) -> Option<(&'a str, &'a NamedMatrix)> {
    steps.iter().find_map(|s| match s {
        Step::Visit {
            figure: f,
            node,
            composite,
            ..
        } if figure.is_none_or(|g| g == f) => Some((node.as_str(), composite)),
        _ => None,
    })
}

/// The state of a traversal: what it has drawn and done so far.
struct Walk<'a> {
    figure: &'a str,
    first: usize,
    parts: Vec<Part>,
    steps: Vec<Step>,
}

impl Walk<'_> {
    fn visit(&mut self, node: &Node, parent: &NamedMatrix, depth: usize) {
        let composite = NamedMatrix::new(
            &format!("M({})", node.name),
            "M ← M·local: the parent's composite times this part's placement",
            parent.matrix * node.local.matrix,
        )
        .with_factors(vec![
            NamedMatrix::new("M (parent)", &parent.formula, parent.matrix),
            node.local.clone(),
        ]);
        let placement = NamedMatrix::new(
            "M·instance",
            "the part's composite times its instance matrix",
            composite.matrix * node.instance.matrix,
        )
        .with_factors(vec![composite.clone(), node.instance.clone()]);
        self.steps.push(Step::Visit {
            figure: self.figure.to_owned(),
            node: node.name.clone(),
            composite: composite.clone(),
            object: self.first + self.parts.len(),
        });
        self.parts.push(Part {
            name: format!("{}: {}", self.figure, node.name),
            placement,
            color: node.color,
        });
        for child in &node.children {
            self.steps.push(Step::Push { depth: depth + 1 });
            self.visit(child, &composite, depth + 1);
            self.steps.push(Step::Pop { depth });
        }
    }
}
