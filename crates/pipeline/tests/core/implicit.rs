//! Implicit surfaces: the distance functions, their combinations, polygonizing and point clouds.

use glam::Vec3;
use pipeline::mesh::implicit::{Implicit, ImplicitShape, smooth_min};

fn surface(shape: ImplicitShape, resolution: u32, points: u32) -> Implicit {
    Implicit {
        shape,
        gap: 0.8,
        smooth: 0.4,
        resolution,
        points,
    }
}

/// f is a signed distance: the sphere's value at a point is its distance to the surface, with
/// the sign of the inside test (lesson 21's answer: (0.5, 0.5, 0.5) is 0.066 outside).
#[test]
fn the_sign_of_f_is_the_inside_test() {
    let s = surface(ImplicitShape::Sphere, 16, 0);
    assert!((s.f(Vec3::splat(0.5)) - (0.75f32.sqrt() - 0.8)).abs() < 1e-6);
    assert!(s.f(Vec3::ZERO) < 0.0 && s.f(Vec3::X * 2.0) > 0.0);
    // Lesson 21's CSG answer at p = (0.1, 0, 0) with gap 0.8: a = −0.2, b = −0.25.
    let p = Vec3::new(0.1, 0.0, 0.0);
    let value = |shape| surface(shape, 16, 0).f(p);
    assert!((value(ImplicitShape::Union) + 0.25).abs() < 1e-6);
    assert!((value(ImplicitShape::Intersection) + 0.2).abs() < 1e-6);
    assert!((value(ImplicitShape::Difference) - 0.25).abs() < 1e-6);
}

/// The smooth minimum is the minimum where the two differ by more than k, and k/4 below it
/// where they are equal (lesson 21: the neck forms at gap 1.4 for radius 0.6 and k = 0.4).
#[test]
fn the_smooth_minimum_rounds_only_near_the_crease() {
    assert_eq!(smooth_min(0.1, 0.9, 0.4), 0.1);
    assert!((smooth_min(0.3, 0.3, 0.4) - 0.2).abs() < 1e-6);
    assert_eq!(smooth_min(0.3, 0.5, 0.0), 0.3);
    let blend = |gap: f32| Implicit {
        gap,
        ..surface(ImplicitShape::Blend, 16, 0)
    };
    assert!(blend(1.39).f(Vec3::ZERO) < 0.0, "joined just below 1.4");
    assert!(blend(1.41).f(Vec3::ZERO) > 0.0, "apart just above 1.4");
}

/// Polygonized, the sphere's vertices lie on it to within a cell, every triangle is wound
/// counter-clockwise seen from outside and its vertex normals point outwards; more cells, more
/// triangles, closer to the surface.
#[test]
fn a_polygonized_sphere_is_closed_outward_and_converges() {
    let coarse = surface(ImplicitShape::Sphere, 12, 0).build();
    let fine = surface(ImplicitShape::Sphere, 48, 0).build();
    assert!(fine.indices.len() > 10 * coarse.indices.len());
    for (m, cell) in [(&coarse, 3.4 / 12.0), (&fine, 3.4 / 48.0)] {
        assert!(!m.indices.is_empty());
        for p in &m.positions {
            assert!((p.length() - 0.8).abs() < cell, "{p} off the sphere");
        }
        for t in &m.indices {
            let [a, b, c] = t.map(|i| m.positions[i as usize]);
            let centre = (a + b + c) / 3.0;
            assert!((b - a).cross(c - a).dot(centre) > 0.0, "wound outward");
        }
        for (p, n) in m.positions.iter().zip(&m.normals) {
            assert!(n.dot(p.normalize()) > 0.99, "the normal of the sphere");
        }
        // Closed: every edge is shared by exactly two triangles.
        let mut edges = std::collections::HashMap::new();
        for t in &m.indices {
            for k in 0..3 {
                let (i, j) = (t[k], t[(k + 1) % 3]);
                *edges.entry((i.min(j), i.max(j))).or_insert(0) += 1;
            }
        }
        assert!(edges.values().all(|&n| n == 2), "a closed surface");
    }
}

/// A point cloud has the number of points asked for, every one on the surface.
#[test]
fn a_point_cloud_lies_on_the_surface() {
    let s = surface(ImplicitShape::Torus, 8, 500);
    let m = s.build();
    assert_eq!(
        m.positions.len(),
        500 * 8,
        "a small cube of 8 corners per point"
    );
    for dot in m.positions.chunks(8) {
        let centre = dot.iter().copied().sum::<Vec3>() / 8.0;
        assert!(s.f(centre).abs() < 2e-3, "{centre} is on the torus");
    }
}
