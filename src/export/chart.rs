//! The intensity profile as a chart image for handouts and slides, drawn by `plotters` with the
//! app's curves, colours and axis labels (`vocabulary::profile`), in the handout's language.

use anyhow::{Result, anyhow};
use image::RgbaImage;
use plotters::prelude::*;

use super::palette::Palette;
use crate::vocabulary::{Lang, profile};

/// The family name the embedded font is registered under for plotters.
const FAMILY: &str = "pipelens";

/// Registers the embedded font with plotters (on the desktop; in the browser plotters draws text
/// with the page's fonts and has no registry).
fn register_font() {
    #[cfg(not(target_arch = "wasm32"))]
    static DONE: std::sync::Once = std::sync::Once::new();
    #[cfg(not(target_arch = "wasm32"))]
    DONE.call_once(|| {
        // The embedded font parses (the app and a test use it); a failure would only leave
        // plotters without text.
        let _ = plotters::style::register_font(
            FAMILY,
            FontStyle::Normal,
            crate::vocabulary::cjk_font(),
        );
    });
}

/// The background, the axes' and the grid's colours: the app's dark plot on screen, dark ink
/// on white in print.
fn colours(palette: Palette) -> (RGBColor, RGBColor, RGBColor) {
    match palette {
        Palette::Screen => (
            RGBColor(14, 14, 14),
            RGBColor(220, 220, 220),
            RGBColor(50, 50, 50),
        ),
        Palette::Print => (
            RGBColor(255, 255, 255),
            RGBColor(30, 30, 30),
            RGBColor(215, 215, 215),
        ),
    }
}

/// A `width`×`height` chart of `curves` (each a name and its points, in the comparison's order).
///
/// # Errors
/// When plotters cannot draw (an empty or degenerate chart area).
pub fn profile_chart(
    curves: &[(String, Vec<[f64; 2]>)],
    (lang, palette): (Lang, Palette),
    width: u32,
    height: u32,
) -> Result<RgbaImage> {
    register_font();
    let (background, ink, grid) = colours(palette);
    let mut rgb = vec![0u8; (width * height * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
        root.fill(&background).map_err(|e| anyhow!("{e}"))?;
        let x_max = curves
            .iter()
            .flat_map(|(_, p)| p.iter().map(|q| q[0]))
            .fold(1.0f64, f64::max);
        let y_max = curves
            .iter()
            .flat_map(|(_, p)| p.iter().map(|q| q[1]))
            .fold(0.0f64, f64::max)
            .max(0.1)
            * 1.08;
        let font = |size: f64| (FAMILY, size).into_font().color(&ink);
        // Type sized to the image: it is shown as wide as the picture above it.
        let scale = (f64::from(width) / 800.0).max(f64::from(height) / 400.0);
        let mut chart = ChartBuilder::on(&root)
            .margin((12.0 * scale) as i32)
            .x_label_area_size((52.0 * scale) as i32)
            .y_label_area_size((64.0 * scale) as i32)
            .build_cartesian_2d(0.0..x_max, 0.0..y_max)
            .map_err(|e| anyhow!("{e}"))?;
        chart
            .configure_mesh()
            .x_desc(profile::x_label(lang))
            .y_desc(profile::y_label(lang))
            .axis_desc_style(font(17.0 * scale))
            .label_style(font(14.0 * scale))
            .light_line_style(grid)
            .bold_line_style(grid.mix(0.9))
            .axis_style(ink)
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
        for (i, (name, points)) in curves.iter().enumerate() {
            let [r, g, b] = profile::CURVE_COLORS[i % profile::CURVE_COLORS.len()];
            let color = RGBColor(r, g, b);
            chart
                .draw_series(LineSeries::new(
                    points.iter().map(|p| (p[0], p[1])),
                    color.stroke_width((2.0 * scale).max(1.0) as u32),
                ))
                .map_err(|e| anyhow!("{e}"))?
                .label(name.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(background.mix(0.85))
            .border_style(grid)
            .label_font(font(15.0 * scale))
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
        root.present().map_err(|e| anyhow!("{e}"))?;
    }
    let rgba = rgb
        .chunks_exact(3)
        .flat_map(|p| [p[0], p[1], p[2], 255])
        .collect();
    RgbaImage::from_raw(width, height, rgba).ok_or_else(|| anyhow!("chart buffer size"))
}
