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
        check_lines(&text, shown)?;
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

/// Checks every line tobj will read, so that a mistake is reported with its line
/// (`file.obj:LINE: what is wrong`) rather than as tobj's "face vertex index out of bounds":
/// `v` needs three finite numbers (three more for a colour), `vt` one to three, `vn` three; a
/// face at least three vertices, each `v`, `v/t`, `v//n` or `v/t/n` with indices that are not 0
/// and name an existing `v`, `vt` or `vn` (negative ones count back from the last read, as the
/// format allows).
fn check_lines(text: &str, shown: &str) -> Result<(), MeshError> {
    let fail = |line: usize, reason: String| MeshError::Line {
        path: shown.to_owned(),
        line,
        reason,
    };
    // Positive indices may name any vertex of the file; negative ones count back from the
    // vertices read so far.
    let total = |k: &str| {
        text.lines()
            .filter(|l| l.split_whitespace().next() == Some(k))
            .count()
    };
    let totals = [total("v"), total("vt"), total("vn")];
    let (mut v, mut vt, mut vn) = (0usize, 0usize, 0usize);
    for (n, line) in text.lines().enumerate() {
        let line_no = n + 1;
        let mut words = line
            .split('#')
            .next()
            .unwrap_or_default()
            .split_whitespace();
        let Some(keyword) = words.next() else {
            continue;
        };
        let rest: Vec<&str> = words.collect();
        let numbers = |what: &str, allowed: &[usize]| -> Result<(), MeshError> {
            if !allowed.contains(&rest.len()) {
                return Err(fail(
                    line_no,
                    format!("`{keyword}` needs {what}, got {} number(s)", rest.len()),
                ));
            }
            for w in &rest {
                match w.parse::<f32>() {
                    Ok(x) if x.is_finite() => {}
                    Ok(_) => {
                        return Err(fail(line_no, format!("`{w}` is not a finite number")));
                    }
                    Err(_) => return Err(fail(line_no, format!("`{w}` is not a number"))),
                }
            }
            Ok(())
        };
        match keyword {
            "v" => {
                numbers(
                    "three numbers x y z (then w, or r g b for a colour)",
                    &[3, 4, 6, 7],
                )?;
                v += 1;
            }
            "vt" => {
                numbers("one to three numbers u v w", &[1, 2, 3])?;
                vt += 1;
            }
            "vn" => {
                numbers("three numbers x y z", &[3])?;
                vn += 1;
            }
            "f" => check_face(&rest, totals, [v, vt, vn]).map_err(|r| fail(line_no, r))?,
            _ => {}
        }
    }
    Ok(())
}

/// One face's corners: at least three, each index a whole number, not 0, naming a `v`, `vt`
/// or `vn` that exists (`totals` in the file; `sofar`, read before this line, for negative
/// ones, which count back).
fn check_face(rest: &[&str], totals: [usize; 3], sofar: [usize; 3]) -> Result<(), String> {
    if rest.len() < 3 {
        return Err(format!(
            "a face needs at least three vertices, got {}",
            rest.len()
        ));
    }
    let big = |c: usize| i64::try_from(c).unwrap_or(i64::MAX);
    for corner in rest {
        for (k, (index, what)) in corner.split('/').zip(["v", "vt", "vn"]).enumerate() {
            if index.is_empty() && k > 0 {
                continue;
            }
            let Ok(i) = index.parse::<i64>() else {
                return Err(format!(
                    "`{corner}`: `{index}` is not a whole number (a face lists v, v/t, v//n or v/t/n)"
                ));
            };
            if i == 0 {
                return Err(format!("`{corner}`: index 0, but OBJ indices start at 1"));
            }
            if i > big(totals[k]) {
                return Err(format!(
                    "`{corner}`: {what} index {i}, but the file has {} `{what}` line(s)",
                    totals[k]
                ));
            }
            if -i > big(sofar[k]) {
                return Err(format!(
                    "`{corner}`: {what} index {i} counts back past the first: only {} `{what}` line(s) come before it",
                    sofar[k]
                ));
            }
        }
    }
    Ok(())
}
