//! The parts of a scene below its parsing ([`super::scene`]): where a run ends, the contact
//! model, the limits, and the raw TOML tables. `scene_checks`,
//! `scene_shape` and [`super::output`] build on these, and `scene` on all of them.

use serde::Deserialize;
use toml::Spanned;

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
    pub(super) angle: Option<Spanned<f64>>,
    /// The start as its complement π/2 − θ0 (exclusive with `angle`; see `scene::start_angle`).
    pub(super) angle_from_floor: Option<Spanned<f64>>,
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
    pub(super) order: Option<Spanned<f64>>,
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
/// Hard limit on the steps of one phase; a scene that would need more is refused up front
/// (`scene_work`).
pub const MAX_STEPS: u64 = 10_000_000;
