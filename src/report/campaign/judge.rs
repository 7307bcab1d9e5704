//! What the reliability campaign ([`crate::report::campaign`]) holds a completed run to: every output
//! it asked for finite, and each result within its **stated tolerance**, worked out here in the
//! scene's own units (m = l = g = 1, Ω² = 3/4, times in T = √(l/g)).
//!
//! **The integrator's promise** is the error model of `ladder stability` and `tests/sim/fall/scale.rs`:
//! N accepted steps, each with a local error of at most τ relative to the state's scale
//! max(|y|, 1) (τ the tolerance; for a fixed step h of order p, (h/T)^(p+1)) and a rounding of
//! the update by an ulp or so, added without cancellation: a global error E = 10 N (τ + u)
//! (10, the margin on the O(1) constants; the u term is what a million small fixed steps add).
//! * **separation angle** (rigid): cos θ_s = (2/3) cos θ0 + (4/9) (θ̇0 T)² is a function of the
//!   energy, so it inherits E without amplification: |cos θ_s − that| ≤ E max(θ_s, 1) + 8u.
//!   `exact` promises rounding only (E = 0).
//! * **separation time** (rigid, integrators): against the exact reference (the linear lead-in
//!   and Carlson's closed form, `sim::exact`). A state error δy moves the zero of the factor
//!   g = Ω² cos θ − θ̇² by δt = ∇g·δy / ġ, with ġ = −3 Ω² sin θ θ̇ there:
//!   E (Ω² sin θ_s max(θ_s, 1) + 2 θ̇_s max(θ̇_s, 1)) / (3 Ω² sin θ_s θ̇_s) + 16u t_s (the event
//!   stops at 8 ulps of t). `exact` is that reference and is not compared with itself. A start
//!   given from the floor (`angle_from_floor` φ0, which θ0 cannot hold) is judged with cos θ0
//!   = sin φ0 throughout, and its t_s against the near-flat closed form
//!   (`sim::exact::near_flat`, exact to f64 for φ0 + (θ̇0 T)²/Ω² ≤ 2⁻³⁰) or, above that, Carlson's
//!   from the nearest θ0 with the slip of its complement from φ0 (≤ 1.1e-16 rad) times the
//!   slope of t_s added to the bound.
//! * **flat time** (rigid): against t_s + the floor phase's duration by quadrature of its
//!   conservation laws (`sim::exact::flat`). The separation time's bound, plus the state error
//!   of the whole run E' = 10 (N_wall + N_floor) τ through the duration
//!   D = ∫ dθ/θ̇: an energy error δ changes θ̇² by at most 6δ, so D by 3 δ D/θ̇_s²
//!   (δ ≤ E' (1 + 3 θ̇_max) max(θ̇_max, 1)); the start and end angles move by E' max(θ, 1),
//!   i.e. the times by that over θ̇_s and θ̇_flat; rounding 16u t_flat; quadrature 1e-14 D.
//! * **energy error** |ΔE|/(m g l): the energy's gradient is at most 1 + 3 θ̇ in these units,
//!   so E' (1 + 3 θ̇_max) max(θ̇_max, 1) + 16u (1 + θ̇_max²).
//! * **momentum error** (tests/sim/fall/momentum_balance.rs): 4 (E' max(θ̇_max, 1) + 4u).
//! * **penalty separation angle**: the error model of the penalty contact,
//!   `sim::penalty::confirm::separation_bound`: the model's own distance to the rigid angle θ_r,
//!   4/(κ sin θ_r) (its constant measured over the start domain and damping γ = 0..κ, with a
//!   margin of 3), the integrator's 10 N (τ + u) (times 1/((9/4) sin²θ_r) for a small θ_r) and rounding 10u. The run itself refuses a
//!   zero outside that bound (exit 2), so here it holds the reported angle, as written to the
//!   outputs, to the same promise.
//!
//! * **a start at or past the release push** (D0 = Ω² cos θ0 − θ̇0² ≤ 0 from the SI inputs,
//!   `sim::start_margin`): the separation is the start itself, θ_s = θ0 and t_s = 0 exactly;
//!   the flat time against the floor phase's duration from (θ0, θ̇0)
//!   (`sim::exact::flat::floor_duration_from`), with the bounds above at θ̇_s = θ̇0.
//!   Near that push the closed form takes the margin of the SI inputs too
//!   (`PhaseOne::with_start_margin`).
//!
//! Results a scene did not reach (an end time before separation) are not judged; a run that
//! stops short of the end it asked for is a failed run (the command exits 1), counted by the
//! campaign, not here.

