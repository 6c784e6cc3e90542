//! The axes of the app's plots (the depth curve, the intensity profile): named, and their tick
//! numbers at the text's full contrast. egui_plot fades a tick's number in as the ticks spread
//! from 60 to 80 points apart (20 to 30 on y); a faded number was 3.6:1 on the plot's ground,
//! under WCAG AA's 4.5:1, so here a number shows at full strength once its ticks are far
//! enough apart, and not at all before.

use egui_plot::AxisHints;

/// The x axis named `x` and the y axis named `y` at least `y_width` points wide.
pub fn axes<'a>(x: &str, y: &str, y_width: f32) -> (Vec<AxisHints<'a>>, Vec<AxisHints<'a>>) {
    (
        vec![AxisHints::new_x().label(x).label_spacing(60.0..=60.01)],
        vec![
            AxisHints::new_y()
                .label(y)
                .min_thickness(y_width)
                .label_spacing(20.0..=20.01),
        ],
    )
}

/// The part of `rect` to show a plot in so that all of it is painted inside `rect`: egui_plot
/// draws the y axis's title a quarter of its line's height left of the plot's own rect (its
/// `AXIS_LABEL_GAP`), which cut the title's first pixels off at the left edge of a panel.
pub fn plot_rect(ui: &egui::Ui, rect: egui::Rect) -> egui::Rect {
    let gap = 0.25 * ui.text_style_height(&egui::TextStyle::Body);
    rect.with_min_x(rect.min.x + gap.ceil() + 1.0)
}
