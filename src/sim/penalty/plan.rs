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

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    /// The least κ a refusal states ("allowed: κ > …").
    fn stated_least_kappa(message: &str) -> f64 {
        let after = message.split("κ > ").nth(1).expect("a least κ");
        after.split(' ').next().unwrap().parse().unwrap()
    }

    #[test]
    fn starts_the_springs_cannot_tell_from_flat_are_refused_and_the_rest_run() {
        // Scene 418: π/2 − 2.1e-7 at κ = 1.6e6 is refused; κ = 1e12 runs.
        let near = (FRAC_PI_2 - 2.1e-7, 0.0);
        let m = too_close_to_flat(1.6e6, near).expect("refused");
        assert!(
            m.contains("cannot tell this start's separation from flat"),
            "{m}"
        );
        assert_eq!(too_close_to_flat(1e12, near), None);
        // The stated least κ: just above it runs, just below it is refused.
        let least = stated_least_kappa(&m);
        assert!(too_close_to_flat(least * 1.01, near).is_none());
        assert!(too_close_to_flat(least * 0.99, near).is_some());
        // A start at rest from 1.17 rad separates at θ_r = 1.31 (sin θ_r = 0.966, not 1), 0.26
        // rad from flat: its least κ is near the softest springs, and the shift's κ sin θ_r
        // is tried there 1 % either side (mutation testing: κ + sin θ_r and κ/sin θ_r, which
        // near flat agree with κ sin θ_r, went unseen).
        let (far, soft) = (
            (1.17, 0.0),
            too_close_to_flat(1.0, (1.17, 0.0)).expect("κ = 1"),
        );
        let least = stated_least_kappa(&soft);
        assert!((3.0..10.0).contains(&least), "{least}");
        assert!(too_close_to_flat(least * 1.01, far).is_none());
        assert!(too_close_to_flat(least * 0.99, far).is_some());
        // The last float below π/2 cannot be told from flat at any κ ≤ 1e15.
        let last = f64::from_bits(FRAC_PI_2.to_bits() - 1);
        assert!(too_close_to_flat(1e15, (last, 0.0)).is_some());
        // Ordinary starts at the softest springs scenes allow (κ = 5) run.
        assert_eq!(too_close_to_flat(5.0, (0.6, 0.0)), None);
        assert_eq!(too_close_to_flat(5.0, (1e-12, 0.0)), None);
        // A start the wall cannot hold is left to the run (it leaves at once).
        assert_eq!(too_close_to_flat(1e6, (0.3, 2.0)), None);
        // So is the limiting push θ̇0² = Ω² cos θ0, where cos θ_r is 1 and the top leaves at
        // t = 0: from θ0 = 0 with θ̇0 = √(3/4), cos θ_r comes out exactly 1 in f64
        // (mutation testing: `cos_r < 1` → `<= 1` refused it as "cannot tell from flat").
        let limiting = (0.0, OMEGA2.sqrt());
        assert_eq!(separation_cos(limiting.0, limiting.1, OMEGA2), 1.0);
        assert_eq!(too_close_to_flat(1e6, limiting), None);
    }
}
