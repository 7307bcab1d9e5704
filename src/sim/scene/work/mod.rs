//! Plan-time refusals: requests the run could not meet, said up front (exit 2 and the field)
//! rather than found out after a long run (issue 11: the reliability campaign found each).
//!
//! * **A fixed step too small for the run**: a phase may take at most [`MAX_STEPS`] steps.
//!   The phases' lengths are known before the run, in units of T = √(l/g): the wall phase
//!   lasts t_s (Carlson's closed form, `sim::exact`, behind the linear growth of a tiny start)
//!   and the floor phase the duration of `sim::exact::flat`; an end time cuts both.
//! * **Penalty springs an explicit method cannot follow** (`report::stability::stiff`): the
//!   contact vibrates at up to ω = 2√κ + 4γ per T (the modes' frequencies 2√κ and the
//!   dashpot's rate); a fixed step must resolve it, h ω ≤ 0.2, or it is unstable or inaccurate
//!   (the spurious zeros and lift-offs the campaign found). Explicit Euler also gains energy by
//!   a factor 1 + (h ω)² a step, e^{h ω² t_s} over the phase: it needs h ω² t_s ≤ 0.02.
//! * **A penalty start the springs cannot tell from flat** (F3): the model's own shift of the
//!   separation exceeds the rigid separation's distance from flat (`crate::sim::penalty::plan`).
//! * **An explicit adaptive method on penalty springs** takes the most of three counts, more
//!   than [`MAX_STEPS`] is refused (the campaign's F6: dopri5 at tolerance 1.9e-16 on κ = 1.5e7
//!   took 1.18e6 steps where the stability count alone said 7.7e3; dop853 at 2.8e-16 on
//!   κ = 6.9e6 hit the 1e7-step limit after 15 s):
//!   - *stability*: its error control holds h ω near the edge of its stability region, c ω t_s
//!     steps. Measured from θ0 = 0.0106 and 0.3 (θ̇0 = 4e-5) at τ = 1e-4 and 1e-6, κ = 1e6..1e11,
//!     γ = 0 and 10 (`tools/experiments/penalty_stability_count.rs`): dopri5 takes 0.53-1.03 ω t_s
//!     steps, dop853 0.19-0.69; c is the top of each (1.05, 0.7). It was ω t_s / 3, an
//!     assumption: campaign scene 180450 (dopri5, κ = 6.9e11, τ = 3.7e-5) was estimated at
//!     3.25e6 steps and hit the 1e7-step limit;
//!   - *accuracy*: the contact's vibration (frequency ~√κ, amplitude ∝ κ^{-1/2} in the force
//!     rates) resolved to τ by an estimate of order q: h ~ (A/τ)^{1/(q+1)}/√κ, so
//!     a t_s κ^{1/2 − 1/(2(q+1))} τ^{−1/(q+1)} steps;
//!   - *rounding*: the force rates' derivatives κ p̈ are κ times O(1) terms cancelling to
//!     O(1/κ), so they carry a rounding of ~κ u that the error estimate sees as h c κ u against
//!     τ: b t_s κ u / τ steps.
//!
//!   The exponents are the model's; a and b fitted to runs from θ0 = 0.4186 at rest (t_s = 1.68)
//!   over κ = 1e4..1e10 and τ = 1e-10..3e-16: dopri5 (q + 1 = 5) a = 0.29 (every run within 3%),
//!   b ≈ 0.02-0.045; dop853 (q + 1 = 8) a = 0.21-0.28, b = 2.05-2.15 (2.46 with γ = 13). The
//!   constants below take the top of each range, so the estimate errs towards refusing: it
//!   is within 0.9-1.5 of the runs where one count dominates and up to 2.1 above where the
//!   accuracy and rounding counts meet (dop853, κ = 1e4, τ = 1e-15: 4.6e3 for 2.25e3);
//!   `tests/sim/scene/work.rs` holds it against runs. Outside the fitted range the runs went
//!   further: the 1e6-scene campaign's heavy share (scenes the plan put over 1e4 steps a
//!   phase, first run with `--work-above`) hit the 1e7-step limit after 3-5 s on scenes 8113,
//!   18442, 58703 and 67260 of seed 1 (κ = 7.9e9..7.2e11, γ up to 2.1e6, τ = 7e-14..2.5e-9),
//!   whose runs took 1.41-2.24 times the estimate; so a count above [`MAX_STEPS`] /
//!   [`EXPLICIT_MARGIN`] is refused (`tests/sim/penalty/estimate_margin.rs`). radau5 is not held: its steps follow its
//!   tolerance (the lead-in and its controller keep them to thousands up to κ = 1e12).
//! * **radau5 on stiff springs below its rounding floor**: its error estimate sees the force
//!   rates' rounding (κ u), so below [`RADAU5_LEAST_TOLERANCE`] on springs stiffer than
//!   [`RADAU5_STIFF`] it rejects step after step (the 1e6-scene campaign's seed 1 scenes 42205,
//!   44765, 335462, 406910, 421769: κ ≈ 1e11, τ = 1.1..1.8e-16, 1e6 steps and more). Sweep
//!   (separation from θ0 = 0.3 and 1e-300 at rest, m = l = g = 1): κ = 1e2..1e6 take 3.4e3-1.4e4
//!   steps at every τ in 1.1e-16..1e-15; κ = 1e8 up to 4.6e4 at 1.1e-16 (15% rejected); at
//!   τ = 3e-16 κ = 1e9 rejects 62%, 1e10 77%, and κ ≥ 1e10 take 4e4 to more than 2e5 steps;
//!   at τ = 1e-15 every κ up to 1e12 takes at most 7e3 steps (15% rejected), 5e-16 at most
//!   1.6e4. So the floor is 1e-15 (three times the cliff's start) above κ = 1e8.
//! * **An explicit adaptive method whose tolerance exceeds the starting wall force, far from
//!   the separation**: its error control holds each spring force to τ m g a step (absolute:
//!   `PenaltyModel::scale`), so a wall force F_w0 of the order of τ where the integration
//!   starts (the lead-in's hand-over at θ ≈ 9.3e-10 for a tiny start) is not resolved: the
//!   force errors excite the contact's vibration by about the wall force itself and it
//!   crosses zero at once (the campaign's scenes 714, 1031, 1502 of seed 1: zeros near
//!   θ = 1e-9, 0.84 rad from the rigid separation). Measured with dopri5 and dop853 (8,405
//!   random runs: κ = 3..1e9, γ = 0 or 1e-3..10 √κ, tiny, ordinary and near-π/2 starts,
//!   pushes, F_w0/τ = 10^U(−1.5, 3); and a grid of τ = 1e-1..1e-14): spurious zeros up to
//!   F_w0/τ = 12.1 (dop853, κ = 3.6e4, θ0 = 1e-20, τ = 5.8e-11; dopri5 up to 3.6), none in
//!   the 3,310 runs above it (3,034 separated within the bound, 276 stopped at the sweeps'
//!   step caps; `tests/sim/penalty/refusals.rs` reruns it). Above F_w0/τ ≈ 1 the spurious
//!   zeros are isolated (a 1% change of κ or τ removes each), chance failures of the error
//!   estimate rather than a region: hence the margin. Refused below
//!   F_w0/τ = [`RESOLVED_WALL_FORCE`] = 40, a margin of 3.3, where a zero at the start would
//!   lie outside the stated bound of the rigid separation angle θ_r
//!   (`penalty::confirm::separation_bound` with N = 1 step). Near π/2, or pushed to the wall's
//!   limit, F_w0 is small because the separation is near (θ_r ≈ θ0): an early zero is then
//!   within what the tolerance promised (1,378 such runs with F_w0/τ < 20, all within the
//!   bound), and those are not refused. radau5 is not held: it damps the vibration in every
//!   step (L-stable, stiffly accurate) and had no spurious zero in the same sweep.
//! * **The same from θ0 = 0 with a push** (the campaign's F8: seed 1 scenes 16562, 24057,
//!   50003, 81135, 84325 failed at run time): the rigid wall force starts at exactly 0, so the
//!   rule above cannot see it, and grows at Ḟ_w0 = θ̇0 (Ω² − θ̇0²) m g per √(l/g)
//!   ([`wall_force_rate`]). A spurious zero comes while the force is still of the order of the
//!   errors, so the measure is the force the start builds in a stated time, the first √(l/g):
//!   Ḟ_w0 T against τ. Sweeps of such starts (51,450 runs: κ = 5..1e12, γ = 0 or
//!   1e-3..10 √κ, θ̇0 = 1e-9..0.87, τ = 1e-16..0.1 or set by Ḟ_w0 T/τ = 10^U(−1, 4.5)) found
//!   1,064 spurious zeros: with dopri5 up to Ḟ_w0 T/τ = 23.8 (593 of 18,405 runs; none in the
//!   4,820 at 75 or above), with dop853 up to 1,164 (471 of 33,045; none in the 5,999 at
//!   3,500 or above). dop853's tail is long and thin (6 zeros above 200 in 17,504 runs
//!   there, all at κ ≥ 3e5, after 5 to 3,257 steps). Refused below
//!   [`resolved_wall_force_rates`] (75 for dopri5, 3,500 for dop853: margins of 3.2 and 3.0),
//!   when the separation is far as above. Below those limits many runs still separate
//!   correctly (a bound on the risk, not a prediction): of seed 1's first 100,000 campaign
//!   scenes the rule refuses 52, of which 41 would have run within tolerance, 7 ended at
//!   spurious zeros and 3 took more than 1e6 steps; `tests/sim/penalty/refusals.rs` sweeps it
//!   again.

