//! The inspector: the matrices with their formulas and factors, the vertex table through every
//! space, and the pixel inspector (every fragment that reached a pixel, and what became of it).

use egui::{Color32, RichText, Ui};
use pipeline::capture::{Fate, FrameCapture};

use super::{matrix, palette};
use crate::app::session::{Command, Session};
use crate::vocabulary::{Lang, num, vec3, vec4};

/// The inspector's tabs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tab {
    /// The matrices.
    #[default]
    Matrices,
    /// The vertex table.
    Vertices,
    /// The pixel inspector.
    Pixel,
}

/// The inspector's state: the tab shown, and the inspected pixel's record, kept while the
/// capture and the pixel stay the same (replaying the fragments walks every triangle).
#[derive(Default)]
pub struct Inspector {
    /// The tab shown.
    pub tab: Tab,
    record: Option<(u64, (u32, u32), pipeline::capture::PixelRecord)>,
}

impl Inspector {
    /// The record of the inspected pixel, computed once per capture and pixel.
    fn record(
        &mut self,
        session: &Session,
        capture: &FrameCapture,
    ) -> Option<&pipeline::capture::PixelRecord> {
        let (x, y) = session.selection.pixel?;
        let key = (session.shown_generation, (x, y));
        if self.record.as_ref().is_none_or(|(g, p, _)| (*g, *p) != key) {
            self.record = capture.pixel_record(x, y).map(|r| (key.0, key.1, r));
        }
        self.record.as_ref().map(|(_, _, r)| r)
    }
}

/// Draws the inspector.
pub fn ui(
    ui: &mut Ui,
    inspector: &mut Inspector,
    session: &Session,
    capture: &FrameCapture,
) -> Vec<Command> {
    let tab = &mut inspector.tab;
    let lang = session.lang;
    let mut cmds = Vec::new();
    ui.horizontal(|ui| {
        ui.selectable_value(tab, Tab::Matrices, lang.tr("Matrices", "矩阵"));
        ui.selectable_value(tab, Tab::Vertices, lang.tr("Vertices", "顶点表"));
        ui.selectable_value(tab, Tab::Pixel, lang.tr("Pixel", "像素"));
    });
    ui.separator();
    match tab {
        Tab::Matrices => {
            egui::ScrollArea::vertical()
                .id_salt("matrices")
                .show(ui, |ui| matrices(ui, capture, lang));
        }
        Tab::Vertices => cmds.extend(vertices(ui, session, capture)),
        Tab::Pixel => {
            let record = inspector.record(session, capture);
            egui::ScrollArea::vertical()
                .id_salt("pixel")
                .show(ui, |ui| pixel(ui, session, capture, record));
        }
    }
    cmds
}

fn matrices(ui: &mut Ui, capture: &FrameCapture, lang: Lang) {
    let m = &capture.matrices;
    for (i, model) in m.models.iter().enumerate() {
        matrix(ui, model, lang, &format!("model{i}"));
        ui.add_space(6.0);
    }
    matrix(ui, &m.view, lang, "view");
    ui.add_space(6.0);
    matrix(ui, &m.projection, lang, "projection");
    ui.add_space(6.0);
    ui.label(
        RichText::new(lang.tr(
            "The same projection in GAMES101's terms (n = −near, f = −far):",
            "GAMES101 记法下的同一投影（n = −near, f = −far）：",
        ))
        .weak(),
    );
    matrix(ui, &m.projection_games101, lang, "games101");
    ui.label(
        RichText::new(if capture.projection.is_perspective() {
            lang.tr(
                "M_ortho·M_persp→ortho = −Z·P with Z = diag(1, 1, −1, 1): the same x, y after division; NDC z mirrored (near → +1).",
                "M_ortho·M_persp→ortho = −Z·P，Z = diag(1, 1, −1, 1)：除法后 x、y 相同；NDC 的 z 取反（近平面 → +1）。",
            )
        } else {
            lang.tr(
                "M_ortho = Z·Ortho with Z = diag(1, 1, −1, 1): NDC z mirrored (near → +1).",
                "M_ortho = Z·Ortho，Z = diag(1, 1, −1, 1)：NDC 的 z 取反（近平面 → +1）。",
            )
        })
        .italics(),
    );
    ui.add_space(6.0);
    matrix(ui, &m.viewport, lang, "viewport");
    if !capture.hierarchy.is_empty() {
        ui.add_space(6.0);
        hierarchy(ui, capture, lang);
    }
}

