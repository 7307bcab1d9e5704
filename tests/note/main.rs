//! The note's mathematics: every display (1)-(90) and every derivation of the equation of motion,
//! checked in floats, exact arithmetic and symbolically (`cargo test --test note`).
//!
//! The modules follow the crate: `ladder` (the ladder's torque analyses), `method` (derivations),
//! `registry` (the checks of each display), `print` (the printed LaTeX as the check), `verify`
//! (verdicts and errata), `show` (one display at a state).

#[path = "../common/mod.rs"]
mod common;
mod derivation;
mod docs;
mod extending;
mod ladder;
mod milne;
mod print;
mod registry;
mod scalar;
mod show;
mod system;
mod vector;
mod verify;