mod springs;

use crate::ladder::Ladder;
use crate::sim::exact::{flat::floor_duration, PhaseOne};
use crate::sim::integrators::card::PenaltyFit;
use crate::sim::integrators::{card, Control, TABLE};
use crate::sim::lead_in::linear_lead_in;
use crate::sim::penalty::plan::too_close_to_flat;
use crate::sim::penalty::start::{rigid_forces, OMEGA2};
use crate::sim::penalty::Contact;
use crate::sim::scene::errors::{Ctx, SceneError};
use crate::sim::scene::parts::{ContactModel, End, RawIntegrator, MAX_STEPS};
use crate::sim::units::Units;
use num_dual::Dual64;

/// Ω in the scene's units (Ω² = 3/4).
const OMEGA: f64 = 0.866_025_403_784_438_6;
/// Largest h ω of a fixed step with penalty springs.
const MAX_STEP_FREQUENCY: f64 = 0.2;
/// How far below [`MAX_STEPS`] an explicit adaptive method's estimated count must stay: runs
/// took up to 2.24 times the estimate (module docs).
pub const EXPLICIT_MARGIN: f64 = 3.0;
/// radau5 on penalty springs stiffer than this needs a tolerance of at least
/// [`RADAU5_LEAST_TOLERANCE`] (module docs). Measured on radau5; an implicit method added to
/// the table is held to the same rule until it is measured.
pub const RADAU5_STIFF: f64 = 1e8;
/// The least tolerance radau5 reaches on springs stiffer than [`RADAU5_STIFF`] (module docs).
pub const RADAU5_LEAST_TOLERANCE: f64 = 1e-15;
/// Least F_w0/τ an explicit adaptive method needs on penalty springs (module docs).
pub const RESOLVED_WALL_FORCE: f64 = 40.0;