/// The figures' traversal as the matrix stack sees it.
fn hierarchy(ui: &mut Ui, capture: &FrameCapture, lang: Lang) {
    use pipeline::hierarchy::Step;
    ui.label(
        RichText::new(lang.tr("Matrix stack, depth-first", "矩阵栈（深度优先遍历）")).strong(),
    );
    for (i, step) in capture.hierarchy.iter().enumerate() {
        match step {
            Step::Push { depth } => {
                ui.label(
                    RichText::new(format!("{}push(M)  → {depth}", "  ".repeat(depth - 1)))
                        .monospace()
                        .weak(),
                );
            }
            Step::Pop { depth } => {
                ui.label(
                    RichText::new(format!("{}M = pop() → {depth}", "  ".repeat(*depth)))
                        .monospace()
                        .weak(),
                );
            }
            Step::Visit {
                node, composite, ..
            } => {
                egui::CollapsingHeader::new(
                    RichText::new(format!("M({node}) = M·local")).monospace(),
                )
                .id_salt(("stack", i))
                .show(ui, |ui| matrix(ui, composite, lang, &format!("stack{i}")));
            }
        }
    }
}

fn vertices(ui: &mut Ui, session: &Session, capture: &FrameCapture) -> Vec<Command> {
    let lang = session.lang;
    let mut cmds = Vec::new();
    ui.label(
        RichText::new(lang.tr(
            "Click a row to highlight the vertex in every view.",
            "单击一行，在所有视图中高亮该顶点。",
        ))
        .weak(),
    );
    let headers = [
        lang.tr("vertex", "顶点"),
        lang.tr("object", "物体"),
        lang.tr("model", "模型"),
        lang.tr("world", "世界"),
        lang.tr("eye", "相机"),
        lang.tr("clip (x, y, z, w)", "裁剪 (x, y, z, w)"),
        "NDC",
        lang.tr("window", "屏幕"),
    ];
    let row_height = ui.text_style_height(&egui::TextStyle::Monospace) + 4.0;
    egui::ScrollArea::both().id_salt("vertices").show_rows(
        ui,
        row_height,
        capture.vertices.len() + 1,
        |ui, range| {
            egui::Grid::new("vertex-table")
                .striped(true)
                .spacing([12.0, 2.0])
                .show(ui, |ui| {
                    for h in headers {
                        ui.label(RichText::new(h).strong());
                    }
                    ui.end_row();
                    for i in range.start.saturating_sub(1)
                        ..range.end.saturating_sub(1).min(capture.vertices.len())
                    {
                        let v = &capture.vertices[i];
                        let selected = session.selection.vertex == Some(i as u32);
                        let text = |s: String| {
                            let t = RichText::new(s).monospace();
                            if selected {
                                t.color(palette::SELECTED)
                            } else {
                                t
                            }
                        };
                        if ui
                            .selectable_label(selected, text(format!("v{i}")))
                            .clicked()
                        {
                            cmds.push(Command::SelectVertex((!selected).then_some(i as u32)));
                        }
                        ui.label(text(v.object.to_string()));
                        ui.label(text(vec3(v.object_pos.truncate())));
                        ui.label(text(vec3(v.world.truncate())));
                        ui.label(text(vec3(v.eye.truncate())));
                        ui.label(text(vec4(v.clip)));
                        ui.label(text(v.ndc.map_or_else(|| "— (w ≤ 0)".to_owned(), vec3)));
                        ui.label(text(v.window.map_or_else(|| "—".to_owned(), vec3)));
                        ui.end_row();
                    }
                });
        },
    );
    cmds
}

