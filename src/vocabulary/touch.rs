//! The lessons' words on a touch screen. A lesson is written for a keyboard and a mouse ("press
//! Space", "click a pixel", "the inspector on the right", "the Shader panel (key S)"); a phone
//! or a tablet has no keys and lays its panels out differently (`app::compact`): there the same
//! sentence names the gesture and the button instead ("tap ▶ Play", "tap a pixel", "Menu → Show
//! → Inspector"). The lesson's file stays as its author wrote it; the words change where they
//! are shown.

use std::borrow::Cow;

/// Each keyboard-and-mouse phrase of the lessons and catalogs (English and Chinese), and what
/// a touch screen says instead: the longer phrase first, where one holds another. A phrase
/// that starts or ends with a Latin letter matches only a whole word there ("click" is not
/// "clicking").
const PHRASES: [(&str, &str); 16] = [
    ("press Space", "tap ▶ Play"),
    (
        "Press → to",
        "Swipe the narration left (or tap ▶ at the top) to",
    ),
    ("Press **S**", "Tap **Code** at the top"),
    ("(key S)", "(the Code tab at the top)"),
    (
        "in the inspector on the right",
        "in the inspector (Menu → Show → Inspector)",
    ),
    ("Click", "Tap"),
    ("click", "tap"),
    ("clicks", "taps"),
    ("按空格键", "点「▶ 播放」"),
    ("按 → ", "在讲解上向左滑动（或点上方的 ▶）"),
    ("按 **S**", "点顶部的**代码**"),
    ("（S 键）", "（顶部的「代码」标签）"),
    ("（空格）", "（「▶ 播放」）"),
    ("右侧的检查器", "检查器（菜单 → 显示 → 检查器）"),
    ("单击", "点按"),
    ("点击", "点按"),
];

/// `text` as a touch screen says it when `touch` (see [`PHRASES`]); as written otherwise.
#[must_use]
pub fn for_device(text: &str, touch: bool) -> Cow<'_, str> {
    if !touch {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    let mut rest = text;
    let mut changed = false;
    'scan: while let Some(c) = rest.chars().next() {
        let before = out.chars().next_back();
        for (keys, touch) in PHRASES {
            if let Some(after) = rest.strip_prefix(keys)
                && whole(keys, before, after.chars().next())
            {
                out.push_str(touch);
                rest = after;
                changed = true;
                continue 'scan;
            }
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    if changed {
        Cow::Owned(out)
    } else {
        Cow::Borrowed(text)
    }
}

/// Whether `phrase`, found between the characters `before` and `after`, is whole: a Latin
/// letter at either end of it may not run on into another.
fn whole(phrase: &str, before: Option<char>, after: Option<char>) -> bool {
    let letter = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphabetic());
    let starts = letter(phrase.chars().next());
    let ends = letter(phrase.chars().next_back());
    !(starts && letter(before) || ends && letter(after))
}

#[cfg(test)]
mod tests {
    use super::for_device;

    /// The tour's first step and a predicting question, as a phone says them: each sentence
    /// rewritten by hand from the lesson's words.
    #[test]
    fn the_keys_become_gestures_and_buttons() {
        assert_eq!(
            for_device(
                "Press → to follow the data from the start.\n\nClick any pixel to see, in the \
                 inspector on the right, every fragment that reached it.",
                true
            ),
            "Swipe the narration left (or tap ▶ at the top) to follow the data from the \
             start.\n\nTap any pixel to see, in the inspector (Menu → Show → Inspector), every \
             fragment that reached it."
        );
        assert_eq!(
            for_device("Predict before you press Space: the cube turns.", true),
            "Predict before you tap ▶ Play: the cube turns."
        );
        assert_eq!(
            for_device("按 → 从头跟随数据。单击任意像素，右侧的检查器会列出", true),
            "在讲解上向左滑动（或点上方的 ▶）从头跟随数据。点按任意像素，检查器（菜单 → 显示 → 检查器）会列出"
        );
        assert_eq!(
            for_device("着色器面板（S 键）中的片元着色器", true),
            "着色器面板（顶部的「代码」标签）中的片元着色器"
        );
        assert_eq!(
            for_device("the Shader panel (key S): Press **S**.", true),
            "the Shader panel (the Code tab at the top): Tap **Code** at the top."
        );
        assert_eq!(
            for_device("a click on a line number, two clicks", true),
            "a tap on a line number, two taps"
        );
    }

    /// Only whole words change, and nothing changes with a keyboard.
    #[test]
    fn words_stay_whole_and_keyboards_keep_their_words() {
        for text in ["clicking", "Clickable", "declicks", "the lens"] {
            assert_eq!(for_device(text, true), text);
        }
        let text = "Press → to follow; click a pixel.";
        assert!(matches!(for_device(text, false), std::borrow::Cow::Borrowed(t) if t == text));
    }
}
