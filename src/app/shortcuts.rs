//! The keyboard's shortcuts in one table ([`SHORTCUTS`]): each listener asks it whether its
//! action's keys were pressed ([`pressed`]), and the help (F1) prints it, so a key cannot work
//! unlisted, be listed and do nothing, or do two things.

use egui::{Context, Key, KeyboardShortcut, Modifiers};

/// What a shortcut does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// The next step of a lesson (the next stage without one).
    Next,
    /// The previous step (the previous stage).
    Previous,
    /// Play or pause the step's animation (replay the transition).
    Play,
    /// Show or hide the narration card.
    Narration,
    /// Show or hide the parameters panel.
    Parameters,
    /// Show or hide the inspector.
    Inspector,
    /// Show or hide the matrix card over the geometry.
    MatrixCard,
    /// Classroom mode on or off.
    Classroom,
    /// Show or hide the shader editor.
    ShaderEditor,
    /// Open or close the lesson editor.
    LessonEditor,
    /// The lesson editor saves its file.
    Save,
    /// The lesson editor undoes its last edit.
    Undo,
    /// The lesson editor redoes the edit undone.
    Redo,
    /// The shader editor compiles and draws with its shaders.
    ApplyShaders,
    /// The shader debugger: one step back.
    StepBack,
    /// The shader debugger: the next step, a call run whole.
    StepOver,
    /// The shader debugger: the next step, into a call.
    StepInto,
    /// The shader debugger: out of the function shown.
    StepOut,
    /// The shader debugger: on to the cursor's line.
    RunToCursor,
    /// The shader debugger: on to the next breakpoint.
    Continue,
    /// The shader debugger: back to the previous breakpoint.
    ContinueBack,
    /// The shader debugger: a breakpoint on the cursor's line, or none.
    Breakpoint,
    /// Full screen on or off.
    FullScreen,
    /// Larger or smaller text (egui's own zoom listens for these keys).
    TextSize,
    /// The keyboard to the main picture, then to the one beside it, then back to the steps
    /// (`views::picture_keys`).
    FocusView,
    /// Show or hide this list.
    Keys,
}

/// One shortcut: what it does, the keys that do it (any of them) and its words in the help.
pub struct Shortcut {
    /// What it does.
    pub action: Action,
    /// The keys, each with the modifiers it needs; a key with none works only while no text
    /// box has the keyboard.
    pub keys: &'static [KeyboardShortcut],
    /// What it does: its message in the catalogs (`locales/`).
    pub does: &'static str,
}

const fn plain(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::NONE, key)
}

const fn command(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::COMMAND, key)
}

const fn shift(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::SHIFT, key)
}

/// Every shortcut, in the order the help lists them. Redo comes before Undo: Ctrl+Shift+Z
/// holds Ctrl+Z's keys too, so it is asked first.
pub const SHORTCUTS: [Shortcut; 26] = [
    Shortcut {
        action: Action::Next,
        keys: &[plain(Key::ArrowRight), plain(Key::PageDown)],
        does: "shortcuts-next-step-of-a-lesson",
    },
    Shortcut {
        action: Action::Previous,
        keys: &[plain(Key::ArrowLeft), plain(Key::PageUp)],
        does: "shortcuts-previous-step-previous-stage",
    },
    Shortcut {
        action: Action::Play,
        keys: &[plain(Key::Space)],
        does: "shortcuts-play-or-pause-the-step",
    },
    Shortcut {
        action: Action::Narration,
        keys: &[plain(Key::N)],
        does: "shortcuts-the-narration-card",
    },
    Shortcut {
        action: Action::Parameters,
        keys: &[plain(Key::P)],
        does: "shortcuts-the-parameters-panel",
    },
    Shortcut {
        action: Action::Inspector,
        keys: &[plain(Key::I)],
        does: "shortcuts-the-inspector-matrices-vertices-the",
    },
    Shortcut {
        action: Action::MatrixCard,
        keys: &[plain(Key::M)],
        does: "shortcuts-the-matrix-card-over-the",
    },
    Shortcut {
        action: Action::Classroom,
        keys: &[plain(Key::C)],
        does: "shortcuts-classroom-mode-large-type-the",
    },
    Shortcut {
        action: Action::ShaderEditor,
        keys: &[plain(Key::S)],
        does: "shortcuts-the-shader-editor-glsl",
    },
    Shortcut {
        action: Action::ApplyShaders,
        keys: &[command(Key::Enter)],
        does: "shortcuts-apply-the-shaders",
    },
    Shortcut {
        action: Action::LessonEditor,
        keys: &[plain(Key::R)],
        does: "shortcuts-the-lesson-editor-record-what",
    },
    Shortcut {
        action: Action::Save,
        keys: &[command(Key::S)],
        does: "shortcuts-the-lesson-editor-saves-its",
    },
    Shortcut {
        action: Action::Redo,
        keys: &[
            KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z),
            command(Key::Y),
        ],
        does: "shortcuts-the-lesson-editor-redoes",
    },
    Shortcut {
        action: Action::Undo,
        keys: &[command(Key::Z)],
        does: "shortcuts-the-lesson-editor-undoes",
    },
    Shortcut {
        action: Action::StepOver,
        keys: &[plain(Key::F10)],
        does: "shortcuts-shader-debugger-next-step-a",
    },
    Shortcut {
        action: Action::StepBack,
        keys: &[shift(Key::F10)],
        does: "shortcuts-shader-debugger-one-step-back",
    },
    Shortcut {
        action: Action::StepInto,
        keys: &[plain(Key::F7)],
        does: "shortcuts-shader-debugger-next-step-into",
    },
    Shortcut {
        action: Action::StepOut,
        keys: &[shift(Key::F7)],
        does: "shortcuts-shader-debugger-out-of-this",
    },
    Shortcut {
        action: Action::RunToCursor,
        keys: &[command(Key::F10)],
        does: "shortcuts-shader-debugger-run-to-the",
    },
    Shortcut {
        action: Action::Continue,
        keys: &[plain(Key::F8)],
        does: "shortcuts-shader-debugger-on-to-the",
    },
    Shortcut {
        action: Action::ContinueBack,
        keys: &[shift(Key::F8)],
        does: "shortcuts-shader-debugger-back-to-the",
    },
    Shortcut {
        action: Action::Breakpoint,
        keys: &[plain(Key::F9)],
        does: "shortcuts-shader-debugger-a-breakpoint-on",
    },
    Shortcut {
        action: Action::FullScreen,
        keys: &[plain(Key::F11)],
        does: "shortcuts-full-screen",
    },
    Shortcut {
        action: Action::TextSize,
        keys: &[command(Key::Plus), command(Key::Minus)],
        does: "shortcuts-text-size",
    },
    Shortcut {
        action: Action::FocusView,
        keys: &[plain(Key::V)],
        does: "shortcuts-the-keyboard-to-the-picture",
    },
    Shortcut {
        action: Action::Keys,
        keys: &[plain(Key::F1), plain(Key::Questionmark)],
        does: "shortcuts-this-list",
    },
];

