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
    /// What it does, in English and in Chinese.
    pub does: Both,
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
pub const SHORTCUTS: [Shortcut; 25] = [
    Shortcut {
        action: Action::Next,
        keys: &[plain(Key::ArrowRight), plain(Key::PageDown)],
        does: (
            "next step of a lesson (next stage without one)",
            "课程的下一步（无课程时为下一阶段）",
        ),
    },
    Shortcut {
        action: Action::Previous,
        keys: &[plain(Key::ArrowLeft), plain(Key::PageUp)],
        does: ("previous step (previous stage)", "上一步（上一阶段）"),
    },
    Shortcut {
        action: Action::Play,
        keys: &[plain(Key::Space)],
        does: (
            "play or pause the step's animation (replay the transition)",
            "播放或暂停本步动画（重放过渡）",
        ),
    },
    Shortcut {
        action: Action::Narration,
        keys: &[plain(Key::N)],
        does: ("the narration card", "讲解卡片"),
    },
    Shortcut {
        action: Action::Parameters,
        keys: &[plain(Key::P)],
        does: ("the parameters panel", "参数面板"),
    },
    Shortcut {
        action: Action::Inspector,
        keys: &[plain(Key::I)],
        does: (
            "the inspector: matrices, vertices, the pixel explained",
            "检查器：矩阵、顶点、像素解释",
        ),
    },
    Shortcut {
        action: Action::MatrixCard,
        keys: &[plain(Key::M)],
        does: ("the matrix card over the geometry", "几何视图上的矩阵卡片"),
    },
    Shortcut {
        action: Action::Classroom,
        keys: &[plain(Key::C)],
        does: (
            "classroom mode: large type, the picture first",
            "课堂模式：大字号，画面优先",
        ),
    },
    Shortcut {
        action: Action::ShaderEditor,
        keys: &[plain(Key::S)],
        does: ("the shader editor (GLSL)", "着色器编辑器（GLSL）"),
    },
    Shortcut {
        action: Action::ApplyShaders,
        keys: &[command(Key::Enter)],
        does: ("apply the shaders", "应用着色器"),
    },
    Shortcut {
        action: Action::LessonEditor,
        keys: &[plain(Key::R)],
        does: (
            "the lesson editor: record what is on screen as steps, word, arrange",
            "课程编辑器：把屏幕内容录制为步骤，撰写文字，调整顺序",
        ),
    },
    Shortcut {
        action: Action::Save,
        keys: &[command(Key::S)],
        does: (
            "the lesson editor saves its file, whole or not at all",
            "课程编辑器保存文件（要么完整写入，要么不写）",
        ),
    },
    Shortcut {
        action: Action::Redo,
        keys: &[
            KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z),
            command(Key::Y),
        ],
        does: ("the lesson editor redoes", "课程编辑器重做"),
    },
    Shortcut {
        action: Action::Undo,
        keys: &[command(Key::Z)],
        does: ("the lesson editor undoes", "课程编辑器撤销"),
    },
    Shortcut {
        action: Action::StepOver,
        keys: &[plain(Key::F10)],
        does: (
            "shader debugger: next step (a call run whole)",
            "着色器调试器：下一步（整个执行调用）",
        ),
    },
    Shortcut {
        action: Action::StepBack,
        keys: &[shift(Key::F10)],
        does: ("shader debugger: one step back", "着色器调试器：后退一步"),
    },
    Shortcut {
        action: Action::StepInto,
        keys: &[plain(Key::F7)],
        does: (
            "shader debugger: next step, into a call",
            "着色器调试器：下一步，进入调用",
        ),
    },
    Shortcut {
        action: Action::StepOut,
        keys: &[shift(Key::F7)],
        does: (
            "shader debugger: out of this function",
            "着色器调试器：跳出此函数",
        ),
    },
    Shortcut {
        action: Action::RunToCursor,
        keys: &[command(Key::F10)],
        does: (
            "shader debugger: run to the cursor's line",
            "着色器调试器：运行到光标所在行",
        ),
    },
    Shortcut {
        action: Action::Continue,
        keys: &[plain(Key::F8)],
        does: (
            "shader debugger: on to the next breakpoint",
            "着色器调试器：继续到下一个断点",
        ),
    },
    Shortcut {
        action: Action::ContinueBack,
        keys: &[shift(Key::F8)],
        does: (
            "shader debugger: back to the previous breakpoint",
            "着色器调试器：倒退到上一个断点",
        ),
    },
    Shortcut {
        action: Action::Breakpoint,
        keys: &[plain(Key::F9)],
        does: (
            "shader debugger: a breakpoint on the cursor's line (or off); a click on a line number too",
            "着色器调试器：在光标所在行设置或取消断点；单击行号亦可",
        ),
    },
    Shortcut {
        action: Action::FullScreen,
        keys: &[plain(Key::F11)],
        does: ("full screen", "全屏"),
    },
    Shortcut {
        action: Action::TextSize,
        keys: &[command(Key::Plus), command(Key::Minus)],
        does: ("text size", "字号"),
    },
    Shortcut {
        action: Action::Keys,
        keys: &[plain(Key::F1), plain(Key::Questionmark)],
        does: ("this list", "本列表"),
    },
];

/// Words in English and in Chinese.
type Both = (&'static str, &'static str);

/// What the mouse does, for the help beside the keys: how the help writes it, in English and
/// in Chinese, and what it does, in both.
pub const MOUSE: [(Both, Both); 2] = [
    (
        ("wheel, drag", "滚轮、拖动"),
        (
            "zoom at the cursor, pan (geometry: orbit)",
            "以光标为中心缩放、平移（几何视图：环绕）",
        ),
    ),
    (
        ("click", "单击"),
        ("select a pixel or a vertex", "选择像素或顶点"),
    ),
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

/// Whether one of `action`'s keys was pressed this frame. A key with modifiers is consumed, so
/// that nothing else acts on it too. A key with none counts with no Ctrl, Alt, Command or Shift
/// held (the key's own modifiers, not those at the end of the frame: a Ctrl+S whose Ctrl is let
/// go within the frame is still Ctrl+S, not S) — nor Shift for a function key, whose Shift+ is
/// another action —, and, unless it is a function key, only while
/// no text box has the keyboard: the debugger's F10 steps while the cursor is in the source.
#[must_use]
pub fn pressed(ctx: &Context, action: Action) -> bool {
    of(action).keys.iter().any(|k| {
        if k.modifiers.is_none() {
            (function_key(k.logical_key) || !ctx.egui_wants_keyboard_input())
                && ctx.input(|i| {
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

    /// Only F1 … F35 are function keys: a letter or an arrow is not, though its name starts
    /// with an F or holds digits.
    #[test]
    fn function_keys_are_f_and_a_number() {
        assert!(function_key(Key::F1) && function_key(Key::F10) && function_key(Key::F35));
        assert!(!function_key(Key::F) && !function_key(Key::Num1) && !function_key(Key::Space));
    }
}
