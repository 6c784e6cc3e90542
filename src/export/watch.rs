//! A watch's files (`pipelens export --watch EXPR@LINE`): the picture as the debugger draws it
//! (`watch.png`, and for a vector each component on the ramp), and every number
//! (`watch.csv`: the window pixel, y up as the inspector counts, and the value's components,
//! for each pixel whose fragment ran the line).

use std::fmt::Write as _;

use anyhow::Result;
use pipeline::capture::{WatchPicture, WatchView};

use super::{ExportFile, png_rgba};

/// The components' names, as GLSL's swizzles write them.
const COMPONENTS: [&str; 4] = ["x", "y", "z", "w"];

/// The files of `picture`.
///
/// # Errors
/// A PNG that could not be encoded.
pub fn watch_files(picture: &WatchPicture) -> Result<Vec<ExportFile>> {
    let kind = picture
        .kind
        .unwrap_or(pipeline::shader::probe::WatchKind::Float);
    let what = format!("`{}` {}", picture.expression, picture.place());
    let unrun = picture.unrun();
    let shown = picture.drawn(WatchView::Value);
    let mut files = vec![ExportFile {
        name: "watch.png".to_owned(),
        description: match shown.range {
            Some((lo, hi)) => format!(
                "{what} on the cividis ramp, dark blue {lo} to yellow {hi}; grey checks {unrun}, magenta NaN or infinite"
            ),
            None if kind == pipeline::shader::probe::WatchKind::Bool => {
                format!("{what}: yellow where it holds, dark blue where not; grey checks {unrun}")
            }
            None => {
                format!("{what} as a colour, each component clamped to [0, 1]; grey checks {unrun}")
            }
        },
        bytes: png_rgba(&shown.image)?,
    }];
    if kind.components() > 1 {
        for (c, name) in COMPONENTS.iter().enumerate().take(kind.components()) {
            let one = picture.drawn(WatchView::Component(c));
            let (lo, hi) = one.range.unwrap_or((0.0, 0.0));
            files.push(ExportFile {
                name: format!("watch-{name}.png"),
                description: format!(
                    "{what}, its {name} component on the cividis ramp, dark blue {lo} to yellow {hi}"
                ),
                bytes: png_rgba(&one.image)?,
            });
        }
    }
    // The pixel's x and y, then the value: `value`, or `value.x`, `value.y` … for a vector.
    let mut csv = String::from("x,y");
    if kind.components() == 1 {
        csv.push_str(",value");
    } else {
        for name in COMPONENTS.iter().take(kind.components()) {
            let _ = write!(csv, ",value.{name}");
        }
    }
    csv.push('\n');
    let h = picture.height();
    for (i, v) in picture.values.iter().enumerate() {
        let Some(v) = v else { continue };
        let (x, row) = (i as u32 % picture.width, i as u32 / picture.width);
        let _ = write!(csv, "{x},{}", h - 1 - row);
        for c in v.iter().take(kind.components()) {
            let _ = write!(csv, ",{c}");
        }
        csv.push('\n');
    }
    files.push(ExportFile {
        name: "watch.csv".to_owned(),
        description: format!(
            "{what} at each pixel that has it: window x, y (y up), then each component"
        ),
        bytes: csv.into_bytes(),
    });
    Ok(files)
}
