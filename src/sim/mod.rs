//! The simulator: scene files, the two phases of the fall (wall and floor), an exact reference
//! of the wall phase, hand-written integrators with dense output, and event location.
//!
//! Contents: [`scene`] (TOML scenes; its parts, errors and limits in [`scene_parts`]), [`output`]
//! (what a scene may ask for), [`outcome`] (what a run produces), [`units`] and [`scaled`] (the
//! scene's own units and the conversions of a run),
//! [`rigid`] (phase 1, the note's sec. 2.1), [`floor`] (phase 2, beyond the note), [`exact`]
//! (reference), [`integrators`], [`event`] (crossings refined on the interpolant), [`run`] (the
//! phase driver), [`fall`] (a whole scene; what it watches in `fall_observer`); the `ladder
//! simulate` command lives in `crate::cli`.
//! Stiff and extreme cases: [`penalty`] (the ladder on one-sided springs, beyond the note),
//! [`penalty_confirm`] (when its separation is believed), [`penalty_plan`] (which it could not
//! tell, refused up front) and [`penalty_scene`] (scenes with
//! `contact.model = "penalty"`), [`constrained`] (full coordinates with Lagrange multipliers
//! and their drift), [`extreme`] (the wall phase at the edges of its domain: equilibrium,
//! immediate release, any scale; a tiny start's linear growth in [`lead_in`]), [`complement`]
//! (the wall phase near the floor, in φ = π/2 − θ), [`near_release`] (the wall phase near the
//! release push, in the deviation from the start, with the start's margin from
//! [`start_margin`]).

pub mod complement;
pub mod constrained;
pub mod event;
pub mod exact;
pub mod extreme;
pub mod fall;
mod fall_floor;
mod fall_observer;
mod fall_wall;
pub mod floor;
pub mod impact;
pub mod integrators;
pub mod lead_in;
pub mod minimum;
pub mod near_release;
pub mod outcome;
pub mod output;
pub mod penalty;
pub mod penalty_confirm;
pub mod penalty_plan;
pub mod penalty_run;
pub mod penalty_scene;
pub mod penalty_start;
pub mod rigid;
pub mod run;
pub mod scaled;
pub mod scene;
mod scene_checks;
mod scene_errors;
pub mod scene_parts;
mod scene_shape;
pub mod scene_work;
mod start;
pub mod start_margin;
pub mod trace;
pub mod units;
