//! Plan-time refusals: requests the run could not meet, said up front (exit 2 and the field)
//! rather than found out after a long run (issue 11: the reliability campaign found each).
//!
//! * **A fixed step too small for the run**: a phase may take at most [`MAX_STEPS`] steps.
//!   The phases' lengths are known before the run, in units of T = √(l/g): the wall phase
//!   lasts t_s (Carlson's closed form, `sim::exact`, behind the linear growth of a tiny start)
//!   and the floor phase the duration of `sim::exact::flat`; an end time cuts both.
//! * **Penalty springs an explicit method cannot follow** (`report::stability_stiff`): the
//!   contact vibrates at up to ω = 2√κ + 4γ per T (the modes' frequencies 2√κ and the
//!   dashpot's rate); a fixed step must resolve it, h ω ≤ 0.2, or it is unstable or inaccurate
//!   (the spurious zeros and lift-offs the campaign found). Explicit Euler also gains energy by
//!   a factor 1 + (h ω)² a step, e^{h ω² t_s} over the phase: it needs h ω² t_s ≤ 0.02.
//! * **An explicit adaptive method on penalty springs** takes the most of three counts, more
//!   than [`MAX_STEPS`] is refused (the campaign's F6: dopri5 at tolerance 1.9e-16 on κ = 1.5e7
//!   took 1.18e6 steps where the stability count alone said 7.7e3; dop853 at 2.8e-16 on
//!   κ = 6.9e6 hit the 1e7-step limit after 15 s):
//!   - *stability*: its error control holds h ω near its stability boundary, ω t_s / 3 steps;
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
//!   `tests/scene_work.rs` holds it against runs. radau5 is not held: its steps follow its
//!   tolerance (the lead-in and its controller keep them to thousands up to κ = 1e12).

use super::exact::{flat::floor_duration, PhaseOne};
use super::integrators::Control;
use super::penalty::Contact;
use super::rigid::Ladder;
use super::scene_errors::{Ctx, SceneError};
use super::scene_parts::{ContactModel, End, RawIntegrator, MAX_STEPS};
use super::units::Units;

/// Ω in the scene's units (Ω² = 3/4).
const OMEGA: f64 = 0.866_025_403_784_438_6;
/// Largest h ω of a fixed step with penalty springs.
const MAX_STEP_FREQUENCY: f64 = 0.2;
/// The explicit adaptive methods' step-count fits on penalty springs (module docs):
/// (method, q + 1 of its error estimate, a, b).
const EXPLICIT_FITS: [(&str, f64, f64, f64); 2] =
    [("dopri5", 5.0, 0.3, 0.05), ("dop853", 8.0, 0.3, 2.5)];

/// Steps of an explicit adaptive `method` at tolerance `tol` over `t` (units of √(l/g)) on
/// springs of stiffness κ vibrating at up to ω: the most of the stability, accuracy and
/// rounding counts (module docs).
pub fn explicit_penalty_steps(method: &str, kappa: f64, omega: f64, t: f64, tol: f64) -> f64 {
    let stability = omega * t / 3.0;
    let Some(&(_, q1, a, b)) = EXPLICIT_FITS.iter().find(|f| f.0 == method) else {
        return stability;
    };
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
fn vibration(ladder: &Ladder, contact: ContactModel) -> Option<(f64, f64, f64)> {
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
    ladder: &Ladder,
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
            (Some((omega, kappa, _)), Control::Tolerance(tol)) if method != "radau5" => [
                explicit_penalty_steps(method, kappa, omega, t_s.min(t_end), tol),
                0.0,
            ],
            _ => [0.0, 0.0],
        };
    };
    let hs = h / unit;
    let cs = 2.0 / 3.0 * theta0.cos() + 4.0 / 9.0 * rate * rate;
    let floor = match (end, contact) {
        (End::Separation, _) | (_, ContactModel::Penalty { .. }) => 0.0,
        _ if t_end <= t_s => 0.0,
        _ => floor_duration(cs).min(t_end - t_s),
    };
    [t_s.min(t_end) / hs, floor / hs]
}

/// What a run of this scene will take; a refusal naming the key when it cannot be done.
#[allow(clippy::too_many_arguments)]
pub(super) fn check_work(
    cx: &Ctx,
    i: &RawIntegrator,
    ladder: &Ladder,
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
            Control::Fixed(h) => {
                let (limit, why) = if method == "euler" {
                    (
                        (0.02 / (omega * omega * t_s)).min(MAX_STEP_FREQUENCY / omega),
                        "explicit Euler gains energy by (h ω)² a step",
                    )
                } else {
                    (MAX_STEP_FREQUENCY / omega, "h ω ≤ 0.2 to follow them")
                };
                if h / unit > limit {
                    return Err(cx.err(
                        step_span,
                        "integrator.step",
                        format!(
                            "{springs} ({why}); allowed: a step ≤ {:e} s ({limit:e} √(l/g)), or method = \"radau5\"",
                            limit * unit
                        ),
                    ));
                }
            }
            Control::Tolerance(_) if steps[0] > MAX_STEPS as f64 => {
                return Err(cx.err(
                    Some(i.method.span()),
                    "integrator.method",
                    format!(
                        "{springs}: \"{method}\" is explicit and its steps must resolve them to the tolerance, about {:.1e} steps (stability, accuracy and the rounding floor κ u/τ), more than the {MAX_STEPS:e} a phase may take; allowed: method = \"radau5\" or a looser tolerance",
                        steps[0]
                    ),
                ));
            }
            Control::Tolerance(_) => {}
        }
    }
    let Control::Fixed(h) = control else {
        return Ok(());
    };
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
