//! Scene files (TOML) and their validation. Every problem becomes one [`SceneError`] naming the
//! file, the line (from toml's spans) and the field, and saying what is allowed.
//!
//! Schema (DESIGN.md, "Scenes"): `[ladder] mass half_length gravity`, `[start] angle
//! angular_velocity`, `[contact] model (stiffness damping)`, `[integrator] method tolerance|step`,
//! `[end] at (time)`, `[outputs] want`. Unknown keys are errors.

use super::integrators::Control;
use super::output::Output;
use super::rigid::Ladder;
use super::scaled::Units;
use super::scene_checks::{
    check_contact, check_end, check_integrator, check_outputs, check_penalty,
};
use serde::Deserialize;
use std::fmt;
use std::path::Path;
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

/// A validated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The file it came from.
    pub file: String,
    /// m, l, g.
    pub ladder: Ladder,
    /// θ0, rad.
    pub theta0: f64,
    /// θ̇0, rad/s.
    pub rate0: f64,
    /// Integrator name (one of [`METHODS`] or `exact`).
    pub method: String,
    /// Step or tolerance (None for `exact`).
    pub control: Option<Control>,
    /// Where the run ends.
    pub end: End,
    /// The outputs asked for, in the order given.
    pub outputs: Vec<Output>,
    /// Rigid contacts or penalty springs.
    pub contact: ContactModel,
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

pub(super) struct Ctx<'a> {
    file: &'a str,
    text: &'a str,
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
    fn field_at(&self, pos: usize) -> String {
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

/// Read and validate the scene at `path`.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SceneError {
        file: file.clone(),
        line: None,
        field: "file".into(),
        message: format!("cannot read the scene: {e}"),
    })?;
    parse(&file, &text)
}

/// Validate the scene text `text` read from `file`.
pub fn parse(file: &str, text: &str) -> Result<Scene, SceneError> {
    let cx = Ctx { file, text };
    let raw: Raw = toml::from_str(text).map_err(|e| {
        let field = e
            .span()
            .map_or_else(|| "scene".to_string(), |s| cx.field_at(s.start));
        cx.err(e.span(), &field, e.message().trim().to_string())
    })?;
    let l = raw.ladder.get_ref();
    // Any scale from 1e-30 to 1e30: the simulator is checked to give the same angles, times
    // scaled by √(l/g) and forces by m g over that whole range (`ladder stability`).
    let positive = |x: f64| (1e-30..=1e30).contains(&x);
    let ladder = Ladder {
        mass: cx.number(
            &l.mass,
            "ladder.mass",
            positive,
            "a number > 0 (kg) in [1e-30, 1e30]",
        )?,
        half_length: cx.number(
            &l.half_length,
            "ladder.half_length",
            positive,
            "a number > 0 (m) in [1e-30, 1e30]",
        )?,
        gravity: cx.number(
            &l.gravity,
            "ladder.gravity",
            positive,
            "a number > 0 (m/s²) in [1e-30, 1e30]",
        )?,
    };
    let s = raw.start.get_ref();
    let theta0 = cx.number(
        &s.angle,
        "start.angle",
        |x| (0.0..std::f64::consts::FRAC_PI_2).contains(&x),
        "an angle in [0, π/2) rad",
    )?;
    let rate0 = cx.number(
        &s.angular_velocity,
        "start.angular_velocity",
        |x| x >= 0.0,
        "a number >= 0 (rad/s)",
    )?;
    let omega2 = ladder.omega2();
    if rate0 * rate0 >= omega2 * theta0.cos() {
        let max = (omega2 * theta0.cos()).sqrt();
        return Err(cx.err(Some(s.angular_velocity.span()), "start.angular_velocity", format!(
            "{rate0} rad/s is too fast: the wall would have to pull at the start; allowed: below sqrt(3g cos θ0 / 4l) = {max}"
        )));
    }
    let contact = check_contact(&cx, raw.contact.get_ref(), &ladder)?;
    // The scene's time unit √(l/g): steps and end times are limited in it (see `sim::scaled`).
    let unit = Units::of(&ladder).time;
    let (method, control) = check_integrator(&cx, raw.integrator.get_ref(), unit)?;
    let end = check_end(&cx, raw.end.get_ref(), unit)?;
    if theta0 == 0.0 && rate0 == 0.0 && !matches!(end, End::Time(_)) {
        return Err(cx.err(Some(s.angle.span()), "start", "θ0 = 0 with θ̇0 = 0 is the equilibrium: the ladder never leaves the wall; give angle > 0 or angular_velocity > 0"));
    }
    let outputs = check_outputs(&cx, raw.outputs.get_ref(), &method, end)?;
    if let ContactModel::Penalty { .. } = contact {
        check_penalty(&cx, &raw, &method, end, &outputs)?;
    }
    Ok(Scene {
        file: file.to_string(),
        ladder,
        theta0,
        rate0,
        method,
        control,
        end,
        outputs,
        contact,
    })
}
