//! The simulator's contact forces (`sim::rigid::wall_force`, `floor_force`, in f64 for its
//! events and monitors) are the note's eqs. (14) and (15) of the equation modules
//! (`ladder::forces`, checked against the print) on the motion (5), θ̈ = (3g/4l) sin θ, for any
//! m, l, g. The runs use the unit ladder (m = l = g = 1, `sim::scaled`), where m l = m/l, so only
//! a ladder of other units tells the two apart (mutation testing: m · l → m / l in the wall
//! force went unseen).
//!
//! Error model: each side is a few roundings of terms of size m l (Ω² + θ̇²) and m g: 8 ulps of
//! their sum.

use sliding_ladder::ladder::{forces, Ladder, State};
use sliding_ladder::sim::rigid;
#[test]
fn the_simulator_s_forces_are_eqs_14_and_15_on_the_motion_for_any_units() {
    let ladders = [(2.0, 3.0, 5.0), (1e3, 1e-2, 9.81), (7e-20, 4e15, 1e-8)];
    let states = [(0.3, 0.0), (1.0, -0.7), (1.4, 2.5)];
    for (m, l, g) in ladders {
        let ladder: Ladder<f64> = Ladder { m, l, g };
        for (theta, rate_per_t) in states {
            let rate = rate_per_t * (g / l).sqrt();
            let accel = 3.0 * g / (4.0 * l) * f64::sin(theta);
            let st = State {
                sin: theta.sin(),
                cos: theta.cos(),
                rate,
                accel,
                jerk: 0.0, // no force depends on it
            };
            let size = m * l * (accel.abs() + rate * rate) + m * g;
            let bound = 8.0 * f64::EPSILON * size;
            let (w, f) = (
                forces::wall_force(&ladder, &st),
                forces::floor_force(&ladder, &st),
            );
            let (sw, sf) = (
                rigid::wall_force(&ladder, theta, rate),
                rigid::floor_force(&ladder, theta, rate),
            );
            assert!(
                (sw - w).abs() <= bound,
                "m, l, g = {m}, {l}, {g}, θ = {theta}: F_w {sw} against {w}"
            );
            assert!(
                (sf - f).abs() <= bound,
                "m, l, g = {m}, {l}, {g}, θ = {theta}: F_f {sf} against {f}"
            );
        }
    }
}
