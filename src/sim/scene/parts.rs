//! The parts of a scene below its parsing ([`crate::sim::scene`]): where a run ends, the contact
//! model, the limits, and the raw TOML tables. `scene::checks`,
//! `scene::shape` and [`crate::sim::scene::output`] build on these, and `scene` on all of them.

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

/// A scene file as serde reads it: its six sections, each with its span in the file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Raw {
    pub(in crate::sim) ladder: Spanned<RawLadder>,
    pub(in crate::sim) start: Spanned<RawStart>,
    pub(in crate::sim) contact: Spanned<RawContact>,
    pub(in crate::sim) integrator: Spanned<RawIntegrator>,
    pub(in crate::sim) end: Spanned<RawEnd>,
    pub(in crate::sim) outputs: Spanned<RawOutputs>,
}
/// The `[ladder]` section: mass m, half-length l, gravity g.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLadder {
    pub(in crate::sim) mass: Spanned<f64>,
    pub(in crate::sim) half_length: Spanned<f64>,
    pub(in crate::sim) gravity: Spanned<f64>,
}
/// The `[start]` section: θ0 (or its complement π/2 − θ0) and θ̇0.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawStart {
    pub(in crate::sim) angle: Option<Spanned<f64>>,
    /// The start as its complement π/2 − θ0 (exclusive with `angle`; see `scene::start_angle`).
    pub(in crate::sim) angle_from_floor: Option<Spanned<f64>>,
    pub(in crate::sim) angular_velocity: Spanned<f64>,
}
/// The `[contact]` section: the contact model and a penalty's stiffness and damping.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    pub(in crate::sim) model: Spanned<String>,
    pub(in crate::sim) stiffness: Option<Spanned<f64>>,
    pub(in crate::sim) damping: Option<Spanned<f64>>,
}
/// The `[integrator]` section: the method and its tolerance, step or order.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawIntegrator {
    pub(in crate::sim) method: Spanned<String>,
    pub(in crate::sim) tolerance: Option<Spanned<f64>>,
    pub(in crate::sim) step: Option<Spanned<f64>>,
    pub(in crate::sim) scaled_step: Option<Spanned<f64>>,
    pub(in crate::sim) order: Option<Spanned<f64>>,
}
/// The `[end]` section: where the fall ends and an end time.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEnd {
    pub(in crate::sim) at: Spanned<String>,
    pub(in crate::sim) time: Option<Spanned<f64>>,
    pub(in crate::sim) scaled_time: Option<Spanned<f64>>,
}
/// The `[outputs]` section: the outputs wanted.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOutputs {
    pub(in crate::sim) want: Spanned<Vec<Spanned<String>>>,
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
/// (`scene::work`).
pub const MAX_STEPS: u64 = 10_000_000;
