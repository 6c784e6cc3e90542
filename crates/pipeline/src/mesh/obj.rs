//! Wavefront OBJ files, read with `tobj`: polygons triangulated, normals and texture coordinates
//! kept when the file has them, vertex colours written as `v x y z r g b` kept.

use std::path::Path;

use glam::{Vec2, Vec3};

use super::{Mesh, MeshError, NormalAveraging};

impl Mesh {
    /// Loads a Wavefront OBJ file, triangulating polygons. Normals and texture coordinates are
    /// kept when the file has them; missing normals are computed with the notes' plain average.
    /// Vertex colours written as `v x y z r g b` are kept.
    ///
    /// # Errors
    /// A [`MeshError`] naming the file and what is wrong with it.
    pub fn load_obj(path: &Path) -> Result<Mesh, MeshError> {
        let shown = path.display().to_string();
        let file = std::fs::File::open(path).map_err(|e| MeshError::Obj {
            path: shown.clone(),
            reason: format!("cannot open it: {e}"),
        })?;
        let name = path
            .file_name()
            .map_or_else(|| shown.clone(), |n| n.to_string_lossy().into_owned());
        Self::parse_obj(&mut std::io::BufReader::new(file), &shown, &name)
    }

    /// Reads OBJ text from `reader` as [`Self::load_obj`] does; `shown` names it in errors.
    ///
    /// # Errors
    /// A [`MeshError`] naming `shown` and what is wrong.
    pub fn parse_obj(
        reader: &mut impl std::io::Read,
        shown: &str,
        name: &str,
    ) -> Result<Mesh, MeshError> {
        let options = tobj::LoadOptions {
            triangulate: true,
            single_index: true,
            ignore_points: true,
            ignore_lines: true,
        };
        let mut text = String::new();
        reader
            .read_to_string(&mut text)
            .map_err(|e| MeshError::Obj {
                path: shown.to_owned(),
                reason: format!("cannot read it as text: {e}"),
            })?;
        check_face_sizes(&text, shown)?;
        // Materials are not used: a missing .mtl file is no error.
        let (models, _materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| {
            Ok((Vec::new(), Default::default()))
        })
        .map_err(|e| MeshError::Obj {
            path: shown.to_owned(),
            reason: e.to_string(),
        })?;
        let mut mesh = Mesh {
            name: name.to_owned(),
            ..Mesh::default()
        };
        let mut has_normals = true;
        let mut has_uvs = true;
        let mut has_colors = true;
        for model in &models {
            let m = &model.mesh;
            let base = u32::try_from(mesh.positions.len()).unwrap_or(u32::MAX);
            let count = m.positions.len() / 3;
            mesh.positions.extend(
                m.positions
                    .chunks_exact(3)
                    .map(|p| Vec3::new(p[0], p[1], p[2])),
            );
            has_normals &= m.normals.len() == m.positions.len();
            has_uvs &= m.texcoords.len() / 2 == count;
            has_colors &= m.vertex_color.len() == m.positions.len();
            if has_normals {
                mesh.normals.extend(
                    m.normals
                        .chunks_exact(3)
                        .map(|n| Vec3::new(n[0], n[1], n[2])),
                );
            }
            if has_uvs {
                mesh.uvs
                    .extend(m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
            }
            if has_colors {
                mesh.colors.extend(
                    m.vertex_color
                        .chunks_exact(3)
                        .map(|c| Vec3::new(c[0], c[1], c[2])),
                );
            }
            mesh.indices.extend(
                m.indices
                    .chunks_exact(3)
                    .map(|f| [base + f[0], base + f[1], base + f[2]]),
            );
        }
        check_loaded(&mesh, shown)?;
        if !has_uvs {
            mesh.uvs.clear();
        }
        if !has_colors {
            mesh.colors.clear();
        }
        if has_normals && mesh.normals.iter().all(|n| n.is_finite()) {
            for n in &mut mesh.normals {
                *n = n.try_normalize().unwrap_or(Vec3::Z);
            }
        } else {
            mesh.compute_vertex_normals(NormalAveraging::Plain);
        }
        Ok(mesh)
    }
}

/// A loaded mesh has faces, indices in range and finite positions.
fn check_loaded(mesh: &Mesh, shown: &str) -> Result<(), MeshError> {
    if mesh.indices.is_empty() {
        return Err(MeshError::NoFaces {
            path: shown.to_owned(),
        });
    }
    let count = mesh.positions.len();
    for (face, tri) in mesh.indices.iter().enumerate() {
        if let Some(&index) = tri.iter().find(|&&i| i as usize >= count) {
            return Err(MeshError::IndexOutOfRange {
                path: shown.to_owned(),
                face,
                index,
                count,
            });
        }
    }
    if let Some((vertex, &value)) = mesh
        .positions
        .iter()
        .enumerate()
        .find(|(_, p)| !p.is_finite())
    {
        return Err(MeshError::NotFinite {
            path: shown.to_owned(),
            vertex,
            value,
        });
    }
    Ok(())
}

/// tobj drops a face of fewer than three vertices without a word: name it, with its line.
fn check_face_sizes(text: &str, shown: &str) -> Result<(), MeshError> {
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        if words.next() == Some("f") {
            let count = words.count();
            if count < 3 {
                return Err(MeshError::Obj {
                    path: shown.to_owned(),
                    reason: format!(
                        "line {}: a face needs at least three vertices, got {count}",
                        n + 1
                    ),
                });
            }
        }
    }
    Ok(())
}