/// The watchdog lived here first; it has its own file now.
pub use super::watchdog::Watchdog;
use crate::sim::complement::complement;
use crate::sim::exact::flat::{floor_duration, floor_duration_from};
use crate::sim::exact::near_flat::near_flat;
use crate::sim::exact::PhaseOne;
use crate::sim::extreme::linear_lead_in;
use crate::sim::integrators::{order, Control};
use crate::sim::near_release;
use crate::sim::outcome::Outcome;
use crate::sim::penalty::confirm::separation_bound;
use crate::sim::penalty::Contact;
use crate::sim::scene::output::Output;
use crate::sim::scene::{ContactModel, Scene};
use crate::sim::start_margin::Lean;
use crate::sim::units::Units;

const U: f64 = f64::EPSILON / 2.0;
const OMEGA2: f64 = 0.75;

/// One thing wrong with a completed run.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// An output it asked for is NaN or infinite.
    NonFinite(&'static str),
    /// A result outside its stated tolerance.
    OutOfTolerance {
        /// Which result.
        what: &'static str,
        /// |result − reference| in the scene's units.
        error: f64,
        /// The stated tolerance.
        bound: f64,
    },
}

fn finite(xs: &[f64]) -> bool {
    xs.iter().all(|x| x.is_finite())
}

/// The outputs `scene` asked for that `o` holds as NaN or infinity.
pub fn non_finite(scene: &Scene, o: &Outcome) -> Vec<Problem> {
    let mut bad = Vec::new();
    for out in &scene.outputs {
        let ok = match out {
            Output::SeparationAngle => o.separation.is_none_or(|s| s.angle.is_finite()),
            Output::SeparationTime => o.separation.is_none_or(|s| s.time.is_finite()),
            Output::SeparationRate => o.separation.is_none_or(|s| s.rate.is_finite()),
            Output::FlatTime => o.flat.is_none_or(|f| f.time.is_finite()),
            Output::FlatState => o.flat.is_none_or(|f| {
                finite(&[f.rate, f.centre_x, f.centre_velocity_x, f.centre_velocity_y])
            }),
            Output::FloorForceMin | Output::TopClearanceMin => o
                .floor_report
                .is_none_or(|r| finite(&[r.floor_force_min, r.top_clearance_min])),
            Output::MomentumError => o.momentum_error.is_none_or(f64::is_finite),
            Output::EnergyError => o.energy_error.is_none_or(f64::is_finite),
            Output::FinalState => finite(&[o.last.0, o.last.1, o.last.2]),
            Output::RhsEvals => true,
            Output::Trajectory | Output::Forces => o.trace.as_ref().is_none_or(|t| {
                t.iter().all(|p| {
                    finite(&[p.t, p.theta, p.rate]) && p.forces.is_none_or(|(a, b)| finite(&[a, b]))
                })
            }),
        };
        if !ok {
            bad.push(Problem::NonFinite(out.name()));
        }
    }
    bad
}

/// τ of the error model: the tolerance, or (h/T)^(p+1) for a fixed step; 0 for `exact`.
fn local_error(scene: &Scene, unit: f64) -> f64 {
    match scene.control {
        None => 0.0,
        Some(Control::Tolerance(t)) => t,
        Some(Control::Fixed(h)) => {
            let p = order(&scene.method).unwrap_or(1) as i32;
            (h / unit).powi(p + 1)
        }
    }
}

/// cos θ0 of the scene's start: sin φ0 when it was given from the floor (θ0 cannot hold it).
fn start_cos(scene: &Scene) -> f64 {
    scene.phi0.map_or(scene.theta0.cos(), f64::sin)
}