fn pixel(
    ui: &mut Ui,
    session: &Session,
    capture: &FrameCapture,
    record: Option<&pipeline::capture::PixelRecord>,
) {
    let lang = session.lang;
    let Some(record) = record else {
        ui.label(lang.tr("Click a pixel in a pixel view (Rasterization, Depth, Output) to see every fragment that reached it.", "在像素视图（光栅化、深度、输出）中单击一个像素，查看到达它的每个片元。"));
        return;
    };
    let (x, y) = (record.x, record.y);
    let s = capture.settings.samples.count();
    ui.heading(format!("{} ({x}, {y})", lang.tr("Pixel", "像素")));
    ui.label(format!(
        "{}: ({}, {}) · {} {}",
        lang.tr("centre", "中心"),
        x as f32 + 0.5,
        y as f32 + 0.5,
        lang.tr("image row", "图像行"),
        capture.height() - 1 - y
    ));
    ui.label(format!(
        "{}: {}/{s}",
        lang.tr("coverage", "覆盖"),
        record.coverage
    ));
    ui.label(format!(
        "{}: {}",
        lang.tr("depth z_w (mean of samples)", "深度 z_w（采样平均）"),
        num(record.depth)
    ));
    let c = record.color;
    ui.horizontal(|ui| {
        ui.label(format!(
            "{}: ({}, {}, {})",
            lang.tr("final colour", "最终颜色"),
            num(c[0]),
            num(c[1]),
            num(c[2])
        ));
        let swatch = Color32::from_rgb(
            (c[0].clamp(0.0, 1.0) * 255.0) as u8,
            (c[1].clamp(0.0, 1.0) * 255.0) as u8,
            (c[2].clamp(0.0, 1.0) * 255.0) as u8,
        );
        let (r, _) = ui.allocate_exact_size(egui::vec2(18.0, 18.0), egui::Sense::hover());
        ui.painter().rect_filled(r, 2.0, swatch);
    });
    owner_terms(ui, record, lang);
    ui.separator();
    if record.fragments.is_empty() {
        ui.label(lang.tr(
            "No fragment reached this pixel: it keeps the background.",
            "没有片元到达此像素：保持背景色。",
        ));
    }
    for (k, f) in record.fragments.iter().enumerate() {
        fragment(ui, k, f, capture, lang);
    }
    if record.primitive.is_none() && !record.fragments.is_empty() {
        ui.label(lang.tr(
            "Every fragment failed the depth test.",
            "所有片元都未通过深度测试。",
        ));
    }
}

/// What the owning fragment computed at the pixel centre: the lighting terms that sum to its
/// colour and its texture lookup (uv, footprint, level of detail, level read, texel).
fn owner_terms(ui: &mut Ui, record: &pipeline::capture::PixelRecord, lang: Lang) {
    let v3 = |a: [f32; 3]| vec3(glam::Vec3::from_array(a));
    let row = |ui: &mut Ui, name: &str, value: String, formula: &str| {
        ui.label(RichText::new(format!("{name:<10} {value}")).monospace())
            .on_hover_text(formula);
    };
    if let Some(sh) = &record.lighting {
        ui.separator();
        ui.strong(lang.tr("Lighting (owning fragment)", "光照（所属片元）"));
        row(ui, "ambient", v3(sh.ambient), "Σ k_a·I_a");
        row(ui, "diffuse", v3(sh.diffuse), "Σ f_att·k_d·I_d·max(n·l, 0)");
        row(
            ui,
            "specular",
            v3(sh.specular),
            "Σ f_att·k_s·I_s·max(n·h, 0)^p",
        );
        if sh.reflected != [0.0; 3] {
            row(ui, "reflected", v3(sh.reflected), "k·C_env(2(n·v)n − v)");
        }
        row(ui, "n", v3(sh.normal), "unit normal, world space");
        row(
            ui,
            "n·l, n·h",
            format!("{}, {}", num(sh.n_dot_l), num(sh.n_dot_h)),
            "of the key light",
        );
    }
    if let Some(t) = &record.texture {
        let [s_x, t_x, s_y, t_y] = t.footprint;
        ui.separator();
        ui.strong(lang.tr("Texture lookup", "纹理查询"));
        let [u, v] = t.uv;
        row(
            ui,
            "(u, v)",
            format!("({}, {})", num(u), num(v)),
            "interpolated",
        );
        row(
            ui,
            "∂/∂x",
            format!("({}, {}) texels", num(s_x), num(t_x)),
            "∂(u·w, v·h)/∂x: the footprint's first axis",
        );
        row(
            ui,
            "∂/∂y",
            format!("({}, {}) texels", num(s_y), num(t_y)),
            "∂(u·w, v·h)/∂y: the footprint's second axis",
        );
        row(ui, "λ", num(t.lod), "λ = log₂ max(|∂/∂x|, |∂/∂y|) + bias");
        row(
            ui,
            "level",
            num(t.level),
            "k + blend (trilinear mixes k and k+1)",
        );
        row(ui, "texel", v3(t.texel), "the filtered colour");
    }
}

