//! The quick `src/sim` test files in one test binary, for mutation testing only
//! (`equations/MUTATION-SIM.md`). Each file below is also a test target of its own, and
//! `cargo test` runs it there: this target has `test = false` in `Cargo.toml`, so `cargo test`
//! does not build it and nothing runs twice. It is built only when named
//! (`cargo mutants ... --cargo-arg=--test=sim_mutants`).
//!
//! Why one binary: a mutant of the library makes cargo rebuild and link every test target that
//! uses it. Built one by one, the 58 files cost 58 crate compilations and links a mutant; here
//! they cost one. The files are included unchanged (`#[path]`), so a test fails here exactly
//! when it fails in its own target. The list: every `src/sim` test file that runs in under
//! about 5 s at opt-level 0 (a new one belongs here too).
#![allow(dead_code, unused_imports)]

#[path = "../angle_from_floor.rs"]
mod angle_from_floor;
#[path = "../any_stepper.rs"]
mod any_stepper;
#[path = "../baumgarte.rs"]
mod baumgarte;
#[path = "../campaign.rs"]
mod campaign;
#[path = "../carlson_fallback.rs"]
mod carlson_fallback;
#[path = "../cli_scene_errors.rs"]
mod cli_scene_errors;
#[path = "../constrained_drift_checkpoints.rs"]
mod constrained_drift_checkpoints;
#[path = "../error_units.rs"]
mod error_units;
#[path = "../event_defaults.rs"]
mod event_defaults;
#[path = "../event_interior_samples.rs"]
mod event_interior_samples;
#[path = "../exact_ode.rs"]
mod exact_ode;
#[path = "../exact_quadrature.rs"]
mod exact_quadrature;
#[path = "../exact_reference.rs"]
mod exact_reference;
#[path = "../exact_robust.rs"]
mod exact_robust;
#[path = "../fall_figures.rs"]
mod fall_figures;
#[path = "../fixed_step_stop.rs"]
mod fixed_step_stop;
#[path = "../floor_minima.rs"]
mod floor_minima;
#[path = "../floor_starts.rs"]
mod floor_starts;
#[path = "../integrate_phase.rs"]
mod integrate_phase;
#[path = "../near_flat_starts.rs"]
mod near_flat_starts;
#[path = "../order_per_phase.rs"]
mod order_per_phase;
#[path = "../overflowing_state.rs"]
mod overflowing_state;
#[path = "../penalty_confirm.rs"]
mod penalty_confirm;
#[path = "../penalty_energy.rs"]
mod penalty_energy;
#[path = "../penalty_estimate_margin.rs"]
mod penalty_estimate_margin;
#[path = "../penalty_refusals.rs"]
mod penalty_refusals;
#[path = "../penalty_retry.rs"]
mod penalty_retry;
#[path = "../radau5_domain.rs"]
mod radau5_domain;
#[path = "../radau5_step_reuse.rs"]
mod radau5_step_reuse;
#[path = "../rhs_counts.rs"]
mod rhs_counts;
#[path = "../scene_errors.rs"]
mod scene_errors;
#[path = "../scene_work.rs"]
mod scene_work;
#[path = "../sim_fall.rs"]
mod sim_fall;
#[path = "../sim_floor.rs"]
mod sim_floor;
#[path = "../sim_forces.rs"]
mod sim_forces;
#[path = "../sim_integrators.rs"]
mod sim_integrators;
#[path = "../sim_plan.rs"]
mod sim_plan;
#[path = "../sim_scale.rs"]
mod sim_scale;
#[path = "../slow_start.rs"]
mod slow_start;
#[path = "../stability_extreme.rs"]
mod stability_extreme;
#[path = "../stability_memory.rs"]
mod stability_memory;
#[path = "../stability_penalty.rs"]
mod stability_penalty;
#[path = "../taylor.rs"]
mod taylor;
#[path = "../taylor_every_scene.rs"]
mod taylor_every_scene;
#[path = "../taylor_f64.rs"]
mod taylor_f64;
#[path = "../taylor_models.rs"]
mod taylor_models;
#[path = "../taylor_order.rs"]
mod taylor_order;
#[path = "../taylor_poly.rs"]
mod taylor_poly;
#[path = "../taylor_scaled.rs"]
mod taylor_scaled;
#[path = "../taylor_step.rs"]
mod taylor_step;
#[path = "../tiny_error_scale.rs"]
mod tiny_error_scale;
#[path = "../tiny_starts.rs"]
mod tiny_starts;
#[path = "../top_clearance.rs"]
mod top_clearance;
#[path = "../unit_free_steps.rs"]
mod unit_free_steps;
#[path = "../verlet_penalty_start.rs"]
mod verlet_penalty_start;
#[path = "../verlet_step.rs"]
mod verlet_step;
#[path = "../verlet_velocity_dependent.rs"]
mod verlet_velocity_dependent;
#[path = "../work_precision.rs"]
mod work_precision;