/// t_s in units of T by an independent reference, and the part of its tolerance that comes
/// from the reference itself: the linear lead-in of a tiny start (in SI, where a subnormal θ̇0
/// keeps its digits) and Carlson's closed form from there (rounding only); for a start given
/// from the floor as φ0, the near-flat closed form where it is exact to f64
/// (`sim::exact::near_flat`), else Carlson's from the nearest θ0, whose complement may miss φ0
/// by ~1e-16 rad: that slip times the slope of t_s in θ0 (measured over one ulp of θ0, with
/// a factor 2 for the slope's own change).
pub fn reference_separation_time(scene: &Scene) -> Option<(f64, f64)> {
    let unit = Units::of(&scene.ladder).time;
    let rate0 = scene.rate0 * unit;
    if at_once(scene) {
        return Some((0.0, 0.0));
    }
    if let Some(phi0) = scene.phi0 {
        if let Some(nf) = near_flat(OMEGA2, phi0, rate0) {
            return Some((nf.separation_time, 0.0));
        }
        let at = |theta: f64| Some(PhaseOne::new(theta, rate0, OMEGA2).ok()?.separation()?.time);
        let t = at(scene.theta0)?;
        let slip = (complement(scene.theta0) - phi0).abs();
        if slip == 0.0 {
            return Some((t, 0.0));
        }
        let ulp = scene.theta0 - f64::from_bits(scene.theta0.to_bits() - 1);
        let slope = (at(scene.theta0 - ulp)? - t).abs() / ulp;
        return Some((t, 2.0 * slope * slip));
    }
    let (t0, theta, rate) =
        match linear_lead_in(scene.ladder.big_omega2(), scene.theta0, scene.rate0) {
            Some((t, th, w)) => (t / unit, th, w * unit),
            None => (0.0, scene.theta0, scene.rate0 * unit),
        };
    let mut p = PhaseOne::new(theta, rate, OMEGA2).ok()?;
    // Near the release push the margin of the SI inputs: θ̇0 T, rounded, would move it.
    if let (Some(d), 0.0) = (start_margin(scene), t0) {
        p = p.with_start_margin(d);
    }
    Some((t0 + p.separation()?.time, 0.0))
}

/// The start's margin D0 T² = (Ω² cos θ0 − θ̇0²) T² from the SI inputs, near the release push
/// (`sim::near_release::near_margin`); None away from it.
fn start_margin(scene: &Scene) -> Option<f64> {
    let unit = Units::of(&scene.ladder).time;
    let lean = scene.phi0.map_or(Lean::Theta(scene.theta0), Lean::Phi);
    near_release::near_margin(&scene.ladder, lean, scene.rate0).map(|d| d * (unit * unit))
}

/// Whether the scene starts at or past the release push (D0 ≤ 0): the top leaves at once.
fn at_once(scene: &Scene) -> bool {
    start_margin(scene).is_some_and(|d| d <= 0.0)
}

fn check(out: &mut Vec<Problem>, what: &'static str, error: f64, bound: f64) {
    // NaN counts as outside.
    if error.is_nan() || error > bound {
        out.push(Problem::OutOfTolerance { what, error, bound });
    }
}

/// The results of `o` outside their stated tolerance (see the module docs).
pub fn out_of_tolerance(scene: &Scene, o: &Outcome) -> Vec<Problem> {
    let mut bad = Vec::new();
    let unit = Units::of(&scene.ladder).time;
    let tau = local_error(scene, unit);
    let r0 = scene.rate0 * unit;
    let cs = 2.0 / 3.0 * start_cos(scene) + 4.0 / 9.0 * r0 * r0;
    let Some(sep) = o.separation else {
        return bad;
    };
    let n_wall = o.work.wall.steps as f64;
    if let ContactModel::Penalty { stiffness, damping } = scene.contact {
        let springs = (stiffness, damping);
        check_penalty(&mut bad, scene, springs, (sep.angle, cs), o, tau);
        return bad;
    }
    let e_wall = 10.0 * n_wall * (tau + U);
    if at_once(scene) {
        // The wall would have to pull at the start: the run reports the start itself.
        check(
            &mut bad,
            "separation_angle",
            (sep.angle - scene.theta0).abs(),
            0.0,
        );
        check(&mut bad, "separation_time", sep.time.abs(), 0.0);
    }
    let (theta_s, rate_s) = match at_once(scene) {
        true => (sep.angle, r0),
        false => (sep.angle, (OMEGA2 * cs).sqrt()),
    };
    if !at_once(scene) {
        check(
            &mut bad,
            "separation_angle",
            (theta_s.cos() - cs).abs(),
            e_wall * theta_s.max(1.0) + 8.0 * U,
        );
    }
    if scene.control.is_none() {
        return bad;
    }
    let Some((ts_ref, ts_ref_slip)) = reference_separation_time(scene) else {
        return bad;
    };
    let sin_s = theta_s.sin();
    let ts_bound = match at_once(scene) {
        true => 0.0,
        false => {
            e_wall * (OMEGA2 * sin_s * theta_s.max(1.0) + 2.0 * rate_s * rate_s.max(1.0))
                / (3.0 * OMEGA2 * sin_s * rate_s)
                + 16.0 * U * ts_ref
                + ts_ref_slip
        }
    };
    check(
        &mut bad,
        "separation_time",
        (sep.time / unit - ts_ref).abs(),
        ts_bound,
    );
    let wall = WallPhase {
        unit,
        tau,
        r0,
        cs,
        n_wall,
        theta_s,
        rate_s,
        ts_ref,
        ts_bound,
    };
    check_whole_fall(&mut bad, scene, o, &wall);
    bad
}

