//! Plan-time refusal of a penalty start the model cannot tell from flat (the reliability
//! campaign's F3; exit 2 before any step, called by `crate::sim::scene::work`).
//!
//! The penalty model's separation lies c/(κ sin θ_r) from the rigid one θ_r, with
//! κ (θ_s − θ_r) sin θ_r measured at 0.4..1.25 over the start domain
//! ([`crate::sim::penalty::confirm`]; [`MEASURED_SHIFT`] is the top of that range). Near the floor the
//! rigid separation is π/2 − θ_r = asin((2/3) cos θ0 + (4/9) θ̇0²) from flat, which for a start
//! 1e-7 rad from the floor is 7e-8 rad: springs of κ = 1.6e6 then shift the separation by more
//! than the distance left, and the run "separates" wherever its integration error puts the
//! force's zero, past flat included (seed 1's scene 418: radau5 reported θ_s = π/2 + 3.3e-7,
//! inside the model's stated bound 4/κ but not a separation). Such a start is refused naming the
//! stiffness, with the least κ that can tell them apart.
//!
//! Integrating the penalty model in φ = π/2 − θ (as the rigid phases do, `crate::sim::complement`)
//! would not help: its error there is the model's 1/κ ≥ 1e-15, not θ's rounding (1e-16).

use crate::sim::exact::separation_cos;
use crate::sim::penalty::confirm::rigid_separation_angle;
use crate::sim::penalty::start::OMEGA2;

/// The largest measured κ (θ_s − θ_r) sin θ_r of the penalty model (`tests/sim/penalty/confirm.rs`).
pub const MEASURED_SHIFT: f64 = 1.25;

/// For a penalty start (θ0, θ̇0) (θ̇0 in √(g/l)) with stiffness κ: None when the model's shift
/// MEASURED_SHIFT/(κ sin θ_r) is below the rigid separation's distance from flat, else why
/// not and the least κ that would be, as one line.
pub fn too_close_to_flat(kappa: f64, (theta0, rate0): (f64, f64)) -> Option<String> {
    let cos_r = separation_cos(theta0, rate0, OMEGA2);
    // The wall cannot hold the start (it leaves at once) or the start is the equilibrium:
    // other checks answer those.
    if !(cos_r > 0.0 && cos_r < 1.0) {
        return None;
    }
    let rigid = rigid_separation_angle(theta0, rate0);
    // π/2 − θ_r = asin(cos θ_r) keeps its digits near the floor.
    let room = cos_r.asin();
    let shift = MEASURED_SHIFT / (kappa * rigid.sin());
    if shift < room {
        return None;
    }
    Some(format!(
        "springs of κ = k l/(m g) = {kappa:.3e} cannot tell this start's separation from flat: the penalty model moves it by up to {MEASURED_SHIFT}/(κ sin θ_r) = {shift:.3e} rad, more than the {room:.3e} rad from the rigid separation to flat; allowed: κ > {:.3e} (k above that m g/l), or model = \"rigid\" (with angle_from_floor near the floor)",
        MEASURED_SHIFT / (room * rigid.sin())
    ))
}
