//! Where the student's inside or depth test first parts from pipelens' at the first wrong
//! pixel, sample by sample: the sample, the triangle's three edge values there and which edges
//! are top or left ones, both verdicts (the inside test); the fragment's depth, the depth
//! stored, both verdicts (the depth test). What the lab is about, named at the place it
//! differs.

use glam::I64Vec2;
use pipeline::capture::FrameCapture;
use pipeline::raster::ONE;
use pipeline::scene::Scene;
use pipeline::shader::HookKind;

use crate::vocabulary::Lang;

/// A sample where the student's function and pipelens' rule disagree.
#[derive(Clone, Debug, PartialEq)]
pub enum SampleMismatch {
    /// The inside test.
    Inside {
        /// The pixel, in window coordinates.
        pixel: (u32, u32),
        /// The triangle, numbered as the Inspector numbers it (its primitive: a clipped
        /// triangle's pieces are one).
        triangle: u32,
        /// The sample's position, window pixels.
        position: [f64; 2],
        /// `(E_0, E_1, E_2)` there, square pixels (edge `i` opposite corner `i`).
        e: [f64; 3],
        /// Which edges are top or left edges.
        top_left: [bool; 3],
        /// Whether pipelens counts the sample inside.
        theirs: bool,
        /// Whether the student's `inside` does.
        yours: bool,
    },
    /// The depth test.
    Depth {
        /// The pixel, in window coordinates.
        pixel: (u32, u32),
        /// The sample (from 0).
        sample: usize,
        /// The triangle whose fragment is tested, numbered as the Inspector numbers it.
        triangle: u32,
        /// Its window depth at the sample.
        z: f32,
        /// What the z-buffer holds there before it (pipelens' run).
        stored: f32,
        /// Whether pipelens writes the fragment.
        theirs: bool,
        /// Whether the student's `depth_test` does.
        yours: bool,
    },
}

/// The first sample of pixel `(x, y)` of `reference` (pipelens' own frame of the same
/// geometry) where the student's inside or depth test in `scene` answers otherwise than
/// pipelens' rule: the triangles in drawing order, each one's samples in order.
#[must_use]
pub fn first_sample_mismatch(
    scene: &Scene,
    reference: &FrameCapture,
    (x, y): (u32, u32),
) -> Option<SampleMismatch> {
    let offsets = pipeline::raster::sample_offsets_fixed(reference.settings.samples);
    let corner = I64Vec2::new(i64::from(x) * ONE, i64::from(y) * ONE);
    let pixels = |v: i64| v as f64 / ONE as f64;
    let square = (ONE * ONE) as f64;
    let test = reference.settings.depth_test;
    let mut stored = vec![test.clear_value(); offsets.len()];
    let (inside, depth_test) = (
        scene.hook(HookKind::Inside),
        scene.hook(HookKind::DepthTest),
    );
    for tri in &reference.triangles {
        let [x0, y0, x1, y1] = tri.bbox.map(u32::from);
        if x < x0 || x > x1 || y < y0 || y > y1 {
            continue;
        }
        // The corners as the rasterizer hands them to the student's inside test: snapped.
        let corners = tri.window.map(|c| {
            let f = pipeline::raster::snap_xy(c);
            [pixels(f.x) as f32, pixels(f.y) as f32]
        });
        for (s, off) in offsets.iter().enumerate() {
            let p = corner + *off;
            let covered = tri.covers(p);
            if let Some(hook) = inside {
                let position = [pixels(p.x), pixels(p.y)];
                let yours = hook
                    .covers(&[[position[0] as f32, position[1] as f32]], corners)
                    .ok()?
                    .first()
                    .copied()?;
                if yours != covered {
                    return Some(SampleMismatch::Inside {
                        pixel: (x, y),
                        triangle: tri.primitive,
                        position,
                        e: tri.edge_values(p).map(|e| e as f64 / square),
                        top_left: tri.top_left(),
                        theirs: covered,
                        yours,
                    });
                }
            }
            if !covered {
                continue;
            }
            let z = tri.depth_at(p);
            let theirs = test.passes(z, stored[s]);
            if let Some(hook) = depth_test {
                let yours = hook.passes(&[z], &[stored[s]]).ok()?.first().copied()?;
                if yours != theirs {
                    return Some(SampleMismatch::Depth {
                        pixel: (x, y),
                        sample: s,
                        triangle: tri.primitive,
                        z,
                        stored: stored[s],
                        theirs,
                        yours,
                    });
                }
            }
            if theirs {
                stored[s] = z;
            }
        }
    }
    None
}

