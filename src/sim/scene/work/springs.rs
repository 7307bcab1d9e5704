//! The refusals of a penalty scene whose integrator cannot follow the springs: a fixed step
//! too long for their vibration, and a tolerance too loose for the wall force at the start.

use super::{
    is_implicit, starting_wall_force, wall_force_rate, MAX_STEP_FREQUENCY, RESOLVED_WALL_FORCE,
};
use crate::sim::integrators::card;
use crate::sim::penalty::confirm::{rigid_separation_angle, separation_bound};
use crate::sim::scene::errors::{Ctx, SceneError};
use crate::sim::scene::parts::RawIntegrator;

/// A fixed step `h` (s; `unit` = √(l/g) s, `t_s` the time to separation in units) that
/// follows springs vibrating at up to `omega` per √(l/g): h ω ≤ 0.2, and for a method that
/// gains energy on every oscillation, (h ω)² a step over the t_s/h steps at most 0.02.
pub(super) fn check_fixed_step(
    cx: &Ctx,
    step_span: Option<std::ops::Range<usize>>,
    method: &str,
    (h, unit, t_s): (f64, f64, f64),
    omega: f64,
    springs: &str,
) -> Result<(), SceneError> {
    let (limit, why) = match card(method).filter(|c| c.gains_energy_on_oscillations()) {
        Some(c) => (
            (0.02 / (omega * omega * t_s)).min(MAX_STEP_FREQUENCY / omega),
            format!(
                "{} gains energy on every oscillation, by up to (h ω)² a step",
                c.title
            ),
        ),
        None => (
            MAX_STEP_FREQUENCY / omega,
            "h ω ≤ 0.2 to follow them".into(),
        ),
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
    Ok(())
}

/// An explicit method's tolerance `tol` small enough that its errors do not excite the
/// contact's vibration (κ = `kappa`) by as much as the wall force at the start (or, at θ0 = 0,
/// its growth in the first √(l/g)) from the start (θ0, θ̇0 in 1/s) = `start`: else a spurious
/// separation.
pub(super) fn check_wall_force_resolved(
    cx: &Ctx,
    i: &RawIntegrator,
    method: &str,
    tol: f64,
    (start, unit): ((f64, f64), f64),
    kappa: f64,
) -> Result<(), SceneError> {
    let rate = start.1 * unit;
    let (theta_i, fw0) = starting_wall_force(start.0, rate);
    let rigid = rigid_separation_angle(start.0, rate);
    let to_go = (rigid - theta_i).abs();
    let (least, largest) = (RESOLVED_WALL_FORCE * tol, fw0 / RESOLVED_WALL_FORCE);
    let far = !is_implicit(method) && to_go > separation_bound(kappa, rigid, 1, tol);
    let tol_span = i.tolerance.as_ref().map(|t| t.span());
    if far && fw0 > 0.0 && tol > largest {
        return Err(cx.err(
            tol_span,
            "integrator.tolerance",
            format!(
                "the wall force where the integration starts is {fw0:.3e} m g, below {RESOLVED_WALL_FORCE} times the tolerance ({least:.3e} m g), {to_go:.3e} rad before the separation: \"{method}\" holds the spring forces to the tolerance a step, so its errors excite the contact's vibration (κ = {kappa:e}) by about the wall force and the force crosses zero at once (a spurious separation); allowed: tolerance ≤ {largest:e}, or method = \"radau5\""
            ),
        ));
    }
    // θ0 = 0 with a push (F8; or a subnormal θ0, where the force underflows to 0):
    // no wall force at the start, only its rate.
    let need = card(method).and_then(|c| c.penalty_fit);
    if let Some(need) = need
        .map(|f| f.wall_force_rate)
        .filter(|_| far && fw0 == 0.0)
    {
        let growth = wall_force_rate(theta_i, rate);
        let largest = growth / need;
        if tol > largest {
            return Err(cx.err(
                tol_span,
                "integrator.tolerance",
                format!(
                    "the wall force starts at 0 m g (θ0 = {theta_i:e}) and grows by {growth:.3e} m g in the first √(l/g), below {need} times the tolerance ({:.3e} m g), {to_go:.3e} rad before the separation: \"{method}\" holds the spring forces to the tolerance a step, so while the wall force is that small its errors excite the contact's vibration (κ = {kappa:e}) by more and the force crosses zero early (a spurious separation); allowed: tolerance ≤ {largest:e}, or method = \"radau5\"",
                    need * tol
                ),
            ));
        }
    }
    Ok(())
}
