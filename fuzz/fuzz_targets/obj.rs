//! The OBJ loader on arbitrary bytes: never a panic; a mesh it accepts has indices in range and
//! finite positions.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut reader = data;
    if let Ok(mesh) = pipeline::mesh::Mesh::parse_obj(&mut reader, "fuzz.obj", "fuzz.obj") {
        let n = mesh.positions.len() as u32;
        assert!(mesh.indices.iter().flatten().all(|&i| i < n));
        assert!(mesh.positions.iter().all(|p| p.is_finite()));
        assert!(mesh.normals.is_empty() || mesh.normals.len() == mesh.positions.len());
    }
});
