//! Hierarchical models: composites by hand, the order of the traversal and its stack.

use glam::{Mat4, Vec3};
use pipeline::hierarchy::{Figure, Humanoid, Pose, RobotArm, Step, traverse};
use pipeline::transform::{rotate_x, rotate_y, rotate_z, translate};

fn close(a: &Mat4, b: &Mat4) -> bool {
    a.abs_diff_eq(*b, 1e-5)
}

#[test]
fn the_robot_arm_composites_are_the_notes_products() {
    let arm = RobotArm {
        base: 30.0,
        lower: 25.0,
        upper: -60.0,
    };
    let figure = Figure {
        name: "arm".into(),
        pose: Pose::RobotArm(arm),
        translate: Vec3::ZERO,
    };
    let (objects, steps) = traverse(&figure, 0);
    let composites: Vec<Mat4> = steps
        .iter()
        .filter_map(|s| match s {
            Step::Visit { composite, .. } => Some(composite.matrix),
            _ => None,
        })
        .collect();
    let [hb, hl, _] = RobotArm::HEIGHTS;
    let r_b = rotate_y(30f32.to_radians());
    let m_lower = r_b * translate(Vec3::new(0.0, hb, 0.0)) * rotate_z(25f32.to_radians());
    let m_upper = m_lower * translate(Vec3::new(0.0, hl, 0.0)) * rotate_z((-60f32).to_radians());
    // M_base = R_b, M_lower = R_b·T_la·R_la, M_upper = R_b·T_la·R_la·T_ua·R_ua.
    assert!(close(&composites[0], &r_b));
    assert!(close(&composites[1], &m_lower));
    assert!(close(&composites[2], &m_upper));
    // Push before each child, pop after: base, push, lower, push, upper, pop, pop.
    let ops: Vec<&str> = steps
        .iter()
        .map(|s| match s {
            Step::Push { .. } => "push",
            Step::Visit { .. } => "visit",
            Step::Pop { .. } => "pop",
        })
        .collect();
    assert_eq!(
        ops,
        ["visit", "push", "visit", "push", "visit", "pop", "pop"]
    );
    // The lower arm's joint sits on top of the base: the composite takes (0,0,0) to (0, h_b, 0)
    // turned by the base's rotation about y (which leaves it where it is).
    let joint = composites[1].transform_point3(Vec3::ZERO);
    assert!((joint - Vec3::new(0.0, hb, 0.0)).length() < 1e-6);
    assert_eq!(objects.len(), 3);
}

#[test]
fn the_humanoid_is_traversed_depth_first_with_the_torso_restored_between_limbs() {
    let pose = Humanoid {
        torso: 10.0,
        left_upper_arm: 40.0,
        left_lower_arm: 30.0,
        ..Humanoid::default()
    };
    let figure = Figure {
        name: "h".into(),
        pose: Pose::Humanoid(pose),
        translate: Vec3::new(1.0, 2.0, 0.0),
    };
    let (_, steps) = traverse(&figure, 0);
    let visits: Vec<&str> = steps
        .iter()
        .filter_map(|s| match s {
            Step::Visit { node, .. } => Some(node.as_str()),
            _ => None,
        })
        .collect();
    assert_eq!(
        visits,
        [
            "torso",
            "head",
            "left arm upper",
            "left arm lower",
            "right arm upper",
            "right arm lower",
            "left leg upper",
            "left leg lower",
            "right leg upper",
            "right leg lower"
        ]
    );
    // Stack depth never goes below 0 and returns to 0.
    let mut depth = 0i32;
    for s in &steps {
        match s {
            Step::Push { .. } => depth += 1,
            Step::Pop { .. } => depth -= 1,
            Step::Visit { .. } => {}
        }
        assert!(depth >= 0);
    }
    assert_eq!(depth, 0);
    // The left lower arm's composite, by hand: T·R_torso·T_joint·Rx(40°)·T(0, −0.6, 0)·Rx(30°).
    let by_hand = translate(Vec3::new(1.0, 2.0, 0.0))
        * rotate_y(10f32.to_radians())
        * translate(Vec3::new(-0.45, 1.15, 0.0))
        * rotate_x(40f32.to_radians())
        * translate(Vec3::new(0.0, -0.6, 0.0))
        * rotate_x(30f32.to_radians());
    let lower = steps
        .iter()
        .find_map(|s| match s {
            Step::Visit {
                node, composite, ..
            } if node == "left arm lower" => Some(composite.matrix),
            _ => None,
        })
        .expect("visited");
    assert!(close(&lower, &by_hand));
}

/// Each visit names its figure, and a step about the humanoid finds the humanoid's root,
/// M(torso), even when the robot arm was traversed first.
#[test]
fn the_root_of_each_figure_is_found_by_its_name() {
    use pipeline::hierarchy::root_composite;
    let arm = Figure {
        name: "arm".into(),
        pose: Pose::RobotArm(RobotArm::default()),
        translate: Vec3::ZERO,
    };
    let body = Figure {
        name: "body".into(),
        pose: Pose::Humanoid(Humanoid {
            torso: 30.0,
            ..Humanoid::default()
        }),
        translate: Vec3::new(2.0, 0.0, 0.0),
    };
    let (parts, mut steps) = traverse(&arm, 0);
    steps.extend(traverse(&body, parts.len()).1);
    let (node, m) = root_composite(&steps, Some("body")).expect("the humanoid's root");
    assert_eq!(node, "torso");
    assert_eq!(m.name, "M(torso)");
    // The humanoid's own first composite, not the arm's base.
    let (_, alone) = traverse(&body, 0);
    let (_, torso) = root_composite(&alone, None).expect("a root");
    assert!(close(&m.matrix, &torso.matrix));
    let (_, base) = root_composite(&steps, None).expect("a root");
    assert!(!close(&m.matrix, &base.matrix));
    assert_eq!(root_composite(&steps, None).map(|(n, _)| n), Some("base"));
    assert_eq!(
        root_composite(&steps, Some("arm")).map(|(n, _)| n),
        Some("base")
    );
    assert!(root_composite(&steps, Some("nobody")).is_none());
}