/// Least Ḟ_w0 T/τ each explicit adaptive method needs on penalty springs from θ0 = 0 with a
/// push (F_w0 = 0 there; module docs): three times the largest ratio with a spurious zero in
/// the sweeps.
/// From the cards' [`PenaltyFit::wall_force_rate`] (dopri5 75, dop853 3,500).
pub fn resolved_wall_force_rates() -> Vec<(&'static str, f64)> {
    TABLE
        .iter()
        .filter_map(|c| c.penalty_fit.map(|f| (c.name, f.wall_force_rate)))
        .collect()
}

/// Whether `method` is implicit (its card says so); false for a name the table does not know.
fn is_implicit(method: &str) -> bool {
    card(method).is_some_and(|c| c.is_implicit())
}

/// The rate of the rigid wall force (m g per √(l/g)) at (θ, θ̇) (dimensionless) along the
/// motion (5), θ̈ = Ω² sin θ: θ̇ (Ω² − θ̇²) at θ = 0. By a dual number through
/// [`rigid_forces`], so that it cannot drift from the force itself.
pub fn wall_force_rate(theta: f64, rate: f64) -> f64 {
    let th = Dual64::new(theta, rate);
    let w = Dual64::new(rate, OMEGA2 * theta.sin());
    rigid_forces(th, w).0.eps
}

