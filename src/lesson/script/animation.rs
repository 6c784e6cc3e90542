//! A step's `animate = [{ param, from, to, seconds, easing, repeat }]`, checked against the
//! scene as the steps before it left it.

use toml::Spanned;

use super::super::SceneSpec;
use super::super::param::{self, Animation, Easing, Repeat, Value};
use super::super::raw::RawAnimate;
use super::super::validate::Checker;

impl Checker<'_> {
    pub(super) fn animation(
        &mut self,
        a: &Spanned<RawAnimate>,
        spec: &SceneSpec,
    ) -> Option<Animation> {
        let r = a.get_ref();
        let from = self.value(&r.from)?;
        let to = self.value(&r.to)?;
        let same_kind = matches!(
            (&from, &to),
            (Value::Number(_), Value::Number(_))
                | (Value::Vec2(_), Value::Vec2(_))
                | (Value::Vec3(_), Value::Vec3(_))
                | (Value::Vec4(_), Value::Vec4(_))
        );
        if !same_kind {
            self.error(
                r.to.span(),
                "`from` and `to` must both be numbers or both vectors of the same length ([x, y, z]): only those can move",
            );
            return None;
        }
        let seconds = *r.seconds.get_ref();
        if !(seconds > 0.0 && seconds <= 600.0) {
            self.error(
                r.seconds.span(),
                format!("`seconds` must be more than 0 and at most 600, got {seconds}"),
            );
            return None;
        }
        let name = r.param.get_ref();
        for (end, span) in [(&from, r.from.span()), (&to, r.to.span())] {
            let mut probe = spec.clone();
            if let Err(e) = param::apply(&mut probe, name, end) {
                let span = if e.starts_with("unknown parameter") {
                    r.param.span()
                } else {
                    span
                };
                self.error(span, e);
                return None;
            }
        }
        let easing = match &r.easing {
            Some(v) => self.choice("easing", v, &Easing::NAMES)?,
            None => Easing::DEFAULT,
        };
        let repeat = match &r.repeat {
            Some(v) => self.choice("repeat", v, &Repeat::NAMES)?,
            None => Repeat::DEFAULT,
        };
        Some(Animation {
            param: name.clone(),
            from,
            to,
            seconds: seconds as f32,
            easing,
            repeat,
        })
    }
}
