//! The lesson editor (issue 36; R, or "Edit this lesson…" in the Lessons menu): a teacher builds a
//! lesson by clicking. Its panel, docked at the right beside the view, lists the steps (those
//! changed since the last save marked), moves, copies and deletes them, words the current step in
//! English and Chinese side by side with the card's typeset preview, records what is on screen as a
//! new step or into the current one (a slider dragged while the editor is open becomes an `animate`
//! entry), undoes and redoes every edit, and saves the file whole or not at all. Unsaved edits are
//! kept in a recovery copy beside the file and offered at the next open; a file changed on disk
//! meanwhile is not overwritten without asking. A new lesson starts from the scene on screen, a
//! built-in lesson, or a mesh of one's own (`new.rs`).

mod file;
mod file_actions;
mod new;
mod screen;
mod window;
mod words;

pub use new::From;
pub use window::Editor;
