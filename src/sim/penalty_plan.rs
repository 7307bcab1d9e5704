//! Plan-time refusals of penalty scenes whose separation the run could not tell (exit 2 before
//! any step; `super::scene_work` calls these with the scene's numbers). Both were found by the
//! reliability campaign as errors *after* the run (the run's own check,
//! `super::penalty_confirm`, refused a spurious zero or the foot lifted off the floor):
//!
//! * **The wall force is not resolved by an explicit adaptive method** (F1, F3): dopri5 and
//!   dop853 hold the forces to their tolerance τ per step in units of m g. When the rigid wall force where the integration starts (after the linear lead-in of a
//!   tiny start: F_w ≈ (3/4) θ m g at θ ~ 1e-9; near the floor F_w ≈ (3/4) φ0 m g with
//!   φ0 = π/2 − θ0) is no larger than that, one step's error can cross zero: the zero found is
//!   the error's, not the contact's. Seed 1 of the campaign had 26 such runs in 10000 scenes
//!   (dop853/dopri5 at τ ≥ 3e-8 after a tiny start), all refused now; F3's scene 69 (θ0 the
//!   last float below π/2, F_w = 1.2e-16 m g, τ = 1.4e-5) likewise.
//! * **Springs too soft for the start**: the penalty model's own distance from the rigid
//!   separation θ_r is up to 4/(κ sin θ_r) ([`super::penalty_confirm::separation_bound`]).
//!   Above a radian its answer says nothing about the note's ladder, and the soft floor lets the
//!   foot lift off before the top leaves the wall (the campaign's 14 lift-offs, all at
//!   κ = 1.0-1.6). Above π/2 − θ_r (a start near the floor, the campaign's F3) it cannot tell
//!   separation from flat: scene 418 (κ = 1.6e6, π/2 − θ0 = 2.1e-7) "separated" at
//!   θ = π/2 + 3.3e-7, inside the model's 2.5e-6 but past flat. Integrating the penalty model
//!   in φ = π/2 − θ would not help: its error is the model's 1/κ, not θ's rounding (1e-16).

use super::exact::separation_cos;
use super::integrators::{order, Control};
use super::lead_in::linear_lead_in;
use super::penalty_confirm::{rigid_separation_angle, MODEL_CONSTANT};
use super::penalty_start::{rigid_forces, OMEGA2};

/// Largest model shift 4/(κ sin θ_r), rad, of a scene the penalty model may run.
pub const MAX_MODEL_SHIFT: f64 = 1.0;

/// Why a penalty scene is refused up front: the key to name and the message.
#[derive(Clone, Debug, PartialEq)]
pub enum PenaltyRefusal {
    /// `[contact] stiffness`: the springs are too soft.
    Soft(String),
    /// `[integrator] tolerance` or `step`: the wall force is below the integration's error.
    Unresolved(String),
}

/// The local error τ per step in units of m g: the tolerance, or (h/T)^(p+1) for a fixed step
/// `h` in units of T = √(l/g).
pub fn force_error(method: &str, control: Control) -> f64 {
    match control {
        Control::Tolerance(t) => t,
        Control::Fixed(h) => h.powi(order(method).map_or(2, |p| p as i32 + 1)),
    }
}

