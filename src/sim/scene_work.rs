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
//!   a factor 1 + (h ω)² a step, e^{h ω² t_s} over the phase: it needs h ω² t_s ≤ 0.02. An
//!   explicit adaptive method is held to the same stability limit by its error control, about
//!   ω t_s / 3 steps: more than [`MAX_STEPS`] is refused.

use super::exact::{flat::floor_duration, PhaseOne};
use super::integrators::Control;
use super::penalty::Contact;
use super::rigid::Ladder;
use super::scene_errors::{Ctx, SceneError};
use super::scene_parts::{ContactModel, End, RawIntegrator, MAX_STEPS};
use super::units::Units;

/// Ω in the scene's units (Ω² = 3/4).
const OMEGA: f64 = 0.866_025_403_784_438_6;
/// How many tolerances the start of a penalty run with an explicit method must measure.
const SPURIOUS_MARGIN: f64 = 100.0;
/// Largest h ω of a fixed step with penalty springs.
const MAX_STEP_FREQUENCY: f64 = 0.2;

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
/// explicit method on penalty springs ω t_s / 3.
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
        return match vibration(ladder, contact) {
            Some((omega, _, _)) if method != "radau5" => [omega * t_s.min(t_end) / 3.0, 0.0],
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
                        "{springs}: \"{method}\" is explicit and its steps must resolve them, about {:.1e} steps, more than the {MAX_STEPS:e} a phase may take; allowed: method = \"radau5\"",
                        steps[0]
                    ),
                ));
            }
            Control::Tolerance(tol) if method != "radau5" => {
                // An explicit method's force components carry an absolute error of about the
                // tolerance (in m g), while the wall force near the start is about (3/4) θ m g:
                // from a start below 100 × tolerance a spurious zero of the integrated force can
                // pass for the separation (the campaign's finding F1: θ0 = 1e-12, dop853, tol
                // 1e-10 reported θ_s = 1.4e-12). The size is formed scaled, as above.
                let big = 2f64.powi(600);
                let size_big = (start.0 * big).max(start.1 * big * unit / OMEGA);
                let least = SPURIOUS_MARGIN * tol;
                if size_big < least * big {
                    return Err(cx.err(
                        Some(i.method.span()),
                        "integrator.method",
                        format!(
                            "penalty contact from a start of size {:.1e} rad (θ0 or θ̇0 √(l/g)/Ω) with \"{method}\" at tolerance {tol:e}: its force error (~ tolerance × m g) would swamp the wall force (~ θ m g) and fake a separation; allowed: method = \"radau5\", a start ≥ {least:e} rad, or a tolerance ≤ {:.1e}",
                            size_big / big,
                            size_big / big / SPURIOUS_MARGIN
                        ),
                    ));
                }
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
