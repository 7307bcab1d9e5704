//! Each model's own Taylor recursion (`Ode::taylor_series`: the wall and floor phases, in θ and
//! in the complement φ = π/2 − θ) drives the Taylor method along the same motion as dop853 on
//! the model's right-hand side: two independent routes to the state at the end. The recursions
//! themselves are checked exactly in `tests/sim/integrators/taylor/coefficients.rs` and `tests/sim/integrators/taylor/f64_paths.rs`; this checks
//! that each model hands its own recursion to the stepper. (Mutation testing:
//! `FloorPhase::taylor_series` → `true` without filling the series went unseen; the model in θ
//! is run by tests and work-precision, the simulator's floor phase is the complement's.)

use sliding_ladder::sim::complement::{ComplementFloor, ComplementWall};
use sliding_ladder::sim::floor::{state_at_separation, FloorPhase};
use sliding_ladder::sim::integrators::taylor::Taylor;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
const TOL: f64 = 1e-12;

/// The state at `t_end` by Taylor and by dop853 (both at tolerance 1e-12), and their steps.
fn both<const N: usize, S: Ode<N>>(sys: &S, y0: [f64; N], t_end: f64) -> ([f64; N], [f64; N], u64) {
    let mut taylor = Taylor::new(0.0, y0, TOL);
    while taylor.t() < t_end {
        taylor.step(sys, t_end).unwrap();
    }
    let mut dop = AnyStepper::new("dop853", Control::Tolerance(TOL), 0.0, y0).unwrap();
    while dop.t() < t_end {
        dop.step(sys, t_end).unwrap();
    }
    let steps = taylor.stats().steps + dop.stats().steps;
    (taylor.y(), dop.y(), steps)
}

/// Error model: each run's global error is at most 10 N τ in the model's scale (unit ladder:
/// angles, rates and lengths of order 1), N the steps of both runs.
#[test]
fn every_model_s_series_follows_its_right_hand_side() {
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    };
    let check = |name: &str, a: &[f64], b: &[f64], steps: u64| {
        let bound = 10.0 * steps as f64 * TOL;
        for (i, (x, y)) in a.iter().zip(b).enumerate() {
            assert!(
                (x - y).abs() <= bound * x.abs().max(1.0),
                "{name}[{i}]: {x} vs {y}"
            );
        }
    };
    let (a, b, n) = both(&WallPhase::new(&ladder), [0.3, 0.0], 1.5);
    check("wall", &a, &b, n);
    let (a, b, n) = both(&ComplementWall::new(&ladder), [1.2, 0.0], 1.5);
    check("complement wall", &a, &b, n);
    // From a separation at θ = 0.9 with θ̇ = 0.8, 0.3 √(l/g) into the floor phase.
    let y0 = state_at_separation(&ladder, 0.9, 0.8);
    let (a, b, n) = both(&FloorPhase::new(&ladder), y0, 0.3);
    check("floor", &a, &b, n);
    let y0 = [std::f64::consts::FRAC_PI_2 - y0[0], y0[1], -y0[2], y0[3]];
    let (a, b, n) = both(&ComplementFloor::new(&ladder), y0, 0.3);
    check("complement floor", &a, &b, n);
}