/// What the mouse does, for the help beside the keys: the messages of how the help writes it
/// and of what it does.
pub const MOUSE: [(&str, &str); 2] = [
    ("shortcuts-wheel-drag", "shortcuts-zoom-at-the-cursor-pan"),
    ("shortcuts-click", "shortcuts-select-a-pixel-or-a"),
];

/// What a picture does with the keys while it has the keyboard (V, or Tab; a ring shows it),
/// for the help: the keys as the help writes them (the same in every language) and the message
/// of what they do. `views::picture_keys` reads these keys.
pub const IN_A_PICTURE: [(&str, &str); 4] = [
    ("← → ↑ ↓", "shortcuts-in-the-picture-the-inspected"),
    ("+  −", "shortcuts-in-the-picture-zoom"),
    ("[  ]", "shortcuts-in-a-geometry-view-the"),
    ("Esc", "shortcuts-the-keyboard-back-from-the"),
];

/// The shortcut of `action`.
#[must_use]
pub fn of(action: Action) -> &'static Shortcut {
    SHORTCUTS
        .iter()
        .find(|s| s.action == action)
        .expect("every action stands in the table (a test checks it)")
}

/// Whether `modifiers` leave `key` a plain press: no Ctrl, Alt or Command, nor Shift on a
/// function key (Shift+F10 is another action; Shift on `?` is how it is typed).
fn plain_press(modifiers: egui::Modifiers, key: Key) -> bool {
    !(modifiers.ctrl
        || modifiers.alt
        || modifiers.command
        || (modifiers.shift && function_key(key)))
}

/// Whether `key` is a function key (F1 …), which types nothing into a text box.
fn function_key(key: Key) -> bool {
    let name = key.name();
    name.len() > 1 && name.starts_with('F') && name[1..].chars().all(|c| c.is_ascii_digit())
}

/// Whether a focused widget acts on `key` itself: the arrows (a slider's value, a picture's
/// pixel, egui's own move of the focus), Space and Enter (a button's click), Tab and Escape.
fn widget_key(key: Key) -> bool {
    matches!(
        key,
        Key::ArrowLeft
            | Key::ArrowRight
            | Key::ArrowUp
            | Key::ArrowDown
            | Key::Space
            | Key::Enter
            | Key::Tab
            | Key::Escape
    )
}

/// Whether a plain press of `key` is the window's shortcut, given what has the keyboard: a
/// function key always (the debugger's F10 steps while the cursor is in the source); any other
/// key never while a text box has it (it types); and while another widget has the focus (a
/// button, a slider, a picture reached by Tab or V), every key but the ones that widget acts on
/// itself, so that N, I or Page Down still work from a focused button.
fn plain_key_is_ours(key: Key, (text_box, focused): (bool, bool)) -> bool {
    function_key(key) || !(text_box || (focused && widget_key(key)))
}

