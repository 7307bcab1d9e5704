//! The parts of a scene below its parsing ([`super::scene`]): the error a bad scene gives, where
//! a run ends, the contact model, the limits, and the raw TOML tables with the context that
//! places an error at its file, line and field. [`super::scene_checks`] and [`super::output`]
//! build on these, and `scene` on all of them.

use serde::Deserialize;
use std::fmt;
use toml::Spanned;

/// A bad scene: one line for the user.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    /// The scene file as given.
    pub file: String,
    /// 1-based line, where the problem has one.
    pub line: Option<usize>,
    /// The field, as `section.key`.
    pub field: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(l) => write!(f, "{}:{}: {}: {}", self.file, l, self.field, self.message),
            None => write!(f, "{}: {}: {}", self.file, self.field, self.message),
        }
    }
}

/// Where the ladder run ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// When the wall force reaches zero.
    Separation,
    /// When the ladder lies flat (θ = π/2), through the floor phase.
    Flat,
    /// At a given time (s), through whatever phases come first.
    Time(f64),
}

/// The contact model of a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactModel {
    /// Rigid, frictionless wall and floor (constraints): the note's model.
    Rigid,
    /// One-sided springs (see `sim::penalty`).
    Penalty {
        /// k, N/m.
        stiffness: f64,
        /// c, N·s/m.
        damping: f64,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Raw {
    pub(super) ladder: Spanned<RawLadder>,
    pub(super) start: Spanned<RawStart>,
    pub(super) contact: Spanned<RawContact>,
    pub(super) integrator: Spanned<RawIntegrator>,
    pub(super) end: Spanned<RawEnd>,
    pub(super) outputs: Spanned<RawOutputs>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawLadder {
    pub(super) mass: Spanned<f64>,
    pub(super) half_length: Spanned<f64>,
    pub(super) gravity: Spanned<f64>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawStart {
    pub(super) angle: Spanned<f64>,
    pub(super) angular_velocity: Spanned<f64>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawContact {
    pub(super) model: Spanned<String>,
    pub(super) stiffness: Option<Spanned<f64>>,
    pub(super) damping: Option<Spanned<f64>>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawIntegrator {
    pub(super) method: Spanned<String>,
    pub(super) tolerance: Option<Spanned<f64>>,
    pub(super) step: Option<Spanned<f64>>,
    pub(super) scaled_step: Option<Spanned<f64>>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawEnd {
    pub(super) at: Spanned<String>,
    pub(super) time: Option<Spanned<f64>>,
    pub(super) scaled_time: Option<Spanned<f64>>,
}
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOutputs {
    pub(super) want: Spanned<Vec<Spanned<String>>>,
}

/// Smallest tolerance accepted (below it f64 rounding dominates any error estimate).
pub const MIN_TOLERANCE: f64 = 1e-16;
/// Smallest fixed step accepted, in units of √(l/g) (a fall takes a few: more steps than this
/// allows is absurd).
pub const MIN_STEP: f64 = 1e-6;
/// Longest fixed step accepted, in units of √(l/g) (the event-safe step is 0.58 of it at rest).
pub const MAX_STEP: f64 = 1.0;
/// Longest end time accepted, in units of √(l/g).
pub const MAX_END_TIME: f64 = 1e4;

/// Where a scene's text came from, to place its errors (file, line, field).
pub(super) struct Ctx<'a> {
    pub(super) file: &'a str,
    pub(super) text: &'a str,
}

impl Ctx<'_> {
    fn line_of(&self, pos: usize) -> usize {
        self.text[..pos.min(self.text.len())]
            .bytes()
            .filter(|&b| b == b'\n')
            .count()
            + 1
    }
    pub(super) fn err(
        &self,
        span: Option<std::ops::Range<usize>>,
        field: &str,
        message: impl Into<String>,
    ) -> SceneError {
        SceneError {
            file: self.file.to_string(),
            line: span.map(|s| self.line_of(s.start)),
            field: field.to_string(),
            message: message.into().replace('\n', " "),
        }
    }
    /// A finite number in the range `ok`, described by `allowed`.
    pub(super) fn number(
        &self,
        v: &Spanned<f64>,
        field: &str,
        ok: impl Fn(f64) -> bool,
        allowed: &str,
    ) -> Result<f64, SceneError> {
        let x = *v.get_ref();
        let x_text = if x != 0.0 && (x.abs() < 1e-4 || x.abs() >= 1e6) {
            format!("{x:e}")
        } else {
            format!("{x}")
        };
        if !x.is_finite() {
            return Err(self.err(
                Some(v.span()),
                field,
                format!("{x} is not a finite number; allowed: {allowed}"),
            ));
        }
        if !ok(x) {
            return Err(self.err(
                Some(v.span()),
                field,
                format!("{x_text} is out of range; allowed: {allowed}"),
            ));
        }
        Ok(x)
    }
    /// A duration given either in seconds (`keys.0`) or in units of √(l/g) = `unit` s
    /// (`keys.1`), at most one of them; `ok` judges it in units of √(l/g). Returns it in
    /// seconds with the span of the key that gave it.
    pub(super) fn time_like(
        &self,
        seconds: Option<&Spanned<f64>>,
        scaled: Option<&Spanned<f64>>,
        keys: (&str, &str),
        unit: f64,
        ok: impl Fn(f64) -> bool,
        allowed: &str,
    ) -> Result<Option<(f64, std::ops::Range<usize>)>, SceneError> {
        match (seconds, scaled) {
            (Some(_), Some(b)) => Err(self.err(
                Some(b.span()),
                keys.1,
                format!("give {} or {}, not both", keys.0, keys.1),
            )),
            (Some(v), None) => {
                let x = self.number(v, keys.0, |x| ok(x / unit), allowed)?;
                Ok(Some((x, v.span())))
            }
            (None, Some(v)) => {
                let x = self.number(v, keys.1, &ok, allowed)?;
                Ok(Some((x * unit, v.span())))
            }
            (None, None) => Ok(None),
        }
    }
    /// The `section.key` around byte `pos` (for toml's own errors, which carry a span only).
    pub(super) fn field_at(&self, pos: usize) -> String {
        let before = &self.text[..pos.min(self.text.len())];
        let section = before
            .lines()
            .rev()
            .find_map(|l| {
                let l = l.trim();
                (l.starts_with('[') && l.ends_with(']'))
                    .then(|| l.trim_matches(|c| c == '[' || c == ']').trim().to_string())
            })
            .unwrap_or_default();
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let line = self.text[line_start..].lines().next().unwrap_or("");
        let key = line.split('=').next().unwrap_or("").trim();
        match (section.is_empty(), key.is_empty() || key.starts_with('[')) {
            (true, _) => key.to_string(),
            (false, true) => section,
            (false, false) => format!("{section}.{key}"),
        }
    }
}
