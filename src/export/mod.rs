//! Export of a capture: one PNG per buffer, the overlays drawn over the colour image, and
//! `capture.json` with the numbers. Everything is encoded in memory first; then each file is
//! written to a temporary name beside its target and renamed, so a file is either whole or absent.

mod chart;
mod composing;
mod filmstrip;
mod font;
mod handout;
mod handout_exercise;
mod html;
mod json;
pub mod lesson;
mod lesson_data;
mod listing;
mod palette;
mod picture;
mod slides;
pub mod text;
mod watch;

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use image::{ImageEncoder, codecs::png::PngEncoder};
use pipeline::buffers::BufferKind;
use pipeline::capture::FrameCapture;
use pipeline::overlay::OverlayKind;

use crate::vocabulary::Lang;

pub use json::capture_json;
pub use watch::watch_files;

/// A flag that stops an export between two files (the app's Cancel button, Ctrl+C on the
/// command line): what was written stays whole, nothing half-written is left.
#[derive(Clone, Debug, Default)]
pub struct Cancel(std::sync::Arc<std::sync::atomic::AtomicBool>);

impl Cancel {
    /// Asks the export to stop.
    pub fn cancel(&self) {
        self.0.store(true, std::sync::atomic::Ordering::Relaxed);
    }

    /// Whether it was asked to stop.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        self.0.load(std::sync::atomic::Ordering::Relaxed)
    }

    /// An error once cancelled.
    ///
    /// # Errors
    /// "cancelled", when it was.
    pub fn check(&self) -> Result<()> {
        if self.is_cancelled() {
            anyhow::bail!(
                "export cancelled: every file written before is whole, none is half-written"
            );
        }
        Ok(())
    }
}

/// Options of an export.
#[derive(Clone, Debug)]
pub struct ExportOptions {
    /// The folder the files go to (created if missing).
    pub out: PathBuf,
    /// Magnification of the overlay image (nearest-neighbour, so pixels stay visible);
    /// 0 chooses one that makes it at least 1280 pixels wide (at most 16×).
    pub overlay_zoom: u32,
    /// The most vertex and primitive records written to `capture.json` (the rest is counted).
    pub max_records: usize,
    /// A window pixel `(x, y)` (y up) whose full record goes into `capture.json`.
    pub pixel: Option<(u32, u32)>,
    /// Stops the export between two files.
    pub cancel: Cancel,
    /// The language a failure is said in.
    pub lang: Lang,
}

/// One file of an export.
#[derive(Clone, Debug)]
pub struct ExportFile {
    /// File name within the folder.
    pub name: String,
    /// What it holds.
    pub description: String,
    /// Its bytes.
    pub bytes: Vec<u8>,
}

/// The files of a capture, encoded, in the order they are written.
///
/// # Errors
/// When an image cannot be encoded.
pub fn encode_capture(capture: &FrameCapture, opts: &ExportOptions) -> Result<Vec<ExportFile>> {
    let mut files = Vec::new();
    for kind in capture.buffers() {
        let img = capture.image(kind);
        files.push(ExportFile {
            name: format!("{}.png", kind.name()),
            description: kind.mapping().to_owned(),
            bytes: png_rgba(&img)?,
        });
    }
    for (k, (object, texture)) in capture.textures.iter().enumerate() {
        for level in 0..texture.levels.len() {
            let l = &texture.levels[level];
            files.push(ExportFile {
                name: format!("texture{k}_level{level}.png"),
                description: format!(
                    "mip level {level} ({}×{}) of the texture of `{object}` ({}), each level the 2×2 box filter of the one before",
                    l.width, l.height, texture.name
                ),
                bytes: png_rgba(&texture.level_image(level))?,
            });
        }
    }
    for (k, (object, cube)) in capture.cubes.iter().enumerate() {
        for (face, name) in cube.faces.iter().zip(pipeline::texture::CubeMap::FACES) {
            files.push(ExportFile {
                name: format!("cube{k}_{name}.png"),
                description: format!(
                    "face {name} ({}×{}) of the cube map `{object}` mirrors, as seen from the cube's centre with +y up (top row first): in this order OpenGL's glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i, …) takes it",
                    face.width, face.height
                ),
                bytes: png_rgba(&face.image())?,
            });
        }
    }
    let d16 = capture.depth16();
    let mut bytes = Vec::new();
    // `write_image` takes the samples in native byte order and writes PNG's big-endian itself.
    PngEncoder::new(&mut bytes)
        .write_image(
            d16.as_raw()
                .iter()
                .flat_map(|v| v.to_ne_bytes())
                .collect::<Vec<u8>>()
                .as_slice(),
            d16.width(),
            d16.height(),
            image::ExtendedColorType::L16,
        )
        .context("encoding depth16.png")?;
    files.push(ExportFile {
        name: "depth16.png".into(),
        description: "16-bit grey = round(65535·z_w), window depth with no stretching".into(),
        bytes,
    });
    files.push(ExportFile {
        name: "depth.pfm".into(),
        description: "window depth z_w as 32-bit floats, exactly (Portable Float Map, one channel, little-endian, rows bottom to top)".into(),
        bytes: capture.depth_pfm(),
    });
    let zoom = if opts.overlay_zoom == 0 {
        1280u32.div_ceil(capture.width()).clamp(1, 16)
    } else {
        opts.overlay_zoom
    };
    let overlays = capture.image_with_overlays(BufferKind::Color, &OverlayKind::ALL, zoom);
    files.push(ExportFile {
        name: "overlays.png".into(),
        description: format!(
            "the colour image magnified {zoom}× with each triangle's bounding box (amber) and edges (white)"
        ),
        bytes: png_rgba(&overlays)?,
    });
    let listing: Vec<(String, String)> = files
        .iter()
        .map(|f| (f.name.clone(), f.description.clone()))
        .collect();
    let mut json = capture_json(capture, &listing, opts.max_records);
    if let Some((x, y)) = opts.pixel {
        let record = capture.pixel_record(x, y).with_context(|| {
            format!(
                "--pixel {x},{y} is outside the {}×{} viewport",
                capture.width(),
                capture.height()
            )
        })?;
        json["pixel"] = serde_json::to_value(record).context("encoding the pixel record")?;
    }
    files.push(ExportFile {
        name: "capture.json".into(),
        description: "matrices, vertex table, primitive records, raster triangles".into(),
        bytes: serde_json::to_vec_pretty(&json).context("encoding capture.json")?,
    });
    Ok(files)
}

