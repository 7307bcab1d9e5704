//! Phase 3 of a fall, beyond the note: the ladder lies flat. When the floor phase reaches
//! θ = π/2 its top strikes the floor, the foot still on it, at the angular rate θ̇_f; a run to
//! a later time (`[end] at = "time"`) goes on from there.
//!
//! **The impact** is taken as perfectly inelastic: afterwards neither end moves vertically, so
//! the centre's vertical velocity Ẏ = −l sin θ θ̇ and θ̇ are both 0. The frictionless floor
//! gives no horizontal impulse, so Ẋ is kept. The vertical impulses at the top C and the foot
//! D follow from the impulse-momentum laws of the rod (I = m l²/3 about the centre, C at
//! distance l on the side that falls):
//!
//!   P_C + P_D = m l θ̇_f   (Ẏ from −l θ̇_f to 0),   l (P_C − P_D) = I θ̇_f   (θ̇_f to 0),
//!
//! so P_C = (2/3) m l θ̇_f and P_D = (1/3) m l θ̇_f ([`impulses`]): both push up, so the foot
//! stays on the floor and the assumption is consistent. The impact takes the kinetic energy
//! ½ m (l θ̇_f)² + ½ I θ̇_f² = (2/3) m l² θ̇_f².
//!
//! **After it** the floor holds each end with m g/2 (the rod is at rest vertically and the
//! forces' moments about the centre cancel) and nothing acts along it: the ladder slides flat
//! at Ẋ, X(t) = X_f + Ẋ (t − t_f), for as long as the run asks (a frictionless floor has no
//! end; the wall is behind the ladder, which moves away from it, Ẋ ≥ 0).

use super::outcome::{FlatState, Sample, Slide};
use crate::ladder::Ladder;
use std::f64::consts::FRAC_PI_2;

/// The vertical impulses (P_C, P_D) of the perfectly inelastic impact at θ = π/2 with angular
/// rate `rate` (module docs), N·s.
pub fn impulses(ladder: &Ladder<f64>, rate: f64) -> (f64, f64) {
    let p = ladder.m * ladder.l * rate;
    (2.0 / 3.0 * p, p / 3.0)
}

/// The slide after the ladder lay flat at `flat`, up to `t_end` (module docs).
pub fn slide(ladder: &Ladder<f64>, flat: &FlatState, t_end: f64) -> Slide {
    let l = ladder.l;
    Slide {
        impact_time: flat.time,
        centre_velocity_x: flat.centre_velocity_x,
        centre_x_end: flat.centre_x + flat.centre_velocity_x * (t_end - flat.time),
        energy_lost: 2.0 / 3.0 * l * flat.rate * flat.rate / ladder.g,
    }
}

/// A sample of the trace while lying flat at time `t` (θ = π/2, θ̇ = 0, phase 3), the centre
/// at `centre_x`.
pub fn lying_flat_sample(t: f64, centre_x: f64) -> Sample {
    Sample {
        phase: 3,
        t,
        theta: FRAC_PI_2,
        rate: 0.0,
        centre_x,
        forces: None,
    }
}

/// The floor force at the foot D while lying flat: m g/2 (module docs).
pub fn lying_flat_floor_force(ladder: &Ladder<f64>) -> f64 {
    0.5 * ladder.m * ladder.g
}

#[cfg(test)]
mod tests {
    use super::*;

    const LADDER: Ladder<f64> = Ladder {
        m: 3.0,
        l: 0.7,
        g: 9.81,
    };

    /// The impulses satisfy the two impulse-momentum laws of the rod and leave both ends at
    /// rest vertically; both are upward. Checked in exact arithmetic on binary fractions (the
    /// products are then exact): m = 3, l = 0.75, θ̇ = 2. A wrong split (½, ½) fails the
    /// angular law.
    #[test]
    fn the_impulses_stop_both_ends_and_push_up() {
        let ladder = Ladder {
            m: 3.0,
            l: 0.75,
            g: 9.81,
        };
        let (m, l, w) = (3.0, 0.75, 2.0);
        let (pc, pd) = impulses(&ladder, w);
        let inertia = m * l * l / 3.0;
        // Linear: m ΔẎ = P_C + P_D with Ẏ from −l θ̇ to 0.
        assert_eq!(pc + pd, m * l * w);
        // Angular about the centre: C lies at l on the falling side, I Δθ̇ = −l (P_C − P_D).
        assert_eq!(l * (pc - pd), inertia * w);
        assert!(pc > 0.0 && pd > 0.0);
        // The angular law can fail: an even split (each ½ m l θ̇) leaves the rod turning.
        let even = 0.5 * m * l * w;
        assert_ne!(l * (even - even), inertia * w);
    }

    /// The energy the impact takes is the kinetic energy of the vertical and rotational motion
    /// at flat, ½ m (l θ̇)² + ½ (m l²/3) θ̇², over m g l; the slide keeps Ẋ and moves X by
    /// Ẋ (t − t_f). Error model: a few roundings of products of O(1) numbers.
    #[test]
    fn the_slide_keeps_the_horizontal_speed_and_loses_the_rest() {
        let flat = FlatState {
            time: 1.25,
            rate: 2.3,
            centre_x: 0.7,
            centre_velocity_x: 0.9,
            centre_velocity_y: -0.7 * 2.3,
        };
        let s = slide(&LADDER, &flat, 3.25);
        let (m, l, g) = (LADDER.m, LADDER.l, LADDER.g);
        let kinetic =
            0.5 * m * (l * flat.rate).powi(2) + 0.5 * (m * l * l / 3.0) * flat.rate.powi(2);
        let u = f64::EPSILON;
        assert!((s.energy_lost - kinetic / (m * g * l)).abs() <= 8.0 * u * s.energy_lost);
        assert_eq!(s.centre_velocity_x, 0.9);
        assert!((s.centre_x_end - (0.7 + 0.9 * 2.0)).abs() <= 4.0 * u * 2.5);
        assert_eq!(s.impact_time, 1.25);
        assert_eq!(lying_flat_floor_force(&LADDER), 0.5 * m * g);
    }
}