/// The refusal of a penalty run of stiffness κ from (θ0, θ̇0) (θ̇0 in √(g/l)) with `method` at
/// `control` (a step in units of √(l/g)), if any (see the module docs).
pub fn penalty_refusal(
    kappa: f64,
    (theta0, rate0): (f64, f64),
    method: &str,
    control: Control,
) -> Option<PenaltyRefusal> {
    let (theta, rate, lead) = linear_lead_in(OMEGA2, theta0, rate0)
        .map_or((theta0, rate0, false), |(_, t, w)| (t, w, true));
    let (wall, _) = rigid_forces(theta, rate);
    // A start the wall cannot hold leaves at once (t_s = 0): nothing is integrated.
    if wall.is_nan() || wall <= 0.0 {
        return None;
    }
    let rigid = rigid_separation_angle(theta0, rate0);
    let shift = MODEL_CONSTANT / (kappa * rigid.sin());
    // π/2 − θ_r = asin(cos θ_r), which keeps its digits near the floor.
    let room = (separation_cos(theta0, rate0, OMEGA2).clamp(-1.0, 1.0)).asin();
    if shift.is_nan() || shift > MAX_MODEL_SHIFT || shift >= room {
        let (what, limit) = match shift < room {
            true => (format!("more than {MAX_MODEL_SHIFT} rad"), MAX_MODEL_SHIFT),
            false => (format!("more than the rigid separation's distance from flat, π/2 − θ_r = {room:.3e} rad: the model could not tell separation from flat"), room),
        };
        return Some(PenaltyRefusal::Soft(format!(
            "springs of κ = k l/(m g) = {kappa:.3e} are too soft for this start: the penalty model's separation may lie 4/(κ sin θ_r) = {shift:.3e} rad from the rigid one at θ_r = {rigid:.6} ({what}); allowed: κ > {:.3e} (k above that m g/l), or model = \"rigid\" (with angle_from_floor near the floor)",
            MODEL_CONSTANT / (limit * rigid.sin())
        )));
    }
    // Explicit adaptive methods only: fixed steps on springs are already held to h ω ≤ 0.2
    // (`super::scene_work`), and radau5 ends each step on the slow manifold (stiff accuracy),
    // so neither left a spurious zero in the campaign; refusing them would refuse good runs.
    let explicit_adaptive = matches!(control, Control::Tolerance(_)) && method != "radau5";
    let tau = force_error(method, control);
    if explicit_adaptive && wall <= tau {
        let at = if lead {
            format!("θ = {theta:.3e} rad, where the linear lead-in of the tiny start ends")
        } else {
            format!(
                "θ0 = {theta:?} rad, π/2 − θ0 = {:.3e}",
                std::f64::consts::FRAC_PI_2 - theta
            )
        };
        return Some(PenaltyRefusal::Unresolved(format!(
            "the rigid wall force where the integration starts ({at}) is {wall:.3e} m g, no more than the integration's force error per step, τ = {tau:.3e} m g: a zero of the integrated force could be the error's; allowed: a tolerance below {wall:.3e}, or method = \"radau5\""
        )));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unresolved_and_soft_starts_are_refused_and_the_rest_run() {
        let tol = |t| Control::Tolerance(t);
        // F1: dop853 at 1e-10 after the lead-in of θ0 = 1e-12 (F_w = 7e-10 m g) runs; dopri5 at
        // 1e-6 is refused.
        assert_eq!(
            penalty_refusal(1e6, (1e-12, 0.0), "dop853", tol(1e-10)),
            None
        );
        let r = penalty_refusal(1e6, (1e-12, 0.0), "dopri5", tol(1e-6));
        assert!(
            matches!(&r, Some(PenaltyRefusal::Unresolved(m)) if m.contains("linear lead-in")),
            "{r:?}"
        );
        // F3: the last float below π/2 cannot be told from flat at any κ ≤ 1e15 (π/2 − θ_r =
        // 1.2e-16 rad against 4/κ); π/2 − 1e-9 at κ = 1e12 can, but dop853 at 1e-8 does not
        // resolve its wall force of 7.5e-10 m g.
        let last = f64::from_bits(std::f64::consts::FRAC_PI_2.to_bits() - 1);
        let r = penalty_refusal(1e15, (last, 0.0), "radau5", tol(1e-15));
        assert!(
            matches!(&r, Some(PenaltyRefusal::Soft(m)) if m.contains("from flat")),
            "{r:?}"
        );
        let nine = (std::f64::consts::FRAC_PI_2 - 1e-9, 0.0);
        let r = penalty_refusal(1e12, nine, "dop853", tol(1e-8));
        assert!(
            matches!(&r, Some(PenaltyRefusal::Unresolved(m)) if m.contains("π/2 − θ0 = 1.000e-9")),
            "{r:?}"
        );
        assert_eq!(penalty_refusal(1e12, nine, "dop853", tol(1e-12)), None);
        // radau5 and fixed steps are not refused for it (their runs resolve the contact).
        assert_eq!(
            penalty_refusal(1e6, (1e-12, 0.0), "radau5", tol(1e-6)),
            None
        );
        assert_eq!(
            penalty_refusal(1e6, (1e-12, 0.0), "rk4", Control::Fixed(1e-3)),
            None
        );
        // π/2 − 2e-7 (F3's scene 418): κ = 1.6e6 cannot tell separation from flat; κ = 1e12 can.
        let near = (std::f64::consts::FRAC_PI_2 - 2e-7, 0.0);
        let r = penalty_refusal(1.6e6, near, "radau5", tol(1.8e-15));
        assert!(
            matches!(&r, Some(PenaltyRefusal::Soft(m)) if m.contains("from flat")),
            "{r:?}"
        );
        assert_eq!(penalty_refusal(1e12, near, "radau5", tol(1.8e-15)), None);
        // A fixed step: rk4's (h/T)^5.
        assert_eq!(force_error("rk4", Control::Fixed(0.1)), 0.1f64.powi(5));
        // Soft springs: κ = 1.4 at θ0 = 0.55 (the campaign's lift-offs); κ = 10 runs (its shift,
        // 0.49 rad, is below π/2 − θ_r = 0.60).
        assert!(matches!(
            penalty_refusal(1.4, (0.55, 0.0), "rk4", Control::Fixed(2e-3)),
            Some(PenaltyRefusal::Soft(_))
        ));
        assert_eq!(
            penalty_refusal(10.0, (0.55, 0.0), "radau5", tol(1e-10)),
            None
        );
        // A start the wall cannot hold is not refused here (it leaves at once).
        assert_eq!(penalty_refusal(1.4, (0.3, 2.0), "rk4", tol(1.0)), None);
    }
}
