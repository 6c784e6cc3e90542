//! A file watched for live reload: its path and the latest change to it or to a shader file
//! beside it, checked no more than twice a second.

use std::path::PathBuf;

use web_time::Instant;

/// A file watched for changes.
pub(super) struct Watched {
    path: PathBuf,
    modified: Option<std::time::SystemTime>,
    checked: Instant,
}

impl Watched {
    /// `path` watched from now on, as it is now.
    pub(super) fn new(path: PathBuf) -> Self {
        Self {
            modified: Self::modified(&path),
            path,
            checked: Instant::now(),
        }
    }

    /// Whether the file or a shader beside it changed since the last time this said so, asked no
    /// more than once in 400 ms (the app asks at every frame).
    pub(super) fn changed(&mut self) -> bool {
        if self.checked.elapsed() < std::time::Duration::from_millis(400) {
            return false;
        }
        self.checked = Instant::now();
        let now = Self::modified(&self.path);
        if now == self.modified {
            return false;
        }
        self.modified = now;
        true
    }

    /// The file watched.
    pub(super) fn path(&self) -> &std::path::Path {
        &self.path
    }

    /// The latest change to `path` or to a shader file (`.vert`, `.frag`, …) in its folder or
    /// a folder within it: a lesson reads its shaders from there.
    fn modified(path: &std::path::Path) -> Option<std::time::SystemTime> {
        let stamp = |p: &std::path::Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
        let is_shader = |p: &std::path::Path| {
            let name = p.to_string_lossy();
            crate::lesson::SHADER_FILE_ENDINGS
                .iter()
                .any(|e| name.ends_with(e))
        };
        let entries = |dir: &std::path::Path| {
            std::fs::read_dir(dir)
                .into_iter()
                .flatten()
                .filter_map(|e| e.ok().map(|e| e.path()))
                .collect::<Vec<_>>()
        };
        let folder = path
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(std::path::Path::new("."));
        let mut latest = stamp(path);
        for entry in entries(folder) {
            let inner = if entry.is_dir() {
                entries(&entry)
            } else {
                vec![entry]
            };
            for p in inner.iter().filter(|p| is_shader(p)) {
                latest = latest.max(stamp(p));
            }
        }
        latest
    }
}
