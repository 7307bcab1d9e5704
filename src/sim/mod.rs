//! The simulator: scene files, the two phases of the fall (wall and floor), an exact reference
//! of the wall phase, hand-written integrators with dense output, and event location.
//!
//! Contents, by concept (ARCHITECTURE.md, "Where a concept lives"): [`scene`] (a TOML scene:
//! its parts, start, outputs, refusals and the work its outputs need), [`outcome`] (what a run
//! produces), [`units`] and [`scaled`] (the scene's own units and the conversions of a run),
//! [`rigid`] (phase 1, the note's sec. 2.1), [`floor`] (phase 2, beyond the note), [`exact`]
//! (reference), [`integrators`], [`event`] (crossings refined on the interpolant), [`run`] (the
//! phase driver), [`fall`] (a whole scene, rigid or with the penalty contact), [`impact`] (the
//! top's impact on the floor and the slide lying flat); the `ladder simulate` command lives in
//! `crate::cli`. Stiff and extreme cases: [`penalty`] (the ladder on one-sided springs, beyond
//! the note: its plan, start, run and when its separation is believed), [`constrained`] (full
//! coordinates with Lagrange multipliers and their drift), [`extreme`] (the wall phase at the
//! edges of its domain: equilibrium, immediate release, any scale; a tiny start's linear growth
//! in [`lead_in`]), [`complement`] (the wall phase near the floor, in φ = π/2 − θ),
//! [`near_release`] (the wall phase near the release push, in the deviation from the start,
//! with the start's margin from [`start_margin`]).

pub mod complement;
pub mod constrained;
pub mod event;
pub mod exact;
pub mod extreme;
pub mod fall;
pub mod floor;
pub mod impact;
pub mod integrators;
pub mod lead_in;
pub mod minimum;
pub mod near_release;
pub mod outcome;
pub mod penalty;
pub mod rigid;
pub mod run;
pub mod scaled;
pub mod scene;
pub mod start_margin;
pub mod trace;
pub mod units;