/// Whether one of `action`'s keys was pressed this frame. A key with modifiers is consumed, so
/// that nothing else acts on it too. A key with none counts with no Ctrl, Alt, Command or Shift
/// held (the key's own modifiers, not those at the end of the frame: a Ctrl+S whose Ctrl is let
/// go within the frame is still Ctrl+S, not S) — nor Shift for a function key, whose Shift+ is
/// another action —, and as [`plain_key_is_ours`] says given what has the keyboard.
#[must_use]
pub fn pressed(ctx: &Context, action: Action) -> bool {
    of(action).keys.iter().any(|k| {
        if k.modifiers.is_none() {
            plain_key_is_ours(
                k.logical_key,
                (ctx.text_edit_focused(), ctx.egui_wants_keyboard_input()),
            ) && ctx.input(|i| {
                i.events.iter().any(|e| {
                    matches!(e, egui::Event::Key { key, pressed: true, modifiers, .. }
                            if *key == k.logical_key && plain_press(*modifiers, *key))
                })
            })
        } else {
            ctx.input_mut(|i| i.consume_shortcut(k))
        }
    })
}

/// How the help writes a key: `Ctrl+` before the key, arrows as arrows.
#[must_use]
pub fn written(k: &KeyboardShortcut) -> String {
    let key = match k.logical_key {
        Key::ArrowRight => "→",
        Key::ArrowLeft => "←",
        Key::PageDown => "Page Down",
        Key::PageUp => "Page Up",
        Key::Minus => "−",
        other => other.symbol_or_name(),
    };
    let mut s = String::new();
    if k.modifiers.command || k.modifiers.ctrl {
        s.push_str("Ctrl+");
    }
    if k.modifiers.shift {
        s.push_str("Shift+");
    }
    s.push_str(key);
    s
}

/// How the help writes all of a shortcut's keys.
#[must_use]
pub fn keys_written(s: &Shortcut) -> String {
    s.keys.iter().map(written).collect::<Vec<_>>().join("  ")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each action once in the table, each key for one action only, and every action with keys.
    #[test]
    fn each_action_and_each_key_stands_once_in_the_table() {
        let actions = [
            Action::Next,
            Action::Previous,
            Action::Play,
            Action::Narration,
            Action::Parameters,
            Action::Inspector,
            Action::MatrixCard,
            Action::Classroom,
            Action::ShaderEditor,
            Action::LessonEditor,
            Action::Save,
            Action::Undo,
            Action::Redo,
            Action::ApplyShaders,
            Action::StepBack,
            Action::StepOver,
            Action::StepInto,
            Action::StepOut,
            Action::RunToCursor,
            Action::Continue,
            Action::ContinueBack,
            Action::Breakpoint,
            Action::FullScreen,
            Action::TextSize,
            Action::FocusView,
            Action::Keys,
        ];
        assert_eq!(actions.len(), SHORTCUTS.len());
        for a in actions {
            let n = SHORTCUTS.iter().filter(|s| s.action == a).count();
            assert_eq!(n, 1, "{a:?} stands {n} times");
            assert!(!of(a).keys.is_empty(), "{a:?} has no key");
        }
        let keys: Vec<&KeyboardShortcut> = SHORTCUTS.iter().flat_map(|s| s.keys).collect();
        for (i, k) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(k), "{k:?} does two things");
        }
    }

    /// The help writes the keys as a reader types them.
    #[test]
    fn the_help_writes_the_keys_as_typed() {
        assert_eq!(keys_written(of(Action::Next)), "→  Page Down");
        assert_eq!(keys_written(of(Action::Redo)), "Ctrl+Shift+Z  Ctrl+Y");
        assert_eq!(keys_written(of(Action::Keys)), "F1  ?");
        assert_eq!(keys_written(of(Action::TextSize)), "Ctrl++  Ctrl+−");
        assert_eq!(keys_written(of(Action::StepBack)), "Shift+F10");
        assert_eq!(keys_written(of(Action::RunToCursor)), "Ctrl+F10");
    }

    /// A text box keeps every key but the function keys; a focused button or picture keeps the
    /// arrows, Space and Enter, and leaves the letters and Page Down to the window.
    #[test]
    fn a_focused_widget_keeps_only_the_keys_it_acts_on() {
        let (none, button, text) = ((false, false), (false, true), (true, true));
        for key in [Key::ArrowRight, Key::Space, Key::N, Key::PageDown, Key::F10] {
            assert!(plain_key_is_ours(key, none), "{key:?} with nothing focused");
        }
        for key in [Key::N, Key::PageDown, Key::V, Key::F1] {
            assert!(
                plain_key_is_ours(key, button),
                "{key:?} beside a focused button"
            );
        }
        for key in [Key::ArrowRight, Key::ArrowUp, Key::Space, Key::Enter] {
            assert!(!plain_key_is_ours(key, button), "{key:?} is the button's");
        }
        assert!(!plain_key_is_ours(Key::N, text) && !plain_key_is_ours(Key::PageDown, text));
        assert!(plain_key_is_ours(Key::F10, text));
    }

    /// Only F1 … F35 are function keys: a letter or an arrow is not, though its name starts
    /// with an F or holds digits.
    #[test]
    fn function_keys_are_f_and_a_number() {
        assert!(function_key(Key::F1) && function_key(Key::F10) && function_key(Key::F35));
        assert!(!function_key(Key::F) && !function_key(Key::Num1) && !function_key(Key::Space));
    }
}