/// One fragment of the pixel inspector: its samples' depth-test outcomes, depth, barycentrics.
fn fragment(
    ui: &mut Ui,
    k: usize,
    f: &pipeline::capture::FragmentRecord,
    capture: &FrameCapture,
    lang: Lang,
) {
    let prim = &capture.primitives[f.primitive as usize];
    let title = format!(
        "{} {} · {} {}{}",
        lang.tr("fragment", "片元"),
        k + 1,
        lang.tr("triangle", "三角形"),
        f.primitive,
        if f.visible {
            lang.tr("  √ visible", "  √ 可见")
        } else {
            ""
        }
    );
    egui::CollapsingHeader::new(RichText::new(title).strong())
        .id_salt(("frag", k))
        .default_open(true)
        .show(ui, |ui| {
            if prim.fate == Fate::Clipped {
                ui.label(
                    RichText::new(lang.tr(
                        "(a piece of a clipped triangle)",
                        "（被裁剪三角形的一部分）",
                    ))
                    .weak(),
                );
            }
            ui.horizontal_wrapped(|ui| {
                ui.label(lang.tr("samples:", "采样点："));
                for (si, outcome) in f.samples.iter().enumerate() {
                    let (text, color) = match outcome {
                        None => ("·", Color32::GRAY),
                        Some(true) => ("√", Color32::from_rgb(90, 210, 90)),
                        Some(false) => ("×", Color32::from_rgb(235, 80, 80)),
                    };
                    ui.label(
                        RichText::new(format!("{si}{text}"))
                            .color(color)
                            .monospace(),
                    )
                    .on_hover_text(match (outcome, f.sample_depths[si]) {
                        (None, _) => lang.tr("not covered", "未覆盖").to_owned(),
                        (Some(true), Some(z)) => format!(
                            "{} z = {}",
                            lang.tr("passed the depth test,", "通过深度测试，"),
                            num(z)
                        ),
                        (Some(false), Some(z)) => format!(
                            "{} z = {}",
                            lang.tr("failed the depth test,", "未通过深度测试，"),
                            num(z)
                        ),
                        _ => String::new(),
                    });
                }
            });
            ui.label(format!(
                "{} z_w = {}",
                lang.tr("depth at the centre:", "中心处深度："),
                num(f.depth)
            ));
            let b = f.bary_perspective;
            let a = f.bary_affine;
            ui.label(
                RichText::new(format!(
                    "b  = ({}, {}, {})  {}",
                    num(b[0]),
                    num(b[1]),
                    num(b[2]),
                    lang.tr("perspective-correct", "透视校正")
                ))
                .monospace(),
            );
            ui.label(
                RichText::new(format!(
                    "λ  = ({}, {}, {})  {}",
                    num(a[0]),
                    num(a[1]),
                    num(a[2]),
                    lang.tr("affine (screen space)", "仿射（屏幕空间）")
                ))
                .monospace(),
            );
            ui.label(
                RichText::new("b_i = (λ_i / w_i) / Σ_k (λ_k / w_k)")
                    .italics()
                    .weak(),
            );
        });
}
