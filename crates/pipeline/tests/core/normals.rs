//! Vertex normals as the notes define them: the average of the normals of the faces around the
//! vertex, around its position even where a uv seam splits it.

use glam::Vec3;
use pipeline::mesh::{Mesh, NormalAveraging};

/// A gable: two triangles meeting at the apex (0, 1, 0), the front one tilted towards +z, the
/// back one towards −z. Each has its own texture coordinates, so the apex is on a uv seam and
/// the OBJ reader splits it in two.
const GABLE: &str = "\
v 0 1 0
v -1 0 1
v 1 0 1
v 1 0 -1
v -1 0 -1
vt 0.5 1
vt 0 0
vt 1 0
vt 0.5 0.4
f 2/2 3/3 1/1
f 4/2 5/3 1/4
";

#[test]
fn a_uv_seam_does_not_crease_the_averaged_normals() {
    let mesh = Mesh::parse_obj(&mut GABLE.as_bytes(), "gable.obj", "gable").expect("parses");
    let apex: Vec<usize> = (0..mesh.positions.len())
        .filter(|&i| mesh.positions[i] == Vec3::Y)
        .collect();
    assert_eq!(apex.len(), 2, "the seam splits the apex");
    // The faces' unit normals are (0, 1, 1)/√2 and (0, 1, −1)/√2: their average is +y, for
    // both copies (without welding each copy would keep its own face's normal: a crease).
    for i in apex {
        assert!(
            (mesh.normals[i] - Vec3::Y).length() < 1e-6,
            "apex copy {i}: {}",
            mesh.normals[i]
        );
    }
    // The other corners belong to one face each and keep its normal.
    for (i, p) in mesh
        .positions
        .iter()
        .enumerate()
        .filter(|(_, p)| p.y == 0.0)
    {
        let face = Vec3::new(0.0, 1.0, p.z.signum()).normalize();
        assert!((mesh.normals[i] - face).length() < 1e-6, "corner {i}");
    }
}

/// At the corner of a big and a small face, the plain average (the notes) treats them alike;
/// the area-weighted one leans towards the big face, by hand:
/// big (area 2) along +y, small (area 0.5) along +x: (0.5, 2, 0)/|…| against (1, 1, 0)/√2.
#[test]
fn plain_and_area_weighted_averages_differ_as_computed_by_hand() {
    let mut mesh = Mesh {
        name: "corner".into(),
        positions: vec![
            Vec3::ZERO,
            Vec3::new(0.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        ],
        indices: vec![[0, 1, 2], [0, 3, 4]],
        ..Mesh::default()
    };
    mesh.compute_vertex_normals(NormalAveraging::Plain);
    let plain = Vec3::new(1.0, 1.0, 0.0).normalize();
    assert!(
        (mesh.normals[0] - plain).length() < 1e-6,
        "{}",
        mesh.normals[0]
    );
    mesh.compute_vertex_normals(NormalAveraging::AreaWeighted);
    let weighted = Vec3::new(0.5, 2.0, 0.0).normalize();
    assert!(
        (mesh.normals[0] - weighted).length() < 1e-6,
        "{}",
        mesh.normals[0]
    );
}

/// The built-in shapes close their seams exactly (the last column of a sphere, a cylinder or a
/// torus at the very positions of the first, the sphere's poles one point each), so normals
/// averaged from their faces agree wherever two vertices share a position.
#[test]
fn built_in_shapes_close_their_seams_so_averaged_normals_agree() {
    use pipeline::mesh::{BuiltinMesh, NormalAveraging};
    for shape in [
        BuiltinMesh::UvSphere {
            segments: 12,
            rings: 6,
        },
        BuiltinMesh::Cylinder { segments: 9 },
        BuiltinMesh::Torus {
            minor: 0.35,
            segments: 10,
            sides: 7,
        },
    ] {
        let mut mesh = shape.build();
        for averaging in [NormalAveraging::Plain, NormalAveraging::AreaWeighted] {
            mesh.compute_vertex_normals(averaging);
            let mut seams = 0;
            for i in 0..mesh.positions.len() {
                for j in i + 1..mesh.positions.len() {
                    if (mesh.positions[i] - mesh.positions[j]).length() < 1e-5 {
                        assert_eq!(
                            mesh.positions[i], mesh.positions[j],
                            "{}: vertices {i} and {j} almost meet",
                            mesh.name
                        );
                        assert_eq!(mesh.normals[i], mesh.normals[j], "{}", mesh.name);
                        seams += 1;
                    }
                }
            }
            assert!(seams > 0, "{} has a seam", mesh.name);
        }
    }
}