/// The angle (rad) where a penalty run's integration starts from (θ0, θ̇0) (dimensionless) and
/// the rigid wall force (m g) there: at the lead-in's hand-over for a tiny start
/// (`sim::lead_in`), as `penalty::run::separation` does.
pub fn starting_wall_force(theta0: f64, rate0: f64) -> (f64, f64) {
    let (_, theta, rate) = linear_lead_in(OMEGA2, theta0, rate0).unwrap_or((0.0, theta0, rate0));
    (theta, rigid_forces(theta, rate).0)
}

/// Steps of an explicit adaptive `method` at tolerance `tol` over `t` (units of √(l/g)) on
/// springs of stiffness κ vibrating at up to ω: the most of the stability, accuracy and
/// rounding counts (module docs).
pub fn explicit_penalty_steps(method: &str, kappa: f64, omega: f64, t: f64, tol: f64) -> f64 {
    let Some(PenaltyFit {
        stability: c,
        estimate_order: q1,
        accuracy: (a, b),
        ..
    }) = card(method).and_then(|c| c.penalty_fit)
    else {
        return omega * t / 3.0;
    };
    let stability = c * omega * t;
    let accuracy = a * t * kappa.powf(0.5 - 0.5 / q1) * tol.powf(-1.0 / q1);
    let rounding = b * t * kappa * (f64::EPSILON / 2.0) / tol;
    stability.max(accuracy).max(rounding)
}

/// t_s in units of T from θ0 and θ̇0 (in SI, with T = `unit` seconds): the exact wall phase, and
/// for a start below 1e-100 the time its linear growth e^{Ω t} takes to reach 1e-100 (within a
/// few percent: an estimate). The size of the start is formed scaled by 2^600, so a subnormal
/// θ0 or θ̇0 T does not round to zero (which would give an infinite estimate).
fn separation_time(theta0: f64, rate0: f64, unit: f64) -> f64 {
    const FLOOR: f64 = 1e-100;
    let big = 2f64.powi(600);
    let size_big = (theta0 * big).max(rate0 * big * unit / OMEGA);
    let (lead, theta, rate) = if size_big < FLOOR * big {
        let grow = FLOOR * big / size_big;
        (grow.ln() / OMEGA, theta0 * grow, rate0 * grow * unit)
    } else {
        (0.0, theta0, rate0 * unit)
    };
    lead + PhaseOne::new(theta, rate, OMEGA * OMEGA)
        .ok()
        .and_then(|p| p.separation())
        .map_or(f64::INFINITY, |s| s.time)
}

/// The contact's fastest rate ω = 2√κ + 4γ per √(l/g), and κ, γ (None for rigid contact).
fn vibration(ladder: &Ladder<f64>, contact: ContactModel) -> Option<(f64, f64, f64)> {
    let ContactModel::Penalty { stiffness, damping } = contact else {
        return None;
    };
    let c = Contact::from_dimensional(ladder, stiffness, damping);
    Some((2.0 * c.kappa.sqrt() + 4.0 * c.gamma, c.kappa, c.gamma))
}

/// Estimated steps of the wall and the floor phase of a run (0 where a phase is not run or an
/// adaptive method's steps follow its tolerance alone): a fixed step's span over the step; an
/// explicit adaptive method on penalty springs [`explicit_penalty_steps`].
pub fn phase_steps(
    ladder: &Ladder<f64>,
    (theta0, rate0): (f64, f64),
    method: &str,
    control: Control,
    end: End,
    contact: ContactModel,
) -> [f64; 2] {
    let unit = Units::of(ladder).time;
    let rate = rate0 * unit;
    let t_end = match end {
        End::Time(t) => t / unit,
        _ => f64::INFINITY,
    };
    let t_s = separation_time(theta0, rate0, unit);
    let Control::Fixed(h) = control else {
        return match (vibration(ladder, contact), control) {
            (Some((omega, kappa, _)), Control::Tolerance(tol)) if !is_implicit(method) => [
                explicit_penalty_steps(method, kappa, omega, t_s.min(t_end), tol),
                0.0,
            ],
            _ => [0.0, 0.0],
        };
    };
    let hs = h / unit;
    // At or past the release push the floor phase starts at θ0, faster than from a separation
    // there: its duration from cos θ_s = cos θ0 bounds it.
    let cs = (2.0 / 3.0 * theta0.cos() + 4.0 / 9.0 * rate * rate).min(theta0.cos());
    let floor = match (end, contact) {
        (End::Separation, _) | (_, ContactModel::Penalty { .. }) => 0.0,
        _ if t_end <= t_s => 0.0,
        _ => floor_duration(cs).min(t_end - t_s),
    };
    [t_s.min(t_end) / hs, floor / hs]
}

