//! The projection as the course names it: switching between its kinds.

/// Switching a projection's kind keeps its view volume as near as the new kind can; each value
/// below worked out by hand from the rule in `Projection::with_kind`.
#[test]
fn switching_the_projection_kind_keeps_the_view_volume() {
    use pipeline::camera::{Projection, ProjectionKind as K};
    let close = |a: Projection, b: Projection| {
        let (x, y) = (a.bounds(2.0), b.bounds(2.0));
        assert!(
            x.iter().zip(y).all(|(p, q)| (p - q).abs() < 1e-5) && a.kind() == b.kind(),
            "{a:?} != {b:?}"
        );
    };
    // fovy 90°, the viewport's aspect 2, near 1: the near rectangle is t = 1·tan 45° = 1, r = 2.
    let wide = Projection::Perspective {
        fovy_deg: 90.0,
        aspect: None,
        near: 1.0,
        far: 10.0,
    };
    let frustum = Projection::Frustum {
        left: -2.0,
        right: 2.0,
        bottom: -1.0,
        top: 1.0,
        near: 1.0,
        far: 10.0,
    };
    close(wide.with_kind(K::Frustum, 2.0, 5.0), frustum);
    // Ortho: the cross-section at the focus, 5 away: the rectangle × 5/1.
    let ortho = Projection::Ortho {
        left: -10.0,
        right: 10.0,
        bottom: -5.0,
        top: 5.0,
        near: 1.0,
        far: 10.0,
    };
    close(wide.with_kind(K::Ortho, 2.0, 5.0), ortho);
    close(frustum.with_kind(K::Ortho, 2.0, 5.0), ortho);
    // And back: the same perspective, its aspect (the viewport's) left unset.
    let back = ortho.with_kind(K::Perspective, 2.0, 5.0);
    close(back, wide);
    assert!(
        matches!(back, Projection::Perspective { aspect: None, .. }),
        "{back:?}"
    );
    // An off-centre frustum becomes the centred perspective of its size: fovy = 2·atan(1/2)
    // = 53.130°, aspect 1.3/1 = 1.3, pinned (it is not the viewport's).
    let off = Projection::Frustum {
        left: -0.3,
        right: 1.0,
        bottom: -0.5,
        top: 0.5,
        near: 1.0,
        far: 10.0,
    };
    let Projection::Perspective {
        fovy_deg, aspect, ..
    } = off.with_kind(K::Perspective, 2.0, 5.0)
    else {
        panic!("a perspective");
    };
    assert!((fovy_deg - 53.130_1).abs() < 1e-3, "{fovy_deg}");
    assert!(aspect.is_some_and(|a| (a - 1.3).abs() < 1e-6), "{aspect:?}");
    // An ortho box whose near face is behind the eye: near becomes focus/10 = 0.5, and the
    // rectangle there is the box × 0.5/5.
    let behind = Projection::Ortho {
        left: -4.0,
        right: 4.0,
        bottom: -2.0,
        top: 2.0,
        near: -1.0,
        far: 10.0,
    };
    close(
        behind.with_kind(K::Frustum, 2.0, 5.0),
        Projection::Frustum {
            left: -0.4,
            right: 0.4,
            bottom: -0.2,
            top: 0.2,
            near: 0.5,
            far: 10.0,
        },
    );
    // The same kind: unchanged.
    assert_eq!(wide.with_kind(K::Perspective, 2.0, 5.0), wide);
}