impl SampleMismatch {
    /// The mismatch in words: where, the numbers the test reads, both verdicts.
    #[must_use]
    pub fn words(&self, lang: Lang) -> String {
        let verdict = |inside: bool| {
            lang.t(if inside {
                "samples-inside"
            } else {
                "samples-outside"
            })
        };
        let writes = |w: bool| {
            lang.t(if w {
                "samples-writes-the-fragment"
            } else {
                "samples-keeps-what-is-stored"
            })
        };
        let num = |v: f64| crate::vocabulary::short(v as f32, 4);
        match self {
            Self::Inside {
                pixel: (x, y),
                triangle,
                position: [px, py],
                e,
                top_left,
                theirs,
                yours,
            } => {
                let edges: Vec<String> = (0..3)
                    .map(|i| {
                        let on = if e[i] == 0.0 {
                            lang.t(if top_left[i] {
                                "samples-on-a-top-or-left-edge"
                            } else {
                                "samples-on-neither-top-nor-left"
                            })
                        } else {
                            ""
                        };
                        lang.t_with(
                            "samples-edge-value",
                            &[("edge", &i), ("value", &num(e[i])), ("on", &on)],
                        )
                    })
                    .collect();
                lang.t_with(
                    "samples-inside-differs",
                    &[
                        ("x", x),
                        ("y", y),
                        ("sx", &num(*px)),
                        ("sy", &num(*py)),
                        ("triangle", triangle),
                        ("edges", &edges.join(lang.t("list-separator"))),
                        ("theirs", &verdict(*theirs)),
                        ("yours", &verdict(*yours)),
                    ],
                )
            }
            Self::Depth {
                pixel: (x, y),
                sample,
                triangle,
                z,
                stored,
                theirs,
                yours,
            } => {
                let (z, stored) = (format!("{z:.6}"), format!("{stored:.6}"));
                lang.t_with(
                    "samples-depth-differs",
                    &[
                        ("x", x),
                        ("y", y),
                        ("sample", sample),
                        ("triangle", triangle),
                        ("z", &z),
                        ("stored", &stored),
                        ("theirs", &writes(*theirs)),
                        ("yours", &writes(*yours)),
                    ],
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sample on a shared edge that the student counts in and pipelens leaves out, and a
    /// depth test answered the other way, each read as a whole sentence in both languages
    /// (written here by hand from the fields).
    #[test]
    fn a_mismatch_reads_as_a_sentence_in_both_languages() {
        let inside = SampleMismatch::Inside {
            pixel: (12, 7),
            triangle: 3,
            position: [12.5, 7.5],
            e: [0.0, 1.25, -0.5],
            top_left: [false, true, true],
            theirs: false,
            yours: true,
        };
        assert_eq!(
            inside.words(Lang::EN),
            "At pixel (12, 7), the sample (12.5, 7.5) against triangle 3: \
             E0 = 0 (on it: neither a top nor a left edge), E1 = 1.25, E2 = -0.5. \
             pipelens: outside; your inside(): inside."
        );
        assert_eq!(
            inside.words(Lang::ZH),
            "在像素 (12, 7)，采样点 (12.5, 7.5) 对三角形 3：\
             E0 = 0（恰在边上：既非上边也非左边）、E1 = 1.25、E2 = -0.5。\
             pipelens：在外部；你的 inside()：在内部。"
        );
        let depth = SampleMismatch::Depth {
            pixel: (4, 5),
            sample: 2,
            triangle: 1,
            z: 0.25,
            stored: 0.5,
            theirs: true,
            yours: false,
        };
        assert_eq!(
            depth.words(Lang::EN),
            "At pixel (4, 5), sample 2: triangle 1's fragment has z = 0.250000 and the z-buffer \
             holds 0.500000. pipelens writes the fragment; your depth_test(z, stored) keeps what \
             is stored."
        );
        assert_eq!(
            depth.words(Lang::ZH),
            "在像素 (4, 5) 的第 2 个采样点：三角形 1 的片元 z = 0.250000，深度缓冲中已存 0.500000。\
             pipelens 写入这个片元；你的 depth_test(z, stored) 保留已存的值。"
        );
    }
}
