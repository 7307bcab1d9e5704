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
