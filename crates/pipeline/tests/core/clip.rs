//! Clipping in homogeneous coordinates.

use glam::{Vec3, Vec4};
use pipeline::clip::{ClipOutcome, ClipPlane, ClipVertex, clip_triangle};

fn tri(p: [Vec4; 3]) -> [ClipVertex; 3] {
    let corners = [Vec3::X, Vec3::Y, Vec3::Z];
    [0, 1, 2].map(|k| ClipVertex {
        clip: p[k],
        bary: corners[k],
    })
}

#[test]
fn inside_outside_and_on_the_plane() {
    let inside = tri([
        Vec4::new(0.0, 0.0, 0.0, 1.0),
        Vec4::new(0.5, 0.0, 0.0, 1.0),
        Vec4::new(0.0, 0.5, 0.0, 1.0),
    ]);
    assert_eq!(clip_triangle(inside), ClipOutcome::Inside);
    // A vertex exactly on the near plane (z = −w) counts as inside.
    let on_near = tri([
        Vec4::new(0.0, 0.0, -1.0, 1.0),
        Vec4::new(0.5, 0.0, 0.0, 1.0),
        Vec4::new(0.0, 0.5, 0.0, 1.0),
    ]);
    assert_eq!(clip_triangle(on_near), ClipOutcome::Inside);
    // All behind the eye: eye points (0,0,2), (1,0,2), (0,1,3) through Frustum with near 1,
    // far 10 (α = −11/9, β = −20/9): w = −z_e < 0 and z_c = α·z_e + β; the near plane is the
    // first of the planes they are all outside of.
    let (alpha, beta) = (-11.0 / 9.0, -20.0 / 9.0);
    let c = |x: f32, y: f32, ze: f32| Vec4::new(x, y, alpha * ze + beta, -ze);
    let behind = tri([c(0.0, 0.0, 2.0), c(1.0, 0.0, 2.0), c(0.0, 1.0, 3.0)]);
    assert_eq!(clip_triangle(behind), ClipOutcome::Outside(ClipPlane::Near));
    let right = tri([
        Vec4::new(2.0, 0.0, 0.0, 1.0),
        Vec4::new(3.0, 0.0, 0.0, 1.0),
        Vec4::new(2.0, 1.0, 0.0, 1.0),
    ]);
    assert_eq!(clip_triangle(right), ClipOutcome::Outside(ClipPlane::Right));
}

#[test]
fn the_near_plane_cut_by_hand() {
    // Edge from (0,0,−2,1) [z < −w: outside near] to (0,0,0,1): the crossing is where
    // w + z = 0 → t = d_a/(d_a − d_b) from the inside end.
    let t = tri([
        Vec4::new(0.0, 0.0, -2.0, 1.0),
        Vec4::new(0.5, 0.0, 0.0, 1.0),
        Vec4::new(0.0, 0.5, 0.0, 1.0),
    ]);
    let ClipOutcome::Clipped(poly) = clip_triangle(t) else {
        panic!("expected a clipped polygon");
    };
    // Two vertices inside plus two crossings: a quad.
    assert_eq!(poly.len(), 4);
    for v in &poly {
        assert!(
            (v.clip.w + v.clip.z) >= -1e-6,
            "{v:?} outside the near plane"
        );
        // The barycentric weights still describe the same clip-space point.
        let p = t[0].clip * v.bary.x + t[1].clip * v.bary.y + t[2].clip * v.bary.z;
        assert!((p - v.clip).abs().max_element() < 1e-6);
    }
    // The crossing on edge 0→1: a = (0,0,−2,1), b = (0.5,0,0,1), d_a = −1, d_b = 1 → t = ½ from b.
    assert!(
        poly.iter()
            .any(|v| (v.clip - Vec4::new(0.25, 0.0, -1.0, 1.0)).length() < 1e-6)
    );
}

#[test]
fn clipping_never_leaves_the_view_volume() {
    let mut rng = fastrand::Rng::with_seed(5);
    let mut clipped = 0;
    for _ in 0..5000 {
        let mut r = || {
            Vec4::new(
                rng.f32() * 8.0 - 4.0,
                rng.f32() * 8.0 - 4.0,
                rng.f32() * 8.0 - 4.0,
                rng.f32() * 6.0 - 2.0,
            )
        };
        let t = tri([r(), r(), r()]);
        if let ClipOutcome::Clipped(poly) = clip_triangle(t) {
            clipped += 1;
            assert!(poly.len() >= 3 && poly.len() <= 10);
            for v in &poly {
                let c = v.clip;
                let tol = 1e-4 * c.w.abs().max(1.0);
                assert!(c.w > 0.0, "w ≤ 0 after clipping: {c}");
                for d in [
                    c.w + c.x,
                    c.w - c.x,
                    c.w + c.y,
                    c.w - c.y,
                    c.w + c.z,
                    c.w - c.z,
                ] {
                    assert!(d >= -tol, "{c} outside the volume");
                }
                assert!((v.bary.x + v.bary.y + v.bary.z - 1.0).abs() < 1e-4);
            }
        }
    }
    assert!(
        clipped > 500,
        "the random triangles exercise the clipper ({clipped})"
    );
}

/// A segment running from in front of the camera (w = 3) to behind it (w = −1) keeps the part
/// in front: its end behind moves to w = ε, three quarters of the way along, where the other
/// coordinates are interpolated alike (x from 2 to −2 gives 2 − 4·¾ = −1); a segment wholly
/// behind is dropped, and one wholly in front is kept as it is.
#[test]
fn a_segment_keeps_its_part_in_front_of_the_camera() {
    use pipeline::clip::{W_EPSILON, segment_in_front};
    let (front, behind) = (
        Vec4::new(2.0, 1.0, 0.0, 3.0),
        Vec4::new(-2.0, 1.0, 0.0, -1.0),
    );
    for (a, b) in [(front, behind), (behind, front)] {
        let (p, q) = segment_in_front(a, b).expect("half of it is in front");
        let (kept, cut) = if a == front { (p, q) } else { (q, p) };
        assert_eq!(kept, front);
        assert!(cut.w > W_EPSILON && cut.w < 2.0 * W_EPSILON, "{cut}");
        assert!(
            (cut.x + 1.0).abs() < 1e-4 && (cut.y - 1.0).abs() < 1e-6,
            "{cut}"
        );
    }
    assert_eq!(segment_in_front(behind, behind * 2.0), None);
    assert_eq!(
        segment_in_front(front, front * 2.0),
        Some((front, front * 2.0))
    );
}
