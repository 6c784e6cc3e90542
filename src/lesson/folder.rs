//! Where the files a lesson or scene names (a mesh `obj = "bunny.obj"`, a texture, a shader
//! file) are read: beside the lesson on disk, as a path relative to its folder; or, in a page,
//! among the files the page was given (dropped on it with the lesson, or before it), by name —
//! a page has no disk to read from.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Files a page was given, by their names (`bunny.obj`), with their bytes.
pub type Given = BTreeMap<String, Arc<[u8]>>;

/// Where the files a lesson names are looked for: the files given first, then the disk.
#[derive(Clone, Debug, Default)]
pub struct Folder {
    /// The lesson's folder on disk (empty: the working folder); none in a page.
    disk: Option<PathBuf>,
    /// The files given, by name.
    given: Given,
}

/// A file read for a lesson.
#[derive(Clone, Debug)]
pub struct File {
    /// How messages name it: its path, or its name among the files given.
    pub shown: String,
    /// Its bytes.
    pub bytes: Arc<[u8]>,
}

impl Folder {
    /// The folder `path` on disk, the paths a lesson writes relative to it.
    #[must_use]
    pub fn on_disk(path: &Path) -> Self {
        Self {
            disk: Some(path.to_path_buf()),
            given: Given::new(),
        }
    }

    /// A page's folder: only the files it was given.
    #[must_use]
    pub fn of_page(given: Given) -> Self {
        Self { disk: None, given }
    }

    /// The folder on disk, if there is one.
    #[must_use]
    pub fn disk(&self) -> Option<&Path> {
        self.disk.as_deref()
    }

    /// The file `written` names (`bunny.obj`, `models/bunny.obj`): a file given under that
    /// name or its last part (a lesson written on the desktop names `models/bunny.obj`, the
    /// page was given `bunny.obj`); else the file at that path relative to the folder on disk.
    ///
    /// # Errors
    /// When there is no such file or it cannot be read: in words, with the path it was looked
    /// for at, the rule, and a similar name there if there is one.
    pub fn read(&self, written: &str) -> Result<File, String> {
        let written = written.trim();
        let plain = written.trim_start_matches("./");
        let last = Path::new(plain)
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        for name in [plain, last.as_str()] {
            if let Some(bytes) = self.given.get(name) {
                return Ok(File {
                    shown: name.to_owned(),
                    bytes: Arc::clone(bytes),
                });
            }
        }
        let Some(base) = &self.disk else {
            return Err(self.missing_from_page(written, &last));
        };
        let path = base.join(written);
        if path.is_file() {
            return std::fs::read(&path)
                .map(|b| File {
                    shown: path.display().to_string(),
                    bytes: b.into(),
                })
                .map_err(|e| format!("cannot read {}: {e}", path.display()));
        }
        let resolved = std::path::absolute(&path).unwrap_or_else(|_| path.clone());
        let here = if base.as_os_str().is_empty() {
            Path::new(".")
        } else {
            base
        };
        let folder = std::path::absolute(here).unwrap_or_else(|_| here.to_path_buf());
        let mut files = path
            .parent()
            .and_then(|dir| std::fs::read_dir(dir).ok())
            .into_iter()
            .flatten()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .collect::<Vec<_>>();
        files.extend(self.given.keys().cloned());
        let hint = nearest(written, &last, &files);
        Err(format!(
            "there is no file {} (paths are relative to the folder of the lesson or scene file, {}){hint}",
            resolved.display(),
            folder.display()
        ))
    }

    /// Why `written` is not among a page's files: which it has, and how to give it one.
    fn missing_from_page(&self, written: &str, last: &str) -> String {
        let names = self.given.keys().cloned().collect::<Vec<_>>();
        let had = if names.is_empty() {
            "none".to_owned()
        } else {
            names.join(", ")
        };
        let hint = nearest(written, last, &names);
        format!(
            "there is no file {written} among the files dropped on the page ({had}): a page \
             cannot read a path, so drop {last} on the page with the lesson{hint}"
        )
    }
}

/// "; did you mean "models/bunny.obj"?" when a name in `files` is like `last`, written as
/// `written` would be.
fn nearest(written: &str, last: &str, files: &[String]) -> String {
    use pipeline::shader::suggest;
    suggest::nearest(last, files.iter().map(String::as_str))
        .map(|n| {
            let beside = Path::new(written).with_file_name(n);
            suggest::hint(&beside.display().to_string(), suggest::Quote::Value)
        })
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn page() -> Folder {
        let mut given = Given::new();
        given.insert("bunny.obj".to_owned(), Arc::from(&b"v 0 0 0"[..]));
        Folder::of_page(given)
    }

    /// A page finds a file it was given by the name a lesson writes, by its last part, and
    /// with a leading `./`.
    #[test]
    fn a_page_finds_a_given_file_by_its_name() {
        for written in [
            "bunny.obj",
            "./bunny.obj",
            "models/bunny.obj",
            " bunny.obj ",
        ] {
            let file = page().read(written).expect(written);
            assert_eq!(file.shown, "bunny.obj");
            assert_eq!(&*file.bytes, b"v 0 0 0");
        }
    }

    /// A file a page was not given: the message says which it has, how to give it the file,
    /// and the similar name.
    #[test]
    fn a_page_says_which_files_it_has() {
        let e = page().read("bunny2.obj").expect_err("not given");
        assert!(
            e.starts_with(
                "there is no file bunny2.obj among the files dropped on the page (bunny.obj)"
            ) && e.contains("drop bunny2.obj on the page with the lesson")
                && e.contains("\"bunny.obj\""),
            "{e}"
        );
        let e = Folder::of_page(Given::new())
            .read("cow.obj")
            .expect_err("nothing given");
        assert!(e.contains("(none)"), "{e}");
    }

    /// On disk a path is relative to the lesson's folder; a missing one names the folder.
    #[test]
    fn on_disk_a_path_is_relative_to_the_folder() {
        let dir = std::env::temp_dir().join(format!("pipelens-folder-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("models")).expect("a folder");
        std::fs::write(dir.join("models/cube.obj"), b"v 1 2 3").expect("a file");
        let folder = Folder::on_disk(&dir);
        let file = folder.read("models/cube.obj").expect("beside the lesson");
        assert_eq!(&*file.bytes, b"v 1 2 3");
        assert!(file.shown.ends_with("cube.obj"));
        let e = folder.read("models/cub.obj").expect_err("a typo");
        assert!(
            e.contains("paths are relative to the folder of the lesson")
                && e.contains("\"models/cube.obj\""),
            "{e}"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
