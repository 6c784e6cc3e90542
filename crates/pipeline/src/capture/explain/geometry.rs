//! The geometry of the derivation: the vertices through clip space, NDC and window coordinates,
//! the edge functions and the inside test, the weights, depth and interpolated attributes.

use glam::Vec3;

use super::{Lines, Owner, Remark, Section, n, n64, pt, v3, v4};
use crate::capture::{EdgeTest, FrameCapture};
use crate::raster::RasterTriangle;
use crate::vertex::VertexRecord;

impl FrameCapture {
    /// clip → NDC → window for the three vertices.
    pub(super) fn explain_vertices(
        &self,
        vertices: &[VertexRecord; 3],
        clipped: bool,
        lines: &mut Lines,
    ) {
        let (w, h) = (self.width() as f32, self.height() as f32);
        for (k, v) in vertices.iter().enumerate() {
            lines.add(
                Section::Vertices,
                &format!("clip_{k} = P·V·M·p_{k}"),
                format!("P·V·M·{}", v4(v.object_pos)),
                v4(v.clip),
            );
            match (v.ndc, v.window) {
                (Some(ndc), Some(win)) => {
                    lines.add(
                        Section::Vertices,
                        &format!("ndc_{k} = (x_c, y_c, z_c)/w_c"),
                        format!(
                            "({}, {}, {})/{}",
                            n(v.clip.x),
                            n(v.clip.y),
                            n(v.clip.z),
                            n(v.clip.w)
                        ),
                        v3(ndc),
                    );
                    lines.add(
                        Section::Vertices,
                        &format!("win_{k} = ((x+1)·W/2, (y+1)·H/2, (z+1)/2)"),
                        format!(
                            "(({}+1)·{}/2, ({}+1)·{}/2, ({}+1)/2)",
                            n(ndc.x),
                            n(w),
                            n(ndc.y),
                            n(h),
                            n(ndc.z)
                        ),
                        v3(win),
                    );
                }
                _ => {
                    lines.add(
                        Section::Vertices,
                        &format!("w_{k} ≤ 0"),
                        format!("w_{k} = {}", n(v.clip.w)),
                        String::new(),
                    );
                    lines.note(Remark::BehindEye);
                }
            }
        }
        if clipped {
            lines.add(
                Section::Vertices,
                "−w ≤ x, y, z ≤ w ?",
                String::new(),
                String::new(),
            );
            lines.note(Remark::Clipped);
        }
    }
}

/// The edge functions at the centre, the inside test with its ties, and λ.
pub(super) fn explain_edges(e: &EdgeTest, corner_vertex: &[Option<usize>; 3], lines: &mut Lines) {
    let s = Section::Rasterization;
    // v_k: vertex k of the triangle; c_k: a corner clipping made.
    let names: Vec<String> = corner_vertex
        .iter()
        .enumerate()
        .map(|(k, v)| v.map_or_else(|| format!("c_{k}"), |j| format!("v_{j}")))
        .collect();
    lines.add(
        s,
        "a_0, a_1, a_2",
        format!(
            "{} = {}, {} = {}, {} = {}",
            names[0],
            pt(e.corners[0]),
            names[1],
            pt(e.corners[1]),
            names[2],
            pt(e.corners[2])
        ),
        String::new(),
    );
    lines.note(Remark::Corners);
    let centre = e.centre_position;
    lines.add(s, "p = (x + 1/2, y + 1/2)", String::new(), pt(centre));
    lines.note(Remark::PixelCentre);
    for k in 0..3 {
        let (a, b) = (e.corners[(k + 1) % 3], e.corners[(k + 2) % 3]);
        lines.add(
            s,
            &format!(
                "E_{k} = (a_{} − a_{}) × (p − a_{})",
                (k + 2) % 3,
                (k + 1) % 3,
                (k + 1) % 3
            ),
            format!(
                "({} − {})·({} − {}) − ({} − {})·({} − {})",
                n64(b[0]),
                n64(a[0]),
                n64(centre[1]),
                n64(a[1]),
                n64(b[1]),
                n64(a[1]),
                n64(centre[0]),
                n64(a[0])
            ),
            n64(e.centre[k]),
        );
        lines.note(Remark::EdgeOpposite { edge: k });
    }
    explain_samples(e, lines);
    lines.add(
        s,
        "λ_k = E_k/(E_0 + E_1 + E_2)",
        format!(
            "({}, {}, {})/{}",
            n64(e.centre[0]),
            n64(e.centre[1]),
            n64(e.centre[2]),
            n64(e.area2)
        ),
        format!(
            "({}, {}, {})",
            n64(e.lambda[0]),
            n64(e.lambda[1]),
            n64(e.lambda[2])
        ),
    );
}