/// A penalty run's separation angle against the rigid one, cos θ_s = `cs`, within the bound
/// of `separation_bound` for its springs (stiffness, damping) and its steps at local error `tau`.
fn check_penalty(
    bad: &mut Vec<Problem>,
    scene: &Scene,
    (stiffness, damping): (f64, f64),
    (angle, cs): (f64, f64),
    o: &Outcome,
    tau: f64,
) {
    let c = Contact::from_dimensional(&scene.ladder, stiffness, damping);
    let rigid = cs.clamp(-1.0, 1.0).acos();
    let bound = separation_bound(c.kappa, rigid, o.work.wall.steps, tau);
    check(bad, "separation_angle", (angle - rigid).abs(), bound);
}

/// What the checks of the wall phase leave to those of the whole fall (times in units of
/// `unit` = √(l/g) s, rates in 1/√(l/g)).
#[derive(Clone, Copy)]
struct WallPhase {
    unit: f64,
    /// The local error per step.
    tau: f64,
    /// θ̇0 scaled.
    r0: f64,
    /// cos θ_s of the separation, from the start.
    cs: f64,
    /// Steps of the wall phase.
    n_wall: f64,
    /// θ_s and θ̇_s at the separation.
    theta_s: f64,
    rate_s: f64,
    /// The reference separation time and the bound on the run's.
    ts_ref: f64,
    ts_bound: f64,
}

/// The flat time, the energy error and the momentum balance of a whole fall, each within the
/// error of all its steps.
fn check_whole_fall(bad: &mut Vec<Problem>, scene: &Scene, o: &Outcome, w: &WallPhase) {
    let WallPhase {
        unit,
        tau,
        r0,
        cs,
        n_wall,
        theta_s,
        rate_s,
        ts_ref,
        ts_bound,
    } = *w;
    let n_all = n_wall + o.work.floor.map_or(0, |s| s.steps) as f64;
    let e_all = 10.0 * n_all * (tau + U);
    let rate_end = o.flat.map_or(o.last.2, |f| f.rate) * unit;
    let w_max = r0.max(rate_s).max(rate_end.abs());
    let energy_slip = e_all * (1.0 + 3.0 * w_max) * w_max.max(1.0);
    if let Some(f) = o.flat {
        let d = match at_once(scene) {
            true => floor_duration_from(scene.phi0.unwrap_or(complement(scene.theta0)), r0),
            false => floor_duration(cs),
        };
        let tf_ref = ts_ref + d;
        let rate_f = f.rate * unit;
        let bound = ts_bound
            + energy_slip * 3.0 * d / (rate_s * rate_s)
            + e_all * (theta_s.max(1.0) / rate_s + 2.0 / rate_f)
            + 16.0 * U * tf_ref
            + 1e-14 * d;
        check(bad, "flat_time", (f.time / unit - tf_ref).abs(), bound);
    }
    if let Some(e) = o.energy_error {
        let bound = energy_slip + 16.0 * U * (1.0 + w_max * w_max);
        check(bad, "energy_error", e, bound);
    }
    if let Some(p) = o.momentum_error {
        check(
            bad,
            "momentum_error",
            p,
            4.0 * (e_all * w_max.max(1.0) + 4.0 * U),
        );
    }
}
