//! The geometry view's legend: what each colour and dash drawn means, named only for what the
//! picture shows; on a small screen folded into a chip that a tap opens.

use egui::{Align2, Color32, Pos2, Rect, Stroke, Vec2};
use glam::Vec3;
use pipeline::capture::FrameCapture;

use crate::app::views::{FATES, label_with_background, palette, picture_font, picture_scale};
use crate::spaces::world_into;
use crate::vocabulary::{Lang, Space};

/// The most triangles drawn as wireframe (every k-th beyond that).
const MAX_TRIANGLES: usize = 30_000;

/// The most triangles drawn dashed (their fate's pattern, `spaces::FATE_DASHES`): each dashed
/// edge is a dozen segments, so past this the fates are told by colour and the legend alone.
const MOST_DASHED: usize = 4_000;

/// What the picture shows, so that the legend names only that.
pub(super) struct Shown {
    /// Which fates (by `fate_index`) some drawn triangle met.
    pub fates: [bool; FATES.len()],
    /// Every how many triangles one is drawn.
    pub stride: usize,
    /// Whether the triangles are dashed by their fate (few enough of them to be).
    pub dashed: bool,
    /// Whether the view volume's edges are drawn.
    pub volume: bool,
    /// Whether a light is drawn.
    pub lights: bool,
}

/// The legend, measured before the picture is framed so that the subject can be framed clear
/// of it: what each colour drawn means, one item a row (a column) or as many a row as the
/// view's width holds (a strip along the foot).
pub(super) struct Legend {
    /// Each item's colour, words, and the fate whose dashes its line shows (by `fate_index`).
    items: Vec<(Color32, &'static str, Option<usize>)>,
    /// Each item's width (the widest's), its line and words.
    item_w: f32,
    row: f32,
    /// "showing triangles 1/n" when only every n-th triangle is drawn.
    note: Option<String>,
    /// On a small screen the legend folds into a chip that a tap opens ([`Self::folded`]).
    chip: Option<Chip>,
}

/// The folded legend's chip: its words, its size (at least a finger's target), and whether
/// the legend is open above it.
struct Chip {
    name: &'static str,
    size: Vec2,
    open: bool,
}

impl Legend {
    /// The legend of what `shown` says is drawn, for a view: on a small screen folded into a
    /// chip, open when the student opened it (`open`).
    pub(super) fn for_view(
        ui: &egui::Ui,
        painter: &egui::Painter,
        shown: &Shown,
        (open, lang): (bool, Lang),
    ) -> Self {
        let legend = Self::new(painter, shown, lang);
        if !crate::app::window_size::is_compact(ui.ctx()) {
            return legend;
        }
        let least = ui.spacing().interact_size.y;
        legend.folded(painter, lang.t("geometry-legend"), open, least)
    }