/// Depth and the barycentric weights of the primitive's vertices.
pub(super) fn explain_weights(
    tri: &RasterTriangle,
    lambda: Vec3,
    pc: bool,
    b: Vec3,
    depth: f32,
    lines: &mut Lines,
) {
    let s = Section::Interpolation;
    let z = tri.window.map(|w| w.z);
    lines.add(
        s,
        "z_w = Σ_k λ_k·z_k",
        format!(
            "{}·{} + {}·{} + {}·{}",
            n(lambda.x),
            n(z[0]),
            n(lambda.y),
            n(z[1]),
            n(lambda.z),
            n(z[2])
        ),
        n(depth),
    );
    lines.note(Remark::ScreenLinear);
    if pc {
        let w = tri.inv_w;
        lines.add(
            s,
            "b_k = (λ_k/w_k)/Σ_j (λ_j/w_j)",
            format!("1/w = ({}, {}, {})", n(w[0]), n(w[1]), n(w[2])),
            v3(b),
        );
        lines.note(Remark::PerspectiveCorrect);
    } else {
        lines.add(s, "b_k = λ_k", String::new(), v3(b));
        lines.note(Remark::Affine);
    }
}

/// The surface point, the normal and (untextured) the colour at the centre.
pub(super) fn explain_attributes(o: &Owner<'_>, vertex_color: Vec3, lines: &mut Lines) {
    let s = Section::Interpolation;
    lines.add(s, "p = Σ_k b_k·p_k", String::new(), v3(o.position));
    let normals = o.vertices.map(|v| v.normal_world);
    lines.add(
        s,
        "n = normalize(Σ_k b_k·n_k)",
        format!(
            "n_k = {}, {}, {}",
            v3(normals[0]),
            v3(normals[1]),
            v3(normals[2])
        ),
        v3(o.normal),
    );
    if o.object.texture.is_none() {
        let c = o.vertices.map(|v| v.color);
        lines.add(
            s,
            "c = Σ_k b_k·c_k",
            format!(
                "{}·{} + {}·{} + {}·{}",
                n(o.b.x),
                v3(c[0]),
                n(o.b.y),
                v3(c[1]),
                n(o.b.z),
                v3(c[2])
            ),
            v3(vertex_color),
        );
    }
}

/// The inside test at each sample, with the fill rule's decision where a sample lies on an edge.
fn explain_samples(e: &EdgeTest, lines: &mut Lines) {
    let s = Section::Rasterization;
    for (j, q) in e.samples.iter().enumerate() {
        lines.add(
            s,
            &format!("s_{j} = {}: E_0, E_1, E_2 ≥ 0 ?", pt(q.position)),
            format!("E = ({}, {}, {})", n64(q.e[0]), n64(q.e[1]), n64(q.e[2])),
            if q.inside { "√" } else { "×" }.to_owned(),
        );
        lines.note(Remark::Sample {
            index: j,
            inside: q.inside,
        });
        for &k in &q.on_edges {
            lines.note(Remark::OnEdge {
                edge: k,
                top_left: e.top_left[k],
            });
        }
    }
}