/// `profile.csv`: the intensity profile along `line` (`[x0, y0, x1, y1]`, image pixels, y down)
/// of each capture given, one column per capture (e.g. flat, Gouraud and Phong shading of the
/// same scene, for the Mach band comparison).
#[must_use]
pub fn profile_csv(line: [f32; 4], captures: &[(&str, &FrameCapture)]) -> ExportFile {
    let profiles: Vec<_> = captures
        .iter()
        .map(|(_, c)| c.profile([line[0], line[1]], [line[2], line[3]]))
        .collect();
    let mut text = String::from("t,x,y");
    for (name, _) in captures {
        text.push_str(&format!(",{name}_r,{name}_g,{name}_b,{name}_intensity"));
    }
    text.push('\n');
    let rows = profiles.first().map_or(0, Vec::len);
    for i in 0..rows {
        let first = &profiles[0][i];
        text.push_str(&format!("{:.5},{},{}", first.t, first.x, first.y));
        for p in &profiles {
            let s = &p[i];
            text.push_str(&format!(
                ",{:.6},{:.6},{:.6},{:.6}",
                s.rgb[0], s.rgb[1], s.rgb[2], s.intensity
            ));
        }
        text.push('\n');
    }
    let names: Vec<&str> = captures.iter().map(|(n, _)| *n).collect();
    ExportFile {
        name: "profile.csv".into(),
        description: format!(
            "intensity profile from ({}, {}) to ({}, {}): colour and Rec. 709 luminance for {}",
            line[0],
            line[1],
            line[2],
            line[3],
            names.join(", ")
        ),
        bytes: text.into_bytes(),
    }
}

fn png_rgba(img: &image::RgbaImage) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    PngEncoder::new(&mut bytes)
        .write_image(
            img.as_raw(),
            img.width(),
            img.height(),
            image::ExtendedColorType::Rgba8,
        )
        .context("encoding a PNG")?;
    Ok(bytes)
}

/// Encodes and writes every file of a capture into `opts.out`; returns the paths written.
/// `progress` is called after each file with (files done, files in all, name).
///
/// # Errors
/// When the folder cannot be created or a file cannot be written; files already renamed into
/// place stay whole, and no partial file is left behind.
pub fn export_capture(
    capture: &FrameCapture,
    opts: &ExportOptions,
    progress: &mut dyn FnMut(usize, usize, &str),
) -> Result<Vec<PathBuf>> {
    let files = encode_capture(capture, opts)?;
    write_files(&opts.out, &files, progress, (&opts.cancel, opts.lang))
}

/// Writes files into a folder, each through a temporary file and a rename; a failure is said
/// in `lang`.
///
/// # Errors
/// When the folder cannot be created, a file cannot be written, or `cancel` was set.
pub fn write_files(
    dir: &Path,
    files: &[ExportFile],
    progress: &mut dyn FnMut(usize, usize, &str),
    (cancel, lang): (&Cancel, Lang),
) -> Result<Vec<PathBuf>> {
    create_folder(dir, lang)?;
    let mut written = Vec::with_capacity(files.len());
    for (i, f) in files.iter().enumerate() {
        cancel.check()?;
        let target = dir.join(&f.name);
        write_atomically(&target, &f.bytes, lang)?;
        written.push(target);
        progress(i + 1, files.len(), &f.name);
    }
    Ok(written)
}

/// Creates the folder `dir` (and those above it); a failure is said in `lang`.
///
/// # Errors
/// When the folder cannot be created.
pub fn create_folder(dir: &Path, lang: Lang) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| {
        lang.t_with(
            "export-cannot-create-the-folder",
            &[("dir", &dir.display())],
        )
    })
}

/// Writes `bytes` to `target` whole or not at all: a temporary file in the same folder, flushed
/// to disk, then renamed over the target; a failure is said in `lang`.
///
/// # Errors
/// When the temporary file cannot be created, written or renamed (it is removed then).
pub fn write_atomically(target: &Path, bytes: &[u8], lang: Lang) -> Result<()> {
    let name = target
        .file_name()
        .map_or_else(|| "file".into(), |n| n.to_string_lossy().into_owned());
    let tmp = target.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let result = (|| -> std::io::Result<()> {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, target)
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(e)
            .with_context(|| lang.t_with("export-cannot-write", &[("file", &target.display())]));
    }
    Ok(())
}