    /// The legend of what `shown` says is drawn.
    fn new(painter: &egui::Painter, shown: &Shown, lang: Lang) -> Self {
        let stride = shown.stride;
        let mut items: Vec<(Color32, &'static str, Option<usize>)> = FATES
            .iter()
            .zip(shown.fates)
            .enumerate()
            .filter(|(_, (_, drawn))| *drawn)
            .map(|(k, ((color, name), _))| (*color, lang.t(name), shown.dashed.then_some(k)))
            .collect();
        if shown.volume {
            items.push((palette::NEAR, lang.t("cards-near-plane"), None));
            items.push((palette::FAR, lang.t("cards-far-plane"), None));
        }
        if shown.lights {
            items.push((palette::LIGHT, lang.t("cards-light"), None));
        }
        let font = picture_font(painter.ctx(), 14.0);
        let item_w = items
            .iter()
            .map(|(_, text, _)| {
                let g = painter.layout_no_wrap((*text).to_owned(), font.clone(), Color32::WHITE);
                g.size().x
            })
            .fold(0.0f32, f32::max)
            + 40.0 * picture_scale(painter.ctx());
        let note = (stride > 1 && !items.is_empty())
            .then(|| format!("{} 1/{stride}", lang.t("cards-showing-triangles")));
        Self {
            items,
            item_w,
            row: font.size * 1.3,
            note,
            chip: None,
        }
    }

    /// The legend folded into a chip named `name` that opens it (`open`), at least `least`
    /// points high and as wide: over a landscape phone's view (250 × 260 points) its rows took
    /// a fifth of the picture beside the matrix card, for a key the student reads once.
    fn folded(
        mut self,
        painter: &egui::Painter,
        name: &'static str,
        open: bool,
        least: f32,
    ) -> Self {
        let font = egui::TextStyle::Button.resolve(&painter.ctx().global_style());
        let text = painter.layout_no_wrap(name.to_owned(), font, Color32::WHITE);
        let padding = painter.ctx().global_style().spacing.button_padding;
        let size = (text.size() + 2.0 * padding).max(Vec2::splat(least));
        self.chip = Some(Chip { name, size, open });
        self
    }

    /// Whether the legend is folded into a chip ([`Self::folded`]), and if so whether open.
    pub(super) fn chip(&self) -> Option<bool> {
        self.chip.as_ref().map(|c| c.open)
    }

    /// Where the chip is when the legend is at `at`: its bottom-right corner, which stays put
    /// as the legend opens above it (a chip's places are at the view's foot, anchored there).
    pub(super) fn chip_at(&self, at: Rect) -> Option<(Rect, &'static str, bool)> {
        let chip = self.chip.as_ref().filter(|_| !self.items.is_empty())?;
        let rect = Rect::from_min_max(at.max - chip.size, at.max);
        Some((rect, chip.name, chip.open))
    }

    /// How many items a row holds in a strip `width` wide (at least one).
    pub(super) fn per_row(&self, width: f32) -> usize {
        ((width - 8.0) / self.item_w).floor().max(1.0) as usize
    }

    /// The legend's size with `per_row` items a row, its note below included; zero when it
    /// has nothing to say.
    pub(super) fn size(&self, per_row: usize) -> Vec2 {
        if self.items.is_empty() {
            return Vec2::ZERO;
        }
        match &self.chip {
            Some(chip) if !chip.open => chip.size,
            Some(chip) => {
                let keys = self.keys_size(per_row);
                Vec2::new(keys.x.max(chip.size.x), keys.y + 4.0 + chip.size.y)
            }
            None => self.keys_size(per_row),
        }
    }

    /// The size of the legend's keys (its items and note) with `per_row` items a row.
    fn keys_size(&self, per_row: usize) -> Vec2 {
        let per_row = per_row.clamp(1, self.items.len());
        let rows = self.items.len().div_ceil(per_row);
        let note = if self.note.is_some() {
            self.row + 6.0
        } else {
            0.0
        };
        Vec2::new(
            self.item_w * per_row as f32 + 4.0,
            self.row * rows as f32 + 8.0 + note,
        )
    }

    /// Draws the legend in `at` (from [`Self::size`] with `per_row`), folded or not, the chip's
    /// button aside (the view puts it at [`Self::chip_at`]); returns where it is.
    pub(super) fn paint(&self, painter: &egui::Painter, at: Rect, per_row: usize) -> Rect {
        if self.items.is_empty() {
            return Rect::NOTHING;
        }
        match &self.chip {
            Some(chip) if !chip.open => at,
            Some(_) => {
                let keys = Rect::from_min_size(at.min, self.keys_size(per_row));
                self.paint_keys(painter, keys, per_row).union(at)
            }
            None => self.paint_keys(painter, at, per_row),
        }
    }

    /// Draws the legend's keys in `at`; returns where they are.
    fn paint_keys(&self, painter: &egui::Painter, at: Rect, per_row: usize) -> Rect {
        let per_row = per_row.clamp(1, self.items.len());
        let scale = picture_scale(painter.ctx());
        let note = if self.note.is_some() {
            self.row + 6.0
        } else {
            0.0
        };
        let back = Rect::from_min_max(at.min, at.max - Vec2::new(0.0, note));
        painter.rect_filled(back, 4.0, Color32::from_black_alpha(150));
        for (k, (color, text, fate)) in self.items.iter().enumerate() {
            let (r, c) = (k / per_row, k % per_row);
            let p = Pos2::new(
                back.left() + 8.0 + self.item_w * c as f32,
                back.top() + 4.0 + self.row * (r as f32 + 0.5),
            );
            // The line as the picture draws it: a fate's in its dashes, a little longer so
            // that the pattern shows.
            let ends = [p, p + Vec2::new(18.0 * scale, 0.0)];
            palette::fate_segment(
                painter,
                ends,
                Stroke::new(3.0, *color),
                (*fate, scale * 0.8),
            );
            painter.text(
                p + Vec2::new(24.0 * scale, 0.0),
                Align2::LEFT_CENTER,
                *text,
                picture_font(painter.ctx(), 14.0),
                Color32::from_gray(230),
            );
        }
        match &self.note {
            Some(note) => back.union(label_with_background(
                painter,
                back.left_bottom() + Vec2::new(0.0, 6.0),
                Align2::LEFT_TOP,
                note,
                &picture_font(painter.ctx(), 13.0),
                Color32::YELLOW,
            )),
            None => back,
        }
    }
}

/// What the legend names: the fates of the triangles drawn (every `stride`-th, as many as
/// [`MAX_TRIANGLES`] allows), the view
/// volume when drawn, the lights when this space has the world's lights and one has a gizmo
/// around the subject's `sphere`.
pub(super) fn shown(
    capture: &FrameCapture,
    space: Space,
    sphere: Option<(Vec3, f32)>,
    volume: bool,
) -> Shown {
    let stride = capture.primitives.len().div_ceil(MAX_TRIANGLES).max(1);
    let met = crate::spaces::fates_met(capture, stride);
    let fates = met.map(|n| n > 0);
    let patterned: usize = (0..FATES.len())
        .filter(|&k| !crate::spaces::FATE_DASHES[k].is_empty())
        .map(|k| met[k])
        .sum();
    let lights = match (world_into(capture, space), sphere) {
        (Some(m), Some((centre, radius))) => {
            let world_centre = m.inverse().transform_point3(centre);
            capture
                .lights
                .iter()
                .any(|l| l.gizmo(world_centre, radius.max(1e-3) * 2.0).is_some())
        }
        _ => false,
    };
    Shown {
        fates,
        stride,
        dashed: patterned <= MOST_DASHED,
        volume,
        lights,
    }
}

/// The folded legend's chip (from [`Legend::chip_at`]), a button; whether it was tapped (which
/// opens or closes the legend).
pub(super) fn chip(ui: &mut egui::Ui, chip: Option<(Rect, &str, bool)>, lang: Lang) -> bool {
    let Some((at, name, open)) = chip else {
        return false;
    };
    // Framed whether open or not: over the picture a frameless word reads as a label.
    let button = egui::Button::new(name)
        .selected(open)
        .frame(true)
        .min_size(at.size());
    ui.put(at, button)
        .on_hover_text(lang.t("geometry-legend-what"))
        .clicked()
}