/// What a run of this scene will take; a refusal naming the key when it cannot be done.
#[allow(clippy::too_many_arguments)]
pub(in crate::sim) fn check_work(
    cx: &Ctx,
    i: &RawIntegrator,
    ladder: &Ladder<f64>,
    start: (f64, f64),
    method: &str,
    control: Option<Control>,
    end: End,
    contact: ContactModel,
) -> Result<(), SceneError> {
    let Some(control) = control else {
        return Ok(());
    };
    let unit = Units::of(ladder).time;
    let t_s = separation_time(start.0, start.1, unit);
    let step_span = i.step.as_ref().or(i.scaled_step.as_ref()).map(|s| s.span());
    let steps = phase_steps(ladder, start, method, control, end, contact);
    if let Some((omega, kappa, gamma)) = vibration(ladder, contact) {
        let springs = format!(
            "penalty springs of k l/(m g) = {kappa:e}, c √(l/g)/m = {gamma:e} vibrate at up to 2√κ + 4γ = {omega:.3e} per √(l/g)"
        );
        match control {
            Control::Fixed(h) => springs::check_fixed_step(
                cx,
                step_span.clone(),
                method,
                (h, unit, t_s),
                omega,
                &springs,
            )?,
            Control::Tolerance(_) if steps[0] > MAX_STEPS as f64 / EXPLICIT_MARGIN => {
                return Err(cx.err(
                    Some(i.method.span()),
                    "integrator.method",
                    format!(
                        "{springs}: \"{method}\" is explicit and its steps must resolve them to the tolerance, about {:.1e} steps (stability, accuracy and the rounding floor κ u/τ; runs took up to {EXPLICIT_MARGIN} times that), more than 1/{EXPLICIT_MARGIN} of the {MAX_STEPS:e} a phase may take; allowed: method = \"radau5\" or a looser tolerance",
                        steps[0]
                    ),
                ));
            }
            Control::Tolerance(tol) if is_implicit(method) && kappa > RADAU5_STIFF => {
                if tol < RADAU5_LEAST_TOLERANCE {
                    return Err(cx.err(
                        i.tolerance.as_ref().map(|t| t.span()),
                        "integrator.tolerance",
                        format!(
                            "{springs}: below a tolerance of {RADAU5_LEAST_TOLERANCE:e} \"radau5\"'s error estimate on springs stiffer than κ = {RADAU5_STIFF:e} is rounding (κ u in the force rates), so it rejects step after step (up to 1e6 steps or more); allowed: tolerance ≥ {RADAU5_LEAST_TOLERANCE:e}"
                        ),
                    ));
                }
            }
            Control::Tolerance(tol) => {
                springs::check_wall_force_resolved(cx, i, method, tol, (start, unit), kappa)?
            }
        }
        // A start near the floor the springs cannot tell from flat (F3, `crate::sim::penalty::plan`).
        if let Some(m) = too_close_to_flat(kappa, (start.0, start.1 * unit)) {
            let line = cx
                .text
                .lines()
                .position(|l| l.trim_start().starts_with("stiffness"))
                .map_or(1, |i| i + 1);
            return Err(cx.err_at_line(line, "contact.stiffness", m));
        }
    }
    let Control::Fixed(h) = control else {
        return Ok(());
    };
    check_step_count(cx, step_span, h, steps, unit)
}

/// A fixed step `h` (s) makes at most [`MAX_STEPS`] steps in each phase of about `steps`
/// steps; else the least step that does, in s and in units of `unit` = √(l/g) s.
fn check_step_count(
    cx: &Ctx,
    step_span: Option<std::ops::Range<usize>>,
    h: f64,
    steps: [f64; 2],
    unit: f64,
) -> Result<(), SceneError> {
    for (phase, n) in ["wall", "floor"].into_iter().zip(steps) {
        if n > MAX_STEPS as f64 {
            let least = h * n / MAX_STEPS as f64;
            return Err(cx.err(
                step_span,
                "integrator.step",
                format!(
                    "the {phase} phase needs about {n:.1e} steps of this size, more than the {MAX_STEPS:e} a phase may take; allowed: a step ≥ {least:e} s ({:e} √(l/g))",
                    least / unit
                ),
            ));
        }
    }
    Ok(())
}
